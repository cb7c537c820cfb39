//! The `rime` binary's subcommands: the JSON/CSV contract of docs/cli.md and bad input.

use crate::bin::{rime, rime_json as json};
use rime_tests::rel;

#[test]
fn eps_json_has_the_contract_fields_in_order_given() {
    let v = json(&["eps", "--g", "0.01,0.001", "--accuracy", "precise"]);
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), 2);
    assert_eq!(rows[0]["g_n"], 0.01);
    assert_eq!(rows[1]["g_n"], 0.001);
    for r in rows {
        for key in ["g_n", "eps_n", "status", "t_c", "xi_max"] {
            assert!(r.get(key).is_some(), "missing {key}");
        }
        assert_eq!(r["status"], "rebound");
    }
    // Same as the library at the same accuracy.
    let c = rime_core::Contact::new(&rime_core::Scene::default()).unwrap();
    let e = c.normal(0.01, rime_core::Accuracy::Precise).unwrap().eps;
    assert_eq!(rows[0]["eps_n"].as_f64().unwrap(), e);
}

#[test]
fn statuses_are_snake_case_and_stuck_durations_are_null() {
    let v = json(&["eps", "--preset", "ice-frost", "--g", "1e-7"]);
    assert_eq!(v[0]["status"], "stuck_in_layer");
    assert!(v[0]["t_c"].is_null());
    let v = json(&["eps", "--preset", "ice-sticky", "--g", "1e-5"]);
    assert_eq!(v[0]["status"], "stuck_by_adhesion");
    let v = json(&["eps", "--preset", "ice-paper-viscosities", "--g", "0.01"]);
    assert_eq!(v[0]["status"], "overdamped");
}

#[test]
fn curve_is_log_spaced_with_both_ends_and_csv_matches_json() {
    let v = json(&["curve", "--from", "1e-6", "--to", "1", "--points", "7"]);
    let g: Vec<f64> = v
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["g_n"].as_f64().unwrap())
        .collect();
    assert_eq!(g.len(), 7);
    assert_eq!(g[0], 1e-6);
    assert_eq!(g[6], 1.0);
    for (i, gi) in g.iter().enumerate() {
        assert!(rel(*gi, 10f64.powi(i as i32 - 6)) < 1e-12);
    }
    let (code, csv, _) = rime(&[
        "curve", "--from", "1e-6", "--to", "1", "--points", "7", "--format", "csv",
    ]);
    assert_eq!(code, 0);
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "g_n [m/s],eps_n,status,t_c [s],xi_max [m],error_estimate"
    );
    for (line, row) in lines.zip(v.as_array().unwrap()) {
        let eps: f64 = line.split(',').nth(1).unwrap().parse().unwrap();
        assert_eq!(eps, row["eps_n"].as_f64().unwrap());
    }
}

#[test]
fn map_grid_and_classes() {
    let v = json(&["map", "--preset", "ice-frost", "--max", "1e-4", "--n", "5"]);
    let g: Vec<f64> = v["g"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert_eq!(g.len(), 5);
    for (i, gi) in g.iter().enumerate() {
        assert!((gi - 2.5e-5 * i as f64).abs() < 1e-18, "{g:?}");
    }
    assert_eq!(g[4], 1e-4);
    let class = v["class"].as_array().unwrap();
    assert_eq!(class.len(), 5);
    assert_eq!(class[0][0], "undefined");
    let names: Vec<&str> = rime_core::StickClass::ALL
        .iter()
        .map(|c| c.name())
        .collect();
    for row in class {
        for c in row.as_array().unwrap() {
            assert!(names.contains(&c.as_str().unwrap()));
        }
    }
}

#[test]
fn tangential_matches_the_library() {
    let v = json(&["tangential", "--gn", "0.01", "--gt", "0.001,0.05"]);
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), 2);
    assert_eq!(rows[0]["class"], "rolling");
    assert_eq!(rows[1]["class"], "sliding");
    for key in ["g_n", "g_t", "eps_t", "eps_n", "class"] {
        assert!(rows[0].get(key).is_some());
    }
}

#[test]
fn tidal_reports_the_appendix_values() {
    let v = json(&["tidal"]);
    assert!(rel(v["delta_f"].as_f64().unwrap(), 3.84e-11) < 2e-3);
    assert!(rel(v["d_roche"].as_f64().unwrap(), 1.341e8) < 1e-3);
}

#[test]
fn scene_round_trips_through_a_file() {
    let dir = std::env::temp_dir().join(format!("rime-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("scene.json");
    let f = file.to_str().unwrap();
    let (code, _, err) = rime(&[
        "scene",
        "--preset",
        "ice-frost",
        "--set",
        "layer.viscosity=2 kPa s",
        "--out",
        f,
    ]);
    assert_eq!(code, 0, "{err}");
    let v = json(&["scene", "--scene", f]);
    assert_eq!(v["layer"]["viscosity"], 2000.0);
    assert_eq!(v["layer"]["reading"], "offset");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn bad_input_is_one_line_naming_the_field_with_exit_code_2() {
    let dir = std::env::temp_dir().join(format!("rime-cli-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let typo = dir.join("typo.json");
    std::fs::write(&typo, r#"{"grains":{"radius_1":0.02,"radius_2":0.02,"density":900,"colour":1},"bulk":{"youngs_modulus":1e10,"poisson_ratio":0.3,"damping":{"time":1e-4}}}"#).unwrap();
    let negative = dir.join("negative.json");
    std::fs::write(&negative, r#"{"grains":{"radius_1":0.02,"radius_2":0.02,"density":-900},"bulk":{"youngs_modulus":1e10,"poisson_ratio":0.3,"damping":{"time":1e-4}}}"#).unwrap();
    let wrong_type = dir.join("wrong.json");
    std::fs::write(&wrong_type, r#"{"grains":{"radius_1":"big","radius_2":0.02,"density":900},"bulk":{"youngs_modulus":1e10,"poisson_ratio":0.3,"damping":{"time":1e-4}}}"#).unwrap();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["eps", "--g", "-1"], "--g"),
        (vec!["eps", "--g", "abc"], "--g"),
        (
            vec!["eps", "--g", "0.01", "--set", "layer.viscosity=-5"],
            "layer.viscosity",
        ),
        (
            vec!["eps", "--g", "0.01", "--set", "layer.thickness=1 Pa"],
            "layer.thickness",
        ),
        (vec!["eps", "--g", "0.01", "--set", "no.such=1"], "no.such"),
        (
            vec!["eps", "--g", "0.01", "--accuracy", "sloppy"],
            "accuracy",
        ),
        (vec!["eps", "--g", "0.01", "--format", "xml"], "--format"),
        (
            vec!["eps", "--g", "0.01", "--scene", typo.to_str().unwrap()],
            "colour",
        ),
        (
            vec!["eps", "--g", "0.01", "--scene", negative.to_str().unwrap()],
            "grains.density",
        ),
        (
            vec![
                "eps",
                "--g",
                "0.01",
                "--scene",
                wrong_type.to_str().unwrap(),
            ],
            "grains.radius_1",
        ),
        (
            vec!["eps", "--g", "0.01", "--scene", "/nonexistent/scene.json"],
            "--scene",
        ),
        (vec!["map", "--max", "0.01", "--n", "1"], "--n"),
        (vec!["curve", "--from", "1", "--to", "0.1"], "--to"),
        (vec!["eps"], "--g"),
        (vec!["frobnicate"], "frobnicate"),
        (vec!["eps", "--g", "0.01", "--bogus", "1"], "--bogus"),
        (
            vec![
                "eps",
                "--g",
                "0.01",
                "--set",
                "bulk.poisson_ratio=0",
                "--set",
                "bulk.damping.viscosities.shear=1e6",
            ],
            "poisson_ratio",
        ),
    ];
    for (args, field) in cases {
        let (code, out, err) = rime(&args);
        assert_eq!(code, 2, "{args:?}: {out} {err}");
        assert!(out.is_empty(), "{args:?}");
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(field), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

fn write_points(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("rime-fit-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("points.csv");
    std::fs::write(&path, text).unwrap();
    path
}

/// Issue 22: a `g [cm/s]` column is read as cm/s (it was fitted as m/s, 100× off, silently); the
/// same points in m/s give the same A; a file without units says what it assumed.
#[test]
fn fit_reads_cm_per_s_from_the_header_issue_22() {
    let si = write_points(
        "si",
        "g [m/s],eps\n0.001,0.55\n0.01,0.36\n0.1,0.22\n1,0.12\n",
    );
    let cm = write_points("cm", "g [cm/s],eps\n0.1,0.55\n1,0.36\n10,0.22\n100,0.12\n");
    let bare = write_points("bare", "0.001,0.55\n0.01,0.36\n0.1,0.22\n1,0.12\n");
    let fit =
        |p: &std::path::Path| json(&["fit", "--data", p.to_str().unwrap(), "--format", "json"]);
    let (a, b, c) = (fit(&si), fit(&cm), fit(&bare));
    let value = |v: &serde_json::Value| v["value"].as_f64().unwrap();
    assert!(rel(value(&a), value(&b)) < 1e-9, "{a} vs {b}");
    assert_eq!(value(&a), value(&c));
    assert_eq!(
        (b["g_unit"].as_str(), b["g_unit_assumed"].as_bool()),
        (Some("cm/s"), Some(false))
    );
    assert_eq!(
        (c["g_unit"].as_str(), c["g_unit_assumed"].as_bool()),
        (Some("m/s"), Some(true))
    );
    let (code, out, _) = rime(&["fit", "--data", cm.to_str().unwrap(), "--format", "table"]);
    assert_eq!(code, 0);
    assert!(
        out.contains("g in cm/s (from the header), converted to m/s"),
        "{out}"
    );
    let (code, out, _) = rime(&["fit", "--data", bare.to_str().unwrap(), "--format", "table"]);
    assert_eq!(code, 0);
    assert!(out.contains("g taken in m/s"), "{out}");
    // A unit it does not know: refused, naming the column.
    let bad = write_points("bad", "g [ft/s],eps\n0.1,0.55\n1,0.36\n10,0.22\n");
    let (code, _, err) = rime(&["fit", "--data", bad.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        err.contains("column 'g [ft/s]'") && err.contains("unknown unit"),
        "{err}"
    );
}

/// Issue 22: the fit gives its residuals, a runs test, says χ² is unscaled without σ and prints
/// the standard error to 2 significant digits (the value to the same place).
#[test]
fn fit_reports_residuals_misfit_and_two_digit_errors_issue_22() {
    let p = write_points(
        "misfit",
        "g,eps\n1e-4,0.9\n3e-4,0.85\n1e-3,0.8\n3e-3,0.5\n0.01,0.3\n0.03,0.2\n0.1,0.15\n0.3,0.12\n1,0.1\n",
    );
    let v = json(&["fit", "--data", p.to_str().unwrap(), "--format", "json"]);
    let residuals = v["residuals"].as_array().unwrap();
    assert_eq!(residuals.len(), 9);
    assert_eq!(v["chi2_scaled"], false);
    assert!(v["runs_test"]["p"].as_f64().unwrap() <= 1.0);
    let (code, out, _) = rime(&["fit", "--data", p.to_str().unwrap(), "--format", "table"]);
    assert_eq!(code, 0);
    assert!(out.contains("unscaled"), "{out}");
    assert!(out.contains("residuals eps - model"), "{out}");
    let line = out
        .lines()
        .find(|l| l.starts_with("bulk.damping.time"))
        .unwrap();
    // "bulk.damping.time = 9.87e-5 ± 1.2e-6 s": two significant digits after ±.
    let se = line
        .split('±')
        .nth(1)
        .unwrap()
        .split_whitespace()
        .next()
        .unwrap();
    let mantissa: String = se
        .split('e')
        .next()
        .unwrap()
        .chars()
        .filter(char::is_ascii_digit)
        .collect();
    assert!(mantissa.trim_start_matches('0').len() <= 2, "{line}");
    let value = line
        .split('=')
        .nth(1)
        .unwrap()
        .split('±')
        .next()
        .unwrap()
        .trim();
    assert!(value.len() <= 10, "{line}");
}

/// Issue 22: tables people read flag the sliding gap as the printed law's artifact; the map's
/// legend uses the human label.
#[test]
fn tables_flag_the_sliding_gap_as_the_papers_artifact_issue_22() {
    let (code, out, _) = rime(&[
        "tangential",
        "--gn",
        "0.01",
        "--gt",
        "0.02",
        "--format",
        "table",
    ]);
    assert_eq!(code, 0);
    assert!(
        out.contains("sliding_gap: an artifact of the printed Eq. (23)"),
        "{out}"
    );
    let (code, out, _) = rime(&["map", "--max", "0.02", "--n", "6", "--format", "table"]);
    assert_eq!(code, 0);
    assert!(
        out.contains("sliding gap (artifact of the printed Eq. (23))"),
        "{out}"
    );
    assert!(!out.contains("sliding_gap"), "{out}");
}

/// Issue 24: the ring card (built by the core for the page and the terminal) prints what
/// `rime ring` computes: every printed number reads back as the CLI's value at its printed digits.
#[test]
fn issue_24_the_ring_card_and_rime_ring_agree_to_the_printed_digits() {
    use rime_core::explorer::format::agrees_to_printed;
    use rime_core::explorer::ring::ring_card;
    use rime_core::ring::{Orbit, RingInput};
    use rime_core::units::parse_quantity;
    for (radius, friction) in [("0.02", true), ("0.02", false), ("1", true)] {
        let mut args = vec![
            "ring",
            "--preset",
            "ice",
            "--tau",
            "0.5",
            "--omega",
            "1.3143527e-4",
            "--radius",
            radius,
        ];
        if !friction {
            args.extend(["--set", "friction=off"]);
        }
        let cli = json(&args);
        let mut scene = rime_core::Preset::Ice.scene();
        let r: f64 = radius.parse().unwrap();
        scene.grains.radius_1 = r;
        scene.grains.radius_2 = r;
        if !friction {
            scene.friction = None;
        }
        let input = RingInput {
            tau: 0.5,
            orbit: Orbit::Omega(1.3143527e-4),
            damping_set_for_radius: (r != 0.02).then_some(0.02),
        };
        let card = ring_card(&scene, &input, (1e-7, 1.0)).unwrap();
        assert_eq!(card.verdict, cli["verdict_words"], "{args:?}");
        assert_eq!(card.equilibrium, cli["equilibrium"], "{args:?}");
        // A printed "34.16 mm" is compared as 34.16 against the CLI's value in mm: converting the
        // printed text to metres first would add float noise to its digits.
        let printed = |label: &str, unit: &str, computed: f64| {
            let text = &card.rows.iter().find(|r| r.label == label).unwrap().text;
            let shown = text.split(" (").next().unwrap();
            let (number, scale) = match shown.split_once(' ') {
                Some((n, u)) => (n, parse_quantity("unit", &format!("1 {u}"), unit).unwrap()),
                None => (shown, 1.0),
            };
            (
                text.clone(),
                number.parse::<f64>().unwrap(),
                computed / scale,
            )
        };
        for (label, unit, key) in [
            ("velocity dispersion c", "m/s", "velocity_dispersion"),
            ("thickness H (rms z)", "m", "thickness"),
            ("mean impact speed √π c", "m/s", "mean_impact_speed"),
            ("ε_cr at the balance", "1", "eps_cr"),
            ("ε̄ of the impacts", "1", "eps_effective"),
        ] {
            let (text, shown, computed) = printed(label, unit, cli[key].as_f64().unwrap());
            assert!(
                agrees_to_printed(computed, shown),
                "{args:?} {key}: card {text} vs rime ring {computed}"
            );
        }
    }
}

/// Issue 24: the A-ring patch of 2 cm `ice` balances (at the monolayer floor with the scene's
/// friction, above it for smooth grains); the metre-size patch heats unless A is scaled with R.
#[test]
fn issue_24_ring_verdicts_and_the_a_over_r_note() {
    let base = [
        "ring",
        "--preset",
        "ice",
        "--tau",
        "0.5",
        "--omega",
        "1.3143527e-4",
    ];
    let with = |extra: &[&str]| {
        let mut a: Vec<&str> = base.to_vec();
        a.extend_from_slice(extra);
        json(&a)
    };
    let small = with(&["--radius", "0.02"]);
    assert_eq!(small["verdict"], "monolayer_floor");
    // The issue's "done when": the 2 cm patch prints an equilibrium (the floor is one).
    assert_eq!(small["equilibrium"], true);
    assert_eq!(small["verdict_words"], "equilibrium at the monolayer floor");
    assert_eq!(small["smooth"]["verdict"], "equilibrium");
    assert!(small["damping_note"].is_null());
    // The floor is 2RΩ; thickness = c_z/Ω with c_z/c = √(1 − 1.5/(ν̂² + 5.5)), ν̂ = b·8τ/π·Y(φ).
    let r_omega = 0.02 * 1.3143527e-4;
    assert!(
        rel(
            small["velocity_dispersion"].as_f64().unwrap(),
            2.0 * r_omega
        ) < 1e-12
    );
    // Smooth balance: ε̄ = ε_cr at the printed dispersion.
    let s = &small["smooth"];
    assert!(
        rel(
            s["eps_effective"].as_f64().unwrap(),
            s["eps_cr"].as_f64().unwrap()
        ) < 1e-6
    );
    assert!(
        rel(
            s["mean_impact_speed"].as_f64().unwrap(),
            std::f64::consts::PI.sqrt() * s["velocity_dispersion"].as_f64().unwrap()
        ) < 1e-12
    );
    let big = with(&["--radius", "1"]);
    assert_eq!(big["verdict"], "heats");
    assert_eq!(big["equilibrium"], false);
    assert_eq!(big["scaled_damping_time"], 5e-3);
    assert!(
        big["damping_note"]
            .as_str()
            .unwrap()
            .contains("a different material")
    );
    let scaled = with(&["--radius", "1", "--scale-damping"]);
    assert_ne!(scaled["verdict"], "heats");
    assert_eq!(scaled["damping_time"], 5e-3);
    assert!(
        scaled["damping_note"]
            .as_str()
            .unwrap()
            .contains("different material")
    );
    // The planet form gives Ω = √(GM/d³).
    let planet = json(&[
        "ring",
        "--tau",
        "0.5",
        "--planet-mass",
        "5.688e26",
        "--distance",
        "1.336e8",
    ]);
    let omega = (6.672e-11 * 5.688e26 / 1.336e8f64.powi(3)).sqrt();
    assert!(rel(planet["omega"].as_f64().unwrap(), omega) < 1e-15);
    for (args, field) in [
        (vec!["ring", "--omega", "1e-4"], "--tau"),
        (vec!["ring", "--tau", "0.5"], "--omega"),
        (vec!["ring", "--tau", "-1", "--omega", "1e-4"], "tau"),
        (vec!["ring", "--tau", "0.5", "--omega", "0"], "omega"),
        (
            vec!["ring", "--tau", "0.5", "--planet-mass", "1e26"],
            "--distance",
        ),
        (
            vec!["ring", "--tau", "0.5", "--omega", "1e-4", "--scale-damping"],
            "--scale-damping",
        ),
    ] {
        let (code, _, err) = rime(&args);
        assert_eq!(code, 2, "{args:?}");
        assert!(err.contains(field), "{args:?}: {err}");
    }
}

/// Issue 35: A set in the same command as `--radius` (and no grain radius) is A of those grains:
/// no "was set for 0.02 m grains" note, no A′, the record of a scene whose own grains are that
/// size; `--scale-damping` has nothing to scale then. With the grains' radius set too, A is theirs.
#[test]
fn issue_35_ring_a_given_for_the_radius_grains_is_not_rescaled() {
    let base = [
        "ring",
        "--preset",
        "ice",
        "--tau",
        "0.5",
        "--omega",
        "1.3143527e-4",
    ];
    let with = |extra: &[&str]| {
        let mut a: Vec<&str> = base.to_vec();
        a.extend_from_slice(extra);
        json(&a)
    };
    let given = with(&["--radius", "1", "--set", "bulk.damping.time=5e-3"]);
    assert!(given["damping_note"].is_null(), "{}", given["damping_note"]);
    assert!(given["scaled_damping_time"].is_null());
    assert_eq!(given["damping_time"], 5e-3);
    let own = with(&[
        "--set",
        "grains.radius_1=1",
        "--set",
        "grains.radius_2=1",
        "--set",
        "bulk.damping.time=5e-3",
    ]);
    assert_eq!(given, own);
    // A for the 2 cm grains named in the command: the note stays, with A' = A·R/R_set.
    let named = with(&[
        "--radius",
        "1",
        "--set",
        "bulk.damping.time=5e-3",
        "--set",
        "grains.radius_1=0.02",
        "--set",
        "grains.radius_2=0.02",
    ]);
    assert!(rel(named["scaled_damping_time"].as_f64().unwrap(), 0.25) < 1e-12);
    assert!(
        named["damping_note"]
            .as_str()
            .unwrap()
            .contains("was set for 0.02 m grains")
    );
    let mut args = base.to_vec();
    args.extend_from_slice(&[
        "--radius",
        "1",
        "--set",
        "bulk.damping.time=5e-3",
        "--scale-damping",
    ]);
    let (code, _, err) = rime(&args);
    assert_eq!(code, 2);
    assert!(err.contains("--scale-damping: A was given here"), "{err}");
}
