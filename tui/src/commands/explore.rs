//! `rime` without a subcommand: the terminal explorer (crate::explore), which needs a terminal.

use crate::args::Common;
use crate::scene_io::{CliError, CliResult, err};
use std::io::IsTerminal;

/// Starts the explorer, or explains (exit 2) that it needs a terminal on stdin and stdout.
pub fn run(c: Common) -> CliResult<()> {
    if !(std::io::stdin().is_terminal() && std::io::stdout().is_terminal()) {
        return err(
            "explorer: needs a terminal (stdin and stdout are not one); in scripts use a subcommand, \
             e.g. rime eps --g 0.01 or rime curve --from 1e-6 --to 1 (see rime --help)",
        );
    }
    crate::explore::run(c.scene, c.accuracy).map_err(|e| CliError::input(format!("explorer: {e}")))
}
