//! Two ice grains collide obliquely: Eq. (2) gives the relative surface velocity, the contact models
//! give ε_N and ε_T, and the kinematics update velocities and spins, conserving momentum.
//!
//! `cargo run --release -p rime-core --example two_grains`
use nalgebra::Vector3;
use rime_core::kinematics::{collide, decompose, relative_surface_velocity};
use rime_core::{Accuracy, Contact, GrainState, Preset};

fn main() -> Result<(), rime_core::Error> {
    let scene = Preset::Ice.scene();
    let contact = Contact::new(&scene)?;
    let mass =
        4.0 / 3.0 * core::f64::consts::PI * scene.grains.radius_1.powi(3) * scene.grains.density;
    let r = scene.grains.radius_1;
    let mut i =
        GrainState::solid_sphere(mass, r, Vector3::new(-0.01, 0.004, 0.0), Vector3::zeros());
    let mut j = GrainState::solid_sphere(mass, r, Vector3::zeros(), Vector3::zeros());
    // Unit normal from j's centre to i's.
    let n = Vector3::new(1.0, 0.0, 0.0);
    let (g_n, g_t) = decompose(&relative_surface_velocity(&i, &j, &n), &n);
    let t = contact.tangential(-g_n, g_t.norm(), Accuracy::Precise)?;
    println!(
        "g_N = {:.4} m/s, |g_T| = {:.4} m/s → ε_N = {:.6}, ε_T = {:.6} ({})",
        -g_n,
        g_t.norm(),
        t.eps_n,
        t.eps_t,
        t.class.name()
    );
    let before = i.velocity * i.mass + j.velocity * j.mass;
    collide(&mut i, &mut j, &n, t.eps_n, t.eps_t)?;
    let after = i.velocity * i.mass + j.velocity * j.mass;
    println!(
        "v_i = {:?}\nω_i = {:?}\nmomentum change {:.1e}",
        i.velocity,
        i.spin,
        (after - before).norm()
    );
    Ok(())
}
