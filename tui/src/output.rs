//! JSON, CSV and table output of the subcommands (field names are a contract: docs/cli.md).

use crate::args::Format;
use serde::Serialize;

/// One normal-restitution record (`eps` and `curve`).
#[derive(Debug, Clone, Serialize)]
pub struct EpsRecord {
    /// Impact speed \[m/s\].
    pub g_n: f64,
    /// ε_N.
    pub eps_n: f64,
    /// `rebound`, `stuck_in_layer`, `stuck_by_adhesion` or `overdamped`.
    pub status: &'static str,
    /// Contact duration \[s\]; `null` when the grains stick (they come to rest asymptotically).
    pub t_c: Option<f64>,
    /// Maximum compression \[m\].
    pub xi_max: f64,
    /// Bound on the relative error of `eps_n` at the chosen accuracy; `null` where ε_N < 1e-6,
    /// outside the bound's domain.
    pub error_estimate: Option<f64>,
}

impl EpsRecord {
    /// Builds a record from a core result.
    pub fn new(g_n: f64, n: &rime_core::Normal) -> Self {
        EpsRecord {
            g_n,
            eps_n: n.eps,
            status: n.status.name(),
            t_c: n.t_c.is_finite().then_some(n.t_c),
            xi_max: n.xi_max,
            error_estimate: n.error_estimate.is_finite().then_some(n.error_estimate),
        }
    }
}

/// Why a table's error_estimate is empty.
pub const EMPTY_ERROR_ESTIMATE: &str = "error_estimate empty: eps_n < 1e-6 lies outside the error \
     bound's domain; only its order of magnitude is reliable";

/// One tangential record.
#[derive(Debug, Clone, Serialize)]
pub struct TangentialRecord {
    /// Normal impact speed \[m/s\].
    pub g_n: f64,
    /// Tangential speed \[m/s\].
    pub g_t: f64,
    /// ε_T.
    pub eps_t: f64,
    /// ε_N(g_N).
    pub eps_n: f64,
    /// Stick-map class (docs/physics.md#decision-7).
    pub class: &'static str,
}

/// A stick map.
#[derive(Debug, Clone, Serialize)]
pub struct MapRecord {
    /// Grid speeds \[m/s\], 0 to max inclusive.
    pub g: Vec<f64>,
    /// `class[i][j]` at g_N = `g[i]`, g_T = `g[j]`.
    pub class: Vec<Vec<&'static str>>,
    /// `eps_t[i][j]` at g_N = `g[i]`, g_T = `g[j]`.
    pub eps_t: Vec<Vec<f64>>,
    /// ε_N at `g[i]`.
    pub eps_n: Vec<f64>,
}

/// Formats a number for CSV and tables: the core's one record cell
/// ([`rime_core::explorer::records::cell`]): shortest round-trip, never `0e0`, empty (never NaN)
/// for a non-finite value.
pub fn num(v: f64) -> String {
    rime_core::explorer::records::cell(v)
}

fn opt(v: Option<f64>) -> String {
    v.map(num).unwrap_or_default()
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
        vec![
            num(self.g_n),
            num(self.eps_n),
            self.status.to_string(),
            opt(self.t_c),
            num(self.xi_max),
            opt(self.error_estimate),
        ]
    }
}

impl Rows for TangentialRecord {
    fn header() -> &'static [&'static str] {
        &["g_n [m/s]", "g_t [m/s]", "eps_t", "eps_n", "class"]
    }
    fn note(records: &[Self]) -> Option<&'static str> {
        records
            .iter()
            .any(|r| r.class == rime_core::StickClass::SlidingGap.name())
            .then_some(rime_core::explorer::help::ARTIFACT_NOTE_SHORT)
    }
    fn cells(&self) -> Vec<String> {
        vec![
            num(self.g_n),
            num(self.g_t),
            num(self.eps_t),
            num(self.eps_n),
            self.class.to_string(),
        ]
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
            let mut out = table(T::header(), &rows);
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

/// JSON for people and programs alike: objects and arrays of objects indented two spaces (as
/// `serde_json::to_string_pretty`, what `rime eps` prints), arrays of numbers or strings on one
/// line each, so a map or a trajectory stays readable (`rime map`, `rime collision`).
pub fn pretty_json(v: &serde_json::Value) -> String {
    let mut out = String::new();
    write_json(v, 0, &mut out);
    out.push('\n');
    out
}

fn scalar(v: &serde_json::Value) -> bool {
    !(v.is_array() || v.is_object())
}

fn write_json(v: &serde_json::Value, indent: usize, out: &mut String) {
    use serde_json::Value;
    let pad = |n: usize| " ".repeat(n);
    match v {
        Value::Array(a) if a.iter().all(scalar) => {
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
                write_json(x, indent + 2, out);
                out.push_str(if k + 1 < a.len() { ",\n" } else { "\n" });
            }
            out.push_str(&pad(indent));
            out.push(']');
        }
        Value::Object(m) if m.is_empty() => out.push_str("{}"),
        Value::Object(m) => {
            out.push_str("{\n");
            for (k, (key, x)) in m.iter().enumerate() {
                out.push_str(&pad(indent + 2));
                out.push_str(&Value::String(key.clone()).to_string());
                out.push_str(": ");
                write_json(x, indent + 2, out);
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
    use super::pretty_json;

    #[test]
    fn pretty_json_reads_back_as_the_same_value_issue_22() {
        let v = serde_json::json!({
            "a": [1.0, 2.5e-300, -0.0],
            "b": [[1, 2], [3, 4]],
            "c": [{"x": "q\"uote", "y": null}, {}],
            "d": {"e": [], "f": "µ ü"},
            "g": true
        });
        let text = pretty_json(&v);
        assert_eq!(serde_json::from_str::<serde_json::Value>(&text).unwrap(), v);
        assert!(
            text.contains("\n  \"a\": [1.0, 2.5e-300, -0.0],\n"),
            "{text}"
        );
        assert!(text.contains("    [1, 2],\n"), "{text}");
    }
}
