//! `rime export --out DIR`: tables, fitted laws and generated code (crate::takeaway, crate::codegen).

use crate::args::Common;
use crate::scene_io::{self, CliResult};
use crate::{codegen, output, takeaway};
use std::path::Path;

/// Writes the files into `out` and summarises them.
pub fn run(
    c: &Common,
    from: f64,
    to: f64,
    n: usize,
    out: &Path,
    runtime_params: bool,
) -> CliResult<String> {
    let scene = scene_io::scene_json(&c.scene)?;
    let law = codegen::Law::new(&c.scene, c.accuracy, &scene, runtime_params)?;
    let e = takeaway::compute(&c.scene, from, to, n, c.accuracy)?;
    let files = takeaway::write_all(out, &e, &scene, &law)?;
    let mut s = format!("wrote {} into {}\n", files.join(", "), out.display());
    if let Some(f) = e.eq27 {
        s.push_str(&format!(
            "Eq. (27): eps = {:.6} g^{:.6} (1 - exp(-{:.6e} g^{:.6})), rms error {:.2e}, max {:.2e}, on {}..{} m/s\n",
            f.a, f.b, f.c, f.d, f.rms_error, f.max_error, output::num(f.g_min), output::num(f.g_max)
        ));
    }
    if let Some(p) = e.power {
        s.push_str(&format!(
            "power law: eps = {:.6} (g / 1 cm/s)^{:.6}, rms error {:.2e}\n",
            p.a, p.b, p.rms_error
        ));
    }
    Ok(s)
}
