//! `rime scene [--out FILE]`: the scene JSON, printed or written atomically.

use crate::args::{self, Common};
use crate::scene_io::{self, CliResult};
use std::path::Path;

/// The scene JSON on stdout (`Some`), or written to `out` (`None`).
pub fn run(common: &Common, out: Option<&Path>) -> CliResult<Option<String>> {
    let text = args::scene_text(common)?;
    match out {
        None => Ok(Some(text)),
        Some(path) => {
            scene_io::write_atomic(path, text.as_bytes())?;
            Ok(None)
        }
    }
}
