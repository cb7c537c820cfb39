//! Prints ε_N of the default scene at a few speeds and the time per evaluation.
use rime_core::{Accuracy, Contact, ContactEnd, Scene};
use rime_core::normal::viscoelastic::dimensionless;

fn main() -> Result<(), rime_core::Error> {
    let contact = Contact::new(&Scene::default())?;
    for g in [1e-9, 1e-6, 1e-3, 1e-2, 1e-1, 1.0, 10.0] {
        let n = contact.normal(g, Accuracy::Precise)?;
        println!("g = {g:e}: delta = {:.6e}, {n:?}", contact.delta(g));
    }
    for d in [0.0, 1e-6, 1e-3, 0.1, 1.0, 10.0, 100.0, 1e3, 1e4, 1e6] {
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            for rtol in [1e-8, 1e-12, 1e-13] {
                let t = std::time::Instant::now();
                let r = dimensionless(d, end, rtol)?;
                let dt = t.elapsed();
                println!("delta {d:e} {end:?} rtol {rtol:e}: eps {:.15e} s_c {:.6} xmax {:.6e} evals {} time {:?}", r.eps, r.s_c, r.x_max, r.rhs_evaluations, dt);
            }
        }
    }
    Ok(())
}
