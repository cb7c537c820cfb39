//! `rime data`: the atlas of measured ice (rime_core::atlas), listed or evaluated.

use crate::args::{Common, Format, quantity, speed_list};
use crate::output::num;
use crate::scene_io::{CliError, CliResult, err};
use rime_core::atlas::{ENTRIES, Entry, Kind, find};
use rime_core::explorer::records::{AtlasRecord, LAW_HEADER, LawRecord};

/// Arguments of `rime data`.
#[derive(Debug, Clone)]
pub struct Args {
    /// `--law ID` with `--g LIST` and optional `--radius R`.
    pub law: Option<(String, Vec<f64>, Option<f64>)>,
}

/// Ids of the entries that are laws, comma-separated.
pub fn law_ids() -> String {
    ENTRIES
        .iter()
        .filter(|e| e.kind == Kind::Law)
        .map(|e| e.id)
        .collect::<Vec<_>>()
        .join(", ")
}

/// The law `id`, or an error naming `flag` and listing the valid ids.
pub fn law(flag: &str, id: &str) -> CliResult<&'static Entry> {
    match find(id) {
        Some(e) if e.kind == Kind::Law => Ok(e),
        Some(e) => err(format!(
            "{flag} {id}: a {}, not a law; laws: {}",
            e.kind.name(),
            law_ids()
        )),
        None => err(format!(
            "{flag} {id}: unknown atlas entry; laws: {}",
            law_ids()
        )),
    }
}

/// Parses the flags of `rime data`.
pub fn parse(get: &dyn Fn(&str) -> Option<String>) -> CliResult<Args> {
    let radius = get("--radius")
        .map(|r| quantity("--radius", &r, "m"))
        .transpose()?;
    if radius.is_some_and(|r| r <= 0.0) {
        return err("--radius: must be a radius > 0 [m]");
    }
    let law = match (get("--law"), get("--g")) {
        (Some(id), Some(g)) => Some((id, speed_list("--g", &g, false)?, radius)),
        (Some(_), None) => return err("--g: required with --law (speeds in m/s)"),
        (None, Some(_)) => return err("--law: required with --g"),
        (None, None) if radius.is_some() => return err("--law: required with --radius"),
        (None, None) => None,
    };
    Ok(Args { law })
}

fn range(v: [f64; 2]) -> String {
    if v[0] == v[1] {
        num(v[0])
    } else {
        format!("{}..{}", num(v[0]), num(v[1]))
    }
}

/// Runs `rime data`.
// Long by design: the atlas listing and a law's evaluation, each with three outputs kept side by
// side.
pub fn run(common: &Common, args: &Args) -> CliResult<String> {
    let Some((id, speeds, radius)) = &args.law else {
        return Ok(match common.format {
            Format::Json => {
                let all: Vec<_> = ENTRIES.iter().map(AtlasRecord::new).collect();
                serde_json::to_string_pretty(&all).map_err(|e| CliError::input(e.to_string()))?
                    + "\n"
            }
            Format::Csv => {
                let mut s = String::from(
                    "id,kind,year,speed_lo,speed_hi,temperature_lo,temperature_hi,geometry\n",
                );
                for e in ENTRIES {
                    s.push_str(&format!(
                        "{},{},{},{},{},{},{},{}\n",
                        e.id,
                        e.kind.name(),
                        e.citation.year,
                        num(e.valid_speed[0]),
                        num(e.valid_speed[1]),
                        num(e.temperature[0]),
                        num(e.temperature[1]),
                        e.geometry.name()
                    ));
                }
                s
            }
            Format::Table => atlas_table(TABLE_WIDTH),
        });
    };
    let entry = law("--law", id)?;
    if entry.needs_radius() && radius.is_none() {
        return err(format!(
            "--radius: required by --law {} (reduced radius in m)",
            entry.id
        ));
    }
    let mut rows = Vec::with_capacity(speeds.len());
    for &g in speeds {
        let e = entry
            .eval(g, *radius)
            .map_err(|e| CliError::input(format!("--law {}: {e}", entry.id)))?;
        rows.push(e);
    }
    let rows: Vec<LawRecord> = rows.iter().map(LawRecord::new).collect();
    Ok(match common.format {
        Format::Json => {
            serde_json::to_string_pretty(&rows).map_err(|e| CliError::input(e.to_string()))? + "\n"
        }
        Format::Csv => {
            let mut s = LAW_HEADER.join(",") + "\n";
            for r in &rows {
                s.push_str(&(r.cells().join(",") + "\n"));
            }
            s
        }
        // For people: 4 significant digits, speeds with a prefixed unit (issue 37).
        Format::Table => crate::output::human_table(
            &LAW_HEADER,
            &rows.iter().map(|r| r.cells().to_vec()).collect::<Vec<_>>(),
        ),
    })
}

/// Width of `rime data`'s table: an 80-column terminal.
pub const TABLE_WIDTH: usize = 80;

/// The atlas for people (issue 37 C6: 165 columns, the formula right-aligned with no unit for v):
/// one row per entry, text columns left-aligned, then the formula with the units of its symbols
/// on lines of their own, wrapped at word boundaries to `width` columns.
fn atlas_table(width: usize) -> String {
    let header = ["id", "kind", "speed [m/s]", "T [K]", "geometry"];
    let rows: Vec<[String; 5]> = ENTRIES
        .iter()
        .map(|e| {
            [
                e.id.to_string(),
                e.kind.name().to_string(),
                range(e.valid_speed),
                range(e.temperature),
                e.geometry.name().to_string(),
            ]
        })
        .collect();
    let widths: Vec<usize> = (0..header.len())
        .map(|k| {
            rows.iter()
                .map(|r| r[k].chars().count())
                .chain([header[k].chars().count()])
                .max()
                .unwrap_or(0)
        })
        .collect();
    let line = |cells: &[&str]| -> String {
        let mut s = String::new();
        for (k, (c, w)) in cells.iter().zip(&widths).enumerate() {
            if k > 0 {
                s.push_str("  ");
            }
            s.push_str(&format!("{c:<w$}"));
        }
        s.trim_end().to_string() + "\n"
    };
    let mut out = line(&header);
    for (e, r) in ENTRIES.iter().zip(&rows) {
        out.push_str(&line(&r.each_ref().map(String::as_str)));
        out.push_str(&wrap_words(e.formula, width, 4));
        if !e.units.is_empty() {
            out.push_str(&wrap_words(&format!("[{}]", e.units), width, 4));
        }
    }
    out + "Provenance and what was verified: rime data --format json (field verified).\n"
}

/// `text` in lines of at most `width` columns broken at spaces, each indented by `indent`.
fn wrap_words(text: &str, width: usize, indent: usize) -> String {
    let room = width.saturating_sub(indent).max(20);
    let mut out = String::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > room {
            out.push_str(&format!("{}{line}\n", " ".repeat(indent)));
            line.clear();
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    if !line.is_empty() {
        out.push_str(&format!("{}{line}\n", " ".repeat(indent)));
    }
    out
}
