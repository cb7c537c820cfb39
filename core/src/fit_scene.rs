//! Fitting scene parameters to measured (g, ε) points, with standard errors (feature `alloc`).
//!
//! * [`parse_points`] — reads two or three numeric columns (g \[m/s\], ε, optional σ of ε); a header
//!   line is accepted only when it is recognisably one (no cell is a number, every cell starts with
//!   a letter); any other bad line is an error naming its line number.
//! * [`fit`] — least squares over one or several numeric scene parameters (Levenberg–Marquardt on
//!   nalgebra, after a coarse scan of each parameter's range), weighted by 1/σ² when σ is given.
//!   At the optimum the Jacobian J gives the covariance: s²(JᵀJ)⁻¹ with s² = Σr²/(n − p) without σ,
//!   (JᵀWJ)⁻¹ with σ (σ taken as absolute). Parameters are fitted in ln p where their range is
//!   positive, so standard errors are p·σ_{ln p} (first order). Degenerate parameters (near-singular
//!   JᵀJ, or |correlation| > 0.99) are reported as warnings, never silently.
//!
//! A parameter whose effect is off in the scene (e.g. `layer.viscosity` without a layer) is refused:
//! the fit never switches an effect on.

use crate::accuracy::Accuracy;
use crate::contact::Contact;
use crate::math::{exp, ln, sqrt};
use crate::params::{Kind, Value, parameter};
use crate::scene::Scene;
use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec;
use alloc::vec::Vec;
use nalgebra::{DMatrix, DVector, SymmetricEigen};

/// Most points [`parse_points`] accepts.
pub const MAX_POINTS: usize = 100_000;

/// |correlation| above which two parameters are reported as degenerate.
pub const DEGENERATE_CORRELATION: f64 = 0.99;

/// Measured points.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Points {
    /// Impact speeds \[m/s\].
    pub g: Vec<f64>,
    /// Measured ε_N.
    pub eps: Vec<f64>,
    /// Standard deviations of ε_N (third column), if given.
    pub sigma: Option<Vec<f64>>,
    /// The header line, if the file had one.
    pub header: Option<String>,
}

/// A bad line in a points file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParseError {
    /// 1-based line number (0 for the file as a whole).
    pub line: usize,
    /// What is wrong.
    pub reason: String,
}

impl core::fmt::Display for ParseError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        if self.line == 0 {
            write!(f, "{}", self.reason)
        } else {
            write!(f, "line {}: {}", self.line, self.reason)
        }
    }
}

/// A header has no number in it and starts with a name (`g_n [m/s],eps_n`, as `rime curve` writes).
fn is_header(cells: &[&str]) -> bool {
    cells
        .first()
        .is_some_and(|c| c.chars().next().is_some_and(|ch| ch.is_alphabetic()))
        && cells.iter().all(|c| c.parse::<f64>().is_err())
}

/// Parses (g, ε[, σ]) points: cells separated by commas, semicolons, tabs or spaces; `#` comments
/// and blank lines skipped.
pub fn parse_points(text: &str) -> core::result::Result<Points, ParseError> {
    let mut p = Points::default();
    let mut sigma: Vec<f64> = Vec::new();
    let mut columns: Option<usize> = None;
    let mut first = true;
    for (i, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let n = i + 1;
        let err = |reason: String| ParseError { line: n, reason };
        let cells: Vec<&str> = line
            .split([',', ';', '\t', ' '])
            .filter(|c| !c.is_empty())
            .collect();
        if first {
            first = false;
            if is_header(&cells) {
                p.header = Some(line.to_string());
                continue;
            }
        }
        if !(2..=3).contains(&cells.len()) {
            return Err(err(format!(
                "expected 2 or 3 columns (g [m/s], eps[, sigma]), found {}",
                cells.len()
            )));
        }
        match columns {
            None => columns = Some(cells.len()),
            Some(c) if c != cells.len() => {
                return Err(err(format!(
                    "{} columns where the lines before have {c}",
                    cells.len()
                )));
            }
            _ => {}
        }
        let num = |k: usize, name: &str| -> core::result::Result<f64, ParseError> {
            match cells[k].parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(v),
                _ => Err(ParseError {
                    line: n,
                    reason: format!("{name} '{}' is not a finite number", cells[k]),
                }),
            }
        };
        let g = num(0, "g")?;
        let e = num(1, "eps")?;
        if g <= 0.0 {
            return Err(err(format!("g = {g} must be > 0 [m/s]")));
        }
        if !(0.0..=1.0).contains(&e) {
            return Err(err(format!("eps = {e} must lie in [0, 1]")));
        }
        if cells.len() == 3 {
            let s = num(2, "sigma")?;
            if s <= 0.0 {
                return Err(err(format!("sigma = {s} must be > 0")));
            }
            sigma.push(s);
        }
        if p.g.len() >= MAX_POINTS {
            return Err(err(format!("more than {MAX_POINTS} points")));
        }
        p.g.push(g);
        p.eps.push(e);
    }
    if p.g.len() < 2 {
        return Err(ParseError {
            line: 0,
            reason: "need at least two (g, eps) points".to_string(),
        });
    }
    if columns == Some(3) {
        p.sigma = Some(sigma);
    }
    Ok(p)
}

/// One fitted parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct Fitted {
    /// Dotted scene path.
    pub path: &'static str,
    /// SI unit.
    pub unit: &'static str,
    /// Best value.
    pub value: f64,
    /// Standard error (first order); `None` when the parameter is not determined.
    pub standard_error: Option<f64>,
}

/// The result of [`fit`].
#[derive(Debug, Clone, PartialEq)]
pub struct SceneFit {
    /// The fitted parameters, in the order asked.
    pub params: Vec<Fitted>,
    /// Correlation matrix of the parameters; `None` when JᵀJ is singular.
    pub correlation: Option<Vec<Vec<f64>>>,
    /// rms of ε_model − ε over the points (unweighted).
    pub rms_error: f64,
    /// Σ((ε_model − ε)/σ)² / (n − p) when σ is given, Σ(ε_model − ε)² / (n − p) otherwise.
    pub reduced_chi2: f64,
    /// Degrees of freedom n − p.
    pub dof: usize,
    /// Whether σ weighted the fit.
    pub weighted: bool,
    /// Degeneracies, parameters at the edge of their range, and the like.
    pub warnings: Vec<String>,
    /// The scene with the fitted values.
    pub scene: Scene,
}

#[derive(Clone, Copy)]
struct Coord {
    path: &'static str,
    unit: &'static str,
    log: bool,
    lo: f64,
    hi: f64,
}

impl Coord {
    fn value(&self, u: f64) -> f64 {
        if self.log { exp(u) } else { u }
    }
    fn clamp(&self, u: f64) -> f64 {
        u.clamp(self.lo, self.hi)
    }
}

struct Problem<'a> {
    scene: Scene,
    coords: Vec<Coord>,
    g: &'a [f64],
    eps: &'a [f64],
    sigma: Option<&'a [f64]>,
    accuracy: Accuracy,
}

impl Problem<'_> {
    fn scene_at(&self, u: &[f64]) -> Option<Scene> {
        let mut s = self.scene;
        for (c, &x) in self.coords.iter().zip(u) {
            s.set_number(c.path, c.value(c.clamp(x))).ok()?;
        }
        Some(s)
    }

    /// Weighted residuals, or `None` where the model cannot be evaluated.
    fn residuals(&self, u: &[f64]) -> Option<DVector<f64>> {
        let s = self.scene_at(u)?;
        let c = Contact::new(&s).ok()?;
        let mut r = DVector::zeros(self.g.len());
        for (i, (&g, &e)) in self.g.iter().zip(self.eps).enumerate() {
            let m = c.eps_n(g, self.accuracy).ok()?;
            let w = self.sigma.map_or(1.0, |s| s[i]);
            r[i] = (m - e) / w;
        }
        Some(r)
    }

    fn cost(&self, u: &[f64]) -> f64 {
        self.residuals(u)
            .map_or(f64::INFINITY, |r| r.norm_squared())
    }

    fn jacobian(&self, u: &[f64]) -> Option<DMatrix<f64>> {
        let n = self.g.len();
        let mut j = DMatrix::zeros(n, u.len());
        for k in 0..u.len() {
            let c = self.coords[k];
            let h = if c.log {
                1e-4
            } else {
                1e-4 * u[k].abs().max(1e-3 * (c.hi - c.lo))
            };
            let (mut up, mut dn) = (u.to_vec(), u.to_vec());
            up[k] = c.clamp(u[k] + h);
            dn[k] = c.clamp(u[k] - h);
            let width = up[k] - dn[k];
            if width <= 0.0 {
                return None;
            }
            let (rp, rm) = (self.residuals(&up)?, self.residuals(&dn)?);
            for i in 0..n {
                j[(i, k)] = (rp[i] - rm[i]) / width;
            }
        }
        Some(j)
    }
}

/// Coarse scan of one coordinate over its range (log coordinates only), keeping the best.
fn scan(problem: &Problem<'_>, u: &mut [f64], best: &mut f64) {
    const STEPS: usize = 48;
    for k in 0..u.len() {
        let c = problem.coords[k];
        if !c.log {
            continue;
        }
        let mut trial = u.to_vec();
        for i in 0..=STEPS {
            trial[k] = c.lo + (c.hi - c.lo) * i as f64 / STEPS as f64;
            let cost = problem.cost(&trial);
            if cost < *best {
                *best = cost;
                u[k] = trial[k];
            }
        }
    }
}

fn levenberg_marquardt(problem: &Problem<'_>, u: &mut [f64], cost: &mut f64) {
    let p = u.len();
    let mut lambda = 1e-3;
    for _ in 0..200 {
        let (Some(j), Some(r)) = (problem.jacobian(u), problem.residuals(u)) else {
            return;
        };
        let jtj = j.transpose() * &j;
        let jtr = j.transpose() * r;
        let mut improved = false;
        for _ in 0..30 {
            let mut m = jtj.clone();
            for k in 0..p {
                m[(k, k)] += lambda * (jtj[(k, k)] + 1e-12);
            }
            let Some(step) = m.lu().solve(&(-&jtr)) else {
                lambda *= 10.0;
                continue;
            };
            let trial: Vec<f64> = (0..p)
                .map(|k| problem.coords[k].clamp(u[k] + step[k]))
                .collect();
            let c = problem.cost(&trial);
            if c.is_finite() && c < *cost {
                let rel = (*cost - c) / cost.max(1e-300);
                u.copy_from_slice(&trial);
                *cost = c;
                lambda = (lambda * 0.3).max(1e-12);
                improved = true;
                if rel < 1e-13 {
                    return;
                }
                break;
            }
            lambda *= 10.0;
        }
        if !improved {
            return;
        }
    }
}

/// Samples on a law's measured speeds for [`fit_to_entry`].
pub const LAW_POINTS: usize = 40;

/// Fits `paths` of `scene` to a measured law of the data atlas ("fit this scene to that entry"):
/// [`LAW_POINTS`] log-spaced samples of the law over the speeds it was measured at (its ε clamped to
/// \[0, 1\]; the scene's reduced radius for a law that needs one). The standard errors then measure
/// the model's misfit to the law, not measurement noise.
pub fn fit_to_entry(
    scene: &Scene,
    entry: &crate::atlas::Entry,
    paths: &[&str],
    accuracy: Accuracy,
) -> core::result::Result<SceneFit, String> {
    if entry.kind != crate::atlas::Kind::Law {
        return Err(format!(
            "{}: not a law (ranges and thresholds cannot be fitted to)",
            entry.id
        ));
    }
    let radius = if entry.needs_radius() {
        Some(Contact::new(scene).map_err(|e| format!("{e}"))?.r_eff)
    } else {
        None
    };
    let mut g = vec![0.0; LAW_POINTS];
    crate::sweep::log_space(entry.valid_speed[0], entry.valid_speed[1], &mut g);
    let mut eps = Vec::with_capacity(LAW_POINTS);
    for &x in &g {
        let e = entry
            .eval(x, radius)
            .map_err(|e| format!("{}: {e}", entry.id))?;
        eps.push(e.eps.clamp(0.0, 1.0));
    }
    fit(scene, paths, &g, &eps, None, accuracy)
}

/// Fits the numeric scene parameters `paths` to the points (σ optional, same length).
pub fn fit(
    scene: &Scene,
    paths: &[&str],
    g: &[f64],
    eps: &[f64],
    sigma: Option<&[f64]>,
    accuracy: Accuracy,
) -> core::result::Result<SceneFit, String> {
    if paths.is_empty() {
        return Err("no parameter to fit".to_string());
    }
    if g.len() != eps.len() || sigma.is_some_and(|s| s.len() != g.len()) {
        return Err("points: columns differ in length".to_string());
    }
    if g.len() <= paths.len() {
        return Err(format!(
            "{} points cannot determine {} parameters (need more points than parameters)",
            g.len(),
            paths.len()
        ));
    }
    let mut coords = Vec::with_capacity(paths.len());
    let mut u = Vec::with_capacity(paths.len());
    for (i, &path) in paths.iter().enumerate() {
        let p = parameter(path).ok_or_else(|| format!("{path}: unknown parameter"))?;
        if paths[..i].contains(&path) {
            return Err(format!("{path}: listed twice"));
        }
        let Kind::Number { min, max, .. } = p.kind else {
            return Err(format!("{path}: not a numeric parameter"));
        };
        let current = match scene.get(p.path) {
            Ok(Value::Number(v)) => v,
            Ok(Value::Inactive) => {
                return Err(format!(
                    "{path}: its effect is off in this scene; the fit does not switch effects on \
                     (switch it on first, e.g. --set {}=on)",
                    path.split('.').next().unwrap_or(path)
                ));
            }
            _ => return Err(format!("{path}: not a numeric parameter")),
        };
        let log = min >= 0.0;
        let c = if log {
            let lo = if min > 0.0 {
                min
            } else {
                1e-12f64.max(max * 1e-30)
            };
            Coord {
                path: p.path,
                unit: p.unit,
                log,
                lo: ln(lo),
                hi: ln(max),
            }
        } else {
            Coord {
                path: p.path,
                unit: p.unit,
                log,
                lo: min,
                hi: max,
            }
        };
        let start = if log {
            if current > 0.0 {
                ln(current)
            } else {
                0.5 * (c.lo + c.hi)
            }
        } else {
            current
        };
        u.push(c.clamp(start));
        coords.push(c);
    }
    let problem = Problem {
        scene: *scene,
        coords,
        g,
        eps,
        sigma,
        accuracy,
    };
    let mut cost = problem.cost(&u);
    scan(&problem, &mut u, &mut cost);
    if !cost.is_finite() {
        return Err("no parameter values in range give a valid model at these speeds".to_string());
    }
    levenberg_marquardt(&problem, &mut u, &mut cost);
    let fitted_scene = problem
        .scene_at(&u)
        .ok_or_else(|| "fit failed: the optimum is not a valid scene".to_string())?;
    let r = problem
        .residuals(&u)
        .ok_or_else(|| "fit failed: the model fails at the optimum".to_string())?;
    let (n, p) = (g.len(), u.len());
    let dof = n - p;
    let reduced_chi2 = r.norm_squared() / dof as f64;
    let rms_error = {
        let unweighted: f64 = r
            .iter()
            .enumerate()
            .map(|(i, x)| {
                let w = sigma.map_or(1.0, |s| s[i]);
                (x * w) * (x * w)
            })
            .sum();
        sqrt(unweighted / n as f64)
    };
    let mut warnings = Vec::new();
    for (k, c) in problem.coords.iter().enumerate() {
        let span = c.hi - c.lo;
        if u[k] <= c.lo + 1e-9 * span || u[k] >= c.hi - 1e-9 * span {
            warnings.push(format!(
                "{}: the fit ended at the edge of its range [{}, {}]",
                c.path,
                c.value(c.lo),
                c.value(c.hi)
            ));
        }
    }
    // Covariance from the Jacobian at the optimum.
    let j = problem
        .jacobian(&u)
        .ok_or_else(|| "fit failed: no Jacobian at the optimum".to_string())?;
    let jtj = j.transpose() * &j;
    let scale: Vec<f64> = (0..p).map(|k| sqrt(jtj[(k, k)])).collect();
    let mut standard_errors = vec![None; p];
    let mut correlation = None;
    let dead: Vec<usize> = (0..p).filter(|&k| !(scale[k] > 1e-300)).collect();
    for &k in &dead {
        warnings.push(format!(
            "{}: ε does not depend on it at these speeds; it is not determined",
            problem.coords[k].path
        ));
    }
    if dead.is_empty() {
        let scaled = DMatrix::from_fn(p, p, |a, b| jtj[(a, b)] / (scale[a] * scale[b]));
        let eig = SymmetricEigen::new(scaled.clone());
        let (mut imin, mut emin, mut emax) = (0, f64::INFINITY, 0.0f64);
        for (k, &e) in eig.eigenvalues.iter().enumerate() {
            if e < emin {
                emin = e;
                imin = k;
            }
            emax = emax.max(e);
        }
        if !(emin > 1e-10 * emax) {
            let v = eig.eigenvectors.column(imin);
            let names: Vec<&str> = (0..p)
                .filter(|&k| v[k].abs() > 0.2)
                .map(|k| problem.coords[k].path)
                .collect();
            warnings.push(format!(
                "degenerate: {} trade off (JᵀJ is singular to working precision, condition {:.1e}); \
                 only a combination is determined, so no standard errors are given",
                names.join(", "),
                emax / emin.max(1e-300)
            ));
        } else if let Some(inv) = scaled.try_inverse() {
            let s2 = if sigma.is_some() { 1.0 } else { reduced_chi2 };
            let mut corr = vec![vec![0.0; p]; p];
            for a in 0..p {
                let var_u = s2 * inv[(a, a)] / (scale[a] * scale[a]);
                let c = problem.coords[a];
                let se_u = sqrt(var_u.max(0.0));
                standard_errors[a] = Some(if c.log { c.value(u[a]) * se_u } else { se_u });
                for b in 0..p {
                    corr[a][b] = inv[(a, b)] / sqrt(inv[(a, a)] * inv[(b, b)]);
                }
            }
            for a in 0..p {
                for b in a + 1..p {
                    if corr[a][b].abs() > DEGENERATE_CORRELATION {
                        warnings.push(format!(
                            "degenerate: {} and {} are correlated ({:.4}); only a combination is \
                             well determined",
                            problem.coords[a].path, problem.coords[b].path, corr[a][b]
                        ));
                    }
                }
            }
            correlation = Some(corr);
        }
    }
    let params = problem
        .coords
        .iter()
        .enumerate()
        .map(|(k, c)| Fitted {
            path: c.path,
            unit: c.unit,
            value: c.value(u[k]),
            standard_error: standard_errors[k],
        })
        .collect();
    Ok(SceneFit {
        params,
        correlation,
        rms_error,
        reduced_chi2,
        dof,
        weighted: sigma.is_some(),
        warnings,
        scene: fitted_scene,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fitting_a_to_an_atlas_law_recovers_a_scene_that_made_the_law() {
        // Fitting A to the Bridges law never leaves the scene farther from it than it started.
        let f = fit_to_entry(
            &crate::Preset::Ice.scene(),
            crate::atlas::find("bridges1984").unwrap(),
            &["bulk.damping.time"],
            Accuracy::Fast,
        )
        .unwrap();
        assert_eq!(f.params.len(), 1);
        assert!(f.params[0].value > 0.0 && f.rms_error < 0.2, "{f:?}");
        // The fitted scene is at least as close to the law as the starting one.
        let start = crate::atlas::score(
            &Contact::new(&crate::Preset::Ice.scene()).unwrap(),
            Accuracy::Fast,
            crate::atlas::find("bridges1984").unwrap(),
            None,
        )
        .unwrap();
        let end = crate::atlas::score(
            &Contact::new(&f.scene).unwrap(),
            Accuracy::Fast,
            crate::atlas::find("bridges1984").unwrap(),
            None,
        )
        .unwrap();
        assert!(end <= start, "{end} > {start}");
        // A measured range is not a law to fit to.
        let range = crate::atlas::find("hill2015").unwrap();
        let scene = crate::Preset::Ice.scene();
        assert!(fit_to_entry(&scene, range, &["bulk.damping.time"], Accuracy::Fast).is_err());
    }

    #[test]
    fn a_header_with_units_as_rime_curve_writes_it_is_a_header() {
        let p = parse_points("g_n [m/s],eps_n\n0.01,0.3\n0.02,0.28\n").unwrap();
        assert_eq!(p.header.as_deref(), Some("g_n [m/s],eps_n"));
        assert!(parse_points("0.01 [m/s],0.3\n0.02,0.28\n").is_err());
    }

    #[test]
    fn a_header_is_accepted_only_when_it_is_recognisably_one() {
        let p = parse_points("g_n,eps_n\n0.01,0.5\n0.1,0.4\n").unwrap();
        assert_eq!(p.header.as_deref(), Some("g_n,eps_n"));
        assert_eq!(p.g, vec![0.01, 0.1]);
        // A bad first data line used to be taken silently as a header.
        let e = parse_points("0.01,x\n0.02,0.5\n0.1,0.4\n").unwrap_err();
        assert_eq!(e.line, 1);
        let e = parse_points("# c\n\n0.01,0.5\n0.1,1.5\n").unwrap_err();
        assert_eq!(e.line, 4);
        assert!(parse_points("0.01,0.5,0.1\n0.1,0.4\n").unwrap_err().line == 2);
        assert!(parse_points("0.01,0.5,0\n0.1,0.4,1\n").is_err());
        let s = parse_points("g eps sigma\n0.01 0.5 0.02\n0.1 0.4 0.03\n").unwrap();
        assert_eq!(s.sigma, Some(vec![0.02, 0.03]));
        assert_eq!(parse_points("0.01,0.5\n").unwrap_err().line, 0);
    }

    #[test]
    fn switched_off_effects_are_refused_and_degeneracy_is_reported() {
        let scene = Scene::default();
        let g = [1e-3, 1e-2, 1e-1, 1.0];
        let c = Contact::new(&scene).unwrap();
        let e: Vec<f64> = g
            .iter()
            .map(|&x| c.eps_n(x, Accuracy::Fast).unwrap())
            .collect();
        let err = fit(&scene, &["layer.viscosity"], &g, &e, None, Accuracy::Fast).unwrap_err();
        assert!(err.contains("off in this scene"), "{err}");
        // ε depends on A and Y only through A Y^(2/5) (docs/physics.md#decision-3): degenerate.
        let f = fit(
            &scene,
            &["bulk.damping.time", "bulk.youngs_modulus"],
            &g,
            &e,
            None,
            Accuracy::Fast,
        )
        .unwrap();
        assert!(f.warnings.iter().any(|w| w.contains("degenerate")), "{f:?}");
        assert!(fit(&scene, &["grains.density"; 2], &g, &e, None, Accuracy::Fast).is_err());
        assert!(fit(&scene, &["no.such"], &g, &e, None, Accuracy::Fast).is_err());
    }
}
