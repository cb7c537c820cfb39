//! Other models of the same collision, side by side with the paper's (docs/physics.md#models).
//!
//! Every model reads the same [`Scene`]; the paper's model ([`Model::Hertzsch2002`], i.e.
//! [`Contact::normal`]) stays the default everywhere else. What each model takes from the scene,
//! and what it ignores, is listed in docs/physics.md.

pub mod approximants;
pub mod brilliantov2007;
pub mod brilliantov2007_master;
mod brilliantov2007_motion;
// Generated (`generate_brilliantov_table`): long literals, no docs of its own.
#[allow(clippy::all, missing_docs)]
#[rustfmt::skip]
mod brilliantov2007_table;
pub mod thornton1997;

use crate::error::{Error, Result};
use crate::normal::Status;
use crate::normal::viscoelastic::master::Resolution;
use crate::numerics::accuracy::Accuracy;
use crate::scene::Scene;
use crate::scene::contact::Contact;

/// A model of the normal collision.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Model {
    /// The paper: Eq. (4)–(17) with the scene's decisions (the default).
    Hertzsch2002,
    /// Dynamic JKR adhesion with viscous dissipation, integrated to pull-off.
    Brilliantov2007,
    /// Elastic–perfectly-plastic, closed form.
    Thornton1997,
    /// The Schwager–Pöschel series of ε_N(δ) to second order.
    SchwagerPoschel2008,
    /// The Müller–Pöschel [1/4] Padé approximant of ε_N(δ).
    MullerPoschel2011,
}

impl Model {
    /// Every model, the default first.
    pub const ALL: [Model; 5] = [
        Model::Hertzsch2002,
        Model::Brilliantov2007,
        Model::Thornton1997,
        Model::SchwagerPoschel2008,
        Model::MullerPoschel2011,
    ];

    /// The name used by `rime compare --models`.
    pub fn name(self) -> &'static str {
        match self {
            Model::Hertzsch2002 => "hertzsch2002",
            Model::Brilliantov2007 => "brilliantov2007",
            Model::Thornton1997 => "thornton1997",
            Model::SchwagerPoschel2008 => "schwager_poschel2008",
            Model::MullerPoschel2011 => "muller_poschel2011",
        }
    }

    /// The citation.
    pub fn citation(self) -> &'static str {
        match self {
            Model::Hertzsch2002 => {
                "Hertzsch (2002), Planet. Space Sci. 50, 1387: viscoelastic + layer + adhesion (default)"
            }
            Model::Brilliantov2007 => {
                "Brilliantov, Albers, Spahn & Pöschel (2007), Phys. Rev. E 76, 051302: dynamic JKR adhesion + viscous dissipation to pull-off"
            }
            Model::Thornton1997 => {
                "Thornton (1997), J. Appl. Mech. 64, 383: elastic-perfectly-plastic, limiting contact pressure"
            }
            Model::SchwagerPoschel2008 => {
                "Schwager & Pöschel (2008), Phys. Rev. E 78, 051304: series of eps(delta) to second order (both end rules)"
            }
            Model::MullerPoschel2011 => {
                "Müller & Pöschel (2011), Phys. Rev. E 84, 021302: [1/4] Padé approximant of eps(delta) (force_zero end)"
            }
        }
    }

    /// The scene section the model needs beyond grains and bulk, if any (thornton1997 needs a yield
    /// pressure, `plasticity`); the explorers offer a model only on scenes that have it.
    pub fn needs_section(self) -> Option<&'static str> {
        match self {
            Model::Thornton1997 => Some("plasticity"),
            _ => None,
        }
    }

    /// Looks a model up by name.
    pub fn from_name(name: &str) -> Option<Model> {
        Model::ALL.into_iter().find(|m| m.name() == name)
    }
}

/// How a collision of any model ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModelStatus {
    /// The grains separate.
    Rebound,
    /// Stopped in the soft layer (paper, Eq. (10)).
    StuckInLayer,
    /// Held by adhesion (paper: Eq. (15); brilliantov2007: caught before pull-off).
    StuckByAdhesion,
    /// ε_N < 1e-9.
    Overdamped,
    /// A truncated series used beyond where it decreases: the number is not to be trusted.
    OutsideValidity,
}

impl ModelStatus {
    /// The snake_case name used in JSON and CSV.
    pub fn name(self) -> &'static str {
        match self {
            ModelStatus::Rebound => "rebound",
            ModelStatus::StuckInLayer => "stuck_in_layer",
            ModelStatus::StuckByAdhesion => "stuck_by_adhesion",
            ModelStatus::Overdamped => "overdamped",
            ModelStatus::OutsideValidity => "outside_validity",
        }
    }
}

impl From<Status> for ModelStatus {
    fn from(s: Status) -> Self {
        match s {
            Status::Rebound => ModelStatus::Rebound,
            Status::StuckInLayer => ModelStatus::StuckInLayer,
            Status::StuckByAdhesion => ModelStatus::StuckByAdhesion,
            Status::Overdamped => ModelStatus::Overdamped,
        }
    }
}

/// ε_N of one model at one speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModelResult {
    /// ε_N ∈ \[0, 1\].
    pub eps: f64,
    /// How the collision ended.
    pub status: ModelStatus,
}

/// Whether a characteristic speed is a number or a physical status in its place.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpeedStatus {
    /// The speed is [`CharacteristicSpeed::value`].
    Value,
    /// `g_cr` only: the grains stick at every speed the model accepts (up to 1e6 m/s); the value is
    /// `+∞` (impacts slower than it stick).
    AlwaysSticks,
}

impl SpeedStatus {
    /// The snake_case name used in JSON and CSV.
    pub fn name(self) -> &'static str {
        match self {
            SpeedStatus::Value => "value",
            SpeedStatus::AlwaysSticks => "always_sticks",
        }
    }

    /// Words for tables and legends (`None` where the value is shown instead).
    pub fn words(self) -> Option<&'static str> {
        match self {
            SpeedStatus::Value => None,
            SpeedStatus::AlwaysSticks => Some("always sticks"),
        }
    }
}

/// A named speed that characterises a model on a scene (`g_cr`, `v_yield`, …).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CharacteristicSpeed {
    /// `g_cr` (impacts slower than it stick), `g_s_adhesion` (Eq. (15), a rebound speed),
    /// `g_s_layer` (Eq. (10)), `v_yield` (first plastic yield).
    pub name: &'static str,
    /// The speed \[m/s\]; `+∞` for `g_cr` when the grains always stick.
    pub value: f64,
    /// A number, or the physical status in its place.
    pub status: SpeedStatus,
}

/// Up to four [`CharacteristicSpeed`]s, without allocation.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CharacteristicSpeeds {
    items: [Option<CharacteristicSpeed>; 4],
}

impl CharacteristicSpeeds {
    fn push(&mut self, name: &'static str, value: f64) {
        self.push_status(name, value, SpeedStatus::Value);
    }

    fn push_status(&mut self, name: &'static str, value: f64, status: SpeedStatus) {
        if let Some(slot) = self.items.iter_mut().find(|s| s.is_none()) {
            *slot = Some(CharacteristicSpeed {
                name,
                value,
                status,
            });
        }
    }

    /// The speeds, in a fixed order per model.
    pub fn iter(&self) -> impl Iterator<Item = CharacteristicSpeed> + '_ {
        self.items.iter().flatten().copied()
    }

    /// The speed called `name`, if the model has it on this scene (`+∞` for a `g_cr` that
    /// always sticks).
    pub fn get(&self, name: &str) -> Option<f64> {
        self.iter().find(|s| s.name == name).map(|s| s.value)
    }

    /// The speed called `name` with its status, if the model has it on this scene.
    pub fn find(&self, name: &str) -> Option<CharacteristicSpeed> {
        self.iter().find(|s| s.name == name)
    }
}

/// One model prepared for one scene.
#[derive(Debug, Clone, Copy)]
pub struct Evaluator {
    model: Model,
    contact: Contact,
    dynamic: Option<brilliantov2007::Dynamic>,
    plastic: Option<thornton1997::Plastic>,
}

impl Evaluator {
    /// Prepares `model` for `scene`; a model that needs a scene section the scene lacks is an error
    /// naming it (thornton1997 needs `plasticity.yield_pressure`).
    pub fn new(model: Model, scene: &Scene) -> Result<Evaluator> {
        scene.validate()?;
        let contact = Contact::new(scene)?;
        let mut e = Evaluator {
            model,
            contact,
            dynamic: None,
            plastic: None,
        };
        match model {
            Model::Brilliantov2007 => {
                let (w, end) = scene
                    .adhesion
                    .map_or((0.0, Default::default()), |a| (a.surface_energy, a.jkr_end));
                e.dynamic = Some(brilliantov2007::Dynamic::new(&contact, w, end)?);
            }
            Model::Thornton1997 => {
                let p = scene.plasticity.ok_or(Error::InvalidValue {
                    field: "plasticity.yield_pressure",
                    expected: "a yield pressure [Pa] for the plastic model thornton1997 (scene section plasticity, or --set plasticity.yield_pressure=…)",
                })?;
                e.plastic = Some(thornton1997::Plastic::new(&contact, p.yield_pressure)?);
            }
            _ => {}
        }
        Ok(e)
    }

    /// The model.
    pub fn model(&self) -> Model {
        self.model
    }

    /// ε_N at impact speed `g` \[m/s\].
    pub fn eps(&self, g: f64, accuracy: Accuracy) -> Result<ModelResult> {
        crate::normal::check_speed(g)?;
        let rebound = |eps: f64| ModelResult {
            eps,
            status: if eps < crate::normal::OVERDAMPED_THRESHOLD {
                ModelStatus::Overdamped
            } else {
                ModelStatus::Rebound
            },
        };
        Ok(match self.model {
            Model::Hertzsch2002 => {
                let n = self.contact.normal(g, accuracy)?;
                ModelResult {
                    eps: n.eps,
                    status: n.status.into(),
                }
            }
            Model::Brilliantov2007 => {
                let d = self.dynamic.ok_or(Error::UnknownParameter)?;
                // fast and precise read the tables of the dimensionless master surface (where
                // they apply); integrated and explicit tolerances integrate every collision (they
                // are the check on the tables).
                let rtol = accuracy.integrator_rtol();
                let (eps, outcome) = match accuracy {
                    Accuracy::Fast => d.eps_tabulated(g, Resolution::Coarse, rtol)?,
                    Accuracy::Precise => d.eps_tabulated(g, Resolution::Fine, rtol)?,
                    Accuracy::Balanced | Accuracy::Tolerance(_) => {
                        let c = d.collide(g, rtol)?;
                        (c.eps, c.outcome)
                    }
                };
                match outcome {
                    brilliantov2007::Outcome::PullOff => rebound(eps),
                    brilliantov2007::Outcome::Stuck => ModelResult {
                        eps: 0.0,
                        status: ModelStatus::StuckByAdhesion,
                    },
                    brilliantov2007::Outcome::Overdamped => ModelResult {
                        eps: 0.0,
                        status: ModelStatus::Overdamped,
                    },
                }
            }
            Model::Thornton1997 => rebound(self.plastic.ok_or(Error::UnknownParameter)?.eps(g)),
            Model::SchwagerPoschel2008 => {
                let (eps, valid) = approximants::series(self.contact.delta(g));
                if valid {
                    rebound(eps)
                } else {
                    ModelResult {
                        eps,
                        status: ModelStatus::OutsideValidity,
                    }
                }
            }
            Model::MullerPoschel2011 => rebound(approximants::pade(self.contact.delta(g))),
        })
    }

    /// The model's characteristic speeds on this scene.
    pub fn characteristic_speeds(&self, accuracy: Accuracy) -> Result<CharacteristicSpeeds> {
        let mut out = CharacteristicSpeeds::default();
        match self.model {
            Model::Hertzsch2002 => {
                if let Some(l) = &self.contact.layer
                    && l.critical_velocity > 0.0
                {
                    out.push("g_s_layer", l.critical_velocity);
                }
                if let Some(a) = &self.contact.adhesion
                    && a.critical_velocity > 0.0
                {
                    out.push("g_s_adhesion", a.critical_velocity);
                }
                if self.contact.eps_n_at_rest() == 0.0 {
                    let stuck = |g: f64| -> Result<bool> {
                        Ok(self.contact.normal(g, accuracy)?.eps == 0.0)
                    };
                    let start = self
                        .contact
                        .adhesion
                        .map_or(0.0, |a| a.critical_velocity)
                        .max(self.contact.layer.map_or(0.0, |l| l.critical_velocity));
                    match threshold(stuck, start)? {
                        Some(brilliantov2007::Sticking::Below(g)) => out.push("g_cr", g),
                        Some(brilliantov2007::Sticking::Always) => {
                            out.push_status("g_cr", f64::INFINITY, SpeedStatus::AlwaysSticks);
                        }
                        None => {}
                    }
                }
            }
            Model::Brilliantov2007 => {
                let d = self.dynamic.ok_or(Error::UnknownParameter)?;
                let (m_eff, rtol) = (self.contact.m_eff, accuracy.integrator_rtol());
                // fast and precise find g_cr on the tables' sticking boundary (where they reach).
                let sticking = match accuracy {
                    Accuracy::Fast | Accuracy::Precise => {
                        d.critical_speed_tabulated(m_eff, rtol)?
                    }
                    Accuracy::Balanced | Accuracy::Tolerance(_) => d.critical_speed(m_eff, rtol)?,
                };
                match sticking {
                    Some(brilliantov2007::Sticking::Below(g)) => out.push("g_cr", g),
                    Some(brilliantov2007::Sticking::Always) => {
                        out.push_status("g_cr", f64::INFINITY, SpeedStatus::AlwaysSticks);
                    }
                    None => {}
                }
            }
            Model::Thornton1997 => {
                out.push(
                    "v_yield",
                    self.plastic.ok_or(Error::UnknownParameter)?.yield_speed,
                );
            }
            Model::SchwagerPoschel2008 => {
                // The speed where 1.5 δ reaches the series' limit: δ = A α^(2/5) g^(1/5).
                let a = self.contact.delta(1.0);
                if a > 0.0 {
                    let d = approximants::SERIES_LIMIT / 1.5;
                    let g = crate::numerics::math::powf(d / a, 5.0);
                    if g.is_finite() && g > 0.0 {
                        out.push("g_validity", g);
                    }
                }
            }
            Model::MullerPoschel2011 => {}
        }
        Ok(out)
    }
}

/// The speed below which `stuck` holds (it must hold for small and fail for large speeds), by
/// bisection in ln g to relative 1e-10; bracketed from `start` (or 1 µm/s if 0).
/// [`Sticking::Always`](brilliantov2007::Sticking::Always) if `stuck` holds up to the largest
/// accepted speed (1e6 m/s); `None` if it holds nowhere above 1e-15 m/s.
fn threshold(
    stuck: impl Fn(f64) -> Result<bool>,
    start: f64,
) -> Result<Option<brilliantov2007::Sticking>> {
    use brilliantov2007::{MAX_SPEED, Sticking};
    let start = if start > 0.0 {
        start.min(MAX_SPEED)
    } else {
        1e-6
    };
    let (mut lo, mut hi) = (start, start);
    while stuck(hi)? {
        if hi == MAX_SPEED {
            return Ok(Some(Sticking::Always));
        }
        lo = hi;
        hi = (2.0 * hi).min(MAX_SPEED);
    }
    if lo == hi {
        loop {
            lo *= 0.5;
            if lo < 1e-15 {
                return Ok(None);
            }
            if stuck(lo)? {
                break;
            }
            hi = lo;
        }
    }
    while hi / lo - 1.0 > 1e-10 {
        let mid = crate::numerics::math::sqrt(lo * hi);
        if stuck(mid)? {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(Some(Sticking::Below(crate::numerics::math::sqrt(lo * hi))))
}
