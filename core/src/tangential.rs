//! Tangential restitution: Eq. (18)–(26) with docs/physics.md#decision-6, and the stick-map classes of
//! docs/physics.md#decision-7.
//!
//! With the sliding angle `tan ψ = g_T/g_N` (Eq. (25)) and `tan ψ₀ = μ/κ`:
//!
//! * **rolling branch** `ψ ≤ ψ₀`: `ε_T = −ε_N(g_T)`, the normal law evaluated at the tangential speed
//!   (Eq. (26), top);
//! * **sliding branch** `ψ > ψ₀`: the paper's law `ε_T = √(1 − 2μ g_N (1+ε_N(g_N))/(κ g_T))`
//!   (Eq. (23) / Eq. (26), bottom), clamped to `ε_T = 0` where the radicand is negative, or Walton's
//!   linear Coulomb-impulse law `ε_T = 1 − μ(1+ε_N(g_N)) g_N/(κ g_T)` ([`SlidingLaw::Walton`]).
//!
//! **Deviation from the paper.** The paper states (end of §3) that points with a negative radicand
//! lie inside the region where ε_T = 0 anyway. That is not so: just above ψ₀ we have
//! `μ g_N/(κ g_T) → 1⁻`, so the radicand tends to `1 − 2(1 + ε_N(g_N)) ≤ −1 < 0` for *every* normal
//! model, hard spheres included. We clamp to ε_T = 0 and report the class
//! [`StickClass::SlidingGap`] so that the gap is visible instead of hidden.
//!
//! **Boundary.** The comparison is written `g_T κ ≤ μ g_N` (no division), so that `g_T` exactly equal
//! to `(μ/κ) g_N` is on the rolling branch, as in Eq. (26) (`ψ ≤ ψ₀`), and `g_N = 0` needs no special
//! case. A frictionless contact (`μ = 0`) is sliding everywhere with `ε_T = 1`, including the point
//! `g_T = 0` where the ratio is undefined (there `g'_T = 0` whatever ε_T is).

use crate::error::{Error, Result, within};
use crate::numerics::accuracy::Accuracy;
use crate::numerics::math::{atan2, sqrt};
use crate::scene::contact::Contact;
use crate::scene::{Friction, SlidingLaw};

/// The class of a point `(g_N, g_T)` of the stick map (docs/physics.md#decision-7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum StickClass {
    /// Rolling branch (ψ ≤ ψ₀) with `ε_T = −ε_N(g_T) ≠ 0`: the tangential motion reverses.
    Rolling,
    /// Sliding branch (ψ > ψ₀) with a non-negative radicand (paper's law) or Walton's law.
    Sliding,
    /// Rolling branch with `ε_N(g_T) = 0`: the tangential motion stops while the normal one rebounds.
    RollingStop,
    /// Sliding branch where the radicand of Eq. (23) is negative: clamped to `ε_T = 0` while the normal
    /// motion rebounds.
    SlidingGap,
    /// `ε_N(g_N) = 0` and `ε_T = 0`: both components stop, the grains aggregate.
    Aggregation,
    /// `ε_N(g_N) = 0` but `ε_T ≠ 0`: the normal motion stops, the tangential one does not.
    NormalStickOnly,
    /// `g_N = g_T = 0`: no collision; ε_T is reported as 0.
    Undefined,
}

impl StickClass {
    /// The class's index in [`StickClass::ALL`] (its code on the page's wire).
    pub fn code(self) -> u8 {
        StickClass::ALL
            .iter()
            .position(|x| *x == self)
            .map_or(u8::MAX, |i| i as u8)
    }

    /// Every class, in legend order.
    pub const ALL: [StickClass; 7] = [
        StickClass::Rolling,
        StickClass::Sliding,
        StickClass::RollingStop,
        StickClass::SlidingGap,
        StickClass::Aggregation,
        StickClass::NormalStickOnly,
        StickClass::Undefined,
    ];

    /// The snake_case name used in JSON, CSV and legends (`rolling`, `sliding`, `rolling_stop`,
    /// `sliding_gap`, `aggregation`, `normal_stick_only`, `undefined`).
    pub fn name(self) -> &'static str {
        match self {
            StickClass::Rolling => "rolling",
            StickClass::Sliding => "sliding",
            StickClass::RollingStop => "rolling_stop",
            StickClass::SlidingGap => "sliding_gap",
            StickClass::Aggregation => "aggregation",
            StickClass::NormalStickOnly => "normal_stick_only",
            StickClass::Undefined => "undefined",
        }
    }

    /// One character for text maps (terminal tables and plain-text legends).
    pub fn letter(self) -> char {
        match self {
            StickClass::Rolling => 'r',
            StickClass::Sliding => 's',
            StickClass::RollingStop => 'R',
            StickClass::SlidingGap => 'g',
            StickClass::Aggregation => 'A',
            StickClass::NormalStickOnly => 'n',
            StickClass::Undefined => '.',
        }
    }

    /// A short human label for legends and tables people read (`rolling stop`); the sliding gap
    /// is flagged as the printed law's artifact. Data files keep [`name`](Self::name).
    pub fn label(self) -> &'static str {
        match self {
            StickClass::Rolling => "rolling",
            StickClass::Sliding => "sliding",
            StickClass::RollingStop => "rolling stop",
            StickClass::SlidingGap => "sliding gap (artifact of the printed Eq. (23))",
            StickClass::Aggregation => "aggregation",
            StickClass::NormalStickOnly => "normal stick only",
            StickClass::Undefined => "undefined (g_N = g_T = 0)",
        }
    }

    /// What the class means, for help screens (the terminal's `?`, the page's map legend).
    pub fn meaning(self) -> &'static str {
        match self {
            StickClass::Rolling => {
                "rolling (ψ ≤ ψ₀): the contact point sticks; the tangential motion reverses, ε_T = −ε_N(g_T)"
            }
            StickClass::Sliding => {
                "sliding (ψ > ψ₀): the grains slide over each other; ε_T from the sliding law"
            }
            StickClass::RollingStop => {
                "rolling stop: rolling with ε_N(g_T) = 0; the tangential motion stops, the normal one rebounds"
            }
            StickClass::SlidingGap => {
                "sliding gap: an artifact of the printed law, not a regime; Eq. (23)'s radicand is negative, ε_T clamped to 0 (W: Walton's law has no gap)"
            }
            StickClass::Aggregation => {
                "aggregation: ε_N = 0 and ε_T = 0; both motions stop, the grains stick together"
            }
            StickClass::NormalStickOnly => {
                "normal stick only: ε_N = 0 but ε_T ≠ 0; the normal motion stops, the tangential one goes on"
            }
            StickClass::Undefined => "undefined: g_N = g_T = 0, no collision",
        }
    }

    /// A short human-readable description for legends.
    pub fn description(self) -> &'static str {
        match self {
            StickClass::Rolling => "rolling: tangential motion reverses, ε_T = −ε_N(g_T)",
            StickClass::Sliding => "sliding: ε_T from the sliding law (Eq. (23))",
            StickClass::RollingStop => "rolling stop: ε_N(g_T) = 0, tangential motion stops",
            StickClass::SlidingGap => "sliding gap: Eq. (23) radicand < 0, clamped to ε_T = 0",
            StickClass::Aggregation => "aggregation: both components stop",
            StickClass::NormalStickOnly => "normal stick only: ε_N = 0, ε_T ≠ 0",
            StickClass::Undefined => "undefined: g_N = g_T = 0",
        }
    }

    /// Looks a class up by its [`name`](Self::name).
    pub fn from_name(name: &str) -> Option<StickClass> {
        StickClass::ALL.into_iter().find(|c| c.name() == name)
    }
}

/// Tangential restitution at one point `(g_N, g_T)`.
///
/// # Examples
///
/// ```
/// use rime_core::{Accuracy, Contact, Preset, StickClass};
///
/// let contact = Contact::new(&Preset::Ice.scene())?;
/// // A grazing hit (g_T ≫ g_N) slides; a nearly head-on one rolls (Eq. (25)–(26)).
/// let grazing = contact.tangential(1e-3, 1.0, Accuracy::Precise)?;
/// let head_on = contact.tangential(1.0, 1e-3, Accuracy::Precise)?;
/// assert_eq!(grazing.class, StickClass::Sliding);
/// assert_eq!(head_on.class, StickClass::Rolling);
/// assert!((-1.0..=1.0).contains(&grazing.eps_t) && (-1.0..=1.0).contains(&head_on.eps_t));
/// # Ok::<(), rime_core::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Tangential {
    /// Tangential restitution coefficient ε_T = g'_T/g_T ∈ \[−1, 1\] (Eq. (1), (26)).
    pub eps_t: f64,
    /// Normal restitution coefficient ε_N(g_N) at the normal impact speed.
    pub eps_n: f64,
    /// Stick-map class.
    pub class: StickClass,
}

/// `tan ψ₀ = μ/κ` (Eq. (25)): the sliding angle above which the contact slides. 1.05 for μ = 0.3,
/// κ = 2/7.
#[doc(alias = "Eq. (25)")]
pub fn tan_psi0(friction: &Friction) -> f64 {
    friction.coefficient / friction.kappa
}

/// The sliding angle `ψ = atan(g_T/g_N)` \[rad\] of Eq. (25), in `[0, π/2]` for non-negative speeds
/// (`π/2` at `g_N = 0`, 0 at `g = 0`).
pub fn sliding_angle(g_n: f64, g_t: f64) -> f64 {
    atan2(g_t, g_n)
}

/// True on the rolling branch of Eq. (26), `ψ ≤ ψ₀`, evaluated as `g_T κ ≤ μ g_N` so that the
/// boundary itself is rolling. Always false when `μ = 0` (frictionless contacts slide).
pub fn is_rolling(g_n: f64, g_t: f64, friction: &Friction) -> bool {
    // Eq. (25): tan ψ = g_T/g_N ≤ μ/κ = tan ψ₀, multiplied out.
    friction.coefficient > 0.0 && g_t * friction.kappa <= friction.coefficient * g_n
}

/// The radicand `1 − 2μ g_N (1+ε_N)/(κ g_T)` of Eq. (23) (`1` when `μ = 0` or `g_N = 0`).
///
/// Meaningful on the sliding branch, where `g_T > 0` whenever `μ > 0`.
#[doc(alias = "Eq. (23)")]
pub fn paper_radicand(g_n: f64, g_t: f64, eps_n: f64, friction: &Friction) -> f64 {
    1.0 - 2.0 * coulomb_ratio(g_n, g_t, eps_n, friction)
}

/// `μ (1+ε_N) g_N/(κ g_T)`, the tangential velocity change of a Coulomb impulse in units of `g_T`.
fn coulomb_ratio(g_n: f64, g_t: f64, eps_n: f64, friction: &Friction) -> f64 {
    let mu = friction.coefficient;
    if mu == 0.0 || g_n == 0.0 {
        0.0
    } else {
        mu * (1.0 + eps_n) * g_n / (friction.kappa * g_t)
    }
}

/// Classifies one point and evaluates ε_T (Eq. (26), docs/physics.md#decision-6 and #decision-7).
///
/// `eps_n_of_gn` is ε_N(g_N); `eps_n_of_gt` is ε_N(g_T) and is only read on the rolling branch
/// ([`is_rolling`]), so maps can evaluate ε_N once per grid velocity and pass any value elsewhere.
/// Speeds must be finite and non-negative (checked by [`Contact::tangential`], not here).
#[doc(alias = "Eq. (26)")]
pub fn classify(
    g_n: f64,
    g_t: f64,
    eps_n_of_gn: f64,
    eps_n_of_gt: f64,
    friction: &Friction,
) -> Tangential {
    if g_n == 0.0 && g_t == 0.0 {
        return Tangential {
            eps_t: 0.0,
            eps_n: eps_n_of_gn,
            class: StickClass::Undefined,
        };
    }
    let rolling = is_rolling(g_n, g_t, friction);
    let (eps_t, gap) = if rolling {
        // Eq. (26), top: ε_T = −ε_N(g_T). Written so that ε_N = 0 gives +0, not −0.
        (
            if eps_n_of_gt == 0.0 {
                0.0
            } else {
                -eps_n_of_gt
            },
            false,
        )
    } else {
        match friction.sliding_law {
            SlidingLaw::Paper => {
                // Eq. (23) / Eq. (26), bottom; negative radicand clamped (docs/physics.md#decision-6).
                let radicand = paper_radicand(g_n, g_t, eps_n_of_gn, friction);
                if radicand < 0.0 {
                    (0.0, true)
                } else {
                    (sqrt(radicand), false)
                }
            }
            // Walton: the Coulomb impulse μ J_N acting on the tangential mass κ m_eff.
            SlidingLaw::Walton => (1.0 - coulomb_ratio(g_n, g_t, eps_n_of_gn, friction), false),
        }
    };
    let class = if eps_n_of_gn == 0.0 {
        if eps_t == 0.0 {
            StickClass::Aggregation
        } else {
            StickClass::NormalStickOnly
        }
    } else if rolling {
        if eps_t == 0.0 {
            StickClass::RollingStop
        } else {
            StickClass::Rolling
        }
    } else if gap {
        StickClass::SlidingGap
    } else {
        StickClass::Sliding
    };
    Tangential {
        eps_t,
        eps_n: eps_n_of_gn,
        class,
    }
}

impl Contact {
    /// Tangential restitution at normal impact speed `g_n` and tangential speed `g_t` \[m/s\]
    /// (Eq. (26)).
    ///
    /// Evaluates ε_N(g_N) and, on the rolling branch only, ε_N(g_T) with [`Contact::eps_n`] (either
    /// speed may be 0). Fails when the scene has no friction (error names `friction`) or when a speed
    /// is negative, non-finite or above 1e6 m/s (error names `g_n` or `g_t`).
    pub fn tangential(&self, g_n: f64, g_t: f64, accuracy: Accuracy) -> Result<Tangential> {
        let friction = self.friction.ok_or(Error::InvalidValue {
            field: "friction",
            expected: "a friction model (the scene has none)",
        })?;
        within(
            "friction.coefficient",
            friction.coefficient,
            0.0,
            f64::MAX,
            "must be a finite number >= 0",
        )?;
        within(
            "friction.kappa",
            friction.kappa,
            f64::MIN_POSITIVE,
            1.0,
            "must lie in (0, 1]",
        )?;
        let max = crate::scene::limits::SPEED_MAX;
        let g_n = within("g_n", g_n, 0.0, max, "speed must lie in [0, 1e6] m/s")?;
        let g_t = within("g_t", g_t, 0.0, max, "speed must lie in [0, 1e6] m/s")?;
        let eps_n_of_gn = self.eps_n(g_n, accuracy)?;
        let eps_n_of_gt = if g_n == 0.0 && g_t == 0.0 {
            eps_n_of_gn
        } else if is_rolling(g_n, g_t, &friction) {
            self.eps_n(g_t, accuracy)?
        } else {
            // Not read on the sliding branch.
            0.0
        };
        Ok(classify(g_n, g_t, eps_n_of_gn, eps_n_of_gt, &friction))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Preset, Scene};

    fn friction(mu: f64, kappa: f64, law: SlidingLaw) -> Friction {
        Friction {
            coefficient: mu,
            kappa,
            sliding_law: law,
        }
    }

    fn contact(preset: Preset) -> Contact {
        Contact::new(&preset.scene()).unwrap()
    }

    #[test]
    fn class_names_are_unique_snake_case_and_round_trip() {
        let expected = [
            "rolling",
            "sliding",
            "rolling_stop",
            "sliding_gap",
            "aggregation",
            "normal_stick_only",
            "undefined",
        ];
        for (class, name) in StickClass::ALL.into_iter().zip(expected) {
            assert_eq!(class.name(), name);
            assert_eq!(StickClass::from_name(name), Some(class));
            assert!(!class.description().is_empty());
        }
        assert_eq!(StickClass::from_name("Rolling"), None);
    }

    #[test]
    fn tan_psi0_of_the_default_is_1_05() {
        // μ/κ = 0.3 · 7/2 = 1.05.
        assert!((tan_psi0(&Friction::default()) - 1.05).abs() < 1e-15);
        assert!((sliding_angle(1.0, 1.0) - core::f64::consts::FRAC_PI_4).abs() < 1e-15);
        assert_eq!(sliding_angle(0.0, 1.0), core::f64::consts::FRAC_PI_2);
    }

    #[test]
    fn hard_spheres_never_stop_the_tangential_motion_on_a_grid() {
        // Fig. 4 (top): without layer or adhesion, no (g_N, g_T) stops the tangential motion, and
        // ε_N(g_N) > 0 everywhere (no NormalStickOnly either).
        let c = contact(Preset::Ice);
        let n = 16;
        let mut seen_rolling = false;
        let mut seen_sliding = false;
        for i in 0..=n {
            for j in 0..=n {
                let g_n = 0.05 * i as f64 / n as f64;
                let g_t = 0.05 * j as f64 / n as f64;
                let t = c.tangential(g_n, g_t, Accuracy::Balanced).unwrap();
                assert!(t.eps_t.is_finite() && (-1.0..=1.0).contains(&t.eps_t));
                match t.class {
                    StickClass::RollingStop
                    | StickClass::Aggregation
                    | StickClass::NormalStickOnly => {
                        panic!("hard spheres gave {:?} at ({g_n}, {g_t})", t.class)
                    }
                    StickClass::Undefined => assert!(i == 0 && j == 0),
                    StickClass::Rolling => seen_rolling = true,
                    StickClass::Sliding => seen_sliding = true,
                    StickClass::SlidingGap => {}
                }
            }
        }
        assert!(seen_rolling && seen_sliding);
    }

    #[test]
    fn rolling_branch_uses_the_normal_law_at_g_t() {
        let c = contact(Preset::Ice);
        let (g_n, g_t) = (0.03, 0.01);
        let t = c.tangential(g_n, g_t, Accuracy::Precise).unwrap();
        assert_eq!(t.class, StickClass::Rolling);
        assert_eq!(t.eps_t, -c.eps_n(g_t, Accuracy::Precise).unwrap());
        assert_eq!(t.eps_n, c.eps_n(g_n, Accuracy::Precise).unwrap());
    }

    #[test]
    fn walton_law_is_the_energy_balance_of_a_coulomb_impulse() {
        // Independent derivation: a normal impulse J_N = m(1+ε_N)g_N and a sliding tangential
        // impulse μ J_N acting on the tangential mass κ m change g_T by −μ(1+ε_N)g_N/κ. The friction
        // work is −μ J_N times the mean sliding speed (g_T + g'_T)/2 (speed linear in impulse), and
        // equals the tangential energy change ½ κ m (g'_T² − g_T²) of Eq. (22).
        let m = 0.015; // m_eff [kg]; cancels.
        for &(mu, kappa) in &[(0.3, 2.0 / 7.0), (0.1, 0.4), (0.5, 1.0 / 3.0)] {
            let f = friction(mu, kappa, SlidingLaw::Walton);
            for &(g_n, g_t, eps_n) in &[(0.01, 0.05, 0.9), (0.002, 0.04, 0.3), (0.01, 0.2, 0.0)] {
                assert!(!is_rolling(g_n, g_t, &f));
                let t = classify(g_n, g_t, eps_n, f64::NAN, &f);
                let j_n = m * (1.0 + eps_n) * g_n;
                let g_t_after = g_t - mu * j_n / (kappa * m);
                assert!((t.eps_t - g_t_after / g_t).abs() < 1e-14);
                let work = -mu * j_n * 0.5 * (g_t + g_t_after);
                let d_energy = 0.5 * kappa * m * g_t * g_t * (t.eps_t * t.eps_t - 1.0);
                assert!((d_energy - work).abs() <= 1e-13 * work.abs());
                // The paper's Eq. (20) uses g_T instead of the mean speed: Eq. (23) differs.
                let paper = classify(
                    g_n,
                    g_t,
                    eps_n,
                    0.0,
                    &friction(mu, kappa, SlidingLaw::Paper),
                );
                let paper_energy = 0.5 * kappa * m * g_t * g_t * (paper.eps_t * paper.eps_t - 1.0);
                if paper.class == StickClass::Sliding {
                    assert!((paper_energy - (-mu * j_n * g_t)).abs() <= 1e-13 * work.abs());
                }
            }
        }
    }

    #[test]
    fn boundary_is_rolling_and_just_above_is_the_gap() {
        // μ/κ = 0.5 and speeds chosen so that g_T κ and μ g_N are the same double (power-of-two
        // scalings are exact): g_T = (μ/κ) g_N exactly.
        let f = friction(0.25, 0.5, SlidingLaw::Paper);
        let (g_n, g_t) = (0.02, 0.01);
        assert_eq!(g_t * f.kappa, f.coefficient * g_n);
        let on = classify(g_n, g_t, 0.8, 0.9, &f);
        assert_eq!(on.class, StickClass::Rolling);
        assert_eq!(on.eps_t, -0.9);
        let above = classify(g_n, libm::nextafter(g_t, 1.0), 0.8, 0.9, &f);
        assert_eq!(above.class, StickClass::SlidingGap);
        assert_eq!(above.eps_t, 0.0);
        // Walton at the boundary approaches −ε_N(g_N), no gap.
        let w = friction(0.25, 0.5, SlidingLaw::Walton);
        let above = classify(g_n, libm::nextafter(g_t, 1.0), 0.8, 0.9, &w);
        assert_eq!(above.class, StickClass::Sliding);
        assert!((above.eps_t + 0.8).abs() < 1e-12);
        // Stopped variants of the rolling branch.
        assert_eq!(
            classify(g_n, g_t, 0.8, 0.0, &f).class,
            StickClass::RollingStop
        );
        assert_eq!(
            classify(g_n, g_t, 0.0, 0.0, &f).class,
            StickClass::Aggregation
        );
        assert_eq!(
            classify(g_n, g_t, 0.0, 0.5, &f).class,
            StickClass::NormalStickOnly
        );
        assert_eq!(
            classify(0.0, 0.0, 1.0, 1.0, &f).class,
            StickClass::Undefined
        );
        assert_eq!(classify(0.0, 0.0, 1.0, 1.0, &f).eps_t, 0.0);
        // +0, not −0, when ε_N(g_T) = 0.
        assert!(classify(g_n, g_t, 0.8, 0.0, &f).eps_t.is_sign_positive());
    }

    #[test]
    fn the_radicand_is_negative_just_above_psi0_for_every_model() {
        // At g_T = (μ/κ) g_N (1 + η), the radicand is 1 − 2(1+ε_N)/(1+η) → −1 − 2ε_N < 0 as η → 0,
        // whatever ε_N(g_N) ∈ [0, 1] the normal model gives.
        // Every ε_N ∈ [0, 1] a model can return, including an overdamped 1e-12:
        let f = Friction::default();
        for &eps_n in &[0.0, 1e-12, 0.3, 0.9, 1.0] {
            let g_n = 0.01;
            let g_t = tan_psi0(&f) * g_n * (1.0 + 1e-9);
            assert!(paper_radicand(g_n, g_t, eps_n, &f) <= -1.0 + 1e-8);
            assert_eq!(classify(g_n, g_t, eps_n, 0.0, &f).eps_t, 0.0);
        }
        // …and the scene models. `ice-paper-viscosities` is left out: its δ ~ 1e5–1e7 makes the
        // existing viscoelastic integrator exceed its step budget (reported separately).
        for preset in [Preset::Ice, Preset::IceFrost, Preset::IceSticky] {
            let c = contact(preset);
            let f = c.friction.unwrap();
            for &g_n in &[1e-6, 1e-4, 1e-3, 1e-2, 5e-2] {
                let eta = 1e-9;
                let g_t = tan_psi0(&f) * g_n * (1.0 + eta);
                assert!(!is_rolling(g_n, g_t, &f));
                let eps_n = c.eps_n(g_n, Accuracy::Balanced).unwrap();
                let r = paper_radicand(g_n, g_t, eps_n, &f);
                let expected = 1.0 - 2.0 * (1.0 + eps_n) / (1.0 + eta);
                assert!((r - expected).abs() < 1e-8, "{r} vs {expected}");
                assert!(r <= -1.0 + 1e-8);
                let t = c.tangential(g_n, g_t, Accuracy::Balanced).unwrap();
                assert_eq!(t.eps_t, 0.0);
                let want = if eps_n == 0.0 {
                    StickClass::Aggregation
                } else {
                    StickClass::SlidingGap
                };
                assert_eq!(t.class, want, "{} at g_n = {g_n}", preset.name());
            }
        }
    }

    #[test]
    fn grazing_sliding_tends_to_one() {
        // ψ → 90°: μ g_N/(κ g_T) → 0, so ε_T → 1 with 1 − ε_T ≈ μ(1+ε_N)g_N/(κ g_T) ≤ 2μ g_N/(κ g_T).
        let c = contact(Preset::Ice);
        let f = c.friction.unwrap();
        let g_t = 0.05;
        for &g_n in &[1e-4, 1e-6, 1e-9] {
            let t = c.tangential(g_n, g_t, Accuracy::Balanced).unwrap();
            assert_eq!(t.class, StickClass::Sliding);
            let bound = 2.0 * f.coefficient * g_n / (f.kappa * g_t);
            assert!(1.0 - t.eps_t <= bound * (1.0 + 1e-12) && t.eps_t <= 1.0);
        }
        let t = c.tangential(0.0, g_t, Accuracy::Balanced).unwrap();
        assert_eq!((t.eps_t, t.class), (1.0, StickClass::Sliding));
    }

    #[test]
    fn frictionless_contacts_always_slide_with_unit_restitution() {
        for law in [SlidingLaw::Paper, SlidingLaw::Walton] {
            let f = friction(0.0, 2.0 / 7.0, law);
            for &(g_n, g_t) in &[(0.01, 0.0), (0.01, 1e-6), (0.01, 0.01), (0.0, 0.02)] {
                let t = classify(g_n, g_t, 0.7, 0.3, &f);
                assert_eq!((t.eps_t, t.class), (1.0, StickClass::Sliding));
            }
        }
    }

    #[test]
    fn surface_effects_produce_stopped_classes() {
        // ice-frost: layer g_s ≈ 6.6 µm/s (Eq. (10)). Both below g_s: aggregation; g_N above, g_T below
        // on the rolling branch: rolling stop; g_N below, sliding (ε_T = 1 at g_N = 0): normal stick.
        let c = contact(Preset::IceFrost);
        let g_s = c.layer.unwrap().critical_velocity;
        let acc = Accuracy::Balanced;
        assert_eq!(
            c.tangential(0.5 * g_s, 0.2 * g_s, acc).unwrap().class,
            StickClass::Aggregation
        );
        assert_eq!(
            c.tangential(1e-3, 0.5 * g_s, acc).unwrap().class,
            StickClass::RollingStop
        );
        assert_eq!(
            c.tangential(0.0, 1e-3, acc).unwrap().class,
            StickClass::NormalStickOnly
        );
    }

    #[test]
    fn bad_input_names_the_field() {
        let c = contact(Preset::Ice);
        let field = |e: Error| match e {
            Error::OutOfRange { field, .. } | Error::InvalidValue { field, .. } => field,
            other => panic!("unexpected {other:?}"),
        };
        let acc = Accuracy::Balanced;
        assert_eq!(field(c.tangential(-1.0, 0.1, acc).unwrap_err()), "g_n");
        assert_eq!(field(c.tangential(0.1, f64::NAN, acc).unwrap_err()), "g_t");
        assert_eq!(
            field(c.tangential(f64::INFINITY, 0.1, acc).unwrap_err()),
            "g_n"
        );
        let no_friction = Contact::new(&Scene {
            friction: None,
            ..Scene::default()
        })
        .unwrap();
        assert_eq!(
            field(no_friction.tangential(0.1, 0.1, acc).unwrap_err()),
            "friction"
        );
    }
}
