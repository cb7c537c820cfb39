//! Elastic–perfectly-plastic normal impact (Thornton 1997, J. Appl. Mech. 64, 383), closed form
//! (docs/physics.md#model-thornton1997).
//!
//! Hertz (`F = (4/3) E* √R ξ^(3/2)`, `E*` the contact modulus of Eq. (4)) until the pressure at the
//! centre of the contact, `p₀ = 2E*a/(πR)` with `a = √(Rξ)`, reaches the limiting pressure `p_y`; then
//! the force grows linearly, `F = F_y + π p_y R (ξ − ξ_y)`; unloading is Hertzian about a flattened
//! radius `R_p = 4E*a_p³/(3F_max)` with `a_p = √(R ξ_max)`. No viscous damping.

use crate::error::Result;
use crate::numerics::math::{powf, sqrt};

/// The constants of one scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plastic {
    /// Contact modulus `E*` \[Pa\].
    pub modulus: f64,
    /// Limiting contact pressure `p_y` \[Pa\].
    pub yield_pressure: f64,
    /// Overlap at first yield `ξ_y = π² R p_y²/(4E*²)` \[m\].
    pub xi_yield: f64,
    /// Yield speed `v_y = √((16/15) E* √R ξ_y^(5/2)/m_eff)` \[m/s\]: slower impacts stay elastic.
    pub yield_speed: f64,
}

impl Plastic {
    /// From the scene's contact constants and yield pressure.
    pub fn new(contact: &crate::Contact, yield_pressure: f64) -> Result<Plastic> {
        let r = contact.r_eff;
        let modulus = 0.75 * contact.rho_h / sqrt(r);
        let ratio = yield_pressure / modulus;
        let xi_yield = core::f64::consts::PI * core::f64::consts::PI * r * ratio * ratio / 4.0;
        // ½ m v_y² = (8/15) E* √R ξ_y^(5/2), the Hertz energy at first yield.
        let energy = 8.0 / 15.0 * modulus * sqrt(r) * powf(xi_yield, 2.5);
        let yield_speed = sqrt(2.0 * energy / contact.m_eff);
        if !(yield_speed.is_finite() && yield_speed > 0.0) {
            return Err(crate::Error::DerivedOutOfRange {
                quantity: "v_yield",
                fields: "plasticity.yield_pressure, bulk.youngs_modulus, grains",
            });
        }
        Ok(Plastic {
            modulus,
            yield_pressure,
            xi_yield,
            yield_speed,
        })
    }

    /// ε_N at impact speed `g` (Thornton 1997, his closed form in `r = v_y/g`):
    /// `ε = √(6√3/5) √(1 − r²/6) [r/(r + 2√(6/5 − r²/5))]^(1/4)` for `g > v_y`, 1 below.
    pub fn eps(&self, g: f64) -> f64 {
        if g <= self.yield_speed {
            return 1.0;
        }
        let r = self.yield_speed / g;
        let r2 = r * r;
        let e = sqrt(6.0 * sqrt(3.0) / 5.0)
            * sqrt(1.0 - r2 / 6.0)
            * sqrt(sqrt(r / (r + 2.0 * sqrt(1.2 - 0.2 * r2))));
        e.clamp(0.0, 1.0)
    }
}
