//! Fitted laws for event-driven codes: Eq. (27) and power laws (Bridges-type).
//!
//! * [`fit_eq27`]: ε ≈ a g^b (1 − exp(−c g^d)) (Eq. (27)), by Levenberg–Marquardt on nalgebra's
//!   fixed-size matrices (no allocation), with a, c, d > 0 enforced through logarithms.
//! * [`fit_power_law`]: ε ≈ a (g / g₀)^b by linear least squares in log–log; with g₀ = 1 cm/s this is
//!   the form of Bridges et al. (1984), ε = 0.32 (v / 1 cm/s)^−0.234.
//!
//! Every fit reports its parameters, the rms and maximum absolute error over the fitted points and
//! the range of speeds it was fitted on (its validity range).

#[cfg(feature = "alloc")]
pub mod scene;

use crate::error::{Error, Result};
use crate::numerics::lm::{LeastSquares, Schedule, damped_diagonal, minimise};
use crate::numerics::math::{exp, ln, powf, sqrt};
use nalgebra::{SMatrix, SVector};

/// Eq. (27) fitted to a curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Eq27 {
    /// Prefactor a.
    pub a: f64,
    /// High-speed exponent b.
    pub b: f64,
    /// Onset rate c \[(m/s)^−d\].
    pub c: f64,
    /// Onset exponent d.
    pub d: f64,
    /// Root-mean-square error of ε over the fitted points.
    pub rms_error: f64,
    /// Largest absolute error of ε over the fitted points.
    pub max_error: f64,
    /// Smallest fitted speed \[m/s\].
    pub g_min: f64,
    /// Largest fitted speed \[m/s\].
    pub g_max: f64,
}

impl Eq27 {
    /// The fitted law at speed `g`.
    pub fn eval(&self, g: f64) -> f64 {
        eq27(self.a, self.b, self.c, self.d, g)
    }
}

/// A power law ε ≈ a (g / g₀)^b fitted to a curve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerLaw {
    /// Prefactor a (ε at g₀).
    pub a: f64,
    /// Exponent b.
    pub b: f64,
    /// Reference speed g₀ \[m/s\].
    pub g0: f64,
    /// Root-mean-square error of ε over the fitted points.
    pub rms_error: f64,
    /// Largest absolute error of ε over the fitted points.
    pub max_error: f64,
    /// Smallest fitted speed \[m/s\].
    pub g_min: f64,
    /// Largest fitted speed \[m/s\].
    pub g_max: f64,
}

impl PowerLaw {
    /// The fitted law at speed `g`.
    pub fn eval(&self, g: f64) -> f64 {
        self.a * powf(g / self.g0, self.b)
    }
}

/// The Bridges et al. (1984) law for ice at low temperature: ε = 0.32 (v / 1 cm/s)^−0.234.
pub const BRIDGES_1984: PowerLaw = PowerLaw {
    a: 0.32,
    b: -0.234,
    g0: 0.01,
    rms_error: 0.0,
    max_error: 0.0,
    g_min: 0.0,
    g_max: 0.0,
};

/// The legend of [`BRIDGES_1984`] on the explorer's chart (every surface's words).
pub const BRIDGES_1984_LABEL: &str = "Bridges et al. 1984: ε = 0.32 (v / 1 cm/s)^−0.234";

/// The reason of the one [`Error::Fit`] that is a failed computation rather than unusable input
/// (front ends map it to their "computation failed" exit code).
pub const FIT_DID_NOT_CONVERGE: &str = "Eq. (27) did not converge";

/// Eq. (27): a g^b (1 − exp(−c g^d)).
#[doc(alias = "Eq. (27)")]
pub fn eq27(a: f64, b: f64, c: f64, d: f64, g: f64) -> f64 {
    a * powf(g, b) * (1.0 - exp(-c * powf(g, d)))
}

fn check_points(g: &[f64], eps: &[f64], min: usize) -> Result<()> {
    if g.len() != eps.len() {
        return Err(Error::Fit {
            reason: "speeds and coefficients differ in length",
        });
    }
    if g.len() < min {
        return Err(Error::Fit {
            reason: "too few points with ε > 0 to fit",
        });
    }
    if g.iter().chain(eps).any(|v| !v.is_finite()) || g.iter().any(|&v| v <= 0.0) {
        return Err(Error::Fit {
            reason: "speeds must be finite and > 0, coefficients finite",
        });
    }
    Ok(())
}

fn errors(g: &[f64], eps: &[f64], f: impl Fn(f64) -> f64) -> (f64, f64) {
    let (mut sum, mut max) = (0.0, 0.0f64);
    for (&gi, &ei) in g.iter().zip(eps) {
        let r = f(gi) - ei;
        sum += r * r;
        max = max.max(r.abs());
    }
    (sqrt(sum / g.len() as f64), max)
}

fn range(g: &[f64]) -> (f64, f64) {
    g.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &v| {
        (lo.min(v), hi.max(v))
    })
}

/// Fits ε ≈ a (g/g₀)^b to the points with ε > 0 (least squares in ln ε).
pub fn fit_power_law(g: &[f64], eps: &[f64], g0: f64) -> Result<PowerLaw> {
    let (mut n, mut sx, mut sy, mut sxx, mut sxy) = (0.0, 0.0, 0.0, 0.0, 0.0);
    let mut used = 0usize;
    check_points(g, eps, 0)?;
    for (&gi, &ei) in g.iter().zip(eps) {
        if ei > 0.0 {
            let (x, y) = (ln(gi / g0), ln(ei));
            n += 1.0;
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
            used += 1;
        }
    }
    let det = n * sxx - sx * sx;
    if used < 2 || det.abs() <= 1e-300 {
        return Err(Error::Fit {
            reason: "need at least two distinct speeds with ε > 0",
        });
    }
    let b = (n * sxy - sx * sy) / det;
    let a = exp((sy - b * sx) / n);
    let law = |x: f64| a * powf(x / g0, b);
    let (rms_error, max_error) = errors(g, eps, law);
    let (g_min, g_max) = range(g);
    Ok(PowerLaw {
        a,
        b,
        g0,
        rms_error,
        max_error,
        g_min,
        g_max,
    })
}

/// Fits Eq. (27) to a curve by Levenberg–Marquardt (absolute residuals in ε).
///
/// Points with ε = 0 below the first rebound are kept (the law must stay near 0 there); the fit is
/// started from several onset exponents and the best result is returned.
#[doc(alias = "Eq. (27)")]
pub fn fit_eq27(g: &[f64], eps: &[f64]) -> Result<Eq27> {
    check_points(g, eps, 4)?;
    let positive = eps.iter().filter(|&&e| e > 0.0).count();
    if positive < 4 {
        return Err(Error::Fit {
            reason: "Eq. (27) needs at least four points with ε > 0",
        });
    }
    // Start: b, a from the power law of the upper half; c from the speed where ε first reaches half
    // its maximum.
    let (g_min, g_max) = range(g);
    let mid = sqrt(g_min * g_max);
    let mut upper_n = 0;
    let (mut sx, mut sy, mut sxx, mut sxy) = (0.0, 0.0, 0.0, 0.0);
    for (&gi, &ei) in g.iter().zip(eps) {
        if gi >= mid && ei > 0.0 {
            let (x, y) = (ln(gi), ln(ei));
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
            upper_n += 1;
        }
    }
    let n = upper_n as f64;
    let det = n * sxx - sx * sx;
    let (b0, lna0) = if upper_n >= 2 && det.abs() > 1e-300 {
        let b = (n * sxy - sx * sy) / det;
        (b, (sy - b * sx) / n)
    } else {
        (0.0, 0.0)
    };
    let e_max = eps.iter().cloned().fold(0.0f64, f64::max);
    let g_half = g
        .iter()
        .zip(eps)
        .find(|(_, e)| **e >= 0.5 * e_max)
        .map(|(g, _)| *g)
        .unwrap_or(mid);
    let mut best: Option<(f64, [f64; 4])> = None;
    for d0 in [0.5, 1.0, 2.0, 4.0] {
        // 1 − exp(−c g_half^d) = 1/2 at the half-maximum speed.
        let lnc0 = ln(core::f64::consts::LN_2) - d0 * ln(g_half);
        let p = levenberg_marquardt(g, eps, [lna0, b0, lnc0, ln(d0)]);
        let cost = cost(g, eps, &p);
        if cost.is_finite() && best.is_none_or(|(c, _)| cost < c) {
            best = Some((cost, p));
        }
    }
    let Some((_, p)) = best else {
        return Err(Error::Fit {
            reason: FIT_DID_NOT_CONVERGE,
        });
    };
    let (a, b, c, d) = (exp(p[0]), p[1], exp(p[2]), exp(p[3]));
    let (rms_error, max_error) = errors(g, eps, |x| eq27(a, b, c, d, x));
    Ok(Eq27 {
        a,
        b,
        c,
        d,
        rms_error,
        max_error,
        g_min,
        g_max,
    })
}

fn model(p: &[f64; 4], g: f64) -> f64 {
    eq27(exp(p[0]), p[1], exp(p[2]), exp(p[3]), g)
}

fn cost(g: &[f64], eps: &[f64], p: &[f64; 4]) -> f64 {
    g.iter()
        .zip(eps)
        .map(|(&gi, &ei)| {
            let r = model(p, gi) - ei;
            r * r
        })
        .sum()
}

/// The Eq. (27) fit as a least-squares problem in (ln a, b, ln c, ln d), with its analytic Jacobian.
struct Eq27Problem<'a> {
    g: &'a [f64],
    eps: &'a [f64],
}

impl LeastSquares for Eq27Problem<'_> {
    type Point = [f64; 4];
    type Normal = (SMatrix<f64, 4, 4>, SVector<f64, 4>);

    fn normal(&self, p: &[f64; 4]) -> Option<Self::Normal> {
        let mut jtj = SMatrix::<f64, 4, 4>::zeros();
        let mut jtr = SVector::<f64, 4>::zeros();
        let (a, b, c, d) = (exp(p[0]), p[1], exp(p[2]), exp(p[3]));
        for (&gi, &ei) in self.g.iter().zip(self.eps) {
            let lg = ln(gi);
            let gb = powf(gi, b);
            let gd = powf(gi, d);
            let e = exp(-c * gd);
            let f = a * gb * (1.0 - e);
            // ∂f/∂(ln a), ∂f/∂b, ∂f/∂(ln c), ∂f/∂(ln d).
            let j = SVector::<f64, 4>::new(
                f,
                f * lg,
                a * gb * e * c * gd,
                a * gb * e * c * gd * lg * d,
            );
            let r = f - ei;
            jtj += j * j.transpose();
            jtr += j * r;
        }
        Some((jtj, jtr))
    }

    fn damped_step(
        &self,
        p: &[f64; 4],
        (jtj, jtr): &Self::Normal,
        lambda: f64,
    ) -> Option<[f64; 4]> {
        let mut m = *jtj;
        for k in 0..4 {
            m[(k, k)] = damped_diagonal(jtj[(k, k)], lambda);
        }
        let step = m.lu().solve(&(-jtr))?;
        Some([
            p[0] + step[0],
            p[1] + step[1],
            p[2] + step[2],
            p[3] + step[3],
        ])
    }

    fn cost(&self, p: &[f64; 4]) -> f64 {
        cost(self.g, self.eps, p)
    }
}

/// Levenberg–Marquardt on the 4 parameters (ln a, b, ln c, ln d): the crate's one loop
/// ([`crate::numerics::lm`]).
fn levenberg_marquardt(g: &[f64], eps: &[f64], start: [f64; 4]) -> [f64; 4] {
    let problem = Eq27Problem { g, eps };
    let schedule = Schedule {
        iterations: 500,
        tries: 20,
        relative_decrease: 1e-14,
    };
    minimise(&problem, start, cost(g, eps, &start), schedule).0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_law_recovers_its_parameters_exactly() {
        let g: [f64; 5] = [1e-3, 3e-3, 1e-2, 3e-2, 1e-1];
        let e: [f64; 5] = core::array::from_fn(|i| 0.32 * powf(g[i] / 0.01, -0.234));
        let law = fit_power_law(&g, &e, 0.01).unwrap();
        assert!((law.a - 0.32).abs() < 1e-13 && (law.b + 0.234).abs() < 1e-13);
        assert!(law.max_error < 1e-14);
        assert_eq!((law.g_min, law.g_max), (1e-3, 1e-1));
    }

    #[test]
    fn eq27_recovers_synthetic_parameters() {
        // Points generated from known parameters: the fit must find them again.
        let (a, b, c, d) = (0.2, -0.1, 3e3, 1.3);
        let mut g = [0.0; 40];
        crate::numerics::grid::log_space(1e-5, 1.0, &mut g);
        let e: [f64; 40] = core::array::from_fn(|i| eq27(a, b, c, d, g[i]));
        let fit = fit_eq27(&g, &e).unwrap();
        assert!(fit.max_error < 1e-9, "{fit:?}");
        assert!(
            (fit.a / a - 1.0).abs() < 1e-6 && (fit.b - b).abs() < 1e-6,
            "{fit:?}"
        );
        assert!(
            (fit.c / c - 1.0).abs() < 1e-5 && (fit.d / d - 1.0).abs() < 1e-6,
            "{fit:?}"
        );
    }

    #[test]
    fn bad_points_are_rejected() {
        assert!(fit_power_law(&[1.0], &[0.5], 1.0).is_err());
        assert!(fit_eq27(&[1.0, 2.0], &[0.5, 0.4],).is_err());
        assert!(fit_power_law(&[1.0, f64::NAN], &[0.5, 0.4], 1.0).is_err());
        assert!(fit_power_law(&[1.0, 2.0], &[0.5], 1.0).is_err());
    }
}
