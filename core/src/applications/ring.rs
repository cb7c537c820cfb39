//! What the collision law does to a ring: the equilibrium velocity dispersion of a non-gravitating
//! ring patch of identical grains (docs/physics.md#ring).
//!
//! Viscous heating by Kepler shear is balanced against the collisional loss (Goldreich & Tremaine
//! 1978, Icarus 34, 227). We use a moment closure of the dilute shearing sheet in which collisions
//! relax the velocity ellipsoid to isotropy at Grad's stress-relaxation rate of inelastic hard
//! spheres, `ν = (4/5)·((1 + ε)(3 − ε)/4)·ω_c`, and remove energy isotropically at
//! `ζ = (1 − ε²) ω_c/3` (docs/physics.md#ring). With `ν̂ = ν/Ω = b ω̂` and `ω̂ = ω_c/Ω`:
//!
//! * viscous gain per unit mass `(9/4) Ω² c² ν̂/(ν̂² + 11/2)`,
//! * collisional loss per unit mass `ω_c (1 − ε̄²) c²/2`,
//!
//! so a constant ε balances only at `1 − ε_cr² = (9/2) b/(b² ω̂² + 11/2)`, `b = (1 + ε_cr)(3 − ε_cr)/5`,
//! with the collision frequency `ω̂ = (8τ/π)·Y(φ)` of a Gaussian layer (dilute limit `ε_cr = 14/23`,
//! Goldreich & Tremaine's ≈ 0.63). A speed-dependent ε_N(g) balances where the energy-weighted mean
//! `ε̄²` over the impacts equals `ε_cr²`. Impacts: the normal relative speed of a 3-D Gaussian
//! relative velocity (dispersion √2 c per component) weighted by the collision rate `∝ g_N`, i.e.
//! Rayleigh-distributed with scale √2 c; the tangential speed is the independent 2-D Gaussian
//! magnitude (same scale), grain spins neglected.

use crate::applications::tidal::G;
use crate::error::{Error, Result, positive, within};
use crate::numerics::accuracy::Accuracy;
use crate::numerics::math::{exp, ln, sqrt};
use crate::scene::Scene;
use crate::scene::contact::Contact;
use core::f64::consts::PI;

/// The monolayer floor of the dispersion, in units of `RΩ`: the non-local (finite-size) viscous
/// gain keeps `c ≥ 2–3 RΩ` even for very inelastic grains (Morgado et al. 2023, Extended Data
/// Fig. 4 caption); we take the lower end.
pub const FLOOR_IN_R_OMEGA: f64 = 2.0;
/// Mean impact speed above which the balance lies outside the slow-collision regime \[m/s\].
pub const SLOW_REGIME_LIMIT: f64 = 1.0;
/// Dispersion, in `RΩ`, above which a ring that takes long to get there is called heating.
pub const HOT_IN_R_OMEGA: f64 = 10.0;
/// Equilibration time \[orbits\] beyond which a hot balance (c > 10 RΩ) is called heating.
pub const SLOW_EQUILIBRATION_ORBITS: f64 = 300.0;
/// Fraction of sticking impacts at or above which the ring aggregates.
pub const AGGREGATE_FRACTION: f64 = 0.5;

/// Where the ring is: the orbital frequency, given directly or from a planet.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Orbit {
    /// Orbital (Kepler) frequency Ω \[1/s\].
    Omega(f64),
    /// A planet of mass \[kg\] and a distance from its centre \[m\]: `Ω = √(GM/d³)` with the `G` of
    /// [`crate::applications::tidal`].
    Planet {
        /// Planet mass \[kg\].
        planet_mass: f64,
        /// Distance from the planet's centre \[m\].
        distance: f64,
    },
}

impl Orbit {
    /// Ω \[1/s\]: as given, or `√(GM/d³)`; errors name `omega`, `planet_mass` or `distance`.
    pub fn omega(self) -> Result<f64> {
        match self {
            Orbit::Omega(o) => positive("omega", o),
            Orbit::Planet {
                planet_mass,
                distance,
            } => {
                let m = positive("planet_mass", planet_mass)?;
                let d = positive("distance", distance)?;
                positive("omega", sqrt(G * m / d / d / d))
            }
        }
    }

    /// The tidal appendix's planet and distance (the explorer's tidal card), as an orbit.
    pub fn of_tidal(input: &crate::applications::tidal::TidalInput) -> Orbit {
        Orbit::Planet {
            planet_mass: input.planet_mass,
            distance: input.distance,
        }
    }
}

/// Inputs of [`equilibrium`]. The grains are the scene's (both of one radius).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RingInput {
    /// Normal optical depth τ \[1\] (> 0, ≤ 5).
    pub tau: f64,
    /// Orbital frequency.
    pub orbit: Orbit,
    /// The radius the scene's damping time `A` was chosen for \[m\], when different from the grains':
    /// only reported ([`RingRecord::scaled_damping_time`]). `None`: the grains' radius.
    pub damping_set_for_radius: Option<f64>,
}

/// One prediction (smooth or rough grains).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Prediction {
    /// One-dimensional velocity dispersion `c = √(⟨|v − v_shear|²⟩/3)` \[m/s\].
    pub velocity_dispersion: f64,
    /// Root mean square of z, `c_z/Ω` \[m\].
    pub thickness: f64,
    /// Mean normal impact speed `√π c` \[m/s\].
    pub mean_impact_speed: f64,
    /// Effective restitution `ε̄ = √(1 − loss/((m/4)⟨g_N²⟩))` of the impacts at this dispersion.
    pub eps_effective: f64,
    /// Fraction of impacts (collision-rate weighted) that stick.
    pub sticking_fraction: f64,
    /// Orbits to heat from the monolayer floor to 90 % of the equilibrium dispersion (0 at the floor).
    pub equilibration_orbits: f64,
    /// The verdict.
    pub verdict: Verdict,
    /// ε_cr at this dispersion, with the Enskog-enhanced collision frequency.
    pub eps_cr: f64,
    /// Collision frequency per orbital frequency, `ω_c/Ω = (8τ/π)·Y(φ)`.
    pub collision_frequency: f64,
    /// Volume filling factor φ of the layer, `2τR/(3√π H)`.
    pub filling_factor: f64,
}

/// What the ring does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Verdict {
    /// Gain and loss balance in the slow-collision regime, above the monolayer floor.
    Equilibrium,
    /// Even the slowest impacts lose more than the local gain: the ring flattens to `c ≈ 2 RΩ`.
    MonolayerFloor,
    /// Most impacts at the balance stick: the ring clumps.
    Aggregates,
    /// The balance lies outside the slow-collision regime (see [`SLOW_REGIME_LIMIT`]).
    Heats,
}

impl Verdict {
    /// The snake_case name used in JSON and CSV.
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Equilibrium => "equilibrium",
            Verdict::MonolayerFloor => "monolayer_floor",
            Verdict::Aggregates => "aggregates",
            Verdict::Heats => "heats",
        }
    }

    /// Whether the ring settles in a steady state of the slow-collision regime: a local balance
    /// ([`Verdict::Equilibrium`]) or the monolayer floor, where the finite-size (non-local) gain
    /// balances the loss ([`Verdict::MonolayerFloor`]).
    pub fn is_equilibrium(self) -> bool {
        matches!(self, Verdict::Equilibrium | Verdict::MonolayerFloor)
    }

    /// The verdict in words, as `rime ring` and the ring cards print it: `equilibrium`,
    /// `equilibrium at the monolayer floor`, `aggregates`, `heats`.
    pub fn words(self) -> &'static str {
        match self {
            Verdict::Equilibrium => "equilibrium",
            Verdict::MonolayerFloor => "equilibrium at the monolayer floor",
            Verdict::Aggregates => "aggregates",
            Verdict::Heats => "heats",
        }
    }
}

/// The record of [`equilibrium`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RingRecord {
    /// Optical depth τ.
    pub tau: f64,
    /// Orbital frequency Ω \[1/s\].
    pub omega: f64,
    /// Grain radius R \[m\].
    pub radius: f64,
    /// Critical restitution of the dilute closure, ε_cr(τ) ([`eps_cr`]).
    pub eps_cr: f64,
    /// Dilute collision frequency per orbital frequency, `ω_c/Ω = 8τ/π`.
    pub collision_frequency: f64,
    /// The monolayer floor `2RΩ` \[m/s\].
    pub floor_dispersion: f64,
    /// Smooth grains: the normal restitution only.
    pub smooth: Prediction,
    /// Rough grains: normal and tangential losses (equal to `smooth` without friction).
    pub rough: Prediction,
    /// Whether the scene has friction (then `rough` is the ring's prediction).
    pub friction: bool,
    /// The scene's damping time A \[s\].
    pub damping_time: f64,
    /// `A′ = A·R/R_set`: the damping time grains of this radius need to keep the ε_N(g) of the
    /// `R_set` grains A was set for. A different material. `None` when A was set for this radius.
    pub scaled_damping_time: Option<f64>,
    /// The radius A was set for \[m\] (when it differs).
    pub damping_set_for_radius: Option<f64>,
}

impl RingRecord {
    /// The prediction that applies to the scene (rough with friction, smooth without).
    pub fn prediction(&self) -> &Prediction {
        if self.friction {
            &self.rough
        } else {
            &self.smooth
        }
    }
}

/// The dilute `ε_cr(τ)`: the root of `1 − ε² = (9/2) b/(b² ω̂² + 11/2)`, `b = (1 + ε)(3 − ε)/5`,
/// `ω̂ = 8τ/π` (docs/physics.md#ring; 14/23 for τ → 0). Fails for τ outside (0, 5].
pub fn eps_cr(tau: f64) -> Result<f64> {
    let tau = within("tau", tau, f64::MIN_POSITIVE, 5.0, "must lie in (0, 5]")?;
    Ok(eps_cr_of(collision_frequency(tau)))
}

/// Grad's stress-relaxation rate of inelastic hard spheres per collision frequency,
/// `ν/ω_c = (4/5)·(1 + ε)(3 − ε)/4` (4/5 for elastic spheres: `p/η` of the Chapman–Enskog
/// viscosity over `ω_c`).
pub fn relaxation_per_collision(eps: f64) -> f64 {
    (1.0 + eps) * (3.0 - eps) / 5.0
}

/// `ε_cr` for a collision frequency `ω̂ = ω_c/Ω ≥ 0`: the root in [0, 1] of
/// `1 − ε² − (9/2) b/(b² ω̂² + 11/2)` (positive at 0, negative at 1), by bisection to 1e-16.
pub fn eps_cr_of(w: f64) -> f64 {
    let excess = |e: f64| {
        let b = relaxation_per_collision(e);
        1.0 - e * e - 4.5 * b / (b * b * w * w + 5.5)
    };
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for _ in 0..56 {
        let mid = 0.5 * (lo + hi);
        if excess(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Volume filling factor `φ = 2τR/(3√π H)` of a Gaussian layer of rms thickness `H = c_z/Ω`
/// (the density-weighted mean of n(z)·(4/3)πR³), capped at 0.5.
pub fn filling_factor(tau: f64, c: f64, omega: f64, radius: f64) -> f64 {
    let h = c * vertical_fraction(collision_frequency(tau)) / omega;
    (2.0 * tau * radius / (3.0 * sqrt(PI) * h)).min(0.5)
}

/// `ω_c/Ω = (8τ/π)·Y(φ)` with the Carnahan–Starling contact factor `Y = (1 − φ/2)/(1 − φ)³`
/// (Enskog): collisions are more frequent in a dense layer.
pub fn dense_collision_frequency(tau: f64, c: f64, omega: f64, radius: f64) -> f64 {
    let phi = filling_factor(tau, c, omega, radius);
    let q = 1.0 - phi;
    collision_frequency(tau) * (1.0 - 0.5 * phi) / (q * q * q)
}

/// `ω_c/Ω = 8τ/π`: the dilute collision frequency of a Gaussian layer of 1-D dispersion c.
pub fn collision_frequency(tau: f64) -> f64 {
    8.0 * tau / PI
}

/// `A′ = A·R′/R`: the damping time a grain of radius `r_new` needs to keep the ε_N(g) of grains of
/// radius `r` with damping time `a` (δ ∝ A α^(2/5), α^(2/5) ∝ 1/R). **A′ describes a different
/// material**: A is a material constant.
pub fn scaled_damping_time(a: f64, r: f64, r_new: f64) -> Result<f64> {
    let a = positive("damping_time", a)?;
    let r = positive("radius", r)?;
    let r_new = positive("new_radius", r_new)?;
    Ok(a * (r_new / r))
}

/// A ring patch of one grain size: the scene with both grains of `radius` (the scene's when
/// `None`) and the input of [`equilibrium`]. The damping time A is kept (a material constant, so
/// ε_N(g) changes with the size) unless `scale_damping` asks for `A′ = A·R/R_set`
/// ([`scaled_damping_time`]: the set grains' ε_N(g), a different material).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RingPatch {
    /// The patch's scene.
    pub scene: Scene,
    /// The input of [`equilibrium`].
    pub input: RingInput,
    /// The radius the scene's A was set for \[m\] (the scene's grain radius).
    pub set_for: f64,
    /// Whether A was scaled.
    pub scaled: bool,
}

impl RingPatch {
    /// The patch of `scene`'s grains at `radius` (fails, naming `scale_damping`, when A is to be
    /// scaled to the radius it was set for).
    pub fn new(
        scene: &Scene,
        tau: f64,
        orbit: Orbit,
        radius: Option<f64>,
        scale_damping: bool,
    ) -> Result<RingPatch> {
        Self::with_damping_set_for(
            scene,
            tau,
            orbit,
            radius,
            scale_damping,
            scene.grains.radius_1,
        )
    }

    /// [`RingPatch::new`] when the scene's A was set for grains of radius `set_for` \[m\] rather
    /// than for the scene's own grains: e.g. `rime ring --radius 1 --set bulk.damping.time=5e-3`
    /// gives A for the 1 m grains of the patch, so `set_for` is 1 m and nothing is scaled or noted.
    pub fn with_damping_set_for(
        scene: &Scene,
        tau: f64,
        orbit: Orbit,
        radius: Option<f64>,
        scale_damping: bool,
        set_for: f64,
    ) -> Result<RingPatch> {
        let set_for = crate::error::positive("set_for", set_for)?;
        let mut scene = *scene;
        if let Some(r) = radius {
            scene.grains.radius_1 = r;
            scene.grains.radius_2 = r;
        }
        let r = scene.grains.radius_1;
        if scale_damping {
            if r == set_for {
                return Err(Error::InvalidValue {
                    field: "scale_damping",
                    expected: "a radius other than the scene's (A is scaled to a new grain size)",
                });
            }
            let a = scaled_damping_time(scene.damping_time(), set_for, r)?;
            scene.bulk.damping = crate::scene::Damping::Time(a);
        }
        Ok(RingPatch {
            scene,
            input: RingInput {
                tau,
                orbit,
                damping_set_for_radius: (r != set_for && !scale_damping).then_some(set_for),
            },
            set_for,
            scaled: scale_damping,
        })
    }

    /// What A describes in the patch `rec` was computed for, when the grains are not the ones A
    /// was set for; `flag` names the surface's switch that scales A (`--scale-damping`,
    /// `scale_damping=True`).
    #[cfg(feature = "alloc")]
    pub fn damping_note(&self, rec: &RingRecord, flag: &str) -> Option<alloc::string::String> {
        use crate::format::shortest as num;
        if self.scaled {
            Some(alloc::format!(
                "A scaled to {} s = A·R/R_set for R = {} m (A was set for {} m grains): this keeps \
                 ε_N(g) of the {} m grains and describes a different material",
                num(rec.damping_time),
                num(rec.radius),
                num(self.set_for),
                num(self.set_for)
            ))
        } else {
            rec.scaled_damping_time.map(|a2| {
                alloc::format!(
                    "the scene's A = {} s was set for {} m grains; grains of {} m keep that ε_N(g) \
                     with A' = {} s ({flag}), a different material",
                    num(rec.damping_time),
                    num(self.set_for),
                    num(rec.radius),
                    num(a2)
                )
            })
        }
    }
}

/// The vertical to 1-D dispersion ratio of the closure at the balance, `c_z²/c² = 1 − ζ/ν =
/// 1 − (3/2)/(ν̂² + 11/2)` with `ν̂ = b(ε_cr) ω̂`.
pub(crate) fn vertical_fraction(w: f64) -> f64 {
    let nu = relaxation_per_collision(eps_cr_of(w)) * w;
    sqrt(1.0 - 1.5 / (nu * nu + 5.5))
}

// Simpson nodes in x = g/s for the Rayleigh impact distributions, on [0, X_MAX].
pub(crate) const X_MAX: f64 = 8.0;
pub(crate) const N_NORMAL: usize = 96;
pub(crate) const N_TANGENTIAL: usize = 48;

pub(crate) fn simpson_weight(i: usize, n: usize) -> f64 {
    if i == 0 || i == n {
        1.0
    } else if i % 2 == 1 {
        4.0
    } else {
        2.0
    }
}

/// Loss average at dispersion `c`: returns (1 − ε̄², sticking fraction), smooth or rough.
fn loss(contact: &Contact, c: f64, rough: bool) -> Result<(f64, f64)> {
    let s = core::f64::consts::SQRT_2 * c;
    let average = pair_average(contact, s, rough, "tau, omega, radius")?;
    Ok((average.loss, average.sticking))
}

/// Impact averages of one pair at relative dispersion `s` per component.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct PairAverage {
    /// `1 − ε̄²`: energy-weighted loss fraction, normal and (rough) tangential.
    pub(crate) loss: f64,
    /// `⟨(1 + ε_N) g_N²⟩/⟨g_N²⟩ + κ⟨(1 + ε_T) g_T²⟩/⟨g_T²⟩`: the momentum-exchange weight.
    pub(crate) exchange: f64,
    /// Rate-weighted fraction of sticking impacts.
    pub(crate) sticking: f64,
}

/// The impact averages of a pair whose normal impact speed is Rayleigh with scale `s` per component
/// (`s = √2 c` for one size; a ring of many sizes, `crate::applications::ring_sizes`, passes each pair's):
/// the one place the loss, exchange and sticking averages are integrated (Simpson nodes in
/// `x = g/s`). `fields` names the inputs an error blames.
pub(crate) fn pair_average(
    contact: &Contact,
    s: f64,
    rough: bool,
    fields: &'static str,
) -> Result<PairAverage> {
    let h = X_MAX / N_NORMAL as f64;
    let ht = X_MAX / N_TANGENTIAL as f64;
    let kappa = if rough {
        contact
            .friction
            .ok_or(Error::InvalidValue {
                field: "friction",
                expected: "a friction model (the scene has none)",
            })?
            .kappa
    } else {
        0.0
    };
    let (mut num, mut den, mut stuck, mut rate, mut exch) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for i in 0..=N_NORMAL {
        let x = i as f64 * h;
        let w = simpson_weight(i, N_NORMAL) * x * exp(-0.5 * x * x);
        if w == 0.0 {
            continue;
        }
        let g_n = s * x;
        let eps_n = contact.eps_n(g_n, Accuracy::Fast)?;
        rate += w;
        if eps_n == 0.0 {
            stuck += w;
        }
        den += w * x * x;
        num += w * x * x * (1.0 - eps_n * eps_n);
        exch += w * x * x * (1.0 + eps_n);
        if rough {
            let (mut tangential, mut t_exch) = (0.0, 0.0);
            for j in 0..=N_TANGENTIAL {
                let y = j as f64 * ht;
                let wt = simpson_weight(j, N_TANGENTIAL) * y * exp(-0.5 * y * y);
                if wt == 0.0 {
                    continue;
                }
                let eps_t = contact.tangential(g_n, s * y, Accuracy::Fast)?.eps_t;
                tangential += wt * y * y * (1.0 - eps_t * eps_t);
                t_exch += wt * y * y * (1.0 + eps_t);
            }
            num += w * kappa * tangential * ht / 3.0;
            // ⟨g_T²⟩ of the 2-D Rayleigh law is 2 s², i.e. 2 in units of s² (Simpson: ht/3).
            exch += w * x * x * kappa * t_exch * ht / 3.0 / 2.0;
        }
    }
    if !(den > 0.0) {
        return Err(Error::DerivedOutOfRange {
            quantity: "impact average",
            fields,
        });
    }
    Ok(PairAverage {
        loss: num / den,
        exchange: exch / den,
        sticking: stuck / rate,
    })
}

/// `ε̄` and the sticking fraction at dispersion `c` \[m/s\] for smooth (`rough = false`) or rough
/// grains. Fails when `rough` and the scene has no friction.
pub fn effective_restitution(contact: &Contact, c: f64, rough: bool) -> Result<(f64, f64)> {
    let c = within(
        "velocity_dispersion",
        c,
        f64::MIN_POSITIVE,
        1e5,
        "must lie in (0, 1e5] m/s",
    )?;
    let (l, stick) = loss(contact, c, rough)?;
    Ok((sqrt((1.0 - l).max(0.0)), stick))
}

fn predict(
    contact: &Contact,
    rough: bool,
    tau: f64,
    omega: f64,
    floor: f64,
    radius: f64,
) -> Result<Prediction> {
    let excess = |c: f64| -> Result<f64> {
        let w = dense_collision_frequency(tau, c, omega, radius);
        Ok(1.0 - loss(contact, c, rough)?.0 - eps_cr_of(w) * eps_cr_of(w))
    };
    let c_max = 1e3;
    let at_floor = excess(floor)?;
    let c = if at_floor <= 0.0 {
        floor
    } else if excess(c_max)? > 0.0 {
        c_max
    } else {
        // Bisection in ln c: ε̄² falls with c for a viscoelastic law but need not be monotonic with
        // a layer or adhesion; this finds a crossing.
        let (mut lo, mut hi) = (ln(floor), ln(c_max));
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if excess(exp(mid))? > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        exp(0.5 * (lo + hi))
    };
    let (l, sticking_fraction) = loss(contact, c, rough)?;
    // d ln c/dt = (ω_c/6)(ε̄² − ε_cr²): time from the floor to 0.9 c (midpoint rule in ln c).
    let equilibration_orbits = if c > floor * (1.0 / 0.9) {
        let steps = 40;
        let (a, b) = (ln(floor), ln(0.9 * c));
        let dl = (b - a) / steps as f64;
        let mut t = 0.0;
        for k in 0..steps {
            let ck = exp(a + (k as f64 + 0.5) * dl);
            let wk = dense_collision_frequency(tau, ck, omega, radius);
            let rate = wk * omega / 6.0 * excess(ck)?;
            t += dl / rate.max(f64::MIN_POSITIVE);
        }
        t * omega / (2.0 * PI)
    } else {
        0.0
    };
    let mean_impact_speed = sqrt(PI) * c;
    let w = dense_collision_frequency(tau, c, omega, radius);
    let verdict = if sticking_fraction >= AGGREGATE_FRACTION {
        Verdict::Aggregates
    } else if c >= c_max
        || mean_impact_speed > SLOW_REGIME_LIMIT
        || (c > HOT_IN_R_OMEGA * radius * omega && equilibration_orbits > SLOW_EQUILIBRATION_ORBITS)
    {
        Verdict::Heats
    } else if c <= floor {
        Verdict::MonolayerFloor
    } else {
        Verdict::Equilibrium
    };
    Ok(Prediction {
        velocity_dispersion: c,
        thickness: c * vertical_fraction(w) / omega,
        mean_impact_speed,
        eps_effective: sqrt((1.0 - l).max(0.0)),
        sticking_fraction,
        equilibration_orbits,
        verdict,
        eps_cr: eps_cr_of(w),
        collision_frequency: w,
        filling_factor: filling_factor(tau, c, omega, radius),
    })
}

/// The ring's equilibrium for `scene` (grains of equal radius; the scene is validated).
///
/// Errors name the field: `tau`, `omega`, `planet_mass`, `distance`, `grains.radius_2` (the radii
/// must be equal), `damping_set_for_radius`, or any scene field.
pub fn equilibrium(scene: &Scene, input: &RingInput) -> Result<RingRecord> {
    let tau = within(
        "tau",
        input.tau,
        f64::MIN_POSITIVE,
        5.0,
        "must lie in (0, 5]",
    )?;
    let omega = input.orbit.omega()?;
    let radius = scene.grains.radius_1;
    if scene.grains.radius_2 != radius {
        return Err(Error::InvalidValue {
            field: "grains.radius_2",
            expected: "equal to grains.radius_1 (a ring of identical grains)",
        });
    }
    let contact = Contact::new(scene)?;
    let w = collision_frequency(tau);
    let eps_cr = eps_cr(tau)?;
    let floor = positive("radius", FLOOR_IN_R_OMEGA * radius * omega)?;
    let smooth = predict(&contact, false, tau, omega, floor, radius)?;
    let friction = scene.friction.is_some();
    let rough = if friction {
        predict(&contact, true, tau, omega, floor, radius)?
    } else {
        smooth
    };
    let damping_time = scene.damping_time();
    let (scaled, set_for) = match input.damping_set_for_radius {
        Some(r_set) if r_set != radius => {
            let r_set = positive("damping_set_for_radius", r_set)?;
            (
                Some(scaled_damping_time(damping_time, r_set, radius)?),
                Some(r_set),
            )
        }
        _ => (None, None),
    };
    Ok(RingRecord {
        tau,
        omega,
        radius,
        eps_cr,
        collision_frequency: w,
        floor_dispersion: floor,
        smooth,
        rough,
        friction,
        damping_time,
        scaled_damping_time: scaled,
        damping_set_for_radius: set_for,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Damping, Preset};

    /// The patch both surfaces build (`rime ring`, `rime_grains.ring`): A kept or scaled by R/R_set
    /// (closed form), and the refusal to scale A to the radius it was set for.
    #[test]
    fn a_patch_keeps_or_scales_a_and_says_which() {
        let ice = Preset::Ice.scene();
        let orbit = Orbit::Omega(1.3e-4);
        let kept = RingPatch::new(&ice, 0.5, orbit, Some(1.0), false).unwrap();
        assert_eq!(kept.scene.damping_time(), ice.damping_time());
        assert_eq!(kept.input.damping_set_for_radius, Some(0.02));
        let scaled = RingPatch::new(&ice, 0.5, orbit, Some(1.0), true).unwrap();
        let a = scaled.scene.damping_time();
        assert!((a / ice.damping_time() - 1.0 / 0.02).abs() < 1e-12, "{a}");
        assert_eq!(scaled.input.damping_set_for_radius, None);
        let e = RingPatch::new(&ice, 0.5, orbit, None, true).unwrap_err();
        assert!(alloc::format!("{e}").starts_with("scale_damping:"), "{e}");
        let rec = equilibrium(&kept.scene, &kept.input).unwrap();
        let note = kept.damping_note(&rec, "--flag").unwrap();
        assert!(
            note.contains("(--flag)") && note.contains("different material"),
            "{note}"
        );
        let rec = equilibrium(&scaled.scene, &scaled.input).unwrap();
        assert!(
            scaled
                .damping_note(&rec, "--flag")
                .unwrap()
                .starts_with("A scaled to 0.005 s")
        );
        let same = RingPatch::new(&ice, 0.5, orbit, None, false).unwrap();
        let rec = equilibrium(&same.scene, &same.input).unwrap();
        assert_eq!(same.damping_note(&rec, "--flag"), None);
    }

    /// A given for the patch's own grains (issue 35): no note, the same record as a scene whose
    /// grains are that size, and nothing to scale.
    #[test]
    fn issue_35_a_set_for_the_patch_grains_is_not_noted() {
        let mut ice = Preset::Ice.scene();
        ice.bulk.damping = Damping::Time(5e-3);
        let orbit = Orbit::Omega(1.3e-4);
        let given =
            RingPatch::with_damping_set_for(&ice, 0.5, orbit, Some(1.0), false, 1.0).unwrap();
        assert_eq!(given.input.damping_set_for_radius, None);
        let rec = equilibrium(&given.scene, &given.input).unwrap();
        assert_eq!(rec.scaled_damping_time, None);
        assert_eq!(given.damping_note(&rec, "--flag"), None);
        // The same as a scene of 1 m grains with that A, asked about its own grains.
        let mut metre = ice;
        (metre.grains.radius_1, metre.grains.radius_2) = (1.0, 1.0);
        let own = RingPatch::new(&metre, 0.5, orbit, None, false).unwrap();
        assert_eq!(equilibrium(&own.scene, &own.input).unwrap(), rec);
        let e =
            RingPatch::with_damping_set_for(&ice, 0.5, orbit, Some(1.0), true, 1.0).unwrap_err();
        assert!(alloc::format!("{e}").starts_with("scale_damping:"), "{e}");
    }

    const SATURN_A_RING_OMEGA: f64 = 1.3143527e-4;

    fn ice(radius: f64) -> Scene {
        let mut scene = Preset::Ice.scene();
        scene.grains.radius_1 = radius;
        scene.grains.radius_2 = radius;
        scene
    }

    fn input(tau: f64) -> RingInput {
        RingInput {
            tau,
            orbit: Orbit::Omega(SATURN_A_RING_OMEGA),
            damping_set_for_radius: Some(0.02),
        }
    }

    #[test]
    fn eps_cr_matches_its_closed_form_limits() {
        // τ → 0: ω̂ → 0, 1 − ε² = (9/11)(1 + ε)(3 − ε)/5, i.e. 23ε² + 9ε − 14 = 0: ε = 14/23.
        let small = eps_cr(1e-9).unwrap();
        assert!((small - 14.0 / 23.0).abs() < 1e-9, "{small}");
        // ω̂ = 1 (τ = π/8) and τ = 0.5: roots in (0, 1) of the degree-6 polynomial
        // (1 − ε²)(b²ω̂² + 11/2) − (9/2)b by numpy.polynomial (an independent root finder).
        let one = eps_cr(PI / 8.0).unwrap();
        assert!((one - 0.6539967624924253).abs() < 1e-13, "{one}");
        let half = eps_cr(0.5).unwrap();
        assert!((half - 0.6776695285906746).abs() < 1e-13, "{half}");
        // Elastic spheres relax at p/η = (4/5) ω_c.
        assert_eq!(relaxation_per_collision(1.0), 0.8);
        // Monotonic increasing, below 1.
        let (a, b) = (eps_cr(0.1).unwrap(), eps_cr(1.0).unwrap());
        assert!(a < b && b < 1.0);
        assert!(matches!(
            eps_cr(0.0),
            Err(Error::OutOfRange { field: "tau", .. })
        ));
        assert!(matches!(
            eps_cr(f64::NAN),
            Err(Error::OutOfRange { field: "tau", .. })
        ));
    }

    #[test]
    fn the_impact_average_matches_an_independent_quadrature() {
        // ⟨ε_N² g_N²⟩/⟨g_N²⟩ over the Rayleigh(√2 c) law, here by the trapezoid rule in t = x²/2
        // (density of t for the g²-weighted law: t e^{−t}), 20000 steps to t = 40.
        let contact = Contact::new(&ice(0.02)).unwrap();
        for c in [3e-6, 3e-5, 3e-4, 3e-2] {
            let s = core::f64::consts::SQRT_2 * c;
            let (n, t_max) = (20_000, 40.0);
            let dt = t_max / n as f64;
            let mut sum = 0.0;
            for k in 0..=n {
                let t = k as f64 * dt;
                let g = s * (2.0 * t).sqrt();
                let e = contact.eps_n(g, Accuracy::Fast).unwrap();
                let w = if k == 0 || k == n { 0.5 } else { 1.0 };
                sum += w * t * (-t).exp() * e * e;
            }
            let expected = (sum * dt).sqrt();
            let (got, stuck) = effective_restitution(&contact, c, false).unwrap();
            assert!(
                (got - expected).abs() < 2e-6,
                "c = {c}: {got} vs {expected}"
            );
            assert_eq!(stuck, 0.0);
        }
    }

    #[test]
    fn the_average_lies_within_the_law_and_rough_loses_more() {
        // ε_N falls with g: the average lies between ε_N at the 1st and 99.8th percentile speeds.
        let contact = Contact::new(&ice(0.02)).unwrap();
        let c = 1e-4;
        let s = core::f64::consts::SQRT_2 * c;
        let (smooth, _) = effective_restitution(&contact, c, false).unwrap();
        let (rough, _) = effective_restitution(&contact, c, true).unwrap();
        let lo = contact.eps_n(s * 3.5, Accuracy::Fast).unwrap();
        let hi = contact.eps_n(s * 0.14, Accuracy::Fast).unwrap();
        assert!(lo < smooth && smooth < hi);
        // Tangential loss ≤ κ⟨g_T²⟩/⟨g_N²⟩ = κ: ε̄_rough² ≥ ε̄_smooth² − 2κ (ε_T ∈ [−1, 1]).
        assert!(rough < smooth && rough * rough >= smooth * smooth - 2.0 * 2.0 / 7.0 - 1e-12);
    }

    #[test]
    fn scaling_a_with_r_keeps_the_impact_average() {
        let small = Contact::new(&ice(0.02)).unwrap();
        let mut big_scene = ice(1.0);
        big_scene.bulk.damping = Damping::Time(scaled_damping_time(1e-4, 0.02, 1.0).unwrap());
        assert_eq!(scaled_damping_time(1e-4, 0.02, 1.0).unwrap(), 5e-3);
        let big = Contact::new(&big_scene).unwrap();
        for c in [1e-5, 1e-4, 1e-3] {
            let a = effective_restitution(&small, c, false).unwrap().0;
            let b = effective_restitution(&big, c, false).unwrap().0;
            assert!((a - b).abs() < 1e-9, "c = {c}: {a} vs {b}");
        }
    }

    #[test]
    fn issue_24_verdicts_for_the_a_ring_patches() {
        let r2cm = equilibrium(&ice(0.02), &input(0.5)).unwrap();
        assert_eq!(r2cm.smooth.verdict, Verdict::Equilibrium);
        assert_eq!(r2cm.rough.verdict, Verdict::MonolayerFloor);
        // Issue 24's "done when": the 2 cm A-ring patch prints an equilibrium (at the floor).
        assert!(r2cm.prediction().verdict.is_equilibrium());
        assert_eq!(
            r2cm.prediction().verdict.words(),
            "equilibrium at the monolayer floor"
        );
        assert_eq!(r2cm.scaled_damping_time, None);
        // The balance holds where it is claimed.
        let p = r2cm.smooth;
        assert!((p.eps_effective - p.eps_cr).abs() < 1e-9);
        assert!((p.mean_impact_speed - PI.sqrt() * p.velocity_dispersion).abs() < 1e-18);
        let r1m = equilibrium(&ice(1.0), &input(0.5)).unwrap();
        assert_eq!(r1m.prediction().verdict, Verdict::Heats);
        assert!(!r1m.prediction().verdict.is_equilibrium());
        assert_eq!(r1m.scaled_damping_time, Some(1e-4 * 1.0 / 0.02));
        let mut scaled = ice(1.0);
        scaled.bulk.damping = Damping::Time(5e-3);
        let r1m_scaled = equilibrium(&scaled, &input(0.5)).unwrap();
        assert_ne!(r1m_scaled.prediction().verdict, Verdict::Heats);
        // The sticky preset aggregates.
        let mut sticky = Preset::IceSticky.scene();
        sticky.grains.radius_1 = 0.02;
        sticky.grains.radius_2 = 0.02;
        let agg = equilibrium(&sticky, &input(0.5)).unwrap();
        assert_eq!(agg.prediction().verdict, Verdict::Aggregates);
    }

    #[test]
    fn the_planet_gives_kepler_omega_and_bad_input_names_the_field() {
        let planet = RingInput {
            tau: 0.5,
            orbit: Orbit::Planet {
                planet_mass: 5.688e26,
                distance: 1.336e8,
            },
            damping_set_for_radius: None,
        };
        let rec = equilibrium(&ice(0.02), &planet).unwrap();
        let expected = (G * 5.688e26 / 1.336e8f64.powi(3)).sqrt();
        assert!((rec.omega - expected).abs() < 1e-18);
        // The tidal appendix's example is that planet and distance.
        let tidal = crate::applications::tidal::TidalInput::default();
        assert_eq!(Orbit::of_tidal(&tidal), planet.orbit);
        let mut bad = input(0.5);
        bad.orbit = Orbit::Omega(-1.0);
        assert!(matches!(
            equilibrium(&ice(0.02), &bad),
            Err(Error::OutOfRange { field: "omega", .. })
        ));
        let mut uneven = ice(0.02);
        uneven.grains.radius_2 = 0.03;
        assert!(matches!(
            equilibrium(&uneven, &input(0.5)),
            Err(Error::InvalidValue {
                field: "grains.radius_2",
                ..
            })
        ));
        assert!(matches!(
            equilibrium(&ice(0.02), &input(f64::INFINITY)),
            Err(Error::OutOfRange { field: "tau", .. })
        ));
    }
}
