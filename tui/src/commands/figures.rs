//! `rime figures --out DIR`: the paper's Figs. 2–4 from the model, SVG + PNG.

use crate::cli::Common;
use crate::scene_io::{self, CliError, CliResult};
use std::path::Path;

/// Writes every figure into `out` and lists them with their captions.
pub fn run(c: &Common, out: &Path) -> CliResult<String> {
    std::fs::create_dir_all(out).map_err(|e| CliError(format!("--out {}: {e}", out.display())))?;
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
            .map_err(|e| CliError(format!("{}: cannot write: {e}", png.display())))?;
        s.push_str(&format!("{}: {}\n  {}\n", f.name, f.title, f.caption));
    }
    s.push_str(&format!(
        "wrote {} figures (SVG + PNG) into {}\n",
        figures.len(),
        out.display()
    ));
    Ok(s)
}
