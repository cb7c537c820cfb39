//! The stick map of Fig. 4 for sticky ice (Eq. (18)–(26)): which regime each (g_N, g_T) falls in.
//!
//! `cargo run --release -p rime-core --example stick_map`
use rime_core::sweep::StickMap;
use rime_core::{Accuracy, Contact, Preset, StickClass};

fn main() -> Result<(), rime_core::Error> {
    let contact = Contact::new(&Preset::IceSticky.scene())?;
    let n = 24;
    let map = StickMap::new(&contact, 5e-4, n, Accuracy::Fast)?;
    println!("g_N ↑ 0 … 0.5 mm/s, g_T → 0 … 0.5 mm/s");
    for i in (0..n).rev() {
        let row: String = (0..n).map(|j| map.class[i * n + j].letter()).collect();
        println!("{row}");
    }
    for class in StickClass::ALL {
        println!("{}  {}", class.letter(), class.name());
    }
    Ok(())
}
