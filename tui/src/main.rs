//! `rime`: the terminal explorer and the scriptable subcommands.

mod bench;
mod cli;
mod codegen;
mod commands;
mod eps_file;
mod explore;
mod export;
mod output;
mod scene_io;

use cli::{Command, Common};
use output::{EpsRecord, MapRecord, TangentialRecord, render};
use rime_core::sweep;
use scene_io::{CliError, CliResult};
use std::io::Write;
use std::process::ExitCode;

fn run_eps(common: &Common, speeds: &[f64]) -> CliResult<String> {
    let contact = cli::contact(common)?;
    let mut records = Vec::with_capacity(speeds.len());
    for &g in speeds {
        let n = contact
            .normal(g, common.accuracy)
            .map_err(|e| CliError(format!("g_n = {g}: {e}")))?;
        records.push(EpsRecord::new(g, &n));
    }
    render(&records, common.format).map_err(CliError)
}

fn run_tangential(common: &Common, gn: &[f64], gt: &[f64]) -> CliResult<String> {
    let contact = cli::contact(common)?;
    if contact.friction.is_none() {
        return Err(CliError(
            "friction: is off in this scene; tangential restitution needs it (--set friction=on)"
                .into(),
        ));
    }
    let mut records = Vec::with_capacity(gn.len() * gt.len());
    for &n in gn {
        for &t in gt {
            let r = contact
                .tangential(n, t, common.accuracy)
                .map_err(|e| CliError(format!("g_n = {n}, g_t = {t}: {e}")))?;
            records.push(TangentialRecord {
                g_n: n,
                g_t: t,
                eps_t: r.eps_t,
                eps_n: r.eps_n,
                class: r.class.name(),
            });
        }
    }
    render(&records, common.format).map_err(CliError)
}

fn run_map(common: &Common, max: f64, n: usize) -> CliResult<String> {
    let contact = cli::contact(common)?;
    if contact.friction.is_none() {
        return Err(CliError(
            "friction: is off in this scene; the stick map needs it (--set friction=on)".into(),
        ));
    }
    let map = sweep::StickMap::new(&contact, max, n, common.accuracy)?;
    let rows = |f: &dyn Fn(usize) -> f64| -> Vec<Vec<f64>> {
        (0..n)
            .map(|i| (0..n).map(|j| f(i * n + j)).collect())
            .collect()
    };
    let record = MapRecord {
        g: map.g.clone(),
        class: (0..n)
            .map(|i| (0..n).map(|j| map.class[i * n + j].name()).collect())
            .collect(),
        eps_t: rows(&|k| map.eps_t[k]),
        eps_n: map.eps_n.clone(),
    };
    Ok(match common.format {
        cli::Format::Json => {
            serde_json::to_string(&record).map_err(|e| CliError(e.to_string()))? + "\n"
        }
        cli::Format::Csv => {
            let mut s = String::from("g_n,g_t,eps_t,class\n");
            for i in 0..n {
                for j in 0..n {
                    s.push_str(&format!(
                        "{},{},{},{}\n",
                        output::num(map.g[i]),
                        output::num(map.g[j]),
                        output::num(map.eps_t[i * n + j]),
                        map.class[i * n + j].name()
                    ));
                }
            }
            s
        }
        cli::Format::Table => {
            // One letter per cell, g_T to the right, g_N upwards, with a legend.
            use rime_core::tangential::StickClass;
            let mut s = format!("g_N ↑ (0 … {max} m/s), g_T → (0 … {max} m/s)\n");
            for i in (0..n).rev() {
                for j in 0..n {
                    s.push(map.class[i * n + j].letter());
                }
                s.push('\n');
            }
            for c in StickClass::ALL {
                s.push_str(&format!("  {}  {}\n", c.letter(), c.name()));
            }
            s
        }
    })
}

fn run_tidal(common: &Common, input: &rime_core::tidal::TidalInput) -> CliResult<String> {
    let t = rime_core::tidal::tidal(input)?;
    let values: Vec<(&str, Option<f64>, &str)> = vec![
        ("planet_mass", Some(input.planet_mass), "kg"),
        ("distance", Some(input.distance), "m"),
        ("radius", Some(input.radius), "m"),
        ("density", Some(input.density), "kg/m3"),
        ("surface_energy", Some(input.surface_energy), "J/m2"),
        ("grain_mass", Some(t.mass), "kg"),
        ("delta_f", Some(t.delta_f), "N"),
        ("delta_f_approx", Some(t.delta_f_approx), "N"),
        ("surface_force", Some(t.surface_force), "N"),
        ("surface_force_paper", Some(t.surface_force_paper), "N"),
        ("gravity", Some(t.gravity), "N"),
        ("d_roche", Some(t.d_roche), "m"),
        ("d_min", Some(t.d_min), "m"),
        ("r_max", t.r_max, "m"),
    ];
    Ok(match common.format {
        cli::Format::Json => {
            let mut map = serde_json::Map::new();
            for (k, v, _) in &values {
                map.insert(
                    k.to_string(),
                    v.map_or(serde_json::Value::Null, serde_json::Value::from),
                );
            }
            serde_json::to_string_pretty(&map).map_err(|e| CliError(e.to_string()))? + "\n"
        }
        cli::Format::Csv => {
            let mut s = String::from("name,value,unit\n");
            for (k, v, u) in &values {
                s.push_str(&format!(
                    "{k},{},{u}\n",
                    v.map(output::num).unwrap_or_default()
                ));
            }
            s
        }
        cli::Format::Table => {
            let rows: Vec<Vec<String>> = values
                .iter()
                .map(|(k, v, u)| {
                    vec![
                        k.to_string(),
                        v.map(output::num).unwrap_or_else(|| "none".into()),
                        u.to_string(),
                    ]
                })
                .collect();
            output::table(&["name", "value", "unit"], &rows)
        }
    })
}

fn run_curve(common: &Common, from: f64, to: f64, n: usize) -> CliResult<String> {
    let contact = cli::contact(common)?;
    let (g, normals) = sweep::curve(&contact, from, to, n, common.accuracy)?;
    let records: Vec<EpsRecord> = g
        .iter()
        .zip(&normals)
        .map(|(&g, n)| EpsRecord::new(g, n))
        .collect();
    render(&records, common.format).map_err(CliError)
}

fn run(command: Command) -> CliResult<Option<String>> {
    Ok(Some(match command {
        Command::Help => format!("{}\n", cli::USAGE),
        Command::Version => format!("rime {}\n", env!("CARGO_PKG_VERSION")),
        Command::Scene(c, None) => cli::scene_text(&c)?,
        Command::Scene(c, Some(path)) => {
            scene_io::write_atomic(&path, cli::scene_text(&c)?.as_bytes())?;
            return Ok(None);
        }
        Command::Eps(c, g) => run_eps(&c, &g)?,
        Command::EpsFile(c, path) => {
            eps_file::run(&c, &path)?;
            return Ok(None);
        }
        Command::Compare(c, a) => commands::compare::run(&c, &a)?,
        Command::Curve(c, from, to, n) => run_curve(&c, from, to, n)?,
        Command::Tangential(c, gn, gt) => run_tangential(&c, &gn, &gt)?,
        Command::Map(c, max, n) => run_map(&c, max, n)?,
        Command::Tidal(c, input) => run_tidal(&c, &input)?,
        Command::Export(c, from, to, n, out, runtime_params) => {
            let scene = scene_io::scene_json(&c.scene)?;
            let law = codegen::Law::new(&c.scene, c.accuracy, &scene, runtime_params)?;
            let e = export::compute(&c.scene, from, to, n, c.accuracy)?;
            let files = export::write_all(&out, &e, &scene, &law)?;
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
            s
        }
        Command::Fit(c, a) => commands::fit::run(&c, &a)?,
        Command::Data(c, a) => commands::data::run(&c, &a)?,
        Command::Stick(c, a) => commands::stick::run(&c, &a)?,
        Command::Collision(c, a) => commands::collision::run(&c, &a)?,
        Command::Figures(c, out) => {
            std::fs::create_dir_all(&out)
                .map_err(|e| CliError(format!("--out {}: {e}", out.display())))?;
            let figures = rime_core::figure::paper::all(c.accuracy, 160)?;
            let mut s = String::new();
            for f in &figures {
                let svg = rime_core::figure::render_svg(f, 1000, 680)?;
                scene_io::write_atomic(&out.join(format!("{}.svg", f.name)), svg.as_bytes())?;
                let png = out.join(format!("{}.png", f.name));
                let tmp = out.join(format!(".{}.tmp.png", f.name));
                rime_core::figure::render_png(f, &tmp, 1000, 680)?;
                std::fs::rename(&tmp, &png)
                    .map_err(|e| CliError(format!("{}: cannot write: {e}", png.display())))?;
                s.push_str(&format!("{}: {}\n  {}\n", f.name, f.title, f.caption));
            }
            s.push_str(&format!(
                "wrote {} figures (SVG + PNG) into {}\n",
                figures.len(),
                out.display()
            ));
            s
        }
        Command::Bench(out, quick) => {
            let (_, text) = bench::run(&out, quick)?;
            format!(
                "{text}\nwrote {0}/bench.json and {0}/work-precision.svg\n",
                out.display()
            )
        }
        Command::Explore(c) => {
            explore::run(c.scene, c.accuracy).map_err(|e| CliError(format!("explorer: {e}")))?;
            return Ok(None);
        }
    }))
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = cli::parse(&args).and_then(run);
    match result {
        Ok(Some(text)) => {
            let mut out = std::io::stdout().lock();
            // A closed pipe (e.g. `| head`) is not an error worth reporting.
            let _ = out.write_all(text.as_bytes());
            let _ = out.flush();
            ExitCode::SUCCESS
        }
        Ok(None) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("rime: error: {e}");
            ExitCode::from(2)
        }
    }
}
