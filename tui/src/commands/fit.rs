//! `rime fit`: scene parameters fitted to measured points or to an atlas law, with standard errors
//! and correlations (rime_core::fit_scene).

use crate::args::{Common, Format, quantity};
use crate::commands::data::law;
use crate::scene_io::{CliError, CliResult, err};
use rime_core::explorer::format::sig;
use rime_core::fit_scene::{Points, SceneFit, fit, parse_points};
use std::path::{Path, PathBuf};

/// Largest points file read \[bytes\].
pub const MAX_DATA_BYTES: u64 = 16 << 20;

/// Points sampled from an atlas law.
pub const LAW_POINTS: usize = 40;

/// Where the points come from.
#[derive(Debug, Clone)]
pub enum Source {
    /// `--data FILE.csv`.
    Data(PathBuf),
    /// `--law ID [--radius R]`.
    Law(String, Option<f64>),
}

/// Arguments of `rime fit`.
#[derive(Debug, Clone)]
pub struct Args {
    /// The points.
    pub source: Source,
    /// `--param a,b,c` (default `bulk.damping.time`).
    pub params: Vec<String>,
}

/// Parses the flags of `rime fit`.
pub fn parse(get: &dyn Fn(&str) -> Option<String>) -> CliResult<Args> {
    let radius = get("--radius")
        .map(|r| quantity("--radius", &r, "m"))
        .transpose()?;
    let source = match (get("--data"), get("--law")) {
        (Some(d), None) => {
            if radius.is_some() {
                return err("--radius: only with --law");
            }
            Source::Data(PathBuf::from(d))
        }
        (None, Some(l)) => Source::Law(l, radius),
        (Some(_), Some(_)) => return err("--law: cannot be combined with --data"),
        (None, None) => return err("--data: required (or --law ID)"),
    };
    let params: Vec<String> = get("--param")
        .unwrap_or_else(|| "bulk.damping.time".into())
        .split(',')
        .map(|s| s.trim().to_string())
        .collect();
    if params.iter().any(String::is_empty) {
        return err("--param: empty name in the list");
    }
    Ok(Args { source, params })
}

/// Reads a points file: regular files of at most [`MAX_DATA_BYTES`] only.
pub fn read_points(path: &Path) -> CliResult<Points> {
    let shown = path.display();
    let meta =
        std::fs::metadata(path).map_err(|e| CliError::input(format!("--data {shown}: {e}")))?;
    if !meta.is_file() {
        return err(format!("--data {shown}: not a regular file"));
    }
    if meta.len() > MAX_DATA_BYTES {
        return err(format!(
            "--data {shown}: file is {} bytes; at most {MAX_DATA_BYTES} bytes are read",
            meta.len()
        ));
    }
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::input(format!("--data {shown}: {e}")))?;
    parse_points(&text).map_err(|e| CliError::input(format!("--data {shown}: {e}")))
}

// Long by design: one fit's three outputs (JSON, CSV, table) side by side so that their fields
// stay in step.
fn render(common: &Common, f: &SceneFit, points: &Points, what: &str) -> CliResult<String> {
    let n = points.g.len();
    Ok(match common.format {
        Format::Json => {
            // The core's record of this fit (field names are a contract, docs/cli.md).
            let record = rime_core::explorer::records::FitRecord::new(f, points, what);
            // The record's own order, the documented one (issue 37 C5: the keys were sorted).
            serde_json::to_string_pretty(&record).map_err(|e| CliError::input(e.to_string()))?
                + "\n"
        }
        _ => {
            let mut s = format!("fit to {what} ({n} points");
            if let Some(h) = &points.header {
                s.push_str(&format!(", header '{h}'"));
            }
            s.push_str(if f.weighted {
                ", weighted by the sigma column)\n"
            } else {
                ", unweighted)\n"
            });
            s.push_str(&match (&points.g_unit, &points.header) {
                // A law's points have no header: its speeds are in m/s (issue 37 review: it said
                // "from the header").
                (Some(_), None) => "g in m/s (the law's measured speeds)\n".to_string(),
                (Some(u), _) if u == "m/s" => "g in m/s (from the header)\n".to_string(),
                (Some(u), _) => format!("g in {u} (from the header), converted to m/s\n"),
                (None, Some(_)) => "g taken in m/s: the header gives no unit\n".to_string(),
                (None, None) => "g taken in m/s: the file has no header with units\n".to_string(),
            });
            for p in &f.params {
                let (value, se) = with_error(p.value, p.standard_error);
                s.push_str(&format!("{} = {value} {se} {}\n", p.path, p.unit));
            }
            if let (Some(c), true) = (&f.correlation, f.params.len() > 1) {
                s.push_str("correlation:\n");
                for row in c {
                    let cells: Vec<String> = row.iter().map(|x| format!("{x:>8.4}")).collect();
                    s.push_str(&format!("  {}\n", cells.join(" ")));
                }
            }
            s.push_str(&format!(
                "rms error of eps_n {}, reduced chi^2 {} ({} degrees of freedom{})\n",
                sig(f.rms_error, 3),
                sig(f.reduced_chi2, 3),
                f.dof,
                if f.weighted {
                    ""
                } else {
                    "; unscaled: without a sigma column it is the mean squared residual, not a \
                     goodness of fit"
                }
            ));
            if let Some(t) = &f.runs_test {
                s.push_str(&format!(
                    "runs test on the residuals' signs in order of g: {} runs, {} expected, p = {}\n",
                    t.runs,
                    sig(t.expected, 3),
                    sig(t.p, 2)
                ));
            }
            s.push_str(&residual_table(points, &f.residuals));
            for w in &f.warnings {
                s.push_str(&format!("warning: {w}\n"));
            }
            s
        }
    })
}

/// Residual rows printed in the table format (all of them in JSON).
pub const SHOWN_RESIDUALS: usize = 40;

/// A value and its standard error as people read them: the error to 2 significant digits, the
/// value to the same decimal place.
pub fn with_error(value: f64, se: Option<f64>) -> (String, String) {
    match se {
        Some(e) if e > 0.0 && e.is_finite() && value.is_finite() => {
            let last = e.log10().floor() as i32 - 1;
            let digits = if value == 0.0 {
                2
            } else {
                (value.abs().log10().floor() as i32 - last + 1).clamp(2, 17)
            };
            (sig(value, digits), format!("± {}", sig(e, 2)))
        }
        Some(e) => (sig(value, 6), format!("± {}", sig(e, 2))),
        None => (sig(value, 6), "(not determined)".into()),
    }
}

/// The residuals ε − ε_model in order of g (at most [`SHOWN_RESIDUALS`] rows).
fn residual_table(points: &Points, residuals: &[f64]) -> String {
    let mut order: Vec<usize> = (0..points.g.len()).collect();
    order.sort_by(|&a, &b| points.g[a].total_cmp(&points.g[b]));
    let mut s = format!(
        "residuals eps - model:\n  {:>12} {:>10} {:>10} {:>11}\n",
        "g [m/s]", "eps", "model", "residual"
    );
    for &i in order.iter().take(SHOWN_RESIDUALS) {
        let r = residuals.get(i).copied().unwrap_or(f64::NAN);
        s.push_str(&format!(
            "  {:>12} {:>10} {:>10} {:>11}\n",
            sig(points.g[i], 4),
            sig(points.eps[i], 4),
            sig(points.eps[i] - r, 4),
            sig(r, 2)
        ));
    }
    if order.len() > SHOWN_RESIDUALS {
        s.push_str(&format!(
            "  ({} more: --format json lists every residual)\n",
            order.len() - SHOWN_RESIDUALS
        ));
    }
    s
}

/// Runs `rime fit`.
pub fn run(common: &Common, args: &Args) -> CliResult<String> {
    let (points, what, extra) = match &args.source {
        Source::Data(path) => (read_points(path)?, format!("{}", path.display()), None),
        Source::Law(id, radius) => {
            let entry = law("--law", id)?;
            if entry.needs_radius() && radius.is_none() {
                return err(format!(
                    "--radius: required by --law {} (reduced radius in m)",
                    entry.id
                ));
            }
            let mut g = vec![0.0; LAW_POINTS];
            rime_core::sweep::log_space(entry.valid_speed[0], entry.valid_speed[1], &mut g);
            let mut eps = Vec::with_capacity(LAW_POINTS);
            for &x in &g {
                let e = entry
                    .eval(x, *radius)
                    .map_err(|e| CliError::input(format!("--law {}: {e}", entry.id)))?;
                eps.push(e.eps.clamp(0.0, 1.0));
            }
            let points = Points {
                g,
                eps,
                sigma: None,
                header: None,
                g_unit: Some("m/s".into()),
            };
            let note = "fitted to a law's curve over its measured speeds: the standard errors \
                        measure the model's misfit to the law, not measurement noise";
            (points, format!("law {}", entry.id), Some(note))
        }
    };
    let paths: Vec<&str> = args.params.iter().map(String::as_str).collect();
    let mut f = fit(
        &common.scene,
        &paths,
        &points.g,
        &points.eps,
        points.sigma.as_deref(),
        common.accuracy,
    )
    .map_err(|e| CliError::input(format!("--param {e}")))?;
    if let Some(note) = extra {
        f.warnings.push(note.to_string());
    }
    render(common, &f, &points, &what)
}
