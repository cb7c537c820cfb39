//! The non-interactive subcommands (docs/cli.md): machine-readable output for scripts.

use crate::scene_io::{CliError, CliResult, apply_set, err, load_scene, preset, scene_json};
use crate::spec::{self, Sub};
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

/// `rime figures --explorer`: the explorer's figures and records of a scene, as the terminal's `x`
/// and the page's downloads draw them.
#[derive(Debug, Clone)]
pub struct ExplorerFigures {
    /// The core's request: scene, level, speeds, points, map (validated by the core, so the flags
    /// refuse exactly what the terminal and the page refuse).
    pub request: rime_core::explorer::request::Request,
    /// ε_N on a log axis.
    pub y_log: bool,
    /// Leave out the experimental context.
    pub no_experiments: bool,
}

/// The flag that sets a field of the core's [`Request`](rime_core::explorer::request::Request).
fn request_flag(field: &str) -> &str {
    match field {
        "from" => "--from",
        "to" => "--to",
        "points" => "--points",
        "map_n" => "--n",
        "map_max" => "--max",
        "overlays" => "--overlays",
        other => other,
    }
}

/// The core's request of `rime figures --explorer`, checked by the core; errors name the flag.
fn explorer_request(
    common: &Common,
    get: &dyn Fn(&str) -> Option<String>,
) -> CliResult<rime_core::explorer::request::Request> {
    use rime_core::explorer::frame::Overlay;
    use rime_core::explorer::request::Request;
    let mut request = Request::new(common.scene, common.accuracy);
    request.speeds = match (get("--from"), get("--to")) {
        (None, None) => None,
        (Some(a), Some(b)) => Some((speed("--from", &a, false)?, speed("--to", &b, false)?)),
        (Some(_), None) => return err("--to: required with --from"),
        (None, Some(_)) => return err("--from: required with --to"),
    };
    let whole = |flag: &str, default: usize| -> CliResult<usize> {
        match get(flag) {
            None => Ok(default),
            Some(t) => t
                .trim()
                .parse::<usize>()
                .map_err(|_| CliError::input(format!("{flag}: '{t}' is not a whole number"))),
        }
    };
    request.points = whole("--points", Request::POINTS)?;
    request.map_n = whole("--n", Request::MAP_N)?;
    request.map_max = get("--max")
        .map(|m| speed("--max", &m, false))
        .transpose()?;
    if let Some(list) = get("--overlays") {
        request.overlays = list
            .split(',')
            .map(str::trim)
            .map(|o| Overlay::parse(o).map_err(|e| CliError::input(format!("--overlays {o}: {e}"))))
            .collect::<CliResult<_>>()?;
    }
    request.validate().map_err(|e| {
        let text = e.to_string();
        let (field, rest) = text.split_once(':').unwrap_or(("", &text));
        CliError::input(format!("{}:{rest}", request_flag(field)))
    })?;
    Ok(request)
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
    /// `export --lammps DIR`: a LAMMPS deck, its reference values and README.
    ExportLammps(Common, PathBuf),
    /// `rime fit (--data FILE.csv | --law ID) [--param A,B]`.
    Fit(Common, crate::commands::fit::Args),
    /// `rime data [--law ID --g LIST [--radius R]]`.
    Data(Common, crate::commands::data::Args),
    /// `rime ring --tau T (--omega W | --planet-mass M --distance D) [--radius R] [--scale-damping]`.
    Ring(Common, crate::commands::ring::Args),
    /// `rime stick --radius LIST [--temperature LIST] [--gamma surface|adhesion] [--out DIR]`.
    Stick(Common, crate::commands::stick::Args),
    /// `rime collision --g G [--gt G] [--points N]`.
    Collision(Common, crate::commands::collision::Args),
    /// `rime figures --out DIR`.
    Figures(Common, PathBuf, Option<Box<ExplorerFigures>>),
    /// `rime compare --models LIST --g LIST | --list | --bench`.
    Compare(Common, crate::commands::compare::Args),
    /// `rime bench [--out DIR] [--quick]`.
    Bench(PathBuf, bool),
    /// `rime help [SUB]`, `rime SUB --help`: the overview or one subcommand's help.
    Help(Option<&'static crate::spec::Sub>),
    /// `rime completions bash|zsh|fish`.
    Completions(String),
    /// `rime man`.
    Man,
    /// `rime --version`.
    Version,
}

pub(crate) fn number(flag: &str, text: &str) -> CliResult<f64> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(v) => err(format!("{flag}: {v} is not a finite number")),
        Err(_) => err(format!("{flag}: '{text}' is not a number")),
    }
}

/// A value in the SI unit `unit`, with an optional unit (`1e-6`, `"1 um"`, `200 K`), parsed by
/// [`rime_core::units::parse_quantity`] like `--set`.
pub(crate) fn quantity(flag: &str, text: &str, unit: &str) -> CliResult<f64> {
    rime_core::units::parse_quantity("", text, unit).map_err(|e| {
        let shown: String = text.trim().chars().take(40).collect();
        CliError::input(format!("{flag} {shown}{e}"))
    })
}

/// A speed in m/s, with an optional unit (`0.01`, `"2 mm/s"`, `5cm/s`), parsed by
/// [`rime_core::units::parse_quantity`] like `--set`.
pub(crate) fn speed(flag: &str, text: &str, allow_zero: bool) -> CliResult<f64> {
    // The core names the field in front of its message; the flag goes there instead.
    let v = rime_core::units::parse_quantity("", text, "m/s").map_err(|e| {
        let shown: String = text.trim().chars().take(40).collect();
        CliError::input(format!("{flag} {shown}{e}"))
    })?;
    let ok = if allow_zero { v >= 0.0 } else { v > 0.0 };
    if !ok || v > rime_core::limits::SPEED_MAX {
        let range = if allow_zero { "[0, 1e6]" } else { "(0, 1e6]" };
        return err(format!(
            "{flag}: speed {} must lie in {range} m/s",
            rime_core::error::Number(v)
        ));
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

/// Most points of any curve or table the CLI computes: the core's limit.
const MAX_POINTS: usize = rime_core::explorer::request::Request::MAX_POINTS;
/// Largest stick map the CLI computes: the core's limit.
const MAX_MAP_N: usize = rime_core::explorer::request::Request::MAX_MAP_N;

fn count(flag: &str, text: &str, min: usize, max: usize) -> CliResult<usize> {
    match text.trim().parse::<usize>() {
        Ok(n) if (min..=max).contains(&n) => Ok(n),
        _ => err(format!(
            "{flag}: '{text}' must be a whole number in [{min}, {max}]"
        )),
    }
}

fn format_of(sub: &Sub, value: &str) -> CliResult<Format> {
    let name = sub.command();
    if sub.formats.is_empty() {
        return err(format!(
            "--format: not an option of `{name}`, which prints no table (see {name} --help)"
        ));
    }
    if !sub.formats.contains(&value) {
        if !["json", "csv", "table"].contains(&value) {
            return err(format!("--format {value}: expected json, csv or table"));
        }
        return err(format!(
            "--format {value}: `{name}` writes {} only",
            sub.formats.join(" or ")
        ));
    }
    Ok(match value {
        "csv" => Format::Csv,
        "table" => Format::Table,
        _ => Format::Json,
    })
}

/// Parses the command line (without the program name); the accepted flags come from
/// [`crate::spec::SUBS`].
pub fn parse(args: &[String]) -> CliResult<Command> {
    let mut rest = args;
    let mut name = "";
    if let Some(first) = args.first().filter(|a| !a.starts_with('-')) {
        name = if first == "explore" {
            ""
        } else {
            first.as_str()
        };
        rest = &args[1..];
    }
    let Some(sub) = spec::find(name) else {
        return err(format!("{name}: unknown subcommand (see rime --help)"));
    };
    // Positional arguments of `help` and `completions`.
    let mut positional: Option<&str> = None;
    if matches!(sub.name, "help" | "completions")
        && let Some(p) = rest.first().filter(|a| !a.starts_with('-'))
    {
        positional = Some(p.as_str());
        rest = &rest[1..];
    }
    let accepted = sub.accepted();
    let mut scene_file: Option<PathBuf> = None;
    let mut preset_name: Option<String> = None;
    let mut sets: Vec<String> = Vec::new();
    let mut accuracy = Accuracy::default();
    let mut format: Option<Format> = None;
    let mut flags: Vec<(&'static str, String)> = Vec::new();
    let mut i = 0;
    while i < rest.len() {
        let raw = rest[i].as_str();
        match raw {
            "-h" | "--help" => return Ok(Command::Help(Some(sub))),
            "-V" | "--version" => return Ok(Command::Version),
            _ => {}
        }
        if !raw.starts_with("--") {
            return err(format!(
                "{raw}: unexpected argument (see {} --help)",
                sub.command()
            ));
        }
        let (given, inline) = match raw.split_once('=') {
            Some((f, v)) => (f, Some(v.to_string())),
            None => (raw, None),
        };
        let Some(flag) = accepted.iter().find(|f| f.name == given) else {
            if given == "--format" {
                format_of(sub, "")?;
            }
            return err(format!(
                "{given}: not an option of `{}` (see {} --help)",
                sub.command(),
                sub.command()
            ));
        };
        let value = match (flag.value, inline) {
            (_, Some(v)) => v,
            // A bare switch; `true`/`false` after it is still accepted (older scripts).
            (None, None) => match rest.get(i + 1).map(String::as_str) {
                Some(v @ ("true" | "false")) => {
                    i += 1;
                    v.to_string()
                }
                _ => "true".to_string(),
            },
            (Some(_), None) => {
                i += 1;
                match rest.get(i) {
                    Some(v) => v.clone(),
                    None => return err(format!("{given}: missing value")),
                }
            }
        };
        if flag.value.is_none() && !matches!(value.as_str(), "true" | "false") {
            return err(format!("{given} {value}: expected true or false"));
        }
        match flag.name {
            "--scene" => scene_file = Some(PathBuf::from(value)),
            "--preset" => preset_name = Some(value),
            "--set" => sets.push(value),
            "--accuracy" => {
                accuracy = Accuracy::parse(&value)
                    .map_err(|e| CliError::input(format!("--accuracy {value}: {e}")))?
            }
            "--format" => format = Some(format_of(sub, &value)?),
            _ => flags.push((flag.name, value)),
        }
        i += 1;
    }
    match sub.name {
        "help" => {
            return match positional {
                None => Ok(Command::Help(None)),
                Some(p) => match spec::find(p).filter(|s| !s.name.is_empty()) {
                    Some(s) => Ok(Command::Help(Some(s))),
                    None => err(format!("help {p}: unknown subcommand (see rime --help)")),
                },
            };
        }
        "completions" => {
            return match positional {
                Some(sh @ ("bash" | "zsh" | "fish")) => Ok(Command::Completions(sh.to_string())),
                Some(other) => err(format!("completions {other}: expected bash, zsh or fish")),
                None => err("completions: which shell? bash, zsh or fish"),
            };
        }
        "man" => return Ok(Command::Man),
        _ => {}
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
    let terminal_default = if std::io::stdout().is_terminal() {
        Format::Table
    } else {
        Format::Json
    };
    let format = format.unwrap_or(match sub.formats {
        [] => terminal_default,
        [only] => format_of(sub, only)?,
        _ => terminal_default,
    });
    let common = Common {
        scene,
        accuracy,
        format,
    };
    let get = |name: &str| -> Option<&str> {
        flags
            .iter()
            .rev()
            .find(|(f, _)| *f == name)
            .map(|(_, v)| v.as_str())
    };
    let owned = |name: &str| get(name).map(str::to_string);
    let switch = |name: &str| get(name) == Some("true");
    let require = |name: &str| -> CliResult<&str> {
        get(name).ok_or_else(|| CliError::input(format!("{name}: required")))
    };
    Ok(match sub.name {
        "" => Command::Explore(common),
        "scene" => Command::Scene(common, get("--out").map(PathBuf::from)),
        "export" if get("--lammps").is_some() => {
            if get("--out").is_some() {
                return err("--lammps: writes its own directory; give --out or --lammps, not both");
            }
            for flag in ["--from", "--to", "--points", "--runtime-params"] {
                if get(flag).is_some() || switch(flag) {
                    return err(format!("{flag}: not used with --lammps"));
                }
            }
            Command::ExportLammps(common, PathBuf::from(require("--lammps")?))
        }
        "export" => {
            let from = speed("--from", get("--from").unwrap_or("1e-6"), false)?;
            let to = speed("--to", get("--to").unwrap_or("1"), false)?;
            if to <= from {
                return err(format!(
                    "--to: {} must exceed --from {}",
                    rime_core::error::Number(to),
                    rime_core::error::Number(from)
                ));
            }
            let n = count("--points", get("--points").unwrap_or("200"), 8, MAX_POINTS)?;
            let out = PathBuf::from(require("--out")?);
            Command::Export(common, from, to, n, out, switch("--runtime-params"))
        }
        "figures" => {
            let out = PathBuf::from(get("--out").unwrap_or("figures"));
            let explorer = if switch("--explorer") {
                let owned_get = |flag: &str| get(flag).map(str::to_string);
                Some(Box::new(ExplorerFigures {
                    request: explorer_request(&common, &owned_get)?,
                    y_log: switch("--y-log"),
                    no_experiments: switch("--no-experiments"),
                }))
            } else {
                let only = [
                    "--from",
                    "--to",
                    "--points",
                    "--n",
                    "--max",
                    "--y-log",
                    "--overlays",
                    "--no-experiments",
                ];
                if let Some(f) = only.iter().find(|f| get(f).is_some()) {
                    return err(format!(
                        "{f}: only with --explorer (the paper's figures have fixed speeds)"
                    ));
                }
                if scene_file.is_some() || preset_name.is_some() || !sets.is_empty() {
                    return err(
                        "--scene/--preset/--set: only with --explorer (the paper's figures use \
                         the paper's scenes)",
                    );
                }
                None
            };
            Command::Figures(common, out, explorer)
        }
        "fit" => Command::Fit(common, crate::commands::fit::parse(&owned)?),
        "data" => Command::Data(common, crate::commands::data::parse(&owned)?),
        "stick" => Command::Stick(common, crate::commands::stick::parse(&owned)?),
        "ring" => Command::Ring(common, crate::commands::ring::parse(&owned)?),
        "collision" => Command::Collision(common, crate::commands::collision::parse(&owned)?),
        "bench" => {
            let out = PathBuf::from(get("--out").unwrap_or("target/bench"));
            Command::Bench(out, switch("--quick"))
        }
        "compare" => Command::Compare(common, {
            let (models, laws) = match get("--models") {
                Some(m) => crate::commands::compare::parse_models(m)?,
                None => (Vec::new(), Vec::new()),
            };
            crate::commands::compare::Args {
                models,
                laws,
                g: match get("--g") {
                    Some(g) => speed_list("--g", g, false)?,
                    None => Vec::new(),
                },
                list: switch("--list"),
                bench: switch("--bench"),
            }
        }),
        "eps" => match (get("--g"), get("--g-file")) {
            (Some(_), Some(_)) => return err("--g-file: cannot be combined with --g"),
            (None, Some(file)) => Command::EpsFile(common, PathBuf::from(file)),
            _ => {
                let g = speed_list("--g", require("--g")?, false)?;
                Command::Eps(common, g)
            }
        },
        "curve" => {
            let from = speed("--from", require("--from")?, false)?;
            let to = speed("--to", require("--to")?, false)?;
            if to < from {
                return err(format!(
                    "--to: {} is below --from {}",
                    rime_core::error::Number(to),
                    rime_core::error::Number(from)
                ));
            }
            let n = count("--points", get("--points").unwrap_or("400"), 1, MAX_POINTS)?;
            Command::Curve(common, from, to, n)
        }
        "tangential" => {
            let gn = speed_list("--gn", require("--gn")?, true)?;
            let gt = speed_list("--gt", require("--gt")?, true)?;
            if gn.len().saturating_mul(gt.len()) > 1_000_000 {
                return err("--gt: at most 1000000 combinations of --gn and --gt");
            }
            Command::Tangential(common, gn, gt)
        }
        "map" => {
            let max = speed("--max", require("--max")?, false)?;
            let n = count("--n", get("--n").unwrap_or("200"), 2, MAX_MAP_N)?;
            Command::Map(common, max, n)
        }
        "tidal" => {
            let mut input = rime_core::tidal::TidalInput::default();
            for (name, unit, slot) in [
                ("--planet-mass", "kg", &mut input.planet_mass),
                ("--distance", "m", &mut input.distance),
                ("--radius", "m", &mut input.radius),
                ("--density", "kg/m³", &mut input.density),
                ("--surface-energy", "J/m²", &mut input.surface_energy),
            ] {
                if let Some(v) = get(name) {
                    *slot = rime_core::units::parse_quantity(name, v, unit)?;
                }
            }
            Command::Tidal(common, input)
        }
        _ => Command::Help(Some(sub)),
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
