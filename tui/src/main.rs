//! `rime`: the terminal explorer and the scriptable subcommands. This file only parses
//! (crate::cli, from the table in crate::spec) and dispatches; each subcommand's body lives in
//! `commands/<name>.rs`.

mod args;
mod bench;
mod cli;
mod codegen;
mod commands;
mod eps_file;
mod explore;
mod output;
mod parallel;
mod progress;
mod scene_io;
mod spec;
mod suggest;
mod takeaway;

use cli::Command;
use scene_io::CliResult;
use std::io::Write;
use std::process::ExitCode;

/// Runs a parsed command: `Some(text)` for stdout, `None` when it wrote its own output.
fn run(command: Command) -> CliResult<Option<String>> {
    use commands::*;
    Ok(Some(match command {
        Command::Help(sub) => help::help(sub),
        Command::Version => format!("rime {}\n", env!("CARGO_PKG_VERSION")),
        Command::Completions(shell) => help::completions(&shell)?,
        Command::Man => help::man(),
        Command::Scene(c, out) => return scene::run(&c, out.as_deref()),
        Command::Eps(c, g) => eps::run(&c, &g)?,
        Command::EpsFile(c, path) => return eps::run_file(&c, &path).map(|()| None),
        Command::Compare(c, a) => compare::run(&c, &a)?,
        Command::Curve(c, from, to, n) => curve::run(&c, from, to, n)?,
        Command::Tangential(c, gn, gt) => tangential::run(&c, &gn, &gt)?,
        Command::Map(c, max, n) => map::run(&c, max, n)?,
        Command::Tidal(c, input) => tidal::run(&c, &input)?,
        Command::Export(c, from, to, n, out, rt) => export::run(&c, from, to, n, &out, rt)?,
        Command::ExportLammps(c, dir, adhesion) => lammps::run(&c, &dir, adhesion)?,
        Command::Fit(c, a) => fit::run(&c, &a)?,
        Command::Data(c, a) => data::run(&c, &a)?,
        Command::Stick(c, a) => stick::run(&c, &a)?,
        Command::Kernel(c, a) => kernel::run(&c, &a)?,
        Command::Ring(c, a) => ring::run(&c, &a)?,
        Command::Collision(c, a) => collision::run(&c, &a)?,
        Command::Figures(c, out, explorer) => figures::run(&c, &out, explorer.as_deref())?,
        Command::Bench(out, quick, frames) => bench::run(&out, quick, frames)?,
        Command::Explore(c) => return explore::run(c).map(|()| None),
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
            ExitCode::from(e.exit_code())
        }
    }
}
