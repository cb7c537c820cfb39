//! `rime export --lammps DIR` (issue 25): the deck's LAMMPS keywords and numbers against the
//! mappings written out independently here (LAMMPS's own run is scripts/test-all.d/50-lammps.sh).

use crate::bin::rime;
use std::f64::consts::PI;

fn export(tag: &str, extra: &[&str]) -> (i32, String, String, std::path::PathBuf) {
    let dir = std::env::temp_dir().join(format!("rime-lammps-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let d = dir.display().to_string();
    let mut args = vec!["export", "--lammps", d.as_str()];
    args.extend(extra);
    let (code, out, err) = rime(&args);
    (code, out, err, dir)
}

fn coeff_numbers(deck: &str) -> Vec<f64> {
    let line = deck.lines().find(|l| l.starts_with("pair_coeff")).unwrap();
    line.split_whitespace()
        .filter_map(|w| w.parse::<f64>().ok())
        .collect()
}

#[test]
fn issue_25_lammps_deck_maps_every_number() {
    // ice: Y = 1e10 Pa, ν = 0.3, A = 1e-4 s, two 2 cm grains of 900 kg/m³.
    let m = 900.0 * 4.0 / 3.0 * PI * 0.02f64.powi(3);
    let m_eff = m / 2.0;
    let e_star = 1e10 / (2.0 * (1.0 - 0.09));
    let eta = 2.0 * e_star * 1e-4 / m_eff;
    for (tag, end, keyword) in [("fz", "force_zero", true), ("zo", "zero_overlap", false)] {
        let set = format!("contact_end={end}");
        let (code, _, err, dir) = export(tag, &["--set", set.as_str()]);
        assert_eq!(code, 0, "{err}");
        let deck = std::fs::read_to_string(dir.join("in.rime")).unwrap();
        assert!(deck.contains("units si"));
        assert!(deck.contains("pair_style granular"));
        assert!(deck.contains("pair_coeff * * hertz/material"));
        assert_eq!(deck.contains("limit_damping"), keyword, "{end}");
        let n = coeff_numbers(&deck);
        // E, η_n0, ν, then the tangential zeros.
        assert_eq!(n[0], 1e10);
        assert!((n[1] / eta - 1.0).abs() < 1e-12, "{} vs {eta}", n[1]);
        assert_eq!(n[2], 0.3);
        for f in ["reference.tsv", "README.md"] {
            assert!(dir.join(f).exists(), "{f}");
        }
        let _ = std::fs::remove_dir_all(dir);
    }
    // Adhesion: LAMMPS's jkr with γ = w/2, plain damping.
    let (code, _, err, dir) = export(
        "jkr",
        &[
            "--preset",
            "ice-sticky",
            "--set",
            "adhesion.jkr_end=pull_off_force",
            "--lammps-adhesion",
            "jkr",
        ],
    );
    assert_eq!(code, 0, "{err}");
    let deck = std::fs::read_to_string(dir.join("in.rime")).unwrap();
    assert!(deck.contains("pair_coeff * * jkr"));
    assert!(!deck.contains("limit_damping"));
    let n = coeff_numbers(&deck);
    assert_eq!(n[3], 0.05, "γ = w/2");
    let table = std::fs::read_to_string(dir.join("reference.tsv")).unwrap();
    assert!(table.contains("stuck_by_adhesion"), "{table}");
    // The deck says whether the grains stuck: caught once they turn back towards each other while
    // in contact (the Lyapunov argument of docs/physics.md#model-brilliantov2007), not apart.
    assert!(deck.contains("if \"${separating} == 1 && ${vrel} < 0\" then \"jump SELF caught\""));
    assert!(
        deck.contains("variable status string stuck_by_adhesion"),
        "{deck}"
    );
    assert!(deck.contains("if \"${gap} > ${apart}\" then \"jump SELF separated\""));
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn issue_25_lammps_export_refuses_a_soft_layer_naming_it() {
    let (code, out, err, dir) = export("layer", &["--preset", "ice-frost"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("layer"), "{err}");
    assert!(out.is_empty());
    assert!(!dir.join("in.rime").exists());
}

#[test]
fn issue_35_adhesive_scene_exports_only_with_a_named_mapping() {
    // Refused without the flag, naming the field and the flag; nothing written.
    let (code, out, err, dir) = export("adh-refused", &["--preset", "ice-sticky"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("adhesion:") && err.contains("--lammps-adhesion jkr"),
        "{err}"
    );
    assert!(out.is_empty());
    assert!(!dir.join("in.rime").exists());
    // Named: the deck is jkr, reference.tsv and stderr say brilliantov2007; the default neck end
    // is warned about.
    let (code, _, err, dir) = export(
        "adh-neck",
        &["--preset", "ice-sticky", "--lammps-adhesion", "jkr"],
    );
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("brilliantov2007"), "{err}");
    assert!(
        err.contains("neck") && err.contains("pull_off_force"),
        "{err}"
    );
    let table = std::fs::read_to_string(dir.join("reference.tsv")).unwrap();
    assert!(table.contains("model brilliantov2007"), "{table}");
    let _ = std::fs::remove_dir_all(dir);
    // The pull-off end: no warning.
    let (code, _, err, dir) = export(
        "adh-pull",
        &[
            "--preset",
            "ice-sticky",
            "--set",
            "adhesion.jkr_end=pull_off_force",
            "--lammps-adhesion",
            "jkr",
        ],
    );
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("warning"), "{err}");
    let _ = std::fs::remove_dir_all(dir);
    // A mapping for a scene without adhesion, or an unknown one, is an error naming the flag.
    for (tag, args) in [
        ("adh-none", vec!["--lammps-adhesion", "jkr"]),
        (
            "adh-dmt",
            vec!["--preset", "ice-sticky", "--lammps-adhesion", "dmt"],
        ),
    ] {
        let (code, _, err, dir) = export(tag, &args);
        assert_eq!(code, 2, "{err}");
        assert!(err.contains("--lammps-adhesion"), "{err}");
        assert!(!dir.join("in.rime").exists());
    }
    let (code, _, err) = rime(&["export", "--out", "x", "--lammps-adhesion", "jkr"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--lammps-adhesion"), "{err}");
}

#[test]
fn issue_35_strongly_damped_deck_resolves_the_viscous_time() {
    // ice-paper-viscosities (A = 404.44 s): the loading step must resolve the viscous rate η_n0 a
    // at the compression bound, written out here: dt · η_n0 a = t_H/τ / N = 3.218/4000.
    let (code, _, err, dir) = export("ipv", &["--preset", "ice-paper-viscosities"]);
    assert_eq!(code, 0, "{err}");
    let table = std::fs::read_to_string(dir.join("reference.tsv")).unwrap();
    let row: Vec<&str> = table
        .lines()
        .find(|l| l.starts_with("0.001\t"))
        .unwrap()
        .split('\t')
        .collect();
    assert_eq!(row[2], "overdamped", "{table}");
    let dt: f64 = row[5].parse().unwrap();
    // Independent numbers: ice, 2 cm grains of 900 kg/m³, Y = 1e10 Pa, ν = 0.3, A from the scene.
    let deck = std::fs::read_to_string(dir.join("in.rime")).unwrap();
    let eta = coeff_numbers(&deck)[1];
    let m_eff = 900.0 * 4.0 / 3.0 * PI * 0.02f64.powi(3) / 2.0;
    let e_star = 1e10 / (2.0 * (1.0 - 0.09));
    let a = eta * m_eff / (2.0 * e_star);
    let (r, g) = (0.01f64, 1e-3f64);
    let alpha = 4.0 / 3.0 * e_star * r.sqrt() / m_eff;
    let xi_star = (g * g / alpha).powf(0.4);
    let tau = xi_star / g;
    let delta = a * alpha.powf(0.4) * g.powf(0.2);
    let xi_bound = xi_star * delta.powf(-2.0 / 3.0);
    let rate = eta * (r * xi_bound).sqrt();
    let expected = 3.218_065_459_719_043 * tau / (4000.0 * rate * tau);
    assert!((dt / expected - 1.0).abs() < 1e-12, "{dt} vs {expected}");
    // The deck never prints an ε_N outside [0, 1]: its step-limit, unstable and unresolved lines
    // print none.
    assert!(deck.contains("variable status string step_limit"));
    assert!(deck.contains("variable status string unstable\" \"variable eps_out string none\""));
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn issue_35_accuracy_is_honoured_and_plasticity_noted() {
    let (code, _, err, dir) = export("acc", &["--accuracy", "fast", "--set", "plasticity=on"]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("plasticity"), "{err}");
    let table = std::fs::read_to_string(dir.join("reference.tsv")).unwrap();
    assert!(table.contains("accuracy fast"), "{table}");
    let readme = std::fs::read_to_string(dir.join("README.md")).unwrap();
    assert!(readme.contains("Plasticity"), "{readme}");
    let _ = std::fs::remove_dir_all(dir);
}
