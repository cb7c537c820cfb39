//! `rime bench [--out DIR] [--quick]`: speed and accuracy of every model and level (crate::bench).

use crate::scene_io::CliResult;
use std::path::Path;

/// Runs the benchmark (progress on stderr when it is a terminal) and summarises it.
pub fn run(out: &Path, quick: bool) -> CliResult<String> {
    let (_, text) = crate::bench::run(out, quick)?;
    Ok(format!(
        "{text}\nwrote {0}/bench.json and {0}/work-precision.svg\n",
        out.display()
    ))
}
