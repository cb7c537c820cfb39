//! # rime-wasm
//!
//! A thin wasm-bindgen layer over `rime-core` for the web explorer (`www/`). It has no physics of
//! its own: [`explorer`] holds the host-testable logic (argument checks, JSON conversion) as plain
//! Rust, [`frame`] computes one whole frame of the page per call (each part failing on its own),
//! and the `bindings` module (compiled only for `wasm32`) exports both to JavaScript as the classes
//! `Explorer` and `Frame` and the function `computeFrame`. Errors become JS exceptions whose message names the field
//! (`layer.viscosity: must lie in [0, 1e15] Pa s (got -1)`); every argument is validated so that no
//! input can panic the module.

pub mod explorer;
pub mod frame;
pub mod split;

#[cfg(target_arch = "wasm32")]
pub mod bindings;

/// Version of the crate, exposed so the page can show it.
pub fn version() -> &'static str {
    env!("CARGO_PKG_VERSION")
}
