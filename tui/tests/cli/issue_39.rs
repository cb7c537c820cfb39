//! Issue 39, the command line: `rime kernel` (the sticking kernel v_stick(a_i, a_j, T)): the
//! records, equal radii against `rime stick`, symmetry, the provenance, the A rules, the figure,
//! the table for people and bad flags named.

use crate::bin::rime;
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let (code, out, err) = rime(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

fn records(v: &Value) -> &Vec<Value> {
    v["records"].as_array().unwrap()
}

fn f(v: &Value, key: &str) -> f64 {
    v[key].as_f64().unwrap()
}

#[test]
fn issue_39_kernel_records_equal_stick_on_the_diagonal_and_are_symmetric() {
    let k = json(&[
        "kernel",
        "--radii",
        "1um..1cm",
        "--points",
        "20",
        "--temperatures",
        "150,200",
        "--format",
        "json",
    ]);
    let recs = records(&k);
    assert_eq!(recs.len(), 2 * 20 * 20);
    // Radii equal in log from 1 µm to 1 cm.
    for (i, r) in recs[..20].iter().enumerate() {
        let expected = 1e-6 * 10f64.powf(4.0 * i as f64 / 19.0);
        assert!((f(r, "radius_2") / expected - 1.0).abs() < 1e-12);
        assert_eq!(f(r, "radius_1"), 1e-6);
    }
    let at = |t: usize, i: usize, j: usize| &recs[(t * 20 + i) * 20 + j];
    let radii: Vec<String> = (0..20)
        .map(|i| at(0, i, i)["radius_1"].to_string())
        .collect();
    let stick = json(&[
        "stick",
        "--radius",
        &radii.join(","),
        "--temperature",
        "150,200",
        "--format",
        "json",
    ]);
    let stick = stick.as_array().unwrap();
    assert_eq!(stick.len(), 40);
    let mut outcomes = [0, 0];
    for (i, s) in stick.iter().enumerate() {
        // stick is radius-major, temperature-minor.
        let (ri, t) = (i / 2, i % 2);
        let r = at(t, ri, ri);
        assert_eq!(f(r, "radius_1"), f(s, "radius"));
        assert_eq!(f(r, "temperature"), f(s, "temperature"));
        match (r["v_stick"].as_f64(), s["v_stick"].as_f64()) {
            (None, None) => {
                assert_eq!(r["status"], "always_sticks");
                outcomes[0] += 1;
            }
            // The bisection of `rime stick` stops within 1e-10 in ln g.
            (Some(a), Some(b)) => {
                assert!((a / b - 1.0).abs() < 2e-10, "{a} vs {b}");
                assert_eq!(r["status"], "threshold");
                outcomes[1] += 1;
            }
            other => panic!("{other:?} at {i}"),
        }
    }
    assert!(outcomes[0] > 0 && outcomes[1] > 0, "{outcomes:?}");
    for t in 0..2 {
        for i in 0..20 {
            for j in 0..20 {
                assert_eq!(at(t, i, j)["v_stick"], at(t, j, i)["v_stick"]);
                assert_eq!(at(t, i, j)["status"], at(t, j, i)["status"]);
            }
        }
    }
    // γ(T) is measured over 175–200 K: 150 K is held at the cold end and says so.
    assert_eq!(at(0, 3, 4)["gamma_range"], "held_cold");
    assert_eq!(at(1, 3, 4)["gamma_range"], "measured");
    let p = &k["provenance"];
    assert_eq!(p["gamma_source"]["entry"], "musiolik2019");
    assert_eq!(p["gamma_source"]["temperature_rule"], "hold");
    assert_eq!(p["a_rule"], "given");
    assert_eq!(p["rime_version"], env!("CARGO_PKG_VERSION"));
    let not_modelled = p["not_modelled"].to_string();
    for what in ["porous", "fragmentation", "erosion"] {
        assert!(not_modelled.contains(what), "{not_modelled}");
    }
    assert_eq!(p["units"]["v_stick"], "m/s");
}

#[test]
fn issue_39_a_rules_fit_and_keep_epsilon() {
    // fit-measured: the reference pair (two 1.5 µm grains at 200 K) sticks up to 9.6 m/s.
    let k = json(&[
        "kernel",
        "--radii",
        "1.5um,1mm",
        "--temperatures",
        "200",
        "--a-rule",
        "fit-measured",
        "--format",
        "json",
    ]);
    let fit = &k["provenance"]["fit"];
    assert_eq!(fit["entry"], "gundlach2015");
    assert!((f(fit, "achieved_v_stick") / 9.6 - 1.0).abs() < 1e-6);
    assert!((f(&records(&k)[0], "v_stick") / 9.6 - 1.0).abs() < 1e-6);
    // The fitted A applies to every pair: the provenance's A is the fit's.
    assert_eq!(f(&k["provenance"], "damping_time"), f(fit, "damping_time"));
    // keep-epsilon: at the scene's own pair (2 cm) A is the scene's, so v_stick is given's.
    let at = |rule: &str| {
        let v = json(&[
            "kernel",
            "--radii",
            "2cm,1mm",
            "--temperatures",
            "190",
            "--a-rule",
            rule,
            "--format",
            "json",
        ]);
        (f(&records(&v)[0], "v_stick"), f(&records(&v)[3], "v_stick"))
    };
    let (given_ref, given_mm) = at("given");
    let (keep_ref, keep_mm) = at("keep-epsilon");
    assert!((keep_ref / given_ref - 1.0).abs() < 1e-12);
    // At 1 mm keep-epsilon lowers A (A ∝ R^(−1/5) m^(2/5) ∝ R, 20× less): a smaller threshold.
    assert!(keep_mm < given_mm);
}

#[test]
fn issue_39_csv_table_and_figure() {
    let (code, csv, err) = rime(&[
        "kernel",
        "--radii",
        "10um..1mm",
        "--points",
        "3",
        "--temperatures",
        "150,180",
        "--format",
        "csv",
    ]);
    assert_eq!(code, 0, "{err}");
    let lines: Vec<&str> = csv.lines().collect();
    let header = lines.iter().position(|l| !l.starts_with("# ")).unwrap();
    assert!(header >= 3, "provenance lines first: {csv}");
    assert!(csv.contains("musiolik2019") && csv.contains("not modelled"));
    assert_eq!(
        lines[header],
        "radius_1 [m],radius_2 [m],temperature [K],v_stick [m/s],status,gamma_range"
    );
    assert_eq!(lines.len() - header - 1, 2 * 3 * 3);
    let (code, table, err) = rime(&[
        "kernel",
        "--radii",
        "10um..1mm",
        "--points",
        "3",
        "--temperatures",
        "180",
        "--format",
        "table",
    ]);
    assert_eq!(code, 0, "{err}");
    // Each unordered pair once, radii with a prefixed unit, at most 4 significant digits.
    let rows: Vec<&str> = table.lines().filter(|l| l.contains("µm")).collect();
    assert!(rows.len() >= 5, "{table}");
    for row in rows.iter().filter(|r| r.contains("/s")) {
        let v = row.split_whitespace().nth(5).unwrap();
        let digits = v.chars().filter(char::is_ascii_digit).count();
        assert!(digits <= 4 && !v.contains('e'), "{row}");
    }
    let svg = std::env::temp_dir().join(format!("rime-kernel-{}.svg", std::process::id()));
    let (code, _, err) = rime(&[
        "kernel",
        "--radii",
        "1um..1cm",
        "--points",
        "3",
        "--temperatures",
        "150,200",
        "--svg",
        svg.to_str().unwrap(),
        "--format",
        "csv",
    ]);
    assert_eq!(code, 0, "{err}");
    let text = std::fs::read_to_string(&svg).unwrap();
    let _ = std::fs::remove_file(&svg);
    assert!(text.starts_with("<svg") || text.contains("<svg"));
    assert!(text.contains("Gundlach"), "the measured point is drawn");
}

#[test]
fn issue_39_bad_flags_are_named() {
    for (args, flag) in [
        (vec!["--radii", "1cm..1um"], "--radii"),
        (vec!["--radii", "1um..1cm", "--points", "1"], "--points"),
        (vec!["--radii", "1um,2um", "--points", "5"], "--points"),
        (vec!["--radii", "-1um..1cm"], "--radii"),
        (vec!["--radii", "1um..1cm", "--a-rule", "bogus"], "--a-rule"),
        (
            vec!["--radii", "1um..1cm", "--temperatures", "150,nan"],
            "--temperatures",
        ),
        (
            vec![
                "--radii",
                "1um..1cm",
                "--temperatures",
                "150",
                "--temperature-rule",
                "refuse",
            ],
            "--temperatures",
        ),
        (
            vec!["--radii", "1um..1cm", "--temperature-rule", "clamp"],
            "--temperature-rule",
        ),
        (
            vec!["--radii", "1um..1cm", "--fit-radius", "1um"],
            "--fit-radius",
        ),
        (
            vec![
                "--radii",
                "1um..1cm",
                "--a-rule",
                "fit-measured",
                "--fit-radius",
                "1nm",
            ],
            "--a-rule fit-measured",
        ),
        (vec!["--points", "5"], "--radii"),
        (
            vec![
                "--radii",
                "1um..1cm",
                "--points",
                "1000",
                "--temperatures",
                "150,200",
            ],
            "--temperatures",
        ),
    ] {
        let mut all = vec!["kernel"];
        all.extend(args.iter().copied());
        let (code, out, err) = rime(&all);
        assert_ne!(code, 0, "{all:?}: {out}");
        assert!(err.contains(flag), "{all:?}: {err}");
        assert!(out.is_empty(), "{all:?}: {out}");
    }
}
