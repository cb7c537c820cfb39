//! Sticking thresholds for dust codes: v_stick(radius, temperature) of two equal grains.
//!
//! The surface energy comes from the Musiolik & Wurm (2019) entry of the [`crate::data::atlas`]
//! (γ(T) rising from 0.0029 to 0.19 J/m² between 175 and 200 K). Two thresholds are given:
//!
//! * `v_elastic`: Eq. (15) alone, g_s = (14.18/m_eff)^{1/2}(γ⁵R_eff⁴/E²)^{1/6} — the speed below
//!   which perfectly elastic adhesive grains stick (JKR, Thornton & Ning 1998);
//! * `v_stick`: the smallest impact speed at which the scene's full model (viscous damping Eq. (4),
//!   soft layer Eq. (8)–(10) if the scene has one, adhesion Eq. (17)) rebounds; above `v_elastic`
//!   whenever the bulk or a layer dissipates.
//!
//! γ conventions differ (`docs/physics.md#gamma`): the paper's γ enters the JKR pull-off force as
//! F_c = (3/2)πγR_eff, i.e. it is the work of adhesion w = 2γ_s of two surfaces of surface energy
//! γ_s. [`Convention::SurfaceEnergy`] (the default) reads the source's γ as γ_s and uses w = 2γ_s.

use crate::data::atlas;
use crate::error::{Error, Result};
use crate::normal::Status;
use crate::numerics::accuracy::Accuracy;
use crate::numerics::math::{ln, sqrt};
use crate::scene::contact::Contact;
use crate::scene::{Adhesion, AdhesionModulus, Scene};

/// How to read the source's γ.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Convention {
    /// γ is the surface energy of one surface; the paper's γ is w = 2γ (default).
    #[default]
    SurfaceEnergy,
    /// γ is already the work of adhesion w and is used as the paper's γ unchanged.
    WorkOfAdhesion,
}

impl Convention {
    /// The paper's γ (work of adhesion) from the source's γ.
    pub fn work_of_adhesion(self, gamma: f64) -> f64 {
        match self {
            Convention::SurfaceEnergy => 2.0 * gamma,
            Convention::WorkOfAdhesion => gamma,
        }
    }

    /// Name for output: `surface` or `adhesion`.
    pub fn name(self) -> &'static str {
        match self {
            Convention::SurfaceEnergy => "surface",
            Convention::WorkOfAdhesion => "adhesion",
        }
    }
}

/// The measured sticking threshold of µm ice below ~210 K (Gundlach & Blum 2015) \[m/s\].
pub const MEASURED_UM_ICE: f64 = 9.6;

/// Whether threshold `t` lies where µm ice was measured to stick (the atlas' `gundlach2015`:
/// inside its radii, at or below its warmest temperature), so [`MEASURED_UM_ICE`] compares.
pub fn in_measured_regime(t: &Threshold) -> bool {
    crate::data::atlas::find("gundlach2015").is_some_and(|e| {
        t.radius >= e.radius[0] && t.radius <= e.radius[1] && t.temperature <= e.temperature[1]
    })
}

/// Largest speed searched for the full-model threshold \[m/s\].
pub const SEARCH_MAX: f64 = crate::scene::limits::SPEED_MAX;

/// Sticking thresholds of two equal grains.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Threshold {
    /// Grain radius \[m\] (both grains).
    pub radius: f64,
    /// Temperature \[K\].
    pub temperature: f64,
    /// γ(T) as the source gives it \[J/m²\].
    pub gamma_source: f64,
    /// The paper's γ used in Eq. (12) and (15) \[J/m²\].
    pub gamma: f64,
    /// Eq. (15) alone: elastic adhesive threshold \[m/s\].
    pub v_elastic: f64,
    /// Smallest rebounding speed of the full model \[m/s\]; `None` when the grains stick at every
    /// speed up to [`SEARCH_MAX`].
    pub v_stick: Option<f64>,
}

/// The scene used for a threshold: `base` with both radii set to `radius` and adhesion on with the
/// paper's γ (the modulus reading of `base`'s adhesion, `as_printed` if it has none).
pub fn scene_for(base: &Scene, radius: f64, gamma: f64) -> Result<Scene> {
    pair_scene_for(base, radius, radius, gamma)
}

/// [`scene_for`] with two radii: `base` with radii `r1`, `r2` and adhesion on with the paper's γ
/// (the kernel's pairs of unequal grains).
pub fn pair_scene_for(base: &Scene, r1: f64, r2: f64, gamma: f64) -> Result<Scene> {
    let mut s = *base;
    s.grains.radius_1 = r1;
    s.grains.radius_2 = r2;
    s.adhesion = Some(Adhesion {
        surface_energy: gamma,
        modulus: base
            .adhesion
            .map_or(AdhesionModulus::AsPrinted, |a| a.modulus),
        jkr_end: Default::default(),
    });
    s.validate()?;
    Ok(s)
}

fn sticks(contact: &Contact, g: f64, accuracy: Accuracy) -> Result<bool> {
    let n = contact.normal(g, accuracy)?;
    Ok(matches!(n.status, Status::StuckByAdhesion | Status::StuckInLayer) || n.eps <= 0.0)
}

/// The smallest impact speed \[m/s\] at which `contact` rebounds with every effect its scene
/// enables (the full model of [`Contact::normal`]), found by bisection in ln g to 1e-10; `None`
/// when it sticks at every speed up to [`SEARCH_MAX`]. The rebound speed ε g grows with g, so the
/// speeds that stick lie below this one.
pub fn first_rebound_speed(contact: &Contact, accuracy: Accuracy) -> Result<Option<f64>> {
    let v_elastic = contact.adhesion.map_or(0.0, |a| a.critical_velocity);
    // The rebound speed ε g grows with g: bisect in ln g for the first rebounding speed.
    Ok(if sticks(contact, SEARCH_MAX, accuracy)? {
        None
    } else {
        let mut lo = v_elastic.max(1e-300) * 0.5;
        while !sticks(contact, lo, accuracy)? {
            lo *= 0.5;
            if lo < 1e-300 {
                break;
            }
        }
        let mut hi = SEARCH_MAX;
        while ln(hi / lo) > 1e-10 {
            let mid = sqrt(lo * hi);
            if sticks(contact, mid, accuracy)? {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Some(hi)
    })
}

/// Sticking thresholds for grains of `radius` \[m\] at `temperature` \[K\] in `base`'s material.
pub fn threshold(
    base: &Scene,
    radius: f64,
    temperature: f64,
    convention: Convention,
    accuracy: Accuracy,
) -> Result<Threshold> {
    let entry = atlas::find("musiolik2019").ok_or(Error::InvalidValue {
        field: "atlas",
        expected: "the musiolik2019 entry",
    })?;
    let gamma_source = entry.surface_energy(temperature)?;
    let gamma = convention.work_of_adhesion(gamma_source);
    let scene = scene_for(base, radius, gamma)?;
    let contact = Contact::new(&scene)?;
    let v_elastic = contact.adhesion.map_or(0.0, |a| a.critical_velocity);
    let v_stick = first_rebound_speed(&contact, accuracy)?;
    Ok(Threshold {
        radius,
        temperature,
        gamma_source,
        gamma,
        v_elastic,
        v_stick,
    })
}

/// Radii of the explorer's table \[m\].
pub const TABLE_RADII: [f64; 5] = [1e-6, 1e-5, 1e-4, 1e-3, 1e-2];
/// Temperatures of the explorer's table \[K\].
pub const TABLE_TEMPERATURES: [f64; 3] = [150.0, 180.0, 200.0];

/// One cell of a [`ThresholdTable`]: the thresholds, or why they could not be computed.
#[cfg(feature = "alloc")]
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ThresholdCell {
    /// The thresholds.
    pub threshold: Option<Threshold>,
    /// The error, when there are none.
    pub error: Option<alloc::string::String>,
}

/// A column of a [`ThresholdTable`]: its name, SI unit, and where it does not use the scene's own
/// value, which value it uses instead.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Column {
    /// Name (JSON key, CSV column).
    pub name: &'static str,
    /// SI unit (empty: none).
    pub unit: &'static str,
    /// What it uses instead of the scene's value (empty: the scene's values throughout).
    pub note: &'static str,
}

/// The columns of `rime stick` and the explorer's `v` panel, in order.
pub const COLUMNS: [Column; 6] = [
    Column {
        name: "radius",
        unit: "m",
        note: "both grains: the row's radius, not the scene's",
    },
    Column {
        name: "temperature",
        unit: "K",
        note: "",
    },
    Column {
        name: "gamma_source",
        unit: "J/m²",
        note: "γ(T) of Musiolik & Wurm 2019, not the scene's γ",
    },
    Column {
        name: "gamma",
        unit: "J/m²",
        note: "the paper's γ from gamma_source (convention), not the scene's γ",
    },
    Column {
        name: "v_elastic",
        unit: "m/s",
        note: "Eq. (15) alone: A = 0 and no layer, not the scene's",
    },
    Column {
        name: "v_stick",
        unit: "m/s",
        note: "",
    },
];

/// Sticking thresholds of a scene's material over radii × temperatures: what the explorer's `v`
/// panel and `rime stick` show. Computed from the scene itself (its damping time A, layer,
/// modulus reading), with γ(T) and the row's radius in place of the scene's ([`COLUMNS`] says
/// which column uses what).
#[cfg(feature = "alloc")]
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ThresholdTable {
    /// The scene it was computed from.
    pub scene: Scene,
    /// The scene's damping time A \[s\] (what `v_stick` uses).
    pub damping_time: f64,
    /// Whether the scene's soft layer enters `v_stick`.
    pub layer: bool,
    /// Radii \[m\].
    pub radii: alloc::vec::Vec<f64>,
    /// Temperatures \[K\].
    pub temperatures: alloc::vec::Vec<f64>,
    /// How γ(T) was read.
    pub convention: Convention,
    /// Radius-major: the cell of radius `i`, temperature `j` is `cells[i * temperatures.len() + j]`.
    pub cells: alloc::vec::Vec<ThresholdCell>,
}

#[cfg(feature = "alloc")]
impl ThresholdTable {
    /// Every (radius, temperature) of `scene`'s material; a cell that fails keeps its error.
    pub fn compute(
        scene: &Scene,
        radii: &[f64],
        temperatures: &[f64],
        convention: Convention,
        accuracy: Accuracy,
    ) -> Self {
        use alloc::string::ToString;
        let mut cells = alloc::vec::Vec::with_capacity(radii.len() * temperatures.len());
        for &r in radii {
            for &t in temperatures {
                cells.push(match threshold(scene, r, t, convention, accuracy) {
                    Ok(th) => ThresholdCell {
                        threshold: Some(th),
                        error: None,
                    },
                    Err(e) => ThresholdCell {
                        threshold: None,
                        error: Some(e.to_string()),
                    },
                });
            }
        }
        ThresholdTable {
            scene: *scene,
            damping_time: scene.damping_time(),
            layer: scene.layer.is_some_and(|l| l.thickness > 0.0),
            radii: radii.into(),
            temperatures: temperatures.into(),
            convention,
            cells,
        }
    }

    /// The explorer's table ([`TABLE_RADII`] × [`TABLE_TEMPERATURES`], surface convention).
    pub fn explorer(scene: &Scene, accuracy: Accuracy) -> Self {
        Self::compute(
            scene,
            &TABLE_RADII,
            &TABLE_TEMPERATURES,
            Convention::SurfaceEnergy,
            accuracy,
        )
    }

    /// The cell of radius `i`, temperature `j`.
    pub fn cell(&self, i: usize, j: usize) -> Option<&ThresholdCell> {
        self.cells.get(i * self.temperatures.len() + j)
    }

    /// What `v_stick` uses from the scene, for its column header: `A = 1e-4 s` (and the layer).
    pub fn v_stick_note(&self) -> alloc::string::String {
        let a = crate::format::qty3(self.damping_time, "s");
        if self.layer {
            alloc::format!("the scene's A = {a} and layer")
        } else {
            alloc::format!("the scene's A = {a}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elastic_threshold_is_eq15_with_twice_the_source_gamma() {
        // Independent evaluation of Eq. (15) (python3): r = 1 µm, ρ = 900, Y = 10 GPa, ν = 0.3,
        // γ = 0.19 J/m²: g_s = 0.615852 m/s; with w = 2γ the factor 2^(5/6) = 1.781797.
        let mut base = Scene::default();
        base.bulk.damping = crate::Damping::Time(0.0);
        let t = threshold(
            &base,
            1e-6,
            250.0,
            Convention::WorkOfAdhesion,
            Accuracy::Fast,
        )
        .unwrap();
        assert!((t.v_elastic / 0.615_852 - 1.0).abs() < 1e-5, "{t:?}");
        // Without dissipation the full model sticks exactly up to g_s.
        assert!(
            (t.v_stick.unwrap() / t.v_elastic - 1.0).abs() < 1e-6,
            "{t:?}"
        );
        let s = threshold(
            &base,
            1e-6,
            250.0,
            Convention::SurfaceEnergy,
            Accuracy::Fast,
        )
        .unwrap();
        assert!((s.v_elastic / t.v_elastic - 1.781_797).abs() < 1e-5);
        assert_eq!(s.gamma, 0.38);
    }

    #[test]
    fn damping_raises_the_threshold_and_cold_ice_is_less_sticky() {
        let base = Scene::default();
        let warm = threshold(
            &base,
            1e-3,
            250.0,
            Convention::SurfaceEnergy,
            Accuracy::Fast,
        )
        .unwrap();
        assert!(warm.v_stick.unwrap() > warm.v_elastic);
        let cold = threshold(
            &base,
            1e-3,
            150.0,
            Convention::SurfaceEnergy,
            Accuracy::Fast,
        )
        .unwrap();
        // γ drops by 0.19/0.0029: g_s by (0.19/0.0029)^(5/6) = 32.6.
        assert!((warm.v_elastic / cold.v_elastic - 32.6).abs() < 0.1);
        assert!(
            threshold(
                &base,
                -1.0,
                150.0,
                Convention::SurfaceEnergy,
                Accuracy::Fast
            )
            .is_err()
        );
        assert!(
            threshold(
                &base,
                1e-3,
                f64::NAN,
                Convention::SurfaceEnergy,
                Accuracy::Fast
            )
            .is_err()
        );
    }
}
