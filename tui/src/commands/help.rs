//! `rime help [SUB]`, `rime SUB --help`, `rime completions SHELL`, `rime man`: all generated from
//! the one table of subcommands and flags (crate::spec).

use crate::scene_io::{CliResult, err};
use crate::spec::{self, Sub};

/// The overview, or one subcommand's flags and example.
pub fn help(sub: Option<&Sub>) -> String {
    match sub {
        Some(s) if !s.name.is_empty() => spec::sub_help(s),
        _ => spec::usage(),
    }
}

/// The completion script for `shell`.
pub fn completions(shell: &str) -> CliResult<String> {
    match spec::completions(shell) {
        Some(s) => Ok(s),
        None => err(format!("completions {shell}: expected bash, zsh or fish")),
    }
}

/// The man page (roff).
pub fn man() -> String {
    spec::man_page()
}
