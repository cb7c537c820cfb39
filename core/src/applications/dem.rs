//! The mapping of a scene onto a DEM code's contact law (LAMMPS `pair_style granular`), and the
//! time step and run length a two-grain DEM run needs to reproduce rime's ε_N at any damping
//! (docs/physics.md#dem; issues 25 and 35).
//!
//! **Mapping.** LAMMPS's `hertz/material E ν` mixes two equal materials to
//! `E_eff = 1/((1−ν²)/E + (1−ν²)/E) = E/(2(1−ν²))`, rime's contact modulus E* (ρ_H = (4/3)E*√R_eff,
//! Eq. (4)). Its `damping viscoelastic` force is `η_n0 m_eff a v_n` with the contact radius
//! a = √(R_eff ξ); rime's is `2E*A a ξ'` (= Eq. (4)'s `1.5ρ_H A √ξ ξ'`), so `η_n0 = 2E*A/m_eff`.
//! `limit_damping` clamps the normal force at ≥ 0: rime's `force_zero` end; plain damping lets the
//! viscous force pull while ξ > 0: rime's `zero_overlap`. An adhesive scene maps only when the user
//! names the mapping ([`AdhesionMapping`]): LAMMPS's `jkr` is brilliantov2007's dynamic JKR contact
//! (not the paper's energy-balance adhesion, Eq. (11)–(17)), with surface energy γ = w/2 (its tensile
//! term `2πa²√(4γE_eff/(πa))` is rime's `√(8πwE*a³)` only when w = 2γ), and it ends at the maximum
//! tensile force (rime's `pull_off_force`).
//!
//! **Time step.** LAMMPS integrates with velocity Verlet; with a velocity-dependent force it is first
//! order in dt and explicit, so dt must resolve both the elastic contact and the viscous relaxation
//! rate `η_n0 a` (in units of τ = ξ*/g, `1.5 δ √x`). [`LammpsMapping::time_step`] is the Hertz
//! duration over `N · max(1, η_n0 a τ)`: unchanged for weak damping, and for strong damping a fixed
//! number of steps per viscous relaxation time (the contact of `ice-paper-viscosities`, A = 404 s,
//! lasts 2.7 steps of the Hertz-based step and LAMMPS's grains left at 64 times the impact speed).
//! Until the grains turn apart `a` is taken at a bound of the maximum compression,
//! [`LammpsMapping::compression_bound`]; afterwards at the current overlap, which lets a creeping
//! zero-overlap contact (A = 1e-2 s: 0.19 s, 900 Hertz durations) run at the Hertz step.
//!
//! **Run length.** The deck stops on rime's own end rules (force zero: the force clamped at zero
//! while the grains separate — they coast apart at a constant speed; zero overlap: the overlap gone,
//! or the force turned tensile at a separation speed below [`OVERDAMPED_THRESHOLD`] × g, rime's
//! overdamped rule), so [`LammpsMapping::run_time`] is only a guard: a bound of rime's integrated
//! contact duration at every δ (test `issue_35_run_time_covers_rimes_duration_at_any_damping`).

use crate::error::{Error, Result};
use crate::models::{Evaluator, Model, ModelStatus};
use crate::normal::OVERDAMPED_THRESHOLD;
use crate::normal::analytic::{HERTZ_CONTACT_TIME, HERTZ_MAX_COMPRESSION};
use crate::numerics::accuracy::Accuracy;
use crate::numerics::math::{powf, sqrt};
use crate::scene::contact::Contact;
use crate::scene::{ContactEnd, JkrEnd, Scene};

/// LAMMPS's JKR contact holds while the separation is below `R₁ + R₂ + JKRPREFIX (R γ²/E_eff²)^(1/3)`,
/// JKRPREFIX = (3π²/16)^(1/3) (`gran_sub_mod_normal.cpp`).
pub const LAMMPS_JKR_SEPARATION_PREFIX: f64 = 1.227_722_850_784_289;

/// Time steps per (Hertz) contact duration of a deck without adhesion: LAMMPS's ε_N is good to
/// ~4e-5 at this dt and its error halves with dt (Richardson of two runs: ≤ 1e-5).
pub const STEPS_PER_CONTACT: u32 = 4000;

/// The same for a JKR deck, whose force jumps at pull-off: the step in which it falls misplaces up
/// to `F_p dt/(m_eff g)` of ε_N, an O(dt) error that is not smooth in dt.
pub const STEPS_PER_CONTACT_JKR: u32 = 64_000;

/// Factor of the run-time guard over the bound of rime's contact duration.
pub const RUN_TIME_FACTOR: f64 = 4.0;

/// A zero-overlap contact's duration in units of τ is below `HERTZ_CONTACT_TIME + this · δ` wherever
/// it is resolved (ε_N ≥ 1e-9, δ < 58.9; measured from the tables: the worst ratio (s_c − 3.218)/δ
/// is 18.9, near the end of the resolved range).
pub const ZERO_OVERLAP_DURATION_SLOPE: f64 = 20.0;

/// The mapping a user names for an adhesive scene (the paper's adhesion has no DEM equivalent).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AdhesionMapping {
    /// LAMMPS `jkr` with viscoelastic damping: rime's `brilliantov2007` (dynamic JKR contact).
    Jkr,
}

impl AdhesionMapping {
    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            AdhesionMapping::Jkr => "jkr",
        }
    }

    /// Parses a name (`jkr`).
    pub fn parse(text: &str) -> Result<AdhesionMapping> {
        match text.trim() {
            "jkr" => Ok(AdhesionMapping::Jkr),
            _ => Err(Error::InvalidValue {
                field: "adhesion mapping",
                expected: "jkr (LAMMPS pair granular jkr = brilliantov2007)",
            }),
        }
    }
}

/// Every number of a LAMMPS two-grain deck, from a scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LammpsMapping {
    /// LAMMPS `E` \[Pa\]: the scene's Young's modulus (LAMMPS mixes it to [`Self::e_star`]).
    pub youngs_modulus: f64,
    /// LAMMPS `ν`.
    pub poisson_ratio: f64,
    /// The contact modulus E* = E/(2(1−ν²)) \[Pa\].
    pub e_star: f64,
    /// LAMMPS `η_n0` of `damping viscoelastic` = 2E*A/m_eff \[1/(m s)\].
    pub eta_n0: f64,
    /// LAMMPS `jkr` surface energy γ = w/2 \[J/m²\] (`None`: `hertz/material`).
    pub jkr_gamma: Option<f64>,
    /// Whether the deck uses `limit_damping` (rime's `force_zero`).
    pub limit_damping: bool,
    /// The rime model the deck reproduces.
    pub model: Model,
    /// The JKR end the reference values use (`None` without adhesion).
    pub jkr_end: Option<JkrEnd>,
    /// LAMMPS's JKR pull-off force 3πγR_eff \[N\] (0 without adhesion).
    pub pull_off_force: f64,
    /// Separation beyond touching at which LAMMPS's JKR contact ends \[m\] (0 without adhesion).
    pub pull_off_separation: f64,
    /// m₁m₂/(m₁+m₂) \[kg\].
    pub m_eff: f64,
    /// R₁R₂/(R₁+R₂) \[m\].
    pub r_eff: f64,
    /// The damping time A \[s\].
    pub damping_time: f64,
    /// τ = `time_coefficient` · g^(−1/5) \[s\] (τ = ξ*/g).
    pub time_coefficient: f64,
    /// ξ* = `length_coefficient` · g^(4/5) \[m\].
    pub length_coefficient: f64,
    /// δ = `delta_coefficient` · g^(1/5).
    pub delta_coefficient: f64,
    /// Time steps per contact duration at weak damping ([`STEPS_PER_CONTACT`] or the JKR one).
    pub steps_per_contact: u32,
}

impl LammpsMapping {
    /// The mapping of `scene` (with its `contact`); `adhesion` is the mapping the user named for an
    /// adhesive scene.
    ///
    /// Errors: a soft layer (no equivalent), an adhesive scene without a named mapping, a mapping
    /// named for a scene without adhesion (each names the field).
    pub fn new(
        scene: &Scene,
        contact: &Contact,
        adhesion: Option<AdhesionMapping>,
    ) -> Result<LammpsMapping> {
        if scene.layer.is_some() {
            return Err(Error::InvalidValue {
                field: "layer",
                expected: "no soft layer: Eq. (8)–(10) have no LAMMPS pair granular equivalent",
            });
        }
        let (y, nu) = (scene.bulk.youngs_modulus, scene.bulk.poisson_ratio);
        let e_star = y / (2.0 * (1.0 - nu * nu));
        let eta_n0 = 2.0 * e_star * contact.damping_time / contact.m_eff;
        let (jkr_gamma, jkr_end, model) = match (scene.adhesion, adhesion) {
            (Some(a), Some(AdhesionMapping::Jkr)) => (
                Some(0.5 * a.surface_energy),
                Some(a.jkr_end),
                Model::Brilliantov2007,
            ),
            (Some(_), None) => {
                return Err(Error::InvalidValue {
                    field: "adhesion",
                    expected: "a named DEM mapping: the paper's energy-balance adhesion (Eq. (11)–(17)) \
                               has no LAMMPS equivalent; LAMMPS's jkr is brilliantov2007's JKR contact",
                });
            }
            (None, Some(_)) => {
                return Err(Error::InvalidValue {
                    field: "adhesion",
                    expected: "an adhesive scene for an adhesion mapping (this scene has no adhesion)",
                });
            }
            (None, None) => (None, None, Model::Hertzsch2002),
        };
        let (pull_off_force, pull_off_separation) = match jkr_gamma {
            Some(gamma) => (
                3.0 * core::f64::consts::PI * gamma * contact.r_eff,
                LAMMPS_JKR_SEPARATION_PREFIX
                    * powf(contact.r_eff * gamma * gamma / (e_star * e_star), 1.0 / 3.0),
            ),
            None => (0.0, 0.0),
        };
        let mapping = LammpsMapping {
            youngs_modulus: y,
            poisson_ratio: nu,
            e_star,
            eta_n0,
            jkr_gamma,
            limit_damping: jkr_gamma.is_none() && scene.contact_end == ContactEnd::ForceZero,
            model,
            jkr_end,
            pull_off_force,
            pull_off_separation,
            m_eff: contact.m_eff,
            r_eff: contact.r_eff,
            damping_time: contact.damping_time,
            time_coefficient: powf(contact.alpha, -0.4),
            length_coefficient: powf(contact.alpha, -0.4),
            delta_coefficient: contact.damping_time * powf(contact.alpha, 0.4),
            steps_per_contact: if jkr_gamma.is_some() {
                STEPS_PER_CONTACT_JKR
            } else {
                STEPS_PER_CONTACT
            },
        };
        if !(mapping.eta_n0.is_finite() && mapping.e_star > 0.0 && mapping.e_star.is_finite()) {
            return Err(Error::DerivedOutOfRange {
                quantity: "eta_n0",
                fields: "bulk.youngs_modulus, bulk.poisson_ratio, bulk.damping, grains",
            });
        }
        Ok(mapping)
    }

    /// τ = ξ*/g \[s\].
    pub fn time_scale(&self, g: f64) -> f64 {
        self.time_coefficient * powf(g, -0.2)
    }

    /// δ at impact speed `g` (docs/physics.md#decision-3).
    pub fn delta(&self, g: f64) -> f64 {
        self.delta_coefficient * powf(g, 0.2)
    }

    /// The elastic Hertz contact duration `HERTZ_CONTACT_TIME · τ` \[s\] (3.21806546 α^(−2/5) g^(−1/5)).
    pub fn hertz_duration(&self, g: f64) -> f64 {
        HERTZ_CONTACT_TIME * self.time_scale(g)
    }

    /// A bound of the maximum compression \[m\]: `ξ* min(x_H, δ^(−2/3))`. Damping only takes energy
    /// away (≤ the Hertz x_H), and integrating Eq. (4) once, `x' = 1 − δ x^(3/2) − ∫x^(3/2) ds ≤
    /// 1 − δ x^(3/2)`, so x stops growing before δ x^(3/2) = 1.
    pub fn compression_bound(&self, g: f64) -> f64 {
        let delta = self.delta(g);
        let x = if delta > 0.0 {
            HERTZ_MAX_COMPRESSION.min(powf(delta, -2.0 / 3.0))
        } else {
            HERTZ_MAX_COMPRESSION
        };
        x * self.length_coefficient * powf(g, 0.8)
    }

    /// The viscous relaxation rate `η_n0 a` at overlap `xi` \[m\], in units of 1/τ (`1.5 δ √x`).
    pub fn viscous_rate(&self, g: f64, xi: f64) -> f64 {
        self.eta_n0 * sqrt(self.r_eff * xi.max(0.0)) * self.time_scale(g)
    }

    /// The time step \[s\] at impact speed `g` and overlap `xi` \[m\] with `steps` per contact:
    /// `t_Hertz / (steps · max(1, η_n0 a τ · STEPS_PER_CONTACT / steps_per_contact))`: as many
    /// steps per viscous time η_n0 a as a Hertz deck takes per contact (a JKR deck's 16× finer
    /// step, set by its pull-off jump, resolves the viscous time 16× better already).
    pub fn time_step(&self, g: f64, xi: f64, steps: u32) -> f64 {
        let viscous = self.viscous_rate(g, xi) * f64::from(STEPS_PER_CONTACT)
            / f64::from(self.steps_per_contact);
        self.hertz_duration(g) / (f64::from(steps) * viscous.max(1.0))
    }

    /// The time step until the grains turn apart: [`Self::time_step`] at [`Self::compression_bound`].
    pub fn loading_time_step(&self, g: f64, steps: u32) -> f64 {
        self.time_step(g, self.compression_bound(g), steps)
    }

    /// The run-time guard \[s\]: [`RUN_TIME_FACTOR`] × a bound of rime's contact duration
    /// (τ (3.218 + [`ZERO_OVERLAP_DURATION_SLOPE`] δ) for zero overlap, the Hertz duration for force
    /// zero, whose contacts damping only shortens), or 200 Hertz durations for JKR (an adhesive
    /// contact may oscillate several times before it is caught).
    pub fn run_time(&self, g: f64) -> f64 {
        if self.jkr_gamma.is_some() {
            return 200.0 * self.hertz_duration(g);
        }
        let creep = if self.limit_damping {
            0.0
        } else {
            ZERO_OVERLAP_DURATION_SLOPE * self.delta(g)
        };
        RUN_TIME_FACTOR * self.time_scale(g) * (HERTZ_CONTACT_TIME + creep)
    }

    /// rime's values at `g` that the deck must reproduce, at `accuracy`.
    pub fn reference(
        &self,
        scene: &Scene,
        contact: &Contact,
        g: f64,
        accuracy: Accuracy,
    ) -> Result<Reference> {
        let (eps, status, t_c, xi_max) = match (self.jkr_gamma, self.jkr_end) {
            (Some(gamma), Some(end)) => {
                let dynamic =
                    crate::models::brilliantov2007::Dynamic::new(contact, 2.0 * gamma, end)?;
                let c = dynamic.collide(g, accuracy.integrator_rtol())?;
                let r = Evaluator::new(Model::Brilliantov2007, scene)?.eps(g, accuracy)?;
                (r.eps, r.status, c.t_c, c.xi_max)
            }
            _ => {
                let n = contact.normal(g, accuracy)?;
                (n.eps, ModelStatus::from(n.status), n.t_c, n.xi_max)
            }
        };
        Ok(Reference {
            g,
            eps,
            status,
            t_c,
            xi_max,
            time_step: self.loading_time_step(g, self.steps_per_contact),
            run_time: self.run_time(g),
        })
    }
}

/// rime's values at one speed, with the deck's loading time step and run-time guard there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reference {
    /// Impact speed \[m/s\].
    pub g: f64,
    /// ε_N (0 when stuck; the raw tiny value when overdamped).
    pub eps: f64,
    /// How the collision ends.
    pub status: ModelStatus,
    /// Contact duration \[s\] (infinite when unresolved or stuck).
    pub t_c: f64,
    /// Maximum compression \[m\].
    pub xi_max: f64,
    /// The deck's time step until the grains turn apart \[s\].
    pub time_step: f64,
    /// The deck's run-time guard \[s\].
    pub run_time: f64,
}

/// The status a deck prints when it stopped on the run-time guard, not on an end rule.
pub const STEP_LIMIT_STATUS: &str = "step_limit";

/// ε_N below which the deck, like rime, reports `overdamped`.
pub const DECK_OVERDAMPED_THRESHOLD: f64 = OVERDAMPED_THRESHOLD;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Preset;

    fn ice(a: f64, end: ContactEnd) -> (Scene, Contact) {
        let mut scene = Preset::Ice.scene();
        scene
            .set("bulk.damping.time", &alloc::format!("{a}"))
            .unwrap();
        scene.contact_end = end;
        let contact = Contact::new(&scene).unwrap();
        (scene, contact)
    }

    #[test]
    fn lammps_jkr_separation_prefix_is_the_cube_root() {
        let exact = libm::cbrt(3.0 * core::f64::consts::PI * core::f64::consts::PI / 16.0);
        assert!((LAMMPS_JKR_SEPARATION_PREFIX - exact).abs() < 1e-15);
    }

    #[test]
    fn hertz_duration_is_the_closed_form() {
        // 2 x_H ∫₀¹ du/√(1 − u^(5/2)) = 2 x_H √π Γ(7/5)/Γ(9/10), x_H = (5/4)^(2/5): the undamped
        // Hertz duration in units of τ, written out independently of the integrator.
        let x_h = libm::pow(1.25, 0.4);
        let s =
            2.0 * x_h * libm::sqrt(core::f64::consts::PI) * libm::tgamma(1.4) / libm::tgamma(0.9);
        assert!((s - HERTZ_CONTACT_TIME).abs() < 1e-14, "{s}");
        let (scene, contact) = ice(1e-4, ContactEnd::ForceZero);
        let m = LammpsMapping::new(&scene, &contact, None).unwrap();
        // The elastic limit of rime's own duration.
        let soft = {
            let (_, c) = ice(1e-12, ContactEnd::ForceZero);
            c.normal(1e-3, Accuracy::Precise).unwrap().t_c
        };
        assert!((m.hertz_duration(1e-3) / soft - 1.0).abs() < 1e-8);
    }

    #[test]
    fn eta_n0_gives_rimes_damping_force() {
        // LAMMPS: η_n0 m_eff a v; Eq. (4): 1.5 ρ_H A √ξ v with ρ_H = (4/3)E*√R.
        let (scene, contact) = ice(3e-4, ContactEnd::ForceZero);
        let m = LammpsMapping::new(&scene, &contact, None).unwrap();
        let xi = 1e-7;
        let lammps = m.eta_n0 * m.m_eff * sqrt(m.r_eff * xi);
        let rime = 1.5 * contact.rho_h * contact.damping_time * sqrt(xi);
        assert!((lammps / rime - 1.0).abs() < 1e-14);
        // ρ_H = (4/3) E* √R: E* is LAMMPS's mixed modulus.
        assert!((contact.rho_h / (4.0 / 3.0 * m.e_star * sqrt(m.r_eff)) - 1.0).abs() < 1e-14);
        // 1.5 δ √x = η_n0 a τ.
        let g = 2e-3;
        let x = xi / contact.length_scale(g);
        assert!((m.viscous_rate(g, xi) / (1.5 * contact.delta(g) * sqrt(x)) - 1.0).abs() < 1e-13);
    }

    #[test]
    fn adhesion_needs_a_named_mapping() {
        let scene = Preset::IceSticky.scene();
        let contact = Contact::new(&scene).unwrap();
        let e = LammpsMapping::new(&scene, &contact, None).unwrap_err();
        assert!(alloc::format!("{e}").starts_with("adhesion:"), "{e}");
        let m = LammpsMapping::new(&scene, &contact, Some(AdhesionMapping::Jkr)).unwrap();
        let w = scene.adhesion.unwrap().surface_energy;
        assert_eq!(m.jkr_gamma, Some(0.5 * w));
        assert_eq!(m.model, Model::Brilliantov2007);
        let (plain, c) = ice(1e-4, ContactEnd::ForceZero);
        assert!(LammpsMapping::new(&plain, &c, Some(AdhesionMapping::Jkr)).is_err());
        assert!(AdhesionMapping::parse("dmt").is_err());
    }

    #[test]
    fn issue_35_compression_bound_holds_at_any_damping() {
        // rime's ξ_max never exceeds the bound (and the bound is tight for strong damping,
        // where δ^(2/3) x_max → 1), for both end rules from δ ~ 1e-3 to 1e9.
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            for a in [1e-6, 1e-4, 1e-3, 1e-2, 0.1, 1.0, 404.44, 1e5] {
                let (scene, contact) = ice(a, end);
                let m = LammpsMapping::new(&scene, &contact, None).unwrap();
                for g in [1e-5, 1e-3, 0.1, 10.0] {
                    let n = contact.normal(g, Accuracy::Precise).unwrap();
                    let bound = m.compression_bound(g);
                    assert!(
                        n.xi_max <= bound * (1.0 + 1e-10),
                        "A {a} g {g}: {n:?} vs {bound}"
                    );
                    // x_max δ^(2/3) = 1 − O(δ^(−5/3) ln δ): 1.1e-6 low at δ = 1.2e4.
                    if contact.delta(g) > 1e4 {
                        assert!(
                            n.xi_max > bound * (1.0 - 1e-5),
                            "A {a} g {g}: {n:?} vs {bound}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn issue_35_run_time_covers_rimes_duration_at_any_damping() {
        // The deck's guard is at least twice rime's integrated duration wherever rime resolves it
        // (zero overlap up to δ ≈ 58.9; force zero everywhere), so a deck never stops on the guard
        // where rime's contact ends; and the loading step resolves the viscous rate at rime's ξ_max
        // (η_n0 a dt ≤ HERTZ_CONTACT_TIME/steps: as many steps per viscous time as per Hertz
        // duration at weak damping).
        let mut worst_slope = 0.0f64;
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            let mut u = -3.0;
            while u <= 9.0 {
                let delta = powf(10.0, u);
                // δ = A α^(2/5) g^(1/5) at g = 1e-3: choose A for this δ.
                let (_, probe) = ice(1e-4, end);
                let a = delta / (powf(probe.alpha, 0.4) * powf(1e-3, 0.2));
                let (scene, contact) = ice(a, end);
                let m = LammpsMapping::new(&scene, &contact, None).unwrap();
                let g = 1e-3;
                let n = contact.normal(g, Accuracy::Precise).unwrap();
                if n.t_c.is_finite() {
                    assert!(
                        m.run_time(g) >= 2.0 * n.t_c,
                        "{end:?} δ = {delta:e}: guard {} vs t_c {}",
                        m.run_time(g),
                        n.t_c
                    );
                    if end == ContactEnd::ZeroOverlap {
                        worst_slope =
                            worst_slope.max((n.t_c / m.time_scale(g) - HERTZ_CONTACT_TIME) / delta);
                    }
                } else {
                    assert_eq!(ModelStatus::from(n.status), ModelStatus::Overdamped);
                }
                let dt = m.loading_time_step(g, STEPS_PER_CONTACT);
                let rate_per_second = m.viscous_rate(g, n.xi_max) / m.time_scale(g);
                assert!(
                    rate_per_second * dt
                        <= HERTZ_CONTACT_TIME / f64::from(STEPS_PER_CONTACT) * (1.0 + 1e-12),
                    "{end:?} δ = {delta:e}: η_n0 a dt = {}",
                    rate_per_second * dt
                );
                u += 0.0917;
            }
        }
        std::println!("zero overlap: worst (s_c − 3.218)/δ = {worst_slope}");
        assert!(worst_slope < ZERO_OVERLAP_DURATION_SLOPE);
    }
}
