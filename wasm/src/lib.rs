//! # rime-wasm
//!
//! A thin wasm-bindgen layer over `rime-core` for the web explorer (`www/`). It has no logic of its
//! own: the page's operations live in the core (`rime_core::explorer::page` computes a whole frame
//! per call, each part failing on its own; `session` edits a scene; `catalogue` lists what the page
//! shows; `share` splits a frame over two workers), and the `bindings` module (compiled only for
//! `wasm32`) exports them to JavaScript as the classes `Explorer`, `Frame`, `PendingFrame`,
//! `FrameShare` and the function `computeFrame`: text in, JSON text or the wire's flat arrays out
//! (`rime_core::wire`). Errors become JS exceptions whose message names the field
//! (`layer.viscosity: must lie in [0, 1e15] Pa s (got -1)`); every argument is validated so that no
//! input can panic the module.

#[cfg(target_arch = "wasm32")]
pub mod bindings;

/// Version of the crate, exposed so the page can show it.
pub fn version() -> &'static str {
    env!("CARGO_PKG_VERSION")
}
