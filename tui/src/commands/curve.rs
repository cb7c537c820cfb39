//! `rime curve --from G --to G --points N`: the records of `eps` on log-spaced speeds.

use crate::cli::{self, Common};
use crate::output::{EpsRecord, render};
use crate::scene_io::{CliError, CliResult};

/// `n` speeds spaced evenly in log10 from `from` to `to`, both ends exact. The exponents are
/// interpolated from the ends' decimal exponents, and a point whose exponent is a whole number k is
/// the double nearest 10^k (parsed from `1e{k}`), so decades print exactly (`1e-5`, not
/// `9.999999999999999e-6`).
pub fn log_space(from: f64, to: f64, n: usize) -> Vec<f64> {
    if n == 0 {
        return Vec::new();
    }
    if n == 1 {
        return vec![from];
    }
    let (a, b) = (from.log10(), to.log10());
    let m = (n - 1) as f64;
    let mut g: Vec<f64> = (0..n)
        .map(|i| {
            let i = i as f64;
            let e = (a * (m - i) + b * i) / m;
            let k = e.round();
            if (e - k).abs() < 1e-12 {
                format!("1e{k}").parse().unwrap_or_else(|_| 10f64.powf(e))
            } else {
                10f64.powf(e)
            }
        })
        .collect();
    g[0] = from;
    g[n - 1] = to;
    g
}

/// The curve's records.
pub fn run(common: &Common, from: f64, to: f64, n: usize) -> CliResult<String> {
    let contact = cli::contact(common)?;
    let mut records = Vec::with_capacity(n);
    for g in log_space(from, to, n) {
        let normal = contact.normal(g, common.accuracy)?;
        records.push(EpsRecord::new(g, &normal));
    }
    render(&records, common.format).map_err(CliError)
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
