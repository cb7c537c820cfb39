//! The dynamic collision of adhesive viscoelastic spheres (Brilliantov, Albers, Spahn & Pöschel 2007,
//! Phys. Rev. E 76, 051302): the JKR contact force plus the quasi-static viscous force, integrated
//! through loading, unloading and the neck to pull-off (docs/physics.md#model-brilliantov2007).
//!
//! With `E*` the contact modulus of Eq. (4) (`ρ_H = (4/3) E* √R_eff`), `w` the Dupré work of adhesion
//! (the scene's `adhesion.surface_energy`) and `a` the contact radius, the JKR relations are
//! `ξ(a) = a²/R − √(2π w a/E*)` and `F_el(a) = 4E*a³/(3R) − √(8π w E* a³)`; the viscous force is
//! `F_dis = 2 E* A a ξ'`, which for `w = 0` (`a = √(Rξ)`) is exactly the damping term
//! `1.5 ρ_H A √ξ ξ'` of Eq. (4). On the scales of docs/physics.md#decision-3 (`x = ξ/ξ*`,
//! `s = t/τ`, `b = a/√(R ξ*)`) the motion is
//!
//! `x'' = −(b³ − 1.5 κ b^(3/2)) − 1.5 δ b x'`,  `x = b² − κ √b`,  `x(0) = 0`, `x'(0) = 1`,
//!
//! with `δ = A α^(2/5) g^(1/5)` as in the paper's model and `κ = √(2π w/E*) R^(1/4) ξ*^(−3/4)`.
//! The contact forms at `x = 0` with `b = κ^(2/3)` (the JKR jump-in) and breaks at the end of the
//! stable JKR branch, `dx/db = 0`: `b_c = (κ/4)^(2/3)`, `x_c = −(3/4) κ (κ/4)^(1/3)` (the neck
//! ends, the force jumps from `F_el(b_c)` to 0). If the grains stop separating before `x_c` they
//! are caught: they aggregate (ε_N = 0). With `adhesion.jkr_end = pull_off_force` the contact ends
//! earlier, at the maximum tensile force `b_p = (3κ/4)^(2/3)`, `x_p = −(κ/4)(3κ/4)^(1/3)` (LAMMPS's
//! `jkr`; docs/physics.md#jkr-end); `x_c`, `U(b_c)` below then mean that end.
//!
//! The motion has the Lyapunov function `E = v²/2 + U(b)`, `U(b) = (2/5)b⁵ − κ b^(7/2) + (3/8)κ² b²`
//! (the JKR potential along the stable branch, `dU/dx = b³ − 1.5 κ b^(3/2)`): `dE/ds = −1.5 δ b v² ≤ 0`.
//! Pull-off needs `E ≥ U(b_c)` at `x_c`, so once `E` falls below `U(b_c)` the grains are caught for
//! good. That is the stop detected here: with strong damping they creep towards the JKR equilibrium
//! without ever turning back, so waiting for `ξ' = 0` would never end (issue 25).

#[allow(unused_imports)]
use super::brilliantov2007_motion::*;
pub use super::brilliantov2007_motion::{
    Collision, DELTA_LIMIT, LoopPoint, MAX_SPEED, Outcome, Sticking, end_hysteresis_constant,
    energy_margin, hysteresis_constant,
};
use crate::error::{Error, Result};
use crate::numerics::math::{powf, sqrt};
use crate::scene::contact::Contact;

use crate::scene::JkrEnd;
/// The constants of one collision of a scene at one impact speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dynamic {
    /// Contact modulus `E* = 3ρ_H/(4√R_eff)` \[Pa\].
    pub modulus: f64,
    /// Dupré work of adhesion `w` \[J/m²\].
    pub work_of_adhesion: f64,
    /// Where the contact ends.
    pub end: JkrEnd,
    r_eff: f64,
    m_eff: f64,
    alpha: f64,
    rho_h: f64,
    damping_time: f64,
}

impl Dynamic {
    /// The constants of a scene; `work_of_adhesion` is `adhesion.surface_energy` (0 without
    /// adhesion), `end` the scene's `adhesion.jkr_end`.
    pub fn new(contact: &Contact, work_of_adhesion: f64, end: JkrEnd) -> Result<Dynamic> {
        if !(work_of_adhesion.is_finite() && work_of_adhesion >= 0.0) {
            return Err(Error::OutOfRange {
                field: "adhesion.surface_energy",
                value: work_of_adhesion,
                expected: "must be a finite number >= 0",
            });
        }
        Ok(Dynamic {
            modulus: 0.75 * contact.rho_h / sqrt(contact.r_eff),
            work_of_adhesion,
            end,
            r_eff: contact.r_eff,
            m_eff: contact.m_eff,
            alpha: contact.alpha,
            rho_h: contact.rho_h,
            damping_time: contact.damping_time,
        })
    }

    /// `ξ* = (g²/α)^(2/5)` \[m\], as `g^(4/5) α^(−2/5)`: g² underflows below 1e-154 m/s.
    fn length_scale(&self, g: f64) -> f64 {
        powf(g, 0.8) * powf(self.alpha, -0.4)
    }

    /// `(δ, κ)` at impact speed `g`.
    pub fn parameters(&self, g: f64) -> (f64, f64) {
        let xi_star = self.length_scale(g);
        // δ = A g/ξ* = A α^(2/5) g^(1/5), without the ratio of two underflowing numbers.
        let delta = self.damping_time * powf(self.alpha, 0.4) * powf(g, 0.2);
        let kappa = sqrt(2.0 * core::f64::consts::PI * self.work_of_adhesion / self.modulus)
            * sqrt(sqrt(self.r_eff))
            / powf(xi_star, 0.75);
        (delta, kappa)
    }

    /// The JKR hysteresis energy `W = C (w⁵R⁴/E*²)^(1/3)` \[J\] of the scene's end of contact
    /// ([`end_hysteresis_constant`]: C = 7.09220… at the neck, 3.50260… at the maximum tensile force).
    pub fn hysteresis_energy(&self) -> f64 {
        let w = self.work_of_adhesion;
        let r = self.r_eff;
        // (w⁵R⁴/E*²)^(1/3) = w (w R² / E*)^(2/3).
        end_hysteresis_constant(self.end) * w * powf(w * r * r / self.modulus, 2.0 / 3.0)
    }

    fn check_speed(g: f64) -> Result<f64> {
        crate::normal::check_speed(g)
    }

    /// One collision at impact speed `g` \[m/s\], integrated at relative tolerance `rtol`.
    pub fn collide(&self, g: f64, rtol: f64) -> Result<Collision> {
        let g = Self::check_speed(g)?;
        let (delta, kappa) = self.parameters(g);
        if delta > DELTA_LIMIT && self.work_of_adhesion > 0.0 {
            // Not integrated: without adhesion the rebound would be at most K δ⁻⁵ g (the
            // zero-overlap creep bound, docs/physics.md#decision-2); adhesion only takes energy
            // away, so if that cannot pay the hysteresis W the grains are caught.
            let rebound = crate::normal::viscoelastic::creep_eps(delta) * g;
            if 0.5 * self.m_eff * rebound * rebound < self.hysteresis_energy() {
                return Ok(Collision {
                    eps: 0.0,
                    outcome: Outcome::Stuck,
                    t_c: f64::INFINITY,
                    xi_max: 0.0,
                    rhs_evaluations: 0,
                });
            }
        }
        let (eps, s_c, x_max, outcome, n) =
            integrate(delta, kappa, self.end, rtol, false, |_, _, _, _| {})?;
        let xi_star = self.length_scale(g);
        Ok(Collision {
            eps,
            outcome,
            t_c: s_c * xi_star / g,
            xi_max: x_max * xi_star,
            rhs_evaluations: n,
        })
    }

    /// ε_N and how the collision ended at impact speed `g` \[m/s\]: from the tables of the
    /// dimensionless master surface at `resolution` where they apply
    /// ([`crate::models::brilliantov2007_master`]), else by [`Dynamic::collide`] at `rtol`.
    pub fn eps_tabulated(
        &self,
        g: f64,
        resolution: crate::normal::viscoelastic::master::Resolution,
        rtol: f64,
    ) -> Result<(f64, Outcome)> {
        let g = Self::check_speed(g)?;
        let (delta, kappa) = self.parameters(g);
        use crate::models::brilliantov2007_master::{Lookup, lookup};
        match lookup(delta, kappa, self.end, resolution) {
            Lookup::PullOff(eps) => Ok((eps, Outcome::PullOff)),
            Lookup::Stuck => Ok((0.0, Outcome::Stuck)),
            Lookup::Live => {
                let c = self.collide(g, rtol)?;
                Ok((c.eps, c.outcome))
            }
        }
    }

    /// The critical aggregation speed: impacts slower than `g_cr` \[m/s\] stick
    /// ([`Sticking::Below`]), or the grains stick at every speed the model accepts, up to
    /// [`MAX_SPEED`] ([`Sticking::Always`]). `None` without adhesion, or where the search meets a
    /// collision it cannot decide (δ above [`DELTA_LIMIT`] with a rebound bound that could still pay
    /// the hysteresis; never on issue 25's grid). Found by bisection in ln g to relative 1e-10,
    /// bracketed from the elastic estimate `√(2W/m_eff)`: damping only adds loss, so `g_cr` lies
    /// above it (up to integration error).
    ///
    /// Why a scene can always stick: at large δ the rebound speed `ε_N g` tends to a constant
    /// (`ε_N ∝ δ⁻⁵ ∝ 1/g`, docs/physics.md#decision-2), so when that constant rebound cannot pay
    /// the hysteresis `W`, no impact speed separates the grains (docs/physics.md#model-brilliantov2007).
    pub fn critical_speed(&self, m_eff: f64, rtol: f64) -> Result<Option<Sticking>> {
        self.critical_speed_with(m_eff, |g| {
            let c = self.collide(g, rtol)?;
            Ok(match c.outcome {
                Outcome::Stuck => Some(true),
                Outcome::PullOff => Some(false),
                Outcome::Overdamped => None,
            })
        })
    }

    /// [`Dynamic::critical_speed`] with the sticking decided by the tables' boundary κ_cr(δ)
    /// ([`crate::models::brilliantov2007_master`]: stuck where κ > κ_cr) wherever δ lies in them,
    /// and by a live collision at `rtol` elsewhere. The same bracket and bisection to relative 1e-10;
    /// on the boundary's table, without integration (docs/physics.md#brilliantov2007-tables).
    pub fn critical_speed_tabulated(&self, m_eff: f64, rtol: f64) -> Result<Option<Sticking>> {
        let table = crate::models::brilliantov2007_master::table(self.end);
        self.critical_speed_with(m_eff, |g| {
            let (delta, kappa) = self.parameters(g);
            if let Some(kappa_cr) = table.critical_kappa(delta) {
                return Ok(Some(kappa > kappa_cr));
            }
            let c = self.collide(g, rtol)?;
            Ok(match c.outcome {
                Outcome::Stuck => Some(true),
                Outcome::PullOff => Some(false),
                Outcome::Overdamped => None,
            })
        })
    }

    /// The bracket and bisection of [`Dynamic::critical_speed`] with `stuck(g)`: whether an impact
    /// at `g` sticks (`None`: undecided, overdamped).
    fn critical_speed_with(
        &self,
        m_eff: f64,
        stuck: impl Fn(f64) -> Result<Option<bool>>,
    ) -> Result<Option<Sticking>> {
        if self.work_of_adhesion == 0.0 {
            return Ok(None);
        }
        let estimate = sqrt(2.0 * self.hysteresis_energy() / m_eff);
        if !(estimate > 0.0) {
            return Ok(None);
        }
        // Even the elastic (undamped) threshold lies beyond every accepted speed.
        if !(estimate < MAX_SPEED) {
            return Ok(Some(Sticking::Always));
        }
        let (mut lo, mut hi) = (estimate, estimate);
        loop {
            match stuck(hi)? {
                Some(false) => break,
                Some(true) if hi == MAX_SPEED => return Ok(Some(Sticking::Always)),
                Some(true) => {
                    lo = hi;
                    hi = (2.0 * hi).min(MAX_SPEED);
                }
                None => return Ok(None),
            }
        }
        if lo == hi {
            // The estimate already separates (integration error of the elastic limit): step down.
            let mut found = false;
            for _ in 0..80 {
                lo *= 0.5;
                if stuck(lo)? == Some(true) {
                    found = true;
                    break;
                }
            }
            if !found {
                return Ok(None);
            }
        }
        while hi / lo - 1.0 > 1e-10 {
            let mid = sqrt(lo * hi);
            match stuck(mid)? {
                Some(true) => lo = mid,
                Some(false) => hi = mid,
                None => return Ok(None),
            }
        }
        Ok(Some(Sticking::Below(sqrt(lo * hi))))
    }

    /// The force–overlap loop of one collision: the first contact (jump-in), every accepted step,
    /// the maximum compression, the neck and, at pull-off, a last point at the same overlap with
    /// force 0 (the pull-off jump).
    #[cfg(feature = "alloc")]
    pub fn force_loop(&self, g: f64, rtol: f64) -> Result<alloc::vec::Vec<LoopPoint>> {
        let g = Self::check_speed(g)?;
        let (delta, kappa) = self.parameters(g);
        let xi_star = self.length_scale(g);
        let tau = xi_star / g;
        let force_scale = self.rho_h * xi_star * sqrt(xi_star);
        let radius_scale = sqrt(self.r_eff * xi_star);
        let k = 1.5 * delta;
        let mut points = alloc::vec::Vec::new();
        let (_, _, _, outcome, _) =
            integrate(delta, kappa, self.end, rtol, true, |sigma, x, v, b| {
                let elastic = b * b * b - 1.5 * kappa * b * sqrt(b);
                points.push(LoopPoint {
                    t: sigma * sigma * tau,
                    xi: x * xi_star,
                    xi_dot: v * g,
                    force: (elastic + k * b * v) * force_scale,
                    contact_radius: b * radius_scale,
                });
            })?;
        if outcome == Outcome::PullOff
            && let Some(last) = points.last().copied()
        {
            points.push(LoopPoint {
                force: 0.0,
                contact_radius: 0.0,
                ..last
            });
        }
        Ok(points)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn radius_inverts_the_jkr_overlap() {
        for kappa in [0.0, 1e-6, 0.3, 2.0, 50.0] {
            let sys = System::new(0.0, kappa, JkrEnd::Neck);
            for x in [sys.x_neck * 0.5, 0.0, 1e-3, 0.5, 3.0, 1e3] {
                let b = sys.radius(x);
                let back = b * b - kappa * sqrt(b);
                assert!(
                    (back - x).abs() <= 1e-12 * (1.0 + x.abs() + kappa),
                    "κ={kappa} x={x}: {back}"
                );
                assert!(b >= sys.b_c);
            }
        }
    }

    #[test]
    fn elastic_hertz_limit_conserves_energy() {
        // δ = κ = 0: Hertz, ε = 1 and x_max = (5/4)^(2/5) (energy conservation).
        let (eps, s_c, x_max, outcome, _) =
            integrate(0.0, 0.0, JkrEnd::Neck, 1e-12, false, |_, _, _, _| {}).unwrap();
        assert_eq!(outcome, Outcome::PullOff);
        assert!((eps - 1.0).abs() < 1e-9, "{eps}");
        assert!((x_max - libm::pow(1.25, 0.4)).abs() < 1e-10);
        assert!(
            (s_c - crate::normal::analytic::HERTZ_CONTACT_TIME).abs() < 1e-8,
            "{s_c}"
        );
    }

    #[test]
    fn hysteresis_constant_is_the_closed_form() {
        // mpmath: pi**(5/3)*(1/10 + 3/5*2**(2/3)) = 7.0921959718639588…
        assert!(
            (hysteresis_constant() - 7.092_195_971_863_959).abs() < 1e-13,
            "{}",
            hysteresis_constant()
        );
    }
}
