//! The one table of subcommands and flags: the parser's accepted flags (crate::cli), the global
//! and per-subcommand help, the shell completions (`rime completions bash|zsh|fish`) and the man page
//! (`rime man`) are all generated from it, so they cannot drift apart.

/// One flag.
#[derive(Debug, Clone, Copy)]
pub struct Flag {
    /// `--name`.
    pub name: &'static str,
    /// Placeholder of the value (`LIST`, `FILE`…); `None` for a bare switch (`--quick`), which also
    /// accepts `true`/`false` after it.
    pub value: Option<&'static str>,
    /// One line of help.
    pub help: &'static str,
}

/// One subcommand.
#[derive(Debug, Clone, Copy)]
pub struct Sub {
    /// Name (`eps`); `""` for the explorer (`rime` without a subcommand).
    pub name: &'static str,
    /// Usage line after `rime `.
    pub usage: &'static str,
    /// What it does, a few lines.
    pub about: &'static str,
    /// Its own flags.
    pub flags: &'static [Flag],
    /// Whether it reads the scene options (`--scene`, `--preset`, `--set`, `--accuracy`).
    pub scene: bool,
    /// The `--format` values it honours (empty: `--format` is refused).
    pub formats: &'static [&'static str],
    /// One example command line (after `rime `).
    pub example: &'static str,
}

const fn f(name: &'static str, value: &'static str, help: &'static str) -> Flag {
    Flag {
        name,
        value: Some(value),
        help,
    }
}

const fn switch(name: &'static str, help: &'static str) -> Flag {
    Flag {
        name,
        value: None,
        help,
    }
}

/// The scene options (taken by every subcommand with `scene: true`).
pub const SCENE_FLAGS: &[Flag] = &[
    f(
        "--scene",
        "FILE",
        "scene file, JSON (default: the `ice` preset)",
    ),
    f(
        "--preset",
        "NAME",
        "start from a preset: ice, ice-frost, ice-sticky, ice-paper-viscosities",
    ),
    f(
        "--set",
        "PATH=VALUE",
        "override a parameter, repeatable; units allowed (--set layer.thickness=\"2 um\", --set adhesion=off)",
    ),
    f(
        "--accuracy",
        "LEVEL",
        "precise (default: fine table, ε_N error ≤ 1e-10) | fast (coarse table, ≤ 1e-6) | integrated (integrates each contact, ≤ 1e-6, slowest) | a tolerance like 1e-8",
    ),
];

/// `--format` (taken by subcommands with a non-empty `formats`).
pub const FORMAT_FLAG: Flag = f(
    "--format",
    "FORMAT",
    "json | csv | table (table on a terminal, json otherwise)",
);

/// Flags every command takes.
pub const GLOBAL_FLAGS: &[Flag] = &[
    switch("--help", "this subcommand's help (also -h, rime help SUB)"),
    switch("--version", "print the version (also -V)"),
];

const ALL_FORMATS: &[&str] = &["json", "csv", "table"];

/// Every subcommand, the explorer first.
pub const SUBS: &[Sub] = &[
    Sub {
        name: "",
        usage: "[OPTIONS]",
        about: "The terminal explorer: ε_N and the stick map of one scene, edited live. Needs a terminal; \
                scripts use the subcommands.",
        flags: &[],
        scene: true,
        formats: &[],
        example: "--preset ice-frost",
    },
    Sub {
        name: "eps",
        usage: "eps (--g LIST | --g-file FILE) [OPTIONS]",
        about: "ε_N, status, contact time and maximum compression at impact speeds, in the order given. \
                --g-file streams a file of speeds (one per line, # comments) through the batch path.",
        flags: &[
            f(
                "--g",
                "LIST",
                "impact speeds, comma-separated; units allowed (0.01, \"2 mm/s\")",
            ),
            f("--g-file", "FILE", "a file of speeds in m/s, one per line"),
        ],
        scene: true,
        formats: ALL_FORMATS,
        example: "eps --g \"1 mm/s,1 cm/s\" --preset ice-frost",
    },
    Sub {
        name: "curve",
        usage: "curve --from G --to G [--points N] [OPTIONS]",
        about: "The records of eps on N log-spaced speeds, both ends included; powers of ten are exact.",
        flags: &[
            f(
                "--from",
                "G",
                "lowest speed; units allowed (1e-6, \"1 um/s\")",
            ),
            f("--to", "G", "highest speed; units allowed"),
            f(
                "--points",
                "N",
                "number of speeds, 1 to 100000 (default 400)",
            ),
        ],
        scene: true,
        formats: ALL_FORMATS,
        example: "curve --from 1e-6 --to 1 --points 7",
    },
    Sub {
        name: "tangential",
        usage: "tangential --gn LIST --gt LIST [OPTIONS]",
        about: "ε_T and the stick class for every (g_N, g_T) combination, g_N outer.",
        flags: &[
            f(
                "--gn",
                "LIST",
                "normal speeds, comma-separated; units allowed",
            ),
            f(
                "--gt",
                "LIST",
                "tangential speeds, comma-separated; units allowed",
            ),
        ],
        scene: true,
        formats: ALL_FORMATS,
        example: "tangential --gn 1cm/s --gt 1mm/s,5cm/s",
    },
    Sub {
        name: "map",
        usage: "map --max G [--n N] [OPTIONS]",
        about: "Stick-map classes and ε_T on an N×N grid of (g_N, g_T) from 0 to G.",
        flags: &[
            f(
                "--max",
                "G",
                "largest speed of the grid; units allowed (5cm/s)",
            ),
            f("--n", "N", "grid points per axis, 2 to 2000 (default 200)"),
        ],
        scene: true,
        formats: ALL_FORMATS,
        example: "map --max 5cm/s --n 40 --format csv",
    },
    Sub {
        name: "tidal",
        usage: "tidal [--planet-mass M] [--distance D] [--radius R] [--density RHO] [--surface-energy G] [OPTIONS]",
        about: "The appendix's tidal estimate (Eq. (A.1)–(A.7)): forces, Roche distance, largest grain.",
        flags: &[
            f("--planet-mass", "M", "planet mass, kg (default Saturn)"),
            f(
                "--distance",
                "D",
                "distance from the planet; units allowed (m, km…)",
            ),
            f("--radius", "R", "grain radius; units allowed (m, cm…)"),
            f(
                "--density",
                "RHO",
                "grain density; units allowed (kg/m^3, g/cm^3)",
            ),
            f(
                "--surface-energy",
                "G",
                "surface energy; units allowed (J/m^2, mJ/m^2)",
            ),
        ],
        scene: false,
        formats: ALL_FORMATS,
        example: "tidal --distance 1.2e8 --radius \"1 cm\"",
    },
    Sub {
        name: "ring",
        usage: "ring --tau T (--omega W | --planet-mass M --distance D) [--radius R [--scale-damping] | --radii R1..R2 --q Q [--bins N] | --radii LIST --fractions LIST] [--damping-rule RULE] [OPTIONS]",
        about: "What the scene's law does to a ring: equilibrium velocity dispersion, thickness and \
                verdict (equilibrium, monolayer_floor, aggregates, heats), smooth and rough.",
        flags: &[
            f("--tau", "T", "normal optical depth, in (0, 5]"),
            f("--omega", "W", "orbital frequency, 1/s"),
            f(
                "--planet-mass",
                "M",
                "planet mass, kg (with --distance, instead of --omega)",
            ),
            f(
                "--distance",
                "D",
                "distance from the planet's centre; units allowed (m, km…)",
            ),
            f(
                "--radius",
                "R",
                "both grains' radius; units allowed (m, cm…)",
            ),
            switch(
                "--scale-damping",
                "use A' = A·R/R_scene (keeps ε_N(g); a different material)",
            ),
            f(
                "--radii",
                "R1..R2|LIST",
                "a ring of many sizes: a range (with --q) or a comma list (with --fractions); units allowed",
            ),
            f(
                "--q",
                "Q",
                "power-law exponent of dN/dR ∝ R^−q (with a range of --radii)",
            ),
            f(
                "--bins",
                "N",
                "bins equal in log R (with a range of --radii; default 3)",
            ),
            f(
                "--fractions",
                "LIST",
                "number fractions of a list of --radii, comma-separated, summing to 1",
            ),
            f(
                "--damping-rule",
                "RULE",
                "A across sizes: same (the scene's A, default) or keep_epsilon (every pair keeps the scene's ε_N(g))",
            ),
        ],
        scene: true,
        formats: ALL_FORMATS,
        example: "ring --preset ice --tau 0.5 --radius 0.02 --omega 1.3143527e-4",
    },
    Sub {
        name: "scene",
        usage: "scene [--out FILE] [OPTIONS]",
        about: "Print the scene JSON (after --scene/--preset/--set), or write it atomically with --out. \
                JSON only.",
        flags: &[f(
            "--out",
            "FILE",
            "write the scene to FILE instead of stdout",
        )],
        scene: true,
        formats: &["json"],
        example: "scene --preset ice-frost --set layer.viscosity=\"2 kPa s\" --out my.json",
    },
    Sub {
        name: "export",
        usage: "export (--out DIR [--from G --to G --points N] [--runtime-params] | --lammps DIR [--lammps-adhesion jkr]) [OPTIONS]",
        about: "Write ε_N tables (CSV, JSON), fitted Eq. (27) and power laws, C99 and no_std Rust ε_N, ε_T and \
                collision kinematics (fast: 1e-6, precise: 1e-10 at every speed), and a REBOUND collision \
                handler with its Python recipe into DIR. With --lammps DIR instead: a LAMMPS input deck for two \
                grains of the scene (pair_style granular), the ε_N, t_c and ξ_max it must reproduce, and a README \
                with every mapping.",
        flags: &[
            f(
                "--out",
                "DIR",
                "directory to write into (required unless --lammps)",
            ),
            f(
                "--lammps",
                "DIR",
                "write a LAMMPS deck (in.rime), reference.tsv and README.md into DIR instead",
            ),
            f(
                "--lammps-adhesion",
                "MAP",
                "with --lammps, for an adhesive scene: the model to export (jkr: LAMMPS's jkr = brilliantov2007)",
            ),
            f(
                "--from",
                "G",
                "lowest tabulated speed (default 1e-6 m/s); units allowed",
            ),
            f(
                "--to",
                "G",
                "highest tabulated speed (default 1 m/s); units allowed",
            ),
            f(
                "--points",
                "N",
                "tabulated speeds, 8 to 100000 (default 200)",
            ),
            switch(
                "--runtime-params",
                "A, radii, layer and γ become arguments of the exported functions",
            ),
        ],
        scene: true,
        formats: &[],
        example: "export --preset ice-frost --out my-laws --accuracy precise",
    },
    Sub {
        name: "fit",
        usage: "fit (--data FILE.csv | --law ID [--radius R]) [--param P1,P2] [OPTIONS]",
        about: "Fit scene parameters (default bulk.damping.time) to measured (g [m/s], ε[, σ]) points or an \
                atlas law, with standard errors and correlations.",
        flags: &[
            f(
                "--data",
                "FILE",
                "measured points: g, ε[, σ] per line; header units read (g [cm/s]), else m/s",
            ),
            f(
                "--law",
                "ID",
                "fit to an atlas law instead (rime data lists them)",
            ),
            f(
                "--radius",
                "R",
                "reduced radius in m, for laws that need it",
            ),
            f(
                "--param",
                "LIST",
                "parameters to fit, comma-separated dotted paths",
            ),
        ],
        scene: true,
        formats: &["json", "table"],
        example: "fit --law bridges1984 --param bulk.damping.time",
    },
    Sub {
        name: "data",
        usage: "data [--law ID --g LIST [--radius R]] [OPTIONS]",
        about: "The atlas of measured ice, or one law evaluated at speeds.",
        flags: &[
            f("--law", "ID", "evaluate this law"),
            f("--g", "LIST", "speeds, comma-separated; units allowed"),
            f(
                "--radius",
                "R",
                "reduced radius in m, for laws that need it",
            ),
        ],
        scene: true,
        formats: ALL_FORMATS,
        example: "data --law bridges1984 --g 1e-4,1e-3,1cm/s",
    },
    Sub {
        name: "stick",
        usage: "stick --radius LIST [--temperature LIST] [--gamma surface|adhesion] [--out DIR] [OPTIONS]",
        about: "Sticking thresholds v_stick(r, T) with γ(T) of Musiolik & Wurm 2019; --out also writes a \
                table and a standalone C function.",
        flags: &[
            f("--radius", "LIST", "grain radii in m, comma-separated"),
            f(
                "--temperature",
                "LIST",
                "temperatures in K (default 150,180,190,200)",
            ),
            f(
                "--gamma",
                "READING",
                "surface (γ is a surface energy, default) or adhesion (work of adhesion)",
            ),
            f(
                "--out",
                "DIR",
                "also write stick_table.csv and rime_v_stick.c",
            ),
        ],
        scene: true,
        formats: ALL_FORMATS,
        example: "stick --radius 1e-6,1e-4 --temperature 150,200",
    },
    Sub {
        name: "kernel",
        usage: "kernel --radii R1..R2|LIST [--points N] [--temperatures LIST] [--a-rule RULE] [--svg FILE] [OPTIONS]",
        about: "The sticking kernel for dust codes: v_stick(a_i, a_j, T) of every pair of radii at every \
                temperature (γ(T) of Musiolik & Wurm 2019), with its provenance; --svg draws \
                v_stick(a, a) per temperature with the measured 9.6 m/s of µm ice.",
        flags: &[
            f(
                "--radii",
                "R1..R2|LIST",
                "a range, spaced equally in log (with --points), or a comma list; units allowed (1um..1cm)",
            ),
            f(
                "--points",
                "N",
                "radii in a range (default 20, at most 1000)",
            ),
            f(
                "--temperatures",
                "LIST",
                "temperatures in K (default 150,180,200)",
            ),
            f(
                "--a-rule",
                "RULE",
                "A across sizes: given (default), keep-epsilon (A ∝ R_eff^-1/5 m_eff^2/5 from the scene's pair), fit-measured (one A fitted to 9.6 m/s, Gundlach & Blum 2015)",
            ),
            f(
                "--fit-radius",
                "R",
                "fit-measured: both grains' radius of the reference pair (default 1.5 µm)",
            ),
            f(
                "--fit-temperature",
                "T",
                "fit-measured: temperature of the reference pair in K (default 200)",
            ),
            f(
                "--temperature-rule",
                "RULE",
                "outside γ(T)'s measured 175–200 K: hold (end values, default) or refuse",
            ),
            f(
                "--gamma",
                "READING",
                "surface (γ is a surface energy, default) or adhesion (work of adhesion)",
            ),
            f(
                "--svg",
                "FILE",
                "also draw v_stick(a, a) against a per temperature",
            ),
        ],
        scene: true,
        formats: ALL_FORMATS,
        example: "kernel --radii 1um..1cm --points 20 --temperatures 150,200",
    },
    Sub {
        name: "collision",
        usage: "collision --g G [--gt G] [--points N] [OPTIONS]",
        about: "One collision from the inside: ξ(t), ξ'(t), the normal force F(t), its phases and the \
                energy ledger (each term a quadrature of its own force); --gt adds the tangential side.",
        flags: &[
            f("--g", "G", "normal impact speed (m/s, units allowed)"),
            f(
                "--gt",
                "G",
                "tangential speed (m/s): adds ε_T, friction work and the spin change",
            ),
            f("--points", "N", "samples in time (default 400)"),
        ],
        scene: true,
        formats: ALL_FORMATS,
        example: "collision --g 0.01 --gt 0.005 --points 50 --format json",
    },
    Sub {
        name: "figures",
        usage: "figures [--out DIR] [--accuracy LEVEL] | figures --explorer [scene] [OPTIONS]",
        about: "The paper's Figs. 2–4 rebuilt from the model, SVG + PNG, with captions.txt (their \
                scenes are the paper's; only --accuracy applies). With --explorer: a scene's ε_N chart and stick map with \
                their records, exactly as the explorer's x and the page's downloads draw them.",
        flags: &[
            f("--out", "DIR", "directory to write into (default figures)"),
            f(
                "--accuracy",
                "LEVEL",
                "precise (default: fine table, ε_N error ≤ 1e-10) | fast (coarse table, ≤ 1e-6) | integrated (integrates each contact, ≤ 1e-6, slowest) | a tolerance like 1e-8",
            ),
            switch(
                "--explorer",
                "the explorer's figures and records of the scene (takes --scene/--preset/--set)",
            ),
            f(
                "--from",
                "G",
                "--explorer: lowest chart speed (default: the explorer's range)",
            ),
            f("--to", "G", "--explorer: highest chart speed"),
            f(
                "--points",
                "N",
                "--explorer: points per curve (default 241)",
            ),
            f(
                "--max",
                "G",
                "--explorer: stick-map range (default: automatic)",
            ),
            f("--n", "N", "--explorer: stick-map side (default 81)"),
            switch("--y-log", "--explorer: ε_N on a log axis"),
            f(
                "--overlays",
                "LIST",
                "--explorer: comparisons, e.g. atlas:bridges1984,model:thornton1997",
            ),
            switch(
                "--no-experiments",
                "--explorer: leave out the experimental context",
            ),
        ],
        scene: true,
        formats: &[],
        example: "figures --explorer --preset ice-frost --y-log --out fig",
    },
    Sub {
        name: "compare",
        usage: "compare (--models LIST --g LIST | --list | --bench) [OPTIONS]",
        about: "ε_N of several models side by side and their characteristic speeds (g_cr, v_yield, …).",
        flags: &[
            f(
                "--models",
                "LIST",
                "models, comma-separated (default: all that apply)",
            ),
            f("--g", "LIST", "speeds, comma-separated; units allowed"),
            switch("--list", "name every model with its citation"),
            switch("--bench", "cost per ε_N of each model at each level"),
        ],
        scene: true,
        formats: ALL_FORMATS,
        example: "compare --models hertzsch2002,brilliantov2007 --g 1mm/s,1cm/s",
    },
    Sub {
        name: "bench",
        usage: "bench [--out DIR] [--quick] [--frames]",
        about: "Speed and accuracy of every model and level; writes DIR/bench.json and \
                DIR/work-precision.svg (its scenes are fixed). With --frames: the explorer's \
                input → first and final frame per level, scene and terminal size; writes \
                DIR/frames.json.",
        flags: &[
            f(
                "--out",
                "DIR",
                "directory to write into (default target/bench)",
            ),
            switch(
                "--quick",
                "short timing samples (seconds instead of half a minute)",
            ),
            switch(
                "--frames",
                "time the explorer's frames (input → first and final frame)",
            ),
        ],
        scene: false,
        formats: &[],
        example: "bench --quick --out target/bench",
    },
    Sub {
        name: "completions",
        usage: "completions bash|zsh|fish",
        about: "Print a shell completion script, e.g. `rime completions bash > ~/.local/share/bash-completion/completions/rime`.",
        flags: &[],
        scene: false,
        formats: &[],
        example: "completions fish > ~/.config/fish/completions/rime.fish",
    },
    Sub {
        name: "man",
        usage: "man",
        about: "Print the manual page (roff), e.g. `rime man | man -l -`.",
        flags: &[],
        scene: false,
        formats: &[],
        example: "man > rime.1",
    },
    Sub {
        name: "help",
        usage: "help [SUBCOMMAND]",
        about: "The overview, or one subcommand's help.",
        flags: &[],
        scene: false,
        formats: &[],
        example: "help eps",
    },
];

/// The subcommand called `name` (`""`: the explorer).
pub fn find(name: &str) -> Option<&'static Sub> {
    SUBS.iter().find(|s| s.name == name)
}

impl Sub {
    /// Every flag this subcommand accepts, in help order (without --help/--version).
    pub fn accepted(&self) -> Vec<Flag> {
        let mut v: Vec<Flag> = self.flags.to_vec();
        if self.scene {
            v.extend(SCENE_FLAGS.iter().copied());
        }
        if !self.formats.is_empty() {
            v.push(FORMAT_FLAG);
        }
        v
    }

    /// `rime eps` (or `rime` for the explorer).
    pub fn command(&self) -> String {
        if self.name.is_empty() {
            "rime".into()
        } else {
            format!("rime {}", self.name)
        }
    }
}

fn flag_line(fl: &Flag) -> String {
    let left = match fl.value {
        Some(v) => format!("{} {v}", fl.name),
        None => fl.name.to_string(),
    };
    wrap(&format!("  {left:<24} "), fl.help, 27) + "\n"
}

/// The width help pages wrap to: an 80-column terminal shows them without its own wrapping
/// mid-phrase (issue 37: lines of 93–105 columns).
pub const HELP_WIDTH: usize = 80;

/// Wraps `text` after the verbatim `prefix` at [`HELP_WIDTH`] columns, continuation lines indented
/// by `indent` spaces.
pub(crate) fn wrap(prefix: &str, text: &str, indent: usize) -> String {
    let mut out = prefix.to_string();
    let mut width = prefix.chars().count();
    for (k, word) in text.split_whitespace().enumerate() {
        let n = word.chars().count();
        if k > 0 && width + 1 + n > HELP_WIDTH {
            out.push('\n');
            out.push_str(&" ".repeat(indent));
            width = indent;
        } else if k > 0 {
            out.push(' ');
            width += 1;
        }
        out.push_str(word);
        width += n;
    }
    out
}

impl Sub {
    /// The first sentence of `about` (a period followed by a capital ends it), without the period.
    pub fn summary(&self) -> &'static str {
        let a = self.about;
        let end = a
            .match_indices(". ")
            .find(|(i, _)| a[i + 2..].starts_with(|c: char| c.is_uppercase()))
            .map_or(a.len(), |(i, _)| i);
        a[..end].trim_end_matches('.')
    }
}

/// `rime <sub> --help`.
pub fn sub_help(sub: &Sub) -> String {
    let mut s = format!(
        "{}\n\nUSAGE:\n{}\n\n",
        wrap(&format!("{} — ", sub.command()), sub.about, 2),
        wrap("  rime ", sub.usage, 4)
    );
    s.push_str("OPTIONS:\n");
    let restricted = !sub.formats.is_empty() && sub.formats.len() < ALL_FORMATS.len();
    let own_formats = format!("{} only", sub.formats.join(" | "));
    for fl in sub.accepted().iter().chain(GLOBAL_FLAGS) {
        // A subcommand with fewer formats names its own (issue 37: `fit --help` said
        // "json | csv | table" and then "json or table only").
        if fl.name == FORMAT_FLAG.name && restricted {
            s.push_str(&wrap(
                &format!("  {:<24} ", "--format FORMAT"),
                &own_formats,
                27,
            ));
            s.push('\n');
        } else {
            s.push_str(&flag_line(fl));
        }
    }
    s.push_str(&format!(
        "\nEXAMPLE:\n{}\n",
        wrap("  rime ", sub.example, 4)
    ));
    s.push('\n');
    s.push_str(EXIT_CODES);
    s
}

/// What every help page says about errors, as docs/cli.md does: 2 for bad input, 1 for a failed
/// computation (issue 37: the help said every error exits 2).
pub const EXIT_CODES: &str = "Errors are one line naming the flag. Exit codes: 0 success; 2 bad input (a flag,\n\
     a value, a scene field, a file); 1 a computation that failed on valid input\n\
     (docs/cli.md).\n";

/// `rime --help`: the overview.
pub fn usage() -> String {
    let mut s = String::from("rime — slow collisions of icy grains (Hertzsch 2002)\n\nUSAGE:\n");
    for sub in SUBS {
        s.push_str(&wrap("  rime ", sub.usage, 4));
        s.push('\n');
    }
    s.push_str("\nSUBCOMMANDS:\n");
    for sub in SUBS.iter().filter(|s| !s.name.is_empty()) {
        s.push_str(&wrap(&format!("  {:<12} ", sub.name), sub.summary(), 15));
        s.push('\n');
    }
    s.push_str("\nOPTIONS (of the subcommands that read a scene or print a table):\n");
    for fl in SCENE_FLAGS
        .iter()
        .chain(std::iter::once(&FORMAT_FLAG))
        .chain(GLOBAL_FLAGS)
    {
        s.push_str(&flag_line(fl));
    }
    s.push_str("\nrime help SUB (or rime SUB --help) shows a subcommand's flags and an example.\n");
    s.push_str(EXIT_CODES);
    s
}

fn sub_names() -> Vec<&'static str> {
    SUBS.iter()
        .map(|s| s.name)
        .filter(|n| !n.is_empty())
        .collect()
}

fn all_flags(sub: &Sub) -> Vec<Flag> {
    let mut v = sub.accepted();
    v.extend(GLOBAL_FLAGS.iter().copied());
    v
}

/// The words a flag's value completes to (`--preset` → the preset names), if it has a fixed set.
fn value_words(flag: &str) -> Option<String> {
    Some(match flag {
        "--preset" => rime_core::Preset::ALL
            .iter()
            .map(|p| p.name())
            .collect::<Vec<_>>()
            .join(" "),
        "--accuracy" => "fast precise integrated".to_string(),
        "--format" => "json csv table".to_string(),
        "--gamma" => "surface adhesion".to_string(),
        "--damping-rule" => "same keep_epsilon".to_string(),
        // Parameter paths, each ready for its value (issue 37: flags were offered after --set).
        "--set" => rime_core::params::PARAMETERS
            .iter()
            .chain(rime_core::params::MODEL_PARAMETERS)
            .map(|p| format!("{}=", p.path))
            .collect::<Vec<_>>()
            .join(" "),
        _ => return None,
    })
}

/// Flags whose value is a path.
const PATH_FLAGS: [&str; 4] = ["--scene", "--data", "--out", "--g-file"];

/// `rime completions bash|zsh|fish`.
// Long by design: three shells' completion scripts, each a template generated from the one flag
// table.
pub fn completions(shell: &str) -> Option<String> {
    let names = sub_names();
    let valued = ["--preset", "--accuracy", "--format", "--gamma", "--set"];
    Some(match shell {
        "bash" => {
            let mut s = String::from(
                "# bash completion for rime (rime completions bash)\n_rime() {\n  local cur sub\n  \
                 cur=\"${COMP_WORDS[COMP_CWORD]}\"\n  sub=\"${COMP_WORDS[1]}\"\n  \
                 if [ \"$COMP_CWORD\" -eq 1 ] && [[ \"$cur\" != -* ]]; then\n",
            );
            s.push_str(&format!(
                "    COMPREPLY=($(compgen -W \"{}\" -- \"$cur\"))\n    return\n  fi\n",
                names.join(" ")
            ));
            // A flag's value first: preset names after --preset, paths after --scene, …
            s.push_str("  case \"${COMP_WORDS[COMP_CWORD-1]}\" in\n");
            for flag in valued {
                if let Some(words) = value_words(flag) {
                    // A path= waits for its value: no space after it.
                    let nospace = if flag == "--set" {
                        "compopt -o nospace 2>/dev/null; "
                    } else {
                        ""
                    };
                    s.push_str(&format!(
                        "    {flag}) {nospace}COMPREPLY=($(compgen -W \"{words}\" -- \"$cur\")); return ;;\n"
                    ));
                }
            }
            s.push_str(&format!(
                "    {}) COMPREPLY=($(compgen -f -- \"$cur\")); return ;;\n  esac\n  case \"$sub\" in\n",
                PATH_FLAGS.join("|")
            ));
            for sub in SUBS.iter().filter(|s| !s.name.is_empty()) {
                let flags: Vec<&str> = all_flags(sub).iter().map(|f| f.name).collect();
                let words = if sub.name == "completions" {
                    "bash zsh fish".to_string()
                } else if sub.name == "help" {
                    names.join(" ")
                } else {
                    flags.join(" ")
                };
                s.push_str(&format!(
                    "    {}) COMPREPLY=($(compgen -W \"{words}\" -- \"$cur\")) ;;\n",
                    sub.name
                ));
            }
            let explorer: Vec<&str> = SUBS
                .first()
                .map(|e| all_flags(e).iter().map(|f| f.name).collect())
                .unwrap_or_default();
            s.push_str(&format!(
                "    *) COMPREPLY=($(compgen -W \"{}\" -- \"$cur\")) ;;\n  esac\n}}\ncomplete -o default -F _rime rime\n",
                explorer.join(" ")
            ));
            s
        }
        "zsh" => {
            let mut s = String::from(
                "#compdef rime\n# zsh completion for rime (rime completions zsh)\n_rime() {\n  \
                 if (( CURRENT == 2 )); then\n    local -a subs\n    subs=(\n",
            );
            for sub in SUBS.iter().filter(|s| !s.name.is_empty()) {
                s.push_str(&format!(
                    "      '{}:{}'\n",
                    sub.name,
                    zsh_quote(sub.summary())
                ));
            }
            s.push_str(
                "    )\n    _describe 'subcommand' subs\n    return\n  fi\n  case $words[2] in\n",
            );
            for sub in SUBS.iter().filter(|s| !s.name.is_empty()) {
                s.push_str(&format!("    {})\n      _arguments \\\n", sub.name));
                for fl in all_flags(sub) {
                    let words = value_words(fl.name);
                    let action = match (fl.value, &words) {
                        (Some(_), Some(w)) => format!(":value:({w})"),
                        (Some("FILE") | Some("DIR"), _) => ":file:_files".to_string(),
                        (Some(_), None) if PATH_FLAGS.contains(&fl.name) => {
                            ":file:_files".to_string()
                        }
                        (Some(_), None) => ":value: ".to_string(),
                        (None, _) => String::new(),
                    };
                    s.push_str(&format!(
                        "        '{}[{}]{action}' \\\n",
                        fl.name,
                        zsh_quote(fl.help)
                    ));
                }
                if sub.name == "completions" {
                    s.push_str("        ':shell:(bash zsh fish)' \\\n");
                }
                s.push_str("        && return 0 ;;\n");
            }
            s.push_str("  esac\n}\n_rime \"$@\"\n");
            s
        }
        "fish" => {
            let mut s = String::from(
                "# fish completion for rime (rime completions fish)\ncomplete -c rime -f\n",
            );
            for sub in SUBS.iter().filter(|s| !s.name.is_empty()) {
                s.push_str(&format!(
                    "complete -c rime -n __fish_use_subcommand -a {} -d '{}'\n",
                    sub.name,
                    fish_quote(sub.summary())
                ));
            }
            for sub in SUBS {
                let cond = if sub.name.is_empty() {
                    "__fish_use_subcommand".to_string()
                } else {
                    format!("'__fish_seen_subcommand_from {}'", sub.name)
                };
                for fl in all_flags(sub) {
                    let req = match (fl.value, value_words(fl.name)) {
                        (Some(_), Some(w)) => format!(" -x -a '{w}'"),
                        (Some("FILE") | Some("DIR"), None) => " -r -F".to_string(),
                        (Some(_), None) if PATH_FLAGS.contains(&fl.name) => " -r -F".to_string(),
                        (Some(_), None) => " -x".to_string(),
                        (None, _) => String::new(),
                    };
                    s.push_str(&format!(
                        "complete -c rime -n {cond} -l {}{req} -d '{}'\n",
                        fl.name.trim_start_matches("--"),
                        fish_quote(fl.help)
                    ));
                }
            }
            s.push_str(
                "complete -c rime -n '__fish_seen_subcommand_from completions' -a 'bash zsh fish'\n",
            );
            s
        }
        _ => return None,
    })
}

fn zsh_quote(s: &str) -> String {
    s.replace('\'', "'\\''")
        .replace('[', "(")
        .replace(']', ")")
        .replace(':', " -")
}

fn fish_quote(s: &str) -> String {
    s.replace('\\', "\\\\").replace('\'', "\\'")
}

fn roff(s: &str) -> String {
    s.replace('\\', "\\e").replace('-', "\\-")
}

/// `rime man`: the manual page in roff.
pub fn man_page() -> String {
    let mut s = format!(
        ".TH RIME 1 \"\" \"rime {}\" \"User Commands\"\n.SH NAME\nrime \\- slow collisions of icy grains (Hertzsch 2002)\n.SH SYNOPSIS\n",
        env!("CARGO_PKG_VERSION")
    );
    for sub in SUBS {
        s.push_str(&format!(".B rime\n{}\n.br\n", roff(sub.usage)));
    }
    s.push_str(
        ".SH DESCRIPTION\nThe terminal explorer and scriptable subcommands of rime. JSON field names, \
         status and class names are a contract (docs/cli.md). Errors are one line naming the flag, \
         with exit status 2.\n.SH SUBCOMMANDS\n",
    );
    for sub in SUBS {
        let title = if sub.name.is_empty() {
            "rime (no subcommand)".to_string()
        } else {
            format!("rime {}", sub.name)
        };
        s.push_str(&format!(".SS {}\n{}\n", roff(&title), roff(sub.about)));
        for fl in sub.flags {
            s.push_str(&man_flag(fl));
        }
        s.push_str(&format!(
            ".PP\nExample:\n.RS\n.nf\nrime {}\n.fi\n.RE\n",
            roff(sub.example)
        ));
    }
    s.push_str(".SH OPTIONS\nTaken by every subcommand that reads a scene or prints a table:\n");
    for fl in SCENE_FLAGS
        .iter()
        .chain(std::iter::once(&FORMAT_FLAG))
        .chain(GLOBAL_FLAGS)
    {
        s.push_str(&man_flag(fl));
    }
    s.push_str(".SH EXIT STATUS\n0 on success, 1 when a computation fails, 2 on bad input.\n");
    s
}

fn man_flag(fl: &Flag) -> String {
    let value = fl
        .value
        .map(|v| format!(" \\fI{}\\fR", roff(v)))
        .unwrap_or_default();
    format!(".TP\n\\fB{}\\fR{value}\n{}\n", roff(fl.name), roff(fl.help))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_accepted_flag_is_in_help_completions_and_man() {
        let man = man_page();
        let shells: Vec<String> = ["bash", "zsh", "fish"]
            .iter()
            .map(|sh| completions(sh).unwrap())
            .collect();
        for sub in SUBS {
            let help = sub_help(sub);
            for fl in all_flags(sub) {
                assert!(help.contains(fl.name), "{}: {}", sub.name, fl.name);
                assert!(man.contains(&roff(fl.name)), "man: {}", fl.name);
                for (sh, text) in ["bash", "zsh", "fish"].iter().zip(&shells) {
                    let needle = if *sh == "fish" {
                        format!("-l {}", fl.name.trim_start_matches("--"))
                    } else {
                        fl.name.to_string()
                    };
                    assert!(text.contains(&needle), "{sh}: {}", fl.name);
                }
            }
        }
    }
}
