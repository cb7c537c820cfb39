//! The scene's parameters by dotted path: one registry for `--set`, the explorer's panel and the web
//! page's sliders.

use crate::error::{Error, Result};
use crate::scene::units::parse_quantity;
use crate::scene::{
    AdhesionModulus, ContactEnd, Damping, DampingFormula, JkrEnd, LayerReading, Scene, SlidingLaw,
    Viscosities,
};

/// What kind of value a parameter holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Kind {
    /// A number in `[min, max]`, shown on a log scale when `log` is set.
    Number {
        /// Smallest accepted value.
        min: f64,
        /// Largest accepted value.
        max: f64,
        /// Whether sliders and steps should be logarithmic.
        log: bool,
    },
    /// One of a fixed set of names.
    Choice(&'static [&'static str]),
    /// An effect that can be switched on (with its preset values) or off (`null`).
    Toggle,
}

/// One scene parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parameter {
    /// Dotted path, as in the scene JSON (`layer.viscosity`).
    pub path: &'static str,
    /// Short label with the paper's symbol.
    pub label: &'static str,
    /// SI unit (empty for dimensionless numbers and choices).
    pub unit: &'static str,
    /// What it is.
    pub kind: Kind,
}

/// A parameter's current value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    /// A number in the parameter's SI unit.
    Number(f64),
    /// A choice's name.
    Choice(&'static str),
    /// Whether an effect is on.
    Enabled(bool),
    /// The parameter belongs to an effect or damping form that is not active.
    Inactive,
}

const fn num(
    path: &'static str,
    label: &'static str,
    unit: &'static str,
    min: f64,
    max: f64,
    log: bool,
) -> Parameter {
    Parameter {
        path,
        label,
        unit,
        kind: Kind::Number { min, max, log },
    }
}

/// Every settable parameter, in display order.
pub const PARAMETERS: &[Parameter] = &[
    num(
        "grains.radius_1",
        "R₁ radius of grain 1",
        "m",
        1e-9,
        1e4,
        true,
    ),
    num(
        "grains.radius_2",
        "R₂ radius of grain 2",
        "m",
        1e-9,
        1e4,
        true,
    ),
    num("grains.density", "ρ density", "kg/m³", 1e-3, 1e6, true),
    num(
        "bulk.youngs_modulus",
        "Y Young's modulus",
        "Pa",
        1e-3,
        1e15,
        true,
    ),
    num(
        "bulk.poisson_ratio",
        "ν Poisson ratio",
        "",
        -0.999,
        0.5,
        false,
    ),
    num("bulk.damping.time", "A damping time", "s", 0.0, 1e6, true),
    num(
        "bulk.damping.viscosities.shear",
        "η₁ shear viscosity",
        "Pa s",
        0.0,
        1e30,
        true,
    ),
    num(
        "bulk.damping.viscosities.bulk",
        "η₂ bulk viscosity",
        "Pa s",
        0.0,
        1e30,
        true,
    ),
    Parameter {
        path: "bulk.damping.viscosities.formula",
        label: "A formula",
        unit: "",
        kind: Kind::Choice(&["brilliantov", "as_printed"]),
    },
    Parameter {
        path: "contact_end",
        label: "contact end",
        unit: "",
        kind: Kind::Choice(&["force_zero", "zero_overlap"]),
    },
    Parameter {
        path: "layer",
        label: "soft layer",
        unit: "",
        kind: Kind::Toggle,
    },
    num("layer.thickness", "D layer thickness", "m", 0.0, 1.0, true),
    num(
        "layer.viscosity",
        "η* layer viscosity",
        "Pa s",
        0.0,
        1e15,
        true,
    ),
    Parameter {
        path: "layer.reading",
        label: "Eq. (8) reading",
        unit: "",
        kind: Kind::Choice(&["offset", "literal"]),
    },
    Parameter {
        path: "adhesion",
        label: "adhesion",
        unit: "",
        kind: Kind::Toggle,
    },
    num(
        "adhesion.surface_energy",
        "γ surface energy",
        "J/m²",
        0.0,
        1e6,
        true,
    ),
    Parameter {
        path: "adhesion.modulus",
        label: "adhesion modulus",
        unit: "",
        kind: Kind::Choice(&["as_printed", "consistent"]),
    },
    Parameter {
        path: "adhesion.jkr_end",
        label: "JKR contact end",
        unit: "",
        kind: Kind::Choice(&["neck", "pull_off_force"]),
    },
    Parameter {
        path: "friction",
        label: "friction",
        unit: "",
        kind: Kind::Toggle,
    },
    num(
        "friction.coefficient",
        "μ friction coefficient",
        "",
        0.0,
        100.0,
        false,
    ),
    num("friction.kappa", "κ reduced inertia", "", 1e-6, 1.0, false),
    Parameter {
        path: "friction.sliding_law",
        label: "sliding law",
        unit: "",
        kind: Kind::Choice(&["paper", "walton"]),
    },
];

/// Looks a parameter up by its path.
pub fn parameter(path: &str) -> Option<&'static Parameter> {
    PARAMETERS
        .iter()
        .chain(MODEL_PARAMETERS.iter())
        .find(|p| p.path == path)
}

/// Factor of one notch of a logarithmic parameter (coarse, fine): ×1.25 or ×1.02.
pub const LOG_NOTCH: (f64, f64) = (1.25, 1.02);

/// One notch of a linear parameter as a fraction of its range (coarse, fine), the range counted at
/// most 1: 5 % and 1 %, i.e. steps of at most 0.05 and 0.01, steps a physicist can use for μ, κ, ν.
pub const LINEAR_NOTCH: (f64, f64) = (0.05, 0.01);

/// Why a notch cannot be taken.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NotchError {
    /// The path is not a number parameter.
    NotANumber,
    /// A logarithmic parameter at 0 cannot be stepped up (a factor keeps 0).
    LogFromZero,
}

/// The value one notch up (`up`) or down from `value` for the number parameter `kind`, fine or
/// coarse, clamped to its limits: the one rule of every surface (the terminal's ←/→, the page's
/// arrow keys on a slider). A logarithmic parameter at 0 stays there going down.
pub fn notch(
    kind: Kind,
    value: f64,
    up: bool,
    fine: bool,
) -> core::result::Result<f64, NotchError> {
    let Kind::Number { min, max, log } = kind else {
        return Err(NotchError::NotANumber);
    };
    let dir = if up { 1.0 } else { -1.0 };
    let next = if log {
        let f = if fine { LOG_NOTCH.1 } else { LOG_NOTCH.0 };
        if value > 0.0 {
            value * crate::numerics::math::powf(f, dir)
        } else if up && min <= 0.0 {
            return Err(NotchError::LogFromZero);
        } else {
            value
        }
    } else {
        let span = (max - min).min(1.0);
        let fraction = if fine { LINEAR_NOTCH.1 } else { LINEAR_NOTCH.0 };
        value + dir * span * fraction
    };
    Ok(next.clamp(min, max))
}

/// Parameters read only by the alternative models of `rime compare` (docs/physics.md#models): settable
/// with `--set` and in scene files, but not part of the explorer's panel ([`PARAMETERS`]).
pub static MODEL_PARAMETERS: &[Parameter] = &[
    Parameter {
        path: "plasticity",
        label: "plasticity",
        unit: "",
        kind: Kind::Toggle,
    },
    num(
        "plasticity.yield_pressure",
        "p_y yield pressure",
        "Pa",
        1e-3,
        1e15,
        true,
    ),
];

fn choice(
    field: &'static str,
    text: &str,
    options: &'static [&'static str],
) -> Result<&'static str> {
    let t = text.trim().trim_matches('"');
    options
        .iter()
        .copied()
        .find(|o| *o == t)
        .ok_or(Error::InvalidValue {
            field,
            expected: match field {
                "contact_end" => "force_zero or zero_overlap",
                "layer.reading" => "offset or literal",
                "adhesion.modulus" => "as_printed or consistent",
                "adhesion.jkr_end" => "neck or pull_off_force",
                "friction.sliding_law" => "paper or walton",
                "bulk.damping.viscosities.formula" => "brilliantov or as_printed",
                _ => "one of the listed choices",
            },
        })
}

fn toggle(field: &'static str, text: &str) -> Result<bool> {
    match text.trim().trim_matches('"') {
        "on" | "true" | "default" | "1" => Ok(true),
        "off" | "false" | "null" | "none" | "0" => Ok(false),
        _ => Err(Error::InvalidValue {
            field,
            expected: "on or off (null)",
        }),
    }
}

impl Scene {
    /// The current value of the parameter at `path`.
    pub fn get(&self, path: &str) -> Result<Value> {
        let n = Value::Number;
        let visc = match self.bulk.damping {
            Damping::Viscosities(v) => Some(v),
            Damping::Time(_) => None,
        };
        Ok(match path {
            "grains.radius_1" => n(self.grains.radius_1),
            "grains.radius_2" => n(self.grains.radius_2),
            "grains.density" => n(self.grains.density),
            "bulk.youngs_modulus" => n(self.bulk.youngs_modulus),
            "bulk.poisson_ratio" => n(self.bulk.poisson_ratio),
            "bulk.damping.time" => match self.bulk.damping {
                Damping::Time(a) => n(a),
                Damping::Viscosities(_) => Value::Inactive,
            },
            "bulk.damping.viscosities.shear" => visc.map_or(Value::Inactive, |v| n(v.shear)),
            "bulk.damping.viscosities.bulk" => visc.map_or(Value::Inactive, |v| n(v.bulk)),
            "bulk.damping.viscosities.formula" => visc.map_or(Value::Inactive, |v| {
                Value::Choice(match v.formula {
                    DampingFormula::Brilliantov => "brilliantov",
                    DampingFormula::AsPrinted => "as_printed",
                })
            }),
            "contact_end" => Value::Choice(match self.contact_end {
                ContactEnd::ForceZero => "force_zero",
                ContactEnd::ZeroOverlap => "zero_overlap",
            }),
            "layer" => Value::Enabled(self.layer.is_some()),
            "layer.thickness" => self.layer.map_or(Value::Inactive, |l| n(l.thickness)),
            "layer.viscosity" => self.layer.map_or(Value::Inactive, |l| n(l.viscosity)),
            "layer.reading" => self.layer.map_or(Value::Inactive, |l| {
                Value::Choice(match l.reading {
                    LayerReading::Offset => "offset",
                    LayerReading::Literal => "literal",
                })
            }),
            "adhesion" => Value::Enabled(self.adhesion.is_some()),
            "adhesion.surface_energy" => self
                .adhesion
                .map_or(Value::Inactive, |a| n(a.surface_energy)),
            "adhesion.modulus" => self.adhesion.map_or(Value::Inactive, |a| {
                Value::Choice(match a.modulus {
                    AdhesionModulus::AsPrinted => "as_printed",
                    AdhesionModulus::Consistent => "consistent",
                })
            }),
            "adhesion.jkr_end" => self.adhesion.map_or(Value::Inactive, |a| {
                Value::Choice(match a.jkr_end {
                    JkrEnd::Neck => "neck",
                    JkrEnd::PullOffForce => "pull_off_force",
                })
            }),
            "plasticity" => Value::Enabled(self.plasticity.is_some()),
            "plasticity.yield_pressure" => self
                .plasticity
                .map_or(Value::Inactive, |p| n(p.yield_pressure)),
            "friction" => Value::Enabled(self.friction.is_some()),
            "friction.coefficient" => self.friction.map_or(Value::Inactive, |f| n(f.coefficient)),
            "friction.kappa" => self.friction.map_or(Value::Inactive, |f| n(f.kappa)),
            "friction.sliding_law" => self.friction.map_or(Value::Inactive, |f| {
                Value::Choice(match f.sliding_law {
                    SlidingLaw::Paper => "paper",
                    SlidingLaw::Walton => "walton",
                })
            }),
            _ => return Err(Error::UnknownParameter),
        })
    }

    /// Sets the parameter at `path` from text (a number with optional unit, a choice name, or
    /// `on`/`off` for effects). Setting a field of an absent effect switches the effect on with its
    /// preset values first; setting `bulk.damping.time` or a viscosity switches the damping form.
    /// The scene is changed only if the result validates: on error, nothing the user had is lost.
    // Long by design: one arm per parameter path, so the path table and the setter read side by
    // side.
    pub fn set(&mut self, path: &str, text: &str) -> Result<()> {
        let p = parameter(path).ok_or(Error::UnknownParameter)?;
        let field = p.path;
        let mut next = *self;
        let number = || parse_quantity(field, text, p.unit);
        match field {
            "grains.radius_1" => next.grains.radius_1 = number()?,
            "grains.radius_2" => next.grains.radius_2 = number()?,
            "grains.density" => next.grains.density = number()?,
            "bulk.youngs_modulus" => next.bulk.youngs_modulus = number()?,
            "bulk.poisson_ratio" => next.bulk.poisson_ratio = number()?,
            "bulk.damping.time" => next.bulk.damping = Damping::Time(number()?),
            "bulk.damping.viscosities.shear"
            | "bulk.damping.viscosities.bulk"
            | "bulk.damping.viscosities.formula" => {
                let mut v = match next.bulk.damping {
                    Damping::Viscosities(v) => v,
                    Damping::Time(_) => Viscosities::default(),
                };
                match field {
                    "bulk.damping.viscosities.shear" => v.shear = number()?,
                    "bulk.damping.viscosities.bulk" => v.bulk = number()?,
                    _ => {
                        v.formula = match choice(field, text, &["brilliantov", "as_printed"])? {
                            "brilliantov" => DampingFormula::Brilliantov,
                            _ => DampingFormula::AsPrinted,
                        }
                    }
                }
                next.bulk.damping = Damping::Viscosities(v);
            }
            "contact_end" => {
                next.contact_end = match choice(field, text, &["force_zero", "zero_overlap"])? {
                    "force_zero" => ContactEnd::ForceZero,
                    _ => ContactEnd::ZeroOverlap,
                }
            }
            "layer" => next.layer = toggle(field, text)?.then(|| self.layer.unwrap_or_default()),
            "adhesion" => {
                next.adhesion = toggle(field, text)?.then(|| self.adhesion.unwrap_or_default())
            }
            "friction" => {
                next.friction = toggle(field, text)?.then(|| self.friction.unwrap_or_default())
            }
            "plasticity" => {
                next.plasticity = toggle(field, text)?.then(|| self.plasticity.unwrap_or_default())
            }
            "plasticity.yield_pressure" => {
                let mut p = next.plasticity.unwrap_or_default();
                p.yield_pressure = number()?;
                next.plasticity = Some(p);
            }
            "layer.thickness" | "layer.viscosity" | "layer.reading" => {
                let mut l = next.layer.unwrap_or_default();
                match field {
                    "layer.thickness" => l.thickness = number()?,
                    "layer.viscosity" => l.viscosity = number()?,
                    _ => {
                        l.reading = match choice(field, text, &["offset", "literal"])? {
                            "offset" => LayerReading::Offset,
                            _ => LayerReading::Literal,
                        }
                    }
                }
                next.layer = Some(l);
            }
            "adhesion.surface_energy" | "adhesion.modulus" | "adhesion.jkr_end" => {
                let mut a = next.adhesion.unwrap_or_default();
                match field {
                    "adhesion.surface_energy" => a.surface_energy = number()?,
                    "adhesion.jkr_end" => {
                        a.jkr_end = match choice(field, text, &["neck", "pull_off_force"])? {
                            "neck" => JkrEnd::Neck,
                            _ => JkrEnd::PullOffForce,
                        }
                    }
                    _ => {
                        a.modulus = match choice(field, text, &["as_printed", "consistent"])? {
                            "as_printed" => AdhesionModulus::AsPrinted,
                            _ => AdhesionModulus::Consistent,
                        }
                    }
                }
                next.adhesion = Some(a);
            }
            "friction.coefficient" | "friction.kappa" | "friction.sliding_law" => {
                let mut f = next.friction.unwrap_or_default();
                match field {
                    "friction.coefficient" => f.coefficient = number()?,
                    "friction.kappa" => f.kappa = number()?,
                    _ => {
                        f.sliding_law = match choice(field, text, &["paper", "walton"])? {
                            "paper" => SlidingLaw::Paper,
                            _ => SlidingLaw::Walton,
                        }
                    }
                }
                next.friction = Some(f);
            }
            _ => return Err(Error::UnknownParameter),
        }
        next.validate()?;
        *self = next;
        Ok(())
    }

    /// Sets a numeric parameter directly (no text parsing); same rules as [`Scene::set`].
    pub fn set_number(&mut self, path: &str, value: f64) -> Result<()> {
        let p = parameter(path).ok_or(Error::UnknownParameter)?;
        if !matches!(p.kind, Kind::Number { .. }) {
            return Err(Error::InvalidValue {
                field: p.path,
                expected: "a choice or on/off, not a number",
            });
        }
        if !value.is_finite() {
            return Err(Error::OutOfRange {
                field: p.path,
                value,
                expected: "must be finite",
            });
        }
        // Round-trip through the text path so that both share one set of rules.
        let mut buf = NumberText::default();
        self.set(p.path, buf.format(value))
    }
}

/// A stack buffer that prints an `f64` exactly (shortest round-trip form) without `alloc`.
struct NumberText {
    bytes: [u8; 40],
    len: usize,
}

impl Default for NumberText {
    fn default() -> Self {
        NumberText {
            bytes: [0; 40],
            len: 0,
        }
    }
}

impl core::fmt::Write for NumberText {
    fn write_str(&mut self, s: &str) -> core::fmt::Result {
        let end = self.len + s.len();
        if end > self.bytes.len() {
            return Err(core::fmt::Error);
        }
        self.bytes[self.len..end].copy_from_slice(s.as_bytes());
        self.len = end;
        Ok(())
    }
}

impl NumberText {
    fn format(&mut self, v: f64) -> &str {
        use core::fmt::Write;
        self.len = 0;
        if write!(self, "{v:e}").is_err() {
            self.len = 0;
        }
        core::str::from_utf8(&self.bytes[..self.len]).unwrap_or("nan")
    }
}

#[cfg(test)]
mod tests {

    /// Issue 36: one notch rule. A log parameter moves by ×1.25 (×1.02 fine) and back to where it
    /// was; a linear one by 5 % (1 %) of its range, at most 0.05 (0.01); both stay in their limits.
    #[test]
    fn issue_36_one_notch_of_every_kind() {
        let log = Kind::Number {
            min: 0.0,
            max: 1e3,
            log: true,
        };
        let up = notch(log, 2.0, true, false).unwrap();
        assert!((up - 2.5).abs() < 1e-15);
        assert!((notch(log, up, false, false).unwrap() - 2.0).abs() < 1e-15);
        assert!((notch(log, 2.0, true, true).unwrap() - 2.04).abs() < 1e-15);
        assert_eq!(notch(log, 0.0, true, false), Err(NotchError::LogFromZero));
        assert_eq!(notch(log, 0.0, false, false), Ok(0.0));
        assert_eq!(notch(log, 900.0, true, false), Ok(1e3));
        let nu = Kind::Number {
            min: -1.0,
            max: 0.5,
            log: false,
        };
        assert!((notch(nu, 0.3, true, false).unwrap() - 0.35).abs() < 1e-15);
        assert!((notch(nu, 0.3, false, true).unwrap() - 0.29).abs() < 1e-15);
        let narrow = Kind::Number {
            min: 0.0,
            max: 0.2,
            log: false,
        };
        assert!((notch(narrow, 0.1, true, false).unwrap() - 0.11).abs() < 1e-15);
        assert_eq!(notch(narrow, 0.2, true, false), Ok(0.2));
        assert_eq!(
            notch(Kind::Toggle, 1.0, true, false),
            Err(NotchError::NotANumber)
        );
    }
    use super::*;

    #[test]
    fn set_then_get_round_trips_every_numeric_parameter() {
        for p in PARAMETERS {
            if let Kind::Number { min, max, .. } = p.kind {
                let mut s = crate::Preset::IceFrost.scene();
                s.adhesion = Some(crate::Adhesion::default());
                let target = if p.path.starts_with("bulk.damping.viscosities") {
                    2.5e11
                } else if min > 0.0 {
                    (min * max).sqrt().min(max)
                } else {
                    max * 0.25
                };
                let target = if p.path == "bulk.poisson_ratio" {
                    0.25
                } else {
                    target
                };
                s.set_number(p.path, target).unwrap();
                assert_eq!(s.get(p.path).unwrap(), Value::Number(target), "{}", p.path);
            }
        }
    }

    #[test]
    fn invalid_set_keeps_the_previous_scene() {
        let mut s = Scene::default();
        let before = s;
        assert!(s.set("grains.density", "-1").is_err());
        assert!(s.set("layer.thickness", "1 Pa").is_err());
        assert!(s.set("no.such", "1").is_err());
        assert!(s.set("contact_end", "sideways").is_err());
        assert_eq!(s, before);
        s.set("layer.viscosity", "2 kPa s").unwrap();
        assert_eq!(s.layer.unwrap().viscosity, 2000.0);
        assert_eq!(s.layer.unwrap().thickness, 1e-6);
        s.set("layer", "off").unwrap();
        assert!(s.layer.is_none());
    }
}
