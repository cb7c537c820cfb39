//! Batch ε_N (`rime_core::batch`) against `Contact::normal` at Precise, and `rime eps --g-file`.

use crate::bin::rime_binary;
use rime_core::batch::BatchLaw;
use rime_core::{Accuracy, Adhesion, Contact, ContactEnd, Damping, Preset, Scene};
use std::process::Command;

/// Every preset, plus damping times that move the speeds across the whole table and a scene with
/// both a layer and adhesion, each with both contact-end rules.
fn scenes() -> Vec<(String, Scene)> {
    let mut base: Vec<(String, Scene)> = Preset::ALL
        .iter()
        .map(|p| (p.name().to_string(), p.scene()))
        .collect();
    for a in [1e-9, 1e-7, 1e-2, 1.0] {
        let mut s = Preset::Ice.scene();
        s.bulk.damping = Damping::Time(a);
        base.push((format!("ice, A = {a:e} s"), s));
    }
    let mut both = Preset::IceFrost.scene();
    both.adhesion = Some(Adhesion::default());
    base.push(("ice-frost + adhesion".into(), both));
    let mut out = Vec::new();
    for (name, s) in base {
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            out.push((
                format!("{name}, {end:?}"),
                Scene {
                    contact_end: end,
                    ..s
                },
            ));
        }
    }
    out
}

/// Log-spaced speeds over [1e-12, 1e3] m/s with an irrational step, both ends included.
fn speeds() -> Vec<f64> {
    let mut g: Vec<f64> = (0..)
        .map(|k| 1e-12 * 10f64.powf(k as f64 * 0.0007 * std::f64::consts::SQRT_2))
        .take_while(|&g| g < 1e3)
        .collect();
    g.push(1e3);
    g
}

#[test]
fn batch_meets_the_fast_bound_against_precise_at_every_speed() {
    let g = speeds();
    let mut out = vec![0.0; g.len()];
    let mut worst = (0.0f64, String::new());
    for (name, scene) in scenes() {
        let contact = Contact::new(&scene).unwrap();
        let law = BatchLaw::new(&contact, Accuracy::Fast);
        assert!(law.uses_table(), "{name}");
        law.fill(&g, &mut out).unwrap();
        for (&gi, &e) in g.iter().zip(&out) {
            let want = contact.normal(gi, Accuracy::Precise).unwrap().eps;
            // Stuck (layer or adhesion) is exactly 0, as in `normal`.
            assert_eq!(e == 0.0, want == 0.0, "{name}: g = {gi:e}: {e} vs {want}");
            if want > 1e-6 {
                let err = ((e - want) / want).abs();
                assert!(
                    err <= 1e-6,
                    "{name}: g = {gi:e}: {e} vs {want} (rel {err:.2e})"
                );
                if err > worst.0 {
                    worst = (err, format!("{name}, g = {gi:e}"));
                }
            } else {
                assert!(
                    (e - want).abs() <= 1e-12,
                    "{name}: g = {gi:e}: {e} vs {want} (abs {:.2e})",
                    (e - want).abs()
                );
            }
        }
    }
    println!(
        "batch ε_N, worst relative error against normal(Precise): {:.2e} ({})",
        worst.0, worst.1
    );
}

#[test]
fn batch_takes_signed_speeds_nan_zero_and_refuses_the_rest() {
    for preset in Preset::ALL {
        let contact = Contact::new(&preset.scene()).unwrap();
        let g = [1e-3, -1e-3, f64::NAN, 0.0, -0.0, 0.2, -7e-5];
        let mut out = [0.0; 7];
        contact.eps_n_batch(&g, &mut out, Accuracy::Fast).unwrap();
        assert_eq!(out[0], out[1]);
        assert!(out[2].is_nan());
        let rest = contact.eps_n(0.0, Accuracy::Precise).unwrap();
        assert_eq!(out[3], rest);
        assert_eq!(out[4], rest);
        let mut pos = [0.0; 2];
        contact
            .eps_n_batch(&[0.2, 7e-5], &mut pos, Accuracy::Fast)
            .unwrap();
        assert_eq!([out[5], out[6]], pos);
        // Levels without batch cells are the scalar path value by value.
        for acc in [Accuracy::Balanced, Accuracy::Precise] {
            let mut o = [0.0; 2];
            contact.eps_n_batch(&[0.01, -0.01], &mut o, acc).unwrap();
            let want = contact.eps_n(0.01, acc).unwrap();
            assert_eq!(o, [want, want]);
        }
        for bad in [2e6, f64::INFINITY, -f64::INFINITY] {
            let mut o = [0.0; 3];
            assert!(
                contact
                    .eps_n_batch(&[0.1, bad, 0.1], &mut o, Accuracy::Fast)
                    .is_err()
            );
        }
        let mut short = [0.0; 1];
        assert!(
            contact
                .eps_n_batch(&[0.1, 0.2], &mut short, Accuracy::Fast)
                .is_err()
        );
    }
}

fn rime(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(rime_binary()).args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).to_string(),
        String::from_utf8_lossy(&out.stderr).to_string(),
    )
}

fn temp_file(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("rime-batch-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn g_file_equals_eps_with_the_same_speeds() {
    // More than one chunk of 4096, with comments, blank lines and CRLF.
    let g: Vec<f64> = (0..5000)
        .map(|k| 1e-7 * 10f64.powf(k as f64 * 7.0 / 5000.0))
        .collect();
    let mut text = String::from("# speeds in m/s\n\n");
    for (k, v) in g.iter().enumerate() {
        text.push_str(&format!(
            "{v:e}{}",
            if k % 3 == 0 { " # c\r\n" } else { "\n" }
        ));
    }
    let file = temp_file("speeds.txt", &text);
    let list: String = g
        .iter()
        .map(|v| format!("{v:e}"))
        .collect::<Vec<_>>()
        .join(",");
    for preset in ["ice", "ice-frost", "ice-sticky", "ice-paper-viscosities"] {
        for (level, tolerance) in [("balanced", 0.0), ("fast", 1e-6)] {
            let common = ["--preset", preset, "--accuracy", level, "--format", "json"];
            let (code, out, err) = rime(
                &[
                    &["eps", "--g-file", file.to_str().unwrap()][..],
                    &common[..],
                ]
                .concat(),
            );
            assert_eq!(code, 0, "{err}");
            let streamed: serde_json::Value = serde_json::from_str(&out).unwrap();
            let (code, out, err) = rime(&[&["eps", "--g", &list][..], &common[..]].concat());
            assert_eq!(code, 0, "{err}");
            let listed: serde_json::Value = serde_json::from_str(&out).unwrap();
            let (a, b) = (streamed.as_array().unwrap(), listed.as_array().unwrap());
            assert_eq!(a.len(), g.len());
            assert_eq!(a.len(), b.len());
            for (x, y) in a.iter().zip(b) {
                assert_eq!(x["g_n"], y["g_n"]);
                assert_eq!(x["status"], y["status"], "{preset} {level}: {x} vs {y}");
                let (e, want) = (x["eps_n"].as_f64().unwrap(), y["eps_n"].as_f64().unwrap());
                let err = if want == 0.0 {
                    e.abs()
                } else {
                    ((e - want) / want).abs()
                };
                assert!(err <= tolerance, "{preset} {level}: {x} vs {y}");
            }
        }
    }
    // CSV and table carry the same numbers.
    let (code, csv, _) = rime(&["eps", "--g-file", file.to_str().unwrap(), "--format", "csv"]);
    assert_eq!(code, 0);
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("g_n [m/s],eps_n,status"));
    let (code, table, _) = rime(&[
        "eps",
        "--g-file",
        file.to_str().unwrap(),
        "--format",
        "table",
    ]);
    assert_eq!(code, 0);
    let mut rows = table.lines();
    assert_eq!(
        rows.next().unwrap().split_whitespace().collect::<Vec<_>>(),
        ["g_n", "[m/s]", "eps_n", "status"]
    );
    let c = Contact::new(&Scene::default()).unwrap();
    for ((line, row), &gi) in lines.zip(rows).zip(&g) {
        let cells: Vec<&str> = line.split(',').collect();
        assert_eq!(cells, row.split_whitespace().collect::<Vec<_>>());
        assert_eq!(cells[0].parse::<f64>().unwrap(), gi);
        // Without --accuracy: the default level (precise since issue 12). The batch path's scalar
        // fallback evaluates the fine table at u = log10 δ formed with ln instead of log10 (the
        // cheaper form of `Contact::eps_n`), so it may differ from `normal` in the last bits.
        let want = c.normal(gi, Accuracy::default()).unwrap().eps;
        let got = cells[1].parse::<f64>().unwrap();
        assert!(
            (got - want).abs() <= 1e-14 * want.abs(),
            "{gi}: {got} vs {want}"
        );
    }
}

#[test]
fn g_file_refuses_devices_directories_long_and_bad_lines() {
    let (code, out, err) = rime(&["eps", "--g-file", "/dev/zero"]);
    assert_eq!(code, 2);
    assert!(out.is_empty());
    assert!(
        err.contains("--g-file /dev/zero") && err.contains("not a regular file"),
        "{err}"
    );
    let dir = std::env::temp_dir();
    let (code, _, err) = rime(&["eps", "--g-file", dir.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("not a regular file"), "{err}");
    let bad = temp_file("bad.txt", "# ok\n0.1\n\n0.2\nfast\n0.3\n");
    let (code, _, err) = rime(&["eps", "--g-file", bad.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("--g-file") && err.contains("line 5"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    let negative = temp_file("negative.txt", "0.1\n-0.2\n");
    let (code, _, err) = rime(&["eps", "--g-file", negative.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("line 2"), "{err}");
    let long = temp_file("long.txt", &format!("0.1\n0.2\n{}\n", "1".repeat(10_000)));
    let (code, _, err) = rime(&["eps", "--g-file", long.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("line 3") && err.contains("256 bytes"), "{err}");
    let empty = temp_file("empty.txt", "# nothing\n\n");
    let (code, _, err) = rime(&["eps", "--g-file", empty.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("--g-file"), "{err}");
    let (code, _, err) = rime(&["eps", "--g-file", "/nonexistent/speeds.txt"]);
    assert_eq!(code, 2);
    assert!(err.contains("--g-file /nonexistent/speeds.txt"), "{err}");
}
