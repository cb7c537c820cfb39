//! Regenerates `core/src/normal/batch_table.rs` (the batch path's cells, fitted to the fine master table).
//!
//! `cargo run --release -p rime-core --example generate_batch_table > core/src/normal/batch_table.rs`
fn main() {
    print!("{}", rime_core::batch::generate_source());
}
