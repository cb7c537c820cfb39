//! The one Levenberg–Marquardt loop of the crate: the Eq. (27) fit ([`crate::fit`], four parameters
//! in stack matrices, no allocation) and the fit of scene parameters (`crate::fit::scene`, any number
//! of parameters in heap matrices) run this loop over their own normal equations.
//!
//! The schedule: start at λ = 1e-3; a step that lowers the cost is taken and multiplies λ by 0.3
//! (floored at 1e-12); a step that does not, or a singular damped system, multiplies λ by 10 and
//! tries again, up to [`Schedule::tries`] times per iteration; the loop ends when no try improves,
//! when the cost's relative decrease falls below [`Schedule::relative_decrease`], or after
//! [`Schedule::iterations`] iterations.

/// A least-squares problem as the loop sees it.
pub trait LeastSquares {
    /// A point of the parameter space.
    type Point: Clone;
    /// The normal equations (JᵀJ, Jᵀr) at a point, computed once per iteration.
    type Normal;
    /// The normal equations at `p`, or `None` where the model cannot be differentiated there
    /// (the loop then ends at `p`).
    fn normal(&self, p: &Self::Point) -> Option<Self::Normal>;
    /// The point reached from `p` by the step solving (JᵀJ + λ diag(JᵀJ + 1e-12)) δ = −Jᵀr
    /// (see [`damped_diagonal`]), projected into the parameter space; `None` if that system is
    /// singular.
    fn damped_step(
        &self,
        p: &Self::Point,
        normal: &Self::Normal,
        lambda: f64,
    ) -> Option<Self::Point>;
    /// The sum of squared residuals at `p` (`∞` where the model fails).
    fn cost(&self, p: &Self::Point) -> f64;
}

/// How long the loop runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Schedule {
    /// Outer iterations (normal equations computed) at most.
    pub iterations: usize,
    /// Damped steps tried per iteration before giving up.
    pub tries: usize,
    /// The loop stops after an accepted step that lowered the cost by less than this fraction.
    pub relative_decrease: f64,
}

/// λ at the start.
pub const LAMBDA_START: f64 = 1e-3;
/// λ never falls below this.
pub const LAMBDA_FLOOR: f64 = 1e-12;
/// λ is multiplied by this after an accepted step.
pub const LAMBDA_DOWN: f64 = 0.3;
/// λ is multiplied by this after a rejected step.
pub const LAMBDA_UP: f64 = 10.0;

/// A diagonal element of the damped system: JᵀJ_kk + λ (JᵀJ_kk + 1e-12) (Marquardt's scaling, kept
/// positive for a parameter the data do not constrain).
#[inline]
pub fn damped_diagonal(jtj_kk: f64, lambda: f64) -> f64 {
    jtj_kk + lambda * (jtj_kk + 1e-12)
}

/// Runs the loop from `start` (whose cost is `start_cost`); returns the best point and its cost.
pub fn minimise<P: LeastSquares>(
    problem: &P,
    start: P::Point,
    start_cost: f64,
    schedule: Schedule,
) -> (P::Point, f64) {
    let mut p = start;
    let mut current = start_cost;
    let mut lambda = LAMBDA_START;
    for _ in 0..schedule.iterations {
        let Some(normal) = problem.normal(&p) else {
            break;
        };
        let mut improved = false;
        for _ in 0..schedule.tries {
            let Some(trial) = problem.damped_step(&p, &normal, lambda) else {
                lambda *= LAMBDA_UP;
                continue;
            };
            let cost = problem.cost(&trial);
            if cost.is_finite() && cost < current {
                let relative = (current - cost) / current.max(1e-300);
                p = trial;
                current = cost;
                lambda = (lambda * LAMBDA_DOWN).max(LAMBDA_FLOOR);
                improved = true;
                if relative < schedule.relative_decrease {
                    return (p, current);
                }
                break;
            }
            lambda *= LAMBDA_UP;
        }
        if !improved {
            break;
        }
    }
    (p, current)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rosenbrock's function as residuals r = (1 − x, 10 (y − x²)): its one minimum is (1, 1) with
    /// cost 0, reached from the classic start (−1.2, 1) along a curved valley.
    struct Rosenbrock;

    impl Rosenbrock {
        fn residuals(p: &[f64; 2]) -> [f64; 2] {
            [1.0 - p[0], 10.0 * (p[1] - p[0] * p[0])]
        }
    }

    impl LeastSquares for Rosenbrock {
        type Point = [f64; 2];
        type Normal = ([[f64; 2]; 2], [f64; 2]);
        fn normal(&self, p: &[f64; 2]) -> Option<Self::Normal> {
            let r = Self::residuals(p);
            let j = [[-1.0, 0.0], [-20.0 * p[0], 10.0]];
            let mut jtj = [[0.0; 2]; 2];
            let mut jtr = [0.0; 2];
            for a in 0..2 {
                for b in 0..2 {
                    jtj[a][b] = j[0][a] * j[0][b] + j[1][a] * j[1][b];
                }
                jtr[a] = j[0][a] * r[0] + j[1][a] * r[1];
            }
            Some((jtj, jtr))
        }
        fn damped_step(&self, p: &[f64; 2], n: &Self::Normal, lambda: f64) -> Option<[f64; 2]> {
            let (jtj, jtr) = n;
            let m = [
                [damped_diagonal(jtj[0][0], lambda), jtj[0][1]],
                [jtj[1][0], damped_diagonal(jtj[1][1], lambda)],
            ];
            let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
            if det == 0.0 {
                return None;
            }
            let dx = (-jtr[0] * m[1][1] + jtr[1] * m[0][1]) / det;
            let dy = (-jtr[1] * m[0][0] + jtr[0] * m[1][0]) / det;
            Some([p[0] + dx, p[1] + dy])
        }
        fn cost(&self, p: &[f64; 2]) -> f64 {
            let r = Self::residuals(p);
            r[0] * r[0] + r[1] * r[1]
        }
    }

    #[test]
    fn the_loop_finds_rosenbrocks_minimum() {
        let start = [-1.2, 1.0];
        let schedule = Schedule {
            iterations: 500,
            tries: 30,
            relative_decrease: 1e-14,
        };
        let (p, cost) = minimise(&Rosenbrock, start, Rosenbrock.cost(&start), schedule);
        assert!(
            (p[0] - 1.0).abs() < 1e-6 && (p[1] - 1.0).abs() < 1e-6,
            "{p:?}"
        );
        assert!(cost < 1e-12, "{cost}");
    }

    #[test]
    fn a_start_at_the_minimum_stays_there() {
        let start = [1.0, 1.0];
        let schedule = Schedule {
            iterations: 10,
            tries: 5,
            relative_decrease: 1e-14,
        };
        let (p, cost) = minimise(&Rosenbrock, start, 0.0, schedule);
        assert_eq!((p, cost), (start, 0.0));
    }
}
