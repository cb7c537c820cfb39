//! The non-interactive subcommands (docs/cli.md): machine-readable output for scripts.

use crate::args::{
    Common, ExplorerFigures, Format, MAX_MAP_N, MAX_POINTS, count, explorer_request, speed,
    speed_list,
};
use crate::scene_io::{CliError, CliResult, apply_set, err, load_scene, preset};
use crate::spec::{self, Sub};
use rime_core::{Accuracy, Scene};
use std::io::IsTerminal;
use std::path::PathBuf;

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
    ExportLammps(Common, PathBuf, Option<rime_core::dem::AdhesionMapping>),
    /// `rime fit (--data FILE.csv | --law ID) [--param A,B]`.
    Fit(Common, crate::commands::fit::Args),
    /// `rime data [--law ID --g LIST [--radius R]]`.
    Data(Common, crate::commands::data::Args),
    /// `rime ring --tau T (--omega W | --planet-mass M --distance D) [--radius R] [--scale-damping]`.
    Ring(Common, crate::commands::ring::Args),
    /// `rime stick --radius LIST [--temperature LIST] [--gamma surface|adhesion] [--out DIR]`.
    Stick(Common, crate::commands::stick::Args),
    /// `rime kernel --radii R1..R2|LIST [--points N] [--temperatures LIST] [--a-rule RULE] [--svg FILE]`.
    Kernel(Common, Box<crate::commands::kernel::Args>),
    /// `rime collision --g G [--gt G] [--points N]`.
    Collision(Common, crate::commands::collision::Args),
    /// `rime figures --out DIR`.
    Figures(Common, PathBuf, Option<Box<ExplorerFigures>>),
    /// `rime compare --models LIST --g LIST | --list | --bench`.
    Compare(Common, crate::commands::compare::Args),
    /// `rime bench [--out DIR] [--quick] [--frames]`.
    Bench(PathBuf, bool, bool),
    /// `rime help [SUB]`, `rime SUB --help`: the overview or one subcommand's help.
    Help(Option<&'static crate::spec::Sub>),
    /// `rime completions bash|zsh|fish`.
    Completions(String),
    /// `rime man`.
    Man,
    /// `rime --version`.
    Version,
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
        let hint = crate::suggest::hint(name, spec::SUBS.iter().map(|s| s.name));
        return err(format!(
            "{name}: unknown subcommand{hint} (see rime --help)"
        ));
    };
    // Positional arguments of `help` and `completions`.
    let mut positional: Option<&str> = None;
    if matches!(sub.name, "help" | "completions")
        && let Some(p) = rest.first().filter(|a| !a.starts_with('-'))
    {
        positional = Some(p.as_str());
        rest = &rest[1..];
    }
    let given = match read_flags(sub, rest)? {
        Read::Flags(given) => given,
        Read::Early(command) => return Ok(command),
    };
    match sub.name {
        "help" => {
            return match positional {
                None => Ok(Command::Help(None)),
                Some(p) => match spec::find(p).filter(|s| !s.name.is_empty()) {
                    Some(s) => Ok(Command::Help(Some(s))),
                    None => err(format!(
                        "help {p}: unknown subcommand{} (see rime --help)",
                        crate::suggest::hint(p, spec::SUBS.iter().map(|s| s.name))
                    )),
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
    let common = common_options(sub, &given)?;
    subcommand(sub, common, &given)
}

/// The scene options and the subcommand's own flags, as given.
struct Given {
    scene_file: Option<PathBuf>,
    preset_name: Option<String>,
    sets: Vec<String>,
    accuracy: Accuracy,
    format: Option<Format>,
    flags: Flags,
}

/// What reading the flags gave: the flags, or a command that ends reading (`--help`, `--version`).
enum Read {
    Flags(Given),
    Early(Command),
}

/// The subcommand's own flags (the last one given wins).
struct Flags(Vec<(&'static str, String)>);

impl Flags {
    fn get(&self, name: &str) -> Option<&str> {
        self.0
            .iter()
            .rev()
            .find(|(f, _)| *f == name)
            .map(|(_, v)| v.as_str())
    }
    fn owned(&self, name: &str) -> Option<String> {
        self.get(name).map(str::to_string)
    }
    fn switch(&self, name: &str) -> bool {
        self.get(name) == Some("true")
    }
    fn require(&self, name: &str) -> CliResult<&str> {
        self.get(name)
            .ok_or_else(|| CliError::input(format!("{name}: required")))
    }
}

/// Reads `--flag value`, `--flag=value` and bare switches, refusing what `sub` does not accept.
fn read_flags(sub: &'static Sub, rest: &[String]) -> CliResult<Read> {
    let accepted = sub.accepted();
    let mut given = Given {
        scene_file: None,
        preset_name: None,
        sets: Vec::new(),
        accuracy: Accuracy::default(),
        format: None,
        flags: Flags(Vec::new()),
    };
    let mut i = 0;
    while i < rest.len() {
        let raw = rest[i].as_str();
        match raw {
            "-h" | "--help" => return Ok(Read::Early(Command::Help(Some(sub)))),
            "-V" | "--version" => return Ok(Read::Early(Command::Version)),
            _ => {}
        }
        if !raw.starts_with("--") {
            return err(format!(
                "{raw}: unexpected argument (see {} --help)",
                sub.command()
            ));
        }
        let (name, inline) = match raw.split_once('=') {
            Some((f, v)) => (f, Some(v.to_string())),
            None => (raw, None),
        };
        let Some(flag) = accepted.iter().find(|f| f.name == name) else {
            if name == "--format" {
                format_of(sub, "")?;
            }
            return err(format!(
                "{name}: not an option of `{}`{} (see {} --help)",
                sub.command(),
                crate::suggest::hint(name, accepted.iter().map(|f| f.name)),
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
                    None => return err(format!("{name}: missing value")),
                }
            }
        };
        if flag.value.is_none() && !matches!(value.as_str(), "true" | "false") {
            return err(format!("{name} {value}: expected true or false"));
        }
        match flag.name {
            "--scene" => given.scene_file = Some(PathBuf::from(value)),
            "--preset" => given.preset_name = Some(value),
            "--set" => given.sets.push(value),
            "--accuracy" => {
                given.accuracy = Accuracy::parse(&value).map_err(|e| {
                    // The flag names the field once (it read "--accuracy x: accuracy: …").
                    let text = e.to_string();
                    let text = text.strip_prefix("accuracy: ").unwrap_or(&text);
                    let hint = crate::suggest::hint(&value, ["fast", "precise", "integrated"]);
                    CliError::input(format!("--accuracy {value}: {text}{hint}"))
                })?
            }
            "--format" => {
                let format = format_of(sub, &value)?;
                // Two different formats: one would be ignored silently (the same one twice is
                // harmless, as scripts that append `--format json` give it).
                if given.format.is_some_and(|f| f != format) {
                    return err(format!(
                        "--format {value}: a different --format was given before (one only)"
                    ));
                }
                given.format = Some(format);
            }
            _ => given.flags.0.push((flag.name, value)),
        }
        i += 1;
    }
    Ok(Read::Flags(given))
}

/// The scene (file or preset, then every `--set`), the level and the output format.
fn common_options(sub: &Sub, given: &Given) -> CliResult<Common> {
    let mut scene = match (&given.scene_file, &given.preset_name) {
        (Some(_), Some(_)) => return err("--preset: cannot be combined with --scene"),
        (Some(f), None) => load_scene(f)?,
        (None, Some(p)) => preset(p)?,
        (None, None) => Scene::default(),
    };
    // An effect switched on by setting one of its fields (`--set layer.thickness=2um` on a scene
    // without a layer) takes defaults for the fields not given: a note says which (issue 37: it
    // happened silently).
    let mut switched_on: Vec<&str> = Vec::new();
    for s in &given.sets {
        let path = s.split_once('=').map_or(s.as_str(), |(p, _)| p.trim());
        let section = path.split_once('.').map(|(sec, _)| sec);
        let off = |scene: &Scene, sec: &str| {
            scene.get(sec) == Ok(rime_core::params::Value::Enabled(false))
        };
        let was_off = section.is_some_and(|sec| off(&scene, sec));
        apply_set(&mut scene, s)?;
        if let Some(sec) = section.filter(|sec| was_off && !off(&scene, sec)) {
            switched_on.push(sec);
        }
    }
    for sec in switched_on {
        if let Some(note) = switched_on_note(&scene, sec, &given.sets) {
            eprintln!("{note}");
        }
    }
    let terminal_default = if std::io::stdout().is_terminal() {
        Format::Table
    } else {
        Format::Json
    };
    let format = given.format.unwrap_or(match sub.formats {
        [] => terminal_default,
        [only] => format_of(sub, only)?,
        _ => terminal_default,
    });
    Ok(Common {
        scene,
        accuracy: given.accuracy,
        format,
    })
}

/// The note for effect `section` switched on by a `--set` of one of its fields: the fields the
/// user did not set and the defaults they took; `None` when every field was given.
fn switched_on_note(scene: &Scene, section: &str, sets: &[String]) -> Option<String> {
    let given: Vec<&str> = sets
        .iter()
        .map(|s| s.split_once('=').map_or(s.as_str(), |(p, _)| p.trim()))
        .collect();
    let prefix = format!("{section}.");
    let defaults: Vec<String> = rime_core::params::PARAMETERS
        .iter()
        .filter(|p| p.path.starts_with(&prefix) && !given.contains(&p.path))
        .filter_map(|p| match scene.get(p.path) {
            Ok(rime_core::params::Value::Number(v)) => Some(format!(
                "{} = {}",
                p.path,
                rime_core::explorer::format::qty(v, p.unit)
            )),
            Ok(rime_core::params::Value::Choice(c)) => Some(format!("{} = {c}", p.path)),
            _ => None,
        })
        .collect();
    let first = given.iter().find(|p| p.starts_with(&prefix))?;
    (!defaults.is_empty()).then(|| {
        format!(
            "note: --set {first}: the scene had no {section}; it is switched on, with the defaults {} \
             (--set them too, or --set {section}=off)",
            defaults.join(", ")
        )
    })
}

/// The subcommand with its flags read.
fn subcommand(sub: &'static Sub, common: Common, given: &Given) -> CliResult<Command> {
    let flags = &given.flags;
    let get = |name: &str| flags.get(name);
    let owned = |name: &str| flags.owned(name);
    let switch = |name: &str| flags.switch(name);
    let require = |name: &str| flags.require(name);
    Ok(match sub.name {
        "" => Command::Explore(common),
        "scene" => Command::Scene(common, get("--out").map(PathBuf::from)),
        "export" if get("--lammps").is_some() => export_lammps(common, flags)?,
        "export" => export(common, flags)?,
        "figures" => figures(common, given)?,
        "fit" => Command::Fit(common, crate::commands::fit::parse(&owned)?),
        "data" => Command::Data(common, crate::commands::data::parse(&owned)?),
        "stick" => Command::Stick(common, crate::commands::stick::parse(&owned)?),
        "kernel" => Command::Kernel(common, Box::new(crate::commands::kernel::parse(&owned)?)),
        "ring" => Command::Ring(common, crate::commands::ring::parse(&owned, &given.sets)?),
        "collision" => Command::Collision(common, crate::commands::collision::parse(&owned)?),
        "bench" => {
            let out = PathBuf::from(get("--out").unwrap_or("target/bench"));
            Command::Bench(out, switch("--quick"), switch("--frames"))
        }
        "compare" => compare(common, flags)?,
        "eps" => match (get("--g"), get("--g-file")) {
            (Some(_), Some(_)) => return err("--g-file: cannot be combined with --g"),
            (None, Some(file)) => Command::EpsFile(common, PathBuf::from(file)),
            _ => Command::Eps(common, speed_list("--g", require("--g")?, false)?),
        },
        "curve" => curve(common, flags)?,
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
        "tidal" => tidal(common, flags)?,
        _ => Command::Help(Some(sub)),
    })
}

/// `export --lammps DIR`.
fn export_lammps(common: Common, flags: &Flags) -> CliResult<Command> {
    if flags.get("--out").is_some() {
        return err("--lammps: writes its own directory; give --out or --lammps, not both");
    }
    for flag in ["--from", "--to", "--points", "--runtime-params"] {
        if flags.get(flag).is_some() || flags.switch(flag) {
            return err(format!("{flag}: not used with --lammps"));
        }
    }
    // An adhesive scene maps only onto a named model (issue 35); the name is checked here, its
    // fit with the scene by the export.
    let adhesion = match flags.get("--lammps-adhesion") {
        None => None,
        Some(name) => Some(rime_core::dem::AdhesionMapping::parse(name).map_err(|_| {
            CliError::input(format!(
                "--lammps-adhesion: '{name}' is not a mapping; the one LAMMPS has is jkr \
                 (pair granular jkr = brilliantov2007)"
            ))
        })?),
    };
    Ok(Command::ExportLammps(
        common,
        PathBuf::from(flags.require("--lammps")?),
        adhesion,
    ))
}

/// `export --out DIR [--from G --to G --points N] [--runtime-params]`.
fn export(common: Common, flags: &Flags) -> CliResult<Command> {
    if flags.get("--lammps-adhesion").is_some() {
        return err("--lammps-adhesion: only with --lammps DIR");
    }
    let from = speed("--from", flags.get("--from").unwrap_or("1e-6"), false)?;
    let to = speed("--to", flags.get("--to").unwrap_or("1"), false)?;
    if to <= from {
        return err(format!(
            "--to: {} must exceed --from {}",
            rime_core::error::Number(to),
            rime_core::error::Number(from)
        ));
    }
    let n = count(
        "--points",
        flags.get("--points").unwrap_or("200"),
        8,
        MAX_POINTS,
    )?;
    let out = PathBuf::from(flags.require("--out")?);
    Ok(Command::Export(
        common,
        from,
        to,
        n,
        out,
        flags.switch("--runtime-params"),
    ))
}

/// `figures [--explorer …] --out DIR`.
fn figures(common: Common, given: &Given) -> CliResult<Command> {
    let flags = &given.flags;
    let out = PathBuf::from(flags.get("--out").unwrap_or("figures"));
    if flags.switch("--explorer") {
        let request = explorer_request(&common, &|flag: &str| flags.owned(flag))?;
        let explorer = ExplorerFigures {
            request,
            y_log: flags.switch("--y-log"),
            no_experiments: flags.switch("--no-experiments"),
        };
        return Ok(Command::Figures(common, out, Some(Box::new(explorer))));
    }
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
    if let Some(f) = only.iter().find(|f| flags.get(f).is_some()) {
        return err(format!(
            "{f}: only with --explorer (the paper's figures have fixed speeds)"
        ));
    }
    if given.scene_file.is_some() || given.preset_name.is_some() || !given.sets.is_empty() {
        return err(
            "--scene/--preset/--set: only with --explorer (the paper's figures use the paper's \
             scenes)",
        );
    }
    Ok(Command::Figures(common, out, None))
}

/// `compare --models LIST --g LIST | --list | --bench`.
fn compare(common: Common, flags: &Flags) -> CliResult<Command> {
    let (models, laws) = match flags.get("--models") {
        Some(m) => crate::commands::compare::parse_models(m)?,
        None => (Vec::new(), Vec::new()),
    };
    let g = match flags.get("--g") {
        Some(g) => speed_list("--g", g, false)?,
        None => Vec::new(),
    };
    Ok(Command::Compare(
        common,
        crate::commands::compare::Args {
            models,
            laws,
            g,
            list: flags.switch("--list"),
            bench: flags.switch("--bench"),
        },
    ))
}

/// `curve --from G --to G [--points N]`.
fn curve(common: Common, flags: &Flags) -> CliResult<Command> {
    let from = speed("--from", flags.require("--from")?, false)?;
    let to = speed("--to", flags.require("--to")?, false)?;
    if to < from {
        return err(format!(
            "--to: {} is below --from {}",
            rime_core::error::Number(to),
            rime_core::error::Number(from)
        ));
    }
    let n = count(
        "--points",
        flags.get("--points").unwrap_or("400"),
        1,
        MAX_POINTS,
    )?;
    Ok(Command::Curve(common, from, to, n))
}

/// `tidal [--planet-mass M] [--distance D] [--radius R] [--density RHO] [--surface-energy G]`.
fn tidal(common: Common, flags: &Flags) -> CliResult<Command> {
    let mut input = rime_core::tidal::TidalInput::default();
    for (name, unit, slot) in [
        ("--planet-mass", "kg", &mut input.planet_mass),
        ("--distance", "m", &mut input.distance),
        ("--radius", "m", &mut input.radius),
        ("--density", "kg/m³", &mut input.density),
        ("--surface-energy", "J/m²", &mut input.surface_energy),
    ] {
        if let Some(v) = flags.get(name) {
            *slot = rime_core::units::parse_quantity(name, v, unit)?;
        }
    }
    Ok(Command::Tidal(common, input))
}
