//! `rime eps --g LIST` and `rime eps --g-file FILE` (the latter streams through crate::eps_file).

use crate::args::{self, Common};
use crate::output::{EpsRecord, render};
use crate::scene_io::{CliError, CliResult};
use rime_core::error::Number;
use std::path::Path;

/// ε_N records at the speeds, in the order given.
pub fn run(common: &Common, speeds: &[f64]) -> CliResult<String> {
    let contact = args::contact(common)?;
    let mut records = Vec::with_capacity(speeds.len());
    for &g in speeds {
        let n = contact
            .normal(g, common.accuracy)
            .map_err(|e| CliError::from(e).context(format!("g_n = {}", Number(g))))?;
        records.push(EpsRecord::new(g, &n));
    }
    render(&records, common.format).map_err(CliError::input)
}

/// Streams the records for a file of speeds to stdout.
pub fn run_file(common: &Common, path: &Path) -> CliResult<()> {
    crate::eps_file::run(common, path)
}
