//! `rime export` and `rime fit`: what users take into their own codes.

use crate::codegen::Law;
use crate::output::num;
use crate::scene_io::{CliError, CliResult, write_atomic};
use rime_core::fit::{Eq27, PowerLaw, fit_eq27, fit_power_law};
use rime_core::{Accuracy, Contact, Scene};
use std::path::Path;

/// The exported curve and the laws fitted to it.
pub struct Export {
    /// Speeds.
    pub g: Vec<f64>,
    /// ε_N at the speeds.
    pub eps: Vec<f64>,
    /// Status names.
    pub status: Vec<&'static str>,
    /// Eq. (27), when it could be fitted.
    pub eq27: Option<Eq27>,
    /// Power law with g₀ = 1 cm/s over the rebounding points.
    pub power: Option<PowerLaw>,
}

/// Computes the table and fits.
pub fn compute(
    scene: &Scene,
    from: f64,
    to: f64,
    n: usize,
    accuracy: Accuracy,
) -> CliResult<Export> {
    let contact = Contact::new(scene)?;
    // Decades exact, like `rime curve`.
    let g = crate::commands::curve::log_space(from, to, n);
    let normals = g
        .iter()
        .map(|&gi| contact.normal(gi, accuracy))
        .collect::<Result<Vec<_>, _>>()?;
    let eps: Vec<f64> = normals.iter().map(|n| n.eps).collect();
    let status = normals.iter().map(|n| n.status.name()).collect();
    Ok(Export {
        eq27: fit_eq27(&g, &eps).ok(),
        power: fit_power_law(&g, &eps, 0.01).ok(),
        g,
        eps,
        status,
    })
}

/// C source: the master curve of [`crate::codegen::Law`], then the fitted laws.
pub fn c_source(e: &Export, law: &Law) -> String {
    let mut s = law.c_source();
    if let Some(f) = &e.eq27 {
        s.push_str(&format!(
            "\n/* Eq. (27) of Hertzsch (2002), fitted on {}…{} m/s: rms error {:.2e}, max {:.2e}. */\n\
             double rime_eps_n_eq27(double g) {{\n\
             \x20   return {:?} * pow(g, {:?}) * (1.0 - exp(-{:?} * pow(g, {:?})));\n}}\n",
            num(f.g_min), num(f.g_max), f.rms_error, f.max_error, f.a, f.b, f.c, f.d
        ));
    }
    if let Some(p) = &e.power {
        s.push_str(&format!(
            "\n/* Power law eps = a (g / 1 cm/s)^b fitted on {}…{} m/s: rms error {:.2e}. */\n\
             double rime_eps_n_power(double g) {{\n\
             \x20   return {:?} * pow(g / {:?}, {:?});\n}}\n",
            num(p.g_min),
            num(p.g_max),
            p.rms_error,
            p.a,
            p.g0,
            p.b
        ));
    }
    s
}

/// Rust source (no_std): the same as [`c_source`].
pub fn rust_source(e: &Export, law: &Law) -> String {
    let mut s = law.rust_source();
    if let Some(f) = &e.eq27 {
        s.push_str(&format!(
            "\n/// Eq. (27) of Hertzsch (2002), fitted on {}…{} m/s: rms error {:.2e}, max {:.2e}.\n\
             pub fn rime_eps_n_eq27(g: f64) -> f64 {{\n\
             \x20   {:?} * rime_pow(g, {:?}) * (1.0 - rime_exp(-{:?} * rime_pow(g, {:?})))\n}}\n",
            num(f.g_min), num(f.g_max), f.rms_error, f.max_error, f.a, f.b, f.c, f.d
        ));
    }
    if let Some(p) = &e.power {
        s.push_str(&format!(
            "\n/// Power law ε = a (g / 1 cm/s)^b fitted on {}…{} m/s: rms error {:.2e}.\n\
             pub fn rime_eps_n_power(g: f64) -> f64 {{\n\
             \x20   {:?} * rime_pow(g / {:?}, {:?})\n}}\n",
            num(p.g_min),
            num(p.g_max),
            p.rms_error,
            p.a,
            p.g0,
            p.b
        ));
    }
    s
}

/// Writes every export file into `dir`; returns the file names.
pub fn write_all(dir: &Path, e: &Export, scene_json: &str, law: &Law) -> CliResult<Vec<String>> {
    std::fs::create_dir_all(dir)
        .map_err(|x| CliError::input(format!("--out {}: {x}", dir.display())))?;
    let mut csv = String::from("g_n,eps_n,status\n");
    for ((g, eps), st) in e.g.iter().zip(&e.eps).zip(&e.status) {
        csv.push_str(&format!("{},{},{}\n", num(*g), num(*eps), st));
    }
    let fits = serde_json::json!({
        "eq27": e.eq27.map(|f| serde_json::json!({
            "law": "a * g^b * (1 - exp(-c * g^d))", "a": f.a, "b": f.b, "c": f.c, "d": f.d,
            "rms_error": f.rms_error, "max_error": f.max_error, "g_min": f.g_min, "g_max": f.g_max })),
        "power_law": e.power.map(|p| serde_json::json!({
            "law": "a * (g / g0)^b", "a": p.a, "b": p.b, "g0": p.g0,
            "rms_error": p.rms_error, "max_error": p.max_error, "g_min": p.g_min, "g_max": p.g_max })),
    });
    let table = serde_json::json!({
        "scene": serde_json::from_str::<serde_json::Value>(scene_json).unwrap_or_default(),
        "g_n": e.g, "eps_n": e.eps, "status": e.status, "fits": fits,
    });
    let files = [
        ("eps_table.csv", csv),
        ("eps_table.json", format!("{table:#}\n")),
        ("fits.json", format!("{fits:#}\n")),
        ("rime_eps.h", law.c_header()),
        ("rime_eps.c", c_source(e, law)),
        ("rime_eps.rs", rust_source(e, law)),
        ("rime_rebound.c", law.rebound_c()),
        ("rime_rebound.h", law.rebound_h()),
        ("rime_rebound.py", law.rebound_py()),
    ];
    let mut names = Vec::new();
    for (name, text) in files {
        write_atomic(&dir.join(name), text.as_bytes())?;
        names.push(name.to_string());
    }
    Ok(names)
}
