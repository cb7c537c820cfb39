//! Measured ice (issue 15): the data atlas on the command line, fits with standard errors checked
//! against the Monte-Carlo spread of refits, and sticking thresholds exported as C.

use crate::bin::{rime, rime_json as json};
use rime_core::fit_scene::fit;
use rime_core::{Accuracy, Contact, Preset, Scene};
use rime_tests::rel;
use std::process::Command;

fn scratch(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("rime-measured-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// splitmix64 and Box–Muller: a seeded normal deviate generator for the Monte-Carlo tests.
struct Normal(u64);

impl Normal {
    fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn next(&mut self) -> f64 {
        let u = self.uniform().max(1e-300);
        let v = self.uniform();
        (-2.0 * u.ln()).sqrt() * (2.0 * std::f64::consts::PI * v).cos()
    }
}

fn log_space(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| (a.ln() + (b.ln() - a.ln()) * i as f64 / (n - 1) as f64).exp())
        .collect()
}

fn std_dev(x: &[f64]) -> f64 {
    let m = x.iter().sum::<f64>() / x.len() as f64;
    (x.iter().map(|v| (v - m) * (v - m)).sum::<f64>() / (x.len() - 1) as f64).sqrt()
}

/// Refits `refits` noisy copies of the scene's own curve; returns per parameter the sample standard
/// deviation of the fitted values and the mean reported standard error.
fn monte_carlo(
    scene: &Scene,
    params: &[&str],
    g: &[f64],
    sigma: f64,
    weighted: bool,
    refits: usize,
) -> Vec<(f64, f64)> {
    let c = Contact::new(scene).unwrap();
    let truth: Vec<f64> = g
        .iter()
        .map(|&x| c.eps_n(x, Accuracy::Fast).unwrap())
        .collect();
    let mut rng = Normal(20260115);
    let s = vec![sigma; g.len()];
    let mut values = vec![Vec::new(); params.len()];
    let mut reported = vec![0.0; params.len()];
    for _ in 0..refits {
        let noisy: Vec<f64> = truth.iter().map(|e| e + sigma * rng.next()).collect();
        let f = fit(
            scene,
            params,
            g,
            &noisy,
            weighted.then_some(&s[..]),
            Accuracy::Fast,
        )
        .unwrap();
        for (k, p) in f.params.iter().enumerate() {
            values[k].push(p.value);
            reported[k] += p.standard_error.unwrap() / refits as f64;
        }
    }
    values
        .iter()
        .zip(reported)
        .map(|(v, r)| (std_dev(v), r))
        .collect()
}

#[test]
fn reported_standard_error_matches_the_spread_of_refits() {
    // ε_N with σ = 0.02 noise on 16 speeds; the truth is the default scene (A = 1e-4 s).
    let g = log_space(1e-3, 1.0, 16);
    for weighted in [false, true] {
        let r = monte_carlo(
            &Scene::default(),
            &["bulk.damping.time"],
            &g,
            0.02,
            weighted,
            200,
        );
        let (spread, reported) = r[0];
        eprintln!("weighted {weighted}: reported {reported:e}, Monte-Carlo spread {spread:e}");
        assert!(
            rel(reported, spread) < 0.2,
            "weighted {weighted}: reported {reported:e}, Monte-Carlo spread {spread:e}"
        );
    }
}

#[test]
fn two_parameter_standard_errors_match_the_spread_of_refits() {
    // A and the layer viscosity act in different speed ranges (layer near g_s = 6.6 µm/s).
    let g = log_space(8e-6, 1.0, 24);
    let r = monte_carlo(
        &Preset::IceFrost.scene(),
        &["bulk.damping.time", "layer.viscosity"],
        &g,
        0.02,
        true,
        200,
    );
    for (k, (spread, reported)) in r.iter().enumerate() {
        eprintln!("parameter {k}: reported {reported:e}, Monte-Carlo spread {spread:e}");
        assert!(
            rel(*reported, *spread) < 0.2,
            "parameter {k}: reported {reported:e}, Monte-Carlo spread {spread:e}"
        );
    }
}

#[test]
fn data_lists_the_atlas_with_the_contract_fields() {
    let v = json(&["data"]);
    let rows = v.as_array().unwrap();
    for id in [
        "bridges1984",
        "hatzes1988_frost",
        "hatzes1988_compacted",
        "supulver1995",
        "higa1996",
        "borderies1984",
        "heisselmann2010",
        "hill2015",
        "gundlach2015",
        "musiolik2019",
    ] {
        let r = rows
            .iter()
            .find(|r| r["id"] == id)
            .unwrap_or_else(|| panic!("{id}"));
        for key in ["kind", "citation", "temperature", "geometry", "source"] {
            assert!(!r[key].is_null(), "{id}: {key}");
        }
        let s = r["valid_speed"].as_array().unwrap();
        assert!(s[0].as_f64().unwrap() <= s[1].as_f64().unwrap(), "{id}");
        assert!(r["citation"]["year"].as_u64().unwrap() >= 1984);
    }
}

#[test]
fn data_evaluates_a_law_and_flags_extrapolation() {
    let v = json(&["data", "--law", "bridges1984", "--g", "0.01,1"]);
    // (1 cm/s / 0.0077 cm/s)^-0.234 = 0.3202129 (python3).
    assert!((v[0]["eps_n"].as_f64().unwrap() - 0.320_212_9).abs() < 1e-7);
    assert_eq!(v[0]["extrapolated"], false);
    assert_eq!(v[1]["extrapolated"], true);
    // r = 2.5 cm at 1 cm/s: 0.90 exp(-0.385) = 0.6124056 (python3).
    let v = json(&[
        "data",
        "--law",
        "hatzes1988_compacted",
        "--g",
        "0.01",
        "--radius",
        "0.025",
    ]);
    assert!((v[0]["eps_n"].as_f64().unwrap() - 0.612_405_6).abs() < 1e-7);
    let (code, _, err) = rime(&["data", "--law", "nope", "--g", "1"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("--law") && err.contains("bridges1984"),
        "{err}"
    );
    let (code, _, err) = rime(&["data", "--law", "hatzes1988_compacted", "--g", "1"]);
    assert_eq!(code, 2);
    assert!(err.contains("--radius"), "{err}");
}

#[test]
fn fit_names_bad_lines_and_never_switches_an_effect_on() {
    let dir = scratch("fit");
    let bad = dir.join("bad.csv");
    std::fs::write(&bad, "0.01,x\n0.1,0.3\n0.2,0.3\n").unwrap();
    let (code, _, err) = rime(&["fit", "--data", bad.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("line 1"), "{err}");
    let good = dir.join("good.csv");
    std::fs::write(
        &good,
        "g eps sigma\n0.001 0.6 0.05\n0.01 0.36 0.05\n0.1 0.2 0.05\n1 0.1 0.05\n",
    )
    .unwrap();
    let v = json(&[
        "fit",
        "--data",
        good.to_str().unwrap(),
        "--accuracy",
        "fast",
    ]);
    assert_eq!(v["header"], "g eps sigma");
    assert_eq!(v["weighted"], true);
    assert!(v["standard_error"].as_f64().unwrap() > 0.0);
    let (code, _, err) = rime(&[
        "fit",
        "--data",
        good.to_str().unwrap(),
        "--param",
        "layer.viscosity",
    ]);
    assert_eq!(code, 2);
    assert!(
        err.contains("layer.viscosity") && err.contains("off"),
        "{err}"
    );
    let (code, _, err) = rime(&["fit", "--data", dir.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("not a regular file"), "{err}");
    // A, Y and R enter ε only through δ: fitting two of them is degenerate, and said so.
    let v = json(&[
        "fit",
        "--law",
        "bridges1984",
        "--param",
        "bulk.damping.time,bulk.youngs_modulus",
        "--accuracy",
        "fast",
    ]);
    let w = v["warnings"].as_array().unwrap();
    assert!(
        w.iter().any(|w| w.as_str().unwrap().contains("degenerate")),
        "{w:?}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn stick_exports_a_c_function_that_reproduces_the_table() {
    let dir = scratch("stick");
    let d = dir.to_str().unwrap();
    let v = json(&[
        "stick",
        "--radius",
        "1e-6,1e-3",
        "--temperature",
        "150,187.5,250",
        "--accuracy",
        "fast",
        "--out",
        d,
    ]);
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), 6);
    // Eq. (15) by hand (python3), r = 1 µm, ρ = 900, Y = 10 GPa, ν = 0.3, w = 2 × 0.19 J/m²:
    // 1.0973227 m/s, 8.7 times below the measured 9.6 m/s — which was measured below ~210 K only.
    let warm = &rows[2];
    assert!(rel(warm["v_elastic"].as_f64().unwrap(), 1.097_322_7) < 1e-6);
    assert!(warm["measured_v_stick"].is_null());
    assert_eq!(rows[0]["measured_v_stick"], 9.6);
    let main = dir.join("probe.c");
    let src = std::fs::read_to_string(dir.join("rime_v_stick.c")).unwrap();
    std::fs::write(
        &main,
        format!(
            "{src}\n#include <stdio.h>\n#include <stdlib.h>\nint main(int c, char **v) {{ for (int i = 1; i + 1 < c; i += 2) printf(\"%.17g\\n\", rime_v_stick_elastic(atof(v[i]), atof(v[i + 1]))); return 0; }}\n"
        ),
    )
    .unwrap();
    let exe = dir.join("probe");
    let cc = Command::new("cc")
        .arg("-O2")
        .arg("-o")
        .arg(&exe)
        .arg(&main)
        .arg("-lm")
        .status()
        .expect("a C compiler (cc) is needed for this test");
    assert!(cc.success(), "generated C does not compile");
    let mut args = Vec::new();
    for r in rows {
        args.push(format!("{:?}", r["radius"].as_f64().unwrap()));
        args.push(format!("{:?}", r["temperature"].as_f64().unwrap()));
    }
    let out = Command::new(&exe).args(&args).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    assert_eq!(text.lines().count(), rows.len());
    for (line, r) in text.lines().zip(rows) {
        let got: f64 = line.trim().parse().unwrap();
        let want = r["v_elastic"].as_f64().unwrap();
        assert!(rel(got, want) < 1e-12, "C {got} vs table {want}");
    }
    let csv = std::fs::read_to_string(dir.join("stick_table.csv")).unwrap();
    assert_eq!(csv.lines().count(), 7);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Issue 22: `rime stick` takes units like every other flag ("1 um", "200 K") and prints them, and
/// says which A its v_stick column uses (the scene's) and that v_elastic uses A = 0.
#[test]
fn stick_takes_units_and_prints_them_issue_22() {
    let plain = json(&[
        "stick",
        "--radius",
        "1e-6,2e-3",
        "--temperature",
        "180,200",
        "--accuracy",
        "fast",
    ]);
    let units = json(&[
        "stick",
        "--radius",
        "1 um,2 mm",
        "--temperature",
        "180 K,200K",
        "--accuracy",
        "fast",
    ]);
    assert_eq!(plain, units);
    assert_eq!(plain[0]["damping_time"], 1e-4);
    let (code, out, _) = rime(&[
        "stick",
        "--radius",
        "1 um",
        "--temperature",
        "200",
        "--format",
        "table",
    ]);
    assert_eq!(code, 0);
    for needle in [
        "radius [m]",
        "temperature [K]",
        "v_elastic [m/s]",
        "v_stick [m/s]",
        "the scene's A = 100 µs",
        "A = 0 and no layer",
    ] {
        assert!(out.contains(needle), "missing {needle}\n{out}");
    }
    let (code, out, _) = rime(&[
        "stick",
        "--radius",
        "1 um",
        "--set",
        "bulk.damping.time=2 ms",
        "--format",
        "table",
    ]);
    assert_eq!(code, 0);
    assert!(out.contains("the scene's A = 2 ms"), "{out}");
    let (code, _, err) = rime(&["stick", "--radius", "1 ft"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("--radius 1 ft") && err.contains("a length"),
        "{err}"
    );
    let (code, csv, _) = rime(&[
        "stick",
        "--radius",
        "1 um",
        "--temperature",
        "200",
        "--format",
        "csv",
    ]);
    assert_eq!(code, 0);
    assert!(csv.starts_with("radius [m],temperature [K],"), "{csv}");
}
