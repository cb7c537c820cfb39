//! `rime tidal`: the appendix's tidal estimate (Eq. (A.1)–(A.7)) with units.

use crate::args::{Common, Format};
use crate::output;
use crate::scene_io::{CliError, CliResult};
use rime_core::tidal::TidalInput;

/// The named values in the chosen format.
pub fn run(common: &Common, input: &TidalInput) -> CliResult<String> {
    let t = rime_core::tidal::tidal(input)?;
    let values: Vec<(&str, Option<f64>, &str)> = vec![
        ("planet_mass", Some(input.planet_mass), "kg"),
        ("distance", Some(input.distance), "m"),
        ("radius", Some(input.radius), "m"),
        ("density", Some(input.density), "kg/m3"),
        ("surface_energy", Some(input.surface_energy), "J/m2"),
        ("grain_mass", Some(t.mass), "kg"),
        ("delta_f", Some(t.delta_f), "N"),
        ("delta_f_approx", Some(t.delta_f_approx), "N"),
        ("surface_force", Some(t.surface_force), "N"),
        ("surface_force_paper", Some(t.surface_force_paper), "N"),
        ("gravity", Some(t.gravity), "N"),
        ("d_roche", Some(t.d_roche), "m"),
        ("d_min", Some(t.d_min), "m"),
        ("r_max", t.r_max, "m"),
        // The core's verdict: above 1 the pair stays in contact (Eq. (A.4)).
        ("hold_margin", Some(t.margin()), ""),
    ];
    Ok(match common.format {
        Format::Json => {
            let mut map = serde_json::Map::new();
            for (k, v, _) in &values {
                map.insert(
                    k.to_string(),
                    v.map_or(serde_json::Value::Null, serde_json::Value::from),
                );
            }
            map.insert(
                "stays_in_contact".into(),
                serde_json::Value::from(t.holds()),
            );
            map.insert("verdict".into(), serde_json::Value::from(t.verdict()));
            serde_json::to_string_pretty(&map).map_err(|e| CliError::input(e.to_string()))? + "\n"
        }
        Format::Csv => {
            let mut s = String::from("name,value,unit\n");
            for (k, v, u) in &values {
                s.push_str(&format!(
                    "{k},{},{u}\n",
                    v.map(output::num).unwrap_or_default()
                ));
            }
            s
        }
        Format::Table => {
            let rows: Vec<Vec<String>> = values
                .iter()
                .map(|(k, v, u)| {
                    vec![
                        k.to_string(),
                        v.map(output::num).unwrap_or_else(|| "none".into()),
                        u.to_string(),
                    ]
                })
                .collect();
            output::table(&["name", "value", "unit"], &rows)
        }
    })
}
