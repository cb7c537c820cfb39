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
    assert!(deck.contains("variable caught equal 1"), "{deck}");
    assert!(deck.contains("if \"${separating} == 1 && ${vrel} < 0\" then \"jump SELF done\""));
    assert!(deck.contains("then \"variable caught equal 0\" \"jump SELF done\""));
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
