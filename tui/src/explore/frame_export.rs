//! `x`: writes the current frame's records, scene and figures into `rime-export-<timestamp>/`.
//! Records and figures come from the core ([`rime_core::explorer::records`],
//! [`rime_core::explorer::figures`]): the same functions as the page's downloads and the
//! subcommands, so the same scene gives the same CSV everywhere and the figures show what the
//! screen shows (the [`View`] the explorer draws with).

use super::format;
use crate::scene_io::{CliError, CliResult, scene_json, write_atomic};
use rime_core::explorer::figures::{View, frame_figures};
use rime_core::explorer::frame::Frame;
use rime_core::explorer::records;
use rime_core::explorer::ring::RingCard;
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
pub fn write_frame(
    dir: &Path,
    f: &Frame,
    view: &View,
    ring: Option<&RingCard>,
    date: &str,
) -> CliResult<Vec<String>> {
    let context = |what: &str| records::context(f, what, VERSION, date);
    let mut texts = vec![
        (
            "scene.json".to_string(),
            scene_json(&f.request.scene)? + "\n",
        ),
        (
            "eps_curve.csv".to_string(),
            context(records::CURVE_WHAT) + &records::frame_curve_csv(f),
        ),
        (
            "eps_family.csv".to_string(),
            // Every curve the chart draws: measured laws, pinned curve, the ring's ε_cr line.
            context(records::FAMILY_WHAT)
                + &records::family_csv_drawn(
                    f,
                    &records::Drawn {
                        pinned: view.pinned.as_ref(),
                        experiments: view.experiments,
                        ring_eps_cr: ring.map(|c| (c.record.tau, c.record.prediction().eps_cr)),
                    },
                ),
        ),
    ];
    if let Some(map) = records::frame_map_csv(f) {
        texts.push((
            "stick_map.csv".to_string(),
            context(records::MAP_WHAT) + &map,
        ));
    }
    let mut figures = frame_figures(f, view, VERSION);
    // The ring card's ε_cr line, meeting point and marker, as on screen.
    if let (Some(card), Some(eps)) = (ring, figures.first_mut()) {
        card.overlay(eps);
    }
    for fig in &figures {
        let svg = rime_core::figure::render_svg(fig, 1000, 650)?;
        texts.push((format!("{}.svg", fig.name), svg));
    }
    let mut written = Vec::new();
    for (name, text) in texts {
        write_atomic(&dir.join(&name), text.as_bytes())?;
        written.push(name);
    }
    for fig in &figures {
        // PNG via a temporary name, then renamed: never a half-written file.
        let tmp = dir.join(format!(".{}.tmp.png", fig.name));
        rime_core::figure::render_png(fig, &tmp, 1000, 650)?;
        let png = format!("{}.png", fig.name);
        std::fs::rename(&tmp, dir.join(&png))
            .map_err(|e| CliError::input(format!("{}: {e}", dir.join(&png).display())))?;
        written.push(png);
    }
    Ok(written)
}

/// Writes the frame ([`write_frame`]) into a new folder `rime-export-<UTC timestamp>` under
/// `base`; returns the folder.
pub fn export(
    base: &Path,
    frame: &Frame,
    view: &View,
    ring: Option<&RingCard>,
) -> CliResult<PathBuf> {
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
    std::fs::create_dir_all(&dir)
        .map_err(|e| CliError::input(format!("{}: {e}", dir.display())))?;
    write_frame(&dir, frame, view, ring, &date(secs))?;
    Ok(dir)
}
