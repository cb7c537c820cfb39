//! The viscoelastic contact of Eq. (4) on its dimensionless form (docs/physics.md#decision-3).
//!
//! With ξ* = (g²/α)^(2/5), τ = ξ*/g, x = ξ/ξ*, s = t/τ, Eq. (4) becomes
//! `x'' + x^(3/2) + 1.5 δ √x x' = 0`, `x(0) = 0`, `x'(0) = 1`, with `δ = A α^(2/5) g^(1/5)`,
//! so ε_N depends on δ alone. The start is singular (√x is not Lipschitz at 0); we integrate in
//! `σ = √s`, in which the solution `x = σ² − (2/5)δσ⁵ − (4/35)σ⁷ + …` is analytic.

pub mod master;

use super::trace::{Kind, Nothing, Recorder, StateMap};
use crate::error::{Error, Result};
use crate::numerics::math::{powf, sqrt};
use crate::numerics::ode::{Direction, Dopri5, OdeSystem, StepOutcome, Tolerances};
use crate::scene::ContactEnd;

/// ε_N below this is reported as [`crate::Status::Overdamped`] (docs/physics.md#decision-2).
pub const OVERDAMPED_THRESHOLD: f64 = 1e-9;

/// Below this separation speed (in units of the impact speed) a zero-overlap contact is abandoned
/// as overdamped. After the total force has vanished the tensile viscous force only slows the
/// separation down, so |x'| at that moment bounds ε_N from above.
const CREEP_FLOOR: f64 = OVERDAMPED_THRESHOLD;

/// Step budget of one contact. Force-zero contacts need at most a few thousand steps for any δ;
/// zero-overlap contacts at δ ≳ 30 creep apart over times of order δ, which an explicit method
/// follows only with stability-limited steps. When a creeping contact exhausts the budget it is
/// reported as overdamped with ε_N = [`creep_eps`] = K δ⁻⁵, far below [`OVERDAMPED_THRESHOLD`] there.
const MAX_STEPS: usize = 40_000;

/// Zero-overlap contacts with δ above this are reported overdamped at the moment the total force
/// vanishes, without following the creep: ε_N = [`creep_eps`] = K δ⁻⁵ ≤ 7e-11 there (test
/// `zero_overlap_creep_follows_inverse_fifth_power`).
pub const CREEP_DELTA_LIMIT: f64 = 100.0;

/// ε_N of a zero-overlap contact that creeps apart: K δ⁻⁵ with K = 0.679 293 063 936 485 3.
///
/// For strong damping the slow creep is invariant under x → δ⁻⁴X, s → δS, so ε_N = K δ⁻⁵; the
/// independent mpmath reference finds K constant to 1e-33 between δ = 30 and 100
/// (`tests/reference/README.md`). Used where the creep is not followed (δ > [`CREEP_DELTA_LIMIT`]
/// or ε_N below [`OVERDAMPED_THRESHOLD`]): those contacts are reported overdamped with this value
/// and an unresolved (infinite) duration.
pub const ZERO_OVERLAP_CREEP_COEFFICIENT: f64 = 0.679_293_063_936_485_3;

/// K δ⁻⁵, the zero-overlap creep asymptote.
pub fn creep_eps(delta: f64) -> f64 {
    let d2 = delta * delta;
    ZERO_OVERLAP_CREEP_COEFFICIENT / (d2 * d2 * delta)
}

/// The relative tolerance on the decayed total force, as a multiple of the integrator's rtol: the
/// safety factor between a level's bound and its rtol ([`crate::Accuracy::integrator_rtol`]), so
/// the contact's duration comes out to about the level's bound (see [`ForceTail`]).
const FORCE_TAIL_RTOL_FACTOR: f64 = 1e3;

/// Result of one dimensionless viscoelastic collision.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dimensionless {
    /// ε_N = −x'(s_c).
    pub eps: f64,
    /// Contact duration in units of τ.
    pub s_c: f64,
    /// Maximum compression in units of ξ*.
    pub x_max: f64,
    /// Right-hand-side evaluations used.
    pub rhs_evaluations: usize,
}

/// Eq. (4) in `σ = √s`, with state `(x, w)`.
///
/// * Velocity form (δ ≤ 1): `w = v = dx/ds`; `dx/dσ = 2σ v`, `dv/dσ = −2σ √x (x + 1.5 δ v)`.
/// * Force form (δ > 1): `w = h = x + 1.5 δ v`, the total force divided by √x. Then
///   `v = (h − x)/(1.5 δ)`, `dh/ds = v − 1.5 δ √x h`. For strong damping the rebound speed is a
///   tiny difference `x + 1.5 δ v ≈ 0`; carrying `h` itself keeps its digits, and at the force-zero
///   event ε_N = x/(1.5 δ) exactly, without cancellation.
struct Viscoelastic {
    /// 1.5 δ.
    k: f64,
    force_form: bool,
    /// Separation speed below which a creeping zero-overlap contact is abandoned (0: never).
    creep_floor: f64,
    /// The error scale of h on its way to the force-zero end (`None`: the usual mixed scale).
    force_tail: Option<ForceTail>,
}

/// How the error of the total force h is measured in the force form until the force vanishes
/// (docs/physics.md#accuracy, "strong damping").
///
/// For strong damping h falls from 1.5 δ at the impact through ~(10/3) ln δ e-foldings to its zero
/// (docs/physics.md#decision-2) while x stays nearly at x_max. Measured relative to itself all the
/// way down (the usual scale), each e-folding costs ~40 steps at rtol 1e-11. What h's error does:
/// * to x, hence ε_N = x/(1.5 δ): an error e in h is an error e/(1.5 δ) in x', which the overdamped
///   motion forgets at the rate 1.5 δ √x; x is kept to rtol when e ≤ rtol · max(|h|, 1.5 δ/10),
///   i.e. relative to h while it is large (the loading) and absolute once it has fallen below a
///   tenth of its start;
/// * to the end of contact: h crosses zero where its decaying transient meets the slow manifold's
///   level |h| ≈ √x/(1.5 δ)², so a relative error r of the transient moves the event by
///   r/(1.5 δ √x) in s, a relative error of about r/(3 ln δ) in s_c: r = [`FORCE_TAIL_RTOL_FACTOR`]
///   · rtol keeps s_c within about the level's bound.
///
/// The scale is the tighter of the two (both hold), floored at the smaller of the usual absolute
/// tolerance and a tenth of r times the slow manifold's |h|.
/// Measured against the independent references (`tests/data/viscoelastic.csv`,
/// `tests/data/strong_damping.csv`) by test `integrated_level_resolves_strong_damping_issue_26`.
#[derive(Debug, Clone, Copy)]
struct ForceTail {
    /// Relative tolerance on h once it has fallen below a tenth of its start.
    rtol: f64,
    /// Smallest scale: at the end of contact h is of order √x/(1.5 δ)².
    floor: f64,
}

impl Viscoelastic {
    fn new(delta: f64) -> Self {
        Viscoelastic {
            k: 1.5 * delta,
            force_form: delta > 1.0,
            creep_floor: CREEP_FLOOR,
            force_tail: None,
        }
    }

    /// dx/ds from the state.
    #[inline]
    fn velocity(&self, y: &[f64; 2]) -> f64 {
        if self.force_form {
            (y[1] - y[0]) / self.k
        } else {
            y[1]
        }
    }

    /// x + 1.5 δ v from the state.
    #[inline]
    fn force(&self, y: &[f64; 2]) -> f64 {
        if self.force_form {
            y[1]
        } else {
            y[0] + self.k * y[1]
        }
    }

    fn initial(&self) -> [f64; 2] {
        [0.0, if self.force_form { self.k } else { 1.0 }]
    }
}

// Event indices.
const MAX: usize = 0; // v = 0 falling: maximum compression
const FORCE_ZERO: usize = 1; // x + 1.5 δ v = 0 falling: total force vanishes
const OVERLAP_ZERO: usize = 2; // x = 0 falling
const CREEP: usize = 3; // v = −CREEP_FLOOR rising: a zero-overlap contact creeps to rest

impl OdeSystem<2, 4> for Viscoelastic {
    #[inline]
    fn rhs(&self, sigma: f64, y: &[f64; 2], dydt: &mut [f64; 2]) {
        let x = y[0].max(0.0);
        let two_sigma = 2.0 * sigma;
        let v = self.velocity(y);
        dydt[0] = two_sigma * v;
        // Eq. (4), dimensionless: v' = −√x (x + 1.5 δ v).
        dydt[1] = if self.force_form {
            two_sigma * (v - self.k * sqrt(x) * y[1])
        } else {
            -two_sigma * sqrt(x) * (x + self.k * y[1])
        };
    }

    #[inline]
    fn events(&self, _sigma: f64, y: &[f64; 2], out: &mut [f64; 4]) {
        let v = self.velocity(y);
        out[MAX] = if self.force_form { y[1] - y[0] } else { v };
        out[FORCE_ZERO] = self.force(y);
        out[OVERLAP_ZERO] = y[0];
        out[CREEP] = v + self.creep_floor;
    }

    #[inline]
    fn error_scale(&self, i: usize, y: &[f64; 2], y_new: &[f64; 2], tol: &Tolerances<2>) -> f64 {
        match self.force_tail {
            Some(tail) if i == 1 => {
                let h = y[1].abs().max(y_new[1].abs());
                (tol.rtol * h.max(0.1 * self.k))
                    .min(tail.rtol * h)
                    .max(tail.floor)
            }
            _ => tol.atol[i] + tol.rtol * y[i].abs().max(y_new[i].abs()),
        }
    }

    fn direction(&self, which: usize) -> Direction {
        if which == CREEP {
            Direction::Rising
        } else {
            Direction::Falling
        }
    }
}

/// Integrates the dimensionless Eq. (4) for damping `delta ≥ 0` with relative tolerance `rtol`.
#[doc(alias = "Eq. (4)")]
pub fn dimensionless(delta: f64, end: ContactEnd, rtol: f64) -> Result<Dimensionless> {
    dimensionless_with_budget(delta, end, rtol, MAX_STEPS, CREEP_DELTA_LIMIT)
}

/// [`dimensionless`] with an explicit step budget and creep limit (for tests of the creep regime).
pub fn dimensionless_with_budget(
    delta: f64,
    end: ContactEnd,
    rtol: f64,
    max_steps: usize,
    creep_delta_limit: f64,
) -> Result<Dimensionless> {
    integrate(
        delta,
        end,
        rtol,
        max_steps,
        creep_delta_limit,
        CREEP_FLOOR,
        &mut Nothing,
    )
}

/// [`dimensionless`], handing every accepted step to `recorder` (the collision trajectory).
#[cfg_attr(not(feature = "alloc"), allow(dead_code))]
pub(crate) fn dimensionless_recorded(
    delta: f64,
    end: ContactEnd,
    rtol: f64,
    recorder: &mut dyn Recorder,
) -> Result<Dimensionless> {
    integrate(
        delta,
        end,
        rtol,
        MAX_STEPS,
        CREEP_DELTA_LIMIT,
        CREEP_FLOOR,
        recorder,
    )
}

/// A zero-overlap contact followed through its whole creep, however slow (for building the tables,
/// which need the duration where ε_N is still above [`OVERDAMPED_THRESHOLD`] and a little beyond).
pub fn dimensionless_through_creep(
    delta: f64,
    end: ContactEnd,
    rtol: f64,
    max_steps: usize,
) -> Result<Dimensionless> {
    integrate(
        delta,
        end,
        rtol,
        max_steps,
        f64::INFINITY,
        0.0,
        &mut Nothing,
    )
}

// Long by design: one adaptive integration of Eq. (4) with its end-of-contact events and dense
// output; the state is shared by every branch.
fn integrate(
    delta: f64,
    end: ContactEnd,
    rtol: f64,
    max_steps: usize,
    creep_delta_limit: f64,
    creep_floor: f64,
    recorder: &mut dyn Recorder,
) -> Result<Dimensionless> {
    if !(delta.is_finite() && delta >= 0.0) {
        return Err(Error::OutOfRange {
            field: "delta",
            value: delta,
            expected: "must be a finite number >= 0",
        });
    }
    let mut sys = Viscoelastic {
        creep_floor,
        ..Viscoelastic::new(delta)
    };
    // Natural σ scale: 1 when elastic forces dominate, δ^(-1/3) when damping does.
    let sigma_scale = if delta > 1.0 {
        powf(delta, -1.0 / 3.0)
    } else {
        1.0
    };
    let x_scale = sigma_scale * sigma_scale;
    let w_atol = if sys.force_form {
        // h runs from 1.5 δ down through 0 near x ~ x_scale.
        rtol * 1e-3 * x_scale
    } else {
        rtol * 1e-6
    };
    let tol = Tolerances {
        rtol,
        atol: [rtol * 1e-3 * x_scale, w_atol],
        max_steps,
    };
    // Only where the force-zero event ends the contact: a creeping zero-overlap contact's end
    // ε = −x' = h/(1.5 δ) at x = 0 needs h to rtol relative to itself, as the usual scale has it.
    let ends_at_force_zero = end == ContactEnd::ForceZero || delta > creep_delta_limit;
    if sys.force_form && ends_at_force_zero {
        let tail_rtol = FORCE_TAIL_RTOL_FACTOR * rtol;
        sys.force_tail = Some(ForceTail {
            rtol: tail_rtol,
            floor: w_atol.min(0.1 * tail_rtol * sqrt(x_scale) / (sys.k * sys.k)),
        });
    }
    // A zero-overlap contact can creep for a dimensionless time of order δ.
    let sigma_end = 1e3 * (1.0 + sqrt(delta));
    let mut stepper = Dopri5::new(
        &sys,
        0.0,
        sys.initial(),
        sigma_end,
        0.05 * sigma_scale,
        tol,
        "viscoelastic contact",
    );
    let map = StateMap {
        sigma_clock: true,
        s_offset: 0.0,
        x_offset: 0.0,
        force_k: sys.force_form.then_some(sys.k),
        kind: Kind::Bulk,
    };
    let mut x_max = 0.0;
    let mut creeping = false;
    let done = |eps: f64, s_c: f64, x_max: f64, evals: usize| Dimensionless {
        eps,
        s_c,
        x_max,
        rhs_evaluations: evals,
    };
    loop {
        let outcome = match stepper.step(&sys) {
            Err(Error::StepBudgetExceeded { .. }) if creeping => {
                return Ok(done(
                    creep_eps(delta),
                    f64::INFINITY,
                    x_max,
                    stepper.rhs_evaluations(),
                ));
            }
            other => other?,
        };
        recorder.step(&stepper.dense_step(), &map);
        match outcome {
            StepOutcome::Step => {}
            StepOutcome::Event { t, y, which } => {
                let v = sys.velocity(&y);
                match (which, end) {
                    (MAX, _) => x_max = y[0],
                    (FORCE_ZERO, ContactEnd::ZeroOverlap)
                        if -v < creep_floor || delta > creep_delta_limit =>
                    {
                        // ε_N ≤ |x'| here < OVERDAMPED_THRESHOLD (or, beyond the creep limit,
                        // K δ⁻⁵): no need to follow the slow creep.
                        return Ok(done(
                            creep_eps(delta),
                            f64::INFINITY,
                            x_max,
                            stepper.rhs_evaluations(),
                        ));
                    }
                    (FORCE_ZERO, ContactEnd::ZeroOverlap) => creeping = true,
                    (FORCE_ZERO, ContactEnd::ForceZero) => {
                        // At h = 0, v = −x/(1.5 δ) exactly.
                        let eps = if sys.force_form { y[0] / sys.k } else { -v };
                        // δ ≥ 0 dissipates: the exact ε lies in [0, 1]; clamping only removes
                        // integration error (at δ → 0 it could exceed 1 by the tolerance).
                        return Ok(done(
                            eps.clamp(0.0, 1.0),
                            t * t,
                            x_max,
                            stepper.rhs_evaluations(),
                        ));
                    }
                    (OVERLAP_ZERO, ContactEnd::ZeroOverlap) => {
                        return Ok(done(
                            (-v).clamp(0.0, 1.0),
                            t * t,
                            x_max,
                            stepper.rhs_evaluations(),
                        ));
                    }
                    (CREEP, ContactEnd::ZeroOverlap) if x_max > 0.0 => {
                        // The tensile viscous force holds the grains: ε_N < CREEP_FLOOR.
                        return Ok(done(
                            creep_eps(delta),
                            f64::INFINITY,
                            x_max,
                            stepper.rhs_evaluations(),
                        ));
                    }
                    _ => {}
                }
            }
            StepOutcome::Done if end == ContactEnd::ZeroOverlap && x_max > 0.0 => {
                // Creeping towards zero overlap without reaching it within the time limit.
                return Ok(done(
                    creep_eps(delta),
                    f64::INFINITY,
                    x_max,
                    stepper.rhs_evaluations(),
                ));
            }
            StepOutcome::Done => {
                return Err(Error::StepBudgetExceeded {
                    what: "viscoelastic contact (no separation before the time limit)",
                    steps: 0,
                });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elastic_limit_matches_hertz_closed_forms() {
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            let r = dimensionless(0.0, end, 1e-12).unwrap();
            assert!((r.eps - 1.0).abs() < 1e-11, "{end:?}: eps = {}", r.eps);
            // Hertz: x_max = (5/4)^(2/5), s_c = 3.21806545971904.
            assert!(
                (r.x_max - libm::pow(1.25, 0.4)).abs() < 1e-11,
                "{}",
                r.x_max
            );
            assert!((r.s_c - 3.21806545971904).abs() < 1e-10, "{}", r.s_c);
        }
    }

    #[test]
    fn zero_overlap_creep_follows_inverse_fifth_power() {
        // Followed to the end (no creep cut), ε_N δ⁵ equals the asymptote's K: this justifies
        // reporting K δ⁻⁵ where the creep is not followed.
        for delta in [30.0, 40.0] {
            let r = dimensionless_with_budget(
                delta,
                ContactEnd::ZeroOverlap,
                1e-12,
                4_000_000,
                f64::INFINITY,
            )
            .unwrap();
            assert!(r.s_c.is_finite(), "δ = {delta} should separate");
            let k = r.eps * libm::pow(delta, 5.0);
            assert!(
                (k / ZERO_OVERLAP_CREEP_COEFFICIENT - 1.0).abs() < 1e-6,
                "δ = {delta}: {k}"
            );
        }
        assert!(creep_eps(CREEP_DELTA_LIMIT) < OVERDAMPED_THRESHOLD);
        // Beyond the limit the asymptote is reported (overdamped), continuous with it.
        let cut = dimensionless(2.0 * CREEP_DELTA_LIMIT, ContactEnd::ZeroOverlap, 1e-10).unwrap();
        assert_eq!(cut.eps, creep_eps(2.0 * CREEP_DELTA_LIMIT));
    }
}
