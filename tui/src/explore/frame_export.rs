//! `x`: writes the current frame's tables, scene and figures (SVG + PNG through the shared
//! `rime_core::figure` code) into `rime-export-<timestamp>/`.

use super::compute::{FrameData, SWEEPS};
use super::format;
use crate::output::num;
use crate::scene_io::{CliError, CliResult, scene_json, write_atomic};
use rime_core::explorer::palette;
use rime_core::figure::{Axis, Figure, Marker, Series, speed_label};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// ε_N curves as CSV: `g_n, eps_n, status, eps_n_clean (if any), one column per family member`.
pub fn curves_csv(data: &FrameData) -> String {
    let sweep = SWEEPS.get(data.sweep).map_or("family", |s| s.path);
    let mut s = String::from("g_n,eps_n,status");
    if data.clean.is_some() {
        s.push_str(",eps_n_clean");
    }
    for m in &data.family {
        let _ = write!(s, ",eps_n[{sweep}={}]", num(m.value));
    }
    s.push('\n');
    let cell = |v: f64| if v.is_finite() { num(v) } else { String::new() };
    for (k, &g) in data.g.iter().enumerate() {
        let cur = data.current.get(k).copied().flatten();
        let _ = write!(
            s,
            "{},{},{}",
            num(g),
            cur.map_or(String::new(), |n| cell(n.eps)),
            cur.map_or("error", |n| n.status.name())
        );
        if let Some(clean) = &data.clean {
            let _ = write!(s, ",{}", clean.get(k).map_or(String::new(), |v| cell(*v)));
        }
        for m in &data.family {
            let _ = write!(s, ",{}", m.eps.get(k).map_or(String::new(), |v| cell(*v)));
        }
        s.push('\n');
    }
    s
}

/// The stick map as CSV: `g_n,g_t,eps_t,class` (empty body without friction).
pub fn map_csv(data: &FrameData) -> String {
    let mut s = String::from("g_n,g_t,eps_t,class\n");
    if let Some(map) = &data.map {
        let n = map.n();
        for i in 0..n {
            for j in 0..n {
                let k = i * n + j;
                let (Some(c), Some(e)) = (map.class.get(k), map.eps_t.get(k)) else {
                    continue;
                };
                let _ = writeln!(
                    s,
                    "{},{},{},{}",
                    num(map.g[i]),
                    num(map.g[j]),
                    num(*e),
                    c.name()
                );
            }
        }
    }
    s
}

/// The frame as figure descriptions (the shared `rime_core::figure` code): the ε_N chart and the
/// stick map.
pub fn figures(data: &FrameData) -> Vec<Figure> {
    let sweep = SWEEPS.get(data.sweep);
    let symbol = sweep.map_or("p", |s| s.symbol);
    let pts = |eps: &dyn Fn(usize) -> f64| -> Vec<(f64, f64)> {
        data.g
            .iter()
            .enumerate()
            .map(|(k, &g)| (g, eps(k)))
            .filter(|(_, e)| e.is_finite())
            .collect()
    };
    let mut series: Vec<Series> = data
        .family
        .iter()
        .enumerate()
        .map(|(k, m)| Series {
            name: format!("{symbol} = {}", num(m.value)),
            points: pts(&|i| m.eps.get(i).copied().unwrap_or(f64::NAN)),
            color: k % palette::FAMILY.len(),
            dashed: false,
        })
        .collect();
    series.push(Series {
        name: "this scene".to_string(),
        points: pts(&|i| {
            data.current
                .get(i)
                .copied()
                .flatten()
                .map_or(f64::NAN, |n| n.eps)
        }),
        color: palette::SERIES_SCENE,
        dashed: false,
    });
    if let Some(clean) = &data.clean {
        series.push(Series {
            name: "clean surfaces".to_string(),
            points: pts(&|i| clean.get(i).copied().unwrap_or(f64::NAN)),
            color: palette::SERIES_CLEAN,
            dashed: true,
        });
    }
    let mut markers = Vec::new();
    if let Some(c) = &data.contact {
        if let Some(l) = c.layer {
            markers.push(Marker {
                x: l.critical_velocity,
                label: format!("g_s (layer) = {}", speed_label(l.critical_velocity)),
                color: palette::SERIES_SCENE,
            });
        }
        if let Some(a) = c.adhesion {
            markers.push(Marker {
                x: a.critical_velocity,
                label: format!("g_s (adhesion) = {}", speed_label(a.critical_velocity)),
                color: palette::SERIES_SCENE,
            });
        }
    }
    let (g0, g1) = (
        data.g.first().copied().unwrap_or(1e-7),
        data.g.last().copied().unwrap_or(10.0),
    );
    let scene = scene_json(&data.scene)
        .unwrap_or_default()
        .replace('\n', " ");
    let mut out = vec![Figure {
        name: "eps_n".to_string(),
        title: "ε_N(g_N), rime explorer".to_string(),
        caption: format!("accuracy {}; scene {}", data.accuracy.name(), scene),
        x: Axis {
            label: "normal impact speed g_N [m/s]".to_string(),
            log: true,
            min: g0,
            max: g1,
        },
        y: Axis {
            label: "normal restitution ε_N".to_string(),
            log: false,
            min: 0.0,
            max: 1.0,
        },
        series,
        markers,
        bands: Vec::new(),
        map: None,
    }];
    if let Some(map) = &data.map {
        out.push(Figure::stick_map(
            "stick_map".to_string(),
            "stick-map classes over (g_N, g_T), rime explorer".to_string(),
            format!("accuracy {}; scene {}", data.accuracy.name(), scene),
            map.g.clone(),
            map.class.clone(),
            data.map_max,
        ));
    }
    out
}

/// Writes `scene.json`, `eps_curves.csv` and `stick_map.csv` into a new folder
/// `rime-export-<UTC timestamp>` under `base`; returns the folder.
pub fn export(base: &Path, data: &FrameData) -> CliResult<PathBuf> {
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
    write_atomic(
        &dir.join("scene.json"),
        (scene_json(&data.scene)? + "\n").as_bytes(),
    )?;
    write_atomic(&dir.join("eps_curves.csv"), curves_csv(data).as_bytes())?;
    write_atomic(&dir.join("stick_map.csv"), map_csv(data).as_bytes())?;
    for fig in figures(data) {
        let svg = rime_core::figure::render_svg(&fig, 1000, 650)?;
        write_atomic(&dir.join(format!("{}.svg", fig.name)), svg.as_bytes())?;
        // PNG via a temporary name, then renamed: never a half-written file.
        let tmp = dir.join(format!(".{}.tmp.png", fig.name));
        rime_core::figure::render_png(&fig, &tmp, 1000, 650)?;
        let png = dir.join(format!("{}.png", fig.name));
        std::fs::rename(&tmp, &png).map_err(|e| CliError(format!("{}: {e}", png.display())))?;
    }
    Ok(dir)
}
