//! Hostile input to the real `rime` binary (issue 7): exit code 2, one stderr line naming the
//! field, empty stdout, never a panic, never slow.

use crate::bin::rime_binary;
use std::path::PathBuf;
use std::process::Command;
use std::time::{Duration, Instant};

struct Dir(PathBuf);

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn dir(name: &str) -> Dir {
    let d = std::env::temp_dir().join(format!("rime-bad-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    Dir(d)
}

const VALID: &str = r#"{"grains":{"radius_1":0.02,"radius_2":0.02,"density":900.0},"bulk":{"youngs_modulus":1e10,"poisson_ratio":0.3,"damping":{"time":1e-4}}}"#;

/// Runs `rime args…` and checks the bad-input contract; `field` must appear in the message.
fn rejects(args: &[&str], field: &str) {
    // Resolve (and, once per run, rebuild) the binary before starting the hang guard's clock.
    let binary = rime_binary();
    let t = Instant::now();
    let out = Command::new(binary).args(args).output().unwrap();
    let dt = t.elapsed();
    let err = String::from_utf8_lossy(&out.stderr);
    let shown: Vec<String> = args.iter().map(|a| a.chars().take(80).collect()).collect();
    assert_eq!(out.status.code(), Some(2), "{shown:?}: {err}");
    assert!(out.stdout.is_empty(), "{shown:?}: stdout not empty");
    assert_eq!(err.trim_end().lines().count(), 1, "{shown:?}: {err}");
    assert!(
        err.contains(field),
        "{shown:?}: {err} (should name {field})"
    );
    assert!(!err.contains("panicked"), "{shown:?}: {err}");
    if std::env::var_os("RIME_TIMINGS").is_some() {
        eprintln!("TIMING bad_input {shown:?}: {dt:?}");
    }
    // A hang guard, not a speed check: the slowest refusal took 40 ms (the process's start included)
    // with the machine's 2 cores loaded 3.5 times over, so 30 s is over 500× that.
    assert!(
        dt < Duration::from_secs(30),
        "{shown:?}: took {dt:?} (a hang?)"
    );
}

fn scene_file(d: &Dir, name: &str, text: &[u8]) -> String {
    let p = d.0.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_string()
}

#[test]
fn hostile_scene_files_are_rejected_naming_the_field() {
    let d = dir("scenes");
    let with = |from: &str, to: &str| VALID.replacen(from, to, 1);
    // Adds top-level members before the final brace.
    let add = |extra: &str| format!("{},{extra}}}", &VALID[..VALID.len() - 1]);
    let cases: Vec<(String, &str)> = vec![
        (
            with("\"density\":900.0", "\"density\":1e308"),
            "grains.density",
        ),
        (
            with("\"density\":900.0", "\"density\":-1e308"),
            "grains.density",
        ),
        (
            with("\"density\":900.0", "\"density\":1e999"),
            "grains.density",
        ),
        (
            with("\"radius_1\":0.02", "\"radius_1\":\"NaN\""),
            "grains.radius_1",
        ),
        (
            with("\"radius_1\":0.02", "\"radius_1\":NaN"),
            "grains.radius_1",
        ),
        (
            with("\"radius_1\":0.02", "\"radius_1\":Infinity"),
            "grains.radius_1",
        ),
        (
            with("\"radius_1\":0.02", "\"radius_1\":[0.02]"),
            "grains.radius_1",
        ),
        (
            with("\"radius_1\":0.02", "\"radius_1\":null"),
            "grains.radius_1",
        ),
        (
            with("\"youngs_modulus\":1e10", "\"youngs_modulus\":1e16"),
            "bulk.youngs_modulus",
        ),
        (
            with("\"poisson_ratio\":0.3", "\"poisson_ratio\":0.6"),
            "bulk.poisson_ratio",
        ),
        (
            with("\"poisson_ratio\":0.3", "\"poisson_ratio\":-1"),
            "bulk.poisson_ratio",
        ),
        (
            with("{\"time\":1e-4}", "{\"time\":-1e-4}"),
            "bulk.damping.time",
        ),
        (
            with("{\"time\":1e-4}", "{\"time\":1e-4,\"extra\":1}"),
            "bulk.damping",
        ),
        (
            with(
                "{\"time\":1e-4}",
                "{\"viscosities\":{\"shear\":1e6,\"bulk\":1e12,\"formula\":\"sideways\"}}",
            ),
            "formula",
        ),
        (
            with(
                "{\"time\":1e-4}",
                "{\"viscosities\":{\"shear\":1e6,\"bulk\":1e12}}",
            )
            .replacen("0.3", "0", 1),
            "bulk.poisson_ratio",
        ),
        (
            with("\"grains\":{", "\"colour\":\"blue\",\"grains\":{"),
            "colour",
        ),
        (
            with("\"density\":900.0", "\"density\":900.0,\"denisty\":1"),
            "denisty",
        ),
        (
            add("\"layer\":{\"thickness\":\"1 um\",\"viscosity\":1000}"),
            "layer.thickness",
        ),
        (
            add("\"layer\":{\"thickness\":2,\"viscosity\":1000}"),
            "layer.thickness",
        ),
        (
            add("\"adhesion\":{\"surface_energy\":-0.1}"),
            "adhesion.surface_energy",
        ),
        (
            add("\"friction\":{\"coefficient\":0.3,\"kappa\":0}"),
            "friction.kappa",
        ),
        (add("\"contact_end\":\"never\""), "contact_end"),
        (VALID.replace("\"bulk\"", "\"blk\""), "blk"),
        (VALID[..VALID.len() - 5].to_string(), "scene"),
        (String::new(), "scene"),
        ("[".repeat(100_000), "scene"),
        ("{\"grains\":".repeat(10_000), "grains"),
    ];
    for (i, (text, field)) in cases.iter().enumerate() {
        let f = scene_file(&d, &format!("s{i}.json"), text.as_bytes());
        rejects(&["eps", "--g", "0.01", "--scene", &f], field);
    }
    // Not UTF-8, a 10 MB file, a directory, a missing file: named by --scene.
    let f = scene_file(&d, "binary.json", &[0xff, 0xfe, 0x00, 0x7b]);
    rejects(&["eps", "--g", "0.01", "--scene", &f], "--scene");
    let mut huge = VALID.as_bytes().to_vec();
    huge.resize(10 << 20, b' ');
    let f = scene_file(&d, "huge.json", &huge);
    rejects(&["eps", "--g", "0.01", "--scene", &f], "--scene");
    rejects(&["scene", "--scene", d.0.to_str().unwrap()], "--scene");
    rejects(&["scene", "--scene", "/nonexistent/x.json"], "--scene");
    rejects(&["scene", "--scene", "/dev/null"], "scene");
}

#[test]
fn hostile_set_overrides_and_flags_are_rejected_naming_them() {
    let cases: &[(&[&str], &str)] = &[
        (&["--set", "layer.viscosty=1"], "layer.viscosty"),
        (&["--set", "=1"], "--set"),
        (&["--set", "layer.viscosity"], "layer.viscosity"),
        (&["--set", "layer.viscosity=NaN"], "layer.viscosity"),
        (&["--set", "layer.viscosity=inf"], "layer.viscosity"),
        (&["--set", "layer.viscosity=1e999"], "layer.viscosity"),
        (&["--set", "layer.viscosity=1e308"], "layer.viscosity"),
        (&["--set", "layer.thickness=1 Pa"], "layer.thickness"),
        (&["--set", "grains.radius_1=2 J"], "grains.radius_1"),
        (&["--set", "grains.density=\"900\"x"], "grains.density"),
        (
            &["--set", "bulk.poisson_ratio=0.5000001"],
            "bulk.poisson_ratio",
        ),
        (&["--set", "contact_end=1"], "contact_end"),
        (&["--set", "layer=maybe"], "layer"),
        (
            &["--set", "friction.sliding_law=Walton"],
            "friction.sliding_law",
        ),
        (&["--set", "grains"], "grains"),
        (&["--set", "grains.radius_1.x=1"], "grains.radius_1.x"),
        (&["--accuracy", "1e-20"], "accuracy"),
        (&["--accuracy", "NaN"], "accuracy"),
        (&["--preset", "ice-fog"], "--preset"),
        (&["--format", "xml"], "--format"),
    ];
    for (extra, field) in cases {
        let mut args = vec!["eps", "--g", "0.01"];
        args.extend_from_slice(extra);
        rejects(&args, field);
    }
    for (args, field) in [
        (vec!["eps", "--g", "NaN"], "--g"),
        (vec!["eps", "--g", "1e309"], "--g"),
        (vec!["eps", "--g", "0"], "--g"),
        (vec!["eps", "--g", "0.01,,0.1"], "--g"),
        (vec!["eps", "--g", "1e7"], "--g"),
        (
            vec!["curve", "--from", "1e-6", "--to", "1", "--points", "1e9"],
            "--points",
        ),
        (vec!["map", "--max", "0.01", "--n", "100000"], "--n"),
        (vec!["tangential", "--gn", "-0.01", "--gt", "0.01"], "--gn"),
        (vec!["tidal", "--distance", "NaN"], "--distance"),
        (vec!["eps", "--g"], "--g"),
    ] {
        rejects(&args, field);
    }
}

#[test]
fn unwritable_output_is_a_reported_error_and_leaves_no_file() {
    rejects(
        &["scene", "--out", "/proc/nope/x.json"],
        "/proc/nope/x.json",
    );
    let d = dir("out");
    // A directory as the output path: the rename fails, the directory and nothing else remains.
    let target = d.0.join("sub");
    std::fs::create_dir_all(&target).unwrap();
    rejects(&["scene", "--out", target.to_str().unwrap()], "sub");
    let left: Vec<_> = std::fs::read_dir(&d.0).unwrap().collect();
    assert_eq!(left.len(), 1, "temporary files left behind: {left:?}");
    // A good path still works and writes complete JSON.
    let good = d.0.join("ok.json");
    let out = Command::new(rime_binary())
        .args(["scene", "--out", good.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let back: rime_core::Scene =
        serde_json::from_str(&std::fs::read_to_string(&good).unwrap()).unwrap();
    assert_eq!(back, rime_core::Scene::default());
}

#[test]
fn extreme_valid_values_through_the_cli_never_print_nan() {
    for args in [
        vec![
            "eps",
            "--g",
            "1e-12,1e-6,1,100,1e6",
            "--preset",
            "ice-paper-viscosities",
        ],
        vec!["eps", "--g", "1e-12,1e6", "--set", "bulk.damping.time=1e6"],
        vec![
            "eps",
            "--g",
            "1e-12,1e6",
            "--set",
            "grains.radius_1=1e-9",
            "--set",
            "grains.radius_2=1e4",
        ],
        vec![
            "eps",
            "--g",
            "1e-12,1e6",
            "--set",
            "adhesion.surface_energy=1e6",
        ],
        vec![
            "eps",
            "--g",
            "1e-12,1e6",
            "--set",
            "layer.viscosity=1e15",
            "--set",
            "layer.thickness=1",
        ],
        vec![
            "curve",
            "--from",
            "1e-12",
            "--to",
            "1e6",
            "--points",
            "50",
            "--preset",
            "ice-frost",
        ],
        vec!["map", "--max", "1e6", "--n", "5", "--preset", "ice-sticky"],
    ] {
        let out = Command::new(rime_binary())
            .args(&args)
            .args(["--format", "json"])
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "{args:?}: {err}");
        assert!(
            !text.contains("NaN") && !text.contains("nan"),
            "{args:?}: {text}"
        );
        serde_json::from_str::<serde_json::Value>(&text).unwrap();
    }
}

/// Runs `rime` and gives up after 20 s (a read that never ends must fail the test, not hang it).
/// A hang guard: each of these runs is refused before reading, in about as long as the process takes
/// to start (tens of ms, like every refusal here), so 20 s is over 100× that.
fn rime_within_20_s(args: &[&str]) -> (Option<i32>, String) {
    let mut child = std::process::Command::new(crate::bin::rime_binary())
        .args(args)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    while start.elapsed() < std::time::Duration::from_secs(20) {
        if child.try_wait().unwrap().is_some() {
            let out = child.wait_with_output().unwrap();
            return (
                out.status.code(),
                String::from_utf8_lossy(&out.stderr).to_string(),
            );
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    (None, String::from("timed out"))
}

#[test]
fn devices_and_fifos_are_refused_before_reading_issue_10() {
    // `/dev/zero` used to be read without end, growing memory; a FIFO with no writer blocks.
    let d = std::env::temp_dir().join(format!("rime-fifo-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    let fifo = d.join("scene.json");
    let _ = std::fs::remove_file(&fifo);
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap();
    assert!(made.success());
    for path in ["/dev/zero", fifo.to_str().unwrap()] {
        let (code, err) = rime_within_20_s(&["eps", "--g", "0.01", "--scene", path]);
        assert_eq!(code, Some(2), "{path}: {err}");
        assert!(
            err.contains("--scene") && err.contains("not a regular file"),
            "{path}: {err}"
        );
    }
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn the_cli_refuses_what_the_core_request_refuses_issue_21() {
    use rime_core::explorer::request::Request;
    let over_map = (Request::MAX_MAP_N + 1).to_string();
    let over_points = (Request::MAX_POINTS + 1).to_string();
    for (args, field) in [
        (
            vec!["map", "--max", "0.01", "--n", over_map.as_str()],
            "--n",
        ),
        (
            vec![
                "curve",
                "--from",
                "1e-6",
                "--to",
                "1",
                "--points",
                over_points.as_str(),
            ],
            "--points",
        ),
        (
            vec![
                "figures",
                "--explorer",
                "--n",
                over_map.as_str(),
                "--out",
                "x",
            ],
            "--n",
        ),
        (
            vec![
                "figures",
                "--explorer",
                "--points",
                over_points.as_str(),
                "--out",
                "x",
            ],
            "--points",
        ),
        (
            vec![
                "figures",
                "--explorer",
                "--from",
                "1e-13",
                "--to",
                "1",
                "--out",
                "x",
            ],
            "--from",
        ),
        (
            vec![
                "figures",
                "--explorer",
                "--from",
                "1",
                "--to",
                "0.1",
                "--out",
                "x",
            ],
            "--to",
        ),
        (
            vec![
                "figures",
                "--explorer",
                "--overlays",
                "atlas:nope",
                "--out",
                "x",
            ],
            "--overlays",
        ),
    ] {
        rejects(&args, field);
    }
}
