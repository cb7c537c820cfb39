//! What users take away (issue 6): exported laws compile and reproduce the table, fits recover
//! known parameters, figures and the bench report are written.

use crate::bin::rime_binary;
use rime_tests::rel;
use std::path::{Path, PathBuf};
use std::process::Command;

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("rime-takeaway-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn rime(args: &[&str]) -> String {
    let out = Command::new(rime_binary()).args(args).output().unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).to_string()
}

/// (g, ε) rows of the exported CSV table.
fn table(dir: &Path) -> Vec<(f64, f64)> {
    std::fs::read_to_string(dir.join("eps_table.csv"))
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| {
            let mut c = l.split(',');
            (
                c.next().unwrap().parse().unwrap(),
                c.next().unwrap().parse().unwrap(),
            )
        })
        .collect()
}

#[test]
fn exported_rust_and_c_functions_compile_and_reproduce_the_table() {
    let dir = scratch("export");
    let d = dir.to_str().unwrap();
    rime(&[
        "export",
        "--preset",
        "ice-frost",
        "--points",
        "50",
        "--out",
        d,
    ]);
    let rows = table(&dir);
    assert_eq!(rows.len(), 50);
    // The exported functions evaluate the master curve (issue 14; the bound at every speed is
    // tests/tests/exported.rs): at the table's nodes both are within 1e-6 of the truth.
    let probes: Vec<f64> = vec![rows[10].0, rows[30].0, rows[21].0];
    let expected = [rows[10].1, rows[30].1, rows[21].1];
    let args: Vec<String> = probes.iter().map(|g| format!("{g:?}")).collect();

    // Rust: the generated file plus a main that prints the function at the probes.
    let rs = dir.join("probe.rs");
    let src = std::fs::read_to_string(dir.join("rime_eps.rs")).unwrap();
    std::fs::write(
        &rs,
        format!(
            "{src}\nfn main() {{ for a in std::env::args().skip(1) {{ let g: f64 = a.parse().unwrap(); println!(\"{{:?}} {{:?}} {{:?}}\", rime_eps_n(g), rime_eps_n_eq27(g), rime_eps_n_power(g)); }} }}\n"
        ),
    )
    .unwrap();
    let exe = dir.join("probe-rs");
    let status = Command::new("rustc")
        .args(["-O", "--edition", "2021", "-o"])
        .arg(&exe)
        .arg(&rs)
        .status()
        .unwrap();
    assert!(status.success(), "generated Rust does not compile");
    let out = Command::new(&exe).args(&args).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    for (line, want) in text.lines().zip(expected) {
        let got: f64 = line.split(' ').next().unwrap().parse().unwrap();
        assert!(rel(got, want) < 2e-6, "Rust: {got} vs {want}");
    }

    // C, when a compiler is there (gcc is on the machine image; say so if not).
    let c_main = dir.join("probe.c");
    let c_src = std::fs::read_to_string(dir.join("rime_eps.c")).unwrap();
    std::fs::write(
        &c_main,
        format!("{c_src}\n#include <stdio.h>\n#include <stdlib.h>\nint main(int n, char **v) {{ for (int i = 1; i < n; i++) printf(\"%.17g\\n\", rime_eps_n(strtod(v[i], 0))); return 0; }}\n"),
    )
    .unwrap();
    let c_exe = dir.join("probe-c");
    let cc = Command::new("cc")
        .arg("-O2")
        .arg("-o")
        .arg(&c_exe)
        .arg(&c_main)
        .arg("-lm")
        .status()
        .expect("a C compiler (cc) is needed for this test");
    assert!(cc.success(), "generated C does not compile");
    let out = Command::new(&c_exe).args(&args).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    for (line, want) in text.lines().zip(expected) {
        let got: f64 = line.trim().parse().unwrap();
        assert!(rel(got, want) < 2e-6, "C: {got} vs {want}");
    }
    let fits: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("fits.json")).unwrap()).unwrap();
    assert!(fits["eq27"]["rms_error"].as_f64().unwrap() < 0.1);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn fit_recovers_the_damping_time_that_made_the_data() {
    let dir = scratch("fit");
    // Data from a scene with A = 3e-4 s; the fit starts from the default (1e-4 s).
    let csv = rime(&[
        "curve",
        "--from",
        "1e-4",
        "--to",
        "1",
        "--points",
        "12",
        "--format",
        "csv",
        "--set",
        "bulk.damping.time=3e-4",
        "--accuracy",
        "precise",
    ]);
    let points: String = csv
        .lines()
        .map(|l| l.split(',').take(2).collect::<Vec<_>>().join(","))
        .collect::<Vec<_>>()
        .join("\n");
    let data = dir.join("points.csv");
    std::fs::write(&data, points).unwrap();
    let out = rime(&[
        "fit",
        "--data",
        data.to_str().unwrap(),
        "--param",
        "bulk.damping.time",
        "--accuracy",
        "precise",
        "--format",
        "json",
    ]);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let a = v["value"].as_f64().unwrap();
    assert!(rel(a, 3e-4) < 1e-6, "fitted A = {a}");
    assert!(v["rms_error"].as_f64().unwrap() < 1e-9);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn figures_and_bench_report_are_written() {
    let dir = scratch("figures");
    let d = dir.to_str().unwrap();
    rime(&["figures", "--out", d]);
    for name in [
        "fig2-layer",
        "fig2-layer-paper-viscosities",
        "fig3-adhesion",
        "fig4-hard",
        "fig4-layer-zoom",
        "fig4-adhesion-zoom",
    ] {
        let png = std::fs::read(dir.join(format!("{name}.png"))).unwrap();
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n", "{name}");
        let svg = std::fs::read_to_string(dir.join(format!("{name}.svg"))).unwrap();
        assert!(svg.contains("<svg") && svg.contains("</svg>"), "{name}");
    }
    let bench = scratch("bench");
    rime(&["bench", "--quick", "true", "--out", bench.to_str().unwrap()]);
    let v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(bench.join("bench.json")).unwrap()).unwrap();
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 12);
    for r in rows {
        // Every level meets its documented bound in the bench's own measurement.
        let bound = match r["level"].as_str().unwrap() {
            "precise" => 1e-10,
            _ => 1e-6,
        };
        assert!(r["max_rel_error"].as_f64().unwrap() <= bound, "{r}");
    }
    assert!(
        std::fs::read_to_string(bench.join("work-precision.svg"))
            .unwrap()
            .contains("</svg>")
    );
    std::fs::remove_dir_all(&dir).unwrap();
    std::fs::remove_dir_all(&bench).unwrap();
}
