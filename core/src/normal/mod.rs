//! Normal restitution: viscoelastic (Eq. (4)–(5)), soft layer (Eq. (8)–(10)), adhesion (Eq. (11)–(17)), and
//! their composition (layer, then adhesion on its rebound, as the paper's §4 prescribes).

pub mod analytic;
pub mod batch;

pub mod adhesion;
pub mod layer;
pub mod memo;
// Read by the collision's time course, which needs `alloc`.
#[cfg_attr(not(feature = "alloc"), allow(dead_code))]
pub(crate) mod trace;
pub mod viscoelastic;

use crate::error::{Error, Result};
use crate::normal::viscoelastic::master::Resolution;
use crate::numerics::accuracy::Accuracy;
use crate::numerics::math::powf;
use crate::scene::LayerReading;
use crate::scene::contact::Contact;
use memo::{LayerMemo, LiteralKey};
pub use viscoelastic::OVERDAMPED_THRESHOLD;

/// How a normal collision ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Status {
    /// The grains separate.
    Rebound,
    /// The soft layer dissipated all the kinetic energy (Eq. (10)).
    StuckInLayer,
    /// The rebound could not pay the JKR separation energy (Eq. (15)).
    StuckByAdhesion,
    /// ε_N < 1e-9: Eq. (4) never sticks in finite time, but the rebound is negligible.
    Overdamped,
}

impl Status {
    /// Every status in code order: `Status::ALL[s.code() as usize] == s` (the page's typed arrays
    /// carry the code).
    pub const ALL: [Status; 4] = [
        Status::Rebound,
        Status::StuckInLayer,
        Status::StuckByAdhesion,
        Status::Overdamped,
    ];

    /// The status's index in [`Status::ALL`].
    pub const fn code(self) -> u8 {
        match self {
            Status::Rebound => 0,
            Status::StuckInLayer => 1,
            Status::StuckByAdhesion => 2,
            Status::Overdamped => 3,
        }
    }

    /// The snake_case name used in JSON and CSV.
    pub fn name(self) -> &'static str {
        match self {
            Status::Rebound => "rebound",
            Status::StuckInLayer => "stuck_in_layer",
            Status::StuckByAdhesion => "stuck_by_adhesion",
            Status::Overdamped => "overdamped",
        }
    }

    /// The words screens show (`stuck in layer`): every surface's readouts use these.
    pub fn label(self) -> &'static str {
        match self {
            Status::Rebound => "rebound",
            Status::StuckInLayer => "stuck in layer",
            Status::StuckByAdhesion => "stuck by adhesion",
            Status::Overdamped => "overdamped",
        }
    }
}

/// The outcome of a normal collision at impact speed `g_n`.
///
/// # Examples
///
/// ```
/// use rime_core::{Accuracy, Contact, Preset, Status};
///
/// let contact = Contact::new(&Preset::Ice.scene())?;
/// let slow = contact.normal(1e-4, Accuracy::Precise)?;
/// let fast = contact.normal(1.0, Accuracy::Precise)?;
/// // Viscoelastic grains (Eq. (4)) restitute less the harder they hit.
/// assert_eq!(slow.status, Status::Rebound);
/// assert!(0.0 < fast.eps && fast.eps < slow.eps && slow.eps < 1.0);
/// // The `fast` table and the `precise` one agree within the coarser bound (1e-6).
/// let coarse = contact.normal(1.0, Accuracy::Fast)?;
/// assert!((coarse.eps - fast.eps).abs() <= 1e-6 * fast.eps);
/// # Ok::<(), rime_core::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Normal {
    /// Normal restitution coefficient ε_N = −g'_N/g_N ∈ \[0, 1\] (Eq. (1)). For `Overdamped` this is the
    /// raw (tiny) value.
    pub eps: f64,
    /// How the collision ended.
    pub status: Status,
    /// Contact duration \[s\]; infinite when the grains stick (they come to rest asymptotically).
    pub t_c: f64,
    /// Maximum compression ξ_max \[m\] (including the crushed layer).
    pub xi_max: f64,
    /// Estimated bound on the relative error of `eps` at the requested accuracy; infinite (no
    /// bound) where the rebound ε_N lies below [`crate::numerics::accuracy::ERROR_BOUND_DOMAIN`], outside the
    /// bounds' domain (only its order of magnitude is promised there).
    pub error_estimate: f64,
    /// Right-hand-side evaluations of the integrator spent on this result (0 for table lookups and
    /// closed forms): what a scene costs.
    pub rhs_evaluations: usize,
}

/// ε_N and the rest of a purely viscoelastic collision (Eq. (4)–(5)) at impact speed `g > 0`.
fn viscoelastic(contact: &Contact, g: f64, accuracy: Accuracy) -> Result<(f64, f64, f64, usize)> {
    let delta = contact.delta(g);
    let r = match accuracy {
        // The master curve: no integration (docs/physics.md#accuracy).
        Accuracy::Fast => crate::normal::viscoelastic::master::lookup(
            delta,
            contact.contact_end,
            Resolution::Coarse,
        ),
        // Precise: the fine table, built by the same integrator at rtol 1e-14 and verified to
        // 1e-10 against an independent computation; live integration via Accuracy::Tolerance.
        Accuracy::Precise => crate::normal::viscoelastic::master::lookup(
            delta,
            contact.contact_end,
            Resolution::Fine,
        ),
        // Far beyond the tables' end ε < 1e-11 (overdamped) and follows the measured power laws;
        // the integrator's step budget does not reach there (δ ~ 1e29 for A from viscosities with
        // ν = 1e-12), so every level uses the asymptote.
        _ if delta > DELTA_ASYMPTOTIC => crate::normal::viscoelastic::master::lookup(
            delta,
            contact.contact_end,
            Resolution::Fine,
        ),
        _ => viscoelastic::dimensionless(delta, contact.contact_end, accuracy.integrator_rtol())?,
    };
    Ok((
        r.eps,
        r.s_c * contact.time_scale(g),
        r.x_max * contact.length_scale(g),
        r.rhs_evaluations,
    ))
}

/// δ above which every accuracy level uses the master curve's asymptote (the table's end, 1e7).
pub(crate) const DELTA_ASYMPTOTIC: f64 = 1e7;

/// An impact speed every model accepts: finite, positive, at most 1e6 m/s (errors name `g_n`).
pub(crate) fn check_speed(g: f64) -> Result<f64> {
    if crate::scene::limits::speed_is_valid(g) {
        Ok(g)
    } else {
        Err(Error::OutOfRange {
            field: "g_n",
            value: g,
            expected: "impact speed must lie in (0, 1e6] m/s",
        })
    }
}

impl Contact {
    /// Normal restitution at impact speed `g` \[m/s\] with every effect the scene enables.
    #[doc(alias = "Eq. (5)")]
    pub fn normal(&self, g: f64, accuracy: Accuracy) -> Result<Normal> {
        self.normal_with(g, accuracy, &memo::NoMemo)
    }

    /// [`Contact::normal`], taking the literal layer reading's outcome from `memo` where it is kept
    /// and keeping what it integrates (issue 26): bit for bit the same result, without the
    /// integration when the layer stage's inputs were seen before ([`memo`]).
    // Long by design: the dispatch of every model branch (viscoelastic, layer readings, adhesion)
    // with the error bound of each, in one match.
    pub fn normal_with(&self, g: f64, accuracy: Accuracy, memo: &dyn LayerMemo) -> Result<Normal> {
        let g = check_speed(g)?;
        let error_estimate = accuracy.error_bound();
        let mut literal_widening = 1.0;
        // Stage 1: the layer, if any; gives ε_{N,v} of Eq. (17).
        let (eps_v, t_c, xi_max, stuck_in_layer, rhs_evaluations) = match &self.layer {
            None => {
                let (e, t, x, n) = viscoelastic(self, g, accuracy)?;
                (e, t, x, false, n)
            }
            // A layer without drag (offset reading) or without thickness (either reading) is the
            // clean surface exactly.
            Some(layer)
                if layer.thickness == 0.0
                    || (layer.critical_velocity == 0.0
                        && layer.reading == LayerReading::Offset) =>
            {
                let (e, t, x, n) = viscoelastic(self, g, accuracy)?;
                (e, t, x, false, n)
            }
            Some(layer) => match layer.reading {
                LayerReading::Offset => {
                    let g_s = layer.critical_velocity;
                    if g <= g_s {
                        // Eq. (9): stopped at ξ = (g/c)^(2/3) ≤ D.
                        (0.0, f64::INFINITY, powf(g / layer.drag, 2.0 / 3.0), true, 0)
                    } else {
                        // Eq. (9): the bulk is reached at speed g − g_s; the bulk collision is then
                        // Eq. (4) for the overlap ξ − D.
                        let g_bulk = g - g_s;
                        let (e, t, x, n) = viscoelastic(self, g_bulk, accuracy)?;
                        // 1 − g_s/g without cancellation (g − g_s is exact near the threshold).
                        let t_layer =
                            layer::crush_time_with_gap(layer.thickness / g, g_s / g, g_bulk / g);
                        (e * g_bulk / g, t + t_layer, x + layer.thickness, false, n)
                    }
                }
                LayerReading::Literal => {
                    let xi_star = self.length_scale(g);
                    let d = layer.thickness / xi_star;
                    let lambda = layer.drag * xi_star * crate::numerics::math::sqrt(xi_star) / g;
                    let (delta, rtol) = (self.delta(g), accuracy.integrator_rtol());
                    let key = LiteralKey::new(delta, lambda, d, self.contact_end, rtol);
                    let out = match memo.get(&key) {
                        Some(kept) => kept,
                        None => {
                            let out = layer::literal(delta, lambda, d, self.contact_end, rtol)?;
                            memo.put(key, out);
                            out
                        }
                    };
                    // ε = v_exit − g_s/g: the exit speed's relative error grows by (ε + g_s/g)/ε
                    // near the threshold, where ε is a small difference.
                    if out.eps > 0.0 {
                        literal_widening = 1.0 + layer.critical_velocity / g / out.eps;
                    }
                    (
                        out.eps,
                        out.s_c * self.time_scale(g),
                        out.x_max * xi_star,
                        out.stuck,
                        out.rhs_evaluations,
                    )
                }
            },
        };
        if stuck_in_layer {
            return Ok(Normal {
                eps: 0.0,
                status: Status::StuckInLayer,
                t_c: f64::INFINITY,
                xi_max,
                error_estimate,
                rhs_evaluations,
            });
        }
        // Stage 2: adhesion on the rebound (Eq. (17)).
        let mut error_estimate = error_estimate * literal_widening;
        let eps = match &self.adhesion {
            None => eps_v,
            Some(adh) => match adhesion::apply(eps_v, g, adh.critical_velocity) {
                Some(e) => {
                    // ε = ε_v √(1 − r²), r = g_s/(ε_v g): dε/ε = (dε_v/ε_v)/(1 − r²), so the
                    // relative error grows as the rebound approaches the threshold.
                    let r = adh.critical_velocity / (eps_v * g);
                    error_estimate /= (1.0 - r) * (1.0 + r);
                    e
                }
                None => {
                    return Ok(Normal {
                        eps: 0.0,
                        status: Status::StuckByAdhesion,
                        t_c: f64::INFINITY,
                        xi_max,
                        error_estimate,
                        rhs_evaluations,
                    });
                }
            },
        };
        // Below the bounds' domain no relative error is promised: say so (infinite), rather than
        // claim the level's bound (docs/physics.md#accuracy).
        if eps_v < crate::numerics::accuracy::ERROR_BOUND_DOMAIN {
            error_estimate = f64::INFINITY;
        }
        let status = if eps < OVERDAMPED_THRESHOLD {
            Status::Overdamped
        } else {
            Status::Rebound
        };
        Ok(Normal {
            eps,
            status,
            t_c,
            xi_max,
            error_estimate,
            rhs_evaluations,
        })
    }

    /// ε_N at `g`, with the limit value at `g = 0` (used by maps that include the axis).
    ///
    /// On the table levels (Fast, Precise) and tabulated models (clean, offset layer, adhesion on
    /// either) this is the hot path of curves and maps: one logarithm, one Clenshaw sum and one
    /// exponential, nothing else of [`Contact::normal`]'s record.
    pub fn eps_n(&self, g: f64, accuracy: Accuracy) -> Result<f64> {
        if g == 0.0 {
            return Ok(self.eps_n_at_rest());
        }
        let resolution = match accuracy {
            Accuracy::Fast => Resolution::Coarse,
            Accuracy::Precise => Resolution::Fine,
            _ => return Ok(self.normal(g, accuracy)?.eps),
        };
        let g = check_speed(g)?;
        let g_bulk = match &self.layer {
            Some(l) if l.reading == LayerReading::Literal && l.thickness > 0.0 => {
                return Ok(self.normal(g, accuracy)?.eps);
            }
            // Eq. (9)–(10): stuck in the layer, or the bulk is reached at g − g_s.
            Some(l) if g <= l.critical_velocity => return Ok(0.0),
            Some(l) => g - l.critical_velocity,
            None => g,
        };
        // log₁₀ δ = log₁₀(A α^(2/5)) + 0.2 log₁₀ g, with ln (cheaper than log10 here).
        let u = self.log10_delta_coefficient
            + (0.2 * core::f64::consts::LOG10_E) * crate::numerics::math::ln(g_bulk);
        let mut eps =
            crate::normal::viscoelastic::master::eps_log10(u, self.contact_end, resolution);
        if g_bulk != g {
            eps *= g_bulk / g;
        }
        Ok(match &self.adhesion {
            None => eps,
            Some(adh) => adhesion::apply(eps, g, adh.critical_velocity).unwrap_or(0.0),
        })
    }

    /// The limit of ε_N as the impact speed tends to zero.
    pub fn eps_n_at_rest(&self) -> f64 {
        let layer_stops = self.layer.is_some_and(|l| l.critical_velocity > 0.0);
        let adhesion_stops = self.adhesion.is_some_and(|a| a.critical_velocity > 0.0);
        if layer_stops || adhesion_stops {
            0.0
        } else {
            // δ → 0: elastic limit.
            1.0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Status;

    #[test]
    fn every_status_sits_at_its_code_and_names_are_distinct() {
        for (i, s) in Status::ALL.iter().enumerate() {
            assert_eq!(s.code() as usize, i, "{s:?}");
        }
        let names = Status::ALL.map(Status::name);
        for (i, a) in names.iter().enumerate() {
            assert!(names[i + 1..].iter().all(|b| b != a), "{a}");
        }
    }
}
