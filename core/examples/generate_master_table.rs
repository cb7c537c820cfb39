//! Regenerates `core/src/normal/viscoelastic/master_table.rs` (the fast path's Chebyshev tables).
//!
//! `cargo run --release -p rime-core --example generate_master_table > core/src/normal/viscoelastic/master_table.rs`
fn main() -> Result<(), rime_core::Error> {
    print!("{}", rime_core::master::generate_source()?);
    Ok(())
}
