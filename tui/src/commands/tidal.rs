//! `rime tidal`: the appendix's tidal estimate (Eq. (A.1)–(A.7)) with units.

use crate::args::{Common, Format};
use crate::output;
use crate::scene_io::{CliError, CliResult};
use rime_core::explorer::records::TIDAL_HEADER;
use rime_core::tidal::TidalInput;

/// The named values in the chosen format.
pub fn run(common: &Common, input: &TidalInput) -> CliResult<String> {
    let t = rime_core::tidal::tidal(input)?;
    let record = rime_core::explorer::records::TidalRecord::new(input, &t);
    Ok(match common.format {
        Format::Json => {
            // The record's own order, the documented one: the named values as the CSV rows
            // list them, then `stays_in_contact` and `verdict` (issue 37 C5: the keys were sorted).
            serde_json::to_string_pretty(&record).map_err(|e| CliError::input(e.to_string()))?
                + "\n"
        }
        Format::Csv => {
            let mut s = TIDAL_HEADER.join(",") + "\n";
            for row in record.rows() {
                s.push_str(&(row.join(",") + "\n"));
            }
            s
        }
        Format::Table => {
            // A missing value reads "none" in a table.
            let rows: Vec<Vec<String>> = record
                .rows()
                .into_iter()
                .map(|[k, v, u]| vec![k, if v.is_empty() { "none".into() } else { v }, u])
                .collect();
            // The core's verdict closes the table, as `rime ring`'s summary line does.
            output::table(&TIDAL_HEADER, &output::human_value_rows(rows)) + &record.verdict + "\n"
        }
    })
}
