//! Closed forms: critical velocities (Eq. (10), (12), (15)), the elastic Hertz limits of Eq. (4), and the
//! first-order Schwager–Pöschel expansion of ε_N for weak damping.
//!
//! These are independent of the integrators and serve as limits and cross-checks for them.

use crate::error::{Result, positive};
use crate::numerics::math::{cbrt, sqrt};
use crate::scene::contact::Contact;

/// Critical velocity of a soft layer, Eq. (10): `g_s = √R_eff η* D^(3/2)/m_eff` \[m/s\], with
/// `η* = 1/K` the layer viscosity \[Pa s\], `D = D₁ + D₂` the total thickness \[m\], `R_eff` \[m\] and
/// `m_eff` \[kg\]. Below it the layer absorbs the whole impact (Eq. (9) with `ξ̇ = 0` at `ξ = D`).
#[doc(alias = "Eq. (10)")]
pub fn critical_velocity_layer(r_eff: f64, m_eff: f64, thickness: f64, viscosity: f64) -> f64 {
    // Eq. (10).
    sqrt(r_eff) * viscosity * thickness * sqrt(thickness) / m_eff
}

pub use crate::scene::contact::{EQ12_CONSTANT, EQ15_CONSTANT, adhesion_modulus};

/// JKR separation energy, Eq. (12): `W_s = 7.09 (γ⁵R_eff⁴/E²)^(1/3)` \[J\], with surface energy `γ`
/// \[J/m²\], `R_eff` \[m\] and modulus `E` \[Pa\] (`Y/(1−ν²)` as printed, docs/physics.md#decision-5).
///
/// Evaluated as `7.09 γ (γR²/E)^(2/3)`, which cannot overflow for physical inputs.
#[doc(alias = "Eq. (12)")]
pub fn separation_energy(surface_energy: f64, r_eff: f64, modulus: f64) -> f64 {
    let u = surface_energy * r_eff * r_eff / modulus;
    // Eq. (12).
    EQ12_CONSTANT * surface_energy * cbrt(u * u)
}

/// Critical rebound velocity for adhesion, Eq. (15):
/// `g_s = (14.18/m_eff)^(1/2) (γ⁵R_eff⁴/E²)^(1/6)` \[m/s\].
///
/// Since 14.18 = 2 × 7.09 this is `√(2 W_s/m_eff)`: the rebound kinetic energy `½ m_eff g_s²` just
/// pays the separation energy of Eq. (12).
#[doc(alias = "Eq. (15)")]
pub fn critical_velocity_adhesion(
    m_eff: f64,
    surface_energy: f64,
    r_eff: f64,
    modulus: f64,
) -> f64 {
    // Eq. (15) via Eq. (13)–(14) with g'_N = 0.
    sqrt(2.0 * separation_energy(surface_energy, r_eff, modulus) / m_eff)
}

/// Duration of an elastic Hertz collision in units of `τ = ξ*/g` (docs/physics.md#decision-3):
/// `s_c = 2 x_max ∫₀¹ du/√(1 − u^(5/2)) = 2 x_max (2/5) B(2/5, 1/2)` with `x_max = (5/4)^(2/5)`.
///
/// Value from `(2/5) B(2/5, 1/2) = 1.471637592162352328690…` (mpmath, 30 digits):
/// `s_c = 3.218065459719043084535930…`.
pub const HERTZ_CONTACT_TIME: f64 = 3.218_065_459_719_043;

/// Maximum elastic compression in units of `ξ* = (g²/α)^(2/5)`: energy conservation
/// `½x'² + (2/5)x^(5/2) = ½` gives `x_max = (5/4)^(2/5) = 1.093362073943278056…`.
pub const HERTZ_MAX_COMPRESSION: f64 = 1.093_362_073_943_278;

/// Hertz (elastic, `A = 0`) contact duration \[s\] at impact speed `g` \[m/s\]:
/// `t_c = HERTZ_CONTACT_TIME · τ`, `τ = α^(−2/5) g^(−1/5)`. Error names `g` unless `g > 0` is finite.
pub fn hertz_contact_time(contact: &Contact, g: f64) -> Result<f64> {
    let g = positive("g", g)?;
    Ok(HERTZ_CONTACT_TIME * contact.time_scale(g))
}

/// Hertz (elastic) maximum compression \[m\] at impact speed `g` \[m/s\]:
/// `ξ_max = HERTZ_MAX_COMPRESSION · ξ* = (5 m_eff g²/(4 ρ_H))^(2/5)`. Error names `g` unless `g > 0`.
pub fn hertz_max_compression(contact: &Contact, g: f64) -> Result<f64> {
    let g = positive("g", g)?;
    Ok(HERTZ_MAX_COMPRESSION * contact.length_scale(g))
}

/// The constant `C₁ = √π Γ(3/5) / (2^(1/5) 5^(2/5) Γ(21/10)) = 1.15344885809528879913…` of the
/// Schwager–Pöschel (1998) expansion of ε_N (digits from mpmath at 30 digits).
pub const SCHWAGER_POSCHEL_C1: f64 = 1.153_448_858_095_288_8;

/// The first-order coefficient in our dimensionless damping δ: `(3/2) C₁ = 1.73017328714293…`.
pub const SMALL_DELTA_SLOPE: f64 = 1.5 * SCHWAGER_POSCHEL_C1;

/// First-order weak-damping limit `ε_N ≈ 1 − (3/2) C₁ δ` in the dimensionless damping
/// `δ = A α^(2/5) g^(1/5)` of docs/physics.md#decision-3 (`α = ρ_H/m_eff`).
///
/// **Normalisation.** Schwager and Pöschel write `ε_N = 1 − C₁ (3A/2) α^(2/5) g^(1/5) + …` with the
/// same `α = ρ_H/m_eff`, i.e. `1 − (3/2) C₁ δ`, not `1 − C₁ δ`. Checked against our integrator
/// (`normal::viscoelastic::dimensionless`, rtol 1e-12): `(1 − ε_N)/δ` is 1.7299930 (force-zero end)
/// and 1.7299938 (zero-overlap end) at δ = 1e-4, 1.7301551 (both) at δ = 1e-5, and 1.7301708 (both)
/// at δ = 1e-6, against `(3/2) C₁ = 1.7301733` and `C₁ = 1.1534489`; the ratio to `C₁` is
/// 1.49984, 1.49998, 1.499998. Both contact-end rules share the first order (they differ only at
/// higher order: by 2.3e-8 in ε_N at δ = 1e-3); the remainder is second order,
/// `(1 − ε_N)/δ − (3/2)C₁ ≈ −1.8 δ`.
pub fn eps_small_delta(delta: f64) -> f64 {
    1.0 - SMALL_DELTA_SLOPE * delta
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::normal::viscoelastic::dimensionless;
    use crate::numerics::accuracy::Accuracy;
    use crate::scene::{AdhesionModulus, ContactEnd, Damping, Preset, Scene};

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs()
    }

    #[test]
    fn critical_velocities_agree_with_the_contact_constants() {
        for preset in Preset::ALL {
            for modulus in [AdhesionModulus::AsPrinted, AdhesionModulus::Consistent] {
                let mut scene = preset.scene();
                scene.layer = Some(crate::scene::Layer::default());
                scene.adhesion = Some(crate::scene::Adhesion {
                    surface_energy: 0.3,
                    modulus,
                    jkr_end: Default::default(),
                });
                let c = Contact::new(&scene).unwrap();
                let layer = c.layer.unwrap();
                let adh = c.adhesion.unwrap();
                let l = scene.layer.unwrap();
                let gl = critical_velocity_layer(c.r_eff, c.m_eff, l.thickness, l.viscosity);
                assert!(rel(gl, layer.critical_velocity) < 1e-14);
                let ws = separation_energy(0.3, c.r_eff, adh.modulus);
                assert!(rel(ws, adh.separation_energy) < 1e-14);
                let ga = critical_velocity_adhesion(c.m_eff, 0.3, c.r_eff, adh.modulus);
                assert!(rel(ga, adh.critical_velocity) < 1e-14);
            }
        }
    }

    #[test]
    fn critical_velocities_by_hand() {
        // Eq. (10) with R_eff = 1 cm, m_eff = 15.08 g, D = 1 µm, η* = 1000 Pa s:
        // √0.01 · 1000 · 1e-9 / m_eff = 1e-7/m_eff.
        let m = 0.5 * 4.0 / 3.0 * core::f64::consts::PI * 900.0 * 8e-6;
        let g = critical_velocity_layer(0.01, m, 1e-6, 1000.0);
        assert!(rel(g, 1e-7 / m) < 1e-15);
        // Eq. (12) with γ = 1, R = 1, E = 1: 7.09; Eq. (15) with m = 2: √(14.18/2) = √7.09.
        assert!(rel(separation_energy(1.0, 1.0, 1.0), 7.09) < 1e-15);
        assert!(
            rel(
                critical_velocity_adhesion(2.0, 1.0, 1.0, 1.0),
                libm::sqrt(7.09)
            ) < 1e-15
        );
        // Scaling: W_s ∝ γ^(5/3) R^(4/3) E^(−2/3).
        let base = separation_energy(0.1, 0.01, 1e10);
        assert!(rel(separation_energy(0.8, 0.01, 1e10), 32.0 * base) < 1e-14);
        assert!(rel(separation_energy(0.1, 0.08, 1e10), 16.0 * base) < 1e-14);
        assert!(rel(separation_energy(0.1, 0.01, 8e10), 0.25 * base) < 1e-14);
    }

    /// ∫₀¹ du/√(1 − u^(5/2)) by composite Simpson after u = 1 − t² (removes the endpoint singularity).
    fn hertz_integral_quadrature(n: usize) -> f64 {
        let f = |t: f64| {
            if t == 0.0 {
                // Limit: 1 − (1−t²)^(5/2) ≈ (5/2) t².
                2.0 / libm::sqrt(2.5)
            } else {
                let u = 1.0 - t * t;
                2.0 * t / libm::sqrt(1.0 - libm::pow(u, 2.5))
            }
        };
        let h = 1.0 / n as f64;
        let mut sum = f(0.0) + f(1.0);
        for k in 1..n {
            sum += f(k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 };
        }
        sum * h / 3.0
    }

    #[test]
    fn hertz_constants_match_beta_function_and_quadrature() {
        let x_max = libm::pow(1.25, 0.4);
        assert!(rel(HERTZ_MAX_COMPRESSION, x_max) < 5e-16);
        // (2/5) B(2/5, 1/2) = (2/5) Γ(2/5) Γ(1/2) / Γ(9/10).
        let beta = 0.4 * libm::tgamma(0.4) * libm::tgamma(0.5) / libm::tgamma(0.9);
        assert!(rel(HERTZ_CONTACT_TIME, 2.0 * x_max * beta) < 1e-14);
        let quad = hertz_integral_quadrature(20_000);
        assert!(
            rel(HERTZ_CONTACT_TIME, 2.0 * x_max * quad) < 1e-10,
            "{quad}"
        );
    }

    #[test]
    fn hertz_limits_in_si_match_energy_balance_and_the_elastic_integrator() {
        let scene = Scene {
            bulk: crate::scene::Bulk {
                damping: Damping::Time(0.0),
                ..Default::default()
            },
            ..Scene::default()
        };
        let c = Contact::new(&scene).unwrap();
        for &g in &[1e-6, 1e-3, 0.05, 3.0] {
            // ½ m g² = (2/5) ρ_H ξ^(5/2).
            let xi = libm::pow(5.0 * c.m_eff * g * g / (4.0 * c.rho_h), 0.4);
            assert!(rel(hertz_max_compression(&c, g).unwrap(), xi) < 1e-13);
            let n = c.normal(g, Accuracy::Precise).unwrap();
            assert!(rel(hertz_contact_time(&c, g).unwrap(), n.t_c) < 1e-9);
            assert!(rel(hertz_max_compression(&c, g).unwrap(), n.xi_max) < 1e-9);
        }
        assert!(hertz_contact_time(&c, 0.0).is_err());
        assert!(hertz_max_compression(&c, f64::NAN).is_err());
    }

    #[test]
    fn schwager_poschel_c1_matches_gamma_functions() {
        let c1 = libm::sqrt(core::f64::consts::PI) * libm::tgamma(0.6)
            / (libm::pow(2.0, 0.2) * libm::pow(5.0, 0.4) * libm::tgamma(2.1));
        assert!(rel(SCHWAGER_POSCHEL_C1, c1) < 1e-14, "{c1}");
    }

    #[test]
    fn small_delta_slope_is_three_halves_c1_for_both_contact_ends() {
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            for &delta in &[1e-4, 1e-5] {
                let eps = dimensionless(delta, end, 1e-12).unwrap().eps;
                let slope = (1.0 - eps) / delta;
                // Remainder is second order (≈ 1.8 δ) plus integrator error (≈ 1e-12/δ).
                assert!((slope - SMALL_DELTA_SLOPE).abs() < 3.0 * delta + 1e-11 / delta);
                // C₁ alone (coefficient 1) is far off.
                assert!((slope - SCHWAGER_POSCHEL_C1).abs() > 0.5);
                assert!((eps_small_delta(delta) - eps).abs() < 3.0 * delta * delta + 1e-11);
            }
        }
    }
}
