//! The fast path: the viscoelastic master curve tabulated once on the dimensionless form.
//!
//! ε_N, s_c = t_c/τ and x_max = ξ_max/ξ* depend on δ alone (docs/physics.md#decision-3), so one table
//! serves every material, speed and damping time. For each contact-end rule, ln ε, ln s_c and ln x_max
//! are stored as piecewise Chebyshev series in u = log₁₀ δ on equal segments of [`U_MIN`, u_max],
//! built from the Dormand–Prince integrator at rtol 1e-14 and stored in the generated file
//! `master_table.rs` (regenerate with `cargo run --release -p rime-core --example
//! generate_master_table > core/src/normal/viscoelastic/master_table.rs`; the test `master_table_matches_a_fresh_generation`
//! fails when the committed table is stale). Two resolutions:
//!
//! * [`Resolution::Fine`] (16 coefficients per ⅛ decade, used by [`crate::Accuracy::Precise`]):
//!   relative error ≤ 1e-10 wherever ε > 1e-6, checked against the integrator and against the
//!   independent mpmath reference of `tests/reference/`;
//! * [`Resolution::Coarse`] (7 coefficients per ⅛ decade, used by [`crate::Accuracy::Fast`]):
//!   relative error ≤ 1e-6 with half the Clenshaw chain of the fine table (≈ 45 ns per ε_N).
//!
//! Evaluation needs no allocation and no integration: one logarithm, a Clenshaw sum and an
//! exponential per quantity.
//!
//! Below `U_MIN` the curve is linear in δ (ε = 1 − 1.5 C1 δ + O(δ²), Schwager & Pöschel 1998) and at
//! δ = 0 exactly elastic. Above the table's end ε follows the strong-damping asymptotes
//! ε ≈ (2/3) δ^(-5/3) (force zero; below 1e-11 there) and ε = K δ⁻⁵ (zero overlap, see
//! [`crate::normal::viscoelastic::creep_eps`]); the force-zero duration is
//! [`strong_damping_duration`], which grows with ln δ.

use crate::normal::viscoelastic::Dimensionless;
use crate::numerics::math::{exp, log10, powf};
use crate::scene::ContactEnd;

/// Lower end of the tables in u = log₁₀ δ.
pub const U_MIN: f64 = -9.0;
/// Upper end of the force-zero tables in u = log₁₀ δ.
pub const U_MAX_FORCE_ZERO: f64 = 7.0;
/// Upper end of the zero-overlap tables in u = log₁₀ δ (δ ≈ 75, ε ≈ 2.8e-10 there): past the
/// δ ≈ 58.9 where ε falls below [`crate::normal::OVERDAMPED_THRESHOLD`] and the duration is no
/// longer resolved, so that every resolved duration comes from the table.
pub const U_MAX_ZERO_OVERLAP: f64 = 1.875;
/// Segment width of the fine tables in u.
pub const FINE_SEGMENT: f64 = 0.125;
/// Chebyshev coefficients per segment of the fine tables.
pub const FINE_DEGREE: usize = 16;
/// Segment width of the coarse tables in u (⅛ decade: short series keep the hot path short).
pub const COARSE_SEGMENT: f64 = 0.125;
/// Chebyshev coefficients per segment of the coarse tables.
pub const COARSE_DEGREE: usize = 7;

/// Which table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Resolution {
    /// 7 coefficients per ⅛ decade: relative error ≤ 1e-6.
    Coarse,
    /// 16 coefficients per ⅛ decade: relative error ≤ 1e-10.
    Fine,
}

/// Number of segments of width `segment` spanning `[U_MIN, u_max]`.
pub const fn segments(u_max: f64, segment: f64) -> usize {
    ((u_max - U_MIN) / segment) as usize
}

/// One table: for each segment, Chebyshev coefficients of (ln ε, ln s_c, ln x_max).
pub struct Table<const D: usize> {
    /// Upper end in u.
    pub u_max: f64,
    /// Segment width in u.
    pub segment: f64,
    /// Segments per unit of u (1 / segment: the hot path multiplies instead of dividing).
    pub segments_per_unit: f64,
    /// The contact-end rule it tabulates.
    pub end: ContactEnd,
    /// `coefficients[segment][quantity][k]`.
    pub coefficients: &'static [[[f64; D]; 3]],
}

#[allow(clippy::all, missing_docs)]
mod generated {
    include!("master_table.rs");
}

/// Fine force-zero table.
pub static FORCE_ZERO_FINE: Table<FINE_DEGREE> = Table {
    u_max: U_MAX_FORCE_ZERO,
    segment: FINE_SEGMENT,
    segments_per_unit: 1.0 / FINE_SEGMENT,
    end: ContactEnd::ForceZero,
    coefficients: &generated::FORCE_ZERO_FINE,
};
/// Fine zero-overlap table.
pub static ZERO_OVERLAP_FINE: Table<FINE_DEGREE> = Table {
    u_max: U_MAX_ZERO_OVERLAP,
    segment: FINE_SEGMENT,
    segments_per_unit: 1.0 / FINE_SEGMENT,
    end: ContactEnd::ZeroOverlap,
    coefficients: &generated::ZERO_OVERLAP_FINE,
};
/// Coarse force-zero table.
pub static FORCE_ZERO_COARSE: Table<COARSE_DEGREE> = Table {
    u_max: U_MAX_FORCE_ZERO,
    segment: COARSE_SEGMENT,
    segments_per_unit: 1.0 / COARSE_SEGMENT,
    end: ContactEnd::ForceZero,
    coefficients: &generated::FORCE_ZERO_COARSE,
};
/// Coarse zero-overlap table.
pub static ZERO_OVERLAP_COARSE: Table<COARSE_DEGREE> = Table {
    u_max: U_MAX_ZERO_OVERLAP,
    segment: COARSE_SEGMENT,
    segments_per_unit: 1.0 / COARSE_SEGMENT,
    end: ContactEnd::ZeroOverlap,
    coefficients: &generated::ZERO_OVERLAP_COARSE,
};

/// Runs `$body` with `$t` bound to the table of a contact-end rule and resolution (the tables have
/// different coefficient counts, hence a macro rather than a function returning one type).
macro_rules! with_table {
    ($end:expr, $resolution:expr, |$t:ident| $body:expr) => {
        match ($end, $resolution) {
            (ContactEnd::ForceZero, Resolution::Fine) => {
                let $t = &FORCE_ZERO_FINE;
                $body
            }
            (ContactEnd::ZeroOverlap, Resolution::Fine) => {
                let $t = &ZERO_OVERLAP_FINE;
                $body
            }
            (ContactEnd::ForceZero, Resolution::Coarse) => {
                let $t = &FORCE_ZERO_COARSE;
                $body
            }
            (ContactEnd::ZeroOverlap, Resolution::Coarse) => {
                let $t = &ZERO_OVERLAP_COARSE;
                $body
            }
        }
    };
}

/// `C` of [`strong_damping_duration`]: `(2/3) ln(27/8) + ln 3 − π/(3√3)`
/// (mpmath: 1.3049427168063658…).
pub const STRONG_DAMPING_DURATION_OFFSET: f64 = 1.304_942_716_806_366;

/// The force-zero contact duration s_c = t_c/τ for strong damping (δ ≫ 1):
/// `δ^(−2/3) ((20/9) ln δ + C)`, [`STRONG_DAMPING_DURATION_OFFSET`] = C, relative error
/// O(δ^(−5/3) ln² δ) (below 1e-10 from δ = 1e7; derivation in docs/physics.md#decision-2, checked
/// against the independent integration `tests/reference/strong_damping.py`).
pub fn strong_damping_duration(delta: f64) -> f64 {
    powf(delta, -2.0 / 3.0)
        * (20.0 / 9.0 * crate::numerics::math::ln(delta) + STRONG_DAMPING_DURATION_OFFSET)
}

/// Evaluates the master curve at `delta ≥ 0` (no integration).
#[inline]
pub fn lookup(delta: f64, end: ContactEnd, resolution: Resolution) -> Dimensionless {
    with_table!(end, resolution, |t| t.lookup(delta))
}

/// ε only at `u = log₁₀ δ` (the hot path: callers add logarithms instead of taking powers).
#[inline]
pub fn eps_log10(u: f64, end: ContactEnd, resolution: Resolution) -> f64 {
    with_table!(end, resolution, |t| t.eps_log10(u))
}

/// ε only (the hot path of curves and maps).
#[inline]
pub fn eps(delta: f64, end: ContactEnd, resolution: Resolution) -> f64 {
    with_table!(end, resolution, |t| t.eps(delta))
}

/// [`crate::numerics::math::clenshaw`] on one row of coefficients.
#[inline]
fn clenshaw<const D: usize>(c: &[f64; D], t: f64) -> f64 {
    crate::numerics::math::clenshaw(c, t)
}

impl<const D: usize> Table<D> {
    /// Evaluates ε, s_c and x_max at `delta ≥ 0`.
    #[inline]
    pub fn lookup(&self, delta: f64) -> Dimensionless {
        let (hertz_s, hertz_x) = (
            crate::normal::analytic::HERTZ_CONTACT_TIME,
            crate::normal::analytic::HERTZ_MAX_COMPRESSION,
        );
        let point = |eps: f64, s_c: f64, x_max: f64| Dimensionless {
            eps,
            s_c,
            x_max,
            rhs_evaluations: 0,
        };
        if !(delta > 0.0) {
            return point(1.0, hertz_s, hertz_x);
        }
        let u = log10(delta);
        if u < U_MIN {
            // Schwager–Pöschel: ε = 1 − 1.5 C1 δ + O(δ²), with O(δ²) < 2e-18 here; s_c and x_max
            // are elastic to O(δ) < 1e-9 relative.
            return point(
                1.0 - crate::normal::analytic::SMALL_DELTA_SLOPE * delta,
                hertz_s,
                hertz_x,
            );
        }
        if u >= self.u_max {
            return self.tail(delta, u);
        }
        let (seg, t) = self.locate(u);
        let c = &self.coefficients[seg];
        let eps = exp(clenshaw(&c[0], t));
        point(
            eps,
            self.resolved_duration(eps, exp(clenshaw(&c[1], t))),
            exp(clenshaw(&c[2], t)),
        )
    }

    /// The contact duration as reported: a zero-overlap contact whose ε is below
    /// [`crate::normal::OVERDAMPED_THRESHOLD`] creeps apart over an unboundedly long time, which the
    /// live integration does not follow either; both report it unresolved (infinite).
    #[inline]
    fn resolved_duration(&self, eps: f64, s_c: f64) -> f64 {
        if self.end == ContactEnd::ZeroOverlap && eps < crate::normal::OVERDAMPED_THRESHOLD {
            f64::INFINITY
        } else {
            s_c
        }
    }

    /// ε, s_c and x_max beyond the table's upper end: the strong-damping asymptotes.
    ///
    /// ε: `(2/3) δ^(−5/3)` continued from the end (force zero) or `K δ⁻⁵` (zero overlap).
    /// x_max: the maximum compression comes before either end rule applies, so both rules share it
    /// and a zero-overlap contact takes the force-zero value at every δ (issue 35: continuing the
    /// zero-overlap table's own end, at δ ≈ 75, as δ^(−2/3) left ξ_max 0.2283 % low past 1e7);
    /// past the force-zero table (δ > 1e7) it scales as δ^(−2/3). s_c: for force zero the closed
    /// form [`strong_damping_duration`] (it grows with ln δ: both the approach to the turning point
    /// and the relaxation of the force after it are exponential, docs/physics.md#decision-2); for
    /// zero overlap it is unresolved (ε < 1e-9 beyond the table).
    fn tail(&self, delta: f64, u: f64) -> Dimensionless {
        let eps = self.tail_eps(delta, u - self.u_max);
        let (x_max, s_c) = if self.end == ContactEnd::ZeroOverlap {
            (FORCE_ZERO_FINE.lookup(delta).x_max, f64::INFINITY)
        } else {
            let shrink = powf(10.0, -2.0 / 3.0 * (u - self.u_max));
            (
                exp(self.ln_at(self.u_max, 2)) * shrink,
                strong_damping_duration(delta),
            )
        };
        Dimensionless {
            eps,
            s_c: self.resolved_duration(eps, s_c),
            x_max,
            rhs_evaluations: 0,
        }
    }

    /// ε only.
    #[inline]
    pub fn eps(&self, delta: f64) -> f64 {
        if !(delta > 0.0) {
            return 1.0;
        }
        self.eps_log10(log10(delta))
    }

    /// ε only at `u = log₁₀ δ` (`u = −∞` is δ = 0).
    #[inline]
    pub fn eps_log10(&self, u: f64) -> f64 {
        if u >= U_MIN && u < self.u_max {
            let (seg, t) = self.locate(u);
            return exp(clenshaw(&self.coefficients[seg][0], t));
        }
        if u.is_nan() {
            return f64::NAN;
        }
        self.lookup(powf(10.0, u)).eps
    }

    /// ε beyond the upper end: the strong-damping asymptotes.
    fn tail_eps(&self, delta: f64, beyond: f64) -> f64 {
        match self.end {
            // Force zero: ε ∝ δ^(-5/3), continued from the table's end.
            ContactEnd::ForceZero => {
                exp(self.ln_at(self.u_max, 0)) * powf(10.0, -5.0 / 3.0 * beyond)
            }
            // Zero overlap: the creep asymptote K δ⁻⁵, exact beyond δ ≈ 30.
            ContactEnd::ZeroOverlap => crate::normal::viscoelastic::creep_eps(delta),
        }
    }

    #[inline]
    fn locate(&self, u: f64) -> (usize, f64) {
        let x = (u - U_MIN) * self.segments_per_unit;
        let seg = (x as usize).min(self.coefficients.len() - 1);
        let t = 2.0 * (x - seg as f64) - 1.0;
        (seg, t)
    }

    /// ln of quantity `q` (0: ε, 1: s_c, 2: x_max) at `u` inside or at the ends of the table.
    fn ln_at(&self, u: f64, q: usize) -> f64 {
        let n = self.coefficients.len();
        let x = ((u - U_MIN) / self.segment).clamp(0.0, n as f64);
        let seg = (x as usize).min(n - 1);
        let t = 2.0 * (x - seg as f64) - 1.0;
        clenshaw(&self.coefficients[seg][q], t)
    }
}

/// Generates the table source (the whole of `master_table.rs`) with the precise integrator.
#[cfg(feature = "std")]
pub fn generate_source() -> crate::Result<std::string::String> {
    use core::fmt::Write;
    use std::string::String;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "// Generated by `cargo run --release -p rime-core --example generate_master_table`. Do not edit.\n\
         // Chebyshev coefficients of (ln ε, ln s_c, ln x_max) on segments of u = log10 δ."
    );
    for (name, end, u_max, segment, degree) in [
        (
            "FORCE_ZERO_FINE",
            ContactEnd::ForceZero,
            U_MAX_FORCE_ZERO,
            FINE_SEGMENT,
            FINE_DEGREE,
        ),
        (
            "ZERO_OVERLAP_FINE",
            ContactEnd::ZeroOverlap,
            U_MAX_ZERO_OVERLAP,
            FINE_SEGMENT,
            FINE_DEGREE,
        ),
        (
            "FORCE_ZERO_COARSE",
            ContactEnd::ForceZero,
            U_MAX_FORCE_ZERO,
            COARSE_SEGMENT,
            COARSE_DEGREE,
        ),
        (
            "ZERO_OVERLAP_COARSE",
            ContactEnd::ZeroOverlap,
            U_MAX_ZERO_OVERLAP,
            COARSE_SEGMENT,
            COARSE_DEGREE,
        ),
    ] {
        let n = segments(u_max, segment);
        let _ = writeln!(out, "pub static {name}: [[[f64; {degree}]; 3]; {n}] = [");
        for seg in 0..n {
            let coeffs = fit_segment(end, U_MIN + seg as f64 * segment, segment, degree)?;
            let _ = writeln!(out, "    [");
            for q in coeffs {
                let _ = write!(out, "        [");
                for (k, c) in q.iter().enumerate() {
                    let _ = write!(out, "{}{c:e}", if k == 0 { "" } else { ", " });
                }
                let _ = writeln!(out, "],");
            }
            let _ = writeln!(out, "    ],");
        }
        let _ = writeln!(out, "];");
    }
    Ok(out)
}

/// Step budget of one node of the tables (the slowest, δ ≈ 75 with zero overlap, creeps longest).
#[cfg(feature = "std")]
const GENERATION_STEP_BUDGET: usize = 20_000_000;

/// Chebyshev interpolation of one segment at `degree` Chebyshev nodes (first kind).
#[cfg(feature = "std")]
fn fit_segment(
    end: ContactEnd,
    u0: f64,
    segment: f64,
    degree: usize,
) -> crate::Result<std::vec::Vec<std::vec::Vec<f64>>> {
    use core::f64::consts::PI;
    use std::vec;
    let n = degree;
    let mut values = vec![vec![0.0; n]; 3];
    for j in 0..n {
        let t = libm::cos(PI * (j as f64 + 0.5) / n as f64);
        let u = u0 + 0.5 * (t + 1.0) * segment;
        // Follow a zero-overlap creep to its end, however slow: the table needs its duration.
        let r = crate::normal::viscoelastic::dimensionless_through_creep(
            powf(10.0, u),
            end,
            1e-14,
            GENERATION_STEP_BUDGET,
        )?;
        if !r.s_c.is_finite() {
            return Err(crate::Error::StepBudgetExceeded {
                what: "master table generation: a creeping contact did not end",
                steps: GENERATION_STEP_BUDGET,
            });
        }
        values[0][j] = libm::log(r.eps);
        values[1][j] = libm::log(r.s_c);
        values[2][j] = libm::log(r.x_max);
    }
    let mut coeffs = vec![vec![0.0; n]; 3];
    for q in 0..3 {
        for k in 0..n {
            let mut s = 0.0;
            for j in 0..n {
                s += values[q][j] * libm::cos(PI * k as f64 * (j as f64 + 0.5) / n as f64);
            }
            coeffs[q][k] = s * if k == 0 { 1.0 } else { 2.0 } / n as f64;
        }
    }
    Ok(coeffs)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::normal::viscoelastic::dimensionless;

    fn rel(a: f64, b: f64) -> f64 {
        ((a - b) / b).abs()
    }

    #[test]
    fn table_matches_the_integrator_between_its_nodes() {
        // Off-node points (irrational steps in u) against a tighter integration than the one that
        // built the table's nodes would need.
        let mut worst = [0.0f64; 3];
        let mut worst_coarse = 0.0f64;
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            let mut u = U_MIN + 0.0123;
            let u_max = match end {
                ContactEnd::ForceZero => U_MAX_FORCE_ZERO,
                ContactEnd::ZeroOverlap => U_MAX_ZERO_OVERLAP,
            };
            while u < u_max {
                let delta = powf(10.0, u);
                let fast = lookup(delta, end, Resolution::Fine);
                let coarse = lookup(delta, end, Resolution::Coarse);
                let precise = dimensionless(delta, end, 1e-13).unwrap();
                if precise.eps > 1e-6 {
                    worst[0] = worst[0].max(rel(fast.eps, precise.eps));
                    worst_coarse = worst_coarse.max(rel(coarse.eps, precise.eps));
                    worst_coarse = worst_coarse.max(rel(coarse.s_c, precise.s_c));
                    worst_coarse = worst_coarse.max(rel(coarse.x_max, precise.x_max));
                    assert_eq!(eps(delta, end, Resolution::Coarse), coarse.eps);
                    worst[1] = worst[1].max(rel(fast.s_c, precise.s_c));
                    worst[2] = worst[2].max(rel(fast.x_max, precise.x_max));
                    assert_eq!(eps(delta, end, Resolution::Fine), fast.eps);
                }
                u += 0.1 * core::f64::consts::SQRT_2;
            }
        }
        assert!(worst[0] < 1e-10, "ε: {worst:?}");
        assert!(worst[1] < 1e-8 && worst[2] < 1e-8, "{worst:?}");
        assert!(worst_coarse < 1e-6, "coarse: {worst_coarse}");
    }

    #[test]
    fn tables_agree_with_live_integration_on_duration_and_compression_issue_10() {
        // Zero overlap at δ = 40 used to report the duration at the table's old end (26 % short)
        // and a power-law ξ_max: every quantity, at every δ the tables serve, against the
        // integrator at rtol 1e-13, including whether the duration is resolved at all.
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            let mut u = -9.0 + 0.0371;
            while u <= 7.0 {
                let delta = powf(10.0, u);
                let live = dimensionless(delta, end, 1e-13).unwrap();
                // Durations and compressions: 1e-7 (fine), 1e-6 (coarse); the integrator itself
                // resolves s_c deep in the overdamped regime to about 1e-8.
                for (resolution, bound) in [(Resolution::Fine, 1e-7), (Resolution::Coarse, 1e-6)] {
                    let table = lookup(delta, end, resolution);
                    let what = alloc::format!("{end:?} {resolution:?} δ = {delta:e}");
                    assert!(
                        rel(table.x_max, live.x_max) < bound,
                        "{what}: ξ_max {table:?} vs {live:?}"
                    );
                    assert_eq!(
                        table.s_c.is_finite(),
                        live.s_c.is_finite(),
                        "{what}: {table:?} vs {live:?}"
                    );
                    // Overdamped (ε < 1e-9), the total force crosses zero with slope ~x/(1.5 δ):
                    // the end of contact is ill-conditioned and both agree to 1e-5 there.
                    let duration_bound = if live.eps > 1e-9 { bound } else { 1e-5 };
                    if live.s_c.is_finite() {
                        assert!(
                            rel(table.s_c, live.s_c) < duration_bound,
                            "{what}: s_c {table:?} vs {live:?}"
                        );
                    }
                    if live.eps > 1e-6 {
                        assert!(
                            rel(table.eps, live.eps) < bound,
                            "{what}: ε {table:?} vs {live:?}"
                        );
                    } else {
                        assert!(
                            rel(table.eps, live.eps) < 1e-3,
                            "{what}: ε {table:?} vs {live:?}"
                        );
                    }
                }
                u += 0.173;
            }
        }
    }

    #[test]
    fn below_the_table_the_curve_is_linear_in_delta() {
        // 1 − ε ≈ 1.5 C1 δ (Schwager–Pöschel) far below the table.
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            // Continuity at the table's lower end: the table (built by integration) and the
            // first-order series meet to within the integrator's absolute error.
            let at = powf(10.0, U_MIN);
            let above = lookup(at * (1.0 + 1e-12), end, Resolution::Fine).eps;
            let below = lookup(at * (1.0 - 1e-12), end, Resolution::Fine).eps;
            assert!((above - below).abs() < 1e-12, "{above} vs {below}");
            assert_eq!(eps(0.0, end, Resolution::Coarse), 1.0);
            let l = lookup(1e-13, end, Resolution::Fine);
            assert!(rel(l.s_c, crate::normal::analytic::HERTZ_CONTACT_TIME) < 1e-11);
        }
    }

    #[test]
    fn far_above_the_table_the_coefficient_is_overdamped() {
        let d = 1e8;
        let fz = lookup(d, ContactEnd::ForceZero, Resolution::Fine);
        // ε → (2/3) δ^(-5/3) for strong damping (measured; consistent with the power-law tail).
        assert!(
            rel(fz.eps, 2.0 / 3.0 * powf(d, -5.0 / 3.0)) < 1e-3,
            "{}",
            fz.eps
        );
        assert!(fz.eps < crate::normal::OVERDAMPED_THRESHOLD);
        // Zero overlap: the creep asymptote K δ⁻⁵, continuous with the table at its end.
        let creep = crate::normal::viscoelastic::creep_eps;
        assert_eq!(
            lookup(1e3, ContactEnd::ZeroOverlap, Resolution::Coarse).eps,
            creep(1e3)
        );
        let end = powf(10.0, U_MAX_ZERO_OVERLAP);
        let inside = lookup(
            end * (1.0 - 1e-12),
            ContactEnd::ZeroOverlap,
            Resolution::Fine,
        )
        .eps;
        assert!(rel(inside, creep(end)) < 1e-8, "{inside} vs {}", creep(end));
    }

    #[test]
    fn issue_35_max_compression_agrees_between_the_end_rules_up_to_1e12() {
        // Why ξ_max cannot depend on the end rule: both rules integrate the same Eq. (4),
        // x'' + x^(3/2) + 1.5 δ √x x' = 0, and differ only in when they stop. The maximum is where
        // x' = 0; up to it x' ≥ 0, so the total force √x (x + 1.5 δ x') > 0 and x > 0: neither the
        // force-zero end (total force = 0) nor the zero-overlap end (x = 0) can come first. So the
        // two trajectories are the same function up to and past x_max, and the force-zero value
        // (the longer table, to δ = 1e7) is the zero-overlap one too.
        //
        // Independently, for strong damping: integrating once, x' = 1 − δ x^(3/2) − ∫x^(3/2) ds,
        // and the elastic integral is at most s·x^(3/2) ≤ s/δ over the approach time s ~ ln δ
        // δ^(−2/3), so x_max = δ^(−2/3) (1 + O(δ^(−5/3) ln δ)): δ^(2/3) x_max → 1, to < 1e-10
        // from δ = 1e7 on (δ^(−5/3) ln δ = 3.5e-11 there).
        for (resolution, bound) in [
            (Resolution::Fine, crate::Accuracy::Precise.error_bound()),
            (Resolution::Coarse, crate::Accuracy::Fast.error_bound()),
        ] {
            let mut u = -3.0 + 0.0173;
            while u <= 12.0 {
                let delta = powf(10.0, u);
                let force_zero = lookup(delta, ContactEnd::ForceZero, resolution).x_max;
                let zero_overlap = lookup(delta, ContactEnd::ZeroOverlap, resolution).x_max;
                assert!(
                    rel(zero_overlap, force_zero) <= bound,
                    "{resolution:?} δ = {delta:e}: zero overlap {zero_overlap:e}, force zero {force_zero:e}"
                );
                if delta >= 1e7 {
                    let asymptote = powf(delta, -2.0 / 3.0);
                    assert!(
                        rel(force_zero, asymptote) <= bound,
                        "{resolution:?} δ = {delta:e}: force zero {force_zero:e} vs δ^(−2/3) {asymptote:e}"
                    );
                }
                u += 0.0731;
            }
        }
    }

    #[test]
    fn issue_35_max_compression_of_the_issue_scene_is_the_force_zero_one_at_every_level() {
        // `rime eps --set bulk.damping.time=4004.4 --g 0.01 --set contact_end=zero_overlap`
        // gave ξ_max = 1.37932e-11 m; the force-zero rule's (and the true) value is 1.38248e-11 m.
        let mut scene = crate::scene::Preset::Ice.scene();
        scene.set("bulk.damping.time", "4004.4").unwrap();
        let at = |end: ContactEnd, accuracy: crate::Accuracy| {
            let mut s = scene;
            s.contact_end = end;
            crate::Contact::new(&s)
                .unwrap()
                .normal(0.01, accuracy)
                .unwrap()
                .xi_max
        };
        for accuracy in [
            crate::Accuracy::Fast,
            crate::Accuracy::Precise,
            crate::Accuracy::Balanced,
            crate::Accuracy::Tolerance(1e-8),
        ] {
            let force_zero = at(ContactEnd::ForceZero, accuracy);
            let zero_overlap = at(ContactEnd::ZeroOverlap, accuracy);
            assert!(
                rel(zero_overlap, force_zero) <= accuracy.error_bound(),
                "{accuracy:?}: {zero_overlap:e} vs {force_zero:e}"
            );
            assert!(
                (force_zero / 1.38248e-11 - 1.0).abs() < 5e-6,
                "{force_zero:e}"
            );
        }
    }

    #[cfg(feature = "std")]
    #[test]
    fn master_table_matches_a_fresh_generation() {
        // Compared number by number: the platform's exp/log may differ in the last bits, and the
        // highest coefficients carry the integrator's noise (~1e-12). A changed generator moves
        // coefficients by far more than 1e-9.
        let numbers = |text: &str| -> std::vec::Vec<f64> {
            text.lines()
                .filter(|l| l.trim_start().starts_with('['))
                .flat_map(|l| l.split(['[', ']', ',']))
                .filter_map(|t| t.trim().parse::<f64>().ok())
                .collect()
        };
        let fresh = numbers(&generate_source().unwrap());
        let committed = numbers(include_str!("master_table.rs"));
        assert_eq!(
            fresh.len(),
            committed.len(),
            "table shape changed: regenerate it"
        );
        for (a, b) in fresh.iter().zip(&committed) {
            assert!(
                (a - b).abs() <= 1e-9 * (1.0 + b.abs()),
                "core/src/normal/viscoelastic/master_table.rs is stale ({a} vs {b}): regenerate it with \
                 `cargo run --release -p rime-core --example generate_master_table > core/src/normal/viscoelastic/master_table.rs`"
            );
        }
    }
}
