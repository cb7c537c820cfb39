//! `x`: writes the current frame's tables and scene into `rime-export-<timestamp>/`.

use super::compute::{FrameData, SWEEPS};
use super::format;
use crate::output::num;
use crate::scene_io::{CliError, CliResult, scene_json, write_atomic};
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
    Ok(dir)
}
