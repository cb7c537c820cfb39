//! `rime map --max G --n N`: the stick map on an N×N grid of (g_N, g_T).

use crate::args::{self, Common, Format};
use crate::output::{self, MapRecord};
use crate::scene_io::{CliError, CliResult};
use rime_core::sweep;

/// Grids at least this large announce themselves on a terminal's stderr.
const BIG: usize = 400;

/// The core's [`sweep::StickMap::new`] on every core: ε_N at the grid speeds in chunks, then the
/// rows' cells in chunks of rows; the same map, bit for bit (tested against the core's).
pub fn stick_map(
    contact: &rime_core::Contact,
    max: f64,
    n: usize,
    accuracy: rime_core::Accuracy,
) -> CliResult<sweep::StickMap> {
    let threads = crate::parallel::threads();
    let mut g = vec![0.0; n];
    sweep::linear_space(max, &mut g);
    let parts = crate::parallel::chunks(n, threads, crate::parallel::MIN_CHUNK, |rows| {
        let mut eps = vec![0.0; rows.len()];
        sweep::eps_n_into(contact, &g[rows], accuracy, &mut eps)
            .map(|evaluations| (eps, evaluations))
    });
    let mut eps_n = Vec::with_capacity(n);
    let mut rhs_evaluations = 0;
    for part in parts {
        let (eps, evaluations) = part?;
        eps_n.extend(eps);
        rhs_evaluations += evaluations;
    }
    let parts = crate::parallel::chunks(n, threads, crate::parallel::MIN_CHUNK, |rows| {
        let mut class = vec![rime_core::StickClass::Undefined; rows.len() * n];
        let mut eps_t = vec![0.0; rows.len() * n];
        sweep::stick_map_rows_into(contact, &g, &eps_n, rows.start, &mut class, &mut eps_t)
            .map(|()| (class, eps_t))
    });
    let mut class = Vec::with_capacity(n * n);
    let mut eps_t = Vec::with_capacity(n * n);
    for part in parts {
        let (c, e) = part?;
        class.extend(c);
        eps_t.extend(e);
    }
    Ok(sweep::StickMap {
        g,
        eps_n,
        class,
        eps_t,
        rhs_evaluations,
    })
}

/// The map in the chosen format; JSON pretty-printed like every command's, rows on one line.
pub fn run(common: &Common, max: f64, n: usize) -> CliResult<String> {
    let contact = args::contact(common)?;
    if contact.friction.is_none() {
        return Err(CliError::input(
            "friction: is off in this scene; the stick map needs it (--set friction=on)",
        ));
    }
    let map = {
        let mut progress = crate::progress::Progress::new("map", 1);
        if n >= BIG {
            progress.step(&format!("{n}×{n} grid"));
        }
        stick_map(&contact, max, n, common.accuracy)?
    };
    let rows = |f: &dyn Fn(usize) -> f64| -> Vec<Vec<f64>> {
        (0..n)
            .map(|i| (0..n).map(|j| f(i * n + j)).collect())
            .collect()
    };
    Ok(match common.format {
        Format::Json => {
            let record = MapRecord {
                g: map.g.clone(),
                class: (0..n)
                    .map(|i| (0..n).map(|j| map.class[i * n + j].name()).collect())
                    .collect(),
                eps_t: rows(&|k| map.eps_t[k]),
                eps_n: map.eps_n.clone(),
            };
            let value =
                serde_json::to_value(&record).map_err(|e| CliError::input(e.to_string()))?;
            // The keys in the order docs/cli.md lists them (issue 37 C5: they were sorted).
            output::pretty_json(&value, &[("", &["g", "class", "eps_t", "eps_n"])])
        }
        Format::Csv => rime_core::explorer::records::map_csv(&map),
        Format::Table => {
            // One letter per cell, g_T to the right, g_N upwards, with a legend.
            use rime_core::tangential::StickClass;
            let mut s = format!(
                "g_N ↑ (0 … {} m/s), g_T → (0 … {} m/s)\n",
                output::num(max),
                output::num(max)
            );
            for i in (0..n).rev() {
                for j in 0..n {
                    s.push(map.class[i * n + j].letter());
                }
                s.push('\n');
            }
            for c in StickClass::ALL {
                s.push_str(&format!("  {}  {}\n", c.letter(), c.label()));
            }
            s
        }
    })
}

#[cfg(test)]
mod tests {
    use rime_core::{Accuracy, Contact, Preset};

    /// Issue 26: the map on every core is the core's sequential map, bit for bit (ε_N, classes,
    /// ε_T and the evaluations spent), on a table level and an integrated one.
    #[test]
    fn the_parallel_map_is_the_sequential_one_issue_26() {
        let contact = Contact::new(&Preset::IceFrost.scene()).unwrap();
        for (accuracy, n) in [(Accuracy::Precise, 203), (Accuracy::Balanced, 37)] {
            let sequential = rime_core::sweep::StickMap::new(&contact, 0.05, n, accuracy).unwrap();
            let parallel = super::stick_map(&contact, 0.05, n, accuracy).unwrap();
            assert_eq!(
                format!("{parallel:?}"),
                format!("{sequential:?}"),
                "{accuracy:?}"
            );
        }
    }
}
