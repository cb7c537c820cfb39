//! Reading, overriding and writing scene JSON (the contract of docs/cli.md#scene-json).

use rime_core::{Preset, Scene};
use std::fmt;
use std::io::Write;
use std::path::{Path, PathBuf};

/// A scene file larger than this is rejected before parsing (a scene is a few hundred bytes).
pub const MAX_SCENE_BYTES: u64 = 1 << 20;

/// An error of the command-line layer: one line that names the field or flag.
#[derive(Debug, Clone, PartialEq)]
pub struct CliError(pub String);

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for CliError {}

impl From<rime_core::Error> for CliError {
    fn from(e: rime_core::Error) -> Self {
        CliError(e.to_string())
    }
}

/// Shorthand used throughout the binary.
pub type CliResult<T> = Result<T, CliError>;

/// Builds a [`CliError`] from anything displayable.
pub fn err<T>(msg: impl fmt::Display) -> CliResult<T> {
    Err(CliError(msg.to_string()))
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
    let meta = std::fs::metadata(path).map_err(|e| CliError(format!("{what} {shown}: {e}")))?;
    if !meta.is_file() {
        let kind = if meta.is_dir() {
            "a directory"
        } else {
            "not a regular file (a device, FIFO or socket)"
        };
        return err(format!("{what} {shown}: is {kind}; give a regular file"));
    }
    let too_big = || {
        CliError(format!(
            "{what} {shown}: larger than {limit} bytes, the limit for this file"
        ))
    };
    if meta.len() > limit {
        return Err(too_big());
    }
    let file = std::fs::File::open(path).map_err(|e| CliError(format!("{what} {shown}: {e}")))?;
    let mut bytes = Vec::new();
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| CliError(format!("{what} {shown}: {e}")))?;
    if bytes.len() as u64 > limit {
        return Err(too_big());
    }
    String::from_utf8(bytes).map_err(|_| CliError(format!("{what} {shown}: is not UTF-8 text")))
}

/// Reads a scene file (at most [`MAX_SCENE_BYTES`], regular files only).
pub fn load_scene(path: &Path) -> CliResult<Scene> {
    let shown = path.display();
    let text = read_bounded(path, MAX_SCENE_BYTES, "--scene")?;
    parse_scene(&text).map_err(|e| CliError(format!("--scene {shown}: {}", e.0)))
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
        Err(rime_core::Error::UnknownParameter) => {
            let known: Vec<&str> = rime_core::params::PARAMETERS
                .iter()
                .chain(rime_core::params::MODEL_PARAMETERS)
                .map(|p| p.path)
                .collect();
            err(format!(
                "--set {path}: unknown parameter (known: {})",
                known.join(", ")
            ))
        }
        Err(e) => err(format!("--set {path}={value}: {e}")),
    }
}

/// The scene as pretty JSON.
pub fn scene_json(scene: &Scene) -> CliResult<String> {
    serde_json::to_string_pretty(scene).map_err(|e| CliError(format!("scene: {e}")))
}

/// Looks a preset up by name; the error lists the known names.
pub fn preset(name: &str) -> CliResult<Scene> {
    match Preset::from_name(name) {
        Some(p) => Ok(p.scene()),
        None => {
            let names: Vec<&str> = Preset::ALL.iter().map(|p| p.name()).collect();
            err(format!(
                "--preset {name}: unknown preset (known: {})",
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
