//! Published approximations of the viscoelastic ε_N(δ) of Eq. (4) (docs/physics.md#model-approximants).
//!
//! Both are written in Schwager and Pöschel's variable `x = √(1.5 δ)` (their `β^(1/2) g^(1/10)`,
//! `β = (3/2) A α^(2/5)`), with δ of docs/physics.md#decision-3.

use crate::normal::analytic::SCHWAGER_POSCHEL_C1;

/// `C₂ = (3/5) C₁² = 0.798…` (Ramírez et al. 1999; Schwager & Pöschel 2008).
pub const SCHWAGER_POSCHEL_C2: f64 = 0.6 * SCHWAGER_POSCHEL_C1 * SCHWAGER_POSCHEL_C1;

/// The [1/4] Padé approximant of Müller & Pöschel (2011): `ε = (1 + a₁x)/(1 + a₁x + b₂x² + b₃x³ +
/// b₄x⁴)`, coefficients `[a₁, b₂, b₃, b₄]` as published (6 digits).
pub const MULLER_POSCHEL_PADE: [f64; 4] = [0.501086, 1.15345, 0.577977, 0.532178];

/// `y = 1.5 δ` above which the truncated series no longer decreases (`C₁/(2C₂)`): beyond it the series
/// is reported `outside_validity`.
pub const SERIES_LIMIT: f64 = SCHWAGER_POSCHEL_C1 / (2.0 * SCHWAGER_POSCHEL_C2);

/// The Schwager–Pöschel series to second order in `y = x² = 1.5δ`: `1 − C₁y + C₂y²`, capped at 1
/// (it is positive for every y: `C₁² < 4C₂`). Returns `(ε, within validity)`.
pub fn series(delta: f64) -> (f64, bool) {
    let y = 1.5 * delta;
    let e = 1.0 - SCHWAGER_POSCHEL_C1 * y + SCHWAGER_POSCHEL_C2 * y * y;
    (e.clamp(0.0, 1.0), y <= SERIES_LIMIT)
}

/// The Müller–Pöschel [1/4] Padé approximant at damping δ; in (0, 1] for every δ ≥ 0.
pub fn pade(delta: f64) -> f64 {
    let x = crate::numerics::math::sqrt(1.5 * delta);
    let [a1, b2, b3, b4] = MULLER_POSCHEL_PADE;
    let num = 1.0 + a1 * x;
    let den = num + x * x * (b2 + x * (b3 + x * b4));
    if den.is_finite() { num / den } else { 0.0 }
}
