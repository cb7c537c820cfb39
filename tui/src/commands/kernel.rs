//! `rime kernel`: the sticking kernel v_stick(a_i, a_j, T) of a scene's material for dust codes
//! (rime_core::kernel, issue 39), as JSON, CSV or a table, with its provenance; `--svg` draws
//! v_stick(a, a) per temperature with the measured point.

use crate::args::{Common, Format};
use crate::output::{human_table, num};
use crate::scene_io::{CliError, CliResult, err, write_atomic};
use rime_core::error::Number;
use rime_core::explorer::format::qty;
use rime_core::kernel::{
    self, ARule, GAMMA_ENTRY, Kernel, KernelOptions, MeasuredSpeed, StickStatus, TemperatureRule,
};
use rime_core::stick::Convention;
use serde_json::{Value, json};
use std::path::PathBuf;

/// Most radii of a range or list.
pub const MAX_RADII: usize = 1000;
/// Most records one command prints (temperatures × radii²).
pub const MAX_RECORDS: usize = 1_000_000;
/// Radii of the figure's curves.
const FIGURE_POINTS: usize = 121;
/// What rime does not model, said in every output.
pub const NOT_MODELLED: [&str; 5] = [
    "porous aggregates (compact spheres only)",
    "fragmentation",
    "erosion",
    "mass transfer",
    "grains of two different materials",
];

/// Arguments of `rime kernel`.
#[derive(Debug, Clone)]
pub struct Args {
    /// Radii \[m\].
    pub radii: Vec<f64>,
    /// The range the radii were spaced over, when given as `R1..R2` (for the figure).
    pub range: Option<(f64, f64)>,
    /// Temperatures \[K\].
    pub temperatures: Vec<f64>,
    /// The rule for A, γ reading, temperature rule (accuracy comes from the common options).
    pub options: KernelOptions,
    /// `--svg FILE`: the figure.
    pub svg: Option<PathBuf>,
}

fn radius(flag: &str, text: &str) -> CliResult<f64> {
    let r = crate::args::quantity(flag, text, "m")?;
    if !(1e-9..=1e4).contains(&r) {
        return err(format!("{flag}: {} must lie in [1e-9, 1e4] m", Number(r)));
    }
    Ok(r)
}

/// `n` radii equal in log from `lo` to `hi`, both included.
fn log_spaced(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    let mut out = vec![0.0; n];
    rime_core::sweep::log_space(lo, hi, &mut out);
    out
}

/// The radii, and the range they were spaced over (`R1..R2`).
type Radii = (Vec<f64>, Option<(f64, f64)>);

/// Reads `--radii R1..R2 [--points N]` or `--radii LIST`.
fn parse_radii(get: &dyn Fn(&str) -> Option<String>) -> CliResult<Radii> {
    let text = get("--radii").ok_or_else(|| {
        CliError::input(
            "--radii: required: a range R1..R2 (with --points) or a list, units allowed (1um..1cm)",
        )
    })?;
    if let Some((lo, hi)) = text.split_once("..") {
        let (lo, hi) = (radius("--radii", lo)?, radius("--radii", hi)?);
        // Both are finite (checked by `radius`).
        if hi <= lo {
            return err(format!(
                "--radii: the range's end {} must exceed its start {}",
                Number(hi),
                Number(lo)
            ));
        }
        let points = match get("--points") {
            None => 20,
            Some(p) => match p.trim().parse::<usize>() {
                Ok(n) if (2..=MAX_RADII).contains(&n) => n,
                _ => {
                    return err(format!(
                        "--points: expected a whole number from 2 to {MAX_RADII}, got {p:?}"
                    ));
                }
            },
        };
        Ok((log_spaced(lo, hi, points), Some((lo, hi))))
    } else {
        if get("--points").is_some() {
            return err("--points: only with a range of --radii (R1..R2)");
        }
        let radii: Vec<f64> = text
            .split(',')
            .map(|s| radius("--radii", s))
            .collect::<CliResult<_>>()?;
        if radii.len() > MAX_RADII {
            return err(format!("--radii: at most {MAX_RADII} radii"));
        }
        Ok((radii, None))
    }
}

/// Reads `--a-rule` and, for `fit-measured`, `--fit-radius`, `--fit-temperature`.
fn parse_a_rule(get: &dyn Fn(&str) -> Option<String>) -> CliResult<ARule> {
    let rule = get("--a-rule");
    let fit = matches!(rule.as_deref(), Some("fit-measured" | "fit_measured"));
    if !fit {
        for flag in ["--fit-radius", "--fit-temperature"] {
            if get(flag).is_some() {
                return err(format!("{flag}: only with --a-rule fit-measured"));
            }
        }
    }
    Ok(match rule.as_deref() {
        None | Some("given") => ARule::Given,
        Some("keep-epsilon" | "keep_epsilon") => ARule::KeepEpsilon,
        Some("fit-measured" | "fit_measured") => {
            let mut m = MeasuredSpeed::GUNDLACH_2015;
            if let Some(r) = get("--fit-radius") {
                m.radius = radius("--fit-radius", &r)?;
            }
            if let Some(t) = get("--fit-temperature") {
                m.temperature = crate::args::quantity("--fit-temperature", &t, "K")?;
                if !(1.0..=1000.0).contains(&m.temperature) {
                    return err(format!(
                        "--fit-temperature: {} must lie in [1, 1000] K",
                        Number(m.temperature)
                    ));
                }
            }
            ARule::FitMeasured(m)
        }
        Some(o) => {
            return err(format!(
                "--a-rule {o}: expected given, keep-epsilon or fit-measured"
            ));
        }
    })
}

/// Parses the flags of `rime kernel` (the accuracy is the common `--accuracy`).
pub fn parse(get: &dyn Fn(&str) -> Option<String>) -> CliResult<Args> {
    let (radii, range) = parse_radii(get)?;
    let temperatures = crate::commands::stick::list(
        "--temperatures",
        &get("--temperatures").unwrap_or_else(|| "150,180,200".into()),
        1.0,
        1000.0,
        "K",
    )?;
    if temperatures
        .len()
        .saturating_mul(radii.len())
        .saturating_mul(radii.len())
        > MAX_RECORDS
    {
        return err(format!(
            "--temperatures: at most {MAX_RECORDS} records (temperatures × radii²); use fewer \
             --points or temperatures"
        ));
    }
    let convention = match get("--gamma").as_deref() {
        None | Some("surface") => Convention::SurfaceEnergy,
        Some("adhesion") => Convention::WorkOfAdhesion,
        Some(o) => return err(format!("--gamma {o}: expected surface or adhesion")),
    };
    let temperature_rule = match get("--temperature-rule").as_deref() {
        None | Some("hold") => TemperatureRule::Hold,
        Some("refuse") => TemperatureRule::Refuse,
        Some(o) => return err(format!("--temperature-rule {o}: expected hold or refuse")),
    };
    let options = KernelOptions {
        a_rule: parse_a_rule(get)?,
        convention,
        temperature_rule,
        ..Default::default()
    };
    for &t in &temperatures {
        kernel::gamma(t, &options).map_err(flagged)?;
    }
    if let ARule::FitMeasured(m) = options.a_rule {
        kernel::gamma(m.temperature, &options).map_err(|e| {
            let text = e.to_string();
            let rest = text.strip_prefix("temperatures:").unwrap_or(&text);
            CliError::input(format!("--fit-temperature:{rest}"))
        })?;
    }
    let svg = get("--svg").map(PathBuf::from);
    if svg.is_some() && temperatures.len() > kernel::figure::MAX_CURVES {
        return err(format!(
            "--svg: the figure draws at most {} temperatures",
            kernel::figure::MAX_CURVES
        ));
    }
    Ok(Args {
        radii,
        range,
        temperatures,
        options,
        svg,
    })
}

/// A core error of the kernel, named by the flag it came from (the core names its field:
/// `temperatures: …`, `fit.radius: …`).
fn flagged(e: rime_core::Error) -> CliError {
    let text = e.to_string();
    const FLAGS: [(&str, &str); 6] = [
        ("fit.radius", "--fit-radius"),
        ("fit.temperature", "--fit-temperature"),
        ("fit.speed", "--a-rule fit-measured"),
        ("fit", "--a-rule fit-measured"),
        ("temperatures", "--temperatures"),
        ("radii", "--radii"),
    ];
    for (field, flag) in FLAGS {
        if let Some(rest) = text.strip_prefix(field).and_then(|r| r.strip_prefix(':')) {
            return CliError::input(format!("{flag}:{rest}"));
        }
    }
    CliError::from(e)
}

/// The provenance every format carries.
fn provenance(k: &Kernel, common: &Common) -> Value {
    let entry = rime_core::atlas::find(GAMMA_ENTRY);
    let fit = k.fit.map(|f| {
        json!({
            "entry": f.reference.entry,
            "radius": f.reference.radius,
            "temperature": f.reference.temperature,
            "measured_v_stick": f.reference.speed,
            "damping_time": f.damping_time,
            "achieved_v_stick": f.achieved,
            "v_elastic": f.v_elastic,
        })
    });
    let scene = &common.scene;
    json!({
        "rime_version": env!("CARGO_PKG_VERSION"),
        "model": "Hertzsch (2002): viscoelastic Eq. (4), soft layer Eq. (8)–(10), adhesion Eq. (15)/(17); compact spheres of one material",
        "gamma_source": {
            "entry": GAMMA_ENTRY,
            "citation": "Musiolik, G., Wurm, G. (2019), Astrophys. J. 873, 58",
            "measured_temperatures": entry.map(|e| e.temperature),
            "outside": match k.temperature_rule {
                TemperatureRule::Hold => "held at the end values (0.0029 J/m² below 175 K, 0.19 J/m² above 200 K)",
                TemperatureRule::Refuse => "refused",
            },
            "temperature_rule": k.temperature_rule.name(),
            "convention": k.convention.name(),
        },
        "a_rule": k.a_rule.name(),
        "a_rule_meaning": match k.a_rule {
            ARule::Given => "the scene's A for every pair",
            ARule::KeepEpsilon => "A_ij = A (R_eff/R_eff,ref)^(-1/5) (m_eff/m_eff,ref)^(2/5), reference: the scene's pair; every pair keeps its ε_N(g)",
            ARule::FitMeasured(_) => "one A for every pair, fitted so that the reference pair's v_stick equals the measured speed",
        },
        "damping_time": k.damping_time,
        "reference_radii": [scene.grains.radius_1, scene.grains.radius_2],
        "fit": fit,
        "density": scene.grains.density,
        "youngs_modulus": scene.bulk.youngs_modulus,
        "poisson_ratio": scene.bulk.poisson_ratio,
        "layer": scene.layer.is_some_and(|l| l.thickness > 0.0),
        "accuracy": common.accuracy.name(),
        "method": k.method.name(),
        "not_modelled": NOT_MODELLED,
        "units": {"radius_1": "m", "radius_2": "m", "temperature": "K", "v_stick": "m/s", "damping_time": "s"},
    })
}

/// The provenance as `# ` lines (CSV) or plain lines (table).
fn provenance_lines(k: &Kernel, prefix: &str) -> String {
    let mut s = format!(
        "{prefix}rime {} kernel: v_stick(a_i, a_j, T), the first rebounding speed of the full model \
         (Hertzsch 2002); empty/— where the pair sticks at every speed up to 1e6 m/s\n",
        env!("CARGO_PKG_VERSION")
    );
    s.push_str(&format!(
        "{prefix}γ(T): {GAMMA_ENTRY} (Musiolik & Wurm 2019), measured 175–200 K; outside: {} ({}); \
         convention {}\n",
        k.temperature_rule.name(),
        match k.temperature_rule {
            TemperatureRule::Hold => "end values held",
            TemperatureRule::Refuse => "refused",
        },
        k.convention.name()
    ));
    let a = match k.fit {
        Some(f) => format!(
            "fit_measured: A = {} for every pair, fitted to {} at two {} grains, {} ({}; the \
             model gives {})",
            qty(f.damping_time, "s"),
            qty(f.reference.speed, "m/s"),
            qty(f.reference.radius, "m"),
            qty(f.reference.temperature, "K"),
            f.reference.entry,
            qty(f.achieved, "m/s")
        ),
        None => match k.a_rule {
            ARule::KeepEpsilon => format!(
                "keep_epsilon: A = {} for the scene's pair, scaled as R_eff^(-1/5) m_eff^(2/5)",
                qty(k.damping_time, "s")
            ),
            _ => format!("given: A = {} for every pair", qty(k.damping_time, "s")),
        },
    };
    s.push_str(&format!("{prefix}A rule: {a}\n"));
    s.push_str(&format!(
        "{prefix}not modelled: {}\n",
        NOT_MODELLED.join(", ")
    ));
    s
}

/// Runs `rime kernel`.
pub fn run(common: &Common, args: &Args) -> CliResult<String> {
    let options = KernelOptions {
        accuracy: common.accuracy,
        ..args.options
    };
    let k = kernel::table_parallel(
        &common.scene,
        &args.radii,
        &args.temperatures,
        &options,
        crate::parallel::threads(),
    )
    .map_err(flagged)?;
    let mut note = String::new();
    if let Some(path) = &args.svg {
        let (lo, hi) = args.range.unwrap_or_else(|| {
            let lo = args.radii.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = args.radii.iter().copied().fold(0.0, f64::max);
            (lo, hi)
        });
        let radii = if hi > lo {
            log_spaced(lo, hi, FIGURE_POINTS)
        } else {
            vec![lo]
        };
        // The diagonal only: one radius per table.
        let mut diagonal = k.clone();
        diagonal.radii = radii.clone();
        let n = radii.len();
        let nt = k.gammas.len();
        diagonal.v_stick = vec![f64::INFINITY; nt * n * n];
        diagonal.status = vec![StickStatus::AlwaysSticks; nt * n * n];
        for (i, &r) in radii.iter().enumerate() {
            let one = kernel::table(&common.scene, &[r], &args.temperatures, &options)
                .map_err(flagged)?;
            for t in 0..nt {
                let idx = diagonal.index(t, i, i);
                diagonal.v_stick[idx] = one.v_stick[t];
                diagonal.status[idx] = one.status[t];
            }
        }
        let figure = kernel::diagonal_figure(&diagonal).map_err(flagged)?;
        let svg = rime_core::figure::render_svg(&figure, 1000, 680)?;
        write_atomic(path, svg.as_bytes())?;
        note = format!("wrote {} ({})\n", path.display(), figure.title);
    }
    let n = k.n();
    let temps = k.temperatures();
    Ok(match common.format {
        Format::Json => {
            let mut records = Vec::with_capacity(k.v_stick.len());
            for (t, g) in k.gammas.iter().enumerate() {
                for i in 0..n {
                    for j in 0..n {
                        let idx = k.index(t, i, j);
                        records.push(json!({
                            "radius_1": k.radii[i],
                            "radius_2": k.radii[j],
                            "temperature": temps[t],
                            "v_stick": k.get(t, i, j),
                            "status": k.status[idx].name(),
                            "gamma_range": g.range.name(),
                        }));
                    }
                }
            }
            let temperatures: Vec<Value> = k
                .gammas
                .iter()
                .map(|g| {
                    json!({
                        "temperature": g.temperature,
                        "gamma_source": g.gamma_source,
                        "gamma": g.gamma,
                        "gamma_range": g.range.name(),
                    })
                })
                .collect();
            let v = json!({
                "provenance": provenance(&k, common),
                "temperatures": temperatures,
                "records": records,
            });
            serde_json::to_string_pretty(&v).map_err(|e| CliError::input(e.to_string()))? + "\n"
        }
        Format::Csv => {
            let mut s = provenance_lines(&k, "# ");
            s.push_str(
                "radius_1 [m],radius_2 [m],temperature [K],v_stick [m/s],status,gamma_range\n",
            );
            for (t, g) in k.gammas.iter().enumerate() {
                for i in 0..n {
                    for j in 0..n {
                        let idx = k.index(t, i, j);
                        s.push_str(&format!(
                            "{},{},{},{},{},{}\n",
                            num(k.radii[i]),
                            num(k.radii[j]),
                            num(temps[t]),
                            k.get(t, i, j).map(num).unwrap_or_default(),
                            k.status[idx].name(),
                            g.range.name()
                        ));
                    }
                }
            }
            s + &note
        }
        Format::Table => {
            // Symmetric in (i, j): each unordered pair once.
            let mut rows = Vec::new();
            for (t, g) in k.gammas.iter().enumerate() {
                for i in 0..n {
                    for j in i..n {
                        let idx = k.index(t, i, j);
                        rows.push(vec![
                            num(k.radii[i]),
                            num(k.radii[j]),
                            num(temps[t]),
                            k.get(t, i, j).map(num).unwrap_or_else(|| "—".into()),
                            match k.status[idx] {
                                StickStatus::Threshold => "sticks below".into(),
                                StickStatus::AlwaysSticks => "sticks always".into(),
                            },
                            g.range.name().replace('_', " "),
                        ]);
                    }
                }
            }
            let mut s = human_table(
                &[
                    "radius_1 [m]",
                    "radius_2 [m]",
                    "temperature [K]",
                    "v_stick [m/s]",
                    "status",
                    "γ(T)",
                ],
                &rows,
            );
            s.push_str(
                "each unordered pair once (v_stick is symmetric); all pairs: --format csv|json\n",
            );
            // Wrapped at 80 columns (the CSV keeps one line each).
            for line in provenance_lines(&k, "").lines() {
                s.push_str(&crate::spec::wrap("", line, 2));
                s.push('\n');
            }
            s + &note
        }
    })
}
