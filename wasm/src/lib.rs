//! Thin wasm-bindgen layer over `rime-core` (filled in by the web-explorer issue).

/// Version of the crate, exposed so the page can show it.
pub fn version() -> &'static str {
    env!("CARGO_PKG_VERSION")
}
