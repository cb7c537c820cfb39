//! Sticking speeds of unequal pairs over radius × radius × temperature: the sticking kernel a
//! dust-coagulation code needs (`rime kernel`, issue 39, docs/physics.md#kernel).
//!
//! For grains of radii `a_i`, `a_j` at temperature `T`, [`table`] gives the smallest impact speed
//! at which the scene's full model rebounds (viscous Eq. (4), offset layer Eq. (9)–(10), adhesion
//! Eq. (17) with γ(T) of Musiolik & Wurm 2019 from the [`crate::data::atlas`]), with
//! `R_eff = a_i a_j/(a_i + a_j)` and `m_eff` from the two radii and the scene's density. At
//! `a_i = a_j` it is [`crate::applications::stick::threshold`]'s `v_stick`.
//!
//! **The scaling law.** Without a layer the grains stick iff the rebound speed without adhesion,
//! `g ε(δ)`, is at most Eq. (15)'s `g_s` (Eq. (17)), and ε depends on `δ = β g^(1/5)` alone,
//! `β = A α^(2/5)` (docs/physics.md#decision-3). With `u = log₁₀ δ`, `g = 10^(5(u − log₁₀ β))`, so
//! the pair rebounds iff
//!
//! `Ψ(u) = 5 ln 10 · u + ln ε(u)  >  c = 5 ln 10 · log₁₀ β + ln g_s`,
//!
//! where `Ψ` is one universal function (of the contact-end rule only) and every pair, material
//! and temperature enters through the single number `c`. The threshold is
//! `v_stick = 10^(5(u* − log₁₀ β))` with `Ψ(u*) = c`: `v_stick/g_s` is a function of the
//! dimensionless damping at the elastic threshold, `β g_s^(1/5)`, alone. `g_s ∝ γ^(5/6)` and `β`
//! and `g_s` of a pair are computed once for all temperatures; each (pair, temperature) then costs
//! one root of `Ψ` on the master curve's Chebyshev table ([`crate::normal::viscoelastic::master`]), bracketed between
//! `g_s` (ε ≤ 1: sticks there) and [`crate::applications::stick::SEARCH_MAX`], never an integration. With an
//! offset layer the bulk is reached at `g − g_s,layer` (Eq. (9)): the threshold shifts by
//! `g_s,layer`. The literal layer reading and the integrated accuracy levels have no such form:
//! there every pair is bisected on the full model ([`Method::Bisection`]).
//!
//! **The rule for A across sizes** is the user's ([`ARule`]): `A` as given (a material
//! constant), scaled so that every pair keeps the scene's pair's ε_N(g) (then `β` is the same for
//! every pair; [`crate::applications::ring_sizes::DampingRule::damping_time`]), or fitted so that the model's
//! sticking speed equals a measured one at a reference size ([`MeasuredSpeed`]).
//!
//! **Temperatures** outside γ(T)'s measured 175–200 K get the end values ([`TemperatureRule::Hold`],
//! what `rime stick` does, flagged per temperature by [`GammaRange`]) or an error
//! ([`TemperatureRule::Refuse`]).
//!
//! Not modelled: porous aggregates, fragmentation, erosion, mass transfer; compact spheres of one
//! material only.
//!
//! ```
//! use rime_core::kernel::{self, KernelOptions};
//! use rime_core::Scene;
//!
//! let radii = [1e-5, 1e-4, 1e-3];
//! let k = kernel::table(&Scene::default(), &radii, &[150.0, 200.0], &KernelOptions::default())?;
//! // Flat, temperature-major: v_stick[(t·N + i)·N + j], symmetric in (i, j).
//! assert_eq!(k.v_stick.len(), 2 * 3 * 3);
//! assert_eq!(k.v_stick[k.index(1, 0, 2)], k.v_stick[k.index(1, 2, 0)]);
//! # Ok::<(), rime_core::Error>(())
//! ```

use crate::applications::ring_sizes::DampingRule;
use crate::applications::stick::{self, Convention, SEARCH_MAX};
use crate::data::atlas;
use crate::error::{Error, Result};
use crate::normal::viscoelastic::master::{self, Resolution};
use crate::numerics::accuracy::Accuracy;
use crate::numerics::math::{exp, ln, log10};
use crate::scene::contact::Contact;
use crate::scene::{ContactEnd, Damping, LayerReading, Scene};
use alloc::vec::Vec;

/// The atlas entry γ(T) comes from.
pub const GAMMA_ENTRY: &str = "musiolik2019";

/// Most entries of a table (temperatures × radii²).
pub const MAX_ENTRIES: usize = 50_000_000;

/// A measured sticking speed that [`ARule::FitMeasured`] fits A to.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct MeasuredSpeed {
    /// The atlas entry the speed comes from (its provenance).
    pub entry: &'static str,
    /// Radius of both grains of the reference pair \[m\].
    pub radius: f64,
    /// Temperature of the reference pair \[K\] (γ(T) is evaluated there).
    pub temperature: f64,
    /// The measured sticking speed \[m/s\].
    pub speed: f64,
}

impl MeasuredSpeed {
    /// Gundlach & Blum (2015): µm ice sticks below 9.6 m/s below ~210 K. Reference pair: two
    /// grains of 1.5 µm radius (their grains: 1.45–1.49 µm) at 200 K, the warm end of γ(T)'s
    /// measured range (γ = 0.19 J/m²) and inside theirs (114–210 K).
    pub const GUNDLACH_2015: MeasuredSpeed = MeasuredSpeed {
        entry: "gundlach2015",
        radius: 1.5e-6,
        temperature: 200.0,
        speed: stick::MEASURED_UM_ICE,
    };
}

/// How the damping time A of each pair follows from the scene's (the user's stated choice).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum ARule {
    /// The scene's A for every pair (a material constant; ε_N(g) changes with the pair).
    Given,
    /// `A_ij = A·(R_eff/R_eff,ref)^(−1/5)·(m_eff/m_eff,ref)^(2/5)`, the reference being the
    /// scene's own pair of grains: every pair keeps that pair's ε_N(g)
    /// ([`DampingRule::KeepEpsilon`], shared with `rime ring --radii`).
    KeepEpsilon,
    /// One A for every pair, fitted so that the model's `v_stick` of the reference pair equals the
    /// measured speed (the scene's A is not used).
    FitMeasured(MeasuredSpeed),
}

impl ARule {
    /// Name for output: `given`, `keep_epsilon`, `fit_measured`.
    pub fn name(&self) -> &'static str {
        match self {
            ARule::Given => "given",
            ARule::KeepEpsilon => "keep_epsilon",
            ARule::FitMeasured(_) => "fit_measured",
        }
    }
}

/// What to do at temperatures outside γ(T)'s measured range (175–200 K).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum TemperatureRule {
    /// Hold γ at the nearer end value (0.0029 J/m² below 175 K, 0.19 J/m² above 200 K), as the
    /// atlas and `rime stick` do; flagged per temperature ([`GammaRange`]). Default.
    #[default]
    Hold,
    /// An error naming `temperatures` for any temperature outside the measured range.
    Refuse,
}

impl TemperatureRule {
    /// Name for output: `hold` or `refuse`.
    pub fn name(self) -> &'static str {
        match self {
            TemperatureRule::Hold => "hold",
            TemperatureRule::Refuse => "refuse",
        }
    }
}

/// Where a temperature lies relative to γ(T)'s measured range.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum GammaRange {
    /// Inside the measured 175–200 K: γ interpolated log-linearly between the measured ends.
    Measured,
    /// Below 175 K: γ held at its cold end (0.0029 J/m²), not measured there.
    HeldCold,
    /// Above 200 K: γ held at its warm end (0.19 J/m²), not measured there.
    HeldWarm,
}

impl GammaRange {
    /// Name for output: `measured`, `held_cold`, `held_warm`.
    pub fn name(self) -> &'static str {
        match self {
            GammaRange::Measured => "measured",
            GammaRange::HeldCold => "held_cold",
            GammaRange::HeldWarm => "held_warm",
        }
    }

    /// A one-byte code for flat arrays: 0 measured, 1 held cold, 2 held warm.
    pub fn code(self) -> u8 {
        self as u8
    }
}

/// The outcome of one (pair, temperature).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum StickStatus {
    /// The pair sticks below `v_stick` and rebounds above it.
    Threshold,
    /// The pair sticks at every speed up to [`SEARCH_MAX`] (`v_stick` infinite / `null`).
    AlwaysSticks,
}

impl StickStatus {
    /// Name for output: `threshold` or `always_sticks`.
    pub fn name(self) -> &'static str {
        match self {
            StickStatus::Threshold => "threshold",
            StickStatus::AlwaysSticks => "always_sticks",
        }
    }

    /// A one-byte code for flat arrays: 0 threshold, 1 always sticks.
    pub fn code(self) -> u8 {
        self as u8
    }
}

/// How a table was computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum Method {
    /// The scaling law on the master curve's table (no layer or offset layer; `fast` or
    /// `precise` accuracy): one root of Ψ per entry.
    ScalingLaw,
    /// Bisection on the full model per entry ([`stick::first_rebound_speed`]).
    Bisection,
}

impl Method {
    /// Name for output: `scaling_law` or `bisection`.
    pub fn name(self) -> &'static str {
        match self {
            Method::ScalingLaw => "scaling_law",
            Method::Bisection => "bisection",
        }
    }
}

/// Options of a kernel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KernelOptions {
    /// The rule for A across sizes.
    pub a_rule: ARule,
    /// How the source's γ is read (default: surface energy, w = 2γ).
    pub convention: Convention,
    /// Temperatures outside 175–200 K.
    pub temperature_rule: TemperatureRule,
    /// Accuracy of ε_N (`fast` and `precise` use the scaling law).
    pub accuracy: Accuracy,
}

impl Default for KernelOptions {
    fn default() -> Self {
        KernelOptions {
            a_rule: ARule::Given,
            convention: Convention::SurfaceEnergy,
            temperature_rule: TemperatureRule::Hold,
            accuracy: Accuracy::Fast,
        }
    }
}

/// The fitted A of [`ARule::FitMeasured`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Fit {
    /// What was fitted to.
    pub reference: MeasuredSpeed,
    /// The fitted A \[s\].
    pub damping_time: f64,
    /// `v_stick` of the reference pair with the fitted A by bisection on the full model \[m/s\]
    /// (equals `reference.speed` to the bisection's 1e-10 and the table's accuracy).
    pub achieved: f64,
    /// Eq. (15)'s `g_s` of the reference pair (A = 0) \[m/s\].
    pub v_elastic: f64,
}

/// γ at one temperature.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Gamma {
    /// Temperature \[K\].
    pub temperature: f64,
    /// γ(T) as the source gives it \[J/m²\].
    pub gamma_source: f64,
    /// The paper's γ (work of adhesion) used in Eq. (15) \[J/m²\].
    pub gamma: f64,
    /// Where T lies relative to the measured range.
    pub range: GammaRange,
}

/// γ at `temperature` under `options` (errors name `temperatures`).
pub fn gamma(temperature: f64, options: &KernelOptions) -> Result<Gamma> {
    let entry = atlas::find(GAMMA_ENTRY).ok_or(Error::InvalidValue {
        field: "atlas",
        expected: "the musiolik2019 entry",
    })?;
    if !(temperature.is_finite() && temperature > 0.0) {
        return Err(Error::OutOfRange {
            field: "temperatures",
            value: temperature,
            expected: "must be a finite temperature > 0 K",
        });
    }
    let [t_lo, t_hi] = entry.temperature;
    let range = if temperature < t_lo {
        GammaRange::HeldCold
    } else if temperature > t_hi {
        GammaRange::HeldWarm
    } else {
        GammaRange::Measured
    };
    if range != GammaRange::Measured && options.temperature_rule == TemperatureRule::Refuse {
        return Err(Error::OutOfRange {
            field: "temperatures",
            value: temperature,
            expected: "must lie in [175, 200] K, where γ(T) was measured (Musiolik & Wurm 2019), \
                       unless the end values are held",
        });
    }
    let gamma_source = entry.surface_energy(temperature)?;
    Ok(Gamma {
        temperature,
        gamma_source,
        gamma: options.convention.work_of_adhesion(gamma_source),
        range,
    })
}

/// `base` with radii `r1`, `r2`, adhesion on with the paper's γ `gamma` (the modulus reading of
/// `base`'s adhesion, `as_printed` if it has none) and, when given, damping time `a`.
fn pair_scene(base: &Scene, r1: f64, r2: f64, gamma: f64, a: Option<f64>) -> Result<Scene> {
    let mut s = stick::pair_scene_for(base, r1, r2, gamma)?;
    if let Some(a) = a {
        s.bulk.damping = Damping::Time(a);
    }
    s.validate()?;
    Ok(s)
}

/// The damping time of every pair: the scene's, scaled from it, or one fitted value.
#[derive(Debug, Clone, Copy)]
enum PairDamping {
    /// The scene's damping as it is (time or viscosities).
    Scene,
    /// Scaled from the scene's pair with A = `a_ref` (keep ε).
    KeepEpsilon { reference: Contact, a_ref: f64 },
    /// This A for every pair.
    Fixed(f64),
}

impl PairDamping {
    fn new(base: &Scene, options: &KernelOptions) -> Result<(PairDamping, Option<Fit>)> {
        Ok(match options.a_rule {
            ARule::Given => (PairDamping::Scene, None),
            ARule::KeepEpsilon => (
                PairDamping::KeepEpsilon {
                    reference: Contact::new(base)?,
                    a_ref: base.damping_time(),
                },
                None,
            ),
            ARule::FitMeasured(m) => {
                let fit = fit_measured(base, &m, options)?;
                (PairDamping::Fixed(fit.damping_time), Some(fit))
            }
        })
    }

    /// The pair's scene at the paper's γ `gamma`.
    fn scene(&self, base: &Scene, r1: f64, r2: f64, gamma: f64) -> Result<Scene> {
        match *self {
            PairDamping::Scene => pair_scene(base, r1, r2, gamma, None),
            PairDamping::Fixed(a) => pair_scene(base, r1, r2, gamma, Some(a)),
            PairDamping::KeepEpsilon { reference, a_ref } => {
                let unscaled = pair_scene(base, r1, r2, gamma, None)?;
                if a_ref == 0.0 {
                    return Ok(unscaled);
                }
                let a = DampingRule::KeepEpsilon.damping_time(
                    a_ref,
                    &reference,
                    &Contact::new(&unscaled)?,
                )?;
                pair_scene(base, r1, r2, gamma, Some(a))
            }
        }
    }
}

/// The sticking speed of one pair, by bisection on the full model (the reference path; slower
/// than [`table`], which agrees with it to the bisection's 1e-10 where it uses the scaling law).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PairThreshold {
    /// Radius of grain 1 \[m\].
    pub radius_1: f64,
    /// Radius of grain 2 \[m\].
    pub radius_2: f64,
    /// γ at the temperature.
    pub gamma: Gamma,
    /// The pair's damping time A under the rule \[s\].
    pub damping_time: f64,
    /// Eq. (15) alone \[m/s\].
    pub v_elastic: f64,
    /// Smallest rebounding speed \[m/s\]; `None` when it sticks at every speed up to
    /// [`SEARCH_MAX`].
    pub v_stick: Option<f64>,
}

/// The sticking speed of the pair (`radius_1`, `radius_2`) at `temperature` in `base`'s material,
/// by bisection on the full model ([`stick::first_rebound_speed`]).
pub fn pair(
    base: &Scene,
    radius_1: f64,
    radius_2: f64,
    temperature: f64,
    options: &KernelOptions,
) -> Result<PairThreshold> {
    let g = gamma(temperature, options)?;
    let (damping, _) = PairDamping::new(base, options)?;
    let scene = damping.scene(base, radius_1, radius_2, g.gamma)?;
    let contact = Contact::new(&scene)?;
    Ok(PairThreshold {
        radius_1,
        radius_2,
        gamma: g,
        damping_time: contact.damping_time,
        v_elastic: contact.adhesion.map_or(0.0, |a| a.critical_velocity),
        v_stick: stick::first_rebound_speed(&contact, options.accuracy)?,
    })
}

/// A sticking kernel: `v_stick` over temperatures × radii × radii, flat and temperature-major.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Kernel {
    /// Radii \[m\] (N), as given.
    pub radii: Vec<f64>,
    /// γ at every temperature (T), in the order given.
    pub gammas: Vec<Gamma>,
    /// Smallest rebounding speed \[m/s\] at `index(t, i, j) = (t·N + i)·N + j`, length T·N·N;
    /// `f64::INFINITY` where the pair sticks at every speed up to [`SEARCH_MAX`]. Symmetric in
    /// (i, j) bit for bit.
    pub v_stick: Vec<f64>,
    /// The outcome of every entry (same index).
    pub status: Vec<StickStatus>,
    /// The rule for A.
    pub a_rule: ARule,
    /// A of the reference: the scene's (given, keep ε) or the fitted one \[s\].
    pub damping_time: f64,
    /// The fit, for [`ARule::FitMeasured`].
    pub fit: Option<Fit>,
    /// How γ was read.
    pub convention: Convention,
    /// Temperatures outside the measured range.
    pub temperature_rule: TemperatureRule,
    /// Scaling law or bisection.
    pub method: Method,
}

impl Kernel {
    /// Number of radii N.
    pub fn n(&self) -> usize {
        self.radii.len()
    }

    /// The flat index of temperature `t`, radii `i`, `j`.
    pub fn index(&self, t: usize, i: usize, j: usize) -> usize {
        (t * self.radii.len() + i) * self.radii.len() + j
    }

    /// `v_stick` of temperature `t`, radii `i`, `j` (`None`: sticks at every speed, or out of
    /// range).
    pub fn get(&self, t: usize, i: usize, j: usize) -> Option<f64> {
        if t >= self.gammas.len() || i >= self.n() || j >= self.n() {
            return None;
        }
        let v = self.v_stick[self.index(t, i, j)];
        v.is_finite().then_some(v)
    }

    /// The temperatures \[K\].
    pub fn temperatures(&self) -> Vec<f64> {
        self.gammas.iter().map(|g| g.temperature).collect()
    }
}

/// What the scaling law needs of one pair, for every temperature.
#[derive(Debug, Clone, Copy)]
struct PairLaw {
    /// log₁₀(A α^(2/5)) (−∞ for A = 0).
    log10_beta: f64,
    /// ln g_s of Eq. (15) at the paper's γ = 1 J/m² (g_s ∝ γ^(5/6)).
    ln_gs_unit: f64,
    /// The offset layer's g_s (Eq. (10)), 0 without one.
    layer_gs: f64,
}

const LN10: f64 = core::f64::consts::LN_10;

/// Tolerance on u = log₁₀ δ of the root of Ψ: 5 ln 10 · 1e-13 ≈ 1.2e-12 relative in v_stick,
/// below the 1e-10 of the bisection it replaces.
const U_TOLERANCE: f64 = 1e-13;

/// The smallest rebounding speed from the scaling law (module docs): the root of
/// Ψ(u) = 5 ln 10 u + ln ε(u) = c, bracketed between g_s and [`SEARCH_MAX`].
fn scaling_law_threshold(
    law: &PairLaw,
    ln_gamma56: f64,
    end: ContactEnd,
    resolution: Resolution,
    grid: Option<&PsiGrid>,
) -> Option<f64> {
    let g_cap = SEARCH_MAX - law.layer_gs;
    if !(g_cap > 0.0) {
        return None;
    }
    let ln_gs = law.ln_gs_unit + ln_gamma56;
    if law.log10_beta == f64::NEG_INFINITY {
        // A = 0: ε = 1, the pair rebounds exactly above g_s.
        let gs = exp(ln_gs);
        return (g_cap > gs).then_some(law.layer_gs + gs);
    }
    let k = 5.0 * LN10;
    let l = law.log10_beta;
    let c = k * l + ln_gs;
    let f = |u: f64| k * u + ln(master::eps_log10(u, end, resolution)) - c;
    // Rebounds at the cap? (The bisection's first test: sticking there means at every speed.)
    let mut b = l + 0.2 * log10(g_cap);
    let mut fb = f(b);
    if !(fb > 0.0) {
        return None;
    }
    // At g = g_s the rebound speed g ε ≤ g_s: it sticks.
    let mut a = l + ln_gs / k;
    let mut fa = f(a);
    if a >= b {
        return None;
    }
    // Where Ψ is increasing, its grid narrows the bracket to one cell around the only root.
    if let Some(grid) = grid {
        let k = grid.psi.partition_point(|&p| p <= c);
        if k >= 1 && k < grid.psi.len() {
            let (ua, ub) = (grid.u(k - 1), grid.u(k));
            if ua > a {
                (a, fa) = (ua, grid.psi[k - 1] - c);
            }
            if ub < b {
                (b, fb) = (ub, grid.psi[k] - c);
            }
        }
    }
    // Illinois false position, kept inside the bracket (midpoint when it leaves it or f is not
    // finite); fa ≤ 0 < fb throughout.
    let mut side = 0i8;
    for _ in 0..200 {
        if b - a <= U_TOLERANCE {
            break;
        }
        let mut m = b - fb * (b - a) / (fb - fa);
        if !(m > a && m < b) {
            m = 0.5 * (a + b);
        }
        let fm = f(m);
        if fm > 0.0 {
            b = m;
            fb = fm;
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        } else {
            a = m;
            fa = if fm.is_finite() { fm } else { -1.0 };
            if side == -1 {
                fb *= 0.5;
            }
            side = -1;
        }
    }
    let v_bulk = exp(k * (b - l));
    Some(law.layer_gs + v_bulk.min(g_cap))
}

/// Ψ(u) = 5 ln 10 u + ln ε(u) on a grid of u = log₁₀ δ, kept only where it increases
/// strictly (the force-zero master curve; checked on the grid itself).
#[derive(Debug, Clone)]
struct PsiGrid {
    u0: f64,
    step: f64,
    psi: Vec<f64>,
}

impl PsiGrid {
    /// Lowest and highest u of the grid, and its cells per unit of u.
    const RANGE: (f64, f64, f64) = (-12.0, 12.0, 64.0);

    fn u(&self, k: usize) -> f64 {
        self.u0 + k as f64 * self.step
    }

    fn new(end: ContactEnd, resolution: Resolution) -> Option<PsiGrid> {
        let (lo, hi, per_unit) = Self::RANGE;
        let n = ((hi - lo) * per_unit) as usize + 1;
        let mut grid = PsiGrid {
            u0: lo,
            step: 1.0 / per_unit,
            psi: Vec::with_capacity(n),
        };
        let k5 = 5.0 * LN10;
        for i in 0..n {
            let u = grid.u(i);
            grid.psi
                .push(k5 * u + ln(master::eps_log10(u, end, resolution)));
        }
        grid.psi.windows(2).all(|w| w[1] > w[0]).then_some(grid)
    }
}

/// Checks radii and temperatures (errors name `radii`, `temperatures`).
fn check_grid(radii: &[f64], temperatures: &[f64]) -> Result<()> {
    if radii.is_empty() {
        return Err(Error::InvalidValue {
            field: "radii",
            expected: "at least one radius",
        });
    }
    if temperatures.is_empty() {
        return Err(Error::InvalidValue {
            field: "temperatures",
            expected: "at least one temperature",
        });
    }
    if let Some(&r) = radii.iter().find(|r| !(**r >= 1e-9 && **r <= 1e4)) {
        return Err(Error::OutOfRange {
            field: "radii",
            value: r,
            expected: "must lie in [1e-9, 1e4] m",
        });
    }
    let n = radii.len();
    if n.checked_mul(n)
        .and_then(|nn| nn.checked_mul(temperatures.len()))
        .is_none_or(|e| e > MAX_ENTRIES)
    {
        return Err(Error::InvalidValue {
            field: "radii",
            expected: "at most 5e7 entries (temperatures × radii²)",
        });
    }
    Ok(())
}

/// What every temperature of a table shares: the pairs' laws (scaling law) or scenes' rule
/// (bisection).
struct Plan<'a> {
    base: &'a Scene,
    radii: &'a [f64],
    damping: PairDamping,
    accuracy: Accuracy,
    /// The scaling law's per-pair constants (unordered pairs, i ≤ j, row by row), its table level
    /// and Ψ's grid; `None`: bisection.
    law: Option<(Vec<PairLaw>, Resolution, Option<PsiGrid>)>,
}

impl Plan<'_> {
    /// Fills one temperature's N × N block (`v`, `status`, row-major, symmetric).
    fn fill(&self, g: &Gamma, v: &mut [f64], status: &mut [StickStatus]) -> Result<()> {
        let n = self.radii.len();
        let mut put = |i: usize, j: usize, threshold: Option<f64>| {
            let (value, s) = match threshold {
                Some(x) => (x, StickStatus::Threshold),
                None => (f64::INFINITY, StickStatus::AlwaysSticks),
            };
            for idx in [i * n + j, j * n + i] {
                v[idx] = value;
                status[idx] = s;
            }
        };
        let end = self.base.contact_end;
        match &self.law {
            Some((laws, resolution, grid)) => {
                let ln_gamma56 = 5.0 / 6.0 * ln(g.gamma);
                let mut k = 0;
                for i in 0..n {
                    for j in i..n {
                        put(
                            i,
                            j,
                            scaling_law_threshold(
                                &laws[k],
                                ln_gamma56,
                                end,
                                *resolution,
                                grid.as_ref(),
                            ),
                        );
                        k += 1;
                    }
                }
            }
            None => {
                for i in 0..n {
                    for j in i..n {
                        let scene =
                            self.damping
                                .scene(self.base, self.radii[i], self.radii[j], g.gamma)?;
                        let c = Contact::new(&scene)?;
                        put(i, j, stick::first_rebound_speed(&c, self.accuracy)?);
                    }
                }
            }
        }
        Ok(())
    }
}

/// The sticking kernel of `base`'s material: `v_stick` of every pair of `radii` \[m\] at every
/// temperature of `temperatures` \[K\], with A across sizes by `options.a_rule`.
///
/// The flat-array entry point for dust codes (the Python `rime_grains` binds it):
/// `v_stick[(t·N + i)·N + j]` \[m/s\] (`f64::INFINITY` where the pair sticks at every speed,
/// `status` says [`StickStatus::AlwaysSticks`]), symmetric in (i, j); `gammas[t].range` flags
/// temperatures where γ is held. Each unordered pair is computed once; γ(T) once per temperature;
/// with no layer or an offset layer at `fast`/`precise` accuracy, each entry is one root on the
/// master curve ([`Method::ScalingLaw`], module docs), otherwise a bisection on the full model.
/// Errors name `radii`, `temperatures` or the scene field; on error nothing is returned.
/// One thread; [`table_parallel`] spreads the temperatures over threads.
pub fn table(
    base: &Scene,
    radii: &[f64],
    temperatures: &[f64],
    options: &KernelOptions,
) -> Result<Kernel> {
    table_parallel(base, radii, temperatures, options, 1)
}

/// [`table`] with the temperatures spread over up to `threads` threads (each temperature's
/// block is computed by one thread exactly as [`table`] computes it: the result is bit for bit
/// the same). `threads` ≤ 1, a single temperature, or a target without threads (wasm32, no
/// `std`): one thread.
pub fn table_parallel(
    base: &Scene,
    radii: &[f64],
    temperatures: &[f64],
    options: &KernelOptions,
    threads: usize,
) -> Result<Kernel> {
    check_grid(radii, temperatures)?;
    base.validate()?;
    let gammas = temperatures
        .iter()
        .map(|&t| gamma(t, options))
        .collect::<Result<Vec<_>>>()?;
    let (damping, fit) = PairDamping::new(base, options)?;
    let resolution = match options.accuracy {
        Accuracy::Fast => Some(Resolution::Coarse),
        Accuracy::Precise => Some(Resolution::Fine),
        _ => None,
    };
    let layer_ok = base
        .layer
        .is_none_or(|l| l.thickness == 0.0 || l.reading == LayerReading::Offset);
    let n = radii.len();
    let law = match resolution {
        Some(resolution) if layer_ok => {
            // γ = 1 J/m²: g_s of every temperature is this one times γ^(5/6) (Eq. (15)).
            let mut laws = Vec::with_capacity(n * (n + 1) / 2);
            for i in 0..n {
                for j in i..n {
                    let c = Contact::new(&damping.scene(base, radii[i], radii[j], 1.0)?)?;
                    let gs = c.adhesion.map_or(0.0, |a| a.critical_velocity);
                    laws.push(PairLaw {
                        log10_beta: c.log10_delta_coefficient,
                        ln_gs_unit: ln(gs),
                        layer_gs: c
                            .layer
                            .filter(|l| l.thickness > 0.0)
                            .map_or(0.0, |l| l.critical_velocity),
                    });
                }
            }
            Some((laws, resolution, PsiGrid::new(base.contact_end, resolution)))
        }
        _ => None,
    };
    let method = if law.is_some() {
        Method::ScalingLaw
    } else {
        Method::Bisection
    };
    let plan = Plan {
        base,
        radii,
        damping,
        accuracy: options.accuracy,
        law,
    };
    let nt = gammas.len();
    let mut v_stick = alloc::vec![f64::INFINITY; nt * n * n];
    let mut status = alloc::vec![StickStatus::AlwaysSticks; nt * n * n];
    fill_blocks(&plan, &gammas, &mut v_stick, &mut status, threads)?;
    Ok(Kernel {
        radii: radii.into(),
        gammas,
        v_stick,
        status,
        a_rule: options.a_rule,
        damping_time: fit.map_or(base.damping_time(), |f| f.damping_time),
        fit,
        convention: options.convention,
        temperature_rule: options.temperature_rule,
        method,
    })
}

/// Every temperature's block, on this thread.
fn fill_sequential(
    plan: &Plan,
    gammas: &[Gamma],
    v_stick: &mut [f64],
    status: &mut [StickStatus],
) -> Result<()> {
    let nn = plan.radii.len() * plan.radii.len();
    for ((g, v), s) in gammas
        .iter()
        .zip(v_stick.chunks_mut(nn))
        .zip(status.chunks_mut(nn))
    {
        plan.fill(g, v, s)?;
    }
    Ok(())
}

#[cfg(not(all(feature = "std", not(target_arch = "wasm32"))))]
fn fill_blocks(
    plan: &Plan,
    gammas: &[Gamma],
    v_stick: &mut [f64],
    status: &mut [StickStatus],
    _threads: usize,
) -> Result<()> {
    fill_sequential(plan, gammas, v_stick, status)
}

/// The temperatures in contiguous runs, one run per thread (each block is the temperature's own
/// contiguous N × N slice, so no two threads write the same memory).
#[cfg(all(feature = "std", not(target_arch = "wasm32")))]
fn fill_blocks(
    plan: &Plan,
    gammas: &[Gamma],
    v_stick: &mut [f64],
    status: &mut [StickStatus],
    threads: usize,
) -> Result<()> {
    let threads = threads.min(gammas.len());
    if threads <= 1 {
        return fill_sequential(plan, gammas, v_stick, status);
    }
    let nn = plan.radii.len() * plan.radii.len();
    let per = gammas.len().div_ceil(threads);
    std::thread::scope(|scope| {
        let handles: Vec<_> = gammas
            .chunks(per)
            .zip(v_stick.chunks_mut(per * nn))
            .zip(status.chunks_mut(per * nn))
            .map(|((g, v), s)| scope.spawn(move || fill_sequential(plan, g, v, s)))
            .collect();
        handles.into_iter().try_for_each(|h| {
            h.join().unwrap_or(Err(Error::InvalidValue {
                field: "threads",
                expected: "every kernel thread to finish (one panicked)",
            }))
        })
    })
}

/// Fits one A so that the reference pair of `m` sticks up to `m.speed`: at the threshold the
/// rebound speed without adhesion is g_s (Eq. (17)), so ε(δ*) = g_s/speed fixes δ* on the master
/// curve and A = δ* speed^(−1/5) α^(−2/5) (docs/physics.md#decision-3). Errors name `fit`.
pub fn fit_measured(base: &Scene, m: &MeasuredSpeed, options: &KernelOptions) -> Result<Fit> {
    if !(m.speed.is_finite() && m.speed > 0.0 && m.speed <= SEARCH_MAX) {
        return Err(Error::OutOfRange {
            field: "fit.speed",
            value: m.speed,
            expected: "must be a speed in (0, 1e6] m/s",
        });
    }
    let g = gamma(m.temperature, options).map_err(|e| match e {
        Error::OutOfRange { value, .. } => Error::OutOfRange {
            field: "fit.temperature",
            value,
            expected: "must be a finite temperature > 0 K (inside 175–200 K unless held)",
        },
        other => other,
    })?;
    if !(m.radius >= 1e-9 && m.radius <= 1e4) {
        return Err(Error::OutOfRange {
            field: "fit.radius",
            value: m.radius,
            expected: "must lie in [1e-9, 1e4] m",
        });
    }
    let elastic = Contact::new(&pair_scene(base, m.radius, m.radius, g.gamma, Some(0.0))?)?;
    let v_elastic = elastic.adhesion.map_or(0.0, |a| a.critical_velocity);
    let target = v_elastic / m.speed;
    if base.layer.is_some_and(|l| l.thickness > 0.0) {
        return Err(Error::InvalidValue {
            field: "fit",
            expected: "a scene without a layer (the fit inverts the clean master curve)",
        });
    }
    if !(target < 1.0) {
        return Err(Error::OutOfRange {
            field: "fit",
            value: v_elastic,
            expected: "the reference pair's elastic threshold g_s of Eq. (15) must lie below the \
                       measured speed: no A ≥ 0 lowers the threshold below g_s (choose a larger \
                       reference radius or a colder temperature)",
        });
    }
    // ε(u) falls monotonically from 1: bisect ln ε(u) = ln target in u = log₁₀ δ.
    let resolution = match options.accuracy {
        Accuracy::Precise => Resolution::Fine,
        _ => Resolution::Coarse,
    };
    let end = base.contact_end;
    let ln_target = ln(target);
    let h = |u: f64| ln(master::eps_log10(u, end, resolution)) - ln_target;
    let (mut lo, mut hi) = (-40.0, 60.0);
    if !(h(lo) > 0.0 && h(hi) < 0.0) {
        return Err(Error::InvalidValue {
            field: "fit",
            expected: "a measured speed whose ε = g_s/speed the master curve reaches",
        });
    }
    while hi - lo > 1e-14 * (1.0 + lo.abs()) {
        let mid = 0.5 * (lo + hi);
        if h(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let u = 0.5 * (lo + hi);
    // δ* = A α^(2/5) speed^(1/5).
    let log10_a = u - 0.2 * log10(m.speed) - 0.4 * log10(elastic.alpha);
    let damping_time = crate::numerics::math::powf(10.0, log10_a);
    let fitted = Contact::new(&pair_scene(
        base,
        m.radius,
        m.radius,
        g.gamma,
        Some(damping_time),
    )?)?;
    let achieved =
        stick::first_rebound_speed(&fitted, options.accuracy)?.ok_or(Error::InvalidValue {
            field: "fit",
            expected: "a fitted A whose reference pair rebounds",
        })?;
    Ok(Fit {
        reference: *m,
        damping_time,
        achieved,
        v_elastic,
    })
}

#[cfg(test)]
mod tests;

pub mod figure;
pub use figure::diagonal_figure;
