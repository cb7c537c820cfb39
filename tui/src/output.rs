//! JSON, CSV and table output of the subcommands (field names are a contract: docs/cli.md).

use crate::args::Format;
use serde::Serialize;

pub use rime_core::explorer::records::{EpsRecord, MapRecord, TangentialRecord};

/// Why a table's error_estimate is empty.
pub const EMPTY_ERROR_ESTIMATE: &str = "error_estimate empty: eps_n < 1e-6 lies outside the error \
     bound's domain; only its order of magnitude is reliable";

/// Formats a number for CSV and tables: the core's one record cell
/// ([`rime_core::explorer::records::cell`]): shortest round-trip, never `0e0`, empty (never NaN)
/// for a non-finite value.
pub fn num(v: f64) -> String {
    rime_core::explorer::records::cell(v)
}

/// A number as a table for people prints it (issue 37: tables carried 17 digits): the core's
/// [`qty`](rime_core::explorer::format::qty), 4 significant digits with an SI prefix where the
/// unit takes one, split into the value and its (prefixed) unit: `(5.257, µm/s)`, `(30.16, g)`.
/// JSON and CSV keep every digit ([`num`]).
pub fn human(v: f64, unit: &str) -> (String, String) {
    let unit = if unit == "1" { "" } else { unit };
    // A mass of a kilogram and more reads in kg (a planet is not 5.688e29 g).
    if unit == "kg" && v.abs() >= 1.0 {
        return (rime_core::explorer::format::sig(v, 4), unit.to_string());
    }
    let text = rime_core::explorer::format::qty(v, unit);
    match text.split_once(' ') {
        Some((value, unit)) if v.is_finite() => (value.to_string(), unit.to_string()),
        _ => (text, unit.to_string()),
    }
}

/// A record table's header and rows for people: each numeric cell to 4 significant digits; where
/// the column's unit (`name [unit]`) takes an SI prefix, each cell carries its prefixed unit and
/// the header drops it (`t_c` · `605.2 µs`), else the header keeps it. Cells that are not numbers
/// (`rebound`, empty) are kept.
pub fn human_table(header: &[&str], rows: &[Vec<String>]) -> String {
    let units: Vec<(&str, &str)> = header
        .iter()
        .map(|h| match h.split_once(" [") {
            Some((name, rest)) => (name, rest.trim_end_matches(']')),
            None => (*h, ""),
        })
        .collect();
    let with_unit = |u: &str| !u.is_empty() && rime_core::explorer::format::prefixable(u);
    let head: Vec<&str> = header
        .iter()
        .zip(&units)
        .map(|(h, (name, u))| if with_unit(u) { *name } else { *h })
        .collect();
    let rows: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            r.iter()
                .zip(&units)
                .map(|(c, (_, u))| match c.parse::<f64>() {
                    Ok(v) if v.is_finite() && with_unit(u) => {
                        rime_core::explorer::format::qty(v, u)
                    }
                    Ok(v) if v.is_finite() => rime_core::explorer::format::sig(v, 4),
                    _ => c.clone(),
                })
                .collect()
        })
        .collect();
    table(&head, &rows)
}

/// A `name value unit` table for people: each value as [`human`] prints it, its prefixed unit in
/// the unit column; values that are not numbers (`rebound`, `none`) kept.
pub fn human_value_rows(rows: Vec<Vec<String>>) -> Vec<Vec<String>> {
    rows.into_iter()
        .map(|r| match (r.first(), r.get(1), r.get(2)) {
            (Some(k), Some(v), Some(u)) => match v.parse::<f64>() {
                Ok(x) if x.is_finite() => {
                    let (value, unit) = human(x, u);
                    vec![k.clone(), value, unit]
                }
                _ => r,
            },
            _ => r,
        })
        .collect()
}

/// Prints records in the chosen format.
pub trait Rows {
    /// Column names of CSV and tables: the JSON names, with units in brackets.
    fn header() -> &'static [&'static str];
    /// Cells of one row.
    fn cells(&self) -> Vec<String>;
    /// A line below a table that explains empty cells (none by default).
    fn note(_records: &[Self]) -> Option<&'static str>
    where
        Self: Sized,
    {
        None
    }
}

impl Rows for EpsRecord {
    fn header() -> &'static [&'static str] {
        &rime_core::explorer::records::CURVE_HEADER
    }
    fn note(records: &[Self]) -> Option<&'static str> {
        records
            .iter()
            .any(|r| r.error_estimate.is_none())
            .then_some(EMPTY_ERROR_ESTIMATE)
    }
    fn cells(&self) -> Vec<String> {
        EpsRecord::cells(self).to_vec()
    }
}

impl Rows for TangentialRecord {
    fn header() -> &'static [&'static str] {
        &rime_core::explorer::records::TANGENTIAL_HEADER
    }
    fn note(records: &[Self]) -> Option<&'static str> {
        records
            .iter()
            .any(|r| r.class == rime_core::StickClass::SlidingGap.name())
            .then_some(rime_core::explorer::help::ARTIFACT_NOTE_SHORT)
    }
    fn cells(&self) -> Vec<String> {
        TangentialRecord::cells(self).to_vec()
    }
}

/// Renders a list of records.
pub fn render<T: Rows + Serialize>(records: &[T], format: Format) -> Result<String, String> {
    match format {
        Format::Json => serde_json::to_string_pretty(records)
            .map(|s| s + "\n")
            .map_err(|e| e.to_string()),
        Format::Csv => {
            let mut out = T::header().join(",");
            out.push('\n');
            for r in records {
                out.push_str(&r.cells().join(","));
                out.push('\n');
            }
            Ok(out)
        }
        Format::Table => {
            let rows: Vec<Vec<String>> = records.iter().map(|r| r.cells()).collect();
            let mut out = human_table(T::header(), &rows);
            if let Some(note) = T::note(records) {
                out.push_str(note);
                out.push('\n');
            }
            Ok(out)
        }
    }
}

/// An aligned text table.
pub fn table(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut widths: Vec<usize> = header.iter().map(|h| h.chars().count()).collect();
    for r in rows {
        for (w, c) in widths.iter_mut().zip(r) {
            *w = (*w).max(c.chars().count());
        }
    }
    let line = |cells: Vec<String>| -> String {
        let mut s = String::new();
        for (i, (c, w)) in cells.iter().zip(&widths).enumerate() {
            if i > 0 {
                s.push_str("  ");
            }
            s.push_str(&format!("{c:>w$}"));
        }
        s.trim_end().to_string() + "\n"
    };
    let mut out = line(header.iter().map(|h| h.to_string()).collect());
    for r in rows {
        out.push_str(&line(r.clone()));
    }
    out
}

/// The documented order of an output's JSON keys (issue 37 C5: `tidal`, `ring` and `compare`
/// printed their keys sorted, not in the order docs/cli.md lists them). One entry per object: its
/// path from the top (`""`, `"ledger"`, `"size_bins"` — an array's elements share its path) and its
/// keys in order. A key not listed follows the listed ones, sorted; an object not listed is sorted.
pub type KeyOrder<'a> = [(&'a str, &'a [&'a str])];

/// JSON for people and programs alike: objects and arrays of objects indented two spaces (as
/// `serde_json::to_string_pretty`, what `rime eps` prints), arrays of numbers or strings on one
/// line each, so a map or a trajectory stays readable (`rime map`, `rime collision`); each
/// object's keys in the order `order` gives.
pub fn pretty_json(v: &serde_json::Value, order: &KeyOrder) -> String {
    let mut out = String::new();
    write_json(v, 0, "", order, true, &mut out);
    out.push('\n');
    out
}

/// JSON exactly as `serde_json::to_string_pretty` writes it (every array element on its own line),
/// with each object's keys in the order `order` gives.
pub fn json_in_order(v: &serde_json::Value, order: &KeyOrder) -> String {
    let mut out = String::new();
    write_json(v, 0, "", order, false, &mut out);
    out.push('\n');
    out
}

fn scalar(v: &serde_json::Value) -> bool {
    !(v.is_array() || v.is_object())
}

/// `m`'s entries, the keys `order` lists for `path` first (in its order), then the rest sorted.
fn ordered<'m>(
    m: &'m serde_json::Map<String, serde_json::Value>,
    path: &str,
    order: &KeyOrder,
) -> Vec<(&'m String, &'m serde_json::Value)> {
    let listed: &[&str] = order
        .iter()
        .find(|(p, _)| *p == path)
        .map_or(&[], |(_, keys)| keys);
    let rank = |k: &str| listed.iter().position(|l| *l == k).unwrap_or(listed.len());
    let mut entries: Vec<_> = m.iter().collect();
    // Stable: the unlisted keys keep the map's sorted order.
    entries.sort_by_key(|(k, _)| rank(k));
    entries
}

fn write_json(
    v: &serde_json::Value,
    indent: usize,
    path: &str,
    order: &KeyOrder,
    inline_scalar_arrays: bool,
    out: &mut String,
) {
    use serde_json::Value;
    let pad = |n: usize| " ".repeat(n);
    match v {
        Value::Array(a) if a.is_empty() => out.push_str("[]"),
        Value::Array(a) if inline_scalar_arrays && a.iter().all(scalar) => {
            out.push('[');
            for (k, x) in a.iter().enumerate() {
                if k > 0 {
                    out.push_str(", ");
                }
                out.push_str(&x.to_string());
            }
            out.push(']');
        }
        Value::Array(a) => {
            out.push_str("[\n");
            for (k, x) in a.iter().enumerate() {
                out.push_str(&pad(indent + 2));
                write_json(x, indent + 2, path, order, inline_scalar_arrays, out);
                out.push_str(if k + 1 < a.len() { ",\n" } else { "\n" });
            }
            out.push_str(&pad(indent));
            out.push(']');
        }
        Value::Object(m) if m.is_empty() => out.push_str("{}"),
        Value::Object(m) => {
            out.push_str("{\n");
            for (k, (key, x)) in ordered(m, path, order).into_iter().enumerate() {
                out.push_str(&pad(indent + 2));
                out.push_str(&Value::String(key.clone()).to_string());
                out.push_str(": ");
                let inner = if path.is_empty() {
                    key.clone()
                } else {
                    format!("{path}.{key}")
                };
                write_json(x, indent + 2, &inner, order, inline_scalar_arrays, out);
                out.push_str(if k + 1 < m.len() { ",\n" } else { "\n" });
            }
            out.push_str(&pad(indent));
            out.push('}');
        }
        _ => out.push_str(&v.to_string()),
    }
}

#[cfg(test)]
mod tests {
    use super::{json_in_order, pretty_json};

    #[test]
    fn pretty_json_reads_back_as_the_same_value_issue_22() {
        let v = serde_json::json!({
            "a": [1.0, 2.5e-300, -0.0],
            "b": [[1, 2], [3, 4]],
            "c": [{"x": "q\"uote", "y": null}, {}],
            "d": {"e": [], "f": "µ ü"},
            "g": true
        });
        let text = pretty_json(&v, &[]);
        assert_eq!(serde_json::from_str::<serde_json::Value>(&text).unwrap(), v);
        // Without an order, the other writer is serde_json's own pretty form.
        assert_eq!(
            json_in_order(&v, &[]),
            serde_json::to_string_pretty(&v).unwrap() + "\n"
        );
        assert!(
            text.contains("\n  \"a\": [1.0, 2.5e-300, -0.0],\n"),
            "{text}"
        );
        assert!(text.contains("    [1, 2],\n"), "{text}");
    }
}
