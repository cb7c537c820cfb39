//! Reading, overriding and writing scene JSON (the contract of docs/cli.md#scene-json).

use rime_core::{Preset, Scene};
use std::fmt;
use std::io::Write;
use std::path::{Path, PathBuf};

/// A scene file larger than this is rejected before parsing (a scene is a few hundred bytes).
pub const MAX_SCENE_BYTES: u64 = 1 << 20;

#[cfg(test)]
mod exit_code_tests {
    use super::*;
    use rime_core::Error as E;

    /// docs/cli.md: a failed computation exits 1, bad input 2 (issue 25). No valid input is known
    /// to make a computation fail, so the mapping itself is what is checked here.
    #[test]
    fn issue_25_failed_computations_exit_1_and_bad_input_2() {
        let failed = [
            E::StepBudgetExceeded {
                what: "x",
                steps: 1,
            },
            E::StepSizeUnderflow { what: "x", t: 0.0 },
            E::Plot { reason: "x" },
            E::Fit {
                reason: rime_core::fit::FIT_DID_NOT_CONVERGE,
            },
        ];
        for e in failed {
            assert_eq!(CliError::from(e.clone()).exit_code(), 1, "{e}");
            assert_eq!(
                CliError::from(e.clone()).context("g_n = 1").exit_code(),
                1,
                "{e}"
            );
        }
        let bad = [
            E::OutOfRange {
                field: "g_n",
                value: -1.0,
                expected: "> 0",
            },
            E::DerivedOutOfRange {
                quantity: "m_eff",
                fields: "grains",
            },
            E::UnknownParameter,
            E::InvalidValue {
                field: "x",
                expected: "y",
            },
            E::Fit {
                reason: "too few points with ε > 0 to fit",
            },
        ];
        for e in bad {
            assert_eq!(CliError::from(e.clone()).exit_code(), 2, "{e}");
        }
        assert_eq!(CliError::input("--g: required").exit_code(), 2);
    }
}

/// An error of the command-line layer: one line that names the field or flag, and whether the
/// input was at fault (exit 2) or a computation failed on valid input (exit 1; docs/cli.md).
#[derive(Debug, Clone, PartialEq)]
pub struct CliError {
    /// The one line shown after `rime: error: `.
    pub message: String,
    /// Whose fault.
    pub kind: ErrorKind,
}

/// Why a command failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// Bad input: a flag, a value, a scene field, a file (exit 2).
    BadInput,
    /// A computation failed on valid input: an integrator's step budget or step size, a fit that
    /// did not converge, a figure that could not be drawn (exit 1).
    Failed,
}

impl CliError {
    /// Bad input (exit 2).
    pub fn input(message: impl Into<String>) -> CliError {
        CliError {
            message: message.into(),
            kind: ErrorKind::BadInput,
        }
    }

    /// A failed computation (exit 1).
    pub fn failed(message: impl Into<String>) -> CliError {
        CliError {
            message: message.into(),
            kind: ErrorKind::Failed,
        }
    }

    /// The same error with `prefix: ` in front (what it was computing), its kind kept.
    pub fn context(self, prefix: impl fmt::Display) -> CliError {
        CliError {
            message: format!("{prefix}: {}", self.message),
            kind: self.kind,
        }
    }

    /// The process exit code: 2 for bad input, 1 for a failed computation.
    pub fn exit_code(&self) -> u8 {
        match self.kind {
            ErrorKind::BadInput => 2,
            ErrorKind::Failed => 1,
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for CliError {}

impl From<rime_core::Error> for CliError {
    fn from(e: rime_core::Error) -> Self {
        use rime_core::Error as E;
        match e {
            E::StepBudgetExceeded { .. } | E::StepSizeUnderflow { .. } | E::Plot { .. } => {
                CliError::failed(e.to_string())
            }
            E::Fit { reason } if reason == rime_core::fit::FIT_DID_NOT_CONVERGE => {
                CliError::failed(e.to_string())
            }
            _ => CliError::input(e.to_string()),
        }
    }
}

/// Shorthand used throughout the binary.
pub type CliResult<T> = Result<T, CliError>;

/// Builds a [`CliError`] from anything displayable.
pub fn err<T>(msg: impl fmt::Display) -> CliResult<T> {
    Err(CliError::input(msg.to_string()))
}

/// Parses scene JSON; errors name the JSON path (`layer.viscosity: invalid type ...`).
pub fn parse_scene(text: &str) -> CliResult<Scene> {
    let de = &mut serde_json::Deserializer::from_str(text);
    let scene: Scene = match serde_path_to_error::deserialize(de) {
        Ok(s) => s,
        Err(e) => {
            let path = e.path().to_string();
            let inner = e.into_inner();
            let path = if path == "." || path.is_empty() {
                "scene".to_string()
            } else {
                path
            };
            return err(format!("{path}: {inner}"));
        }
    };
    scene.validate()?;
    Ok(scene)
}

/// Reads a whole text file of at most `limit` bytes, for the option or field named `what`.
///
/// Only regular files are read: devices (`/dev/zero`), FIFOs and directories are refused before
/// anything is read, and the read itself stops at `limit + 1` bytes, so that a file growing while
/// it is read cannot exhaust memory either.
pub fn read_bounded(path: &Path, limit: u64, what: &str) -> CliResult<String> {
    use std::io::Read;
    let shown = path.display();
    let meta =
        std::fs::metadata(path).map_err(|e| CliError::input(format!("{what} {shown}: {e}")))?;
    if !meta.is_file() {
        let kind = if meta.is_dir() {
            "a directory"
        } else {
            "not a regular file (a device, FIFO or socket)"
        };
        return err(format!("{what} {shown}: is {kind}; give a regular file"));
    }
    let too_big = || {
        CliError::input(format!(
            "{what} {shown}: larger than {limit} bytes, the limit for this file"
        ))
    };
    if meta.len() > limit {
        return Err(too_big());
    }
    let file =
        std::fs::File::open(path).map_err(|e| CliError::input(format!("{what} {shown}: {e}")))?;
    let mut bytes = Vec::new();
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| CliError::input(format!("{what} {shown}: {e}")))?;
    if bytes.len() as u64 > limit {
        return Err(too_big());
    }
    String::from_utf8(bytes)
        .map_err(|_| CliError::input(format!("{what} {shown}: is not UTF-8 text")))
}

/// Reads a scene file (at most [`MAX_SCENE_BYTES`], regular files only).
pub fn load_scene(path: &Path) -> CliResult<Scene> {
    let shown = path.display();
    let text = read_bounded(path, MAX_SCENE_BYTES, "--scene")?;
    parse_scene(&text).map_err(|e| CliError::input(format!("--scene {shown}: {}", e.message)))
}

/// Applies one `path=value` override.
pub fn apply_set(scene: &mut Scene, assignment: &str) -> CliResult<()> {
    let Some((path, value)) = assignment.split_once('=') else {
        return err(format!(
            "--set {assignment}: expected path=value, e.g. layer.viscosity=2000"
        ));
    };
    let path = path.trim();
    match scene.set(path, value) {
        Ok(()) => Ok(()),
        Err(rime_core::Error::UnknownParameter) => err(unknown_path(path)),
        Err(e) => err(format!("--set {path}={value}: {e}")),
    }
}

/// The error for an unknown `--set` path, short (issue 37: it listed all 24 paths on one
/// 518-character line): the close path (`did you mean`), else the paths of its section
/// (`friction.mu` → `friction.coefficient, …`), else the sections and where every path is listed.
fn unknown_path(path: &str) -> String {
    let known: Vec<&str> = rime_core::params::PARAMETERS
        .iter()
        .chain(rime_core::params::MODEL_PARAMETERS)
        .map(|p| p.path)
        .collect();
    if let Some(close) = crate::suggest::closest(path, known.iter().copied()) {
        return format!("--set {path}: unknown parameter (did you mean `{close}`?)");
    }
    let section = |p: &str| p.split_once('.').map_or(p, |(s, _)| s).to_string();
    let mut sections: Vec<String> = known.iter().map(|p| section(p)).collect();
    sections.dedup();
    let given = section(path);
    let same: Vec<&str> = known
        .iter()
        .copied()
        .filter(|p| p.contains('.') && section(p) == given)
        .collect();
    if !same.is_empty() {
        return format!(
            "--set {path}: unknown parameter; {given} has {}",
            same.join(", ")
        );
    }
    format!(
        "--set {path}: unknown parameter; the sections are {} (`rime scene` prints the scene: its keys are the paths)",
        sections.join(", ")
    )
}

/// The scene as pretty JSON.
pub fn scene_json(scene: &Scene) -> CliResult<String> {
    serde_json::to_string_pretty(scene).map_err(|e| CliError::input(format!("scene: {e}")))
}

/// Looks a preset up by name; the error lists the known names.
pub fn preset(name: &str) -> CliResult<Scene> {
    match Preset::from_name(name) {
        Some(p) => Ok(p.scene()),
        None => {
            let names: Vec<&str> = Preset::ALL.iter().map(|p| p.name()).collect();
            err(format!(
                "--preset {name}: unknown preset{} (known: {})",
                crate::suggest::hint(name, names.iter().copied()),
                names.join(", ")
            ))
        }
    }
}

/// Writes `contents` to `path` atomically: a temporary file in the same folder, flushed and synced,
/// then renamed over the target. A failure leaves any previous file untouched.
pub fn write_atomic(path: &Path, contents: &[u8]) -> CliResult<()> {
    let shown = path.display();
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().to_string())
        .unwrap_or_else(|| "out".to_string());
    let tmp = dir.join(format!(".{name}.tmp-{}", std::process::id()));
    let result = (|| -> std::io::Result<()> {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(contents)?;
        f.sync_all()?;
        std::fs::rename(&tmp, path)
    })();
    if let Err(e) = result {
        let _ = std::fs::remove_file(&tmp);
        return err(format!("{shown}: cannot write: {e}"));
    }
    Ok(())
}
