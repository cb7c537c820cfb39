//! Dormand–Prince 5(4) with dense output and event location, plus fixed-step RK4.
//!
//! No Rust ODE crate offers `no_std` + events + dense output, so this is ours. The stepper is shaped
//! like diffsol's: [`Dopri5::step`] advances by one accepted step and reports what happened —
//! [`StepOutcome::Step`], an [`StepOutcome::Event`] located on the dense interpolant, or
//! [`StepOutcome::Done`]. The system is passed to every call, so a caller may switch the phase of a
//! piecewise system between steps (restarting with [`Dopri5::restart`]).
//!
//! References: \[1\] Dormand & Prince (1980), J. Comput. Appl. Math. 6, 19–26;
//! \[2\] Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.5–6 (the `dopri5` dense output and step control).

use crate::error::{Error, Result};
use crate::numerics::math::{powf, sqrt};

/// A first-order system `y' = f(t, y)` with `N` states and `M` event functions.
pub trait OdeSystem<const N: usize, const M: usize> {
    /// Evaluates the right-hand side.
    fn rhs(&self, t: f64, y: &[f64; N], dydt: &mut [f64; N]);
    /// Evaluates the event functions; an event fires where one changes sign in its [`Self::direction`].
    fn events(&self, t: f64, y: &[f64; N], out: &mut [f64; M]);
    /// Which sign changes of event `which` count.
    fn direction(&self, which: usize) -> Direction {
        let _ = which;
        Direction::Either
    }
    /// The scale against which the local error of component `i` is measured on a step from `y` to
    /// `y_new` (the step is accepted where the RMS over the components of error/scale is ≤ 1).
    /// The default is the usual mixed scale `atol[i] + rtol·max(|y[i]|, |y_new[i]|)` (\[2\]
    /// §II.4); a system overrides it for a component whose needed accuracy is not relative to its
    /// own size (the viscoelastic contact's decaying total force).
    #[inline]
    fn error_scale(&self, i: usize, y: &[f64; N], y_new: &[f64; N], tol: &Tolerances<N>) -> f64 {
        tol.atol[i] + tol.rtol * y[i].abs().max(y_new[i].abs())
    }
}

/// Sign-change direction of an event function.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// From positive to negative.
    Falling,
    /// From negative to positive.
    Rising,
    /// Either way.
    Either,
}

/// What one call of [`Dopri5::step`] did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StepOutcome<const N: usize> {
    /// One step was accepted; no event inside it.
    Step,
    /// Event `which` fires at `t` with state `y` (from the dense output). The stepper's own state has
    /// already moved to the end of the step; call [`Dopri5::restart`] to continue from the event.
    Event {
        /// Time of the event.
        t: f64,
        /// State at the event.
        y: [f64; N],
        /// Index of the event function.
        which: usize,
    },
    /// The end time was reached.
    Done,
}

// Butcher tableau of Dormand–Prince 5(4) [1].
const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;
// Error coefficients b5 − b4.
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
// Dense output coefficients ([2], `dopri5`, CONTD5).
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// The six Dormand–Prince stages from `(t, y)` with `k1 = f(t, y)` and step `h`, ending at `t_end`
/// (= t + h, or the exact end time on the last step); returns the fifth-order solution and the
/// stages k2…k6.
#[inline]
fn dp5_stages<const N: usize, const M: usize, S: OdeSystem<N, M>>(
    sys: &S,
    t: f64,
    y: &[f64; N],
    k1: &[f64; N],
    h: f64,
    t_end: f64,
) -> ([f64; N], [[f64; N]; 5]) {
    let mut k = [[0.0; N]; 5];
    let mut yt = [0.0; N];
    for i in 0..N {
        yt[i] = y[i] + h * A21 * k1[i];
    }
    sys.rhs(t + C2 * h, &yt, &mut k[0]);
    for i in 0..N {
        yt[i] = y[i] + h * (A31 * k1[i] + A32 * k[0][i]);
    }
    sys.rhs(t + C3 * h, &yt, &mut k[1]);
    for i in 0..N {
        yt[i] = y[i] + h * (A41 * k1[i] + A42 * k[0][i] + A43 * k[1][i]);
    }
    sys.rhs(t + C4 * h, &yt, &mut k[2]);
    for i in 0..N {
        yt[i] = y[i] + h * (A51 * k1[i] + A52 * k[0][i] + A53 * k[1][i] + A54 * k[2][i]);
    }
    sys.rhs(t + C5 * h, &yt, &mut k[3]);
    for i in 0..N {
        yt[i] = y[i]
            + h * (A61 * k1[i] + A62 * k[0][i] + A63 * k[1][i] + A64 * k[2][i] + A65 * k[3][i]);
    }
    sys.rhs(t_end, &yt, &mut k[4]);
    let mut y_new = [0.0; N];
    for i in 0..N {
        y_new[i] = y[i]
            + h * (A71 * k1[i] + A73 * k[1][i] + A74 * k[2][i] + A75 * k[3][i] + A76 * k[4][i]);
    }
    (y_new, k)
}

/// The dense output of one accepted step (\[2\], `dopri5` CONTD5): a quartic in θ = (t − t0)/h,
/// valid on `[t0, t0 + h]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DenseStep<const N: usize> {
    /// Start of the step.
    pub t0: f64,
    /// Length of the step (0 before the first step).
    pub h: f64,
    /// The five coefficient vectors of the interpolant.
    pub cont: [[f64; N]; 5],
}

impl<const N: usize> DenseStep<N> {
    /// The interpolated state at `t`.
    pub fn eval(&self, t: f64) -> [f64; N] {
        let theta = if self.h == 0.0 {
            1.0
        } else {
            (t - self.t0) / self.h
        };
        let theta1 = 1.0 - theta;
        let c = &self.cont;
        let mut out = [0.0; N];
        for i in 0..N {
            out[i] = c[0][i]
                + theta * (c[1][i] + theta1 * (c[2][i] + theta * (c[3][i] + theta1 * c[4][i])));
        }
        out
    }
}

/// Tolerances and limits of a [`Dopri5`] run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerances<const N: usize> {
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance per component.
    pub atol: [f64; N],
    /// Maximum number of attempted steps before giving up (a guard against hangs).
    pub max_steps: usize,
}

/// Dormand–Prince 5(4) stepper with FSAL, PI step control, dense output and event location.
#[derive(Debug, Clone)]
pub struct Dopri5<const N: usize, const M: usize> {
    t: f64,
    y: [f64; N],
    f: [f64; N],
    h: f64,
    t_end: f64,
    tol: Tolerances<N>,
    // Dense output of the last accepted step: t_old, h_old and the five coefficient vectors.
    t_old: f64,
    f_old: [f64; N],
    h_old: f64,
    cont: [[f64; N]; 5],
    events_old: [f64; M],
    pending: [(f64, usize); M],
    pending_len: usize,
    pending_pos: usize,
    err_old: f64,
    attempts: usize,
    rhs_evaluations: usize,
    what: &'static str,
    done: bool,
}

impl<const N: usize, const M: usize> Dopri5<N, M> {
    /// Starts at `(t0, y0)` and integrates towards `t_end` with first trial step `h0`.
    pub fn new<S: OdeSystem<N, M>>(
        sys: &S,
        t0: f64,
        y0: [f64; N],
        t_end: f64,
        h0: f64,
        tol: Tolerances<N>,
        what: &'static str,
    ) -> Self {
        let mut s = Dopri5 {
            t: t0,
            y: y0,
            f: [0.0; N],
            h: h0,
            t_end,
            tol,
            t_old: t0,
            f_old: [0.0; N],
            h_old: 0.0,
            cont: [[0.0; N]; 5],
            events_old: [0.0; M],
            pending: [(0.0, 0); M],
            pending_len: 0,
            pending_pos: 0,
            err_old: 1e-4,
            attempts: 0,
            rhs_evaluations: 0,
            what,
            done: false,
        };
        s.restart(sys, t0, y0);
        s
    }

    /// Changes the tolerances (for a phase whose state variables have other scales); takes effect
    /// from the next step.
    pub fn set_tolerances(&mut self, tol: Tolerances<N>) {
        self.tol = tol;
    }

    /// Continues from `(t, y)`, forgetting the current step (e.g. after a terminal event or a phase switch).
    pub fn restart<S: OdeSystem<N, M>>(&mut self, sys: &S, t: f64, y: [f64; N]) {
        self.t = t;
        self.y = y;
        sys.rhs(t, &y, &mut self.f);
        sys.events(t, &y, &mut self.events_old);
        self.rhs_evaluations += 1;
        // An event function that is exactly zero at the restart point (a boundary just crossed)
        // takes the sign it has just after it, along the current derivative: otherwise a first
        // step that leaves and re-crosses the boundary would see 0 → 0-crossing and miss it.
        if self.events_old.contains(&0.0) {
            let tau = 1e-9 * self.h.abs().max(f64::MIN_POSITIVE);
            let mut nudged = y;
            for i in 0..N {
                nudged[i] += tau * self.f[i];
            }
            let mut ahead = [0.0; M];
            sys.events(t + tau, &nudged, &mut ahead);
            for (old, next) in self.events_old.iter_mut().zip(ahead) {
                if *old == 0.0 {
                    *old = next;
                }
            }
        }
        // A restart usually follows a switch of the right-hand side (a phase change): the old step
        // size may be far too large for the new dynamics, and a step that swallows a whole
        // excursion would step over the events inside it. Start again from the usual estimate
        // h = 0.01 ‖y‖/‖f‖ ([2] §II.4), never larger than the current step.
        let (mut d0, mut d1) = (0.0, 0.0);
        for i in 0..N {
            let sc = sys.error_scale(i, &y, &y, &self.tol);
            d0 += (y[i] / sc) * (y[i] / sc);
            d1 += (self.f[i] / sc) * (self.f[i] / sc);
        }
        if d0 > 1e-10 && d1 > 1e-10 {
            let estimate = 0.01 * sqrt(d0 / d1);
            if estimate.is_finite() && estimate > 0.0 {
                self.h = self.h.min(estimate);
            }
        }
        self.pending_len = 0;
        self.pending_pos = 0;
        self.done = false;
    }

    /// Current time (end of the last accepted step).
    pub fn t(&self) -> f64 {
        self.t
    }

    /// Current state.
    pub fn y(&self) -> &[f64; N] {
        &self.y
    }

    /// Current trial step size.
    pub fn h(&self) -> f64 {
        self.h
    }

    /// Number of right-hand-side evaluations so far.
    pub fn rhs_evaluations(&self) -> usize {
        self.rhs_evaluations
    }

    /// Dense output inside the last accepted step, `t ∈ [t_old, t_old + h_old]`.
    pub fn dense(&self, t: f64) -> [f64; N] {
        self.dense_step().eval(t)
    }

    /// The dense output of the last accepted step as a value that outlives the stepper: a caller
    /// that keeps these can sample the whole solution afterwards at any times it likes (the
    /// collision trajectory does), at a cost proportional to the samples.
    pub fn dense_step(&self) -> DenseStep<N> {
        DenseStep {
            t0: self.t_old,
            h: self.h_old,
            cont: self.cont,
        }
    }

    /// The state at `t` inside the last accepted step, computed by a fresh Dormand–Prince step from
    /// the step's start: as accurate as an accepted step (fifth order), where [`Self::dense`] is
    /// fourth order. Use it to restart after an event that switches the right-hand side.
    pub fn exact_state<S: OdeSystem<N, M>>(&mut self, sys: &S, t: f64) -> [f64; N] {
        let h = t - self.t_old;
        let y = self.cont[0];
        if h == 0.0 || self.h_old == 0.0 {
            return y;
        }
        let (out, _) = dp5_stages(sys, self.t_old, &y, &self.f_old, h, t);
        self.rhs_evaluations += 5;
        out
    }

    /// Advances by one accepted step, or reports the next event inside the last step.
    // Long by design: one Dormand–Prince 5(4) step with its error control and dense-output
    // coefficients, as the method is written.
    pub fn step<S: OdeSystem<N, M>>(&mut self, sys: &S) -> Result<StepOutcome<N>> {
        if self.pending_pos < self.pending_len {
            let (t, which) = self.pending[self.pending_pos];
            self.pending_pos += 1;
            return Ok(StepOutcome::Event {
                t,
                y: self.dense(t),
                which,
            });
        }
        if self.done || self.t >= self.t_end {
            self.done = true;
            return Ok(StepOutcome::Done);
        }
        let mut k7 = [0.0; N];
        let mut rejected = false;
        loop {
            self.attempts += 1;
            if self.attempts > self.tol.max_steps {
                return Err(Error::StepBudgetExceeded {
                    what: self.what,
                    steps: self.tol.max_steps,
                });
            }
            let mut h = self.h;
            let mut last = false;
            if self.t + h >= self.t_end {
                h = self.t_end - self.t;
                last = true;
            }
            if !(h.is_finite()) || h <= f64::EPSILON * self.t.abs().max(f64::MIN_POSITIVE) {
                return Err(Error::StepSizeUnderflow {
                    what: self.what,
                    t: self.t,
                });
            }
            let (t, y, k1) = (self.t, &self.y, &self.f);
            let t_new = if last { self.t_end } else { t + h };
            let (y_new, [_k2, k3, k4, k5, k6]) = dp5_stages(sys, t, y, k1, h, t_new);
            sys.rhs(t_new, &y_new, &mut k7);
            self.rhs_evaluations += 6;
            let mut sum = 0.0;
            let mut finite = true;
            for i in 0..N {
                let e = h
                    * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
                let sc = sys.error_scale(i, y, &y_new, &self.tol);
                let r = e / sc;
                sum += r * r;
                finite &= y_new[i].is_finite();
            }
            let err = if finite {
                sqrt(sum / N as f64)
            } else {
                f64::INFINITY
            };
            if err <= 1.0 {
                // PI step-size control ([2] §IV.2, β = 0.04 as in dopri5).
                let fac = 0.9 * powf(err.max(1e-10), -0.2 + 0.04 * 0.75) * powf(self.err_old, 0.04);
                let mut fac = fac.clamp(0.2, 10.0);
                if rejected {
                    fac = fac.min(1.0);
                }
                self.err_old = err.max(1e-4);
                // Dense output coefficients.
                for i in 0..N {
                    let ydiff = y_new[i] - y[i];
                    let bspl = h * k1[i] - ydiff;
                    self.cont[0][i] = y[i];
                    self.cont[1][i] = ydiff;
                    self.cont[2][i] = bspl;
                    self.cont[3][i] = ydiff - h * k7[i] - bspl;
                    self.cont[4][i] = h
                        * (D1 * k1[i]
                            + D3 * k3[i]
                            + D4 * k4[i]
                            + D5 * k5[i]
                            + D6 * k6[i]
                            + D7 * k7[i]);
                }
                self.t_old = t;
                self.f_old = self.f;
                self.h_old = h;
                self.t = t_new;
                self.y = y_new;
                self.f = k7;
                self.h = h * fac;
                if last {
                    self.done = true;
                }
                self.locate_events(sys);
                if self.pending_len > 0 {
                    self.pending_pos = 1;
                    let (t, which) = self.pending[0];
                    return Ok(StepOutcome::Event {
                        t,
                        y: self.dense(t),
                        which,
                    });
                }
                return Ok(if last {
                    StepOutcome::Done
                } else {
                    StepOutcome::Step
                });
            }
            rejected = true;
            let fac = if err.is_finite() {
                (0.9 * powf(err, -0.2)).clamp(0.1, 0.9)
            } else {
                0.1
            };
            self.h = h * fac;
        }
    }

    /// Finds sign changes of the event functions inside the last step and queues them in time order.
    #[allow(clippy::needless_range_loop)] // `which` also indexes `events_old` and names the event.
    fn locate_events<S: OdeSystem<N, M>>(&mut self, sys: &S) {
        let mut g_new = [0.0; M];
        sys.events(self.t, &self.y, &mut g_new);
        self.pending_len = 0;
        self.pending_pos = 0;
        for which in 0..M {
            let (a, b) = (self.events_old[which], g_new[which]);
            let fires = match sys.direction(which) {
                Direction::Falling => a > 0.0 && b <= 0.0,
                Direction::Rising => a < 0.0 && b >= 0.0,
                Direction::Either => (a > 0.0 && b <= 0.0) || (a < 0.0 && b >= 0.0),
            };
            if fires {
                let t = self.root_on_dense(sys, which, a, b);
                self.pending[self.pending_len] = (t, which);
                self.pending_len += 1;
            }
        }
        self.pending[..self.pending_len].sort_unstable_by(|p, q| p.0.total_cmp(&q.0));
        self.events_old = g_new;
    }

    /// Root of event `which` on the dense interpolant of the last step (Illinois regula falsi,
    /// falling back to bisection), bracketed by `g(t_old) = a`, `g(t) = b`.
    fn root_on_dense<S: OdeSystem<N, M>>(&self, sys: &S, which: usize, a: f64, b: f64) -> f64 {
        let mut out = [0.0; M];
        let (mut lo, mut hi) = (self.t_old, self.t);
        let (mut g_lo, mut g_hi) = (a, b);
        if g_hi == 0.0 {
            return hi;
        }
        let mut side = 0i32;
        for iteration in 0..200 {
            if hi - lo <= 4.0 * f64::EPSILON * hi.abs().max(lo.abs()) {
                break;
            }
            let mut t = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
            if !(t > lo && t < hi) || iteration % 8 == 7 {
                t = 0.5 * (lo + hi);
            }
            let y = self.dense(t);
            sys.events(t, &y, &mut out);
            let g = out[which];
            if g == 0.0 {
                return t;
            }
            if (g > 0.0) == (g_lo > 0.0) {
                lo = t;
                g_lo = g;
                if side == -1 {
                    g_hi *= 0.5;
                }
                side = -1;
            } else {
                hi = t;
                g_hi = g;
                if side == 1 {
                    g_lo *= 0.5;
                }
                side = 1;
            }
        }
        // The event is at the first point where the function has changed sign.
        hi
    }
}

/// One classical fourth-order Runge–Kutta step of size `h` (for the speed/accuracy study).
pub fn rk4_step<const N: usize, const M: usize, S: OdeSystem<N, M>>(
    sys: &S,
    t: f64,
    y: &[f64; N],
    h: f64,
) -> [f64; N] {
    let mut k1 = [0.0; N];
    let mut k2 = [0.0; N];
    let mut k3 = [0.0; N];
    let mut k4 = [0.0; N];
    let mut yt = [0.0; N];
    sys.rhs(t, y, &mut k1);
    for i in 0..N {
        yt[i] = y[i] + 0.5 * h * k1[i];
    }
    sys.rhs(t + 0.5 * h, &yt, &mut k2);
    for i in 0..N {
        yt[i] = y[i] + 0.5 * h * k2[i];
    }
    sys.rhs(t + 0.5 * h, &yt, &mut k3);
    for i in 0..N {
        yt[i] = y[i] + h * k3[i];
    }
    sys.rhs(t + h, &yt, &mut k4);
    let mut out = [0.0; N];
    for i in 0..N {
        out[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Harmonic oscillator y'' = −y with an event at y = 0 falling.
    struct Oscillator;
    impl OdeSystem<2, 1> for Oscillator {
        fn rhs(&self, _t: f64, y: &[f64; 2], dydt: &mut [f64; 2]) {
            dydt[0] = y[1];
            dydt[1] = -y[0];
        }
        fn events(&self, _t: f64, y: &[f64; 2], out: &mut [f64; 1]) {
            out[0] = y[0];
        }
        fn direction(&self, _which: usize) -> Direction {
            Direction::Falling
        }
    }

    #[test]
    fn oscillator_matches_closed_form_and_finds_first_zero_at_pi_over_two() {
        let tol = Tolerances {
            rtol: 1e-12,
            atol: [1e-14; 2],
            max_steps: 100_000,
        };
        let mut s = Dopri5::new(&Oscillator, 0.0, [1.0, 0.0], 10.0, 1e-3, tol, "test");
        let mut first = None;
        loop {
            match s.step(&Oscillator).unwrap() {
                StepOutcome::Event { t, y, .. } => {
                    if first.is_none() {
                        first = Some((t, y));
                    }
                }
                StepOutcome::Step => {}
                StepOutcome::Done => break,
            }
        }
        let (t, y) = first.unwrap();
        assert!((t - core::f64::consts::FRAC_PI_2).abs() < 1e-10, "{t}");
        assert!((y[1] + 1.0).abs() < 1e-10);
        assert!((s.y()[0] - libm::cos(10.0)).abs() < 1e-10);
        assert!((s.y()[1] + libm::sin(10.0)).abs() < 1e-10);
    }

    /// The oscillator with every component's error measured against `factor` times the usual scale.
    struct Scaled(f64);
    impl OdeSystem<2, 1> for Scaled {
        fn rhs(&self, t: f64, y: &[f64; 2], dydt: &mut [f64; 2]) {
            Oscillator.rhs(t, y, dydt);
        }
        fn events(&self, t: f64, y: &[f64; 2], out: &mut [f64; 1]) {
            Oscillator.events(t, y, out);
        }
        fn error_scale(
            &self,
            i: usize,
            y: &[f64; 2],
            y_new: &[f64; 2],
            tol: &Tolerances<2>,
        ) -> f64 {
            self.0 * (tol.atol[i] + tol.rtol * y[i].abs().max(y_new[i].abs()))
        }
    }

    #[test]
    fn the_controller_measures_errors_against_the_systems_error_scale() {
        let tol = Tolerances {
            rtol: 1e-12,
            atol: [1e-14; 2],
            max_steps: 100_000,
        };
        // Error at t = 10 (against cos, −sin) and evaluations spent.
        let run = |factor: f64| {
            let sys = Scaled(factor);
            let mut s = Dopri5::new(&sys, 0.0, [1.0, 0.0], 10.0, 1e-3, tol, "test");
            while s.step(&sys).unwrap() != StepOutcome::Done {}
            let err = (s.y()[0] - libm::cos(10.0)).abs() + (s.y()[1] + libm::sin(10.0)).abs();
            (err, s.rhs_evaluations())
        };
        let (err_usual, evals_usual) = run(1.0);
        // The default scale is the usual mixed one: the same steps as the plain oscillator.
        let mut plain = Dopri5::new(&Oscillator, 0.0, [1.0, 0.0], 10.0, 1e-3, tol, "test");
        while plain.step(&Oscillator).unwrap() != StepOutcome::Done {}
        assert_eq!(plain.rhs_evaluations(), evals_usual);
        // A scale 1e6 times looser is 1e6^(1/5) ≈ 16 times fewer steps and a larger error.
        let (err_loose, evals_loose) = run(1e6);
        assert!(
            evals_loose * 8 < evals_usual,
            "{evals_loose} vs {evals_usual}"
        );
        assert!(
            err_loose > 100.0 * err_usual && err_loose < 1e-4,
            "{err_loose} vs {err_usual}"
        );
    }

    #[test]
    fn rk4_is_fourth_order() {
        let err = |n: usize| {
            let h = 1.0 / n as f64;
            let mut y = [1.0, 0.0];
            for i in 0..n {
                y = rk4_step(&Oscillator, i as f64 * h, &y, h);
            }
            (y[0] - libm::cos(1.0)).abs()
        };
        let ratio = err(50) / err(100);
        assert!((ratio - 16.0).abs() < 0.5, "{ratio}");
    }
}
