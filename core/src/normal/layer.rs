//! Soft surface layers: Eq. (6)–(10), in the two readings of docs/physics.md#decision-4.

use super::trace::{Kind, Nothing, Recorder, StateMap, Tail};
use crate::error::Result;
use crate::numerics::math::{cbrt, ln, powf, sqrt};
use crate::numerics::ode::{Direction, Dopri5, OdeSystem, StepOutcome, Tolerances};
use crate::scene::ContactEnd;

/// Time to crush the layer in stage 1 (Eq. (8) top) from impact speed 1 through thickness `d`, in the
/// same units: `∫₀^d dx / (1 − λ x^(3/2))` with `r = λ d^(3/2) < 1` (Eq. (9) gives the integrand).
///
/// With `x = d w²` this is `2d ∫₀¹ w dw / (1 − r w³)`, evaluated by its series for small `r` and in
/// closed form (partial fractions) otherwise.
#[doc(alias = "Eq. (9)")]
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
                - s3 * crate::numerics::math::atan((2.0 * p + 1.0) / s3))
                / 3.0
        };
        // −ln(1 − a) from the gap: 1 − a³ = (1 − a)(1 + a + a²).
        let one_minus_a = gap / (1.0 + a + a * a);
        let s3 = sqrt(3.0);
        let f_a = (-ln(one_minus_a) + 0.5 * ln(a * a + a + 1.0)
            - s3 * crate::numerics::math::atan((2.0 * a + 1.0) / s3))
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
#[doc(alias = "Eq. (9)")]
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
        let atan_part = (crate::numerics::math::atan((2.0 - b) / (b * s3))
            + core::f64::consts::PI / 6.0)
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

impl LiteralOutcome {
    /// The layer holds the grains: ε = 0, an unresolved (infinite) duration.
    fn stuck(x_max: f64, rhs_evaluations: usize) -> LiteralOutcome {
        LiteralOutcome {
            eps: 0.0,
            stuck: true,
            s_c: f64::INFINITY,
            x_max,
            rhs_evaluations,
        }
    }
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
    /// In the bulk, strong damping (δ > 1) carries the total force h = x + 1.5 δ x' instead of x'
    /// (as the viscoelastic contact does): the force then vanishes exactly when the state's second
    /// component does, while x + 1.5 δ x' computed from x' is a difference of nearly equal numbers
    /// whose sign the integration error decides, so that the force-zero event was missed and the
    /// overdamped creep followed with stiffness-limited steps (10⁶ evaluations and more).
    force_form: bool,
    /// Zero overlap after the total force vanished: the tensile viscous force only slows the
    /// separation down from here on.
    creeping: bool,
    /// Eq. (10) in units of the impact speed: the speed the layer takes off on the way out.
    g_s: f64,
}

impl Literal {
    /// 1.5 δ.
    fn k(&self) -> f64 {
        1.5 * self.delta
    }

    /// Whether the state's second component is the total force h (else the velocity).
    fn carries_force(&self) -> bool {
        self.force_form && self.phase == Phase::Bulk
    }

    /// dx/ds from the state.
    fn velocity(&self, y: &[f64; 2]) -> f64 {
        if self.carries_force() {
            (y[1] - (self.d + y[0])) / self.k()
        } else {
            y[1]
        }
    }

    /// The state's second component for velocity `v` at `u = x − d` in the current phase.
    fn second(&self, u: f64, v: f64) -> f64 {
        if self.carries_force() {
            (self.d + u) + self.k() * v
        } else {
            v
        }
    }
}

const MAX: usize = 0;
const BOUNDARY: usize = 1;
const FORCE_ZERO: usize = 2;
const EXIT: usize = 3;
/// Zero overlap, after the force vanished: the separation speed falls to what the layer takes off.
const CREEP_STICK: usize = 4;

impl OdeSystem<2, 5> for Literal {
    fn rhs(&self, sigma: f64, y: &[f64; 2], dydt: &mut [f64; 2]) {
        // The state carries u = x − d: the bulk excursion beyond the layer is often tiny next to d,
        // and x itself would round it away.
        let x = (self.d + y[0]).max(0.0);
        // dt/dσ = 2σ while the clock is σ = √s (the singular start); 1 once it is local time.
        let two_sigma = if self.sigma_clock { 2.0 * sigma } else { 1.0 };
        let v = self.velocity(y);
        dydt[0] = two_sigma * v;
        dydt[1] = match self.phase {
            // Eq. (8), top: ξ'' + (3/2)(√R/(K m)) √ξ ξ' = 0.
            Phase::Layer => -two_sigma * 1.5 * self.lambda * sqrt(x) * y[1],
            // Eq. (8), bottom, with ξ itself, for h: h' = x' + 1.5 δ x'' = v − 1.5 δ √x h.
            Phase::Bulk if self.force_form => two_sigma * (v - self.k() * sqrt(x) * y[1]),
            // Eq. (8), bottom, with ξ itself.
            Phase::Bulk => -two_sigma * sqrt(x) * (x + self.k() * y[1]),
            Phase::Coast => 0.0,
        };
    }

    fn events(&self, _sigma: f64, y: &[f64; 2], out: &mut [f64; 5]) {
        out[MAX] = if self.carries_force() {
            y[1] - (self.d + y[0])
        } else {
            y[1]
        };
        out[BOUNDARY] = y[0];
        out[FORCE_ZERO] = match self.phase {
            Phase::Bulk if self.force_form => y[1],
            Phase::Bulk => (self.d + y[0]) + self.k() * y[1],
            _ => 1.0,
        };
        out[EXIT] = self.d + y[0];
        out[CREEP_STICK] = if self.creeping {
            self.velocity(y) + self.g_s
        } else {
            -1.0
        };
    }

    fn direction(&self, which: usize) -> Direction {
        match which {
            BOUNDARY => Direction::Either,
            CREEP_STICK => Direction::Rising,
            _ => Direction::Falling,
        }
    }
}

/// How many relaxation times the creep to x = d must last before the slow manifold is taken as
/// reached: the force-zero start relaxes onto it as exp(−k√x s), and the creep lasts
/// k ln(x/d), so what is left of the start at x = d is exp(−k²√d ln(x/d)) < e⁻⁴⁰.
const RELAXED: f64 = 40.0;

/// δ above which the bulk phase carries the total force instead of the velocity.
const FORCE_FORM_DELTA: f64 = 1e3;

/// k²√d above which the zero-overlap creep of the literal reading is taken from its slow manifold:
/// the neglected terms are of relative order (k²√d)⁻³ ≤ 1e-12.
const SLOW_MANIFOLD: f64 = 1e4;

/// The end of a strongly overdamped bulk excursion of the literal reading, in closed form.
///
/// With k = 1.5 δ, the bulk force relaxes within ~1/(k√x) to the slow creep on which
/// x' = −x/k − √x/k³ + O(k⁻⁵) (Eq. (8), bottom, expanded in 1/k²). Force zero: the force vanishes on
/// the way to that creep, at x ≈ `x_from`, and the grains coast to x = d at −x/k. Zero overlap: they
/// follow the creep down to x = d and arrive at d/k + √d/k³ + 1.5/k⁵ (the expansion of the slow
/// manifold in 1/k², next term of relative order (k²√d)⁻³), after a time
/// k ln(x_from/d) − (2/k)(1/√d − 1/√x_from). The layer then takes g_s off the way out (Eq. (9)).
/// Durations: the coast or the creep time, plus the closed-form layer crossing.
fn overdamped_exit(
    d: f64,
    g_s: f64,
    k: f64,
    x_from: f64,
    end: ContactEnd,
    s_from: f64,
    rhs_evaluations: usize,
) -> LiteralOutcome {
    let (speed, s_bulk) = match end {
        ContactEnd::ForceZero => {
            let v = x_from / k;
            (v, (x_from - d) / v)
        }
        ContactEnd::ZeroOverlap => {
            let k3 = k * k * k;
            (
                d / k + sqrt(d) / k3 + 1.5 / (k3 * k * k),
                k * ln(x_from / d) - 2.0 / k * (1.0 / sqrt(d) - 1.0 / sqrt(x_from)),
            )
        }
    };
    let eps = speed - g_s;
    if !(eps > 0.0) {
        return LiteralOutcome::stuck(x_from, rhs_evaluations);
    }
    LiteralOutcome {
        eps: eps.min(1.0),
        stuck: false,
        s_c: s_from + s_bulk + exit_time(d, g_s, eps),
        x_max: x_from,
        rhs_evaluations,
    }
}

/// The literal reading of Eq. (8): dimensionless damping `delta`, layer drag `lambda = c ξ*^(3/2)/g`
/// and thickness `d = D/ξ*` (both in the scales of the impact speed).
#[doc(alias = "Eq. (8)")]
pub fn literal(
    delta: f64,
    lambda: f64,
    d: f64,
    end: ContactEnd,
    rtol: f64,
) -> Result<LiteralOutcome> {
    literal_recorded(delta, lambda, d, end, rtol, &mut Nothing)
}

/// [`literal`], handing every accepted step and the closed-form tail to `recorder` (the collision
/// trajectory).
// Long by design: the literal Eq. (8) contact integrated phase by phase (crushing, bulk, exit)
// with one shared state and event log, like the integrators.
pub(crate) fn literal_recorded(
    delta: f64,
    lambda: f64,
    d: f64,
    end: ContactEnd,
    rtol: f64,
    recorder: &mut dyn Recorder,
) -> Result<LiteralOutcome> {
    let g_s = lambda * d * sqrt(d); // Eq. (10) in units of the impact speed
    if g_s >= 1.0 {
        // Eq. (9): the layer stops the grains on the way in at x = λ^(-2/3).
        return Ok(LiteralOutcome::stuck(powf(lambda, -2.0 / 3.0), 0));
    }
    // As for the clean contact: in the overdamped regime a loose tolerance lets the step-size
    // controller wander along the stiff, nearly force-free creep (measured: δ = 5e6 at rtol 1e-9
    // exhausted 200 000 steps; at 1e-11 it takes 20 000 evaluations).
    let rtol = if delta > 1e3 { rtol.min(1e-11) } else { rtol };
    let mut sys = Literal {
        delta,
        lambda,
        d,
        phase: if d > 0.0 { Phase::Layer } else { Phase::Bulk },
        sigma_clock: true,
        // Only where the creep is strongly overdamped: with moderate δ and a thick layer the bulk
        // force at x = d dominates, and the velocity form resolves the brief excursion better.
        force_form: delta > FORCE_FORM_DELTA,
        creeping: false,
        g_s,
    };
    let sigma_scale = if delta > 1.0 {
        powf(delta, -1.0 / 3.0)
    } else {
        1.0
    };
    let x_scale = sigma_scale * sigma_scale;
    let tol = Tolerances {
        rtol,
        atol: [rtol * 1e-3 * x_scale, rtol * 1e-6],
        max_steps: 200_000,
    };
    // In the force form h runs from 1.5 δ down through 0 (near x ~ d + x_scale).
    let bulk_tol = if sys.force_form {
        Tolerances {
            atol: [tol.atol[0], rtol * 1e-3 * (d + x_scale)],
            ..tol
        }
    } else {
        tol
    };
    // Bounds both clocks: σ up to the layer crossing, then local time (the way out through the
    // layer takes ~ d / exit speed).
    let sigma_end = 1e3 * (1.0 + sqrt(delta)) + 1e3 * sqrt(d) + 1e3 * d;
    let mut stepper = Dopri5::new(
        &sys,
        0.0,
        [-d, sys.second(-d, 1.0)],
        sigma_end,
        0.05 * sigma_scale.min(sqrt(d.max(1e-300))).max(1e-8),
        tol,
        "layer contact (literal reading)",
    );
    let mut x_max = 0.0;
    let mut s_offset = 0.0;
    loop {
        let outcome = stepper.step(&sys)?;
        recorder.step(
            &stepper.dense_step(),
            &StateMap {
                sigma_clock: sys.sigma_clock,
                s_offset,
                x_offset: d,
                force_k: sys.carries_force().then(|| sys.k()),
                kind: match sys.phase {
                    Phase::Layer => Kind::Layer,
                    Phase::Bulk => Kind::Bulk,
                    Phase::Coast => Kind::Coast,
                },
            },
        );
        match outcome {
            StepOutcome::Step => {}
            StepOutcome::Done => {
                return Err(crate::Error::StepBudgetExceeded {
                    what: "layer contact (literal reading): no separation before the time limit",
                    steps: 0,
                });
            }
            StepOutcome::Event { t, y, which } => match which {
                MAX => {
                    x_max = d + y[0];
                    let k = sys.k();
                    // Past the maximum the bulk force relaxes within ~1/(k√x) to the slow creep
                    // x' ≈ −x/k. Where k²√x exceeds what the tolerance resolves, the total force
                    // on that creep (−√x/k² relative to x) is below the integration error and its
                    // zero cannot be located: finish with the creep's closed form instead.
                    if sys.phase == Phase::Bulk && d > 0.0 && k * k * sqrt(x_max) * tol.rtol > 1e3 {
                        let t_max = if sys.sigma_clock { t * t } else { s_offset + t };
                        recorder.tail(Tail::Unresolved);
                        return Ok(overdamped_exit(
                            d,
                            g_s,
                            k,
                            x_max,
                            end,
                            t_max,
                            stepper.rhs_evaluations(),
                        ));
                    }
                }
                BOUNDARY if y[1] > 0.0 && sys.phase == Phase::Layer => {
                    // Eq. (9): the layer is crushed with speed exactly 1 − λ d^(3/2). The bulk
                    // excursion is brief next to the crushing time: continue on a local clock
                    // starting at 0, so that its duration is not rounded away.
                    s_offset = t * t;
                    sys.sigma_clock = false;
                    sys.phase = Phase::Bulk;
                    stepper.set_tolerances(bulk_tol);
                    stepper.restart(&sys, 0.0, [0.0, sys.second(0.0, 1.0 - g_s)]);
                }
                BOUNDARY if sys.velocity(&y) < 0.0 && sys.phase != Phase::Layer => {
                    let y = stepper.exact_state(&sys, t);
                    let v = sys.velocity(&y);
                    // Leaving the bulk through the layer: Eq. (9) integrated once more gives the exit
                    // speed v_d + λ d^(3/2); if that is not negative, the layer holds the grains.
                    let s_bulk = if sys.sigma_clock { t * t } else { s_offset + t };
                    if v + g_s >= 0.0 {
                        recorder.tail(Tail::LayerExit {
                            s: s_bulk,
                            v,
                            eps: 0.0,
                        });
                        return Ok(LiteralOutcome::stuck(x_max, stepper.rhs_evaluations()));
                    }
                    // Eq. (9) once more: the layer takes exactly λ d^(3/2) off the way out, and
                    // the time to cross it has a closed form too ([`exit_time`]). Integrating that
                    // crossing would not end near the threshold, where it lasts ~ ε^(−1/3).
                    let eps = -(v + g_s);
                    recorder.tail(Tail::LayerExit {
                        s: s_bulk,
                        v,
                        eps: eps.clamp(0.0, 1.0),
                    });
                    return Ok(LiteralOutcome {
                        eps: eps.clamp(0.0, 1.0),
                        stuck: false,
                        s_c: s_bulk + exit_time(d, g_s, eps),
                        x_max,
                        rhs_evaluations: stepper.rhs_evaluations(),
                    });
                }
                FORCE_ZERO if sys.phase == Phase::Bulk => {
                    let y = stepper.exact_state(&sys, t);
                    let v = sys.velocity(&y);
                    if end == ContactEnd::ForceZero && d > 0.0 {
                        // The bulk force has vanished while separating: the grains coast to x = d
                        // at −v (a coast from deep in the bulk can take a time of order δ).
                        let s_coast = s_offset + t + y[0] / -v;
                        let eps = -(v + g_s);
                        recorder.tail(Tail::Coast {
                            s: s_offset + t,
                            u: y[0],
                            v,
                            eps: if eps > 0.0 { eps.min(1.0) } else { 0.0 },
                        });
                        return Ok(if eps > 0.0 {
                            LiteralOutcome {
                                eps: eps.min(1.0),
                                stuck: false,
                                s_c: s_coast + exit_time(d, g_s, eps),
                                x_max,
                                rhs_evaluations: stepper.rhs_evaluations(),
                            }
                        } else {
                            LiteralOutcome::stuck(x_max, stepper.rhs_evaluations())
                        });
                    } else if end == ContactEnd::ForceZero {
                        sys.phase = Phase::Coast;
                        stepper.set_tolerances(tol);
                        stepper.restart(&sys, t, [y[0], v]);
                    } else if d > 0.0
                        && -v > g_s
                        && sys.k() * sys.k() * sqrt(d) > SLOW_MANIFOLD
                        && sys.k() * sys.k() * sqrt(d) * ln((d + y[0]) / d) > RELAXED
                    {
                        // The creep to x = d follows its slow manifold to 1e-12: closed form.
                        let s_fz = s_offset + t;
                        recorder.tail(Tail::Unresolved);
                        return Ok(overdamped_exit(
                            d,
                            g_s,
                            sys.k(),
                            d + y[0],
                            end,
                            s_fz,
                            stepper.rhs_evaluations(),
                        ));
                    } else if d > 0.0 && -v > g_s {
                        sys.creeping = true;
                        stepper.restart(&sys, t, y);
                    } else if d > 0.0 {
                        // Zero overlap: from here on the viscous force is tensile and the
                        // separation speed only falls, so the grains reach x = d slower than −v,
                        // which the layer takes off entirely: they stick. Following that creep
                        // would cost stiffness-limited steps over a time of order δ.
                        recorder.tail(Tail::Unresolved);
                        return Ok(LiteralOutcome::stuck(x_max, stepper.rhs_evaluations()));
                    }
                }
                CREEP_STICK if sys.creeping => {
                    // The separation speed only falls from here, so the grains reach x = d
                    // slower than the layer's g_s: they stick (see the force-zero case above).
                    recorder.tail(Tail::Unresolved);
                    return Ok(LiteralOutcome::stuck(x_max, stepper.rhs_evaluations()));
                }
                EXIT if sys.phase != Phase::Bulk || d == 0.0 => {
                    let y = stepper.exact_state(&sys, t);
                    recorder.tail(Tail::End {
                        s: if sys.sigma_clock { t * t } else { s_offset + t },
                    });
                    return Ok(LiteralOutcome {
                        // Layer drag and bulk damping only dissipate and the bulk force depends
                        // on ξ alone: the exact ε lies in [0, 1]; clamping removes integration
                        // error only.
                        eps: (-sys.velocity(&y)).clamp(0.0, 1.0),
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
            assert!(
                (a - b).abs() < 1e-9 * b,
                "g_s = {g_s}, ε = {eps}: {a} vs {b}"
            );
        }
        // No drag: the grains coast through the layer; no thickness: no time.
        assert_eq!(exit_time(2.0, 0.0, 0.5), 4.0);
        assert_eq!(exit_time(0.0, 0.3, 0.5), 0.0);
        // Near the threshold T ~ (2d/g_s) (2π/(3√3)) (g_s/ε)^(1/3): finite, growing as ε^(−1/3).
        let t = exit_time(1.0, 0.5, 1e-30);
        let lead =
            2.0 / 0.5 * 2.0 * core::f64::consts::PI / (3.0 * 3f64.sqrt()) * (0.5f64 / 1e-30).cbrt();
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
