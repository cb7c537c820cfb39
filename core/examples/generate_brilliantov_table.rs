//! Regenerates `core/src/models/brilliantov2007_table.rs` (the brilliantov2007 model's tables of
//! its dimensionless master surface, docs/physics.md#brilliantov2007-tables) on two threads.
//!
//! `cargo run --release -p rime-core --example generate_brilliantov_table > core/src/models/brilliantov2007_table.rs`
fn main() -> Result<(), rime_core::Error> {
    print!(
        "{}",
        rime_core::models::brilliantov2007_master::generate_source(2)?
    );
    Ok(())
}
