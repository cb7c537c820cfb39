//! Adhesion on top of a rebound: Eq. (13)–(17) with docs/physics.md#decision-5.

/// Applies Eq. (17) to a rebound without adhesion.
///
/// `eps_v` is ε_{N,v} of the model without adhesion, `g` the impact speed and `g_s` the critical
/// rebound speed of Eq. (15). The threshold is on the rebound speed `g'_{N,v} = ε_{N,v} g` (Eq. (17)
/// prints `g_N`; Eq. (13)–(16) put it on the rebound). Returns `None` when the grains stick.
#[doc(alias = "Eq. (17)")]
pub fn apply(eps_v: f64, g: f64, g_s: f64) -> Option<f64> {
    if g_s == 0.0 {
        // γ = 0: no separation energy to pay, exactly the model without adhesion (even when the
        // rebound itself is 0, e.g. an abandoned zero-overlap creep, which is overdamped, not stuck).
        return Some(eps_v);
    }
    let rebound = eps_v * g;
    if rebound <= g_s {
        return None;
    }
    let ratio = g_s / rebound;
    // 1 − ratio² written as (1 − ratio)(1 + ratio) to keep digits near the threshold.
    Some(eps_v * crate::numerics::math::sqrt((1.0 - ratio) * (1.0 + ratio)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn energy_balance_of_eq_13_holds() {
        // ½ g'² = ½ g'_v² − ½ g_s²  (W_s = ½ m g_s², Eq. (12)–(15)).
        let (eps_v, g, g_s) = (0.8, 0.01, 0.003);
        let eps = apply(eps_v, g, g_s).unwrap();
        let lhs = (eps * g) * (eps * g);
        let rhs = (eps_v * g) * (eps_v * g) - g_s * g_s;
        assert!((lhs - rhs).abs() < 1e-15 * rhs.abs().max(1e-30) + 1e-20);
        assert_eq!(apply(eps_v, g, eps_v * g), None);
        assert!(apply(1.0, 1.0, 0.0) == Some(1.0));
        assert_eq!(apply(0.0, 1.0, 0.0), Some(0.0));
    }
}
