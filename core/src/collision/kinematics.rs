//! Kinematics of a collision of two spheres in three dimensions: the relative surface velocity of
//! Eq. (2), and applying restitution coefficients (ε_N, ε_T) to both grains by one impulse.
//!
//! Conventions: `n` is the unit normal pointing from grain `j`'s centre to grain `i`'s centre, so the
//! contact point is `x_i − a_i n = x_j + a_j n`. The relative surface velocity `g` (Eq. (2)) is the
//! velocity of `i`'s surface minus that of `j`'s surface at the contact point; the grains approach
//! when `g·n < 0`.
//!
//! [`collide`] applies an impulse `J` to `i` and `−J` to `j` at the contact point, chosen so that the
//! normal component becomes `−ε_N g_N` and the tangential vector `ε_T g_T` (Eq. (1)). Linear momentum
//! and angular momentum (about any point) are conserved exactly; the kinetic energy changes by
//! `−½ m_eff (1−ε_N²) g_N² − ½ m_t (1−ε_T²) |g_T|²`, with the tangential mass `m_t` of
//! [`effective_tangential_mass`] (`= κ m_eff` for equal inertia factors, Eq. (22)).

use crate::error::{Error, Result, positive, within};
pub use nalgebra::Vector3;

/// The inertia factor `q` of a homogeneous solid sphere, `I = 2/5 m a²`.
pub const SOLID_SPHERE: f64 = 0.4;

/// Position-free state of one spherical grain.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GrainState {
    /// Mass `m` \[kg\].
    pub mass: f64,
    /// Radius `a` \[m\].
    pub radius: f64,
    /// Inertia factor `q` in `I = q m a²` \[1\]: 2/5 for a homogeneous solid sphere, 2/3 for a thin
    /// shell.
    pub inertia_factor: f64,
    /// Velocity of the centre `v` \[m/s\].
    pub velocity: Vector3<f64>,
    /// Angular velocity `ω` \[rad/s\].
    pub spin: Vector3<f64>,
}

impl GrainState {
    /// A homogeneous solid sphere (`q = 2/5`).
    pub fn solid_sphere(
        mass: f64,
        radius: f64,
        velocity: Vector3<f64>,
        spin: Vector3<f64>,
    ) -> GrainState {
        GrainState {
            mass,
            radius,
            inertia_factor: SOLID_SPHERE,
            velocity,
            spin,
        }
    }

    /// The same grain with the contact point at `arm` from its centre instead of at its radius,
    /// keeping its moment of inertia `q m a²`: radius `arm`, inertia factor `q a²/arm²`.
    ///
    /// An N-body code finds a pair overlapping (centre distance `d < a_i + a_j`); the contact point
    /// splits the line of centres in the ratio of the radii, at `a_i d/(a_i + a_j)` from each centre.
    /// With these arms in Eq. (2) and in [`collide`], the torques of the impulse about the two
    /// centres cancel the change of orbital angular momentum exactly, and at touching (`d = a_i +
    /// a_j`) it is the grain itself.
    pub fn with_lever_arm(&self, arm: f64) -> GrainState {
        GrainState {
            radius: arm,
            inertia_factor: self.inertia_factor * (self.radius / arm) * (self.radius / arm),
            ..*self
        }
    }

    /// Moment of inertia `I = q m a²` \[kg m²\].
    pub fn moment_of_inertia(&self) -> f64 {
        self.inertia_factor * self.mass * self.radius * self.radius
    }

    /// Kinetic energy `½ m v² + ½ I ω²` \[J\].
    pub fn kinetic_energy(&self) -> f64 {
        0.5 * self.mass * self.velocity.norm_squared()
            + 0.5 * self.moment_of_inertia() * self.spin.norm_squared()
    }

    /// Checks mass, radius and inertia factor (finite, > 0) and that velocity and spin are finite;
    /// errors name `<which>.mass` etc., with `which` = `grain_i` or `grain_j`.
    fn validate(&self, fields: &GrainFields) -> Result<()> {
        positive(fields.mass, self.mass)?;
        positive(fields.radius, self.radius)?;
        positive(fields.inertia_factor, self.inertia_factor)?;
        for (field, v) in [(fields.velocity, &self.velocity), (fields.spin, &self.spin)] {
            if let Some(bad) = v.iter().copied().find(|c| !c.is_finite()) {
                return Err(Error::OutOfRange {
                    field,
                    value: bad,
                    expected: "every component must be finite",
                });
            }
        }
        Ok(())
    }
}

struct GrainFields {
    mass: &'static str,
    radius: &'static str,
    inertia_factor: &'static str,
    velocity: &'static str,
    spin: &'static str,
}

const FIELDS_I: GrainFields = GrainFields {
    mass: "grain_i.mass",
    radius: "grain_i.radius",
    inertia_factor: "grain_i.inertia_factor",
    velocity: "grain_i.velocity",
    spin: "grain_i.spin",
};

const FIELDS_J: GrainFields = GrainFields {
    mass: "grain_j.mass",
    radius: "grain_j.radius",
    inertia_factor: "grain_j.inertia_factor",
    velocity: "grain_j.velocity",
    spin: "grain_j.spin",
};

/// The relative velocity of the surfaces at the contact point, Eq. (2):
/// `g = (v_i − ω_i × n a_i) − (v_j + ω_j × n a_j)`, with `n` the unit normal from `j`'s centre to `i`'s.
#[doc(alias = "Eq. (2)")]
pub fn relative_surface_velocity(i: &GrainState, j: &GrainState, n: &Vector3<f64>) -> Vector3<f64> {
    // Eq. (2).
    (i.velocity - i.spin.cross(n) * i.radius) - (j.velocity + j.spin.cross(n) * j.radius)
}

/// Splits `g` into its normal component `g_N = g·n` (negative when approaching) and its tangential
/// vector `g_T = g − g_N n`.
pub fn decompose(g: &Vector3<f64>, n: &Vector3<f64>) -> (f64, Vector3<f64>) {
    let g_n = g.dot(n);
    (g_n, g - n * g_n)
}

/// `κ = q/(1+q)` (Eq. (22)): the reduced moment of inertia of two grains with the same inertia
/// factor `q`; 2/7 for solid spheres.
#[doc(alias = "Eq. (22)")]
pub fn kappa(inertia_factor: f64) -> f64 {
    inertia_factor / (1.0 + inertia_factor)
}

/// The effective mass of the tangential motion at the contact, `m_t` with
/// `1/m_t = 1/m_i + 1/m_j + a_i²/I_i + a_j²/I_j` \[kg\]. For equal inertia factors `q` it is
/// `κ m_eff` with `κ = q/(1+q)` ([`kappa`]).
pub fn effective_tangential_mass(i: &GrainState, j: &GrainState) -> f64 {
    let inv = 1.0 / i.mass
        + 1.0 / j.mass
        + i.radius * i.radius / i.moment_of_inertia()
        + j.radius * j.radius / j.moment_of_inertia();
    1.0 / inv
}

/// The normal restitution an N-body code applies with a floor `v_min` \[its speed unit\] on the
/// normal separation speed (REBOUND's `minimum_collision_velocity`): `max(ε_N, v_min/|g_N|)`, at
/// most 1, for an approach `g_N < 0`; `eps_n` itself when `v_min ≤ 0` or the pair is not
/// approaching. The floor keeps resting grains from sinking into each other under a steady pull.
pub fn restitution_with_floor(eps_n: f64, g_n: f64, v_min: f64) -> f64 {
    if v_min > 0.0 && g_n < 0.0 {
        eps_n.max((v_min / -g_n).min(1.0))
    } else {
        eps_n
    }
}

/// Applies restitution coefficients to a pair of touching grains.
///
/// An impulse `J = −m_eff (1+ε_N) g_N n − m_t (1−ε_T) g_T` acts on `i` and `−J` on `j`, both at the
/// contact point (`m_eff = m_i m_j/(m_i+m_j)`, `m_t` from [`effective_tangential_mass`]), so that
/// afterwards `g'·n = −ε_N g_N` and `g'_T = ε_T g_T` (Eq. (1)). Velocities and spins are updated in
/// place. The direction of approach is not checked: the map is applied as given.
///
/// Errors (field named): `n` not unit length within 1e-9 or not finite; non-positive or non-finite
/// `grain_i.mass`, `grain_j.radius`, …; non-finite velocities or spins; `eps_n ∉ [0, 1]`,
/// `eps_t ∉ [−1, 1]`. On error the grains are unchanged.
pub fn collide(
    i: &mut GrainState,
    j: &mut GrainState,
    n: &Vector3<f64>,
    eps_n: f64,
    eps_t: f64,
) -> Result<()> {
    i.validate(&FIELDS_I)?;
    j.validate(&FIELDS_J)?;
    let norm = n.norm();
    if !(norm.is_finite() && (norm - 1.0).abs() <= 1e-9) {
        return Err(Error::OutOfRange {
            field: "n",
            value: norm,
            expected: "the contact normal must be a unit vector (|n| = 1 within 1e-9)",
        });
    }
    within("eps_n", eps_n, 0.0, 1.0, "must lie in [0, 1]")?;
    within("eps_t", eps_t, -1.0, 1.0, "must lie in [-1, 1]")?;
    let g = relative_surface_velocity(i, j, n);
    let (g_n, g_t) = decompose(&g, n);
    let m_eff = i.mass * j.mass / (i.mass + j.mass);
    let m_t = effective_tangential_mass(i, j);
    // Δg = J_N/m_eff + J_T/m_t (see the module docs); Eq. (1) fixes both components.
    let impulse = n * (-m_eff * (1.0 + eps_n) * g_n) - g_t * (m_t * (1.0 - eps_t));
    let (ii, ij) = (i.moment_of_inertia(), j.moment_of_inertia());
    // +J at r_i = −a_i n from i's centre, −J at r_j = +a_j n from j's centre.
    i.velocity += impulse / i.mass;
    i.spin += (n * -i.radius).cross(&impulse) / ii;
    j.velocity -= impulse / j.mass;
    j.spin += (n * j.radius).cross(&(-impulse)) / ij;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grain(mass: f64, radius: f64, q: f64, v: [f64; 3], w: [f64; 3]) -> GrainState {
        GrainState {
            mass,
            radius,
            inertia_factor: q,
            velocity: Vector3::from(v),
            spin: Vector3::from(w),
        }
    }

    fn pair() -> (GrainState, GrainState, Vector3<f64>) {
        let i = grain(0.03, 0.02, 0.4, [-0.01, 0.004, 0.002], [0.3, -0.2, 0.5]);
        let j = grain(0.07, 0.035, 0.3, [0.006, -0.003, 0.001], [-0.1, 0.4, 0.2]);
        let n = Vector3::new(2.0, -1.0, 0.5).normalize();
        (i, j, n)
    }

    /// Total linear momentum and angular momentum about the origin, with centres x_i, x_j.
    fn momenta(
        i: &GrainState,
        j: &GrainState,
        xi: &Vector3<f64>,
        xj: &Vector3<f64>,
    ) -> (Vector3<f64>, Vector3<f64>) {
        let p = i.velocity * i.mass + j.velocity * j.mass;
        let l = xi.cross(&(i.velocity * i.mass))
            + i.spin * i.moment_of_inertia()
            + xj.cross(&(j.velocity * j.mass))
            + j.spin * j.moment_of_inertia();
        (p, l)
    }

    fn close(a: &Vector3<f64>, b: &Vector3<f64>, tol: f64) -> bool {
        (a - b).norm() <= tol * b.norm().max(a.norm())
    }

    #[test]
    fn issue_35_the_floor_sets_the_separation_speed_and_never_exceeds_one() {
        // Approach at 2 (g_N = −2): a floor of 0.5 gives ε 0.25 over ε_N = 0, none over ε_N = 0.6.
        assert_eq!(restitution_with_floor(0.0, -2.0, 0.5), 0.25);
        assert_eq!(restitution_with_floor(0.6, -2.0, 0.5), 0.6);
        assert_eq!(restitution_with_floor(0.0, -2.0, 5.0), 1.0);
        assert_eq!(restitution_with_floor(0.3, -2.0, 0.0), 0.3);
        assert_eq!(restitution_with_floor(0.3, 1.0, 0.5), 0.3);
    }

    #[test]
    fn issue_35_a_lever_arm_keeps_the_moment_of_inertia() {
        let g = GrainState::solid_sphere(3.0, 0.5, Vector3::zeros(), Vector3::zeros());
        let arm = g.with_lever_arm(0.49);
        assert_eq!(arm.radius, 0.49);
        // Equal up to the rounding of q (a/arm)² m arm² against q m a²: a few ulp.
        assert!(
            (arm.moment_of_inertia() - g.moment_of_inertia()).abs()
                <= 4.0 * f64::EPSILON * g.moment_of_inertia()
        );
        assert_eq!(g.with_lever_arm(0.5), g);
    }

    #[test]
    fn eq2_by_components() {
        // n = x̂, a_i = 1, a_j = 2, ω_i = ẑ, ω_j = ẑ: ω × n = ŷ for both.
        let i = grain(1.0, 1.0, 0.4, [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
        let j = grain(1.0, 2.0, 0.4, [0.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
        let n = Vector3::x();
        let g = relative_surface_velocity(&i, &j, &n);
        // (x̂ − ŷ) − (0 + 2ŷ) = x̂ − 3ŷ.
        assert_eq!(g, Vector3::new(1.0, -3.0, 0.0));
        let (g_n, g_t) = decompose(&g, &n);
        assert_eq!((g_n, g_t), (1.0, Vector3::new(0.0, -3.0, 0.0)));
        // Contact-point velocity from rigid-body motion: v + ω × (point − centre).
        let ci = i.velocity + i.spin.cross(&(-n * i.radius));
        let cj = j.velocity + j.spin.cross(&(n * j.radius));
        assert_eq!(g, ci - cj);
    }

    #[test]
    fn tangential_mass_is_kappa_m_eff_for_equal_inertia_factors() {
        assert!((kappa(0.4) - 2.0 / 7.0).abs() < 1e-16);
        for &q in &[0.4, 2.0 / 3.0, 0.1] {
            let i = grain(0.03, 0.02, q, [0.0; 3], [0.0; 3]);
            let j = grain(0.11, 0.05, q, [0.0; 3], [0.0; 3]);
            let m_eff = 0.03 * 0.11 / 0.14;
            let m_t = effective_tangential_mass(&i, &j);
            assert!((m_t - kappa(q) * m_eff).abs() < 1e-15 * m_t);
        }
    }

    #[test]
    fn post_collision_velocity_matches_requested_coefficients() {
        for &(eps_n, eps_t) in &[(0.8, 0.5), (1.0, 1.0), (0.0, 0.0), (0.3, -0.7), (1.0, -1.0)] {
            let (mut i, mut j, n) = pair();
            let (g_n, g_t) = decompose(&relative_surface_velocity(&i, &j, &n), &n);
            collide(&mut i, &mut j, &n, eps_n, eps_t).unwrap();
            let (g_n2, g_t2) = decompose(&relative_surface_velocity(&i, &j, &n), &n);
            assert!((g_n2 + eps_n * g_n).abs() < 1e-14 * g_n.abs());
            assert!((g_t2 - g_t * eps_t).norm() < 1e-14 * g_t.norm());
        }
    }

    #[test]
    fn momentum_and_angular_momentum_are_conserved() {
        for &(eps_n, eps_t) in &[(0.8, 0.5), (0.0, 0.0), (0.3, -0.7)] {
            let (mut i, mut j, n) = pair();
            // Touching: x_i − x_j = (a_i + a_j) n; an arbitrary offset away from the origin.
            let xj = Vector3::new(1.5, -2.0, 0.7);
            let xi = xj + n * (i.radius + j.radius);
            let (p0, l0) = momenta(&i, &j, &xi, &xj);
            collide(&mut i, &mut j, &n, eps_n, eps_t).unwrap();
            let (p1, l1) = momenta(&i, &j, &xi, &xj);
            assert!(close(&p1, &p0, 1e-12), "{p0} → {p1}");
            assert!(close(&l1, &l0, 1e-12), "{l0} → {l1}");
        }
    }

    #[test]
    fn energy_change_is_the_closed_form() {
        // With the impulse J at the contact, ΔE = J·(g + g')/2, which for J_N ∥ n and J_T ∥ g_T gives
        // ΔE = −½ m_eff (1−ε_N²) g_N² − ½ m_t (1−ε_T²) |g_T|²: zero for (ε_N, ε_T) = (1, ±1).
        for &(eps_n, eps_t) in &[(1.0, 1.0), (1.0, -1.0), (0.8, 0.5), (0.0, 0.0), (0.3, -0.7)] {
            let (mut i, mut j, n) = pair();
            let (g_n, g_t) = decompose(&relative_surface_velocity(&i, &j, &n), &n);
            let m_eff = i.mass * j.mass / (i.mass + j.mass);
            let m_t = effective_tangential_mass(&i, &j);
            let e0 = i.kinetic_energy() + j.kinetic_energy();
            collide(&mut i, &mut j, &n, eps_n, eps_t).unwrap();
            let e1 = i.kinetic_energy() + j.kinetic_energy();
            let expected = -0.5 * m_eff * (1.0 - eps_n * eps_n) * g_n * g_n
                - 0.5 * m_t * (1.0 - eps_t * eps_t) * g_t.norm_squared();
            assert!(
                ((e1 - e0) - expected).abs() < 1e-12 * e0,
                "({eps_n}, {eps_t}): {} vs {expected}",
                e1 - e0
            );
        }
    }

    #[test]
    fn invalid_input_names_the_field_and_leaves_grains_unchanged() {
        let field = |e: Error| match e {
            Error::OutOfRange { field, .. } => field,
            other => panic!("unexpected {other:?}"),
        };
        let (i0, j0, n) = pair();
        let run = |i: GrainState, j: GrainState, n: Vector3<f64>, en: f64, et: f64| {
            let (mut i2, mut j2) = (i, j);
            let out = collide(&mut i2, &mut j2, &n, en, et);
            assert_eq!((i2, j2), (i, j));
            field(out.unwrap_err())
        };
        assert_eq!(run(i0, j0, n * 2.0, 0.5, 0.5), "n");
        assert_eq!(run(i0, j0, Vector3::zeros(), 0.5, 0.5), "n");
        assert_eq!(run(i0, j0, n, 1.5, 0.5), "eps_n");
        assert_eq!(run(i0, j0, n, 0.5, -1.5), "eps_t");
        let bad_mass = GrainState { mass: 0.0, ..i0 };
        assert_eq!(run(bad_mass, j0, n, 0.5, 0.5), "grain_i.mass");
        let bad_q = GrainState {
            inertia_factor: 0.0,
            ..j0
        };
        assert_eq!(run(i0, bad_q, n, 0.5, 0.5), "grain_j.inertia_factor");
        let bad_r = GrainState { radius: -1.0, ..j0 };
        assert_eq!(run(i0, bad_r, n, 0.5, 0.5), "grain_j.radius");
        let bad_v = GrainState {
            velocity: Vector3::new(0.0, f64::INFINITY, 0.0),
            ..i0
        };
        assert_eq!(run(bad_v, j0, n, 0.5, 0.5), "grain_i.velocity");
    }
}
