//! Running the `rime` binary that Cargo built for this test run.

use std::path::PathBuf;

/// The `rime` binary of this test run (built by Cargo with the tests, never stale).
pub fn rime_binary() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_rime"))
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
