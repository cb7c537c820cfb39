//! Exit codes as docs/cli.md states them (issue 25): bad input exits 2, a failed computation 1,
//! success 0 — for every subcommand that computes.

use crate::bin::rime;

/// Each computing subcommand with arguments that make it succeed.
const COMPUTING: [(&str, &[&str]); 12] = [
    ("eps", &["eps", "--g", "1e-3"]),
    (
        "curve",
        &["curve", "--from", "1e-3", "--to", "1e-2", "--points", "3"],
    ),
    (
        "tangential",
        &["tangential", "--gn", "1e-3", "--gt", "1e-3"],
    ),
    ("map", &["map", "--max", "1e-2", "--n", "3"]),
    ("tidal", &["tidal"]),
    (
        "export",
        &["export", "--out", "EXPORT_DIR", "--points", "8"],
    ),
    ("fit", &["fit", "--law", "bridges1984"]),
    ("data", &["data"]),
    ("stick", &["stick", "--radius", "1e-3"]),
    ("collision", &["collision", "--g", "1e-3"]),
    (
        "compare",
        &["compare", "--models", "hertzsch2002", "--g", "1e-3"],
    ),
    ("figures", &["figures", "--out", "FIGURES_DIR"]),
];

fn with_dirs(args: &[&str], tag: &str) -> (Vec<String>, Vec<std::path::PathBuf>) {
    let mut dirs = Vec::new();
    let args = args
        .iter()
        .map(|a| {
            if a.ends_with("_DIR") {
                let d = std::env::temp_dir()
                    .join(format!("rime-exit-{tag}-{a}-{}", std::process::id()));
                dirs.push(d.clone());
                d.display().to_string()
            } else {
                a.to_string()
            }
        })
        .collect();
    (args, dirs)
}

#[test]
fn issue_25_every_computing_subcommand_exits_0_then_2_on_a_bad_scene_field() {
    for (name, args) in COMPUTING {
        if name == "figures" || name == "fit" {
            // Covered below with the bad field only: a full run takes seconds.
            continue;
        }
        let (ok_args, dirs) = with_dirs(args, "ok");
        let ok: Vec<&str> = ok_args.iter().map(String::as_str).collect();
        let (code, _, err) = rime(&ok);
        assert_eq!(code, 0, "{name}: {err}");
        for d in dirs {
            let _ = std::fs::remove_dir_all(d);
        }
    }
    for (name, args) in COMPUTING {
        let (bad_args, dirs) = with_dirs(args, "bad");
        let mut bad: Vec<&str> = bad_args.iter().map(String::as_str).collect();
        // tidal and data read no scene: a bad value of their own flags instead.
        let (extra, field): (&[&str], &str) = match name {
            "tidal" => (&["--distance", "-1"], "distance"),
            "data" => (&["--law", "bridges1984", "--g", "-1"], "--g"),
            _ => (&["--set", "bulk.youngs_modulus=-1"], "bulk.youngs_modulus"),
        };
        bad.extend(extra);
        let (code, out, err) = rime(&bad);
        assert_eq!(code, 2, "{name}: exit {code}, {err}");
        assert!(err.contains(field), "{name}: {err}");
        assert!(out.is_empty(), "{name}: {out}");
        for d in dirs {
            let _ = std::fs::remove_dir_all(d);
        }
    }
}

/// The issue's case used to end with a step-budget error and exit 2; it is now a physical answer.
#[test]
fn issue_25_ice_sticky_a_1e_3_compare_exits_0_stuck_at_every_speed() {
    let (code, out, err) = rime(&[
        "compare",
        "--preset",
        "ice-sticky",
        "--set",
        "bulk.damping.time=1e-3",
        "--models",
        "brilliantov2007",
        "--g",
        "1e-4,1e-3,0.01,0.1,1",
        "--format",
        "json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let records = v["records"].as_array().unwrap();
    assert_eq!(records.len(), 5);
    for r in records {
        assert_eq!(r["status"], "stuck_by_adhesion", "{r}");
        assert_eq!(r["eps_n"], 0.0);
    }
    // g_cr is the status "always sticks" (no speed separates these grains), in every format.
    let speeds = v["characteristic_speeds"].as_array().unwrap();
    assert_eq!(
        speeds,
        &vec![
            serde_json::json!({"model": "brilliantov2007", "name": "g_cr",
                                 "value": null, "status": "always_sticks"})
        ]
    );
    let args = |format| {
        [
            "compare",
            "--preset",
            "ice-sticky",
            "--set",
            "bulk.damping.time=1e-3",
            "--models",
            "brilliantov2007",
            "--g",
            "0.01",
            "--format",
            format,
        ]
    };
    let (code, csv, err) = rime(&args("csv"));
    assert_eq!(code, 0, "{err}");
    assert!(
        csv.ends_with("model,name,value [m/s],status\nbrilliantov2007,g_cr,,always_sticks\n"),
        "{csv}"
    );
    let (code, table, err) = rime(&args("table"));
    assert_eq!(code, 0, "{err}");
    let row = table.lines().find(|l| l.contains("g_cr")).unwrap();
    assert!(row.trim_end().ends_with("always sticks"), "{table}");
}
