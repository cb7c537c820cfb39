//! Words for every surface: the paper's citation, the one glossary of the symbols a newcomer meets
//! (ε_N, g_N, g_T, "this scene", …), the experiments' sources, one line of help per parameter and human names for the options
//! of choice parameters (`force_zero` reads "force returns to zero (paper)"). Defined once here so
//! that the terminal's help, the web page and exported captions say the same thing.

/// The paper every surface cites.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Citation {
    /// Authors as printed.
    pub authors: &'static str,
    /// Year of publication.
    pub year: u16,
    /// Title.
    pub title: &'static str,
    /// Journal.
    pub journal: &'static str,
    /// Volume.
    pub volume: &'static str,
    /// Pages.
    pub pages: &'static str,
}

/// J.-M. Hertzsch (2002), the model rime implements.
pub const PAPER: Citation = Citation {
    authors: "J.-M. Hertzsch",
    year: 2002,
    title: "A model for surface effects in slow collisions of icy grains",
    journal: "Planetary and Space Science",
    volume: "50",
    pages: "1387–1397",
};

/// The one glossary of every surface (the terminal's `?` overlay, the page's intro): a term and
/// what it means, in the order a newcomer meets them.
pub const GLOSSARY: [(&str, &str); 21] = [
    (
        "ε_N",
        "normal coefficient of restitution −g'_N/g_N: the speed of separation along the line of \
         centres divided by the impact speed (1 elastic, 0 the grains stick), Eq. (1)",
    ),
    (
        "ε_T",
        "tangential coefficient of restitution g'_T/g_T, −1 … 1: the sliding speed of the \
         surfaces after the collision divided by the one before (negative: the motion reverses, \
         rolling), Eq. (1)",
    ),
    (
        "g_N",
        "impact speed: the normal component of the relative velocity of the surfaces, along the \
         line of centres [m/s]",
    ),
    (
        "g_T",
        "tangential component of the relative surface velocity at impact, across the line of \
         centres, Eq. (2) [m/s]",
    ),
    (
        "g_s",
        "critical speed: below it the grains stick (a soft layer, Eq. (10), or adhesion, Eq. (15)); \
         a threshold on the impact speed",
    ),
    (
        "g_s layer",
        "impact speed below which the soft layer stops the grains (Eq. (10)); sticking left of \
         the marker",
    ),
    (
        "g_s adhesion",
        "a rebound speed (Eq. (15)): the grains stick when their rebound speed without adhesion, \
         ε_N·g_N, is below it; the chart draws it at g_N = g_s on the impact axis, and sticking \
         reaches up to where ε_N·g_N = g_s, right of the marker",
    ),
    (
        "δ, δ(g)",
        "dimensionless damping A α^(2/5) g^(1/5) of one collision, at the cursor's speed g; large \
         δ: overdamped",
    ),
    (
        "tan ψ₀",
        "μ/κ (Eq. (25)): impacts with g_T/g_N above it slide, below it roll",
    ),
    (
        "A",
        "damping time of the viscoelastic bulk (Eq. (4)) [s]; η₁, η₂ give it when set",
    ),
    (
        "R_eff, m_eff",
        "reduced radius R₁R₂/(R₁+R₂) and reduced mass m₁m₂/(m₁+m₂) of the pair",
    ),
    ("t_c", "contact duration of one collision [s]"),
    (
        "η*, D",
        "viscosity and thickness of the soft surface layer (frost, dust; Eq. (6)–(10))",
    ),
    (
        "γ",
        "surface energy of adhesion (JKR, Eq. (11)–(17)) [J/m²]",
    ),
    (
        "μ, κ",
        "friction coefficient and reduced moment of inertia (2/7 for solid spheres)",
    ),
    (
        "this scene",
        "the grains and surfaces set in the parameters: two spheres of given radii, bulk material \
         and, optionally, a soft surface layer, adhesion and friction",
    ),
    (
        "family",
        "the scene's curve repeated with one parameter varied around its value (η* with a layer, \
         γ with adhesion, else A, or the one chosen); the member equal to the scene is marked",
    ),
    (
        "clean surface",
        "the same grains without a layer and without adhesion: what the bulk alone gives",
    ),
    (
        "stick map",
        "which tangential regime each impact ends in, over (g_T across, g_N up), as in Fig. 4 of \
         the paper",
    ),
    (
        "pinned",
        "a curve kept to compare with later edits, drawn dashed",
    ),
    (
        "computed in",
        "wall time of the last frame at the accuracy level shown",
    ),
];

/// The sources of the ε_N chart's experimental context, one line each (`Bridges et al. 1984: ε =
/// 0.32 (v / 1 cm/s)^−0.234, measured 150 µm/s–20 mm/s`), built from the data atlas and the
/// Bridges law.
#[cfg(feature = "alloc")]
pub fn experiment_sources() -> alloc::vec::Vec<alloc::string::String> {
    use crate::format::qty;
    use alloc::format;
    let speeds = |[lo, hi]: [f64; 2]| {
        let (a, b) = (qty(lo, "m/s"), qty(hi, "m/s"));
        match (a.split_once(' '), b.split_once(' ')) {
            (Some((na, ua)), Some((_, ub))) if ua == ub => format!("{na}–{b}"),
            _ => format!("{a}–{b}"),
        }
    };
    let mut out = alloc::vec::Vec::new();
    if let Some(b) = crate::data::atlas::find("bridges1984") {
        let label = crate::fit::BRIDGES_1984_LABEL;
        out.push(format!("{label}, measured {}", speeds(b.valid_speed)));
    }
    for e in crate::data::atlas::ENTRIES
        .iter()
        .filter(|e| e.band().is_some())
    {
        out.push(format!(
            "{} {}: {}",
            e.citation.short_authors(),
            e.citation.year,
            speeds(e.valid_speed)
        ));
    }
    out
}

/// One line of help for a parameter of [`crate::scene::params::PARAMETERS`] (by path).
pub fn parameter_help(path: &str) -> Option<&'static str> {
    Some(match path {
        "grains.radius_1" => "radius of the first sphere; the contact uses R_eff = R₁R₂/(R₁+R₂)",
        "grains.radius_2" => "radius of the second sphere (a very large radius: a flat wall)",
        "grains.density" => "density of both grains (ice ≈ 900 kg/m³); sets their masses",
        "bulk.youngs_modulus" => {
            "Young's modulus Y of the bulk (ice ≈ 10 GPa): the Hertz stiffness"
        }
        "bulk.poisson_ratio" => "Poisson ratio ν of the bulk (ice ≈ 0.3)",
        "bulk.damping.time" => {
            "damping time A of the viscoelastic bulk, Eq. (4): larger A, more dissipation, lower ε_N"
        }
        "bulk.damping.viscosities.shear" => {
            "shear viscosity η₁ of the bulk, from which A is derived"
        }
        "bulk.damping.viscosities.bulk" => "bulk viscosity η₂ of the bulk, from which A is derived",
        "bulk.damping.viscosities.formula" => "how A follows from η₁ and η₂ (decision 1)",
        "contact_end" => "when a collision ends: the paper's reading or the overlap (decision 2)",
        "layer" => "a soft surface layer (frost) of thickness D and viscosity η*, Eq. (8)–(10)",
        "layer.thickness" => "thickness D of the soft layer; g_s grows as D^(3/2), Eq. (10)",
        "layer.viscosity" => "viscosity η* of the soft layer: how strongly it brakes, Eq. (8)",
        "layer.reading" => "how Eq. (8) is read (decision 4)",
        "adhesion" => "surface adhesion (JKR) with surface energy γ, Eq. (11)–(17)",
        "adhesion.surface_energy" => {
            "surface energy γ: the work of separation; g_s grows as γ^(5/6), Eq. (15)"
        }
        "adhesion.modulus" => "which elastic modulus enters Eq. (12) (decision 5)",
        "adhesion.jkr_end" => {
            "where the dynamic JKR contact (brilliantov2007, the collision card's loop) ends: the neck, or the maximum tensile force as LAMMPS does"
        }
        "friction" => "tangential friction: ε_T and the stick map, Eq. (18)–(26)",
        "friction.coefficient" => {
            "friction coefficient μ: sliding sets in above tan ψ₀ = μ/κ, Eq. (25)"
        }
        "friction.kappa" => {
            "κ = q/(1+q), the reduced moment of inertia (2/7 for solid spheres), Eq. (22)"
        }
        "friction.sliding_law" => "ε_T on the sliding branch (decision 6)",
        _ => return None,
    })
}

/// The range a slider spans for a number parameter (SI units; log-spaced where the parameter is):
/// the values a user explores, narrower than what the core accepts (typed values may go further).
pub fn slider_range(path: &str) -> Option<(f64, f64)> {
    Some(match path {
        "grains.radius_1" | "grains.radius_2" => (1e-6, 1.0),
        "grains.density" => (100.0, 1e4),
        "bulk.youngs_modulus" => (1e6, 1e12),
        "bulk.poisson_ratio" => (-0.99, 0.5),
        "bulk.damping.time" => (1e-8, 1e3),
        "bulk.damping.viscosities.shear" | "bulk.damping.viscosities.bulk" => (1.0, 1e15),
        "layer.thickness" => (1e-9, 1e-3),
        "layer.viscosity" => (1.0, 1e7),
        "adhesion.surface_energy" => (1e-4, 10.0),
        "friction.coefficient" => (0.0, 2.0),
        "friction.kappa" => (0.01, 1.0),
        _ => return None,
    })
}

/// A human name for `option` of the choice parameter `path` (`None` when unknown).
pub fn option_label(path: &str, option: &str) -> Option<&'static str> {
    Some(match (path, option) {
        ("bulk.damping.viscosities.formula", "brilliantov") => {
            "Brilliantov et al. 1996 (consistent)"
        }
        ("bulk.damping.viscosities.formula", "as_printed") => "as printed in the paper",
        ("contact_end", "force_zero") => "when the force returns to zero",
        ("contact_end", "zero_overlap") => "when the overlap returns to zero",
        ("layer.reading", "offset") => "offset layer (consistent)",
        ("layer.reading", "literal") => "literal Eq. (8) (slow, live integration)",
        ("adhesion.modulus", "as_printed") => "as printed in the paper",
        ("adhesion.modulus", "consistent") => "consistent with Eq. (4)",
        ("adhesion.jkr_end", "neck") => "at the neck instability (fixed grips)",
        ("adhesion.jkr_end", "pull_off_force") => "at the maximum tensile force (LAMMPS jkr)",
        ("friction.sliding_law", "paper") => "paper's Eq. (23) (has an artifact gap)",
        ("friction.sliding_law", "walton") => "Walton's law (no gap)",
        _ => return None,
    })
}

/// Whether a stick-map class is an artifact of the printed law rather than a physical regime.
pub fn class_is_artifact(c: crate::tangential::StickClass) -> bool {
    c == crate::tangential::StickClass::SlidingGap
}

/// The artifact class flagged in one line, for tables and data files that name it `sliding_gap`.
pub const ARTIFACT_NOTE_SHORT: &str = "sliding_gap: an artifact of the printed Eq. (23) (its \
radicand is negative just above tan ψ0 and ε_T is clamped to 0), not a regime; Walton's law has no \
gap (docs/physics.md#decision-6)";

/// What the artifact class means, for the note beside the map.
pub const ARTIFACT_NOTE: &str = "Grey \"sliding gap\" cells are an artifact of the printed law, not \
a regime: just above tan ψ₀ the radicand of Eq. (23) is negative, and ε_T is clamped to 0 there; \
the paper does not mention it. Walton's sliding law has no gap.";

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::params::{Kind, PARAMETERS};

    #[test]
    fn every_parameter_has_help_and_every_option_a_name() {
        for p in PARAMETERS {
            assert!(parameter_help(p.path).is_some(), "{}", p.path);
            if let Kind::Choice(options) = p.kind {
                for o in options {
                    let label = option_label(p.path, o).unwrap_or_else(|| panic!("{} {o}", p.path));
                    assert!(!label.contains('_'), "{label}");
                }
            }
        }
        assert!(parameter_help("no.such").is_none());
        for p in PARAMETERS {
            if let Kind::Number { min, max, .. } = p.kind {
                let (lo, hi) = slider_range(p.path).unwrap_or_else(|| panic!("{}", p.path));
                assert!(min <= lo && lo < hi && hi <= max, "{}", p.path);
            }
        }
        assert!(option_label("contact_end", "nope").is_none());
    }

    /// Issue 36: one glossary — every term once, and the sources say what the atlas says (the
    /// speeds are the sources' own: Bridges et al. 1984's pendulum 0.15–20 mm/s as tabulated by
    /// Hill et al. 2015, Heißelmann et al. 2010 6–22 cm/s, Hill et al. 2015 0.27–0.51 m/s).
    #[test]
    fn issue_36_one_glossary_and_the_sources_from_the_atlas() {
        for (i, (term, meaning)) in GLOSSARY.iter().enumerate() {
            assert!(!meaning.is_empty(), "{term}");
            assert!(
                GLOSSARY[i + 1..].iter().all(|(t, _)| t != term),
                "{term} twice"
            );
        }
        let sources = experiment_sources();
        assert_eq!(
            sources,
            [
                "Bridges et al. 1984: ε = 0.32 (v / 1 cm/s)^−0.234, measured 150 µm/s–20 mm/s",
                "Heißelmann et al. 2010: 60–220 mm/s",
                "Hill et al. 2015: 270–510 mm/s",
            ]
        );
    }
}
