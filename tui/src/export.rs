//! `rime export` and `rime fit`: what users take into their own codes.

use crate::codegen::Law;
use crate::output::num;
use crate::scene_io::{CliError, CliResult, err, write_atomic};
use rime_core::fit::{Eq27, PowerLaw, fit_eq27, fit_power_law};
use rime_core::{Accuracy, Contact, Scene, sweep};
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
    let (g, normals) = sweep::curve(&contact, from, to, n, accuracy)?;
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
    std::fs::create_dir_all(dir).map_err(|x| CliError(format!("--out {}: {x}", dir.display())))?;
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
        ("rime_rebound.py", law.rebound_py()),
    ];
    let mut names = Vec::new();
    for (name, text) in files {
        write_atomic(&dir.join(name), text.as_bytes())?;
        names.push(name.to_string());
    }
    Ok(names)
}

/// Reads (g, ε) points from a CSV file: two numeric columns, an optional header line.
pub fn read_points(path: &Path) -> CliResult<(Vec<f64>, Vec<f64>)> {
    let shown = path.display();
    let text = crate::scene_io::read_bounded(path, 16 << 20, "--data")?;
    let (mut g, mut e) = (Vec::new(), Vec::new());
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let cells: Vec<&str> = line
            .split([',', ';', '\t', ' '])
            .filter(|c| !c.is_empty())
            .collect();
        let parsed = (
            cells.first().map(|c| c.parse::<f64>()),
            cells.get(1).map(|c| c.parse::<f64>()),
        );
        match parsed {
            (Some(Ok(a)), Some(Ok(b)))
                if a.is_finite() && b.is_finite() && a > 0.0 && (0.0..=1.0).contains(&b) =>
            {
                g.push(a);
                e.push(b);
            }
            _ if i == 0 && g.is_empty() => continue, // a header
            _ => {
                return err(format!(
                    "--data {shown}: line {}: expected two numbers g > 0 [m/s] and 0 ≤ ε ≤ 1",
                    i + 1
                ));
            }
        }
    }
    if g.len() < 2 {
        return err(format!("--data {shown}: need at least two (g, ε) points"));
    }
    Ok((g, e))
}

/// Fits one numeric scene parameter (by path) to measured (g, ε) points: the value minimising the
/// squared error of ε_N, searched on a log scale (golden section after a coarse scan).
pub fn fit_parameter(
    scene: &Scene,
    path: &str,
    g: &[f64],
    e: &[f64],
    accuracy: Accuracy,
) -> CliResult<(f64, f64, Scene)> {
    let p = rime_core::params::parameter(path)
        .ok_or_else(|| CliError(format!("--param {path}: unknown parameter")))?;
    let rime_core::params::Kind::Number { min, max, .. } = p.kind else {
        return err(format!("--param {path}: not a numeric parameter"));
    };
    let lo = if min > 0.0 {
        min
    } else {
        1e-12f64.max(max * 1e-30)
    };
    let cost = |x: f64| -> Option<(f64, Scene)> {
        let mut s = *scene;
        s.set_number(p.path, x).ok()?;
        let c = Contact::new(&s).ok()?;
        let mut sum = 0.0;
        for (&gi, &ei) in g.iter().zip(e) {
            let r = c.eps_n(gi, accuracy).ok()? - ei;
            sum += r * r;
        }
        Some((sum, s))
    };
    let (a, b) = (lo.ln(), max.ln());
    let mut best = (f64::INFINITY, a);
    let steps = 80;
    for i in 0..=steps {
        let u = a + (b - a) * i as f64 / steps as f64;
        if let Some((c, _)) = cost(u.exp())
            && c < best.0
        {
            best = (c, u);
        }
    }
    if !best.0.is_finite() {
        return err(format!(
            "--param {path}: no valid value found in [{lo}, {max}]"
        ));
    }
    let h = (b - a) / steps as f64;
    let (mut l, mut r) = (best.1 - h, best.1 + h);
    let phi = 0.5 * (5f64.sqrt() - 1.0);
    let f = |u: f64| cost(u.exp()).map_or(f64::INFINITY, |c| c.0);
    for _ in 0..80 {
        let (m1, m2) = (r - phi * (r - l), l + phi * (r - l));
        if f(m1) < f(m2) {
            r = m2;
        } else {
            l = m1;
        }
    }
    let u = 0.5 * (l + r);
    let (sse, fitted) =
        cost(u.exp()).ok_or_else(|| CliError(format!("--param {path}: fit failed")))?;
    Ok((u.exp(), (sse / g.len() as f64).sqrt(), fitted))
}
