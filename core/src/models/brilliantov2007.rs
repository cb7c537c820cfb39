//! The dynamic collision of adhesive viscoelastic spheres (Brilliantov, Albers, Spahn & Pöschel 2007,
//! Phys. Rev. E 76, 051302): the JKR contact force plus the quasi-static viscous force, integrated
//! through loading, unloading and the neck to pull-off (docs/physics.md#model-brilliantov2007).
//!
//! With `E*` the contact modulus of Eq. (4) (`ρ_H = (4/3) E* √R_eff`), `w` the Dupré work of adhesion
//! (the scene's `adhesion.surface_energy`) and `a` the contact radius, the JKR relations are
//! `ξ(a) = a²/R − √(2π w a/E*)` and `F_el(a) = 4E*a³/(3R) − √(8π w E* a³)`; the viscous force is
//! `F_dis = 2 E* A a ξ'`, which for `w = 0` (`a = √(Rξ)`) is exactly the damping term
//! `1.5 ρ_H A √ξ ξ'` of Eq. (4). On the scales of docs/physics.md#decision-3 (`x = ξ/ξ*`,
//! `s = t/τ`, `b = a/√(R ξ*)`) the motion is
//!
//! `x'' = −(b³ − 1.5 κ b^(3/2)) − 1.5 δ b x'`,  `x = b² − κ √b`,  `x(0) = 0`, `x'(0) = 1`,
//!
//! with `δ = A α^(2/5) g^(1/5)` as in the paper's model and `κ = √(2π w/E*) R^(1/4) ξ*^(−3/4)`.
//! The contact forms at `x = 0` with `b = κ^(2/3)` (the JKR jump-in) and breaks at the end of the
//! stable JKR branch, `dx/db = 0`: `b_c = (κ/4)^(2/3)`, `x_c = −(3/4) κ (κ/4)^(1/3)` (the neck
//! ends, the force jumps from `F_el(b_c)` to 0). If the grains stop separating before `x_c` they
//! are caught: they aggregate (ε_N = 0). With `adhesion.jkr_end = pull_off_force` the contact ends
//! earlier, at the maximum tensile force `b_p = (3κ/4)^(2/3)`, `x_p = −(κ/4)(3κ/4)^(1/3)` (LAMMPS's
//! `jkr`; docs/physics.md#jkr-end); `x_c`, `U(b_c)` below then mean that end.
//!
//! The motion has the Lyapunov function `E = v²/2 + U(b)`, `U(b) = (2/5)b⁵ − κ b^(7/2) + (3/8)κ² b²`
//! (the JKR potential along the stable branch, `dU/dx = b³ − 1.5 κ b^(3/2)`): `dE/ds = −1.5 δ b v² ≤ 0`.
//! Pull-off needs `E ≥ U(b_c)` at `x_c`, so once `E` falls below `U(b_c)` the grains are caught for
//! good. That is the stop detected here: with strong damping they creep towards the JKR equilibrium
//! without ever turning back, so waiting for `ξ' = 0` would never end (issue 25).

use crate::contact::Contact;
use crate::error::{Error, Result};
use crate::math::{powf, sqrt};
use crate::ode::{Direction, Dopri5, OdeSystem, StepOutcome, Tolerances};
use crate::scene::JkrEnd;

/// δ beyond which the collision is reported overdamped without integration (as for the paper's
/// model with `zero_overlap`, docs/physics.md#decision-2: the rebound is below 1e-10 there).
pub const DELTA_LIMIT: f64 = crate::normal::viscoelastic::CREEP_DELTA_LIMIT;

/// Step budget of one collision.
const MAX_STEPS: usize = 100_000;

/// Separation speeds below this (in units of the impact speed) after the maximum compression are
/// treated as a stop: ε_N < 1e-9, reported overdamped.
const CREEP_FLOOR: f64 = 1e-9;

/// `π^(5/3) (1/10 + (3/5) 2^(2/3))`: the JKR hysteresis energy (the work done against the
/// adhesive force through the neck, from `ξ = 0` to pull-off) in units of `(w⁵R⁴/E*²)^(1/3)`.
/// Integrating `F_el dξ` in closed form along the JKR branch from `a³ = πwR²/(8E*)` to
/// `a³ = 2πwR²/E*` gives `π^(5/3)(1/10 + (3/5)2^(2/3)) = 7.09220…`: the paper's 7.09 of Eq. (12)
/// when its γ is the Dupré energy `w` and its `E` the contact modulus `E*`.
pub fn hysteresis_constant() -> f64 {
    powf(core::f64::consts::PI, 5.0 / 3.0) * (0.1 + 0.6 * powf(2.0, 2.0 / 3.0))
}

/// The largest impact speed every model accepts \[m/s\] (`g_n` ∈ (0, 1e6]).
pub const MAX_SPEED: f64 = crate::limits::SPEED_MAX;

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

/// The constants of one collision of a scene at one impact speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dynamic {
    /// Contact modulus `E* = 3ρ_H/(4√R_eff)` \[Pa\].
    pub modulus: f64,
    /// Dupré work of adhesion `w` \[J/m²\].
    pub work_of_adhesion: f64,
    /// Where the contact ends.
    pub end: JkrEnd,
    r_eff: f64,
    m_eff: f64,
    alpha: f64,
    rho_h: f64,
    damping_time: f64,
}

/// The dimensionless system in `σ = √s` with state `(x, v = dx/ds)`.
struct System {
    /// 1.5 δ.
    k: f64,
    kappa: f64,
    /// κ^(1/3), the start of Newton's iteration.
    kappa_third: f64,
    /// The end of the stable branch (the neck): radius b_c and overlap x_neck.
    b_c: f64,
    x_neck: f64,
    /// Where contact ends (the neck, or the maximum tensile force): overlap, and the JKR
    /// potential there.
    x_c: f64,
    u_c: f64,
}

const MAX: usize = 0;
const PULL_OFF: usize = 1;
const STOP: usize = 2;
const CREEP: usize = 3;
const CAUGHT: usize = 4;
const SLOW: usize = 5;

impl System {
    fn new(delta: f64, kappa: f64, end: JkrEnd) -> System {
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
    fn potential(&self, b: f64) -> f64 {
        let b2 = b * b;
        0.4 * b2 * b2 * b - self.kappa * b2 * b * sqrt(b) + 0.375 * self.kappa * self.kappa * b2
    }

    /// The contact radius `b(x)` on the stable JKR branch: the largest root `s = √b` of
    /// `s⁴ − κ s − x = 0`. The function is convex in `s`; Newton's iteration from
    /// `s₀ = x^(1/4) + κ^(1/3)` (which lies above the root) descends monotonically onto it.
    #[inline]
    fn radius(&self, x: f64) -> f64 {
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
    fn elastic(&self, b: f64) -> f64 {
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
fn end_radius(kappa: f64, end: JkrEnd) -> f64 {
    let factor = match end {
        JkrEnd::Neck => 0.25,
        JkrEnd::PullOffForce => 0.75,
    };
    powf(factor * kappa, 2.0 / 3.0)
}

/// The JKR potential `U(b)` at `κ = 1` (`U` scales as κ^(10/3) along the branch `b ∝ κ^(2/3)`).
fn unit_potential(b: f64) -> f64 {
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
fn integrate(
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

impl Dynamic {
    /// The constants of a scene; `work_of_adhesion` is `adhesion.surface_energy` (0 without
    /// adhesion), `end` the scene's `adhesion.jkr_end`.
    pub fn new(contact: &Contact, work_of_adhesion: f64, end: JkrEnd) -> Result<Dynamic> {
        if !(work_of_adhesion.is_finite() && work_of_adhesion >= 0.0) {
            return Err(Error::OutOfRange {
                field: "adhesion.surface_energy",
                value: work_of_adhesion,
                expected: "must be a finite number >= 0",
            });
        }
        Ok(Dynamic {
            modulus: 0.75 * contact.rho_h / sqrt(contact.r_eff),
            work_of_adhesion,
            end,
            r_eff: contact.r_eff,
            m_eff: contact.m_eff,
            alpha: contact.alpha,
            rho_h: contact.rho_h,
            damping_time: contact.damping_time,
        })
    }

    /// `ξ* = (g²/α)^(2/5)` \[m\], as `g^(4/5) α^(−2/5)`: g² underflows below 1e-154 m/s.
    fn length_scale(&self, g: f64) -> f64 {
        powf(g, 0.8) * powf(self.alpha, -0.4)
    }

    /// `(δ, κ)` at impact speed `g`.
    pub fn parameters(&self, g: f64) -> (f64, f64) {
        let xi_star = self.length_scale(g);
        // δ = A g/ξ* = A α^(2/5) g^(1/5), without the ratio of two underflowing numbers.
        let delta = self.damping_time * powf(self.alpha, 0.4) * powf(g, 0.2);
        let kappa = sqrt(2.0 * core::f64::consts::PI * self.work_of_adhesion / self.modulus)
            * sqrt(sqrt(self.r_eff))
            / powf(xi_star, 0.75);
        (delta, kappa)
    }

    /// The JKR hysteresis energy `W = C (w⁵R⁴/E*²)^(1/3)` \[J\] of the scene's end of contact
    /// ([`end_hysteresis_constant`]: C = 7.09220… at the neck, 3.50260… at the maximum tensile force).
    pub fn hysteresis_energy(&self) -> f64 {
        let w = self.work_of_adhesion;
        let r = self.r_eff;
        // (w⁵R⁴/E*²)^(1/3) = w (w R² / E*)^(2/3).
        end_hysteresis_constant(self.end) * w * powf(w * r * r / self.modulus, 2.0 / 3.0)
    }

    fn check_speed(g: f64) -> Result<f64> {
        crate::normal::check_speed(g)
    }

    /// One collision at impact speed `g` \[m/s\], integrated at relative tolerance `rtol`.
    pub fn collide(&self, g: f64, rtol: f64) -> Result<Collision> {
        let g = Self::check_speed(g)?;
        let (delta, kappa) = self.parameters(g);
        if delta > DELTA_LIMIT && self.work_of_adhesion > 0.0 {
            // Not integrated: without adhesion the rebound would be at most K δ⁻⁵ g (the
            // zero-overlap creep bound, docs/physics.md#decision-2); adhesion only takes energy
            // away, so if that cannot pay the hysteresis W the grains are caught.
            let rebound = crate::normal::viscoelastic::creep_eps(delta) * g;
            if 0.5 * self.m_eff * rebound * rebound < self.hysteresis_energy() {
                return Ok(Collision {
                    eps: 0.0,
                    outcome: Outcome::Stuck,
                    t_c: f64::INFINITY,
                    xi_max: 0.0,
                    rhs_evaluations: 0,
                });
            }
        }
        let (eps, s_c, x_max, outcome, n) =
            integrate(delta, kappa, self.end, rtol, false, |_, _, _, _| {})?;
        let xi_star = self.length_scale(g);
        Ok(Collision {
            eps,
            outcome,
            t_c: s_c * xi_star / g,
            xi_max: x_max * xi_star,
            rhs_evaluations: n,
        })
    }

    /// ε_N and how the collision ended at impact speed `g` \[m/s\]: from the tables of the
    /// dimensionless master surface at `resolution` where they apply
    /// ([`crate::models::brilliantov2007_master`]), else by [`Dynamic::collide`] at `rtol`.
    pub fn eps_tabulated(
        &self,
        g: f64,
        resolution: crate::master::Resolution,
        rtol: f64,
    ) -> Result<(f64, Outcome)> {
        let g = Self::check_speed(g)?;
        let (delta, kappa) = self.parameters(g);
        use crate::models::brilliantov2007_master::{Lookup, lookup};
        match lookup(delta, kappa, self.end, resolution) {
            Lookup::PullOff(eps) => Ok((eps, Outcome::PullOff)),
            Lookup::Stuck => Ok((0.0, Outcome::Stuck)),
            Lookup::Live => {
                let c = self.collide(g, rtol)?;
                Ok((c.eps, c.outcome))
            }
        }
    }

    /// The critical aggregation speed: impacts slower than `g_cr` \[m/s\] stick
    /// ([`Sticking::Below`]), or the grains stick at every speed the model accepts, up to
    /// [`MAX_SPEED`] ([`Sticking::Always`]). `None` without adhesion, or where the search meets a
    /// collision it cannot decide (δ above [`DELTA_LIMIT`] with a rebound bound that could still pay
    /// the hysteresis; never on issue 25's grid). Found by bisection in ln g to relative 1e-10,
    /// bracketed from the elastic estimate `√(2W/m_eff)`: damping only adds loss, so `g_cr` lies
    /// above it (up to integration error).
    ///
    /// Why a scene can always stick: at large δ the rebound speed `ε_N g` tends to a constant
    /// (`ε_N ∝ δ⁻⁵ ∝ 1/g`, docs/physics.md#decision-2), so when that constant rebound cannot pay
    /// the hysteresis `W`, no impact speed separates the grains (docs/physics.md#model-brilliantov2007).
    pub fn critical_speed(&self, m_eff: f64, rtol: f64) -> Result<Option<Sticking>> {
        self.critical_speed_with(m_eff, |g| {
            let c = self.collide(g, rtol)?;
            Ok(match c.outcome {
                Outcome::Stuck => Some(true),
                Outcome::PullOff => Some(false),
                Outcome::Overdamped => None,
            })
        })
    }

    /// [`Dynamic::critical_speed`] with the sticking decided by the tables' boundary κ_cr(δ)
    /// ([`crate::models::brilliantov2007_master`]: stuck where κ > κ_cr) wherever δ lies in them,
    /// and by a live collision at `rtol` elsewhere. The same bracket and bisection to relative 1e-10;
    /// on the boundary's table, without integration (docs/physics.md#brilliantov2007-tables).
    pub fn critical_speed_tabulated(&self, m_eff: f64, rtol: f64) -> Result<Option<Sticking>> {
        let table = crate::models::brilliantov2007_master::table(self.end);
        self.critical_speed_with(m_eff, |g| {
            let (delta, kappa) = self.parameters(g);
            if let Some(kappa_cr) = table.critical_kappa(delta) {
                return Ok(Some(kappa > kappa_cr));
            }
            let c = self.collide(g, rtol)?;
            Ok(match c.outcome {
                Outcome::Stuck => Some(true),
                Outcome::PullOff => Some(false),
                Outcome::Overdamped => None,
            })
        })
    }

    /// The bracket and bisection of [`Dynamic::critical_speed`] with `stuck(g)`: whether an impact
    /// at `g` sticks (`None`: undecided, overdamped).
    fn critical_speed_with(
        &self,
        m_eff: f64,
        stuck: impl Fn(f64) -> Result<Option<bool>>,
    ) -> Result<Option<Sticking>> {
        if self.work_of_adhesion == 0.0 {
            return Ok(None);
        }
        let estimate = sqrt(2.0 * self.hysteresis_energy() / m_eff);
        if !(estimate > 0.0) {
            return Ok(None);
        }
        // Even the elastic (undamped) threshold lies beyond every accepted speed.
        if !(estimate < MAX_SPEED) {
            return Ok(Some(Sticking::Always));
        }
        let (mut lo, mut hi) = (estimate, estimate);
        loop {
            match stuck(hi)? {
                Some(false) => break,
                Some(true) if hi == MAX_SPEED => return Ok(Some(Sticking::Always)),
                Some(true) => {
                    lo = hi;
                    hi = (2.0 * hi).min(MAX_SPEED);
                }
                None => return Ok(None),
            }
        }
        if lo == hi {
            // The estimate already separates (integration error of the elastic limit): step down.
            let mut found = false;
            for _ in 0..80 {
                lo *= 0.5;
                if stuck(lo)? == Some(true) {
                    found = true;
                    break;
                }
            }
            if !found {
                return Ok(None);
            }
        }
        while hi / lo - 1.0 > 1e-10 {
            let mid = sqrt(lo * hi);
            match stuck(mid)? {
                Some(true) => lo = mid,
                Some(false) => hi = mid,
                None => return Ok(None),
            }
        }
        Ok(Some(Sticking::Below(sqrt(lo * hi))))
    }

    /// The force–overlap loop of one collision: the first contact (jump-in), every accepted step,
    /// the maximum compression, the neck and, at pull-off, a last point at the same overlap with
    /// force 0 (the pull-off jump).
    #[cfg(feature = "alloc")]
    pub fn force_loop(&self, g: f64, rtol: f64) -> Result<alloc::vec::Vec<LoopPoint>> {
        let g = Self::check_speed(g)?;
        let (delta, kappa) = self.parameters(g);
        let xi_star = self.length_scale(g);
        let tau = xi_star / g;
        let force_scale = self.rho_h * xi_star * sqrt(xi_star);
        let radius_scale = sqrt(self.r_eff * xi_star);
        let k = 1.5 * delta;
        let mut points = alloc::vec::Vec::new();
        let (_, _, _, outcome, _) =
            integrate(delta, kappa, self.end, rtol, true, |sigma, x, v, b| {
                let elastic = b * b * b - 1.5 * kappa * b * sqrt(b);
                points.push(LoopPoint {
                    t: sigma * sigma * tau,
                    xi: x * xi_star,
                    xi_dot: v * g,
                    force: (elastic + k * b * v) * force_scale,
                    contact_radius: b * radius_scale,
                });
            })?;
        if outcome == Outcome::PullOff
            && let Some(last) = points.last().copied()
        {
            points.push(LoopPoint {
                force: 0.0,
                contact_radius: 0.0,
                ..last
            });
        }
        Ok(points)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn radius_inverts_the_jkr_overlap() {
        for kappa in [0.0, 1e-6, 0.3, 2.0, 50.0] {
            let sys = System::new(0.0, kappa, JkrEnd::Neck);
            for x in [sys.x_neck * 0.5, 0.0, 1e-3, 0.5, 3.0, 1e3] {
                let b = sys.radius(x);
                let back = b * b - kappa * sqrt(b);
                assert!(
                    (back - x).abs() <= 1e-12 * (1.0 + x.abs() + kappa),
                    "κ={kappa} x={x}: {back}"
                );
                assert!(b >= sys.b_c);
            }
        }
    }

    #[test]
    fn elastic_hertz_limit_conserves_energy() {
        // δ = κ = 0: Hertz, ε = 1 and x_max = (5/4)^(2/5) (energy conservation).
        let (eps, s_c, x_max, outcome, _) =
            integrate(0.0, 0.0, JkrEnd::Neck, 1e-12, false, |_, _, _, _| {}).unwrap();
        assert_eq!(outcome, Outcome::PullOff);
        assert!((eps - 1.0).abs() < 1e-9, "{eps}");
        assert!((x_max - libm::pow(1.25, 0.4)).abs() < 1e-10);
        assert!(
            (s_c - crate::analytic::HERTZ_CONTACT_TIME).abs() < 1e-8,
            "{s_c}"
        );
    }

    #[test]
    fn hysteresis_constant_is_the_closed_form() {
        // mpmath: pi**(5/3)*(1/10 + 3/5*2**(2/3)) = 7.0921959718639588…
        assert!(
            (hysteresis_constant() - 7.092_195_971_863_959).abs() < 1e-13,
            "{}",
            hysteresis_constant()
        );
    }
}
