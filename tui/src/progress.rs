//! Progress of long work on stderr, only when stderr is a terminal (scripts see nothing).

use std::io::{IsTerminal, Write};

/// A one-line counter `what: k/n label`, redrawn in place and cleared when dropped.
pub struct Progress {
    on: bool,
    what: &'static str,
    total: usize,
    done: usize,
}

impl Progress {
    /// A counter of `total` steps; silent unless stderr is a terminal.
    pub fn new(what: &'static str, total: usize) -> Self {
        Progress {
            on: std::io::stderr().is_terminal(),
            what,
            total,
            done: 0,
        }
    }

    /// Shows that the step `label` starts.
    pub fn step(&mut self, label: &str) {
        self.done += 1;
        if self.on {
            let mut e = std::io::stderr().lock();
            let _ = write!(
                e,
                "\r\x1b[2K{}: {}/{} {label}",
                self.what,
                self.done.min(self.total),
                self.total
            );
            let _ = e.flush();
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        if self.on {
            let mut e = std::io::stderr().lock();
            let _ = write!(e, "\r\x1b[2K");
            let _ = e.flush();
        }
    }
}
