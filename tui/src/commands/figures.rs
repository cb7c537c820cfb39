//! `rime figures --out DIR`: the paper's Figs. 2–4 from the model, SVG + PNG; with `--explorer`,
//! a scene's ε_N chart and stick map with their records, written by the same code as the
//! explorer's `x` (and drawn from the same core figure descriptions as the page's downloads).

use crate::args::{Common, ExplorerFigures};
use crate::scene_io::{self, CliError, CliResult};
use std::path::Path;

/// Writes every figure into `out` and lists them with their captions.
pub fn run(c: &Common, out: &Path, explorer: Option<&ExplorerFigures>) -> CliResult<String> {
    std::fs::create_dir_all(out)
        .map_err(|e| CliError::input(format!("--out {}: {e}", out.display())))?;
    if let Some(x) = explorer {
        return run_explorer(c, out, x);
    }
    let mut progress = crate::progress::Progress::new("figures", 1);
    progress.step("computing the curves");
    let figures = rime_core::figure::paper::all(c.accuracy, 160)?;
    let mut progress = crate::progress::Progress::new("figures", figures.len());
    let mut s = String::new();
    for f in &figures {
        progress.step(&f.name);
        let svg = rime_core::figure::render_svg(f, 1000, 680)?;
        scene_io::write_atomic(&out.join(format!("{}.svg", f.name)), svg.as_bytes())?;
        let png = out.join(format!("{}.png", f.name));
        let tmp = out.join(format!(".{}.tmp.png", f.name));
        rime_core::figure::render_png(f, &tmp, 1000, 680)?;
        std::fs::rename(&tmp, &png)
            .map_err(|e| CliError::input(format!("{}: cannot write: {e}", png.display())))?;
        s.push_str(&format!("{}: {}\n  {}\n", f.name, f.title, f.caption));
    }
    // The captions beside the figures, as docs/figures/captions.txt holds them (issue 37 X1).
    scene_io::write_atomic(&out.join("captions.txt"), s.as_bytes())?;
    s.push_str(&format!(
        "wrote {} figures (SVG + PNG) and captions.txt into {}\n",
        figures.len(),
        out.display()
    ));
    Ok(s)
}

/// `--explorer`: one frame of the core's explorer model, written like the explorer's `x`.
fn run_explorer(c: &Common, out: &Path, x: &ExplorerFigures) -> CliResult<String> {
    use rime_core::explorer::figures::View;
    // The scene and level are the common options' (the request was built from them).
    let mut req = x.request.clone();
    req.scene = c.scene;
    req.accuracy = c.accuracy;
    let mut progress = crate::progress::Progress::new("figures", 1);
    progress.step("computing the frame");
    // On every core; the frame is the core's sequential one, bit for bit.
    let frame = crate::explore::compute::frame(
        &req,
        &|| false,
        crate::explore::compute::threads(),
        &rime_core::normal::memo::NoMemo,
    )
    .ok_or_else(|| CliError::input("figures: cancelled"))?;
    if let Some(e) = frame
        .errors
        .iter()
        .find(|e| e.part == "request" || e.part == "scene")
    {
        return Err(CliError::input(format!("{}: {}", e.part, e.message)));
    }
    let view = View {
        y_log: x.y_log,
        experiments: !x.no_experiments,
        pinned: None,
    };
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let written = crate::explore::frame_export::write_frame(
        out,
        &frame,
        &view,
        None,
        &crate::explore::frame_export::date(secs),
    )?;
    let mut s = String::new();
    for e in &frame.errors {
        s.push_str(&format!("note: {}: {}\n", e.part, e.message));
    }
    s.push_str(&format!(
        "wrote {} into {}\n",
        written.join(", "),
        out.display()
    ));
    Ok(s)
}
