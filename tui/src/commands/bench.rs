//! `rime bench [--out DIR] [--quick] [--frames]`: speed and accuracy of every model and level
//! (crate::bench), or with `--frames` the explorer's input → frame times (crate::bench::frames).

use crate::scene_io::CliResult;
use std::path::Path;

/// Runs the benchmark (progress on stderr when it is a terminal) and summarises it.
pub fn run(out: &Path, quick: bool, frames: bool) -> CliResult<String> {
    if frames {
        let (_, text) = crate::bench::frames::run(out, quick)?;
        return Ok(format!("{text}\nwrote {}/frames.json\n", out.display()));
    }
    let (_, text) = crate::bench::run(out, quick)?;
    Ok(format!(
        "{text}\nwrote {0}/bench.json and {0}/work-precision.svg\n",
        out.display()
    ))
}
