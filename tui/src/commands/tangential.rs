//! `rime tangential --gn LIST --gt LIST`: ε_T and the stick class for every combination.

use crate::args::{self, Common};
use crate::output::{TangentialRecord, render};
use crate::scene_io::{CliError, CliResult};
use rime_core::error::Number;

/// Every (g_N, g_T) combination, g_N outer.
pub fn run(common: &Common, gn: &[f64], gt: &[f64]) -> CliResult<String> {
    let contact = args::contact(common)?;
    if contact.friction.is_none() {
        return Err(CliError::input(
            "friction: is off in this scene; tangential restitution needs it (--set friction=on)",
        ));
    }
    let mut records = Vec::with_capacity(gn.len() * gt.len());
    for &n in gn {
        for &t in gt {
            let r = contact.tangential(n, t, common.accuracy).map_err(|e| {
                CliError::from(e).context(format!("g_n = {}, g_t = {}", Number(n), Number(t)))
            })?;
            records.push(TangentialRecord::new(n, t, &r));
        }
    }
    render(&records, common.format).map_err(CliError::input)
}
