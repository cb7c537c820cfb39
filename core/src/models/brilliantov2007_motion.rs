//! The motion of the dynamic JKR collision (Brilliantov et al. 2007) on its dimensionless scales:
//! the system, its integration to pull-off or capture, and the energy margin the master table
//! is built from. [`super::brilliantov2007`] (the model) and [`super::brilliantov2007_master`]
//! (its table) both read it; neither reads the other's internals, so the three form no circle.

use crate::error::{Error, Result};
use crate::numerics::math::{powf, sqrt};
use crate::numerics::ode::{Direction, Dopri5, OdeSystem, StepOutcome, Tolerances};
use crate::scene::JkrEnd;

/// δ beyond which the collision is reported overdamped without integration (as for the paper's
/// model with `zero_overlap`, docs/physics.md#decision-2: the rebound is below 1e-10 there).
pub const DELTA_LIMIT: f64 = crate::normal::viscoelastic::CREEP_DELTA_LIMIT;

/// Step budget of one collision.
pub(crate) const MAX_STEPS: usize = 100_000;

/// Separation speeds below this (in units of the impact speed) after the maximum compression are
/// treated as a stop: ε_N < 1e-9, reported overdamped.
pub(crate) const CREEP_FLOOR: f64 = 1e-9;

/// `π^(5/3) (1/10 + (3/5) 2^(2/3))`: the JKR hysteresis energy (the work done against the
/// adhesive force through the neck, from `ξ = 0` to pull-off) in units of `(w⁵R⁴/E*²)^(1/3)`.
/// Integrating `F_el dξ` in closed form along the JKR branch from `a³ = πwR²/(8E*)` to
/// `a³ = 2πwR²/E*` gives `π^(5/3)(1/10 + (3/5)2^(2/3)) = 7.09220…`: the paper's 7.09 of Eq. (12)
/// when its γ is the Dupré energy `w` and its `E` the contact modulus `E*`.
pub fn hysteresis_constant() -> f64 {
    powf(core::f64::consts::PI, 5.0 / 3.0) * (0.1 + 0.6 * powf(2.0, 2.0 / 3.0))
}

/// The largest impact speed every model accepts \[m/s\] (`g_n` ∈ (0, 1e6]).
pub const MAX_SPEED: f64 = crate::scene::limits::SPEED_MAX;

/// Where impacts stick: the model's sticking threshold `g_cr`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Sticking {
    /// Impacts slower than this speed \[m/s\] stick; faster ones separate.
    Below(f64),
    /// The grains stick at every speed the model accepts (up to [`MAX_SPEED`]).
    Always,
}

impl Sticking {
    /// The threshold speed \[m/s\], `None` when the grains always stick.
    pub fn speed(self) -> Option<f64> {
        match self {
            Sticking::Below(g) => Some(g),
            Sticking::Always => None,
        }
    }
}

/// How a dynamic adhesive collision ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// The neck broke: the grains separate.
    PullOff,
    /// The grains stopped separating before pull-off: they aggregate.
    Stuck,
    /// Damping so strong that the rebound is below 1e-9 (or δ above [`DELTA_LIMIT`]).
    Overdamped,
}

/// The result of one collision.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Collision {
    /// ε_N = −ξ'(pull-off)/g (0 when stuck or overdamped).
    pub eps: f64,
    /// How it ended.
    pub outcome: Outcome,
    /// Contact duration \[s\] (infinite when stuck or overdamped).
    pub t_c: f64,
    /// Maximum compression ξ_max \[m\] (0 where δ > [`DELTA_LIMIT`] and nothing is integrated; for
    /// grains that creep onto the JKR equilibrium without turning back, the overlap where their
    /// speed fell below 1e-9 of the impact speed).
    pub xi_max: f64,
    /// Right-hand-side evaluations spent.
    pub rhs_evaluations: usize,
}

/// One point of the force–overlap loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoopPoint {
    /// Time since first contact \[s\].
    pub t: f64,
    /// Overlap ξ \[m\] (negative in the neck).
    pub xi: f64,
    /// Approach speed ξ' \[m/s\] (negative while separating).
    pub xi_dot: f64,
    /// Total normal force \[N\], repulsive positive (elastic JKR + viscous).
    pub force: f64,
    /// JKR contact radius \[m\].
    pub contact_radius: f64,
}

/// The dimensionless system in `σ = √s` with state `(x, v = dx/ds)`.
pub(crate) struct System {
    /// 1.5 δ.
    pub(crate) k: f64,
    pub(crate) kappa: f64,
    /// κ^(1/3), the start of Newton's iteration.
    pub(crate) kappa_third: f64,
    /// The end of the stable branch (the neck): radius b_c and overlap x_neck.
    pub(crate) b_c: f64,
    pub(crate) x_neck: f64,
    /// Where contact ends (the neck, or the maximum tensile force): overlap, and the JKR
    /// potential there.
    pub(crate) x_c: f64,
    pub(crate) u_c: f64,
}

pub(crate) const MAX: usize = 0;
pub(crate) const PULL_OFF: usize = 1;
pub(crate) const STOP: usize = 2;
pub(crate) const CREEP: usize = 3;
pub(crate) const CAUGHT: usize = 4;
pub(crate) const SLOW: usize = 5;

impl System {
    pub(crate) fn new(delta: f64, kappa: f64, end: JkrEnd) -> System {
        let q = powf(0.25 * kappa, 1.0 / 3.0);
        let mut sys = System {
            k: 1.5 * delta,
            kappa,
            kappa_third: powf(kappa, 1.0 / 3.0),
            b_c: q * q,
            x_neck: -0.75 * kappa * q,
            x_c: 0.0,
            u_c: 0.0,
        };
        let b_end = end_radius(kappa, end);
        sys.x_c = b_end * b_end - kappa * sqrt(b_end);
        sys.u_c = sys.potential(b_end);
        sys
    }

    /// The JKR potential `U(b) = (2/5)b⁵ − κ b^(7/2) + (3/8)κ² b²` (zero at `b = 0`), whose
    /// derivative along the branch is the elastic force: `dU/dx = b³ − 1.5 κ b^(3/2)`.
    #[inline]
    pub(crate) fn potential(&self, b: f64) -> f64 {
        let b2 = b * b;
        0.4 * b2 * b2 * b - self.kappa * b2 * b * sqrt(b) + 0.375 * self.kappa * self.kappa * b2
    }

    /// The contact radius `b(x)` on the stable JKR branch: the largest root `s = √b` of
    /// `s⁴ − κ s − x = 0`. The function is convex in `s`; Newton's iteration from
    /// `s₀ = x^(1/4) + κ^(1/3)` (which lies above the root) descends monotonically onto it.
    #[inline]
    pub(crate) fn radius(&self, x: f64) -> f64 {
        if self.kappa == 0.0 {
            return sqrt(x.max(0.0));
        }
        if x <= self.x_neck {
            return self.b_c;
        }
        let mut s = sqrt(sqrt(x.max(0.0))) + self.kappa_third;
        let s_c = sqrt(self.b_c);
        for _ in 0..100 {
            let s2 = s * s;
            let f = s2 * s2 - self.kappa * s - x;
            let df = 4.0 * s2 * s - self.kappa;
            if !(df > 0.0) {
                break;
            }
            let step = f / df;
            let next = (s - step).max(s_c);
            if !(step > 1e-16 * s) {
                s = next;
                break;
            }
            s = next;
        }
        s * s
    }

    /// Elastic JKR force `b³ − 1.5 κ b^(3/2)` at radius `b`.
    #[inline]
    pub(crate) fn elastic(&self, b: f64) -> f64 {
        b * b * b - 1.5 * self.kappa * b * sqrt(b)
    }
}

impl OdeSystem<2, 6> for System {
    #[inline]
    fn rhs(&self, sigma: f64, y: &[f64; 2], dydt: &mut [f64; 2]) {
        let b = self.radius(y[0]);
        let two_sigma = 2.0 * sigma;
        dydt[0] = two_sigma * y[1];
        dydt[1] = -two_sigma * (self.elastic(b) + self.k * b * y[1]);
    }

    #[inline]
    fn events(&self, _sigma: f64, y: &[f64; 2], out: &mut [f64; 6]) {
        out[MAX] = y[1];
        // Pull-off only counts while separating (x falls through x_c).
        out[PULL_OFF] = y[0] - self.x_c;
        out[STOP] = y[1];
        out[CREEP] = y[1] + CREEP_FLOOR;
        // Energy left above what pull-off needs (only meaningful with adhesion).
        out[CAUGHT] = if self.kappa > 0.0 {
            0.5 * y[1] * y[1] + self.potential(self.radius(y[0])) - self.u_c
        } else {
            1.0
        };
        out[SLOW] = y[1] - CREEP_FLOOR;
    }

    fn direction(&self, which: usize) -> Direction {
        match which {
            STOP | CREEP => Direction::Rising,
            CAUGHT | SLOW => Direction::Falling,
            _ => Direction::Falling,
        }
    }
}

/// The dimensionless contact radius where contact ends: the neck `b^(3/2) = κ/4`, or the maximum
/// tensile force `b^(3/2) = 3κ/4` (`dF/db = 3b² − (9/4)κ√b = 0`).
pub(crate) fn end_radius(kappa: f64, end: JkrEnd) -> f64 {
    let factor = match end {
        JkrEnd::Neck => 0.25,
        JkrEnd::PullOffForce => 0.75,
    };
    powf(factor * kappa, 2.0 / 3.0)
}

/// The JKR potential `U(b)` at `κ = 1` (`U` scales as κ^(10/3) along the branch `b ∝ κ^(2/3)`).
pub(crate) fn unit_potential(b: f64) -> f64 {
    0.4 * powf(b, 5.0) - powf(b, 3.5) + 0.375 * b * b
}

/// The hysteresis constant of an end of contact: the work against adhesion from the jump-in
/// (`b = κ^(2/3)`, `x = 0`) to the end, in units of `(w⁵R⁴/E*²)^(1/3)`. For the neck it is
/// [`hysteresis_constant`] (7.09220…); for the maximum tensile force it is that times
/// `(0.225 − 0.15·(3/4)^(4/3)) / (0.225 + 2.4·4^(−10/3))` = 3.50260…
pub fn end_hysteresis_constant(end: JkrEnd) -> f64 {
    let work = |e| unit_potential(end_radius(1.0, e)) - unit_potential(1.0);
    hysteresis_constant() * work(end) / work(JkrEnd::Neck)
}

/// The dimensionless result: `(ε, s_c, x_max, outcome, rhs evaluations)`.
type Raw = (f64, f64, f64, Outcome, usize);

/// Integrates one collision with damping `delta`, adhesion `kappa` and relative tolerance `rtol`;
/// `visit(σ, x, v, b)` sees the start, every accepted step and every event (in order). The outcome
/// is decided when the grains are caught (the energy falls below what pull-off needs); with
/// `follow_caught` the path is followed on to where they stop separating (for the force loop),
/// as far as the step budget allows.
// Long by design: one integration of the JKR contact with its events (neck, pull-off) and step
// budget; the state is shared by every branch.
pub(crate) fn integrate(
    delta: f64,
    kappa: f64,
    end: JkrEnd,
    rtol: f64,
    follow_caught: bool,
    mut visit: impl FnMut(f64, f64, f64, f64),
) -> Result<Raw> {
    if !(delta.is_finite() && delta >= 0.0) {
        return Err(Error::OutOfRange {
            field: "bulk.damping",
            value: delta,
            expected: "the dimensionless damping must be a finite number >= 0",
        });
    }
    if !(kappa.is_finite() && kappa >= 0.0) {
        return Err(Error::OutOfRange {
            field: "adhesion.surface_energy",
            value: kappa,
            expected: "the dimensionless adhesion must be a finite number >= 0",
        });
    }
    if delta > DELTA_LIMIT {
        return Ok((0.0, f64::INFINITY, 0.0, Outcome::Overdamped, 0));
    }
    let sys = System::new(delta, kappa, end);
    // Scales: strong adhesion (κ ≫ 1) squeezes the contact to x ~ κ^(4/3) over s ~ κ^(−1/3)… the
    // controller adapts; only the first trial step and the absolute tolerances need a scale.
    let x_scale = 1.0f64.max(powf(kappa, 4.0 / 3.0));
    let sigma_scale = if delta > 1.0 {
        powf(delta, -1.0 / 3.0)
    } else {
        1.0
    };
    let tol = Tolerances {
        rtol,
        atol: [
            rtol * 1e-3 * x_scale * sigma_scale * sigma_scale,
            rtol * 1e-6,
        ],
        max_steps: MAX_STEPS,
    };
    let sigma_end = 1e3 * (1.0 + sqrt(delta)) * (1.0 + powf(kappa, 0.5));
    let y0 = [0.0, 1.0];
    let mut stepper = Dopri5::new(
        &sys,
        0.0,
        y0,
        sigma_end,
        0.05 * sigma_scale / (1.0 + sys.kappa_third),
        tol,
        "adhesive viscoelastic contact (brilliantov2007)",
    );
    visit(0.0, y0[0], y0[1], sys.radius(y0[0]));
    let mut x_max: f64 = 0.0;
    let mut past_max = false;
    // Caught from the start when the impact's kinetic energy cannot pay the hysteresis (the event
    // below only sees E falling through U(b_c)).
    let mut caught =
        kappa > 0.0 && 0.5 * y0[1] * y0[1] + sys.potential(sys.radius(y0[0])) < sys.u_c;
    let stuck = |x_max: f64, n: usize| Ok((0.0, f64::INFINITY, x_max, Outcome::Stuck, n));
    loop {
        let outcome = match stepper.step(&sys) {
            // Caught grains creeping onto the JKR equilibrium (the overdamped approach never turns
            // back, so no event ends it): the outcome is already decided.
            Err(Error::StepBudgetExceeded { .. }) if caught => {
                return stuck(x_max, stepper.rhs_evaluations());
            }
            Err(Error::StepBudgetExceeded { .. }) if past_max => {
                return Ok((
                    0.0,
                    f64::INFINITY,
                    x_max,
                    Outcome::Overdamped,
                    stepper.rhs_evaluations(),
                ));
            }
            other => other?,
        };
        match outcome {
            StepOutcome::Step => {
                let (t, y) = (stepper.t(), *stepper.y());
                x_max = x_max.max(y[0]);
                visit(t, y[0], y[1], sys.radius(y[0]));
            }
            StepOutcome::Event { t, y, which } => {
                x_max = x_max.max(y[0]);
                visit(t, y[0], y[1], sys.radius(y[0]));
                match which {
                    MAX if !past_max => {
                        past_max = true;
                        if caught && !follow_caught {
                            return stuck(x_max, stepper.rhs_evaluations());
                        }
                    }
                    CAUGHT => {
                        caught = true;
                        if past_max && !follow_caught {
                            return stuck(x_max, stepper.rhs_evaluations());
                        }
                    }
                    PULL_OFF if past_max || y[1] < 0.0 => {
                        let eps = (-y[1]).clamp(0.0, 1.0);
                        return Ok((
                            eps,
                            t * t,
                            x_max,
                            Outcome::PullOff,
                            stepper.rhs_evaluations(),
                        ));
                    }
                    // Turned back beyond the end: a grazing pull-off whose brief excursion past
                    // x_c fell inside one step (no sign change at the step's ends). The speed at
                    // the crossing follows from the energy, E(stop) − U(x_c) (the loss over the
                    // excursion is of higher order).
                    STOP if past_max && y[0] < sys.x_c => {
                        let excess = sys.potential(sys.radius(y[0])) - sys.u_c;
                        let eps = sqrt(2.0 * excess.max(0.0)).clamp(0.0, 1.0);
                        return Ok((
                            eps,
                            t * t,
                            x_max,
                            Outcome::PullOff,
                            stepper.rhs_evaluations(),
                        ));
                    }
                    STOP if past_max => {
                        return stuck(x_max, stepper.rhs_evaluations());
                    }
                    // Caught and slower than 1e-9 of the impact speed either way: the grains
                    // settle onto the JKR equilibrium; nothing visible is left to follow.
                    SLOW | CREEP if caught => {
                        return stuck(x_max, stepper.rhs_evaluations());
                    }
                    CREEP if past_max && kappa == 0.0 => {
                        // Without adhesion nothing catches the grains, but the rebound is < 1e-9.
                        return Ok((
                            0.0,
                            f64::INFINITY,
                            x_max,
                            Outcome::Overdamped,
                            stepper.rhs_evaluations(),
                        ));
                    }
                    _ => {}
                }
            }
            StepOutcome::Done if caught => {
                return stuck(x_max, stepper.rhs_evaluations());
            }
            StepOutcome::Done if past_max => {
                return Ok((
                    0.0,
                    f64::INFINITY,
                    x_max,
                    Outcome::Overdamped,
                    stepper.rhs_evaluations(),
                ));
            }
            StepOutcome::Done => {
                return Err(Error::StepBudgetExceeded {
                    what: "adhesive viscoelastic contact (no maximum compression before the time limit)",
                    steps: 0,
                });
            }
        }
    }
}

/// The rebound energy margin `F` of the dimensionless collision and how it ended: for a pull-off,
/// `F = ε²` (twice the energy left at the end of contact, `E(x_c) − U(b_c) = ε²/2`); for grains
/// caught before the end, `F = 2 (E_turn − U(b_c)) < 0`, with `E_turn = U(b)` where they stop
/// separating. Near the sticking boundary the turning point `x_turn` moves linearly through `x_c`
/// and `F ≈ −2 U'(x_c) (x_c − x_turn)` on either side, so `F` crosses zero linearly where ε_N drops
/// to 0; it is not smooth there (with damping the last stretch before the end adds a loss ∝ ε³), and
/// grains that never turn (overdamped creep onto the JKR equilibrium) give the margin at the last
/// point followed. The tables of [`crate::models::brilliantov2007_master`] use the pull-off side
/// (`ε = √F`) and the outcome (for κ_cr), docs/physics.md#brilliantov2007-tables.
pub fn energy_margin(delta: f64, kappa: f64, end: JkrEnd, rtol: f64) -> Result<(f64, Outcome)> {
    let sys = System::new(delta, kappa, end);
    let mut last = (0.0, 1.0, sys.radius(0.0));
    let (eps, _, _, outcome, _) = integrate(delta, kappa, end, rtol, true, |_, x, v, b| {
        last = (x, v, b);
    })?;
    Ok(match outcome {
        Outcome::PullOff => (eps * eps, outcome),
        Outcome::Stuck => {
            let (_, v, b) = last;
            (2.0 * (0.5 * v * v + sys.potential(b) - sys.u_c), outcome)
        }
        Outcome::Overdamped => (0.0, outcome),
    })
}
