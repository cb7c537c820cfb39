//! ε_N over five decades of impact speed for a frost-covered ice grain (Eq. (4), (8)–(10)).
//!
//! `cargo run --release -p rime-core --example curve`
use rime_core::{Accuracy, Contact, Preset, sweep};

fn main() -> Result<(), rime_core::Error> {
    let contact = Contact::new(&Preset::IceFrost.scene())?;
    let (speeds, results) = sweep::curve(&contact, 1e-6, 10.0, 11, Accuracy::Precise)?;
    println!("{:>12}  {:>10}  status", "g_N [m/s]", "ε_N");
    for (g, n) in speeds.iter().zip(&results) {
        println!("{g:>12.3e}  {:>10.6}  {}", n.eps, n.status.name());
    }
    Ok(())
}
