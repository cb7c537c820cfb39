//! Derived contact constants, computed once per scene.

use crate::error::{Error, Result};
use crate::numerics::math::{powf, sqrt};
use crate::scene::{AdhesionModulus, ContactEnd, Friction, LayerReading, Scene};

/// Constants of the soft layer model, Eq. (8)–(10).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LayerConstants {
    /// Total thickness `D` \[m\].
    pub thickness: f64,
    /// Drag constant `√R_eff/(K m_eff) = √R_eff η*/m_eff` [m^(-1/2) s^-1] of Eq. (9).
    pub drag: f64,
    /// Critical velocity `g_s = √R_eff/(K m_eff) D^(3/2)` \[m/s\], Eq. (10).
    pub critical_velocity: f64,
    /// Which reading of Eq. (8).
    pub reading: LayerReading,
}

/// Constants of the adhesion model, Eq. (12)–(17).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdhesionConstants {
    /// Surface energy `γ` \[J/m²\].
    pub surface_energy: f64,
    /// Modulus `E` \[Pa\] entering Eq. (12) and (15).
    pub modulus: f64,
    /// JKR separation energy `W_s` \[J\], Eq. (12).
    pub separation_energy: f64,
    /// Critical rebound velocity `g_s` \[m/s\], Eq. (15).
    pub critical_velocity: f64,
}

/// The constant of Eq. (12): `W_s = 7.09 (γ⁵R_eff⁴/E²)^(1/3)`.
pub const EQ12_CONSTANT: f64 = 7.09;

/// The constant of Eq. (15): `g_s = (14.18/m_eff)^(1/2) (γ⁵R_eff⁴/E²)^(1/6)`; 14.18 = 2 × 7.09, so
/// that `½ m_eff g_s² = W_s`.
pub const EQ15_CONSTANT: f64 = 14.18;

/// The modulus `E` of Eq. (12) and (15) for Young's modulus `youngs` \[Pa\], Poisson's ratio
/// `poisson` and the scene's reading of it: `Y/(1−ν²)` as printed, or half of it, the value
/// consistent with the contact's own E* (docs/physics.md#decision-5).
pub fn adhesion_modulus(youngs: f64, poisson: f64, rule: AdhesionModulus) -> f64 {
    let printed = youngs / (1.0 - poisson * poisson);
    match rule {
        AdhesionModulus::AsPrinted => printed,
        AdhesionModulus::Consistent => 0.5 * printed,
    }
}

/// Everything a collision needs, derived once from a [`Scene`].
///
/// # Examples
///
/// ```
/// use rime_core::{Contact, Preset};
///
/// let scene = Preset::Ice.scene();
/// let contact = Contact::new(&scene)?;
/// // Two equal grains: the reduced radius and mass are half a grain's.
/// assert!((contact.r_eff - scene.grains.radius_1 / 2.0).abs() <= 1e-15 * contact.r_eff);
/// assert!((contact.m_eff - contact.mass_1 / 2.0).abs() <= 1e-15 * contact.m_eff);
/// # Ok::<(), rime_core::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// Mass of grain 1 \[kg\].
    pub mass_1: f64,
    /// Mass of grain 2 \[kg\].
    pub mass_2: f64,
    /// Effective radius `R_eff = R₁R₂/(R₁+R₂)` \[m\].
    pub r_eff: f64,
    /// Effective mass `m_eff = m₁m₂/(m₁+m₂)` \[kg\].
    pub m_eff: f64,
    /// Hertz constant `ρ_H = 2Y√R_eff/(3(1−ν²))` [N m^(-3/2)] of Eq. (4).
    pub rho_h: f64,
    /// `α = ρ_H/m_eff` [m^(-1/2) s^-2].
    pub alpha: f64,
    /// Dissipative constant `A` \[s\] of Eq. (4).
    pub damping_time: f64,
    /// Contact-end rule.
    pub contact_end: ContactEnd,
    /// Layer constants, if the scene has a layer.
    pub layer: Option<LayerConstants>,
    /// Adhesion constants, if the scene has adhesion.
    pub adhesion: Option<AdhesionConstants>,
    /// Friction, if the scene has it.
    pub friction: Option<Friction>,
    /// log₁₀(A α^(2/5)), so that log₁₀ δ = this + 0.2 log₁₀ g (−∞ when A = 0).
    pub log10_delta_coefficient: f64,
}

fn finite_positive(quantity: &'static str, fields: &'static str, v: f64) -> Result<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(Error::DerivedOutOfRange { quantity, fields })
    }
}

impl Scene {
    /// Checks the scene: every field's range, then every derived quantity (the same gate as
    /// [`Contact::new`]); the error names the first offending field by its dotted path.
    pub fn validate(&self) -> Result<()> {
        Contact::new(self).map(|_| ())
    }
}

impl Contact {
    /// Derives the contact constants: the single validity gate of a scene. Checks every field
    /// (the error names it by its dotted path), then fails if a derived quantity over- or
    /// underflows.
    // Long by design: derives every contact constant once, in dependency order, each checked where
    // it is derived (the one validity gate).
    pub fn new(scene: &Scene) -> Result<Contact> {
        scene.check_fields()?;
        let g = &scene.grains;
        let (r1, r2) = (g.radius_1, g.radius_2);
        let volume = |r: f64| 4.0 / 3.0 * core::f64::consts::PI * r * r * r;
        let mass_1 = finite_positive("m_1", "grains.radius_1", g.density * volume(r1))?;
        let mass_2 = finite_positive("m_2", "grains.radius_2", g.density * volume(r2))?;
        let r_eff = finite_positive(
            "R_eff",
            "grains.radius_1, grains.radius_2",
            r1 * r2 / (r1 + r2),
        )?;
        let m_eff = finite_positive(
            "m_eff",
            "grains.radius_1, grains.radius_2, grains.density",
            mass_1 * mass_2 / (mass_1 + mass_2),
        )?;
        let nu = scene.bulk.poisson_ratio;
        let y = scene.bulk.youngs_modulus;
        // Eq. (4): ρ_H = 2Y√R_eff / (3(1−ν²)).
        let rho_h = finite_positive(
            "rho_H",
            "bulk.youngs_modulus, bulk.poisson_ratio",
            2.0 * y * sqrt(r_eff) / (3.0 * (1.0 - nu * nu)),
        )?;
        let alpha = finite_positive("alpha", "bulk.youngs_modulus, grains", rho_h / m_eff)?;
        if nu == 0.0 && matches!(scene.bulk.damping, crate::scene::Damping::Viscosities(_)) {
            // A from viscosities has ν² in the denominator (decision 1).
            return Err(Error::OutOfRange {
                field: "bulk.poisson_ratio",
                value: nu,
                expected: "must be non-zero when A is derived from viscosities (ν² divides)",
            });
        }
        let damping_time = scene.damping_time();
        if !(damping_time.is_finite() && damping_time >= 0.0) {
            return Err(Error::DerivedOutOfRange {
                quantity: "A",
                fields: "bulk.damping",
            });
        }
        let layer = match &scene.layer {
            None => None,
            Some(l) => {
                let drag = sqrt(r_eff) * l.viscosity / m_eff;
                // Eq. (10).
                let critical_velocity = drag * l.thickness * sqrt(l.thickness);
                if !(drag.is_finite() && critical_velocity.is_finite()) {
                    return Err(Error::DerivedOutOfRange {
                        quantity: "g_s (layer)",
                        fields: "layer.viscosity, layer.thickness",
                    });
                }
                Some(LayerConstants {
                    thickness: l.thickness,
                    drag,
                    critical_velocity,
                    reading: l.reading,
                })
            }
        };
        let adhesion = match &scene.adhesion {
            None => None,
            Some(a) => {
                let modulus = adhesion_modulus(y, nu, a.modulus);
                let gamma = a.surface_energy;
                // (γ⁵R⁴/E²)^(1/3), evaluated factor by factor so that no power overflows.
                let k13 =
                    powf(gamma, 5.0 / 3.0) * powf(r_eff, 4.0 / 3.0) * powf(modulus, -2.0 / 3.0);
                // Eq. (12) and Eq. (15); note 14.18 = 2 × 7.09, i.e. ½ m_eff g_s² = W_s.
                let separation_energy = EQ12_CONSTANT * k13;
                let critical_velocity = sqrt(EQ15_CONSTANT / m_eff) * sqrt(k13);
                if !(separation_energy.is_finite() && critical_velocity.is_finite()) {
                    return Err(Error::DerivedOutOfRange {
                        quantity: "g_s (adhesion)",
                        fields: "adhesion.surface_energy",
                    });
                }
                Some(AdhesionConstants {
                    surface_energy: gamma,
                    modulus,
                    separation_energy,
                    critical_velocity,
                })
            }
        };
        Ok(Contact {
            mass_1,
            mass_2,
            r_eff,
            m_eff,
            rho_h,
            alpha,
            damping_time,
            contact_end: scene.contact_end,
            layer,
            adhesion,
            friction: scene.friction,
            log10_delta_coefficient: crate::numerics::math::log10(damping_time)
                + 0.4 * crate::numerics::math::log10(alpha),
        })
    }

    /// The dimensionless damping `δ = A α^(2/5) g^(1/5)` at impact speed `g` \[m/s\] (docs/physics.md#decision-3).
    pub fn delta(&self, g: f64) -> f64 {
        self.damping_time * powf(self.alpha, 0.4) * powf(g, 0.2)
    }

    /// The length scale `ξ* = (g²/α)^(2/5)` \[m\] at impact speed `g`.
    pub fn length_scale(&self, g: f64) -> f64 {
        powf(g, 0.8) * powf(self.alpha, -0.4)
    }

    /// The time scale `τ = ξ*/g` \[s\] at impact speed `g`.
    pub fn time_scale(&self, g: f64) -> f64 {
        powf(g, -0.2) * powf(self.alpha, -0.4)
    }
}
