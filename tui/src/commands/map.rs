//! `rime map --max G --n N`: the stick map on an N×N grid of (g_N, g_T).

use crate::args::{self, Common, Format};
use crate::output::{self, MapRecord};
use crate::scene_io::{CliError, CliResult};
use rime_core::sweep;

/// Grids at least this large announce themselves on a terminal's stderr.
const BIG: usize = 400;

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
        sweep::StickMap::new(&contact, max, n, common.accuracy)?
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
            output::pretty_json(&value)
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
