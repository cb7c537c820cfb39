//! Soft surface layers: Eq. (6)–(10), in the two readings of docs/physics.md#decision-4.

use crate::error::Result;
use crate::math::{cbrt, ln, powf, sqrt};
use crate::ode::{Direction, Dopri5, OdeSystem, StepOutcome, Tolerances};
use crate::scene::ContactEnd;

/// Time to crush the layer in stage 1 (Eq. (8) top) from impact speed 1 through thickness `d`, in the
/// same units: `∫₀^d dx / (1 − λ x^(3/2))` with `r = λ d^(3/2) < 1` (Eq. (9) gives the integrand).
///
/// With `x = d w²` this is `2d ∫₀¹ w dw / (1 − r w³)`, evaluated by its series for small `r` and in
/// closed form (partial fractions) otherwise.
pub fn crush_time(d: f64, r: f64) -> f64 {
    crush_time_with_gap(d, r, 1.0 - r)
}

/// [`crush_time`] with `gap = 1 − r` supplied by the caller, who can often compute it without
/// cancellation (`(g − g_s)/g`): one ulp above the threshold `1 − r` rounds to 0 and the time, which
/// diverges only logarithmically, would come out infinite.
pub fn crush_time_with_gap(d: f64, r: f64, gap: f64) -> f64 {
    if d == 0.0 {
        return 0.0;
    }
    if r >= 1.0 && !(gap > 0.0) {
        return f64::INFINITY;
    }
    let integral = if r <= 0.5 {
        // Σ r^k / (3k + 2): 60 terms bring 0.5^60 ≈ 1e-18.
        let mut sum = 0.0;
        let mut rk = 1.0;
        for k in 0..60 {
            sum += rk / (3.0 * k as f64 + 2.0);
            rk *= r;
        }
        sum
    } else {
        // ∫₀¹ w/(1 − a³w³) dw = (1/a²) [F(a) − F(0)],
        // F(p) = (1/3)[−ln(1−p) + ½ ln(p²+p+1) − √3 atan((2p+1)/√3)].
        let a = cbrt(r);
        let f = |p: f64| {
            let s3 = sqrt(3.0);
            (-ln(1.0 - p) + 0.5 * ln(p * p + p + 1.0)
                - s3 * crate::math::atan((2.0 * p + 1.0) / s3))
                / 3.0
        };
        // −ln(1 − a) from the gap: 1 − a³ = (1 − a)(1 + a + a²).
        let one_minus_a = gap / (1.0 + a + a * a);
        let s3 = sqrt(3.0);
        let f_a = (-ln(one_minus_a) + 0.5 * ln(a * a + a + 1.0)
            - s3 * crate::math::atan((2.0 * a + 1.0) / s3))
            / 3.0;
        (f_a - f(0.0)) / (a * a)
    };
    2.0 * d * integral
}

/// Time to leave the layer on the way out (Eq. (8) top, integrated once as in Eq. (9)), in the
/// scales of the impact speed: from `x = d` to `x = 0` with `x' = −ε − λ x^(3/2)`, where `ε > 0` is
/// the final separation speed and `g_s = λ d^(3/2)`:
/// `T = ∫₀^d dx / (ε + λ x^(3/2)) = (2d/g_s) ∫₀¹ w dw / (b³ + w³)`, `b³ = ε/g_s`.
///
/// Closed form (partial fractions) for `b < 1.5`, the series `Σ (−1)^k b^(−3k−3)/(3k + 2)` above
/// (where the closed form cancels). Near the sticking threshold (ε → 0) the time grows like
/// ε^(−1/3): it is finite for every ε > 0 and integrating it step by step would not end.
pub fn exit_time(d: f64, g_s: f64, eps: f64) -> f64 {
    if d == 0.0 {
        return 0.0;
    }
    if !(eps > 0.0) {
        return f64::INFINITY;
    }
    if g_s == 0.0 {
        return d / eps;
    }
    let b = cbrt(eps / g_s);
    let integral = if b >= 1.5 {
        let b3 = b * b * b;
        let inv = 1.0 / b3;
        let mut term = inv;
        let mut sum = 0.0;
        for k in 0..60 {
            let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
            sum += sign * term / (3.0 * k as f64 + 2.0);
            term *= inv;
        }
        sum
    } else {
        let s3 = sqrt(3.0);
        let log_part = ln((1.0 - b + b * b) / ((1.0 + b) * (1.0 + b))) / (6.0 * b);
        let atan_part = (crate::math::atan((2.0 - b) / (b * s3)) + core::f64::consts::PI / 6.0)
            / (b * s3);
        log_part + atan_part
    };
    2.0 * d / g_s * integral
}

/// Result of a literal-reading layer collision, in units of the impact speed (ξ*, τ of that speed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LiteralOutcome {
    /// ε_N (0 when stuck).
    pub eps: f64,
    /// True when the layer stopped the grains (on the way in or out).
    pub stuck: bool,
    /// Contact duration (dimensionless, infinite when stuck).
    pub s_c: f64,
    /// Maximum compression (dimensionless).
    pub x_max: f64,
    /// Right-hand-side evaluations used.
    pub rhs_evaluations: usize,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Phase {
    /// `x ≤ d`: only the layer acts (Eq. (8) top).
    Layer,
    /// `x > d`: only the bulk acts, with ξ itself (Eq. (8) bottom, as printed).
    Bulk,
    /// Force-zero rule: the bulk force has vanished while separating; the grains coast to `x = d`.
    Coast,
}

/// Eq. (8) read literally, in `σ = √s` with the scales of the impact speed.
struct Literal {
    delta: f64,
    lambda: f64,
    d: f64,
    phase: Phase,
    /// The independent variable is σ = √s (from the start) rather than local time s − s₀.
    sigma_clock: bool,
}

const MAX: usize = 0;
const BOUNDARY: usize = 1;
const FORCE_ZERO: usize = 2;
const EXIT: usize = 3;

impl OdeSystem<2, 4> for Literal {
    fn rhs(&self, sigma: f64, y: &[f64; 2], dydt: &mut [f64; 2]) {
        // The state carries u = x − d: the bulk excursion beyond the layer is often tiny next to d,
        // and x itself would round it away.
        let x = (self.d + y[0]).max(0.0);
        // dt/dσ = 2σ while the clock is σ = √s (the singular start); 1 once it is local time.
        let two_sigma = if self.sigma_clock { 2.0 * sigma } else { 1.0 };
        dydt[0] = two_sigma * y[1];
        dydt[1] = match self.phase {
            // Eq. (8), top: ξ'' + (3/2)(√R/(K m)) √ξ ξ' = 0.
            Phase::Layer => -two_sigma * 1.5 * self.lambda * sqrt(x) * y[1],
            // Eq. (8), bottom, with ξ itself.
            Phase::Bulk => -two_sigma * sqrt(x) * (x + 1.5 * self.delta * y[1]),
            Phase::Coast => 0.0,
        };
    }

    fn events(&self, _sigma: f64, y: &[f64; 2], out: &mut [f64; 4]) {
        out[MAX] = y[1];
        out[BOUNDARY] = y[0];
        out[FORCE_ZERO] = if self.phase == Phase::Bulk {
            (self.d + y[0]) + 1.5 * self.delta * y[1]
        } else {
            1.0
        };
        out[EXIT] = self.d + y[0];
    }

    fn direction(&self, which: usize) -> Direction {
        match which {
            BOUNDARY => Direction::Either,
            _ => Direction::Falling,
        }
    }
}

/// The literal reading of Eq. (8): dimensionless damping `delta`, layer drag `lambda = c ξ*^(3/2)/g`
/// and thickness `d = D/ξ*` (both in the scales of the impact speed).
pub fn literal(
    delta: f64,
    lambda: f64,
    d: f64,
    end: ContactEnd,
    rtol: f64,
) -> Result<LiteralOutcome> {
    let g_s = lambda * d * sqrt(d); // Eq. (10) in units of the impact speed
    if g_s >= 1.0 {
        // Eq. (9): the layer stops the grains on the way in at x = λ^(-2/3).
        return Ok(LiteralOutcome {
            eps: 0.0,
            stuck: true,
            s_c: f64::INFINITY,
            x_max: powf(lambda, -2.0 / 3.0),
            rhs_evaluations: 0,
        });
    }
    let mut sys = Literal {
        delta,
        lambda,
        d,
        phase: if d > 0.0 { Phase::Layer } else { Phase::Bulk },
        sigma_clock: true,
    };
    let sigma_scale = if delta > 1.0 {
        powf(delta, -1.0 / 3.0)
    } else {
        1.0
    };
    let tol = Tolerances {
        rtol,
        atol: [rtol * 1e-3 * sigma_scale * sigma_scale, rtol * 1e-6],
        max_steps: 200_000,
    };
    // Bounds both clocks: σ up to the layer crossing, then local time (the way out through the
    // layer takes ~ d / exit speed).
    let sigma_end = 1e3 * (1.0 + sqrt(delta)) + 1e3 * sqrt(d) + 1e3 * d;
    let mut stepper = Dopri5::new(
        &sys,
        0.0,
        [-d, 1.0],
        sigma_end,
        0.05 * sigma_scale.min(sqrt(d.max(1e-300))).max(1e-8),
        tol,
        "layer contact (literal reading)",
    );
    let mut x_max = 0.0;
    let mut s_offset = 0.0;
    loop {
        match stepper.step(&sys)? {
            StepOutcome::Step => {}
            StepOutcome::Done => {
                return Err(crate::Error::StepBudgetExceeded {
                    what: "layer contact (literal reading): no separation before the time limit",
                    steps: 0,
                });
            }
            StepOutcome::Event { t, y, which } => match which {
                MAX => x_max = d + y[0],
                BOUNDARY if y[1] > 0.0 && sys.phase == Phase::Layer => {
                    // Eq. (9): the layer is crushed with speed exactly 1 − λ d^(3/2). The bulk
                    // excursion is brief next to the crushing time: continue on a local clock
                    // starting at 0, so that its duration is not rounded away.
                    s_offset = t * t;
                    sys.sigma_clock = false;
                    sys.phase = Phase::Bulk;
                    stepper.restart(&sys, 0.0, [0.0, 1.0 - g_s]);
                }
                BOUNDARY if y[1] < 0.0 && sys.phase != Phase::Layer => {
                    let y = stepper.exact_state(&sys, t);
                    // Leaving the bulk through the layer: Eq. (9) integrated once more gives the exit
                    // speed v_d + λ d^(3/2); if that is not negative, the layer holds the grains.
                    if y[1] + g_s >= 0.0 {
                        return Ok(LiteralOutcome {
                            eps: 0.0,
                            stuck: true,
                            s_c: f64::INFINITY,
                            x_max,
                            rhs_evaluations: stepper.rhs_evaluations(),
                        });
                    }
                    // Eq. (9) once more: the layer takes exactly λ d^(3/2) off the way out, and
                    // the time to cross it has a closed form too ([`exit_time`]). Integrating that
                    // crossing would not end near the threshold, where it lasts ~ ε^(−1/3).
                    let eps = -(y[1] + g_s);
                    let s_bulk = if sys.sigma_clock { t * t } else { s_offset + t };
                    return Ok(LiteralOutcome {
                        eps: eps.clamp(0.0, 1.0),
                        stuck: false,
                        s_c: s_bulk + exit_time(d, g_s, eps),
                        x_max,
                        rhs_evaluations: stepper.rhs_evaluations(),
                    });
                }
                FORCE_ZERO if end == ContactEnd::ForceZero && sys.phase == Phase::Bulk => {
                    let y = stepper.exact_state(&sys, t);
                    sys.phase = Phase::Coast;
                    stepper.restart(&sys, t, y);
                }
                EXIT if sys.phase != Phase::Bulk || d == 0.0 => {
                    let y = stepper.exact_state(&sys, t);
                    return Ok(LiteralOutcome {
                        // Layer drag and bulk damping only dissipate and the bulk force depends
                        // on ξ alone: the exact ε lies in [0, 1]; clamping removes integration
                        // error only.
                        eps: (-y[1]).clamp(0.0, 1.0),
                        stuck: false,
                        s_c: if sys.sigma_clock { t * t } else { s_offset + t },
                        x_max,
                        rhs_evaluations: stepper.rhs_evaluations(),
                    });
                }
                _ => {}
            },
        }
    }
}

/// Stage-1 crush time in closed form against a direct quadrature is checked in the tests.
#[cfg(test)]
mod tests {
    use super::*;

    fn crush_time_quadrature(d: f64, r: f64) -> f64 {
        // Composite Simpson on x = d w², integrand 2 d w / (1 − r w³).
        let n = 200_000;
        let h = 1.0 / n as f64;
        let f = |w: f64| 2.0 * d * w / (1.0 - r * w * w * w);
        let mut s = f(0.0) + f(1.0);
        for i in 1..n {
            let w = i as f64 * h;
            s += if i % 2 == 1 { 4.0 } else { 2.0 } * f(w);
        }
        s * h / 3.0
    }

    /// ∫₀^d dx / (ε + g_s (x/d)^(3/2)) by composite Simpson in x = d w² (smooth integrand).
    fn exit_time_quadrature(d: f64, g_s: f64, eps: f64) -> f64 {
        let n = 400_000;
        let h = 1.0 / n as f64;
        let f = |w: f64| 2.0 * d * w / (eps + g_s * w * w * w);
        let mut s = f(0.0) + f(1.0);
        for i in 1..n {
            s += if i % 2 == 1 { 4.0 } else { 2.0 } * f(i as f64 * h);
        }
        s * h / 3.0
    }

    #[test]
    fn exit_time_matches_quadrature_on_both_branches() {
        // b = (ε/g_s)^(1/3) from 1e-2 (near the threshold) through the switch at 1.5 to 10.
        for &(g_s, eps) in &[
            (0.5, 5e-7),
            (0.5, 1e-3),
            (0.3, 0.3),
            (0.2, 0.6749),
            (0.2, 0.6751),
            (0.01, 0.9),
            (1e-3, 0.99),
        ] {
            let a = exit_time(2.0, g_s, eps);
            let b = exit_time_quadrature(2.0, g_s, eps);
            assert!((a - b).abs() < 1e-9 * b, "g_s = {g_s}, ε = {eps}: {a} vs {b}");
        }
        // No drag: the grains coast through the layer; no thickness: no time.
        assert_eq!(exit_time(2.0, 0.0, 0.5), 4.0);
        assert_eq!(exit_time(0.0, 0.3, 0.5), 0.0);
        // Near the threshold T ~ (2d/g_s) (2π/(3√3)) (g_s/ε)^(1/3): finite, growing as ε^(−1/3).
        let t = exit_time(1.0, 0.5, 1e-30);
        let lead = 2.0 / 0.5 * 2.0 * core::f64::consts::PI / (3.0 * 3f64.sqrt()) * (0.5f64 / 1e-30).cbrt();
        assert!((t / lead - 1.0).abs() < 1e-6, "{t} vs {lead}");
    }

    #[test]
    fn crush_time_matches_quadrature_on_both_branches() {
        for &r in &[0.0, 0.1, 0.5, 0.500001, 0.7, 0.9] {
            let a = crush_time(2.0, r);
            let b = crush_time_quadrature(2.0, r);
            assert!((a - b).abs() < 1e-10 * b, "r = {r}: {a} vs {b}");
        }
        assert_eq!(crush_time(1.0, 0.0), 1.0);
        // One ulp above the threshold: finite, ≈ (2d/3) ln(1/gap) for gap → 0.
        let gap = f64::EPSILON / 2.0;
        let t = crush_time_with_gap(1.0, 1.0, gap);
        assert!(
            t.is_finite() && t > 2.0 / 3.0 * (1.0 / gap).ln() * 0.9,
            "{t}"
        );
    }
}
