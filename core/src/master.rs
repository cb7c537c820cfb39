//! The fast path: the viscoelastic master curve tabulated once on the dimensionless form.
//!
//! ε_N, s_c = t_c/τ and x_max = ξ_max/ξ* depend on δ alone (DESIGN.md decision 3), so one table
//! serves every material, speed and damping time. For each contact-end rule, ln ε, ln s_c and ln x_max
//! are stored as piecewise Chebyshev series in u = log₁₀ δ on segments of [`U_MIN`, `U_MAX`]. The
//! coefficients live in the generated file `master_table.rs` (regenerate with
//! `cargo run --release -p rime-core --example generate_master_table`; the test
//! `master_table_matches_a_fresh_generation` fails when the committed table is stale). Evaluation needs
//! no allocation and no integration: one logarithm, three Clenshaw sums and three exponentials.
//!
//! Below `U_MIN` the curve is linear in δ (ε = 1 − 1.5 C1 δ + O(δ²), Schwager & Pöschel 1998) and at
//! δ = 0 exactly elastic. Above the force-zero table's end ε < 1e-11 (overdamped); above the
//! zero-overlap table's end the creeping contact is overdamped (see
//! [`crate::normal::viscoelastic::CREEP_DELTA_LIMIT`]).

use crate::math::powf;
use crate::normal::viscoelastic::Dimensionless;
use crate::scene::ContactEnd;

/// Lower end of the tables in u = log₁₀ δ.
pub const U_MIN: f64 = -9.0;
/// Upper end of the force-zero table in u = log₁₀ δ.
pub const U_MAX_FORCE_ZERO: f64 = 7.0;
/// Upper end of the zero-overlap table in u = log₁₀ δ (ε ≈ 2e-8 there).
pub const U_MAX_ZERO_OVERLAP: f64 = 1.5;
/// Width of one segment in u.
pub const SEGMENT: f64 = 0.125;
/// Chebyshev coefficients per segment.
pub const DEGREE: usize = 16;

/// Number of segments of a table spanning `[U_MIN, u_max]`.
pub const fn segments(u_max: f64) -> usize {
    ((u_max - U_MIN) / SEGMENT) as usize
}

/// One table: for each segment, Chebyshev coefficients of (ln ε, ln s_c, ln x_max).
pub struct Table {
    /// Upper end in u.
    pub u_max: f64,
    /// `coefficients[segment][quantity][k]`.
    pub coefficients: &'static [[[f64; DEGREE]; 3]],
}

#[allow(clippy::all, missing_docs)]
mod generated {
    include!("master_table.rs");
}

/// The force-zero table.
pub static FORCE_ZERO: Table = Table {
    u_max: U_MAX_FORCE_ZERO,
    coefficients: &generated::FORCE_ZERO,
};

/// The zero-overlap table.
pub static ZERO_OVERLAP: Table = Table {
    u_max: U_MAX_ZERO_OVERLAP,
    coefficients: &generated::ZERO_OVERLAP,
};

/// The table of a contact-end rule.
pub fn table(end: ContactEnd) -> &'static Table {
    match end {
        ContactEnd::ForceZero => &FORCE_ZERO,
        ContactEnd::ZeroOverlap => &ZERO_OVERLAP,
    }
}

#[inline]
fn clenshaw(c: &[f64; DEGREE], t: f64) -> f64 {
    let (mut b1, mut b2) = (0.0, 0.0);
    let t2 = 2.0 * t;
    for &ck in c[1..].iter().rev() {
        let b0 = ck + t2 * b1 - b2;
        b2 = b1;
        b1 = b0;
    }
    c[0] + t * b1 - b2
}

/// Evaluates the master curve at `delta ≥ 0` from the table (no integration).
#[inline]
pub fn lookup(delta: f64, end: ContactEnd) -> Dimensionless {
    let table = table(end);
    let (hertz_s, hertz_x) = (
        crate::analytic::HERTZ_CONTACT_TIME,
        crate::analytic::HERTZ_MAX_COMPRESSION,
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
    let u = libm::log10(delta);
    if u < U_MIN {
        // Schwager–Pöschel: ε = 1 − 1.5 C1 δ + O(δ²), O(δ²) < 2e-18 here; s_c and x_max are
        // elastic to within O(δ) < 1e-9 relative... and are only used for t_c and ξ_max.
        return point(
            1.0 - crate::analytic::SMALL_DELTA_SLOPE * delta,
            hertz_s,
            hertz_x,
        );
    }
    if u >= table.u_max {
        let beyond = u - table.u_max;
        let eps = tail_eps(table, end, delta, beyond);
        let s_c = if eps == 0.0 {
            f64::INFINITY
        } else {
            libm::exp(table_ln(table, table.u_max, 1))
        };
        // x_max ∝ δ^(-2/3) in the overdamped regime.
        let x_max = libm::exp(table_ln(table, table.u_max, 2)) * powf(10.0, -2.0 / 3.0 * beyond);
        return point(eps, s_c, x_max);
    }
    let (seg, t) = locate(u);
    let c = &table.coefficients[seg];
    point(
        libm::exp(clenshaw(&c[0], t)),
        libm::exp(clenshaw(&c[1], t)),
        libm::exp(clenshaw(&c[2], t)),
    )
}

/// ε beyond the table's upper end: the measured power laws ε ∝ δ^(-5/3) (force zero) and
/// ε ∝ δ^(-5) (zero overlap), cut to 0 where the precise path reports an abandoned creep.
fn tail_eps(table: &Table, end: ContactEnd, delta: f64, beyond: f64) -> f64 {
    let slope = match end {
        ContactEnd::ForceZero => -5.0 / 3.0,
        ContactEnd::ZeroOverlap => -5.0,
    };
    let eps = libm::exp(table_ln(table, table.u_max, 0)) * powf(10.0, slope * beyond);
    let creep_cut = end == ContactEnd::ZeroOverlap
        && (eps < crate::normal::OVERDAMPED_THRESHOLD
            || delta > crate::normal::viscoelastic::CREEP_DELTA_LIMIT);
    if creep_cut { 0.0 } else { eps }
}

/// ε only (the hot path of curves and maps).
#[inline]
pub fn eps(delta: f64, end: ContactEnd) -> f64 {
    let table = table(end);
    if !(delta > 0.0) {
        return 1.0;
    }
    let u = libm::log10(delta);
    if u < U_MIN || u >= table.u_max {
        return lookup(delta, end).eps;
    }
    let (seg, t) = locate(u);
    libm::exp(clenshaw(&table.coefficients[seg][0], t))
}

#[inline]
fn locate(u: f64) -> (usize, f64) {
    let x = (u - U_MIN) / SEGMENT;
    let seg = x as usize;
    let t = 2.0 * (x - seg as f64) - 1.0;
    (seg, t)
}

/// ln of quantity `q` (0: ε, 1: s_c, 2: x_max) at `u` inside or at the ends of the table.
fn table_ln(table: &Table, u: f64, q: usize) -> f64 {
    let n = table.coefficients.len();
    let x = ((u - U_MIN) / SEGMENT).clamp(0.0, n as f64);
    let seg = (x as usize).min(n - 1);
    let t = 2.0 * (x - seg as f64) - 1.0;
    clenshaw(&table.coefficients[seg][q], t)
}

/// Generates the table source (the body of `master_table.rs`) with the precise integrator.
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
    for (name, end, u_max) in [
        ("FORCE_ZERO", ContactEnd::ForceZero, U_MAX_FORCE_ZERO),
        ("ZERO_OVERLAP", ContactEnd::ZeroOverlap, U_MAX_ZERO_OVERLAP),
    ] {
        let n = segments(u_max);
        let _ = writeln!(out, "pub static {name}: [[[f64; {DEGREE}]; 3]; {n}] = [");
        for seg in 0..n {
            let coeffs = fit_segment(end, U_MIN + seg as f64 * SEGMENT)?;
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

/// Chebyshev interpolation of one segment at DEGREE Chebyshev nodes (first kind).
#[cfg(feature = "std")]
fn fit_segment(end: ContactEnd, u0: f64) -> crate::Result<[[f64; DEGREE]; 3]> {
    use core::f64::consts::PI;
    let n = DEGREE;
    let mut values = [[0.0; DEGREE]; 3];
    for j in 0..n {
        let t = libm::cos(PI * (j as f64 + 0.5) / n as f64);
        let u = u0 + 0.5 * (t + 1.0) * SEGMENT;
        let r = crate::normal::viscoelastic::dimensionless(powf(10.0, u), end, 1e-14)?;
        values[0][j] = libm::log(r.eps);
        values[1][j] = libm::log(r.s_c);
        values[2][j] = libm::log(r.x_max);
    }
    let mut coeffs = [[0.0; DEGREE]; 3];
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
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            let mut u = U_MIN + 0.0123;
            while u < table(end).u_max {
                let delta = powf(10.0, u);
                let fast = lookup(delta, end);
                let precise = dimensionless(delta, end, 1e-13).unwrap();
                if precise.eps > 1e-6 {
                    worst[0] = worst[0].max(rel(fast.eps, precise.eps));
                    worst[1] = worst[1].max(rel(fast.s_c, precise.s_c));
                    worst[2] = worst[2].max(rel(fast.x_max, precise.x_max));
                    assert_eq!(eps(delta, end), fast.eps);
                }
                u += 0.1 * core::f64::consts::SQRT_2;
            }
        }
        assert!(worst[0] < 1e-10, "ε: {worst:?}");
        assert!(worst[1] < 1e-8 && worst[2] < 1e-8, "{worst:?}");
    }

    #[test]
    fn below_the_table_the_curve_is_linear_in_delta() {
        // 1 − ε ≈ 1.5 C1 δ (Schwager–Pöschel) far below the table.
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            // Continuity at the table's lower end: the table (built by integration) and the
            // first-order series meet to within the integrator's absolute error.
            let at = powf(10.0, U_MIN);
            let above = lookup(at * (1.0 + 1e-12), end).eps;
            let below = lookup(at * (1.0 - 1e-12), end).eps;
            assert!((above - below).abs() < 1e-12, "{above} vs {below}");
            assert_eq!(eps(0.0, end), 1.0);
            let l = lookup(1e-13, end);
            assert!(rel(l.s_c, crate::analytic::HERTZ_CONTACT_TIME) < 1e-11);
        }
    }

    #[test]
    fn far_above_the_table_the_coefficient_is_overdamped() {
        let d = 1e8;
        let fz = lookup(d, ContactEnd::ForceZero);
        // ε → (2/3) δ^(-5/3) for strong damping (measured; consistent with the power-law tail).
        assert!(
            rel(fz.eps, 2.0 / 3.0 * powf(d, -5.0 / 3.0)) < 1e-3,
            "{}",
            fz.eps
        );
        assert!(fz.eps < crate::normal::OVERDAMPED_THRESHOLD);
        assert_eq!(lookup(1e3, ContactEnd::ZeroOverlap).eps, 0.0);
    }

    #[cfg(feature = "std")]
    #[test]
    fn master_table_matches_a_fresh_generation() {
        let fresh = generate_source().unwrap();
        let committed = include_str!("master_table.rs");
        assert!(
            fresh == committed,
            "core/src/master_table.rs is stale: regenerate it with \
             `cargo run --release -p rime-core --example generate_master_table > core/src/master_table.rs`"
        );
    }
}
