//! The hook through which the normal-contact integrators hand out their dense output, so that one
//! collision can be drawn and its energy ledger computed (`crate::collision`) from the very code
//! path that gives ε_N. Without a recorder ([`Nothing`]) the integrators do what they always did.

use crate::numerics::ode::DenseStep;

/// Which force acts during a recorded step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kind {
    /// The bulk, Eq. (4) (or Eq. (8) bottom in the literal reading).
    Bulk,
    /// The soft layer's drag, Eq. (8) top.
    Layer,
    /// No force: the grains coast (literal reading, force-zero rule).
    Coast,
}

/// How the state `(y0, y1)` of a recorded step maps onto the dimensionless contact: the time
/// `s = t/τ`, the overlap `x = ξ/ξ*` and the velocity `v = dx/ds`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct StateMap {
    /// The step's clock is σ = √s (else local time with `s = s_offset + t`).
    pub sigma_clock: bool,
    /// Start of the local clock in s.
    pub s_offset: f64,
    /// `x = x_offset + y0` (the literal reading carries u = x − d).
    pub x_offset: f64,
    /// Force form with this k = 1.5 δ: `y1 = x + k v` (docs/physics.md#decision-3).
    pub force_k: Option<f64>,
    /// The force acting.
    pub kind: Kind,
}

impl StateMap {
    /// s at clock time `t`.
    pub fn s(&self, t: f64) -> f64 {
        if self.sigma_clock {
            t * t
        } else {
            self.s_offset + t
        }
    }

    /// Clock time at `s`.
    pub fn clock(&self, s: f64) -> f64 {
        if self.sigma_clock {
            crate::numerics::math::sqrt(s.max(0.0))
        } else {
            s - self.s_offset
        }
    }

    /// ds/dt at clock time `t`.
    pub fn ds_dt(&self, t: f64) -> f64 {
        if self.sigma_clock { 2.0 * t } else { 1.0 }
    }

    /// `(x, v, h)` from the state, `h = x + k v` in the force form (else NaN: not carried).
    pub fn overlap_velocity(&self, y: &[f64; 2]) -> (f64, f64) {
        let x = self.x_offset + y[0];
        let v = match self.force_k {
            Some(k) => (y[1] - x) / k,
            None => y[1],
        };
        (x, v)
    }
}

/// The ends of the literal reading that are closed forms rather than integrated steps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Tail {
    /// At `s` the grains re-enter the layer (x = d) with velocity `v < 0`; they leave it with
    /// `eps` (Eq. (9) once more), or the layer holds them (`eps` = 0).
    LayerExit { s: f64, v: f64, eps: f64 },
    /// At `s` the bulk force vanished at `u = x − d > 0` with velocity `v`: the grains coast to
    /// x = d, then leave through the layer with `eps` (0: held).
    Coast { s: f64, u: f64, v: f64, eps: f64 },
    /// The contact ends at `s` without a closed-form tail.
    End { s: f64 },
    /// An end the integrators give in closed form for ε_N only (strongly overdamped creep).
    Unresolved,
}

/// Receives every accepted step of an integration, with how to read its state, and the tail.
pub(crate) trait Recorder {
    /// One accepted step (the same step may be handed over more than once; keep one).
    fn step(&mut self, step: &DenseStep<2>, map: &StateMap);
    /// How the integration ended (literal reading).
    fn tail(&mut self, tail: Tail) {
        let _ = tail;
    }
}

/// The recorder that records nothing: the integrators' usual path.
pub(crate) struct Nothing;

impl Recorder for Nothing {
    fn step(&mut self, _step: &DenseStep<2>, _map: &StateMap) {}
}
