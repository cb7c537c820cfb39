//! `rime bench`: the measured speed/accuracy trade of every model and accuracy level.
//!
//! For each model and level it prints the maximum relative error of ε_N against a reference (the
//! live integrator at rtol 1e-14), nanoseconds per ε evaluation, milliseconds per 400-point curve
//! and per 200×200 stick map, and the cost of a full explorer frame (four 400-point curves and a
//! 200×200 map). It writes the table as JSON and a work–precision figure (error vs time, log–log)
//! as SVG. Absolute times drift on a shared machine; compare ratios measured in one run.

pub mod frames;

use crate::scene_io::{CliError, CliResult, write_atomic};
use rime_core::sweep::{self, StickMap};
use rime_core::{Accuracy, Contact, Layer, LayerReading, Preset, Scene};
use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

/// One row of the table.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Row {
    /// Model name.
    pub model: &'static str,
    /// Accuracy level.
    pub level: &'static str,
    /// Maximum relative error of ε_N (where the reference ε_N > 1e-6).
    pub max_rel_error: f64,
    /// Nanoseconds per ε_N evaluation.
    pub ns_per_eps: f64,
    /// Milliseconds per 400-point curve.
    pub ms_per_curve: f64,
    /// Milliseconds per 200×200 stick map.
    pub ms_per_map: f64,
}

fn models() -> Vec<(&'static str, Scene)> {
    let frost = Preset::IceFrost.scene();
    let literal = Scene {
        layer: Some(Layer {
            reading: LayerReading::Literal,
            ..Layer::default()
        }),
        ..frost
    };
    vec![
        ("viscoelastic", Preset::Ice.scene()),
        ("layer (offset)", frost),
        ("layer (literal)", literal),
        ("adhesion", Preset::IceSticky.scene()),
    ]
}

/// Median wall time of `f` in seconds, repeating it until each sample takes ≥ `min_sample` s.
fn time_it(mut f: impl FnMut() -> CliResult<()>, min_sample: f64) -> CliResult<f64> {
    let mut reps = 1usize;
    loop {
        let t = Instant::now();
        for _ in 0..reps {
            f()?;
        }
        let dt = t.elapsed().as_secs_f64();
        if dt >= min_sample || reps >= 1 << 24 {
            break;
        }
        reps *= if dt < min_sample / 20.0 { 10 } else { 2 };
    }
    let mut samples = Vec::new();
    for _ in 0..5 {
        let t = Instant::now();
        for _ in 0..reps {
            f()?;
        }
        samples.push(t.elapsed().as_secs_f64() / reps as f64);
    }
    samples.sort_by(f64::total_cmp);
    Ok(samples[2])
}

fn speeds() -> Vec<f64> {
    let mut g = vec![0.0; 60];
    sweep::log_space(1e-8, 10.0, &mut g);
    g
}

/// Runs the benchmark; `quick` shortens the timing samples (for tests).
// Long by design: the benchmark's sections in the order the report prints them.
pub fn run(out_dir: &Path, quick: bool) -> CliResult<(Vec<Row>, String)> {
    let min_sample = if quick { 0.002 } else { 0.05 };
    let reference = Accuracy::Tolerance(1e-12); // live DP5 at rtol 1e-14
    let levels = [Accuracy::Fast, Accuracy::Balanced, Accuracy::Precise];
    let g = speeds();
    let mut rows = Vec::new();
    let all = models();
    let mut progress =
        crate::progress::Progress::new("bench", all.len() * levels.len() + levels.len() + 1);
    for (model, scene) in all {
        let contact = Contact::new(&scene)?;
        let truth: Vec<f64> = g
            .iter()
            .map(|&gi| contact.normal(gi, reference).map(|n| n.eps))
            .collect::<Result<_, _>>()?;
        for level in levels {
            progress.step(&format!("{model} at {}", level.name()));
            let mut worst = 0.0f64;
            for (&gi, &t) in g.iter().zip(&truth) {
                let e = contact.normal(gi, level)?.eps;
                if t > 1e-6 {
                    worst = worst.max(((e - t) / t).abs());
                }
            }
            // A single ε_N (the hot path of curves and maps).
            let per_eps = time_it(
                || {
                    for &gi in &g {
                        black_box(contact.eps_n(black_box(gi), level)?);
                    }
                    Ok(())
                },
                min_sample,
            )? / g.len() as f64;
            let per_curve = time_it(
                || {
                    black_box(sweep::curve(&contact, 1e-8, 10.0, 400, level)?);
                    Ok(())
                },
                min_sample,
            )?;
            let per_map = time_it(
                || {
                    black_box(StickMap::new(&contact, 0.05, 200, level)?);
                    Ok(())
                },
                min_sample,
            )?;
            rows.push(Row {
                model,
                level: level.name(),
                max_rel_error: worst,
                ns_per_eps: per_eps * 1e9,
                ms_per_curve: per_curve * 1e3,
                ms_per_map: per_map * 1e3,
            });
        }
    }
    // A full explorer frame on the frost preset: four 400-point curves + one 200×200 map.
    let mut frame = Vec::new();
    let contact = Contact::new(&Preset::IceFrost.scene())?;
    for level in levels {
        progress.step(&format!("explorer frame at {}", level.name()));
        let t = time_it(
            || {
                for _ in 0..4 {
                    black_box(sweep::curve(&contact, 1e-8, 10.0, 400, level)?);
                }
                black_box(StickMap::new(&contact, 0.05, 200, level)?);
                Ok(())
            },
            min_sample,
        )?;
        frame.push((level.name(), t * 1e3));
    }
    let mut text = render(&rows, &frame);
    progress.step("scipy comparison");
    text.push_str(&scipy_comparison(min_sample)?);
    std::fs::create_dir_all(out_dir)
        .map_err(|e| CliError::input(format!("--out {}: {e}", out_dir.display())))?;
    let json = serde_json::json!({ "rows": rows, "frame_ms": frame });
    write_atomic(
        &out_dir.join("bench.json"),
        format!("{json:#}\n").as_bytes(),
    )?;
    write_atomic(
        &out_dir.join("work-precision.svg"),
        work_precision_svg(&rows).as_bytes(),
    )?;
    Ok((rows, text))
}

/// Times scipy's DOP853 (rtol 1e-10) on the same dimensionless ODE via
/// `core/benches/scipy_compare.py`, and rime's Precise ε_N and live DP5 at the same δ, in one run.
fn scipy_comparison(min_sample: f64) -> CliResult<String> {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("../core/benches/scipy_compare.py");
    let output = std::process::Command::new("python3").arg(&script).output();
    let parsed: Option<serde_json::Value> = match output {
        Ok(o) if o.status.success() => serde_json::from_slice(&o.stdout).ok(),
        _ => None,
    };
    let Some(map) = parsed.as_ref().and_then(|v| v.as_object()) else {
        return Ok("\nscipy comparison skipped (python3 with scipy not available)\n".into());
    };
    let mut s = String::from(
        "\nsingle ε_N vs scipy solve_ivp(DOP853, rtol=1e-10), same ODE, same run:\n\
         δ          scipy [µs]   precise [ns]  ratio     live DP5 1e-12 [µs]  ratio   |Δε|/ε\n",
    );
    let end = rime_core::ContactEnd::ForceZero;
    for (key, v) in map {
        let (Ok(delta), Some(t_scipy), Some(e_scipy)) = (
            key.parse::<f64>(),
            v["median_seconds"].as_f64(),
            v["eps"].as_f64(),
        ) else {
            continue;
        };
        let table = rime_core::master::Resolution::Fine;
        let t_precise = time_it(
            || {
                black_box(rime_core::master::eps(black_box(delta), end, table));
                Ok(())
            },
            min_sample,
        )?;
        let t_live = time_it(
            || {
                black_box(rime_core::normal::viscoelastic::dimensionless(
                    black_box(delta),
                    end,
                    1e-12,
                )?);
                Ok(())
            },
            min_sample,
        )?;
        let e = rime_core::master::eps(delta, end, table);
        s.push_str(&format!(
            "{delta:<10} {:>10.1} {:>13.1} {:>9.0}× {:>14.1} {:>11.0}×  {:.1e}\n",
            t_scipy * 1e6,
            t_precise * 1e9,
            t_scipy / t_precise,
            t_live * 1e6,
            t_scipy / t_live,
            ((e - e_scipy) / e_scipy).abs()
        ));
    }
    Ok(s)
}

fn render(rows: &[Row], frame: &[(&str, f64)]) -> String {
    // At most 80 columns (issue 37 R3), the numbers right-aligned under their headers.
    let mut s = format!(
        "{:<16} {:<10} {:>11} {:>10} {:>12} {:>12}\n",
        "model", "level", "max rel err", "ns/ε", "ms/400-curve", "ms/200²-map"
    );
    for r in rows {
        s.push_str(&format!(
            "{:<16} {:<10} {:>11.2e} {:>10.1} {:>12.3} {:>12.3}\n",
            r.model, r.level, r.max_rel_error, r.ns_per_eps, r.ms_per_curve, r.ms_per_map
        ));
    }
    s.push_str("\nexplorer frame (4 × 400-point curves + 200×200 map, ice-frost):\n");
    for (level, ms) in frame {
        s.push_str(&format!("  {level:<9} {ms:>9.3} ms\n"));
    }
    s
}

/// A log–log work–precision figure: error against time per ε evaluation, one marker per
/// (model, level). Hand-written SVG (no font needed).
// Long by design: one SVG document written in drawing order.
fn work_precision_svg(rows: &[Row]) -> String {
    let (w, h, left, bottom, top, right) = (720.0, 480.0, 80.0, 60.0, 40.0, 200.0);
    let pw = w - left - right;
    let ph = h - top - bottom;
    let points: Vec<(f64, f64, &Row)> = rows
        .iter()
        .map(|r| {
            (
                r.ns_per_eps.max(1e-3).log10(),
                r.max_rel_error.max(1e-17).log10(),
                r,
            )
        })
        .collect();
    let (xmin, xmax) = (
        points
            .iter()
            .map(|p| p.0)
            .fold(f64::INFINITY, f64::min)
            .floor(),
        points
            .iter()
            .map(|p| p.0)
            .fold(f64::NEG_INFINITY, f64::max)
            .ceil(),
    );
    let (ymin, ymax) = (
        points
            .iter()
            .map(|p| p.1)
            .fold(f64::INFINITY, f64::min)
            .floor(),
        points
            .iter()
            .map(|p| p.1)
            .fold(f64::NEG_INFINITY, f64::max)
            .ceil(),
    );
    let (xmax, ymax) = (xmax.max(xmin + 1.0), ymax.max(ymin + 1.0));
    let sx = |x: f64| left + (x - xmin) / (xmax - xmin) * pw;
    let sy = |y: f64| top + (ymax - y) / (ymax - ymin) * ph;
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" font-family=\"sans-serif\" font-size=\"12\">\n\
         <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n\
         <text x=\"{}\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">rime: work–precision of ε_N (lower left is better)</text>\n",
        left + pw / 2.0
    );
    for d in (xmin as i32)..=(xmax as i32) {
        let x = sx(d as f64);
        s.push_str(&format!(
            "<line x1=\"{x}\" y1=\"{top}\" x2=\"{x}\" y2=\"{}\" stroke=\"#ddd\"/><text x=\"{x}\" y=\"{}\" text-anchor=\"middle\">1e{d}</text>\n",
            top + ph,
            top + ph + 18.0
        ));
    }
    for d in (ymin as i32)..=(ymax as i32) {
        let y = sy(d as f64);
        s.push_str(&format!(
            "<line x1=\"{left}\" y1=\"{y}\" x2=\"{}\" y2=\"{y}\" stroke=\"#ddd\"/><text x=\"{}\" y=\"{}\" text-anchor=\"end\">1e{d}</text>\n",
            left + pw,
            left - 6.0,
            y + 4.0
        ));
    }
    s.push_str(&format!(
        "<rect x=\"{left}\" y=\"{top}\" width=\"{pw}\" height=\"{ph}\" fill=\"none\" stroke=\"black\"/>\n\
         <text x=\"{}\" y=\"{}\" text-anchor=\"middle\">time per ε_N evaluation [ns]</text>\n\
         <text transform=\"translate(20 {}) rotate(-90)\" text-anchor=\"middle\">max relative error of ε_N</text>\n",
        left + pw / 2.0,
        h - 15.0,
        top + ph / 2.0
    ));
    let colors = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"];
    let markers = ["fast", "integrated", "precise"];
    let mut legend_y = top + 10.0;
    let mut models: Vec<&str> = rows.iter().map(|r| r.model).collect();
    models.dedup();
    for (i, m) in models.iter().enumerate() {
        let c = colors[i % colors.len()];
        let pts: Vec<&(f64, f64, &Row)> = points.iter().filter(|p| p.2.model == *m).collect();
        let path: Vec<String> = pts
            .iter()
            .map(|p| format!("{},{}", sx(p.0), sy(p.1)))
            .collect();
        s.push_str(&format!(
            "<polyline points=\"{}\" fill=\"none\" stroke=\"{c}\" stroke-dasharray=\"4 3\"/>\n",
            path.join(" ")
        ));
        for p in pts {
            let (x, y) = (sx(p.0), sy(p.1));
            let shape = match markers.iter().position(|l| *l == p.2.level) {
                Some(0) => format!("<circle cx=\"{x}\" cy=\"{y}\" r=\"5\" fill=\"{c}\"/>"),
                Some(1) => format!(
                    "<rect x=\"{}\" y=\"{}\" width=\"9\" height=\"9\" fill=\"{c}\"/>",
                    x - 4.5,
                    y - 4.5
                ),
                _ => format!(
                    "<polygon points=\"{},{} {},{} {},{}\" fill=\"{c}\"/>",
                    x,
                    y - 6.0,
                    x - 5.5,
                    y + 4.0,
                    x + 5.5,
                    y + 4.0
                ),
            };
            s.push_str(&shape);
            s.push('\n');
        }
        s.push_str(&format!(
            "<line x1=\"{}\" y1=\"{legend_y}\" x2=\"{}\" y2=\"{legend_y}\" stroke=\"{c}\" stroke-width=\"3\"/><text x=\"{}\" y=\"{}\">{m}</text>\n",
            left + pw + 15.0,
            left + pw + 35.0,
            left + pw + 40.0,
            legend_y + 4.0
        ));
        legend_y += 20.0;
    }
    legend_y += 10.0;
    for (label, shape) in [
        ("fast (coarse table)", "circle"),
        ("integrated (live DP5)", "square"),
        ("precise (fine table)", "triangle"),
    ] {
        let x = left + pw + 25.0;
        let mark = match shape {
            "circle" => format!("<circle cx=\"{x}\" cy=\"{legend_y}\" r=\"5\" fill=\"#555\"/>"),
            "square" => format!(
                "<rect x=\"{}\" y=\"{}\" width=\"9\" height=\"9\" fill=\"#555\"/>",
                x - 4.5,
                legend_y - 4.5
            ),
            _ => format!(
                "<polygon points=\"{x},{} {},{} {},{}\" fill=\"#555\"/>",
                legend_y - 6.0,
                x - 5.5,
                legend_y + 4.0,
                x + 5.5,
                legend_y + 4.0
            ),
        };
        s.push_str(&format!(
            "{mark}<text x=\"{}\" y=\"{}\">{label}</text>\n",
            left + pw + 40.0,
            legend_y + 4.0
        ));
        legend_y += 20.0;
    }
    s.push_str("</svg>\n");
    s
}

#[cfg(test)]
mod issue_37_tests {
    use super::{Row, models, render};

    /// Issue 37 (review R3): `rime bench`'s table fits 80 columns with the longest model name and
    /// numbers as wide as its columns take; each row's numbers read back.
    #[test]
    fn issue_37_the_bench_table_fits_80_columns() {
        let rows: Vec<Row> = models()
            .into_iter()
            .map(|(model, _)| Row {
                model,
                level: "integrated",
                max_rel_error: 2.68e-10,
                ns_per_eps: 905217.7,
                ms_per_curve: 12345.678,
                ms_per_map: 23456.789,
            })
            .collect();
        let text = render(&rows, &[("integrated", 20.966)]);
        for line in text.lines() {
            assert!(
                line.chars().count() <= 80,
                "{} columns: {line}",
                line.chars().count()
            );
        }
        for r in &rows {
            let row = text
                .lines()
                .find(|l| l.starts_with(r.model))
                .unwrap_or_else(|| panic!("{}: {text}", r.model));
            let numbers: Vec<f64> = row[16..]
                .split_whitespace()
                .filter_map(|c| c.parse().ok())
                .collect();
            assert_eq!(numbers, [2.68e-10, 905217.7, 12345.678, 23456.789], "{row}");
        }
    }
}
