//! `x`: writes the current frame's records, scene and figures into `rime-export-<timestamp>/`.
//! Records and figures come from the core ([`rime_core::explorer::records`],
//! [`rime_core::explorer::figures`]): the same functions as the page's downloads and the
//! subcommands, so the same scene gives the same CSV everywhere and the figures show what the
//! screen shows (the [`View`] the explorer draws with).

use super::compute::FrameData;
use super::format;
use crate::scene_io::{CliError, CliResult, scene_json, write_atomic};
use rime_core::explorer::figures::{View, frame_figures};
use rime_core::explorer::frame::Frame;
use rime_core::explorer::records;
use std::path::{Path, PathBuf};

/// The program's version, as records and captions cite it.
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// The date of an export, `YYYY-MM-DD hh:mm:ss UTC`.
pub fn date(secs: u64) -> String {
    let t = format::timestamp(secs);
    match (
        t.get(0..4),
        t.get(4..6),
        t.get(6..8),
        t.get(9..11),
        t.get(11..13),
        t.get(13..15),
    ) {
        (Some(y), Some(mo), Some(d), Some(h), Some(mi), Some(s)) => {
            format!("{y}-{mo}-{d} {h}:{mi}:{s} UTC")
        }
        _ => t,
    }
}

/// Writes `scene.json`, `eps_curve.csv` (the records `rime curve` writes for the same speeds),
/// `eps_family.csv` (every curve side by side), `stick_map.csv` (the records of `rime map`, when the
/// frame has a map) and the figures as SVG and PNG into `dir`, which must exist. Each CSV starts
/// with `# ` context lines (version, level, scene, `date`, citation). Returns the files written.
pub fn write_frame(dir: &Path, f: &Frame, view: &View, date: &str) -> CliResult<Vec<String>> {
    let mut names = Vec::new();
    let mut written = Vec::new();
    let mut write = |name: &str, bytes: &[u8]| -> CliResult<()> {
        write_atomic(&dir.join(name), bytes)?;
        written.push(name.to_string());
        Ok(())
    };
    write(
        "scene.json",
        (scene_json(&f.request.scene)? + "\n").as_bytes(),
    )?;
    let context = |what: &str| records::context(f, what, VERSION, date);
    write(
        "eps_curve.csv",
        (context("ε_N records of this scene (rime curve)") + &records::frame_curve_csv(f))
            .as_bytes(),
    )?;
    write(
        "eps_family.csv",
        (context("every ε_N curve of the chart") + &records::family_csv(f)).as_bytes(),
    )?;
    if let Some(map) = records::frame_map_csv(f) {
        write(
            "stick_map.csv",
            (context("stick-map records (rime map)") + &map).as_bytes(),
        )?;
    }
    for fig in frame_figures(f, view, VERSION) {
        let svg = rime_core::figure::render_svg(&fig, 1000, 650)?;
        write(&format!("{}.svg", fig.name), svg.as_bytes())?;
        // PNG via a temporary name, then renamed: never a half-written file.
        let tmp = dir.join(format!(".{}.tmp.png", fig.name));
        rime_core::figure::render_png(&fig, &tmp, 1000, 650)?;
        let png = dir.join(format!("{}.png", fig.name));
        std::fs::rename(&tmp, &png).map_err(|e| CliError(format!("{}: {e}", png.display())))?;
        names.push(format!("{}.png", fig.name));
    }
    names.extend(written);
    Ok(names)
}

/// Writes the frame ([`write_frame`]) into a new folder `rime-export-<UTC timestamp>` under
/// `base`; returns the folder.
pub fn export(base: &Path, data: &FrameData, view: &View) -> CliResult<PathBuf> {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let stamp = format::timestamp(secs);
    let mut dir = base.join(format!("rime-export-{stamp}"));
    let mut k = 2;
    while dir.exists() {
        dir = base.join(format!("rime-export-{stamp}-{k}"));
        k += 1;
    }
    std::fs::create_dir_all(&dir).map_err(|e| CliError(format!("{}: {e}", dir.display())))?;
    write_frame(&dir, &data.frame, view, &date(secs))?;
    Ok(dir)
}
