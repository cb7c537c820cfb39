//! Issue 38, the command line: `rime ring --radii …` (a ring of many sizes): the keys, the bins
//! against the closed-form power-law integrals, one size against today's `rime ring`, the table at
//! 80 columns, and bad input naming the flag.

use crate::bin::rime;
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let (code, out, err) = rime(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

const RING: [&str; 7] = [
    "ring",
    "--preset",
    "ice",
    "--tau",
    "0.5",
    "--omega",
    "1.3143527e-4",
];

fn with(extra: &[&'static str]) -> Vec<&'static str> {
    RING.iter().copied().chain(extra.iter().copied()).collect()
}

#[test]
fn issue_38_a_power_law_prints_bins_and_viscosity() {
    let v = json(&with(&[
        "--radii", "1cm..5cm", "--q", "3", "--format", "json",
    ]));
    let bins = v["size_bins"].as_array().unwrap();
    assert_eq!(bins.len(), 3);
    // Edges equal in log R from 1 to 5 cm; number fractions ∝ ∫R^−3 dR.
    let (a, b): (f64, f64) = (0.01, 0.05);
    let mut total_fraction = 0.0;
    for (k, bin) in bins.iter().enumerate() {
        let lo = a * (b / a).powf(k as f64 / 3.0);
        let hi = a * (b / a).powf((k + 1) as f64 / 3.0);
        let get = |key: &str| bin[key].as_f64().unwrap();
        assert!((get("radius_min") / lo - 1.0).abs() < 1e-12);
        assert!((get("radius_max") / hi - 1.0).abs() < 1e-12);
        let frac = (lo.powi(-2) - hi.powi(-2)) / (a.powi(-2) - b.powi(-2));
        assert!((get("number_fraction") / frac - 1.0).abs() < 1e-12);
        total_fraction += get("number_fraction");
        assert!(get("velocity_dispersion") > 0.0 && get("thickness") > 0.0);
    }
    assert!((total_fraction - 1.0).abs() < 1e-12);
    // The ring-wide dispersion is the number-weighted rms of the bins'.
    let c2: f64 = bins
        .iter()
        .map(|b| {
            b["number_fraction"].as_f64().unwrap()
                * b["velocity_dispersion"].as_f64().unwrap().powi(2)
        })
        .sum();
    let c = v["velocity_dispersion"].as_f64().unwrap();
    assert!((c / c2.sqrt() - 1.0).abs() < 1e-12);
    let nu = &v["viscosity"];
    let (t, col, tot) = (
        nu["translational"].as_f64().unwrap(),
        nu["collisional"].as_f64().unwrap(),
        nu["total"].as_f64().unwrap(),
    );
    assert!(t > 0.0 && col > 0.0);
    assert_eq!(tot, t + col);
    assert!(nu["dlnnu_dlntau"].as_f64().unwrap().is_finite());
    assert_eq!(nu["overstability"], "not_assessed");
    assert_eq!(v["verdict"], "equilibrium");
    assert_eq!(v["equilibrium"], true);
    assert_eq!(v["damping_rule"], "same");
    // --bins N.
    let five = json(&with(&[
        "--radii", "1cm..5cm", "--q", "3", "--bins", "5", "--format", "json",
    ]));
    assert_eq!(five["size_bins"].as_array().unwrap().len(), 5);
}

#[test]
fn issue_38_a_list_with_fractions_and_the_a_rule() {
    let v = json(&with(&[
        "--radii",
        "1cm,2cm,5cm",
        "--fractions",
        "0.6,0.3,0.1",
        "--format",
        "json",
    ]));
    let bins = v["size_bins"].as_array().unwrap();
    let radii: Vec<f64> = bins.iter().map(|b| b["radius"].as_f64().unwrap()).collect();
    assert_eq!(radii, vec![0.01, 0.02, 0.05]);
    // τ_i ∝ f_i R_i² and sums to τ.
    let w = [0.6 * 1.0, 0.3 * 4.0, 0.1 * 25.0];
    let sum: f64 = w.iter().sum();
    for (b, wi) in bins.iter().zip(w) {
        let tau = b["tau"].as_f64().unwrap();
        assert!((tau - 0.5 * wi / sum).abs() < 1e-12, "{tau}");
    }
    let keep = json(&with(&[
        "--radii",
        "1cm,2cm,5cm",
        "--fractions",
        "0.6,0.3,0.1",
        "--damping-rule",
        "keep_epsilon",
        "--format",
        "json",
    ]));
    assert_eq!(keep["damping_rule"], "keep_epsilon");
    // The 2 cm pair is the scene's own: its A is the same either way, but the others' differ, so
    // the balance moves.
    assert_ne!(
        keep["size_bins"][0]["velocity_dispersion"],
        v["size_bins"][0]["velocity_dispersion"]
    );
}

/// One size through `--radii` is today's `rime ring` (c, H, verdict); one-size output has no bins
/// and gains the same `viscosity` (the issue: ν for one size and for a distribution), every digit.
#[test]
fn issue_38_one_size_is_todays_ring() {
    let today = json(&with(&["--format", "json"]));
    assert!(today.get("size_bins").is_none());
    let one = json(&with(&["--radii", "2cm", "--format", "json"]));
    let bin = &one["size_bins"][0];
    assert_eq!(bin["velocity_dispersion"], today["velocity_dispersion"]);
    assert_eq!(bin["thickness"], today["thickness"]);
    assert_eq!(one["verdict"], today["verdict"]);
    assert_eq!(one["verdict_words"], today["verdict_words"]);
    assert_eq!(one["viscosity"], today["viscosity"]);
    let nu = &today["viscosity"];
    let (t, c) = (
        nu["translational"].as_f64().unwrap(),
        nu["collisional"].as_f64().unwrap(),
    );
    assert!(t > 0.0 && c > 0.0);
    assert_eq!(nu["total"].as_f64().unwrap(), t + c);
    assert_eq!(nu["overstability"], "not_assessed");
}

#[test]
fn issue_38_the_table_fits_80_columns() {
    let (code, out, err) = rime(&with(&[
        "--radii", "1cm..5cm", "--q", "3", "--format", "table",
    ]));
    assert_eq!(code, 0, "{err}");
    for line in out.lines() {
        assert!(
            line.chars().count() <= 80,
            "{} columns: {line}",
            line.chars().count()
        );
    }
    assert!(out.contains("µm/s") && out.contains("mm²/s"), "{out}");
    assert!(out.contains("overstability: not assessed"), "{out}");
}

#[test]
fn issue_38_bad_sizes_name_the_flag() {
    let cases: [(&[&str], &str); 9] = [
        (&["--radii", "1cm..5cm"], "--q:"),
        (&["--radii", "1cm,2cm"], "--fractions:"),
        (
            &["--radii", "1cm,2cm", "--fractions", "0.5,0.6"],
            "--fractions:",
        ),
        (&["--radii", "5cm..1cm", "--q", "3"], "--radii"),
        (
            &["--radii", "1cm..5cm", "--q", "3", "--bins", "0"],
            "--bins:",
        ),
        (
            &["--radii", "1cm..5cm", "--q", "3", "--damping-rule", "x"],
            "--damping-rule:",
        ),
        (&["--q", "3"], "--q: only with --radii"),
        (&["--radii", "2cm", "--radius", "1cm"], "--radii:"),
        (&["--radii", "1cm,abc", "--fractions", "0.5,0.5"], "--radii"),
    ];
    for (extra, want) in cases {
        let args = with(extra);
        let (code, out, err) = rime(&args);
        assert_ne!(code, 0, "{extra:?}: {out}");
        assert!(err.contains(want), "{extra:?}: {err}");
        assert!(out.is_empty());
    }
}
