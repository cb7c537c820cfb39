//! Fitting scene parameters to measured (g, ε) points, with standard errors (feature `alloc`).
//!
//! * [`parse_points`] — reads two or three numeric columns (g, ε, optional σ of ε); a header
//!   line is accepted only when it is recognisably one (no cell is a number, every cell starts with
//!   a letter); any other bad line is an error naming its line number. Units in the header are read
//!   (`g [cm/s]`, `v_n (mm/s)`, `eps [%]`) and a unit it does not know is refused, naming the column;
//!   without one g is taken in m/s and [`Points::g_unit`] says so.
//! * [`fit`] — least squares over one or several numeric scene parameters (Levenberg–Marquardt on
//!   nalgebra, after a coarse scan of each parameter's range), weighted by 1/σ² when σ is given.
//!   At the optimum the Jacobian J gives the covariance: s²(JᵀJ)⁻¹ with s² = Σr²/(n − p) without σ,
//!   (JᵀWJ)⁻¹ with σ (σ taken as absolute). Parameters are fitted in ln p where their range is
//!   positive, so standard errors are p·σ_{ln p} (first order). Degenerate parameters (near-singular
//!   JᵀJ, or |correlation| > 0.99) are reported as warnings, never silently.
//!
//! A parameter whose effect is off in the scene (e.g. `layer.viscosity` without a layer) is refused:
//! the fit never switches an effect on.

use crate::error::Number;
use crate::format::sig;
use crate::numerics::accuracy::Accuracy;
use crate::numerics::lm::{LeastSquares, Schedule, damped_diagonal, minimise};
use crate::numerics::math::{exp, ln, sqrt};
use crate::scene::Scene;
use crate::scene::contact::Contact;
use crate::scene::params::{Kind, Value, parameter};
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
    /// The unit of g as the header gives it (`cm/s`; the values above are converted to m/s), or
    /// `None`: no header or no unit in it, g taken in m/s.
    pub g_unit: Option<String>,
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

/// The cells of a header line: split at commas, semicolons or tabs when it has any, else at spaces
/// with a bracketed unit kept with its name (`g [cm/s] eps`).
fn header_cells(line: &str) -> Vec<String> {
    if line.contains([',', ';', '\t']) {
        return line
            .split([',', ';', '\t'])
            .map(|c| c.trim().to_string())
            .filter(|c| !c.is_empty())
            .collect();
    }
    let mut cells: Vec<String> = Vec::new();
    for token in line.split(' ').filter(|t| !t.is_empty()) {
        match cells.last_mut() {
            Some(last) if token.starts_with(['[', '(']) => {
                last.push(' ');
                last.push_str(token);
            }
            _ => cells.push(token.to_string()),
        }
    }
    cells
}

/// The unit a header cell gives in brackets or parentheses at its end (`g [cm/s]`, `v_n (mm/s)`).
fn cell_unit(cell: &str) -> Option<&str> {
    let cell = cell.trim();
    let (open, close) = if cell.ends_with(']') {
        ('[', ']')
    } else if cell.ends_with(')') {
        ('(', ')')
    } else {
        return None;
    };
    let start = cell.rfind(open)?;
    Some(cell[start + 1..cell.len() - close.len_utf8()].trim())
}

/// Factor to m/s of the g column's unit, or an error naming the column.
fn speed_factor(cell: &str, unit: &str) -> core::result::Result<f64, String> {
    crate::scene::units::parse_quantity("g", &format!("1 {unit}"), "m/s").map_err(|_| {
        format!(
            "column '{cell}': unknown unit '{unit}' for the impact speed (m/s, cm/s, mm/s, um/s, \
             km/s)"
        )
    })
}

/// Factor of a dimensionless column's unit (ε, σ of ε): none, `1`, `-`, `%`.
fn ratio_factor(cell: &str, unit: &str) -> core::result::Result<f64, String> {
    match unit {
        "" | "1" | "-" | "–" => Ok(1.0),
        "%" => Ok(0.01),
        _ => Err(format!(
            "column '{cell}': unknown unit '{unit}' for a restitution coefficient \
             (dimensionless: none, 1, -, or %)"
        )),
    }
}

/// Parses (g, ε[, σ]) points: cells separated by commas, semicolons, tabs or spaces; `#` comments
/// and blank lines skipped. Units in a header are applied (g to m/s, `%` to fractions).
// Long by design: reads a data file line by line with a named error for every malformed field and
// unit.
pub fn parse_points(text: &str) -> core::result::Result<Points, ParseError> {
    let mut p = Points::default();
    let mut sigma: Vec<f64> = Vec::new();
    let mut columns: Option<usize> = None;
    let mut first = true;
    // Factors to SI of the columns g, ε, σ.
    let mut factors = [1.0; 3];
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
                for (k, cell) in header_cells(line).iter().take(3).enumerate() {
                    let Some(unit) = cell_unit(cell) else {
                        continue;
                    };
                    factors[k] = if k == 0 {
                        p.g_unit = Some(unit.to_string());
                        speed_factor(cell, unit)
                    } else {
                        ratio_factor(cell, unit)
                    }
                    .map_err(err)?;
                }
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
        let g = num(0, "g")? * factors[0];
        let e = num(1, "eps")? * factors[1];
        if g <= 0.0 {
            return Err(err(format!("g = {} must be > 0 [m/s]", Number(g))));
        }
        if !(0.0..=1.0).contains(&e) {
            return Err(err(format!("eps = {} must lie in [0, 1]", Number(e))));
        }
        if cells.len() == 3 {
            let s = num(2, "sigma")? * factors[2];
            if s <= 0.0 {
                return Err(err(format!("sigma = {} must be > 0", Number(s))));
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
    /// Degeneracies, parameters at the edge of their range, a misfit (runs test, χ²), and the like.
    pub warnings: Vec<String>,
    /// The scene with the fitted values.
    pub scene: Scene,
    /// ε − ε_model at each point, in the order given (unweighted).
    pub residuals: Vec<f64>,
    /// The runs test on the residuals' signs in order of g; `None` with fewer than two nonzero
    /// residuals.
    pub runs_test: Option<RunsTest>,
}

/// p below which [`runs_test`] reports a systematic misfit.
pub const RUNS_TEST_LEVEL: f64 = 0.01;

/// Reduced χ² range outside which a fit weighted by σ is reported as a misfit (> 10) or as having
/// overestimated uncertainties (< 0.1).
pub const REDUCED_CHI2_RANGE: [f64; 2] = [0.1, 10.0];

/// A two-sided Wald–Wolfowitz runs test on the signs of residuals.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct RunsTest {
    /// Runs of equal sign observed.
    pub runs: usize,
    /// Runs expected for randomly ordered signs: 1 + 2 n₊ n₋ / (n₊ + n₋).
    pub expected: f64,
    /// Positive and negative residuals (zeros are left out).
    pub positive: usize,
    /// Negative residuals.
    pub negative: usize,
    /// Two-sided p: 2 min(P(R ≤ r), P(R ≥ r)) under the exact distribution of the number of runs
    /// given n₊ and n₋ (capped at 1). With one sign only it is 2^(1−n), the chance that n fair
    /// signs all agree.
    pub p: f64,
}

fn ln_choose(n: usize, k: usize) -> f64 {
    if k > n {
        return f64::NEG_INFINITY;
    }
    let lg = |x: usize| libm::lgamma(x as f64 + 1.0);
    lg(n) - lg(k) - lg(n - k)
}

/// The runs test on the signs of `residuals` taken in the order given (zeros skipped); `None` with
/// fewer than two nonzero values.
pub fn runs_test(residuals: &[f64]) -> Option<RunsTest> {
    let signs: Vec<bool> = residuals
        .iter()
        .filter(|r| **r != 0.0 && r.is_finite())
        .map(|r| *r > 0.0)
        .collect();
    let n = signs.len();
    if n < 2 {
        return None;
    }
    let runs = 1 + signs.windows(2).filter(|w| w[0] != w[1]).count();
    let n1 = signs.iter().filter(|s| **s).count();
    let n2 = n - n1;
    let expected = 1.0 + 2.0 * n1 as f64 * n2 as f64 / n as f64;
    let p = if n1 == 0 || n2 == 0 {
        libm::pow(2.0, 1.0 - n as f64).min(1.0)
    } else {
        let total = ln_choose(n, n1);
        let prob = |r: usize| -> f64 {
            let k = r / 2;
            let ways = if r.is_multiple_of(2) {
                ln_choose(n1 - 1, k - 1) + ln_choose(n2 - 1, k - 1) + core::f64::consts::LN_2
            } else {
                let a = ln_choose(n1 - 1, k) + ln_choose(n2 - 1, k - 1);
                let b = ln_choose(n1 - 1, k - 1) + ln_choose(n2 - 1, k);
                let m = a.max(b);
                if m == f64::NEG_INFINITY {
                    m
                } else {
                    m + ln(exp(a - m) + exp(b - m))
                }
            };
            exp(ways - total)
        };
        let max_runs = 2 * n1.min(n2) + usize::from(n1 != n2);
        let low: f64 = (2..=runs).map(prob).sum();
        let high: f64 = (runs..=max_runs).map(prob).sum();
        (2.0 * low.min(high)).min(1.0)
    };
    Some(RunsTest {
        runs,
        expected,
        positive: n1,
        negative: n2,
        p,
    })
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

impl LeastSquares for Problem<'_> {
    type Point = Vec<f64>;
    type Normal = (DMatrix<f64>, DVector<f64>);

    fn normal(&self, u: &Vec<f64>) -> Option<Self::Normal> {
        let (j, r) = (self.jacobian(u)?, self.residuals(u)?);
        let jtj = j.transpose() * &j;
        let jtr = j.transpose() * r;
        Some((jtj, jtr))
    }

    fn damped_step(
        &self,
        u: &Vec<f64>,
        (jtj, jtr): &Self::Normal,
        lambda: f64,
    ) -> Option<Vec<f64>> {
        let mut m = jtj.clone();
        for k in 0..u.len() {
            m[(k, k)] = damped_diagonal(jtj[(k, k)], lambda);
        }
        let step = m.lu().solve(&(-jtr))?;
        Some(
            (0..u.len())
                .map(|k| self.coords[k].clamp(u[k] + step[k]))
                .collect(),
        )
    }

    fn cost(&self, u: &Vec<f64>) -> f64 {
        Problem::cost(self, u)
    }
}

/// The crate's one Levenberg–Marquardt loop ([`crate::numerics::lm`]) on the scene's coordinates.
fn levenberg_marquardt(problem: &Problem<'_>, u: &mut Vec<f64>, cost: &mut f64) {
    let schedule = Schedule {
        iterations: 200,
        tries: 30,
        relative_decrease: 1e-13,
    };
    let (best, best_cost) = minimise(problem, core::mem::take(u), *cost, schedule);
    *u = best;
    *cost = best_cost;
}

/// Samples on a law's measured speeds for [`fit_to_entry`].
pub const LAW_POINTS: usize = 40;

/// Fits `paths` of `scene` to a measured law of the data atlas ("fit this scene to that entry"):
/// [`LAW_POINTS`] log-spaced samples of the law over the speeds it was measured at (its ε clamped to
/// \[0, 1\]; the scene's reduced radius for a law that needs one). The standard errors then measure
/// the model's misfit to the law, not measurement noise.
pub fn fit_to_entry(
    scene: &Scene,
    entry: &crate::data::atlas::Entry,
    paths: &[&str],
    accuracy: Accuracy,
) -> core::result::Result<SceneFit, String> {
    if entry.kind != crate::data::atlas::Kind::Law {
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
    crate::numerics::grid::log_space(entry.valid_speed[0], entry.valid_speed[1], &mut g);
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
// Long by design: one Levenberg–Marquardt loop whose steps share the Jacobian, the damping and the
// bounds; the steps are commented in order.
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
    // ε − ε_model (r is (ε_model − ε)/σ), and their signs in order of g for the runs test.
    let residuals: Vec<f64> = r
        .iter()
        .enumerate()
        .map(|(i, x)| -x * sigma.map_or(1.0, |s| s[i]))
        .collect();
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| g[a].total_cmp(&g[b]));
    let in_order: Vec<f64> = order.iter().map(|&i| residuals[i]).collect();
    let runs = runs_test(&in_order);
    if let Some(t) = runs.filter(|t| t.p < RUNS_TEST_LEVEL) {
        warnings.push(format!(
            "systematic misfit: in order of g the residuals' signs form {} runs where {} are \
             expected for random scatter (two-sided runs test p = {} < {RUNS_TEST_LEVEL}); the \
             model does not follow these points and the standard errors understate the uncertainty",
            t.runs,
            sig(t.expected, 3),
            sig(t.p, 2)
        ));
    }
    if sigma.is_some() {
        let [lo, hi] = REDUCED_CHI2_RANGE;
        if reduced_chi2 > hi {
            warnings.push(format!(
                "misfit: reduced χ² = {} > {hi}: the model misses the points by far more than \
                 their uncertainties (or the sigma column underestimates them)",
                sig(reduced_chi2, 3)
            ));
        } else if reduced_chi2 < lo {
            warnings.push(format!(
                "reduced χ² = {} < {lo}: the points scatter far less than the sigma column says; \
                 the uncertainties look overestimated and the standard errors with them",
                sig(reduced_chi2, 3)
            ));
        }
    }
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
        residuals,
        runs_test: runs,
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
            crate::data::atlas::find("bridges1984").unwrap(),
            &["bulk.damping.time"],
            Accuracy::Fast,
        )
        .unwrap();
        assert_eq!(f.params.len(), 1);
        assert!(f.params[0].value > 0.0 && f.rms_error < 0.2, "{f:?}");
        // The fitted scene is at least as close to the law as the starting one.
        let start = crate::data::atlas::score(
            &Contact::new(&crate::Preset::Ice.scene()).unwrap(),
            Accuracy::Fast,
            crate::data::atlas::find("bridges1984").unwrap(),
            None,
        )
        .unwrap();
        let end = crate::data::atlas::score(
            &Contact::new(&f.scene).unwrap(),
            Accuracy::Fast,
            crate::data::atlas::find("bridges1984").unwrap(),
            None,
        )
        .unwrap();
        assert!(end <= start, "{end} > {start}");
        // A measured range is not a law to fit to.
        let range = crate::data::atlas::find("hill2015").unwrap();
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
    fn fit_reads_cm_per_s_from_the_header_issue_22() {
        // The same measurements in cm/s, mm/s and m/s: one set of points in m/s.
        let si = parse_points("g [m/s],eps\n0.01,0.3\n0.02,0.28\n").unwrap();
        assert_eq!(si.g, vec![0.01, 0.02]);
        assert_eq!(si.g_unit.as_deref(), Some("m/s"));
        for text in [
            "g [cm/s],eps\n1,0.3\n2,0.28\n",
            "g (cm/s);eps\n1;0.3\n2;0.28\n",
            "g [cm/s] eps\n1 0.3\n2 0.28\n",
            "v_n (mm/s)\teps_n\n10\t0.3\n20\t0.28\n",
            "v_n [µm/s],eps_n [%]\n1e4,30\n2e4,28\n",
        ] {
            let p = parse_points(text).unwrap();
            for (a, b) in p.g.iter().zip(&si.g) {
                assert!((a - b).abs() <= 1e-15 * b, "{text}: {:?}", p.g);
            }
            for (a, b) in p.eps.iter().zip(&si.eps) {
                assert!((a - b).abs() <= 1e-15, "{text}: {:?}", p.eps);
            }
            assert!(p.g_unit.is_some(), "{text}");
        }
        // σ of ε in per cent.
        let p = parse_points("g [cm/s],eps,sigma [%]\n1,0.3,2\n2,0.28,3\n").unwrap();
        assert_eq!(p.sigma, Some(vec![0.02, 0.03]));
        // No unit: taken in m/s, and the points say so.
        let p = parse_points("g,eps\n0.01,0.3\n0.02,0.28\n").unwrap();
        assert_eq!((p.g.clone(), p.g_unit), (vec![0.01, 0.02], None));
        assert_eq!(parse_points("0.01,0.3\n0.02,0.28\n").unwrap().g_unit, None);
    }

    #[test]
    fn fit_refuses_an_unknown_unit_naming_the_column_issue_22() {
        for (text, column) in [
            (
                "g [furlong/fortnight],eps\n1,0.3\n2,0.28\n",
                "g [furlong/fortnight]",
            ),
            ("g [cm],eps\n1,0.3\n2,0.28\n", "g [cm]"),
            ("g [m/s],eps [m]\n1,0.3\n2,0.28\n", "eps [m]"),
            (
                "g [m/s],eps,sigma (cm/s)\n1,0.3,0.1\n2,0.28,0.1\n",
                "sigma (cm/s)",
            ),
        ] {
            let e = parse_points(text).unwrap_err();
            assert_eq!(e.line, 1, "{text}");
            assert!(e.reason.contains(&format!("column '{column}'")), "{e}");
            assert!(e.reason.contains("unknown unit"), "{e}");
        }
    }

    #[test]
    fn runs_test_matches_the_enumerated_distribution_issue_22() {
        // Every arrangement of n1 pluses and n2 minuses, counted: the exact null distribution of
        // the number of runs, independent of the closed form the test uses.
        for n1 in 1..=7usize {
            for n2 in 1..=7usize {
                let n = n1 + n2;
                let mut count = vec![0u64; n + 2];
                let mut example: Vec<Option<u32>> = vec![None; n + 2];
                for mask in 0u32..(1 << n) {
                    if mask.count_ones() as usize != n1 {
                        continue;
                    }
                    let runs = 1
                        + (0..n - 1)
                            .filter(|&i| ((mask >> i) & 1) != ((mask >> (i + 1)) & 1))
                            .count();
                    count[runs] += 1;
                    example[runs].get_or_insert(mask);
                }
                let total: u64 = count.iter().sum();
                for r in 0..n + 2 {
                    let Some(mask) = example[r] else { continue };
                    let low: u64 = count[..=r].iter().sum();
                    let high: u64 = count[r..].iter().sum();
                    let expected = (2.0 * low.min(high) as f64 / total as f64).min(1.0);
                    let signs: Vec<f64> = (0..n)
                        .map(|i| if (mask >> i) & 1 == 1 { 0.5 } else { -0.25 })
                        .collect();
                    let t = runs_test(&signs).unwrap();
                    assert_eq!((t.runs, t.positive, t.negative), (r, n1, n2));
                    assert!(
                        (t.p - expected).abs() < 1e-12,
                        "{n1}+{n2}, r = {r}: {} vs {expected}",
                        t.p
                    );
                    let mean = 1.0 + 2.0 * (n1 * n2) as f64 / n as f64;
                    assert!((t.expected - mean).abs() < 1e-12);
                }
            }
        }
        // One sign only: the chance that n fair signs agree, 2^(1−n).
        assert_eq!(runs_test(&[1.0; 8]).unwrap().p, 2.0f64.powi(-7));
        assert!(runs_test(&[1.0, 0.0]).is_none());
    }

    fn model_points(a: f64, g: &[f64]) -> Vec<f64> {
        let mut scene = Scene::default();
        scene.bulk.damping = crate::scene::Damping::Time(a);
        let c = Contact::new(&scene).unwrap();
        g.iter()
            .map(|&x| c.eps_n(x, Accuracy::Fast).unwrap())
            .collect()
    }

    #[test]
    fn fit_warns_on_systematic_residuals_and_bad_chi2_issue_22() {
        let mut g = vec![0.0; 16];
        crate::numerics::grid::log_space(1e-4, 1.0, &mut g);
        let model = model_points(1e-4, &g);
        let fit_a = |eps: &[f64], sigma: Option<&[f64]>| {
            fit(
                &Scene::default(),
                &["bulk.damping.time"],
                &g,
                eps,
                sigma,
                Accuracy::Fast,
            )
            .unwrap()
        };
        // A smooth bow across the speeds: few long runs of one sign.
        let bowed: Vec<f64> = model
            .iter()
            .enumerate()
            .map(|(i, e)| e * (1.0 + 0.3 * ((i as f64 - 7.5) / 7.5).powi(2)))
            .collect();
        let f = fit_a(&bowed, None);
        let t = f.runs_test.unwrap();
        assert!(t.p < RUNS_TEST_LEVEL, "{t:?}");
        assert!(
            f.warnings.iter().any(|w| w.contains("systematic misfit")),
            "{f:?}"
        );
        assert_eq!(f.residuals.len(), g.len());
        // The residuals are ε − ε_model: they add back to the points.
        let fitted = model_points(f.params[0].value, &g);
        for ((r, e), m) in f.residuals.iter().zip(&bowed).zip(&fitted) {
            assert!((r - (e - m)).abs() < 1e-12, "{r} vs {}", e - m);
        }
        // Scatter without a trend (a sign pattern with 10 runs in 16, 9 expected): no warning.
        let pattern = [
            1., -1., -1., 1., 1., -1., 1., 1., 1., -1., -1., 1., -1., -1., 1., -1.,
        ];
        let scattered: Vec<f64> = model
            .iter()
            .zip(pattern)
            .map(|(e, s)| e + 0.01 * s)
            .collect();
        let f = fit_a(&scattered, None);
        assert!(f.runs_test.unwrap().p > 0.1, "{:?}", f.runs_test);
        assert!(f.warnings.is_empty(), "{:?}", f.warnings);
        // With σ: reduced χ² = Σ(r/σ)²/(n−1) ≈ (0.01/σ)² — 100 for σ = 1e-3, 1e-2 for σ = 0.1.
        for (s, what) in [(1e-3, "> 10"), (0.1, "< 0.1")] {
            let sigma = vec![s; g.len()];
            let f = fit_a(&scattered, Some(&sigma));
            assert!(
                f.warnings.iter().any(|w| w.contains(what)),
                "σ = {s}: {:?}",
                f.warnings
            );
        }
        let f = fit_a(&scattered, Some(&vec![0.01; g.len()]));
        assert!(f.warnings.is_empty(), "{:?}", f.warnings);
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
