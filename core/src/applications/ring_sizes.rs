//! A ring of many sizes: the velocity dispersion and thickness of every size bin and the ring's
//! kinematic viscosity (docs/physics.md#ring-sizes, issue 38).
//!
//! The one-size closure of [`crate::applications::ring`] extended to a mixture. Species `i` (radius `R_i`,
//! number fraction `f_i`, optical depth `τ_i = τ f_i R_i²/Σ f_k R_k²`) has its own dispersion `c_i`
//! and balances its viscous gain against its collisional change with every species `j`:
//!
//! * gain per unit mass `(9/4) Ω c_i² ν̂_i/(ν̂_i² + 11/2)`, `ν̂_i = Σ_j ω̂_ij b_ij`,
//!   `b_ij = (4/5) a(2 − a)`, `a = μ_ij(1 + ε̄_ij)`, `μ_ij = m_j/(m_i + m_j)` (the one-size
//!   `(1 + ε)(3 − ε)/5` at `μ = 1/2`);
//! * collisional change per unit mass `−Σ_j ω_ij 2 s_ij² [μ_ij B_ij X_ij + μ_ij² L_ij/2]`, with
//!   `s_ij² = c_i² + c_j²`, `L_ij = 1 − ε̄_ij²` the pair's loss fraction (normal and tangential,
//!   the pair's own ε_N(g), ε_T), `B_ij = ⟨(1 + ε_N) g_N²⟩/⟨g_N²⟩ + κ⟨(1 + ε_T) g_T²⟩/⟨g_T²⟩` and
//!   `X_ij = (m_i c_i² − m_j c_j²)/((m_i + m_j) s_ij²)` (the exchange that drives equipartition);
//! * collision frequency `ω_ij/Ω = (2/π) τ_j (R_i + R_j)²/R_j² · Y(φ)` (the one-size `8τ/π` at
//!   equal radii), `Y` the Carnahan–Starling factor at the layer's total filling factor.
//!
//! Each species' floor is `2Ω` times the collision-rate-weighted mean of `(R_i + R_j)/2` over its
//! partners (`2RΩ` for one size). The system is solved species by species (Gauss–Seidel sweeps,
//! each a root in ln c).

use crate::applications::ring::{
    self, AGGREGATE_FRACTION, Orbit, PairAverage, SLOW_REGIME_LIMIT, Verdict, pair_average,
    vertical_fraction,
};
use crate::error::{Error, Result, positive, within};
use crate::numerics::math::{exp, ln, sqrt};
use crate::scene::contact::Contact;

/// The inputs an impact average's error blames for a ring of many sizes.
const RADII: &str = "tau, omega, radii";
use crate::scene::{Damping, Scene};
use alloc::vec::Vec;
use core::f64::consts::PI;

/// Highest dispersion searched \[m/s\] (as [`crate::applications::ring`]).
const C_MAX: f64 = 1e3;
/// Most bins of a power law (or radii of a list): the balance costs about N³ impact averages
/// (12 bins: 2.5 s).
pub const MAX_BINS: usize = 16;

/// The grain sizes of the ring.
#[derive(Debug, Clone, PartialEq)]
pub enum SizeDistribution {
    /// `dN/dR ∝ R^−q` between `radius_min` and `radius_max` \[m\], split into `bins` bins equal
    /// in log R.
    PowerLaw {
        /// Exponent q (any finite value; 3 is Saturn's rings' 2.75–3).
        q: f64,
        /// Smallest radius \[m\].
        radius_min: f64,
        /// Largest radius \[m\] (> `radius_min`).
        radius_max: f64,
        /// Number of bins (1 to [`MAX_BINS`]).
        bins: usize,
    },
    /// Sizes \[m\] with number fractions (summing to 1 within 1e-6).
    List {
        /// Radii \[m\], distinct.
        radii: Vec<f64>,
        /// Number fractions, one per radius.
        fractions: Vec<f64>,
    },
}

/// How the damping time A of each pair follows from the scene's.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum DampingRule {
    /// A is a material constant: the scene's A for every pair (ε_N(g) changes with the pair).
    Same,
    /// `A_ij = A·(R_eff/R_eff,ref)^(−1/5)·(m_eff/m_eff,ref)^(2/5)` from the scene's own pair of
    /// grains: every pair keeps that pair's ε_N(g) (δ ∝ A α^(2/5) g^(1/5)); a different
    /// material for every other pair.
    KeepEpsilon,
}

impl DampingRule {
    /// The snake_case name used in JSON and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            DampingRule::Same => "same",
            DampingRule::KeepEpsilon => "keep_epsilon",
        }
    }

    /// The damping time A \[s\] of the pair `pair` when the pair `reference` has `a_ref`:
    /// `a_ref` itself ([`DampingRule::Same`]) or
    /// `a_ref·(R_eff/R_eff,ref)^(−1/5)·(m_eff/m_eff,ref)^(2/5)` ([`DampingRule::KeepEpsilon`]),
    /// which keeps `A α^(2/5)` and so δ(g) and ε_N(g) of Eq. (4) (docs/physics.md#decision-3)
    /// equal to the reference pair's (both pairs of one material: α ∝ √R_eff/m_eff). The error
    /// names `damping_time` when the scaled A is not a finite positive number.
    pub fn damping_time(self, a_ref: f64, reference: &Contact, pair: &Contact) -> Result<f64> {
        match self {
            DampingRule::Same => Ok(a_ref),
            DampingRule::KeepEpsilon => positive(
                "damping_time",
                a_ref
                    * crate::numerics::math::powf(pair.r_eff / reference.r_eff, -0.2)
                    * crate::numerics::math::powf(pair.m_eff / reference.m_eff, 0.4),
            ),
        }
    }
}

/// One size bin: its range, representative radius and number fraction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bin {
    /// Lower edge \[m\] (the radius itself for a list).
    pub radius_min: f64,
    /// Upper edge \[m\].
    pub radius_max: f64,
    /// Representative radius `√⟨R²⟩` of the bin \[m\] (keeps the bin's optical depth).
    pub radius: f64,
    /// Number fraction of the bin.
    pub number_fraction: f64,
}

/// `∫_a^b R^(k−q) dR`.
fn moment(q: f64, k: f64, a: f64, b: f64) -> f64 {
    let p = k + 1.0 - q;
    if p.abs() < 1e-12 {
        ln(b / a)
    } else {
        (crate::numerics::math::powf(b, p) - crate::numerics::math::powf(a, p)) / p
    }
}

impl SizeDistribution {
    /// The bins, validated (errors name `q`, `radius_min`, `radius_max`, `bins`, `radii`,
    /// `fractions`).
    pub fn bins(&self) -> Result<Vec<Bin>> {
        match self {
            SizeDistribution::PowerLaw {
                q,
                radius_min,
                radius_max,
                bins,
            } => {
                let q = within("q", *q, -20.0, 20.0, "must lie in [-20, 20]")?;
                let a = positive("radius_min", *radius_min)?;
                let b = positive("radius_max", *radius_max)?;
                if !(b > a) {
                    return Err(Error::OutOfRange {
                        field: "radius_max",
                        value: b,
                        expected: "must be > radius_min",
                    });
                }
                if *bins == 0 || *bins > MAX_BINS {
                    return Err(Error::OutOfRange {
                        field: "bins",
                        value: *bins as f64,
                        expected: "must lie in [1, 16]",
                    });
                }
                let n = *bins;
                let total = moment(q, 0.0, a, b);
                let mut out = Vec::with_capacity(n);
                for k in 0..n {
                    let lo = a * exp(ln(b / a) * k as f64 / n as f64);
                    let hi = if k + 1 == n {
                        b
                    } else {
                        a * exp(ln(b / a) * (k + 1) as f64 / n as f64)
                    };
                    let count = moment(q, 0.0, lo, hi);
                    let r2 = moment(q, 2.0, lo, hi) / count;
                    out.push(Bin {
                        radius_min: lo,
                        radius_max: hi,
                        radius: sqrt(r2),
                        number_fraction: count / total,
                    });
                }
                if out
                    .iter()
                    .any(|b| !(b.number_fraction > 0.0 && b.radius.is_finite()))
                {
                    return Err(Error::DerivedOutOfRange {
                        quantity: "bin number fractions",
                        fields: "q, radius_min, radius_max",
                    });
                }
                Ok(out)
            }
            SizeDistribution::List { radii, fractions } => {
                if radii.is_empty() || radii.len() > MAX_BINS {
                    return Err(Error::InvalidValue {
                        field: "radii",
                        expected: "1 to 16 radii",
                    });
                }
                if fractions.len() != radii.len() {
                    return Err(Error::InvalidValue {
                        field: "fractions",
                        expected: "one number fraction per radius",
                    });
                }
                let mut sum = 0.0;
                let mut out: Vec<Bin> = Vec::with_capacity(radii.len());
                for (&r, &f) in radii.iter().zip(fractions) {
                    let r = positive("radii", r)?;
                    let f = within("fractions", f, f64::MIN_POSITIVE, 1.0, "must lie in (0, 1]")?;
                    if out.iter().any(|b| b.radius == r) {
                        return Err(Error::InvalidValue {
                            field: "radii",
                            expected: "distinct radii (merge the fractions of equal ones)",
                        });
                    }
                    sum += f;
                    out.push(Bin {
                        radius_min: r,
                        radius_max: r,
                        radius: r,
                        number_fraction: f,
                    });
                }
                if (sum - 1.0).abs() > 1e-6 {
                    return Err(Error::OutOfRange {
                        field: "fractions",
                        value: sum,
                        expected: "must sum to 1 (within 1e-6)",
                    });
                }
                Ok(out)
            }
        }
    }
}

/// Inputs of [`equilibrium`].
#[derive(Debug, Clone, PartialEq)]
pub struct SizeRingInput {
    /// Normal optical depth τ of all sizes together (> 0, ≤ 5).
    pub tau: f64,
    /// Orbital frequency.
    pub orbit: Orbit,
    /// The sizes.
    pub sizes: SizeDistribution,
    /// How A follows from the scene's for every pair.
    pub damping_rule: DampingRule,
}

/// The prediction for one size bin.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct BinPrediction {
    /// Lower edge of the bin \[m\].
    pub radius_min: f64,
    /// Upper edge of the bin \[m\].
    pub radius_max: f64,
    /// Representative radius `√⟨R²⟩` \[m\].
    pub radius: f64,
    /// Number fraction.
    pub number_fraction: f64,
    /// Optical depth of the bin.
    pub tau: f64,
    /// One-dimensional velocity dispersion c_i \[m/s\].
    pub velocity_dispersion: f64,
    /// rms z, `c_z,i/Ω` \[m\].
    pub thickness: f64,
    /// The bin's floor `2Ω⟨(R_i + R_j)/2⟩` \[m/s\].
    pub floor_dispersion: f64,
    /// Whether the bin sits at its floor.
    pub at_floor: bool,
    /// Rate-weighted mean normal impact speed of the bin's collisions \[m/s\].
    pub mean_impact_speed: f64,
    /// Rate-weighted fraction of the bin's impacts that stick.
    pub sticking_fraction: f64,
    /// Collision frequency per orbital frequency of one grain of the bin, `Σ_j ω_ij/Ω`.
    pub collision_frequency: f64,
    /// Translational kinematic viscosity of the bin \[m²/s\].
    pub viscosity_translational: f64,
}

/// The ring's kinematic viscosity \[m²/s\] (docs/physics.md#ring-sizes).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Viscosity {
    /// Translational (local) part: the velocity ellipsoid's shear stress.
    pub translational: f64,
    /// Collisional (non-local) part: momentum carried across the contact distance.
    pub collisional: f64,
    /// `translational + collisional`.
    pub total: f64,
    /// `d ln ν_total/d ln τ` (central difference in ln τ, ±1e-3).
    pub dlnnu_dlntau: f64,
    /// Viscous overstability: always [`OVERSTABILITY_NOT_ASSESSED`] (no published criterion for
    /// this closure could be read and checked; docs/physics.md#ring-sizes).
    pub overstability: &'static str,
}

/// The overstability verdict rime gives: none (docs/physics.md#ring-sizes says why).
pub const OVERSTABILITY_NOT_ASSESSED: &str = "not_assessed";

/// The record of [`equilibrium`].
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SizeRingRecord {
    /// Optical depth τ.
    pub tau: f64,
    /// Orbital frequency Ω \[1/s\].
    pub omega: f64,
    /// The A rule.
    pub damping_rule: DampingRule,
    /// The scene's damping time A \[s\] (of the reference pair under `keep_epsilon`).
    pub damping_time: f64,
    /// Radius of the reference pair A was set for \[m\] (the scene's grains).
    pub damping_reference_radius: f64,
    /// Whether friction (rough grains) is on.
    pub friction: bool,
    /// Per bin, smallest first.
    pub size_bins: Vec<BinPrediction>,
    /// Ring-wide one-dimensional dispersion `√(Σ f_i c_i²)` (all particles, number-weighted) \[m/s\].
    pub velocity_dispersion: f64,
    /// Ring-wide rms z `√(Σ f_i H_i²)` \[m\].
    pub thickness: f64,
    /// Collision-weighted mean normal impact speed \[m/s\].
    pub mean_impact_speed: f64,
    /// Collision-weighted fraction of sticking impacts.
    pub sticking_fraction: f64,
    /// Layer filling factor φ (all sizes).
    pub filling_factor: f64,
    /// The ring's viscosity.
    pub viscosity: Viscosity,
    /// The verdict.
    pub verdict: Verdict,
}

struct Species {
    radius: f64,
    tau: f64,
    /// Surface number density per π: `τ_i/R_i²` (π cancels in every ratio).
    count: f64,
    mass: f64,
    dilute_frequency: f64,
    floor: f64,
}

struct Model {
    omega: f64,
    /// The scene of the pair (0, 0) (its A per the rule).
    scene00: Scene,
    species: Vec<Species>,
    /// `[i][j]`: contact, μ_ij = m_j/(m_i + m_j), dilute ω_ij/Ω.
    contacts: Vec<Vec<Contact>>,
    mu: Vec<Vec<f64>>,
    w0: Vec<Vec<f64>>,
    rough: bool,
}

struct State {
    c: Vec<f64>,
    /// One size: the record of [`crate::applications::ring::equilibrium`] (c and H are its numbers).
    one_size: Option<ring::RingRecord>,
}

/// Residual (per `Ω c_i²`) below which a Newton step that cannot descend is accepted: the
/// roughness of the residual from the Fast ε_N reading, about 1e-6.
const RESIDUAL_TOLERANCE: f64 = 1e-5;
/// Residual at which the balance is taken as solved (c to about 1e-6 relative).
const CONVERGED: f64 = 1e-6;

impl Model {
    fn n(&self) -> usize {
        self.species.len()
    }

    /// H used by the filling factor (the one-size convention: vertical fraction of the dilute
    /// collision frequency).
    fn layer_thickness(&self, i: usize, c: f64) -> f64 {
        c * vertical_fraction(self.species[i].dilute_frequency) / self.omega
    }

    fn filling_factor(&self, c: &[f64]) -> f64 {
        let phi: f64 = self
            .species
            .iter()
            .enumerate()
            .map(|(i, s)| 2.0 * s.tau * s.radius / (3.0 * sqrt(PI) * self.layer_thickness(i, c[i])))
            .sum();
        phi.min(0.5)
    }

    fn enskog(&self, c: &[f64]) -> f64 {
        let phi = self.filling_factor(c);
        let q = 1.0 - phi;
        (1.0 - 0.5 * phi) / (q * q * q)
    }

    /// Impact averages of every pair at dispersions `c` (symmetric: computed once per pair).
    fn pairs(&self, c: &[f64]) -> Result<Vec<Vec<PairAverage>>> {
        let n = self.n();
        let zero = PairAverage {
            loss: 0.0,
            exchange: 0.0,
            sticking: 0.0,
        };
        let mut t = alloc::vec![alloc::vec![zero; n]; n];
        for i in 0..n {
            for j in i..n {
                let s = sqrt(c[i] * c[i] + c[j] * c[j]);
                let pa = pair_average(&self.contacts[i][j], s, self.rough, RADII)?;
                t[i][j] = pa;
                t[j][i] = pa;
            }
        }
        Ok(t)
    }

    /// `table` with the pairs of species `j` recomputed at dispersions `c` (only c_j changed).
    fn repair(
        &self,
        table: &[Vec<PairAverage>],
        c: &[f64],
        j: usize,
    ) -> Result<Vec<Vec<PairAverage>>> {
        let mut t = table.to_vec();
        for k in 0..self.n() {
            let s = sqrt(c[j] * c[j] + c[k] * c[k]);
            let pa = pair_average(&self.contacts[j][k], s, self.rough, RADII)?;
            t[j][k] = pa;
            t[k][j] = pa;
        }
        Ok(t)
    }

    /// Every species' (gain − loss)/(Ω c_i²) and ν̂_i at dispersions `c`.
    fn residuals(&self, c: &[f64]) -> Result<(Vec<f64>, Vec<f64>)> {
        let t = self.pairs(c)?;
        self.residuals_with(c, &t)
    }

    /// [`Model::residuals`] with the pairs' averages given.
    fn residuals_with(&self, c: &[f64], t: &[Vec<PairAverage>]) -> Result<(Vec<f64>, Vec<f64>)> {
        let y = self.enskog(c);
        let n = self.n();
        let (mut f, mut nus) = (Vec::with_capacity(n), Vec::with_capacity(n));
        for i in 0..n {
            let (mi, ri) = (self.species[i].mass, c[i] * c[i]);
            let (mut nu, mut loss) = (0.0, 0.0);
            for j in 0..n {
                let cj2 = c[j] * c[j];
                let s2 = ri + cj2;
                let pa = t[i][j];
                let mu = self.mu[i][j];
                let w = self.w0[i][j] * y;
                let eps = sqrt((1.0 - pa.loss).max(0.0));
                let a = mu * (1.0 + eps);
                nu += w * 0.8 * a * (2.0 - a);
                let mj = self.species[j].mass;
                let x = (mi * ri - mj * cj2) / ((mi + mj) * s2);
                loss += w * 2.0 * s2 / ri * (mu * pa.exchange * x + 0.5 * mu * mu * pa.loss);
            }
            f.push(2.25 * nu / (nu * nu + 5.5) - loss);
            nus.push(nu);
        }
        Ok((f, nus))
    }

    /// The balance: species above their floors have zero residual, species at their floor a
    /// negative one (they lose more than the local gain). Projected Newton in ln c with a
    /// finite-difference Jacobian and a backtracking line search.
    fn solve(&self) -> Result<State> {
        let n = self.n();
        if n == 1 {
            // One size: today's balance, by the same code (docs/physics.md#ring).
            let rec = ring::equilibrium(
                &self.scene00,
                &ring::RingInput {
                    tau: self.species[0].tau,
                    orbit: Orbit::Omega(self.omega),
                    damping_set_for_radius: None,
                },
            )?;
            return Ok(State {
                c: alloc::vec![rec.prediction().velocity_dispersion],
                one_size: Some(rec),
            });
        }
        let floors: Vec<f64> = self.species.iter().map(|s| s.floor).collect();
        let mut c = floors.clone();
        let (mut f, _) = self.residuals(&c)?;
        // Start: the species that gain at their floor, from a modest multiple of it.
        let mut active: Vec<bool> = f.iter().map(|&r| r > 0.0).collect();
        for i in 0..n {
            if active[i] {
                c[i] = floors[i] * 2.0;
            }
        }
        for _ in 0..300 {
            let table = self.pairs(&c)?;
            let (f0, _) = self.residuals_with(&c, &table)?;
            f = f0;
            // Release or pin species at their floors.
            let mut changed = false;
            for i in 0..n {
                if !active[i] && c[i] <= floors[i] && f[i] > 0.0 {
                    active[i] = true;
                    changed = true;
                }
            }
            let idx: Vec<usize> = (0..n).filter(|&i| active[i]).collect();
            let norm = |f: &[f64]| idx.iter().map(|&i| f[i].abs()).fold(0.0f64, f64::max);
            let f_norm = norm(&f);
            if idx.is_empty() || (!changed && f_norm < CONVERGED) {
                return Ok(State { c, one_size: None });
            }
            // Jacobian of the active residuals in ln c.
            let k = idx.len();
            let mut jac = alloc::vec![0.0; k * k];
            // Larger than the residual's roughness (the Fast ε_N reading, ~1e-6).
            let h = 1e-4;
            for (b, &j) in idx.iter().enumerate() {
                let mut cp = c.clone();
                cp[j] *= exp(h);
                // Only the pairs of j change: N averages per column, not N²/2.
                let (fp, _) = self.residuals_with(&cp, &self.repair(&table, &cp, j)?)?;
                for (a, &i) in idx.iter().enumerate() {
                    jac[a * k + b] = (fp[i] - f[i]) / h;
                }
            }
            let rhs: Vec<f64> = idx.iter().map(|&i| -f[i]).collect();
            let step = solve_linear(&mut jac, rhs, k).ok_or(Error::DerivedOutOfRange {
                quantity: "ring size-bin balance (singular Jacobian)",
                fields: "tau, radii",
            })?;
            // Backtracking: at most a factor e per step in c, then halve until |F| falls.
            let longest = step.iter().fold(0.0f64, |m, s| m.max(s.abs()));
            let mut lambda = if longest > 1.0 { 1.0 / longest } else { 1.0 };
            let mut accepted = false;
            for _ in 0..40 {
                let mut trial = c.clone();
                for (a, &i) in idx.iter().enumerate() {
                    trial[i] = (c[i] * exp(lambda * step[a])).clamp(floors[i], C_MAX);
                }
                let (ft, _) = self.residuals(&trial)?;
                if norm(&ft) < f_norm || lambda * longest < 1e-14 {
                    c = trial;
                    accepted = true;
                    break;
                }
                lambda *= 0.5;
            }
            if !accepted {
                if f_norm < RESIDUAL_TOLERANCE {
                    return Ok(State { c, one_size: None });
                }
                return Err(Error::DerivedOutOfRange {
                    quantity: "ring size-bin balance (no descent)",
                    fields: "tau, radii",
                });
            }
            for &i in &idx {
                if c[i] <= floors[i] {
                    // Pinned if it still loses at its floor; kept active (and released above) else.
                    let (fi, _) = self.residuals(&c)?;
                    if fi[i] <= 0.0 {
                        active[i] = false;
                    }
                }
            }
        }
        Err(Error::StepBudgetExceeded {
            what: "ring size-bin balance (Newton)",
            steps: 300,
        })
    }
}

/// Gaussian elimination with partial pivoting of a `k×k` row-major system; `None` when singular.
fn solve_linear(a: &mut [f64], mut b: Vec<f64>, k: usize) -> Option<Vec<f64>> {
    for col in 0..k {
        let piv =
            (col..k).max_by(|&x, &y| a[x * k + col].abs().total_cmp(&a[y * k + col].abs()))?;
        if !(a[piv * k + col].abs() > 0.0) {
            return None;
        }
        if piv != col {
            for m in 0..k {
                a.swap(piv * k + m, col * k + m);
            }
            b.swap(piv, col);
        }
        for row in col + 1..k {
            let factor = a[row * k + col] / a[col * k + col];
            for m in col..k {
                a[row * k + m] -= factor * a[col * k + m];
            }
            b[row] -= factor * b[col];
        }
    }
    let mut x = alloc::vec![0.0; k];
    for row in (0..k).rev() {
        let mut s = b[row];
        for m in row + 1..k {
            s -= a[row * k + m] * x[m];
        }
        x[row] = s / a[row * k + row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

fn build(scene: &Scene, tau: f64, omega: f64, bins: &[Bin], rule: DampingRule) -> Result<Model> {
    let r_ref = scene.grains.radius_1;
    if scene.grains.radius_2 != r_ref {
        return Err(Error::InvalidValue {
            field: "grains.radius_2",
            expected: "equal to grains.radius_1 (the pair A was set for)",
        });
    }
    let reference = Contact::new(scene)?;
    let a_ref = scene.damping_time();
    let sum_r2: f64 = bins
        .iter()
        .map(|b| b.number_fraction * b.radius * b.radius)
        .sum();
    let n = bins.len();
    let mut scene00 = *scene;
    let mut contacts = Vec::with_capacity(n);
    let mut mu = Vec::with_capacity(n);
    let mut w0 = Vec::with_capacity(n);
    let taus: Vec<f64> = bins
        .iter()
        .map(|b| tau * b.number_fraction * b.radius * b.radius / sum_r2)
        .collect();
    for bi in bins {
        let (mut row_c, mut row_mu, mut row_w) = (Vec::new(), Vec::new(), Vec::new());
        for (j, bj) in bins.iter().enumerate() {
            let mut pair = *scene;
            pair.grains.radius_1 = bi.radius;
            pair.grains.radius_2 = bj.radius;
            let mut contact = Contact::new(&pair)?;
            if rule == DampingRule::KeepEpsilon {
                let a = rule.damping_time(a_ref, &reference, &contact)?;
                pair.bulk.damping = Damping::Time(a);
                contact = Contact::new(&pair)?;
            }
            if row_c.is_empty() && contacts.is_empty() {
                scene00 = pair;
            }
            row_c.push(contact);
            let (mi, mj) = (
                bi.radius * bi.radius * bi.radius,
                bj.radius * bj.radius * bj.radius,
            );
            row_mu.push(mj / (mi + mj));
            let sum = bi.radius + bj.radius;
            row_w.push(2.0 / PI * taus[j] * sum * sum / (bj.radius * bj.radius));
        }
        contacts.push(row_c);
        mu.push(row_mu);
        w0.push(row_w);
    }
    let species = bins
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let total: f64 = w0[i].iter().sum();
            let mean_contact: f64 = w0[i]
                .iter()
                .zip(bins)
                .map(|(w, bj)| w * 0.5 * (b.radius + bj.radius))
                .sum::<f64>()
                / total;
            Species {
                radius: b.radius,
                tau: taus[i],
                count: taus[i] / (b.radius * b.radius),
                mass: b.radius * b.radius * b.radius,
                dilute_frequency: total,
                floor: ring::FLOOR_IN_R_OMEGA * mean_contact * omega,
            }
        })
        .collect();
    Ok(Model {
        omega,
        scene00,
        species,
        contacts,
        mu,
        w0,
        rough: scene.friction.is_some(),
    })
}

/// Per-bin predictions, ring-wide keys and viscosity of a solved state (no derivative).
fn describe(m: &Model, st: &State, bins: &[Bin]) -> Result<(Vec<BinPrediction>, Viscosity, f64)> {
    let n = m.n();
    let c = &st.c;
    let y = m.enskog(c);
    let phi = m.filling_factor(c);
    let mut out = Vec::with_capacity(n);
    let total_mass: f64 = m.species.iter().map(|s| s.count * s.mass).sum();
    let (mut nu_trans, mut nu_cross, mut eta_inst) = (0.0, 0.0, 0.0);
    for i in 0..n {
        let si = &m.species[i];
        // The velocity ellipsoid's relaxation with ε = ε_cr of the species' collision frequency
        // (today's convention for H: equal to ν̂_i at a local balance, defined at the floor too).
        let w_i: f64 = (0..n).map(|j| m.w0[i][j] * y).sum();
        let eps_cr = ring::eps_cr_of(w_i);
        let nu_hat: f64 = (0..n)
            .map(|j| {
                let a = m.mu[i][j] * (1.0 + eps_cr);
                m.w0[i][j] * y * 0.8 * a * (2.0 - a)
            })
            .sum();
        let thickness = match &st.one_size {
            Some(rec) => rec.prediction().thickness,
            None => c[i] * sqrt(1.0 - 1.5 / (nu_hat * nu_hat + 5.5)) / m.omega,
        };
        let nu_t = c[i] * c[i] / m.omega * nu_hat / (nu_hat * nu_hat + 5.5);
        let (mut rate, mut speed, mut stick, mut cross) = (0.0, 0.0, 0.0, 0.0);
        let hi = m.layer_thickness(i, c[i]);
        for j in 0..n {
            let sj = &m.species[j];
            let s = sqrt(c[i] * c[i] + c[j] * c[j]);
            let pa = pair_average(&m.contacts[i][j], s, m.rough, RADII)?;
            let w = m.w0[i][j] * y;
            rate += w;
            speed += w * s * sqrt(PI / 2.0);
            stick += w * pa.sticking;
            let eps = sqrt((1.0 - pa.loss).max(0.0));
            let sigma = si.radius + sj.radius;
            let hj = m.layer_thickness(j, c[j]);
            // Midplane-weighted overlap ∫n_i n_j dz/N_i of the two Gaussian layers, ×π (count is τ/R²).
            let overlap = sj.count / PI / (sqrt(2.0 * PI) * sqrt(hi * hi + hj * hj));
            // (π/6)σ³ n_j: the partner's filling factor at contact distance.
            cross += PI / 6.0 * sigma * sigma * sigma * overlap * 2.0 * m.mu[i][j] * (1.0 + eps);
            let m_eff = si.mass * sj.mass / (si.mass + sj.mass);
            eta_inst += si.count / PI
                * overlap
                * sigma
                * sigma
                * sigma
                * sigma
                * m_eff
                * (1.0 + eps)
                * s
                * y;
        }
        let weight = si.count * si.mass / total_mass;
        nu_trans += weight * nu_t;
        nu_cross += weight * nu_t * 0.8 * y * cross;
        out.push(BinPrediction {
            radius_min: bins[i].radius_min,
            radius_max: bins[i].radius_max,
            radius: si.radius,
            number_fraction: bins[i].number_fraction,
            tau: si.tau,
            velocity_dispersion: c[i],
            thickness,
            floor_dispersion: si.floor,
            at_floor: c[i] <= si.floor,
            mean_impact_speed: match &st.one_size {
                Some(rec) => rec.prediction().mean_impact_speed,
                None => speed / rate,
            },
            sticking_fraction: match &st.one_size {
                Some(rec) => rec.prediction().sticking_fraction,
                None => stick / rate,
            },
            collision_frequency: rate,
            viscosity_translational: nu_t,
        });
    }
    // Enskog's instantaneous collisional transfer, K = 2√(2π)/15 (docs/physics.md#ring-sizes).
    let nu_inst = 2.0 * sqrt(2.0 * PI) / 15.0 * eta_inst / (total_mass / PI);
    let collisional = nu_cross + nu_inst;
    Ok((
        out,
        Viscosity {
            translational: nu_trans,
            collisional,
            total: nu_trans + collisional,
            dlnnu_dlntau: f64::NAN,
            overstability: OVERSTABILITY_NOT_ASSESSED,
        },
        phi,
    ))
}

fn solve_at(scene: &Scene, tau: f64, omega: f64, bins: &[Bin], rule: DampingRule) -> Result<f64> {
    let m = build(scene, tau, omega, bins, rule)?;
    let st = m.solve()?;
    Ok(describe(&m, &st, bins)?.1.total)
}

/// The equilibrium of a ring of many sizes made of `scene`'s material (the scene's grains, of
/// equal radii, are the pair A was set for).
///
/// Errors name the field: `tau`, `omega`, `planet_mass`, `distance`, `q`, `radius_min`,
/// `radius_max`, `bins`, `radii`, `fractions`, `grains.radius_2`, or any scene field.
pub fn equilibrium(scene: &Scene, input: &SizeRingInput) -> Result<SizeRingRecord> {
    let tau = within(
        "tau",
        input.tau,
        f64::MIN_POSITIVE,
        5.0,
        "must lie in (0, 5]",
    )?;
    let omega = input.orbit.omega()?;
    let bins = input.sizes.bins()?;
    let model = build(scene, tau, omega, &bins, input.damping_rule)?;
    let state = model.solve()?;
    let (size_bins, mut viscosity, filling_factor) = describe(&model, &state, &bins)?;
    // d ln ν/d ln τ by a central difference (one-sided at τ = 5).
    let h = 1e-3;
    let (t_up, t_down) = (tau * exp(h), tau * exp(-h));
    let (up, span_up) = if t_up <= 5.0 {
        (solve_at(scene, t_up, omega, &bins, input.damping_rule)?, h)
    } else {
        (viscosity.total, 0.0)
    };
    let down = solve_at(scene, t_down, omega, &bins, input.damping_rule)?;
    viscosity.dlnnu_dlntau = (ln(up) - ln(down)) / (span_up + h);
    let weights: f64 = size_bins.iter().map(|b| b.number_fraction).sum();
    let velocity_dispersion = sqrt(
        size_bins
            .iter()
            .map(|b| b.number_fraction * b.velocity_dispersion * b.velocity_dispersion)
            .sum::<f64>()
            / weights,
    );
    let thickness = sqrt(
        size_bins
            .iter()
            .map(|b| b.number_fraction * b.thickness * b.thickness)
            .sum::<f64>()
            / weights,
    );
    // Collisions per unit area ∝ N_i ω_i.
    let per_area: Vec<f64> = model
        .species
        .iter()
        .zip(&size_bins)
        .map(|(s, b)| s.count * b.collision_frequency)
        .collect();
    let all: f64 = per_area.iter().sum();
    let mean_impact_speed = size_bins
        .iter()
        .zip(&per_area)
        .map(|(b, w)| w * b.mean_impact_speed)
        .sum::<f64>()
        / all;
    let sticking_fraction = size_bins
        .iter()
        .zip(&per_area)
        .map(|(b, w)| w * b.sticking_fraction)
        .sum::<f64>()
        / all;
    let verdict = if sticking_fraction >= AGGREGATE_FRACTION {
        Verdict::Aggregates
    } else if size_bins
        .iter()
        .any(|b| b.velocity_dispersion >= C_MAX || b.mean_impact_speed > SLOW_REGIME_LIMIT)
    {
        Verdict::Heats
    } else if size_bins.iter().all(|b| b.at_floor) {
        Verdict::MonolayerFloor
    } else {
        Verdict::Equilibrium
    };
    Ok(SizeRingRecord {
        tau,
        omega,
        damping_rule: input.damping_rule,
        damping_time: scene.damping_time(),
        damping_reference_radius: scene.grains.radius_1,
        friction: model.rough,
        size_bins,
        velocity_dispersion,
        thickness,
        mean_impact_speed,
        sticking_fraction,
        filling_factor,
        viscosity,
        verdict,
    })
}

/// The kinematic viscosity of the ring of [`crate::applications::ring::equilibrium`]: the scene's
/// one size as a one-bin distribution (which reproduces that ring's c and H to the digit; the
/// test `issue_38_one_size_reproduces_todays_answers`). Errors as [`equilibrium`]'s.
pub fn one_size_viscosity(
    scene: &Scene,
    input: &crate::applications::ring::RingInput,
) -> Result<Viscosity> {
    let one = SizeRingInput {
        tau: input.tau,
        orbit: input.orbit,
        sizes: SizeDistribution::List {
            radii: alloc::vec![scene.grains.radius_1],
            fractions: alloc::vec![1.0],
        },
        damping_rule: DampingRule::Same,
    };
    Ok(equilibrium(scene, &one)?.viscosity)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::applications::ring::{RingInput, equilibrium as one_size};
    use crate::numerics::accuracy::Accuracy;
    use crate::scene::Preset;

    const SATURN_A_RING_OMEGA: f64 = 1.3143527e-4;

    fn sized(scene: &Scene, radius: f64) -> Scene {
        let mut s = *scene;
        (s.grains.radius_1, s.grains.radius_2) = (radius, radius);
        s
    }

    fn input(tau: f64, sizes: SizeDistribution, rule: DampingRule) -> SizeRingInput {
        SizeRingInput {
            tau,
            orbit: Orbit::Omega(SATURN_A_RING_OMEGA),
            sizes,
            damping_rule: rule,
        }
    }

    fn one(radius: f64) -> SizeDistribution {
        SizeDistribution::List {
            radii: alloc::vec![radius],
            fractions: alloc::vec![1.0],
        }
    }

    /// One size is today's `ring::equilibrium`, to the digit.
    #[test]
    fn issue_38_one_size_reproduces_todays_answers() {
        let ice = Preset::Ice.scene();
        let mut smooth = ice;
        smooth.friction = None;
        let mut metre = sized(&ice, 1.0);
        metre.bulk.damping = Damping::Time(5e-3);
        for (scene, r) in [(ice, 0.02), (smooth, 0.02), (metre, 1.0), (ice, 1.0)] {
            let today = one_size(
                &sized(&scene, r),
                &RingInput {
                    tau: 0.5,
                    orbit: Orbit::Omega(SATURN_A_RING_OMEGA),
                    damping_set_for_radius: None,
                },
            )
            .unwrap();
            let p = today.prediction();
            let rec =
                equilibrium(&sized(&scene, r), &input(0.5, one(r), DampingRule::Same)).unwrap();
            let b = rec.size_bins[0];
            assert_eq!(b.velocity_dispersion, p.velocity_dispersion);
            assert_eq!(b.thickness, p.thickness);
            assert_eq!(b.mean_impact_speed, p.mean_impact_speed);
            assert_eq!(rec.velocity_dispersion, p.velocity_dispersion);
            assert_eq!(rec.thickness, p.thickness);
            assert_eq!(rec.verdict, p.verdict, "r = {r}");
            assert_eq!(b.floor_dispersion, today.floor_dispersion);
        }
    }

    /// Two bins of (nearly) the same size solve the mixture equations, and must land on the one-size
    /// balance (the exchange term vanishes, μ = 1/2, the rates add up to 8τ/π).
    #[test]
    fn issue_38_two_equal_bins_are_one_size() {
        let mut smooth = Preset::Ice.scene();
        smooth.friction = None;
        for (scene, r) in [(smooth, 0.02), (Preset::Ice.scene(), 0.02)] {
            let today = one_size(
                &sized(&scene, r),
                &RingInput {
                    tau: 0.5,
                    orbit: Orbit::Omega(SATURN_A_RING_OMEGA),
                    damping_set_for_radius: None,
                },
            )
            .unwrap();
            let p = today.prediction();
            let sizes = SizeDistribution::PowerLaw {
                q: 3.0,
                radius_min: r,
                radius_max: r * (1.0 + 1e-9),
                bins: 2,
            };
            let rec =
                equilibrium(&sized(&scene, r), &input(0.5, sizes, DampingRule::Same)).unwrap();
            for b in &rec.size_bins {
                // The mixture is solved to a residual of 1e-6 (CONVERGED) per Ω c²; the `ice` law's
                // loss changes by only ~0.1 per e-fold of c, so c agrees to a few 1e-5.
                let rel = (b.velocity_dispersion / p.velocity_dispersion - 1.0).abs();
                assert!(
                    rel < 1e-4,
                    "c {} vs {}",
                    b.velocity_dispersion,
                    p.velocity_dispersion
                );
                let rel = (b.thickness / p.thickness - 1.0).abs();
                assert!(rel < 1e-4, "H {} vs {}", b.thickness, p.thickness);
                assert!((b.collision_frequency / p.collision_frequency - 1.0).abs() < 1e-4);
            }
            assert_eq!(rec.verdict, p.verdict);
        }
    }

    /// The bins of a power law against the closed-form integrals of R^−q.
    #[test]
    fn issue_38_power_law_bins_match_their_integrals() {
        let (a, b) = (0.01f64, 0.05f64);
        let bins = SizeDistribution::PowerLaw {
            q: 3.0,
            radius_min: a,
            radius_max: b,
            bins: 3,
        }
        .bins()
        .unwrap();
        assert_eq!(bins.len(), 3);
        for (k, bin) in bins.iter().enumerate() {
            let lo = a * (b / a).powf(k as f64 / 3.0);
            let hi = a * (b / a).powf((k + 1) as f64 / 3.0);
            assert!((bin.radius_min / lo - 1.0).abs() < 1e-12);
            assert!((bin.radius_max / hi - 1.0).abs() < 1e-12);
            // ∫R^−3 = (lo^−2 − hi^−2)/2; ∫R^−1 = ln(hi/lo).
            let count = (lo.powi(-2) - hi.powi(-2)) / 2.0;
            let frac = count / ((a.powi(-2) - b.powi(-2)) / 2.0);
            assert!((bin.number_fraction / frac - 1.0).abs() < 1e-12);
            let r = ((hi / lo).ln() / count).sqrt();
            assert!((bin.radius / r - 1.0).abs() < 1e-12);
        }
        let flat = SizeDistribution::PowerLaw {
            q: 1.0,
            radius_min: a,
            radius_max: b,
            bins: 4,
        }
        .bins()
        .unwrap();
        for bin in &flat {
            // dN/dR ∝ 1/R: equal in log R means equal numbers.
            assert!((bin.number_fraction - 0.25).abs() < 1e-12);
        }
    }

    /// `keep_epsilon` gives every pair the reference pair's ε_N(g); `same` keeps A.
    #[test]
    fn issue_38_keep_epsilon_keeps_every_pairs_law() {
        let ice = Preset::Ice.scene();
        let bins = SizeDistribution::List {
            radii: alloc::vec![0.01, 0.05, 1.0],
            fractions: alloc::vec![0.7, 0.2, 0.1],
        }
        .bins()
        .unwrap();
        let reference = Contact::new(&ice).unwrap();
        let keep = build(&ice, 0.5, 1e-4, &bins, DampingRule::KeepEpsilon).unwrap();
        let same = build(&ice, 0.5, 1e-4, &bins, DampingRule::Same).unwrap();
        for i in 0..3 {
            for j in 0..3 {
                assert_eq!(same.contacts[i][j].damping_time, ice.damping_time());
                for g in [1e-5, 1e-3, 1e-1] {
                    let want = reference.eps_n(g, Accuracy::Precise).unwrap();
                    let got = keep.contacts[i][j].eps_n(g, Accuracy::Precise).unwrap();
                    assert!(
                        (got - want).abs() < 1e-9,
                        "({i},{j}) g = {g}: {got} vs {want}"
                    );
                }
            }
        }
        // Equal grains: A ∝ R (today's scale-damping).
        assert!(
            (keep.contacts[2][2].damping_time / (ice.damping_time() * 1.0 / 0.02) - 1.0).abs()
                < 1e-12
        );
    }

    /// ν for one size: the energy balance (9/4)Ω²ν_trans = ω_c(1 − ε̄²)c²/2 at a local balance, and
    /// the collisional part in the closed Enskog form with one size's φ and Y.
    #[test]
    fn issue_38_one_size_viscosity_closed_forms() {
        let mut smooth = sized(&Preset::Ice.scene(), 0.02);
        smooth.friction = None;
        let omega = SATURN_A_RING_OMEGA;
        let today = one_size(
            &smooth,
            &RingInput {
                tau: 0.5,
                orbit: Orbit::Omega(omega),
                damping_set_for_radius: None,
            },
        )
        .unwrap();
        let p = today.prediction();
        assert_eq!(p.verdict, Verdict::Equilibrium);
        let rec = equilibrium(&smooth, &input(0.5, one(0.02), DampingRule::Same)).unwrap();
        let nu = rec.viscosity;
        let c = p.velocity_dispersion;
        let heating = 2.25 * omega * omega * nu.translational;
        let loss =
            p.collision_frequency * omega * (1.0 - p.eps_effective * p.eps_effective) * c * c / 2.0;
        assert!((heating / loss - 1.0).abs() < 1e-5, "{heating} vs {loss}");
        let phi = crate::applications::ring::filling_factor(0.5, c, omega, 0.02);
        let y = (1.0 - phi / 2.0) / (1.0 - phi).powi(3);
        let e = p.eps_effective;
        let want = 0.8 * phi * y * (1.0 + e) * nu.translational
            + 8.0 / (5.0 * PI.sqrt()) * phi * y * (1.0 + e) * 0.02 * c;
        assert!(
            (nu.collisional / want - 1.0).abs() < 1e-5,
            "{} vs {want}",
            nu.collisional
        );
        assert_eq!(nu.total, nu.translational + nu.collisional);
        // Dilute (τ → 0): c tends to a constant (ε_cr → 14/23) and both parts to ∝ τ (ν̂ ∝ τ,
        // φ ∝ τ), so d ln ν/d ln τ → 1.
        let dilute = equilibrium(&smooth, &input(1e-4, one(0.02), DampingRule::Same)).unwrap();
        let slope = dilute.viscosity.dlnnu_dlntau;
        assert!((slope - 1.0).abs() < 1e-2, "{slope}");
    }

    /// A 1–5 cm ring (q = 3): small grains move faster than large ones, but not with equal energies
    /// (partial equipartition, Salo 1992); the ring-wide keys are the number-weighted means.
    #[test]
    fn issue_38_small_grains_move_faster_without_equipartition() {
        let sizes = SizeDistribution::PowerLaw {
            q: 3.0,
            radius_min: 0.01,
            radius_max: 0.05,
            bins: 3,
        };
        let rec = equilibrium(&Preset::Ice.scene(), &input(0.5, sizes, DampingRule::Same)).unwrap();
        let b = &rec.size_bins;
        for k in 0..2 {
            assert!(b[k].velocity_dispersion >= b[k + 1].velocity_dispersion);
            let e = |x: &BinPrediction| x.radius.powi(3) * x.velocity_dispersion.powi(2);
            assert!(e(&b[k]) < e(&b[k + 1]));
        }
        let c2: f64 = b
            .iter()
            .map(|x| x.number_fraction * x.velocity_dispersion.powi(2))
            .sum();
        assert!((rec.velocity_dispersion / c2.sqrt() - 1.0).abs() < 1e-12);
        assert!(rec.verdict.is_equilibrium());
        assert!(rec.viscosity.total > 0.0 && rec.viscosity.dlnnu_dlntau.is_finite());
    }

    #[test]
    fn issue_38_bad_sizes_name_the_field() {
        let field = |sizes: SizeDistribution| match sizes.bins() {
            Err(Error::OutOfRange { field, .. }) | Err(Error::InvalidValue { field, .. }) => field,
            other => panic!("{other:?}"),
        };
        let list = |r: &[f64], f: &[f64]| SizeDistribution::List {
            radii: r.to_vec(),
            fractions: f.to_vec(),
        };
        let law = |a: f64, b: f64, n: usize| SizeDistribution::PowerLaw {
            q: 3.0,
            radius_min: a,
            radius_max: b,
            bins: n,
        };
        assert_eq!(field(list(&[0.01, 0.02], &[0.5, 0.4])), "fractions");
        assert_eq!(field(list(&[0.01, 0.02], &[1.0])), "fractions");
        assert_eq!(field(list(&[0.01, 0.01], &[0.5, 0.5])), "radii");
        assert_eq!(field(list(&[-0.01], &[1.0])), "radii");
        assert_eq!(field(list(&[], &[])), "radii");
        assert_eq!(field(law(0.05, 0.01, 3)), "radius_max");
        assert_eq!(field(law(0.0, 0.01, 3)), "radius_min");
        assert_eq!(field(law(0.01, 0.05, 0)), "bins");
        assert_eq!(field(law(0.01, 0.05, MAX_BINS + 1)), "bins");
        assert_eq!(field(law(0.01, f64::NAN, 3)), "radius_max");
    }
}
