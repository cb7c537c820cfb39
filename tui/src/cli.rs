//! The non-interactive subcommands (docs/cli.md): machine-readable output for scripts.

use crate::scene_io::{CliError, CliResult, apply_set, err, load_scene, preset, scene_json};
use rime_core::{Accuracy, Contact, Scene};
use std::io::IsTerminal;
use std::path::PathBuf;

/// Output format of a subcommand.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// JSON (default when stdout is not a terminal).
    Json,
    /// CSV with one header line.
    Csv,
    /// An aligned text table (default on a terminal).
    Table,
}

/// Options shared by every subcommand.
#[derive(Debug, Clone)]
pub struct Common {
    /// The scene after `--scene`/`--preset` and every `--set`.
    pub scene: Scene,
    /// Accuracy level.
    pub accuracy: Accuracy,
    /// Output format.
    pub format: Format,
}

/// A parsed command line.
#[derive(Debug, Clone)]
pub enum Command {
    /// The interactive explorer (no subcommand).
    Explore(Common),
    /// `rime eps --g LIST`.
    Eps(Common, Vec<f64>),
    /// `rime eps --g-file FILE` (streamed through the batch path).
    EpsFile(Common, PathBuf),
    /// `rime curve --from G --to G --points N`.
    Curve(Common, f64, f64, usize),
    /// `rime tangential --gn LIST --gt LIST` (every combination, g_n outer).
    Tangential(Common, Vec<f64>, Vec<f64>),
    /// `rime map --max G --n N`.
    Map(Common, f64, usize),
    /// `rime tidal [--planet-mass M] [--distance D] [--radius R] [--density RHO] [--surface-energy G]`.
    Tidal(Common, rime_core::tidal::TidalInput),
    /// `rime scene [--preset NAME] [--out FILE]`.
    Scene(Common, Option<PathBuf>),
    /// `rime export --from G --to G --points N --out DIR [--runtime-params true]`.
    Export(Common, f64, f64, usize, PathBuf, bool),
    /// `rime fit (--data FILE.csv | --law ID) [--param A,B]`.
    Fit(Common, crate::commands::fit::Args),
    /// `rime data [--law ID --g LIST [--radius R]]`.
    Data(Common, crate::commands::data::Args),
    /// `rime stick --radius LIST [--temperature LIST] [--gamma surface|adhesion] [--out DIR]`.
    Stick(Common, crate::commands::stick::Args),
    /// `rime collision --g G [--gt G] [--points N]`.
    Collision(Common, crate::commands::collision::Args),
    /// `rime figures --out DIR`.
    Figures(Common, PathBuf),
    /// `rime compare --models LIST --g LIST | --list | --bench`.
    Compare(Common, crate::commands::compare::Args),
    /// `rime bench [--out DIR] [--quick]`.
    Bench(PathBuf, bool),
    /// `rime help` or `--help`.
    Help,
    /// `rime --version`.
    Version,
}

/// Usage text.
pub const USAGE: &str = "\
rime — slow collisions of icy grains (Hertzsch 2002)

USAGE:
  rime [OPTIONS]                                 start the terminal explorer
  rime eps --g LIST [OPTIONS]                    ε_N at impact speeds (m/s, comma-separated)
  rime eps --g-file FILE [OPTIONS]               ε_N, status for a file of speeds (one per line,
                                                 # comments), streamed through the batch path
  rime curve --from G --to G --points N          ε_N on N log-spaced speeds, both ends included
  rime tangential --gn LIST --gt LIST            ε_T for every (g_N, g_T) combination
  rime map --max G --n N                         stick-map classes on an N×N grid from 0 to G
  rime tidal [--planet-mass KG] [--distance M] [--radius M] [--density KG/M3] [--surface-energy J/M2]
  rime scene [--preset NAME] [--out FILE]        print (or atomically write) the scene JSON
  rime export --out DIR [--from G --to G --points N] [--runtime-params true]
                                                 ε_N table (CSV, JSON), fitted Eq. (27) and power
                                                 laws; C99 + no_std Rust ε_N, ε_T and collision
                                                 kinematics (fast: 1e-6, precise: 1e-10 at every
                                                 speed), a REBOUND collision handler + Python recipe;
                                                 --runtime-params: A, radii, layer, γ as arguments
  rime fit (--data FILE.csv | --law ID [--radius R]) [--param P1,P2]
                                                 fit parameters (default bulk.damping.time) to
                                                 measured (g [m/s], ε[, σ]) points or an atlas law,
                                                 with standard errors and correlations
  rime data [--law ID --g LIST [--radius R]]     the atlas of measured ice, or one law evaluated
  rime stick --radius LIST [--temperature LIST] [--gamma surface|adhesion] [--out DIR]
                                                 sticking thresholds v_stick(r, T), γ(T) of Musiolik
                                                 & Wurm 2019; --out writes a table and a C function
  rime collision --g G [--gt G] [--points N]     one collision: ξ(t), ξ'(t), F(t), phases, energy
                                                 ledger; --gt adds the tangential side
  rime figures [--out DIR]                       the paper's Figs. 2–4 from the model, SVG + PNG
  rime compare --models LIST --g LIST            ε_N of several models side by side and their
                                                 characteristic speeds (g_cr, v_yield, …);
                                                 --list names every model, --bench its cost
  rime bench [--out DIR] [--quick true]          speed/accuracy of every model and level (writes
                                                 DIR/bench.json and DIR/work-precision.svg)

OPTIONS:
  --scene FILE.json        scene file (default: the `ice` preset)
  --preset NAME            start from a preset: ice, ice-frost, ice-sticky, ice-paper-viscosities
  --set PATH=VALUE         override a parameter, repeatable (e.g. --set layer.viscosity=2000,
                           --set layer.thickness=\"2 um\", --set adhesion=off)
  --accuracy LEVEL         fast | balanced | precise | a relative tolerance like 1e-8
  --format FORMAT          json | csv | table (table on a terminal, json otherwise)
  -h, --help               this text
  -V, --version            version

Errors are one line naming the field, with exit code 2.";

pub(crate) fn number(flag: &str, text: &str) -> CliResult<f64> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(v) => err(format!("{flag}: {v} is not a finite number")),
        Err(_) => err(format!("{flag}: '{text}' is not a number")),
    }
}

pub(crate) fn speed(flag: &str, text: &str, allow_zero: bool) -> CliResult<f64> {
    let v = number(flag, text)?;
    let ok = if allow_zero { v >= 0.0 } else { v > 0.0 };
    if !ok || v > 1e6 {
        let range = if allow_zero { "[0, 1e6]" } else { "(0, 1e6]" };
        return err(format!("{flag}: speed {v} must lie in {range} m/s"));
    }
    Ok(v)
}

pub(crate) fn speed_list(flag: &str, text: &str, allow_zero: bool) -> CliResult<Vec<f64>> {
    let items: Vec<&str> = text.split(',').map(str::trim).collect();
    if items.iter().all(|s| s.is_empty()) {
        return err(format!("{flag}: empty list"));
    }
    if items.len() > 1_000_000 {
        return err(format!("{flag}: at most 1000000 values"));
    }
    items.iter().map(|s| speed(flag, s, allow_zero)).collect()
}

fn flag_bool(flag: &str, value: Option<&str>) -> CliResult<bool> {
    match value {
        None | Some("false") => Ok(false),
        Some("true") => Ok(true),
        Some(other) => err(format!("{flag} {other}: expected true or false")),
    }
}

fn count(flag: &str, text: &str, min: usize, max: usize) -> CliResult<usize> {
    match text.trim().parse::<usize>() {
        Ok(n) if (min..=max).contains(&n) => Ok(n),
        _ => err(format!(
            "{flag}: '{text}' must be a whole number in [{min}, {max}]"
        )),
    }
}

/// Parses the command line (without the program name).
pub fn parse(args: &[String]) -> CliResult<Command> {
    let mut sub: Option<&str> = None;
    let mut rest = args;
    if let Some(first) = args.first().filter(|a| !a.starts_with('-')) {
        sub = Some(first.as_str());
        rest = &args[1..];
    }
    let mut scene_file: Option<PathBuf> = None;
    let mut preset_name: Option<String> = None;
    let mut sets: Vec<String> = Vec::new();
    let mut accuracy = Accuracy::Balanced;
    let mut format: Option<Format> = None;
    let mut flags: Vec<(String, String)> = Vec::new();
    let mut i = 0;
    while i < rest.len() {
        let raw = rest[i].as_str();
        match raw {
            "-h" | "--help" => return Ok(Command::Help),
            "-V" | "--version" => return Ok(Command::Version),
            "--list" | "--bench" if sub == Some("compare") => {
                flags.push((raw.to_string(), "true".into()));
                i += 1;
                continue;
            }
            _ => {}
        }
        if !raw.starts_with("--") {
            return err(format!("{raw}: unexpected argument (see rime --help)"));
        }
        let (flag, inline) = match raw.split_once('=') {
            Some((f, v)) => (f, Some(v.to_string())),
            None => (raw, None),
        };
        let value = match inline {
            Some(v) => v,
            None => {
                i += 1;
                match rest.get(i) {
                    Some(v) => v.clone(),
                    None => return err(format!("{flag}: missing value")),
                }
            }
        };
        match flag {
            "--scene" => scene_file = Some(PathBuf::from(value)),
            "--preset" => preset_name = Some(value),
            "--set" => sets.push(value),
            "--accuracy" => {
                accuracy = Accuracy::parse(&value)
                    .map_err(|e| CliError(format!("--accuracy {value}: {e}")))?
            }
            "--format" => {
                format = Some(match value.as_str() {
                    "json" => Format::Json,
                    "csv" => Format::Csv,
                    "table" => Format::Table,
                    other => return err(format!("--format {other}: expected json, csv or table")),
                })
            }
            _ => flags.push((flag.to_string(), value)),
        }
        i += 1;
    }
    let mut scene = match (&scene_file, &preset_name) {
        (Some(_), Some(_)) => return err("--preset: cannot be combined with --scene"),
        (Some(f), None) => load_scene(f)?,
        (None, Some(p)) => preset(p)?,
        (None, None) => Scene::default(),
    };
    for s in &sets {
        apply_set(&mut scene, s)?;
    }
    let format = format.unwrap_or(if std::io::stdout().is_terminal() {
        Format::Table
    } else {
        Format::Json
    });
    let common = Common {
        scene,
        accuracy,
        format,
    };
    let allowed: &[&str] = match sub {
        None | Some("explore") => &[],
        Some("scene") => &["--out"],
        Some("bench") => &["--out", "--quick"],
        Some("export") => &["--from", "--to", "--points", "--out", "--runtime-params"],
        Some("fit") => &["--data", "--param", "--law", "--radius"],
        Some("data") => &["--law", "--g", "--radius"],
        Some("stick") => &["--radius", "--temperature", "--gamma", "--out"],
        Some("figures") => &["--out"],
        Some("collision") => &["--g", "--gt", "--points"],
        Some("eps") => &["--g", "--g-file"],
        Some("compare") => &["--models", "--g", "--list", "--bench"],
        Some("curve") => &["--from", "--to", "--points"],
        Some("tangential") => &["--gn", "--gt"],
        Some("map") => &["--max", "--n"],
        Some("tidal") => &[
            "--planet-mass",
            "--distance",
            "--radius",
            "--density",
            "--surface-energy",
        ],
        Some("help") => return Ok(Command::Help),
        Some(other) => return err(format!("{other}: unknown subcommand (see rime --help)")),
    };
    for (f, _) in &flags {
        if !allowed.contains(&f.as_str()) {
            let name = sub.unwrap_or("rime");
            return err(format!("{f}: not an option of `{name}` (see rime --help)"));
        }
    }
    let get = |name: &str| -> Option<&str> {
        flags
            .iter()
            .rev()
            .find(|(f, _)| f == name)
            .map(|(_, v)| v.as_str())
    };
    let owned = |name: &str| get(name).map(str::to_string);
    let require = |name: &str| -> CliResult<&str> {
        get(name).ok_or_else(|| CliError(format!("{name}: required")))
    };
    Ok(match sub {
        None | Some("explore") => Command::Explore(common),
        Some("scene") => Command::Scene(common, get("--out").map(PathBuf::from)),
        Some("export") => {
            let from = speed("--from", get("--from").unwrap_or("1e-6"), false)?;
            let to = speed("--to", get("--to").unwrap_or("1"), false)?;
            if to <= from {
                return err(format!("--to: {to} must exceed --from {from}"));
            }
            let n = count("--points", get("--points").unwrap_or("200"), 8, 100_000)?;
            let out = PathBuf::from(require("--out")?);
            let runtime = flag_bool("--runtime-params", get("--runtime-params"))?;
            Command::Export(common, from, to, n, out, runtime)
        }
        Some("figures") => {
            Command::Figures(common, PathBuf::from(get("--out").unwrap_or("figures")))
        }
        Some("fit") => Command::Fit(common, crate::commands::fit::parse(&owned)?),
        Some("data") => Command::Data(common, crate::commands::data::parse(&owned)?),
        Some("stick") => Command::Stick(common, crate::commands::stick::parse(&owned)?),
        Some("collision") => Command::Collision(common, crate::commands::collision::parse(&owned)?),
        Some("bench") => {
            let quick = flag_bool("--quick", get("--quick"))?;
            let out = PathBuf::from(get("--out").unwrap_or("target/bench"));
            Command::Bench(out, quick)
        }
        Some("compare") => Command::Compare(
            common,
            crate::commands::compare::Args {
                models: match get("--models") {
                    Some(m) => crate::commands::compare::parse_models(m)?,
                    None => Vec::new(),
                },
                g: match get("--g") {
                    Some(g) => speed_list("--g", g, false)?,
                    None => Vec::new(),
                },
                list: get("--list").is_some(),
                bench: get("--bench").is_some(),
            },
        ),
        Some("eps") => match (get("--g"), get("--g-file")) {
            (Some(_), Some(_)) => return err("--g-file: cannot be combined with --g"),
            (None, Some(file)) => Command::EpsFile(common, PathBuf::from(file)),
            _ => {
                let g = speed_list("--g", require("--g")?, false)?;
                Command::Eps(common, g)
            }
        },
        Some("curve") => {
            let from = speed("--from", require("--from")?, false)?;
            let to = speed("--to", require("--to")?, false)?;
            if to < from {
                return err(format!("--to: {to} is below --from {from}"));
            }
            let n = count("--points", get("--points").unwrap_or("400"), 1, 100_000)?;
            Command::Curve(common, from, to, n)
        }
        Some("tangential") => {
            let gn = speed_list("--gn", require("--gn")?, true)?;
            let gt = speed_list("--gt", require("--gt")?, true)?;
            if gn.len().saturating_mul(gt.len()) > 1_000_000 {
                return err("--gt: at most 1000000 combinations of --gn and --gt");
            }
            Command::Tangential(common, gn, gt)
        }
        Some("map") => {
            let max = speed("--max", require("--max")?, false)?;
            let n = count("--n", get("--n").unwrap_or("200"), 2, 2000)?;
            Command::Map(common, max, n)
        }
        Some("tidal") => {
            let mut input = rime_core::tidal::TidalInput::default();
            for (name, slot) in [
                ("--planet-mass", &mut input.planet_mass),
                ("--distance", &mut input.distance),
                ("--radius", &mut input.radius),
                ("--density", &mut input.density),
                ("--surface-energy", &mut input.surface_energy),
            ] {
                if let Some(v) = get(name) {
                    *slot = number(name, v)?;
                }
            }
            Command::Tidal(common, input)
        }
        Some(_) => Command::Help,
    })
}

/// Builds the contact constants for a command.
pub fn contact(common: &Common) -> CliResult<Contact> {
    Ok(Contact::new(&common.scene)?)
}

/// Renders the scene JSON for `rime scene`.
pub fn scene_text(common: &Common) -> CliResult<String> {
    scene_json(&common.scene).map(|mut s| {
        s.push('\n');
        s
    })
}
