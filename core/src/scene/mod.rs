//! The scene: two grains, their bulk material, and the optional surface effects.
//!
//! A [`Scene`] is plain data with public fields. Its JSON form (feature `serde`) is the contract shared
//! by the CLI, the terminal explorer and the web page (see `docs/cli.md#scene-json`). Effects that are `None`
//! cost nothing when evaluating: *model only what a scene requires*.

pub mod contact;
pub mod limits;
pub mod params;
pub mod units;

use crate::error::{Error, Result, within};

/// The two colliding grains: homogeneous spheres of one material.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct Grains {
    /// Radius of grain 1 \[m\]. Default 0.02 m (so that R_eff = 1 cm as in the paper).
    pub radius_1: f64,
    /// Radius of grain 2 \[m\]. Default 0.02 m.
    pub radius_2: f64,
    /// Density of both grains \[kg/m³\]. Default 900 kg/m³ (water ice).
    pub density: f64,
}

impl Grains {
    /// The grains of two bodies of an N-body code with their own masses and radii \[m, kg\]: the
    /// radii, and the one density whose effective mass with these radii is `m₁m₂/(m₁+m₂)` of the
    /// given masses, `ρ = m_eff (V₁ + V₂)/(V₁V₂)` with `V = 4/3 π r³` (each body's density when both
    /// share one). The models depend on the masses only through `m_eff`, so this pair of grains
    /// collides as the two bodies do.
    ///
    /// ```
    /// use rime_core::Grains;
    /// let m = 900.0 * 4.0 / 3.0 * core::f64::consts::PI * 0.02f64.powi(3);
    /// let g = Grains::from_masses(0.02, m, 0.02, m)?;
    /// assert!((g.density - 900.0).abs() < 1e-12);
    /// # Ok::<(), rime_core::Error>(())
    /// ```
    ///
    /// Errors name `radius_1`, `mass_2`, … when a value is not finite and > 0.
    pub fn from_masses(radius_1: f64, mass_1: f64, radius_2: f64, mass_2: f64) -> Result<Grains> {
        let radius_1 = crate::error::positive("radius_1", radius_1)?;
        let mass_1 = crate::error::positive("mass_1", mass_1)?;
        let radius_2 = crate::error::positive("radius_2", radius_2)?;
        let mass_2 = crate::error::positive("mass_2", mass_2)?;
        let volume = |r: f64| 4.0 / 3.0 * core::f64::consts::PI * r * r * r;
        let (v1, v2) = (volume(radius_1), volume(radius_2));
        let m_eff = mass_1 * mass_2 / (mass_1 + mass_2);
        Ok(Grains {
            radius_1,
            radius_2,
            density: m_eff * (v1 + v2) / (v1 * v2),
        })
    }
}

impl Default for Grains {
    fn default() -> Self {
        Grains {
            radius_1: 0.02,
            radius_2: 0.02,
            density: 900.0,
        }
    }
}

/// How the dissipative constant `A` of Eq. (4) is given.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Damping {
    /// `A` given directly \[s\]. The default preset uses `A = 1e-4 s` (docs/physics.md#decision-1).
    Time(f64),
    /// `A` derived from the shear and bulk viscosities (Eq. (4), Brilliantov et al. 1996).
    Viscosities(Viscosities),
}

impl Default for Damping {
    fn default() -> Self {
        Damping::Time(1.0e-4)
    }
}

/// Viscosities of the bulk material, from which `A` follows.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct Viscosities {
    /// Shear viscosity η₁ \[Pa s\]. The paper uses 1e6 Pa s.
    pub shear: f64,
    /// Bulk viscosity η₂ \[Pa s\]. The paper uses 1e12 Pa s.
    pub bulk: f64,
    /// Which formula turns (η₁, η₂) into `A`.
    #[cfg_attr(feature = "serde", serde(default))]
    pub formula: DampingFormula,
}

impl Default for Viscosities {
    fn default() -> Self {
        Viscosities {
            shear: 1.0e6,
            bulk: 1.0e12,
            formula: DampingFormula::Brilliantov,
        }
    }
}

/// The formula for `A` from viscosities (docs/physics.md#decision-1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum DampingFormula {
    /// `A = (1/3)(3η₂−η₁)²/(3η₂+2η₁)·(1−ν²)(1−2ν)/(Yν²)` (Brilliantov et al. 1996). Default.
    #[default]
    Brilliantov,
    /// The paper's printed form, without the factor (1−2ν).
    AsPrinted,
}

/// The viscoelastic bulk material (Eq. (3)–(4)).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct Bulk {
    /// Young's modulus `Y` \[Pa\]. Default 1e10 Pa (ice).
    pub youngs_modulus: f64,
    /// Poisson ratio `ν` \[1\], in (−1, 0.5]. Default 0.3.
    pub poisson_ratio: f64,
    /// The dissipative constant `A` or the viscosities it derives from.
    pub damping: Damping,
}

impl Default for Bulk {
    fn default() -> Self {
        Bulk {
            youngs_modulus: 1.0e10,
            poisson_ratio: 0.3,
            damping: Damping::default(),
        }
    }
}

/// When the contact of Eq. (4) ends (docs/physics.md#decision-2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
#[doc(alias = "Eq. (5)")]
pub enum ContactEnd {
    /// The contact ends when the total normal force returns to zero while separating (no tensile
    /// viscoelastic force). Default.
    #[default]
    ForceZero,
    /// The contact ends when the overlap ξ returns to zero (Eq. (5) read literally).
    ZeroOverlap,
}

/// How Eq. (8) is read (docs/physics.md#decision-4).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum LayerReading {
    /// The layer is crushed on the way in; the bulk then deforms by ξ − D and the crushed layer does
    /// not act on the way out. Threshold exactly Eq. (10). Default.
    #[default]
    Offset,
    /// Eq. (8) as printed: piecewise in ξ both ways, the bulk force uses ξ itself.
    Literal,
}

/// A soft surface layer (dust, frost): Eq. (6)–(10).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct Layer {
    /// Total thickness `D = D₁ + D₂` \[m\]. Preset `ice-frost`: 1e-6 m.
    pub thickness: f64,
    /// Effective layer viscosity `η* = 1/K` \[Pa s\]. Preset `ice-frost`: 1000 Pa s.
    pub viscosity: f64,
    /// Which reading of Eq. (8).
    #[cfg_attr(feature = "serde", serde(default))]
    pub reading: LayerReading,
}

impl Default for Layer {
    fn default() -> Self {
        Layer {
            thickness: 1.0e-6,
            viscosity: 1000.0,
            reading: LayerReading::Offset,
        }
    }
}

/// Which modulus `E` enters Eq. (12) and (15) (docs/physics.md#decision-5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum AdhesionModulus {
    /// `E = Y/(1−ν²)` as printed. Default.
    #[default]
    AsPrinted,
    /// `E = Y/(2(1−ν²))`, the contact modulus that Eq. (4) implies for two equal grains.
    Consistent,
}

/// Where the JKR contact of the `brilliantov2007` model ends while the grains separate
/// (docs/physics.md#jkr-end). The paper's own model (Eq. (11)–(17)) does not read it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum JkrEnd {
    /// At the neck instability, the end of the stable JKR branch (`dξ/da = 0`, fixed grips):
    /// `a³ = πwR²/(8E*)`. Default.
    #[default]
    Neck,
    /// At the maximum tensile force `F = −(3/2)πwR` (fixed load): `a³ = 9πwR²/(8E*)`, the overlap
    /// `ξ = −(3/64)^(1/3)(π²w²R/E*²)^(1/3)` where LAMMPS's `jkr` ends contact.
    PullOffForce,
}

/// Adhesion by surface energy: Eq. (11)–(17).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct Adhesion {
    /// Dupré energy of adhesion `γ` \[J/m²\]. Preset `ice-sticky`: 0.1 J/m².
    pub surface_energy: f64,
    /// Which modulus enters the JKR energy.
    #[cfg_attr(feature = "serde", serde(default))]
    pub modulus: AdhesionModulus,
    /// Where the JKR contact of `brilliantov2007` ends (scene files without it: the neck).
    #[cfg_attr(feature = "serde", serde(default))]
    pub jkr_end: JkrEnd,
}

impl Default for Adhesion {
    fn default() -> Self {
        Adhesion {
            surface_energy: 0.1,
            modulus: AdhesionModulus::AsPrinted,
            jkr_end: JkrEnd::Neck,
        }
    }
}

/// Plastic yielding of the bulk (Thornton 1997; docs/physics.md#model-thornton1997). The paper's own model
/// ignores it; the plastic models of `rime compare` need it.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct Plasticity {
    /// Limiting contact pressure `p_y` \[Pa\]: the Hertz pressure at the centre of the contact cannot exceed
    /// it. Default 1e7 Pa, of the order of the compressive strength of cold ice.
    pub yield_pressure: f64,
}

impl Default for Plasticity {
    fn default() -> Self {
        Plasticity {
            yield_pressure: 1.0e7,
        }
    }
}

/// The sliding branch of Eq. (26) (docs/physics.md#decision-6).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum SlidingLaw {
    /// Eq. (23) as printed; its radicand is negative just above ψ₀ (clamped, class `sliding_gap`). Default.
    #[default]
    Paper,
    /// The linear Coulomb impulse law ε_T = 1 − μ(1+ε_N)g_N/(κ g_T) (Walton): no gap.
    Walton,
}

/// Friction and tangential restitution: Eq. (18)–(26).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct Friction {
    /// Friction coefficient `μ` \[1\]. Default 0.3 (the paper's value).
    pub coefficient: f64,
    /// Reduced moment of inertia `κ` \[1\] of Eq. (22), `q/(1+q)`; 2/7 for solid spheres.
    pub kappa: f64,
    /// Which sliding law.
    #[cfg_attr(feature = "serde", serde(default))]
    pub sliding_law: SlidingLaw,
}

impl Default for Friction {
    fn default() -> Self {
        Friction {
            coefficient: 0.3,
            kappa: 2.0 / 7.0,
            sliding_law: SlidingLaw::Paper,
        }
    }
}

/// A complete collision scene. `Default` is the `ice` preset.
///
/// # Examples
///
/// ```
/// use rime_core::{Preset, Scene};
///
/// // A preset, then one parameter by its path, with a unit (as `--set` and the explorer read it).
/// let mut scene: Scene = Preset::IceSticky.scene();
/// scene.set("grains.radius_1", "1 mm")?;
/// assert_eq!(scene.grains.radius_1, 1e-3);
/// // Bad values are refused, naming the field.
/// let refused = scene.set("grains.density", "-3").unwrap_err().to_string();
/// assert!(refused.starts_with("grains.density"), "{refused}");
/// # Ok::<(), rime_core::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct Scene {
    /// The two grains.
    pub grains: Grains,
    /// The bulk material.
    pub bulk: Bulk,
    /// When the contact ends (Eq. (5)).
    #[cfg_attr(feature = "serde", serde(default))]
    pub contact_end: ContactEnd,
    /// Optional soft surface layer.
    #[cfg_attr(feature = "serde", serde(default))]
    pub layer: Option<Layer>,
    /// Optional adhesion.
    #[cfg_attr(feature = "serde", serde(default))]
    pub adhesion: Option<Adhesion>,
    /// Optional friction (needed for tangential restitution).
    #[cfg_attr(feature = "serde", serde(default))]
    pub friction: Option<Friction>,
    /// Optional plastic yielding, used only by the plastic models of `rime compare`.
    #[cfg_attr(
        feature = "serde",
        serde(default, skip_serializing_if = "Option::is_none")
    )]
    pub plasticity: Option<Plasticity>,
}

impl Default for Scene {
    fn default() -> Self {
        Scene {
            grains: Grains::default(),
            bulk: Bulk::default(),
            contact_end: ContactEnd::ForceZero,
            layer: None,
            adhesion: None,
            friction: Some(Friction::default()),
            plasticity: None,
        }
    }
}

/// The named presets (docs/cli.md#scene-json).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Preset {
    /// `ice`: A = 1e-4 s, no layer, no adhesion, friction on (the default).
    Ice,
    /// `ice-frost`: `ice` plus a layer D = 1 µm, η* = 1000 Pa s.
    IceFrost,
    /// `ice-sticky`: `ice` plus adhesion γ = 0.1 J/m².
    IceSticky,
    /// `ice-paper-viscosities`: A from the paper's η₁ = 1e6, η₂ = 1e12 Pa s (overdamped).
    IcePaperViscosities,
}

impl Preset {
    /// Every preset, in display order.
    pub const ALL: [Preset; 4] = [
        Preset::Ice,
        Preset::IceFrost,
        Preset::IceSticky,
        Preset::IcePaperViscosities,
    ];

    /// The preset's name as used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Preset::Ice => "ice",
            Preset::IceFrost => "ice-frost",
            Preset::IceSticky => "ice-sticky",
            Preset::IcePaperViscosities => "ice-paper-viscosities",
        }
    }

    /// A one-line description.
    pub fn description(self) -> &'static str {
        match self {
            Preset::Ice => "ice (calibrated): A = 1e-4 s, clean surfaces, μ = 0.3",
            Preset::IceFrost => "ice + frost layer: D = 1 µm, η* = 1000 Pa s",
            Preset::IceSticky => "ice + adhesion: γ = 0.1 J/m²",
            Preset::IcePaperViscosities => {
                "ice with the paper's viscosities η₁ = 1e6, η₂ = 1e12 Pa s (overdamped)"
            }
        }
    }

    /// Looks a preset up by name.
    pub fn from_name(name: &str) -> Option<Preset> {
        Preset::ALL.into_iter().find(|p| p.name() == name)
    }

    /// The preset's scene.
    pub fn scene(self) -> Scene {
        let base = Scene::default();
        match self {
            Preset::Ice => base,
            Preset::IceFrost => Scene {
                layer: Some(Layer::default()),
                ..base
            },
            Preset::IceSticky => Scene {
                adhesion: Some(Adhesion::default()),
                ..base
            },
            Preset::IcePaperViscosities => Scene {
                bulk: Bulk {
                    damping: Damping::Viscosities(Viscosities::default()),
                    ..base.bulk
                },
                ..base
            },
        }
    }
}

impl Scene {
    /// Checks every field against its range; the error names the first offending one by its
    /// dotted path. Only `Contact::new` calls this: it is the single validity
    /// gate (fields, then every derived quantity), and [`Scene::validate`] asks it.
    // Long by design: one check per scene field, in the order of the scene's sections; a table of
    // checks would hide the messages.
    pub(crate) fn check_fields(&self) -> Result<()> {
        within(
            "grains.radius_1",
            self.grains.radius_1,
            1e-9,
            1e4,
            "must lie in [1e-9, 1e4] m",
        )?;
        within(
            "grains.radius_2",
            self.grains.radius_2,
            1e-9,
            1e4,
            "must lie in [1e-9, 1e4] m",
        )?;
        within(
            "grains.density",
            self.grains.density,
            1e-3,
            1e6,
            "must lie in [1e-3, 1e6] kg/m³",
        )?;
        within(
            "bulk.youngs_modulus",
            self.bulk.youngs_modulus,
            1e-3,
            1e15,
            "must lie in [1e-3, 1e15] Pa",
        )?;
        let nu = self.bulk.poisson_ratio;
        if !(nu.is_finite() && nu > -1.0 && nu <= 0.5) {
            return Err(Error::OutOfRange {
                field: "bulk.poisson_ratio",
                value: nu,
                expected: "must lie in (-1, 0.5]",
            });
        }
        match self.bulk.damping {
            Damping::Time(a) => {
                within("bulk.damping.time", a, 0.0, 1e6, "must lie in [0, 1e6] s")?;
            }
            Damping::Viscosities(v) => {
                within(
                    "bulk.damping.viscosities.shear",
                    v.shear,
                    0.0,
                    1e30,
                    "must lie in [0, 1e30] Pa s",
                )?;
                within(
                    "bulk.damping.viscosities.bulk",
                    v.bulk,
                    0.0,
                    1e30,
                    "must lie in [0, 1e30] Pa s",
                )?;
                if v.shear == 0.0 && v.bulk == 0.0 {
                    // A = 0/0: the formula is undefined; ask for an explicit time instead.
                    return Err(Error::OutOfRange {
                        field: "bulk.damping.viscosities",
                        value: 0.0,
                        expected: "shear and bulk viscosity cannot both be 0 (use damping.time = 0)",
                    });
                }
                if nu == 0.0 {
                    return Err(Error::OutOfRange {
                        field: "bulk.poisson_ratio",
                        value: nu,
                        expected: "must be non-zero when A is derived from viscosities (ν² divides)",
                    });
                }
            }
        }
        if let Some(layer) = &self.layer {
            within(
                "layer.thickness",
                layer.thickness,
                0.0,
                1.0,
                "must lie in [0, 1] m",
            )?;
            within(
                "layer.viscosity",
                layer.viscosity,
                0.0,
                1e15,
                "must lie in [0, 1e15] Pa s",
            )?;
        }
        if let Some(adhesion) = &self.adhesion {
            within(
                "adhesion.surface_energy",
                adhesion.surface_energy,
                0.0,
                1e6,
                "must lie in [0, 1e6] J/m²",
            )?;
        }
        if let Some(plasticity) = &self.plasticity {
            within(
                "plasticity.yield_pressure",
                plasticity.yield_pressure,
                1e-3,
                1e15,
                "must lie in [1e-3, 1e15] Pa",
            )?;
        }
        if let Some(friction) = &self.friction {
            within(
                "friction.coefficient",
                friction.coefficient,
                0.0,
                100.0,
                "must lie in [0, 100]",
            )?;
            let kappa = friction.kappa;
            if !(kappa.is_finite() && kappa > 0.0 && kappa <= 1.0) {
                return Err(Error::OutOfRange {
                    field: "friction.kappa",
                    value: kappa,
                    expected: "must lie in (0, 1]",
                });
            }
        }
        Ok(())
    }

    /// The scene with its soft layer (if any) read as `reading` (Eq. (8)); without a layer, the
    /// scene as it is.
    pub fn with_layer_reading(self, reading: LayerReading) -> Scene {
        Scene {
            layer: self.layer.map(|l| Layer { reading, ..l }),
            ..self
        }
    }

    /// The damping time `A` \[s\] of Eq. (4), from whichever form the scene gives.
    pub fn damping_time(&self) -> f64 {
        match self.bulk.damping {
            Damping::Time(a) => a,
            Damping::Viscosities(v) => {
                let nu = self.bulk.poisson_ratio;
                let y = self.bulk.youngs_modulus;
                let (eta1, eta2) = (v.shear, v.bulk);
                let diff = 3.0 * eta2 - eta1;
                // Eq. (4) / Brilliantov et al. (1996).
                let base = diff * diff / (3.0 * (3.0 * eta2 + 2.0 * eta1)) * (1.0 - nu * nu)
                    / (y * nu * nu);
                match v.formula {
                    DampingFormula::Brilliantov => base * (1.0 - 2.0 * nu),
                    DampingFormula::AsPrinted => base,
                }
            }
        }
    }
}
