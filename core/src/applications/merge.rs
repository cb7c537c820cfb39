//! Merging two grains that stick into one (the `merge` outcome of an N-body code's collision
//! handler: REBOUND's `rime_grains.rebound.attach`).
//!
//! The merged grain keeps, exactly up to rounding:
//! * the **mass** `m = m_a + m_b` and the **volume** (radius `∛(a_a³ + a_b³)`), so two grains of one
//!   density give a grain of that density;
//! * the **momentum**: it sits at the centre of mass and moves with its velocity;
//! * the **angular momentum** about the centre of mass, orbital plus spins:
//!   `L = Σ m_k (x_k − x_c) × (v_k − v_c) + Σ I_k ω_k`, which becomes the merged grain's spin
//!   `ω = L / I` with `I = q m a²`. Angular momentum about any other point follows, since the
//!   centre of mass moves with the total momentum.
//!
//! The merged grain is a homogeneous sphere with the two grains' inertia factor `q` (they must
//! share it: 2/5, [`SOLID_SPHERE`], for the solid spheres of the
//! handlers). Kinetic energy is not kept: the merge is perfectly inelastic, like ε_N = 0 and a
//! locked contact.
//!
//! ```
//! use rime_core::kinematics::Vector3;
//! use rime_core::merge::{Body, merge};
//!
//! let grain = |x: f64, v: f64| Body::solid_sphere(1.0, 0.5, Vector3::new(x, 0.0, 0.0),
//!     Vector3::new(v, 0.0, 0.0), Vector3::zeros());
//! let one = merge(&grain(-0.5, 1.0), &grain(0.5, -1.0))?;
//! assert_eq!((one.mass, one.velocity), (2.0, Vector3::zeros()));
//! assert!((one.radius - 0.5 * 2f64.cbrt()).abs() < 1e-15);
//! # Ok::<(), rime_core::Error>(())
//! ```

use crate::collision::kinematics::{SOLID_SPHERE, Vector3};
use crate::error::{Error, Result, positive};
use crate::numerics::math::cbrt;

/// A grain with a position: what a merge needs of each of the two.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    /// Mass `m` \[kg, or the code's unit\].
    pub mass: f64,
    /// Radius `a` \[m, or the code's unit\].
    pub radius: f64,
    /// Inertia factor `q` in `I = q m a²` \[1\] (2/5 for a homogeneous solid sphere).
    pub inertia_factor: f64,
    /// Centre `x`.
    pub position: Vector3<f64>,
    /// Velocity of the centre `v`.
    pub velocity: Vector3<f64>,
    /// Angular velocity `ω` \[rad per time unit\].
    pub spin: Vector3<f64>,
}

impl Body {
    /// A homogeneous solid sphere (`q = 2/5`).
    pub fn solid_sphere(
        mass: f64,
        radius: f64,
        position: Vector3<f64>,
        velocity: Vector3<f64>,
        spin: Vector3<f64>,
    ) -> Body {
        Body {
            mass,
            radius,
            inertia_factor: SOLID_SPHERE,
            position,
            velocity,
            spin,
        }
    }

    /// Moment of inertia `I = q m a²`.
    pub fn moment_of_inertia(&self) -> f64 {
        self.inertia_factor * self.mass * self.radius * self.radius
    }

    /// Momentum `m v`.
    pub fn momentum(&self) -> Vector3<f64> {
        self.velocity * self.mass
    }

    /// Angular momentum about `origin`: orbital `m (x − origin) × v` plus spin `I ω`.
    pub fn angular_momentum(&self, origin: &Vector3<f64>) -> Vector3<f64> {
        (self.position - origin).cross(&self.momentum()) + self.spin * self.moment_of_inertia()
    }

    fn validate(&self, which: Fields) -> Result<()> {
        positive(which.mass, self.mass)?;
        positive(which.radius, self.radius)?;
        positive(which.inertia_factor, self.inertia_factor)?;
        for (field, v) in [
            (which.position, &self.position),
            (which.velocity, &self.velocity),
            (which.spin, &self.spin),
        ] {
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

#[derive(Clone, Copy)]
struct Fields {
    mass: &'static str,
    radius: &'static str,
    inertia_factor: &'static str,
    position: &'static str,
    velocity: &'static str,
    spin: &'static str,
}

const FIELDS_A: Fields = Fields {
    mass: "a.mass",
    radius: "a.radius",
    inertia_factor: "a.inertia_factor",
    position: "a.position",
    velocity: "a.velocity",
    spin: "a.spin",
};

const FIELDS_B: Fields = Fields {
    mass: "b.mass",
    radius: "b.radius",
    inertia_factor: "b.inertia_factor",
    position: "b.position",
    velocity: "b.velocity",
    spin: "b.spin",
};

/// The grain that `a` and `b` become when they stick (see the module documentation for what is
/// kept).
///
/// Errors (field named): a non-positive or non-finite `a.mass`, `b.radius`, …; non-finite
/// positions, velocities or spins; `b.inertia_factor` different from `a`'s.
pub fn merge(a: &Body, b: &Body) -> Result<Body> {
    a.validate(FIELDS_A)?;
    b.validate(FIELDS_B)?;
    if a.inertia_factor != b.inertia_factor {
        return Err(Error::OutOfRange {
            field: "b.inertia_factor",
            value: b.inertia_factor,
            expected: "must equal a.inertia_factor (the merged grain is one homogeneous sphere)",
        });
    }
    let mass = a.mass + b.mass;
    let position = (a.position * a.mass + b.position * b.mass) / mass;
    let velocity = (a.velocity * a.mass + b.velocity * b.mass) / mass;
    // About the centre of mass and relative to its velocity: the orbital part is then small
    // beside the positions' size, so it loses no digits to a far-away origin.
    let relative = |g: &Body| (g.position - position).cross(&((g.velocity - velocity) * g.mass));
    let l =
        relative(a) + relative(b) + a.spin * a.moment_of_inertia() + b.spin * b.moment_of_inertia();
    let radius = cbrt(a.radius * a.radius * a.radius + b.radius * b.radius * b.radius);
    let inertia = a.inertia_factor * mass * radius * radius;
    if !(mass.is_finite() && radius.is_finite() && inertia.is_finite() && inertia > 0.0) {
        return Err(Error::DerivedOutOfRange {
            quantity: "merged mass, radius or moment of inertia",
            fields: "a.mass, b.mass, a.radius, b.radius",
        });
    }
    Ok(Body {
        mass,
        radius,
        inertia_factor: a.inertia_factor,
        position,
        velocity,
        spin: l / inertia,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64, z: f64) -> Vector3<f64> {
        Vector3::new(x, y, z)
    }

    fn pair() -> (Body, Body) {
        let a = Body::solid_sphere(
            0.03,
            0.02,
            v(1.2, -0.4, 0.3),
            v(-0.01, 0.004, 0.002),
            v(0.3, -0.2, 0.5),
        );
        let b = Body::solid_sphere(
            0.07,
            0.035,
            v(1.25, -0.37, 0.31),
            v(0.006, -0.003, 0.001),
            v(-0.1, 0.4, 0.2),
        );
        (a, b)
    }

    fn close(x: &Vector3<f64>, y: &Vector3<f64>, tol: f64) -> bool {
        (x - y).norm() <= tol * x.norm().max(y.norm())
    }

    #[test]
    fn issue_35_merge_keeps_mass_volume_momentum_and_angular_momentum() {
        let (a, b) = pair();
        let m = merge(&a, &b).unwrap();
        assert_eq!(m.mass, a.mass + b.mass);
        let volume = |r: f64| r * r * r;
        assert!(
            (volume(m.radius) - (volume(a.radius) + volume(b.radius))).abs()
                <= 1e-15 * volume(m.radius)
        );
        assert!(close(&m.momentum(), &(a.momentum() + b.momentum()), 1e-15));
        // About any point: the origin, a far one, and the centre of mass.
        for origin in [Vector3::zeros(), v(-30.0, 7.0, 100.0), m.position] {
            let before = a.angular_momentum(&origin) + b.angular_momentum(&origin);
            assert!(
                close(&m.angular_momentum(&origin), &before, 1e-13),
                "{origin}: {before} → {}",
                m.angular_momentum(&origin)
            );
        }
        // The centre of mass by hand: (m_a x_a + m_b x_b)/(m_a + m_b).
        assert!(close(&m.position, &v(1.235, -0.379, 0.307), 1e-15));
    }

    #[test]
    fn issue_35_merge_is_symmetric_and_a_resting_pair_gets_no_spin() {
        let (a, b) = pair();
        let (ab, ba) = (merge(&a, &b).unwrap(), merge(&b, &a).unwrap());
        assert!(close(&ab.spin, &ba.spin, 1e-14) && close(&ab.position, &ba.position, 1e-15));
        // Two grains at rest, not spinning: nothing to turn.
        let rest = |x: f64| {
            Body::solid_sphere(1.0, 1.0, v(x, 0.0, 0.0), Vector3::zeros(), Vector3::zeros())
        };
        assert_eq!(
            merge(&rest(-1.0), &rest(1.0)).unwrap().spin,
            Vector3::zeros()
        );
    }

    #[test]
    fn issue_35_merge_of_a_grazing_pair_spins_by_l_over_i() {
        // Equal spheres (m, a) at ∓a on x, moving ±u along y: L about the centre of mass is
        // 2 m a u (−ẑ), I = 2/5 (2m) (∛2 a)², so ω_z = −2 m a u / (4/5 m ∛4 a²) = −(5/2) u/(∛4 a).
        let (m, a, u) = (2.0, 0.5, 0.3);
        let g = |x: f64, vy: f64| {
            Body::solid_sphere(m, a, v(x, 0.0, 0.0), v(0.0, vy, 0.0), Vector3::zeros())
        };
        let one = merge(&g(-a, u), &g(a, -u)).unwrap();
        let want = -2.5 * u / (4f64.cbrt() * a);
        assert!(
            (one.spin.z - want).abs() <= 1e-15 * want.abs(),
            "{} vs {want}",
            one.spin.z
        );
        assert_eq!((one.spin.x, one.spin.y), (0.0, 0.0));
    }

    #[test]
    fn issue_35_merge_refuses_bad_grains_naming_the_field() {
        let (a, b) = pair();
        let field = |r: Result<Body>| match r {
            Err(Error::OutOfRange { field, .. }) => field,
            other => panic!("unexpected {other:?}"),
        };
        assert_eq!(field(merge(&Body { mass: 0.0, ..a }, &b)), "a.mass");
        assert_eq!(
            field(merge(
                &a,
                &Body {
                    radius: f64::NAN,
                    ..b
                }
            )),
            "b.radius"
        );
        assert_eq!(
            field(merge(
                &a,
                &Body {
                    inertia_factor: 2.0 / 3.0,
                    ..b
                }
            )),
            "b.inertia_factor"
        );
        let far = Body {
            position: v(f64::INFINITY, 0.0, 0.0),
            ..b
        };
        assert_eq!(field(merge(&a, &far)), "b.position");
        let spinning = Body {
            spin: v(0.0, f64::NAN, 0.0),
            ..a
        };
        assert_eq!(field(merge(&spinning, &b)), "a.spin");
    }
}
