//! Shared helpers for the integration tests of rime.

use std::path::PathBuf;

/// Relative difference |a − b| / |b| (absolute when b = 0).
pub fn rel(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        a.abs()
    } else {
        ((a - b) / b).abs()
    }
}

/// Path of a file under `tests/data/`.
pub fn data(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("data")
        .join(name)
}

/// Reads a CSV file with a header into rows of (column name → text) pairs.
pub fn read_csv(name: &str) -> Vec<std::collections::HashMap<String, String>> {
    let path = data(name);
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    let mut lines = text
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'));
    let header: Vec<String> = lines
        .next()
        .unwrap_or_default()
        .split(',')
        .map(|s| s.trim().to_string())
        .collect();
    lines
        .map(|l| {
            header
                .iter()
                .cloned()
                .zip(l.split(',').map(|s| s.trim().to_string()))
                .collect()
        })
        .collect()
}

/// The `rime` binary of this profile, rebuilt once per test run (a no-op when it is fresh), so that
/// CLI tests never run a stale binary.
pub fn rime_binary() -> PathBuf {
    static BUILT: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
    BUILT
        .get_or_init(|| {
            let exe = std::env::current_exe().unwrap_or_default();
            // target/<profile>/deps/integration-… → target/<profile>/rime
            let profile_dir = exe
                .parent()
                .and_then(|p| p.parent())
                .map(PathBuf::from)
                .unwrap_or_default();
            let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
            let mut cmd = std::process::Command::new(env!("CARGO"));
            cmd.args(["build", "-q", "-p", "rime-tui"])
                .current_dir(&root);
            if profile_dir.ends_with("release") {
                cmd.arg("--release");
            }
            let status = cmd.status();
            assert!(
                matches!(status, Ok(s) if s.success()),
                "building rime failed"
            );
            profile_dir.join("rime")
        })
        .clone()
}

/// Runs the `rime` binary: exit code, stdout and stderr.
pub fn rime(args: &[&str]) -> (i32, String, String) {
    let out = std::process::Command::new(rime_binary())
        .args(args)
        .output()
        .unwrap_or_else(|e| panic!("cannot run rime: {e}"));
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).to_string(),
        String::from_utf8_lossy(&out.stderr).to_string(),
    )
}

/// Runs `rime ARGS --format json`, asserts success and parses its output.
pub fn rime_json(args: &[&str]) -> serde_json::Value {
    let mut all = args.to_vec();
    all.extend(["--format", "json"]);
    let (code, out, err) = rime(&all);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("{args:?}: {e}"))
}
