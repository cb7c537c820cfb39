//! `rime curve --from G --to G --points N`: the records of `eps` on log-spaced speeds.

use crate::args::{self, Common};
use crate::output::{EpsRecord, render};
use crate::scene_io::{CliError, CliResult};

/// `n` speeds spaced evenly in log10 from `from` to `to`, both ends exact and decades exact: the
/// core's one spacing ([`rime_core::sweep::log_space`]), shared with the explorer and the page.
pub fn log_space(from: f64, to: f64, n: usize) -> Vec<f64> {
    let mut g = vec![0.0; n];
    rime_core::sweep::log_space(from, to, &mut g);
    g
}

/// The curve's records; the core's warnings about the scene and the curve (the ones the
/// explorer's status line and the page show) go to standard error, one `warning: ` line each.
pub fn run(common: &Common, from: f64, to: f64, n: usize) -> CliResult<String> {
    let contact = args::contact(common)?;
    let g = log_space(from, to, n);
    // The speeds on every core, in order: the output is the sequential one, byte for byte.
    let normals = crate::parallel::map(g.len(), crate::parallel::threads(), |i| {
        contact.normal(g[i], common.accuracy)
    })?;
    let statuses: Vec<_> = normals.iter().map(|r| Some(r.status)).collect();
    let records: Vec<EpsRecord> = g
        .iter()
        .zip(&normals)
        .map(|(&g, r)| EpsRecord::new(g, r))
        .collect();
    let warnings =
        rime_core::explorer::warning::warnings(&common.scene, statuses, Some(contact.damping_time));
    for w in warnings {
        eprintln!("warning: {} ({})", w.text(), w.equation());
    }
    render(&records, common.format).map_err(CliError::input)
}

#[cfg(test)]
mod tests {
    use super::log_space;

    #[test]
    fn decades_are_exact_and_ends_are_kept() {
        let g = log_space(1e-6, 1.0, 7);
        assert_eq!(g, vec![1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1.0]);
        let g = log_space(1e-8, 10.0, 19);
        assert_eq!(g[2], 1e-7);
        assert_eq!(g[16], 1.0);
        assert!((g[1] - 10f64.powf(-7.5)).abs() < 1e-22);
        assert_eq!(log_space(2e-3, 2e-3, 1), vec![2e-3]);
    }
}
