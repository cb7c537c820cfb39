//! The warnings every surface shows about a scene and its curve, defined once: each with a short
//! text (a status line), a full sentence (a list of warnings), a longer help and the equation it
//! refers to. The terminal, the page and the command line show the same set.

use crate::normal::Status;
use crate::scene::{AdhesionModulus, ContactEnd, Damping, DampingFormula, LayerReading, Scene};
use alloc::format;
use alloc::string::String;
use alloc::vec::Vec;

/// Something about a scene or its curve a user should know.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Warning {
    /// ε_N < 1e-9 (overdamped) over part or all of the plotted speeds, with the damping time A.
    Overdamped {
        /// Over all of the speeds (else part of them).
        all: bool,
        /// The damping time A \[s\] (NaN when unknown).
        damping_time: f64,
    },
    /// The damping time from viscosities by the formula as printed (without (1−2ν)).
    AFormulaAsPrinted,
    /// The contact ends at zero overlap (Eq. (5) read literally).
    ZeroOverlap,
    /// The layer's Eq. (8) read literally.
    LayerLiteral,
    /// The adhesion modulus E = Y/(2(1−ν²)) instead of the printed Y/(1−ν²).
    AdhesionModulusConsistent,
}

/// A warning crosses as what a surface shows of it: `{key, short, text, help, equation}`.
#[cfg(feature = "serde")]
impl serde::Serialize for Warning {
    fn serialize<S: serde::Serializer>(&self, s: S) -> core::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut st = s.serialize_struct("Warning", 5)?;
        st.serialize_field("key", self.key())?;
        st.serialize_field("short", self.short())?;
        st.serialize_field("text", &self.text())?;
        st.serialize_field("help", &self.help())?;
        st.serialize_field("equation", self.equation())?;
        st.end()
    }
}

impl Warning {
    /// Every kind, in the order surfaces list them (one representative of `Overdamped`).
    pub const ALL: [Warning; 5] = [
        Warning::Overdamped {
            all: false,
            damping_time: f64::NAN,
        },
        Warning::AFormulaAsPrinted,
        Warning::ZeroOverlap,
        Warning::LayerLiteral,
        Warning::AdhesionModulusConsistent,
    ];

    /// A stable key (`overdamped`, `a_formula_as_printed`, …) for JSON and tests.
    pub const fn key(&self) -> &'static str {
        match self {
            Warning::Overdamped { .. } => "overdamped",
            Warning::AFormulaAsPrinted => "a_formula_as_printed",
            Warning::ZeroOverlap => "zero_overlap",
            Warning::LayerLiteral => "layer_literal",
            Warning::AdhesionModulusConsistent => "adhesion_modulus_consistent",
        }
    }

    /// A few words for a status line.
    pub const fn short(&self) -> &'static str {
        match self {
            Warning::Overdamped { all: true, .. } => "overdamped everywhere",
            Warning::Overdamped { all: false, .. } => "overdamped in part",
            Warning::AFormulaAsPrinted => "A formula as printed",
            Warning::ZeroOverlap => "contact ends at zero overlap",
            Warning::LayerLiteral => "Eq. (8) read literally",
            Warning::AdhesionModulusConsistent => "adhesion modulus consistent",
        }
    }

    /// The equation it refers to, as the paper numbers it.
    #[doc(alias = "Eq. (4)")]
    #[doc(alias = "Eq. (5)")]
    #[doc(alias = "Eq. (8)")]
    #[doc(alias = "Eq. (12)")]
    pub const fn equation(&self) -> &'static str {
        match self {
            Warning::Overdamped { .. } => "Eq. (4)",
            Warning::AFormulaAsPrinted => "Eq. (4)",
            Warning::ZeroOverlap => "Eq. (5)",
            Warning::LayerLiteral => "Eq. (8)",
            Warning::AdhesionModulusConsistent => "Eq. (12)",
        }
    }

    /// Whether it is a scene option that departs from a consistent reading of the paper
    /// (docs/physics.md), rather than a property of the curve.
    pub const fn is_paper_option(&self) -> bool {
        !matches!(self, Warning::Overdamped { .. })
    }

    /// The full sentence (lists of warnings, the page, the command line).
    pub fn text(&self) -> String {
        match self {
            Warning::Overdamped { all, damping_time } => {
                // The one formatter of numbers people read (`404.4 s`, `100 µs`; it wrote
                // `4.044e2 s`); `—` where A is not finite.
                let a = super::format::qty(*damping_time, "s");
                format!(
                    "overdamped: ε_N < 1e-9 over {} of the plotted range (A = {a}); Eq. (4) never \
                     sticks, the rebound is negligible (the stick map counts it as a rebound)",
                    if *all { "all" } else { "part" }
                )
            }
            Warning::AFormulaAsPrinted => {
                "A formula as printed: the paper omits the factor (1−2ν) of Brilliantov et al."
                    .into()
            }
            Warning::ZeroOverlap => "contact end zero_overlap: Eq. (5) read literally, a tensile \
                 viscoelastic force acts while separating"
                .into(),
            Warning::LayerLiteral => "Eq. (8) literal reading: threshold ≈ 2 g_s and ε_N can \
                 exceed the clean value, contradicting the paper's text"
                .into(),
            Warning::AdhesionModulusConsistent => {
                "adhesion modulus consistent: E = Y/(2(1−ν²)) instead of the printed Y/(1−ν²)"
                    .into()
            }
        }
    }

    /// What it means and what to do about it (help screens).
    pub const fn help(&self) -> &'static str {
        match self {
            Warning::Overdamped { .. } => {
                "The viscous term of Eq. (4) dissipates nearly all the energy: ε_N is below 1e-9. \
                 The model never sticks without a layer or adhesion, so the grains separate with \
                 a negligible speed. A shorter damping time A gives a visible rebound."
            }
            Warning::AFormulaAsPrinted => {
                "The paper's formula for A from the viscosities lacks the factor (1−2ν) of \
                 Brilliantov et al. (1996); the scene uses it as printed \
                 (docs/physics.md#decision-1)."
            }
            Warning::ZeroOverlap => {
                "With the contact ending at zero overlap the viscoelastic force of Eq. (5) pulls \
                 the grains together while they separate; the default ends the contact when the \
                 force returns to zero (docs/physics.md#decision-2)."
            }
            Warning::LayerLiteral => {
                "Read literally, Eq. (8) puts the threshold near 2 g_s and lets ε_N exceed the \
                 clean-surface value, which the paper's text rules out; the default is the offset \
                 reading (docs/physics.md#decision-4)."
            }
            Warning::AdhesionModulusConsistent => {
                "The adhesion model's modulus E is taken as Y/(2(1−ν²)), the contact modulus Eq. (4) \
                 implies for two grains of one material, instead of the printed Y/(1−ν²) \
                 (docs/physics.md#decision-5)."
            }
        }
    }
}

/// The warnings of `scene` and its curve's statuses (`statuses` of the plotted speeds; `None`
/// where a speed failed), with the damping time A \[s\].
pub fn warnings(
    scene: &Scene,
    statuses: impl IntoIterator<Item = Option<Status>>,
    damping_time: Option<f64>,
) -> Vec<Warning> {
    let mut w = Vec::new();
    let (mut n, mut over) = (0, 0);
    for s in statuses {
        n += 1;
        if s == Some(Status::Overdamped) {
            over += 1;
        }
    }
    if over > 0 {
        w.push(Warning::Overdamped {
            all: over == n,
            damping_time: damping_time.unwrap_or(f64::NAN),
        });
    }
    if let Damping::Viscosities(v) = scene.bulk.damping
        && v.formula == DampingFormula::AsPrinted
    {
        w.push(Warning::AFormulaAsPrinted);
    }
    if scene.contact_end == ContactEnd::ZeroOverlap {
        w.push(Warning::ZeroOverlap);
    }
    if scene
        .layer
        .is_some_and(|l| l.reading == LayerReading::Literal)
    {
        w.push(Warning::LayerLiteral);
    }
    if scene
        .adhesion
        .is_some_and(|a| a.modulus == AdhesionModulus::Consistent)
    {
        w.push(Warning::AdhesionModulusConsistent);
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Preset;

    #[test]
    fn each_option_that_departs_from_the_paper_is_named_once_issue_21() {
        let mut s = Preset::IceFrost.scene();
        assert!(warnings(&s, [], None).is_empty());
        s.set("layer.reading", "literal").expect("set");
        s.set("contact_end", "zero_overlap").expect("set");
        let w = warnings(
            &s,
            [Some(Status::Rebound), Some(Status::Overdamped)],
            Some(1.0),
        );
        let keys: Vec<&str> = w.iter().map(Warning::key).collect();
        assert_eq!(keys, ["overdamped", "zero_overlap", "layer_literal"]);
        assert_eq!(w[0].short(), "overdamped in part");
        // Issue 37 (review C7): A as people read numbers (it was `1.000e0 s`, `4.044e2 s`).
        assert!(w[0].text().contains("(A = 1 s)"), "{}", w[0].text());
        let paper = Warning::Overdamped {
            all: true,
            damping_time: 404.4,
        };
        assert!(paper.text().contains("(A = 404.4 s)"), "{}", paper.text());
        let short = Warning::Overdamped {
            all: true,
            damping_time: 2e-4,
        };
        assert!(short.text().contains("(A = 200 µs)"), "{}", short.text());
        // Every kind has its words and an equation of the paper.
        for k in Warning::ALL {
            assert!(!k.short().is_empty() && !k.help().is_empty() && !k.text().is_empty());
            assert!(k.equation().starts_with("Eq. ("));
        }
    }
}
