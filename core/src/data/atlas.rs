//! The data atlas: published measurements of icy collisions, with their provenance.
//!
//! Every community re-types the published ice laws by hand, with different prefactors, units and
//! clamps. This module keeps them once, in SI units at the interface, each with its citation, the
//! range it was measured over, the geometry, any clamp a simulation code applies, and how the
//! numbers were obtained (`source`) and checked (`verified`); `docs/physics.md#data-atlas` holds the
//! same record in prose.
//!
//! * [`ENTRIES`] — every entry; [`find`] by id.
//! * [`Entry::eval`] — a law at an impact speed (and radius where it needs one), with a flag when
//!   the speed lies outside the measured range.
//! * [`score`] — rms of ε_scene − ε_entry over the entry's range, for comparing a scene with data.
//!
//! Static data, no allocation: usable with `no_std`.

use crate::error::{Error, Result};
use crate::numerics::accuracy::Accuracy;
use crate::numerics::math::{exp, ln, log10, powf};
use crate::scene::contact::Contact;

/// What an entry describes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// ε_N as a function of the impact speed.
    Law,
    /// A range of measured ε_N over a range of speeds, without a fitted law.
    Range,
    /// A sticking threshold or a surface energy that sets one.
    Threshold,
}

impl Kind {
    /// The name used in the CLI/JSON contract.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Law => "law",
            Kind::Range => "range",
            Kind::Threshold => "threshold",
        }
    }
}

/// The collision geometry of an experiment.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Geometry {
    /// Two free spheres (the paper's case).
    SphereSphere,
    /// A sphere against a flat block (pendulum and free-fall experiments): R_eff is the sphere's radius.
    SphereFlat,
    /// Micrometre grains hitting a grown aggregate of the same grains.
    GrainAggregate,
}

impl Geometry {
    /// The name used in the CLI/JSON contract.
    pub fn name(self) -> &'static str {
        match self {
            Geometry::SphereSphere => "sphere-sphere",
            Geometry::SphereFlat => "sphere-flat",
            Geometry::GrainAggregate => "grain-aggregate",
        }
    }
}

/// A bibliographic reference.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Citation {
    /// Authors as printed, e.g. `"Bridges, F. G., Hatzes, A. P., Lin, D. N. C."`.
    pub authors: &'static str,
    /// Year of publication.
    pub year: u16,
    /// Journal or book.
    pub journal: &'static str,
    /// Volume (empty for a book chapter).
    pub volume: &'static str,
    /// Pages or article number.
    pub pages: &'static str,
    /// DOI where known and checked.
    pub doi: Option<&'static str>,
}

impl Citation {
    /// The first author's surname, with "et al." for three or more authors and "& B" for two
    /// (`Hatzes et al.`, `Gundlach & Blum`): authors are printed as `Surname, I., Surname, I.`.
    pub fn short_authors(&self) -> alloc_free::ShortAuthors {
        let mut names = self
            .authors
            .split(", ")
            .filter(|p| !p.is_empty() && !p.ends_with('.'));
        let first = names.next().unwrap_or(self.authors);
        let second = names.next();
        let more = names.next().is_some();
        alloc_free::ShortAuthors {
            first,
            second: if more { None } else { second },
            et_al: more,
        }
    }
}

/// Formatting without allocation (the atlas is `no_std`).
pub mod alloc_free {
    /// A citation's authors in short form; `Display` writes `Hatzes et al.`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct ShortAuthors {
        /// The first author's surname.
        pub first: &'static str,
        /// The second author's surname, when there are exactly two.
        pub second: Option<&'static str>,
        /// Three or more authors.
        pub et_al: bool,
    }

    impl core::fmt::Display for ShortAuthors {
        fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
            match (self.second, self.et_al) {
                (_, true) => write!(f, "{} et al.", self.first),
                (Some(b), false) => write!(f, "{} & {b}", self.first),
                (None, false) => f.write_str(self.first),
            }
        }
    }
}

/// The mathematical form of an entry. Speeds inside the forms are in the source's own units;
/// [`Entry::eval`] takes and returns SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Form {
    /// ε = a (v / v0)^b with v0 in m/s.
    Power {
        /// Prefactor.
        a: f64,
        /// Exponent.
        b: f64,
        /// Reference speed \[m/s\].
        v0: f64,
    },
    /// ε = 1 for v ≤ v_c, (v / v_c)^b above (a power law clamped at 1).
    ClampedPower {
        /// Exponent.
        b: f64,
        /// Crossover speed \[m/s\].
        v_c: f64,
    },
    /// ε = a exp(−(k0 − k1 r) v) + c v^d, with v in cm/s and r the reduced radius in cm.
    Exponential {
        /// Prefactor a.
        a: f64,
        /// Rate at r = 0 \[(cm/s)^-1\].
        k0: f64,
        /// Change of the rate per cm of radius \[(cm/s)^-1 cm^-1\].
        k1: f64,
        /// Prefactor c of the additive power term (0 when absent).
        c: f64,
        /// Exponent d of the additive power term.
        d: f64,
    },
    /// ε = (v / v_c)^(−log₁₀(v / v_c)), v_c in m/s.
    LogPower {
        /// Critical speed \[m/s\].
        v_c: f64,
    },
    /// Measured ε between `lo` and `hi`, no law.
    Band {
        /// Smallest measured ε.
        lo: f64,
        /// Largest measured ε.
        hi: f64,
    },
    /// Grains stick below `v` \[m/s\].
    StickBelow {
        /// Threshold speed \[m/s\].
        v: f64,
    },
    /// Surface energy rising from `gamma_lo` at `t_lo` to `gamma_hi` at `t_hi` (log-linear in
    /// between, constant outside) \[J/m², K\].
    SurfaceEnergy {
        /// Lower temperature \[K\].
        t_lo: f64,
        /// Upper temperature \[K\].
        t_hi: f64,
        /// γ at and below `t_lo` \[J/m²\].
        gamma_lo: f64,
        /// γ at and above `t_hi` \[J/m²\].
        gamma_hi: f64,
    },
}

/// One atlas entry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Entry {
    /// Stable identifier (`bridges1984`).
    pub id: &'static str,
    /// Law, range or threshold.
    pub kind: Kind,
    /// The reference.
    pub citation: Citation,
    /// One-line description of the material and surface.
    pub material: &'static str,
    /// The formula as the source writes it.
    pub formula: &'static str,
    /// Units of the formula's variables.
    pub units: &'static str,
    /// The form used by [`Entry::eval`].
    pub form: Form,
    /// Measured speeds `[lo, hi]` \[m/s\].
    pub valid_speed: [f64; 2],
    /// Grain radii `[lo, hi]` \[m\] (radius, not diameter).
    pub radius: [f64; 2],
    /// Temperatures `[lo, hi]` \[K\].
    pub temperature: [f64; 2],
    /// Collision geometry.
    pub geometry: Geometry,
    /// Any clamp a simulation code applies, or `""`.
    pub clamp: &'static str,
    /// How the entry was obtained: from the source's text, or as used in a named code.
    pub source: &'static str,
    /// What was verified against which text, and what could not be.
    pub verified: &'static str,
    /// Another entry this one conflicts with, or `""`.
    pub conflicts_with: &'static str,
}

/// A law evaluated at one speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Evaluation {
    /// Impact speed \[m/s\].
    pub g: f64,
    /// ε_N of the law (not clamped).
    pub eps: f64,
    /// The speed (or radius) lies outside the measured range.
    pub extrapolated: bool,
}

const CM: f64 = 0.01;

const HATZES_1988: Citation = Citation {
    authors: "Hatzes, A. P., Bridges, F. G., Lin, D. N. C.",
    year: 1988,
    journal: "Mon. Not. R. Astron. Soc.",
    volume: "231",
    pages: "1091-1115",
    doi: None,
};

// The pendulum range of the Santa Cruz group as tabulated by Hill et al. (2015), Table 2.
/// The speeds of the Bridges et al. (1984) pendulum measurements \[m/s\].
pub const PENDULUM_SPEED: [f64; 2] = [1.5e-4, 0.02];

/// Every atlas entry, in the order listed by `rime data`.
pub const ENTRIES: &[Entry] = &[
    Entry {
        id: "bridges1984",
        kind: Kind::Law,
        citation: Citation {
            authors: "Bridges, F. G., Hatzes, A. P., Lin, D. N. C.",
            year: 1984,
            journal: "Nature",
            volume: "309",
            pages: "333-335",
            doi: None,
        },
        material: "frost-covered water ice",
        formula: "eps = (v / v_c)^-0.234, v_c = 0.0077 cm/s  (= 0.32 (v / 1 cm/s)^-0.234)",
        units: "v and v_c in cm/s",
        form: Form::Power {
            a: 1.0,
            b: -0.234,
            v0: 0.0077 * CM,
        },
        valid_speed: PENDULUM_SPEED,
        radius: [0.025, 0.025],
        temperature: [210.0, 210.0],
        geometry: Geometry::SphereFlat,
        clamp: "REBOUND (examples/shearing_sheet) writes 0.32 (100 v)^-0.234 and clamps eps to [0, 1]; the law exceeds 1 below v_c = 77 um/s",
        source: "as used in ring codes (Morgado et al. 2023, Nature 614, 239, Extended Data Fig. 4, model 1; REBOUND shearing-sheet example); original not reached",
        verified: "form, exponent -0.234, v_c = 0.0077 cm/s and T = 210 K from the Morgado et al. (2023) caption; prefactor 0.32 from REBOUND's source; (1/0.0077)^-0.234 = 0.3202, so both are one law. A prefactor 0.34 was not found in any text reached. Speed range and size: assumed equal to the same pendulum's in Hatzes et al. (1988), not verified",
        conflicts_with: "",
    },
    Entry {
        id: "hatzes1988_frost",
        kind: Kind::Law,
        citation: HATZES_1988,
        material: "frost-covered water ice",
        formula: "eps = 0.48 v^-0.20",
        units: "v in cm/s",
        form: Form::Power {
            a: 0.48,
            b: -0.20,
            v0: CM,
        },
        valid_speed: PENDULUM_SPEED,
        radius: [0.025, 0.025],
        temperature: [123.0, 123.0],
        geometry: Geometry::SphereFlat,
        clamp: "",
        source: "as used in ring codes (Morgado et al. 2023, Extended Data Fig. 4, model 2); original not reached",
        verified: "coefficients 0.48, -0.20 and T = 123 K from the Morgado et al. (2023) caption; speed range 0.00015-0.02 m/s, 85-145 K, 50 mm spheres on an ice block from Hill et al. (2015), Table 2; abstract (NASA ADS/NTRS) confirms that frost turns the exponential law into a power law",
        conflicts_with: "",
    },
    Entry {
        id: "hatzes1988_compacted",
        kind: Kind::Law,
        citation: HATZES_1988,
        material: "water ice with compacted frost",
        formula: "eps = 0.90 exp(-(0.41 - 0.01 r) v)",
        units: "v in cm/s, r the reduced radius in cm (0 < r < 41 cm)",
        form: Form::Exponential {
            a: 0.90,
            k0: 0.41,
            k1: 0.01,
            c: 0.0,
            d: 0.0,
        },
        valid_speed: PENDULUM_SPEED,
        radius: [0.0, 0.41],
        temperature: [123.0, 123.0],
        geometry: Geometry::SphereFlat,
        clamp: "",
        source: "as stated in issue 15 of this project; original not reached",
        verified: "not verified: Morgado et al. (2023), Extended Data Fig. 4, model 4, quote for R = 20 cm 0.90 exp(-0.22 v) + 0.01 v^-0.6, i.e. rate 0.22 (this form gives 0.21) and an extra power term; shipped as hatzes1988_compacted_r20",
        conflicts_with: "hatzes1988_compacted_r20",
    },
    Entry {
        id: "hatzes1988_compacted_r20",
        kind: Kind::Law,
        citation: HATZES_1988,
        material: "water ice with compacted frost, particle radius 20 cm",
        formula: "eps = 0.90 exp(-0.22 v) + 0.01 v^-0.6",
        units: "v in cm/s",
        form: Form::Exponential {
            a: 0.90,
            k0: 0.22,
            k1: 0.0,
            c: 0.01,
            d: -0.6,
        },
        valid_speed: PENDULUM_SPEED,
        radius: [0.2, 0.2],
        temperature: [123.0, 123.0],
        geometry: Geometry::SphereFlat,
        clamp: "",
        source: "as used in ring codes (Morgado et al. 2023, Extended Data Fig. 4, model 4); original not reached",
        verified: "coefficients, R = 20 cm and T = 123 K from the Morgado et al. (2023) caption",
        conflicts_with: "hatzes1988_compacted",
    },
    Entry {
        id: "supulver1995",
        kind: Kind::Law,
        citation: Citation {
            authors: "Supulver, K. D., Bridges, F. G., Lin, D. N. C.",
            year: 1995,
            journal: "Icarus",
            volume: "113",
            pages: "188-199",
            doi: None,
        },
        material: "unfrosted water ice, glancing collisions",
        formula: "eps = 0.52 v^-0.14",
        units: "v in cm/s (assumed, as in the group's other laws)",
        form: Form::Power {
            a: 0.52,
            b: -0.14,
            v0: CM,
        },
        valid_speed: PENDULUM_SPEED,
        radius: [0.025, 0.025],
        temperature: [100.0, 150.0],
        geometry: Geometry::SphereFlat,
        clamp: "",
        source: "as stated in issue 15 of this project; original not reached",
        verified: "not verified: no text reached gives the coefficients, units, range or temperature; citation from memory",
        conflicts_with: "",
    },
    Entry {
        id: "higa1996",
        kind: Kind::Law,
        citation: Citation {
            authors: "Higa, M., Arakawa, M., Maeno, N.",
            year: 1996,
            journal: "Planet. Space Sci.",
            volume: "44",
            pages: "917-925",
            doi: None,
        },
        material: "smooth water ice sphere on an ice block, above the critical speed",
        formula: "eps = (v / v_c)^(-log10(v / v_c)), v_c = 1.8 m/s, for v > v_c (eps = 1 at v_c)",
        units: "v in m/s",
        form: Form::LogPower { v_c: 1.8 },
        valid_speed: [1.8, 7.0],
        radius: [0.015, 0.015],
        temperature: [113.0, 269.0],
        geometry: Geometry::SphereFlat,
        clamp: "below v_c the experiments show a nearly constant eps (quasi-elastic regime); the law is meant above v_c only",
        source: "as stated in issue 15 of this project; original not reached",
        verified: "set-up (30 mm ice sphere on an ice block, free fall, 0.01-7 m/s, 113-269 K) from Hill et al. (2015), Table 2; the form, the base of the logarithm, v_c = 1.8 m/s and its temperature could not be verified",
        conflicts_with: "",
    },
    Entry {
        id: "borderies1984",
        kind: Kind::Law,
        citation: Citation {
            authors: "Borderies, N., Goldreich, P., Tremaine, S.",
            year: 1984,
            journal: "Planetary Rings (Greenberg, R., Brahic, A., eds.), Univ. of Arizona Press",
            volume: "",
            pages: "713-734",
            doi: None,
        },
        material: "ring-dynamics ansatz (no experiment)",
        formula: "eps = 1 for v <= v_c, (v / v_c)^-0.234 above, v_c = 0.0077 cm/s",
        units: "v in cm/s",
        form: Form::ClampedPower {
            b: -0.234,
            v_c: 0.0077 * CM,
        },
        valid_speed: [0.0077 * CM, 0.02],
        radius: [0.0, f64::INFINITY],
        temperature: [0.0, f64::INFINITY],
        geometry: Geometry::SphereSphere,
        clamp: "eps = 1 below v_c",
        source: "the clamped Bridges form ring codes use (REBOUND clamps the same law at 1); attributed to this chapter by issue 15, text not reached",
        verified: "not verified: the chapter's text was not reached; the coefficients are those of bridges1984",
        conflicts_with: "",
    },
    Entry {
        id: "heisselmann2010",
        kind: Kind::Range,
        citation: Citation {
            authors: "Heißelmann, D., Blum, J., Fraser, H. J., Wolling, K.",
            year: 2010,
            journal: "Icarus",
            volume: "206",
            pages: "424-430",
            doi: None,
        },
        material: "rough, unfrosted water-ice spheres in microgravity",
        formula: "eps between 0.06 and 0.84",
        units: "",
        form: Form::Band { lo: 0.06, hi: 0.84 },
        valid_speed: [0.06, 0.22],
        radius: [0.0075, 0.0075],
        temperature: [130.0, 180.0],
        geometry: Geometry::SphereSphere,
        clamp: "",
        source: "from the source's results as summarised by Hill et al. (2015), Table 2, and this project's docs",
        verified: "diameter 15 mm, 0.06-0.22 m/s, 130-180 K from Hill et al. (2015), Table 2; the eps range 0.06-0.84 could not be verified",
        conflicts_with: "",
    },
    Entry {
        id: "hill2015",
        kind: Kind::Range,
        citation: Citation {
            authors: "Hill, C. R., Heißelmann, D., Blum, J., Fraser, H. J.",
            year: 2015,
            journal: "Astron. Astrophys.",
            volume: "573",
            pages: "A49",
            doi: Some("10.1051/0004-6361/201424069"),
        },
        material: "rough, unfrosted water-ice spheres and fragments in microgravity",
        formula: "eps between 0.08 and 0.65 (mean 0.36)",
        units: "",
        form: Form::Band { lo: 0.08, hi: 0.65 },
        valid_speed: [0.27, 0.51],
        radius: [0.00235, 0.0054],
        temperature: [131.0, 160.0],
        geometry: Geometry::SphereSphere,
        clamp: "",
        source: "from the source's text (abstract and Table 2)",
        verified: "diameters 4.7-10.8 mm, 0.27-0.51 m/s, 131-160 K, eps 0.08-0.65 with mean 0.36 from the abstract (arXiv 1411.0563); journal, volume, article and DOI from the A&A page. The project's docs cited A&A 575, A6, which is part II (1.5 cm spheres, 0.01-0.19 m/s)",
        conflicts_with: "",
    },
    Entry {
        id: "gundlach2015",
        kind: Kind::Threshold,
        citation: Citation {
            authors: "Gundlach, B., Blum, J.",
            year: 2015,
            journal: "Astrophys. J.",
            volume: "798",
            pages: "34",
            doi: Some("10.1088/0004-637X/798/1/34"),
        },
        material: "micrometre water-ice grains onto ice aggregates",
        formula: "sticking below 9.6 m/s for T below ~210 K (erosion above 15.3 m/s)",
        units: "m/s",
        form: Form::StickBelow { v: 9.6 },
        valid_speed: [0.0, 9.6],
        radius: [7.0e-7, 2.3e-6],
        temperature: [114.0, 210.0],
        geometry: Geometry::GrainAggregate,
        clamp: "",
        source: "from the source's text (abstract, arXiv 1410.7199)",
        verified: "9.6 m/s, ~210 K, 114-260 K studied and 15.3 m/s erosion from the abstract; grain radius 1.45-1.49 um (spread +-0.7 um) from Gundlach et al. (2011), arXiv 1102.0430; journal, volume and DOI from memory, not verified. Its temperature dependence (sticky when cold) conflicts with musiolik2019",
        conflicts_with: "musiolik2019",
    },
    Entry {
        id: "musiolik2019",
        kind: Kind::Threshold,
        citation: Citation {
            authors: "Musiolik, G., Wurm, G.",
            year: 2019,
            journal: "Astrophys. J.",
            volume: "873",
            pages: "58",
            doi: None,
        },
        material: "1.1 mm water-ice grains, sticking and rolling",
        formula: "gamma = 0.0029 J/m^2 at 175 K rising to 0.19 J/m^2 at 200 K (factor 63.4), level above",
        units: "J/m^2, K",
        form: Form::SurfaceEnergy {
            t_lo: 175.0,
            t_hi: 200.0,
            gamma_lo: 0.0029,
            gamma_hi: 0.19,
        },
        valid_speed: [0.0, 0.0],
        radius: [5.5e-4, 5.5e-4],
        temperature: [175.0, 200.0],
        geometry: Geometry::SphereSphere,
        clamp: "rime interpolates log-linearly between 175 K and 200 K and holds the end values outside",
        source: "from the source's text (abstract, arXiv 1902.08503)",
        verified: "0.0029 and 0.19 J/m^2, 175-200 K, factor 63.4 and 1.1 mm grains from the abstract (0.19/0.0029 = 65.5, not 63.4: the abstract's values are rounded); the shape of gamma(T) between 175 K and 200 K and the journal reference could not be verified. Its temperature dependence (not sticky when cold) conflicts with gundlach2015",
        conflicts_with: "gundlach2015",
    },
];

/// The entry with identifier `id`.
pub fn find(id: &str) -> Option<&'static Entry> {
    ENTRIES.iter().find(|e| e.id == id)
}

fn check_speed(g: f64) -> Result<f64> {
    if g.is_finite() && g > 0.0 {
        Ok(g)
    } else {
        Err(Error::OutOfRange {
            field: "g_n",
            value: g,
            expected: "must be a finite speed > 0",
        })
    }
}

impl Entry {
    /// Whether the entry needs a radius to be evaluated.
    pub fn needs_radius(&self) -> bool {
        matches!(self.form, Form::Exponential { k1, .. } if k1 != 0.0)
    }

    /// ε_N of a law at impact speed `g` \[m/s\]; `radius` \[m\] is the reduced radius, required by
    /// laws that depend on it and ignored by the others. Outside the measured speeds (or radii) the
    /// law is still evaluated and the result says `extrapolated`. Ranges and thresholds are not laws
    /// and give an error.
    pub fn eval(&self, g: f64, radius: Option<f64>) -> Result<Evaluation> {
        let g = check_speed(g)?;
        let mut extrapolated = g < self.valid_speed[0] || g > self.valid_speed[1];
        let eps = match self.form {
            Form::Power { a, b, v0 } => a * powf(g / v0, b),
            Form::ClampedPower { b, v_c } => {
                if g <= v_c {
                    1.0
                } else {
                    powf(g / v_c, b)
                }
            }
            Form::LogPower { v_c } => {
                let x = log10(g / v_c);
                exp(-x * x * core::f64::consts::LN_10)
            }
            Form::Exponential { a, k0, k1, c, d } => {
                let v = g / CM;
                let rate = if k1 != 0.0 {
                    let r = match radius {
                        Some(r) if r.is_finite() && r > 0.0 => r,
                        Some(r) => {
                            return Err(Error::OutOfRange {
                                field: "radius",
                                value: r,
                                expected: "must be a finite radius > 0 [m]",
                            });
                        }
                        None => {
                            return Err(Error::InvalidValue {
                                field: "radius",
                                expected: "a reduced radius [m]: this law depends on it",
                            });
                        }
                    };
                    let rate = k0 - k1 * (r / CM);
                    if rate <= 0.0 {
                        return Err(Error::OutOfRange {
                            field: "radius",
                            value: r,
                            expected: "must be below 0.41 m (the law's rate 0.41 - 0.01 r turns negative)",
                        });
                    }
                    extrapolated |= r < self.radius[0] || r > self.radius[1];
                    rate
                } else {
                    k0
                };
                let power = if c != 0.0 { c * powf(v, d) } else { 0.0 };
                a * exp(-rate * v) + power
            }
            Form::Band { .. } | Form::StickBelow { .. } | Form::SurfaceEnergy { .. } => {
                return Err(Error::InvalidValue {
                    field: "law",
                    expected: "an entry of kind law (this one is a range or threshold)",
                });
            }
        };
        Ok(Evaluation {
            g,
            eps,
            extrapolated,
        })
    }

    /// The measured band `[lo, hi]` of ε for a range entry.
    pub fn band(&self) -> Option<[f64; 2]> {
        match self.form {
            Form::Band { lo, hi } => Some([lo, hi]),
            _ => None,
        }
    }

    /// Surface energy γ(T) \[J/m²\] of a surface-energy entry (log-linear between its two
    /// temperatures, constant outside), as the source defines γ (see `docs/physics.md#gamma`).
    pub fn surface_energy(&self, temperature: f64) -> Result<f64> {
        let Form::SurfaceEnergy {
            t_lo,
            t_hi,
            gamma_lo,
            gamma_hi,
        } = self.form
        else {
            return Err(Error::InvalidValue {
                field: "entry",
                expected: "a surface-energy entry (musiolik2019)",
            });
        };
        if !(temperature.is_finite() && temperature > 0.0) {
            return Err(Error::OutOfRange {
                field: "temperature",
                value: temperature,
                expected: "must be a finite temperature > 0 K",
            });
        }
        Ok(if temperature <= t_lo {
            gamma_lo
        } else if temperature >= t_hi {
            gamma_hi
        } else {
            let s = (temperature - t_lo) / (t_hi - t_lo);
            exp(ln(gamma_lo) + s * (ln(gamma_hi) - ln(gamma_lo)))
        })
    }
}

/// Number of log-spaced speeds [`score`] samples.
pub const SCORE_POINTS: usize = 32;

/// rms of ε_scene − ε_entry over the entry's measured speeds (`SCORE_POINTS` log-spaced speeds, ends
/// included). For a law, the difference to the law (`radius` as in [`Entry::eval`]); for a range,
/// the distance to the measured band (0 inside it). Thresholds cannot be scored this way.
pub fn score(
    contact: &Contact,
    accuracy: Accuracy,
    entry: &Entry,
    radius: Option<f64>,
) -> Result<f64> {
    let [lo, hi] = entry.valid_speed;
    if entry.kind == Kind::Threshold || !(lo > 0.0 && hi >= lo && hi.is_finite()) {
        return Err(Error::InvalidValue {
            field: "entry",
            expected: "a law or range with a measured speed range (thresholds are not scored)",
        });
    }
    let mut g = [0.0; SCORE_POINTS];
    crate::numerics::grid::log_space(lo, hi, &mut g);
    let mut sum = 0.0;
    for &gi in &g {
        let e = contact.eps_n(gi, accuracy)?;
        let d = match entry.band() {
            Some([b_lo, b_hi]) => {
                if e < b_lo {
                    b_lo - e
                } else if e > b_hi {
                    e - b_hi
                } else {
                    0.0
                }
            }
            None => e - entry.eval(gi, radius)?.eps,
        };
        sum += d * d;
    }
    Ok(crate::numerics::math::sqrt(sum / SCORE_POINTS as f64))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_are_unique_and_ranges_ordered() {
        for (i, a) in ENTRIES.iter().enumerate() {
            assert!(ENTRIES[i + 1..].iter().all(|b| b.id != a.id), "{}", a.id);
            assert!(a.valid_speed[0] <= a.valid_speed[1], "{}", a.id);
            assert!(a.temperature[0] <= a.temperature[1], "{}", a.id);
            if !a.conflicts_with.is_empty() {
                let other = find(a.conflicts_with).unwrap();
                assert_eq!(other.conflicts_with, a.id, "conflicts are mutual");
            }
        }
        for id in [
            "bridges1984",
            "hatzes1988_frost",
            "hatzes1988_compacted",
            "supulver1995",
            "higa1996",
            "borderies1984",
        ] {
            assert_eq!(find(id).unwrap().kind, Kind::Law, "{id}");
        }
    }

    #[test]
    fn laws_give_the_sources_numbers() {
        // Hand-computed from the printed formulas (python3: 0.0077**0.234, 0.48*2**-0.2, …).
        let b = find("bridges1984").unwrap();
        // (1 cm/s / 0.0077 cm/s)^-0.234 = 0.320213 (the 0.32 of the ring codes).
        assert!((b.eval(0.01, None).unwrap().eps - 0.320_213).abs() < 1e-6);
        assert!(!b.eval(0.01, None).unwrap().extrapolated);
        assert!(b.eval(1.0, None).unwrap().extrapolated);
        // 0.48 (2 cm/s)^-0.2 = 0.417864.
        let f = find("hatzes1988_frost").unwrap();
        assert!((f.eval(0.02, None).unwrap().eps - 0.417_864).abs() < 1e-6);
        // r = 2.5 cm, v = 1 cm/s: 0.90 exp(-0.385) = 0.612406.
        let c = find("hatzes1988_compacted").unwrap();
        assert!((c.eval(0.01, Some(0.025)).unwrap().eps - 0.612_406).abs() < 1e-6);
        assert!(c.eval(0.01, None).is_err());
        assert!(c.eval(0.01, Some(0.5)).is_err());
        // 0.90 exp(-0.22) + 0.01 = 0.732267 at 1 cm/s.
        let r20 = find("hatzes1988_compacted_r20").unwrap();
        assert!((r20.eval(0.01, None).unwrap().eps - 0.732_267).abs() < 1e-6);
        // 0.52 (0.5 cm/s)^-0.14 = 0.572991.
        let s = find("supulver1995").unwrap();
        assert!((s.eval(0.005, None).unwrap().eps - 0.572_991).abs() < 1e-6);
        // Higa: 1 at v_c, and (10/1.8)^-log10(10/1.8) = 0.278857 at 10 m/s (extrapolated).
        let h = find("higa1996").unwrap();
        assert!((h.eval(1.8, None).unwrap().eps - 1.0).abs() < 1e-15);
        let e = h.eval(10.0, None).unwrap();
        assert!((e.eps - 0.278_857).abs() < 1e-6 && e.extrapolated);
        let bgt = find("borderies1984").unwrap();
        assert_eq!(bgt.eval(1e-5, None).unwrap().eps, 1.0);
        assert!((bgt.eval(0.01, None).unwrap().eps - 0.320_213).abs() < 1e-6);
        assert!(find("hill2015").unwrap().eval(0.3, None).is_err());
        assert!(b.eval(-1.0, None).is_err() && b.eval(f64::NAN, None).is_err());
    }

    #[test]
    fn surface_energy_interpolates_between_the_printed_ends() {
        let m = find("musiolik2019").unwrap();
        assert_eq!(m.surface_energy(150.0).unwrap(), 0.0029);
        assert_eq!(m.surface_energy(250.0).unwrap(), 0.19);
        // Geometric mean at the midpoint 187.5 K: sqrt(0.0029 * 0.19) = 0.0234734.
        assert!((m.surface_energy(187.5).unwrap() - 0.023_473_4).abs() < 1e-7);
        assert!(m.surface_energy(-1.0).is_err());
        assert!(find("bridges1984").unwrap().surface_energy(180.0).is_err());
    }

    #[test]
    fn score_is_zero_for_a_band_that_contains_the_scene_and_positive_otherwise() {
        let contact = Contact::new(&crate::Scene::default()).unwrap();
        let wide = Entry {
            form: Form::Band { lo: 0.0, hi: 1.0 },
            ..*find("hill2015").unwrap()
        };
        assert_eq!(score(&contact, Accuracy::Fast, &wide, None).unwrap(), 0.0);
        let above = Entry {
            form: Form::Band { lo: 1.0, hi: 1.0 },
            ..wide
        };
        // Distance to ε = 1 is 1 − ε_scene at every point: the rms lies between the extremes.
        let s = score(&contact, Accuracy::Fast, &above, None).unwrap();
        let e_lo = contact.eps_n(0.27, Accuracy::Fast).unwrap();
        let e_hi = contact.eps_n(0.51, Accuracy::Fast).unwrap();
        assert!(
            s >= 1.0 - e_lo.max(e_hi) && s <= 1.0 - e_lo.min(e_hi),
            "{s}"
        );
        assert!(
            score(
                &contact,
                Accuracy::Fast,
                find("gundlach2015").unwrap(),
                None
            )
            .is_err()
        );
        assert!(score(&contact, Accuracy::Fast, find("bridges1984").unwrap(), None).unwrap() > 0.0);
    }
}
