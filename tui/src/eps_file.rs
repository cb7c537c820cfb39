//! `rime eps --g-file FILE`: ε_N for a file of speeds, streamed through the batch path
//! (`rime_core::batch`) in chunks, in constant memory.

use crate::args::{self, Common, Format};
use crate::output;
use crate::scene_io::{CliError, CliResult, err};
use rime_core::batch::BatchLaw;
use rime_core::error::Number;
use rime_core::{Contact, Status};
use std::io::{BufRead, BufReader, ErrorKind, Write};
use std::path::Path;

/// Speeds read, computed and written at a time.
const CHUNK: usize = 4096;
/// A longer line is an error (a speed with a comment fits in far less).
pub const MAX_LINE: usize = 256;

/// Reads one line (without its `\n`) into `line`; `Ok(false)` at the end of the file. A line longer
/// than `limit` bytes is an error, raised before the rest of it is read.
fn read_line_bounded(
    reader: &mut impl BufRead,
    line: &mut Vec<u8>,
    limit: usize,
) -> std::io::Result<Option<bool>> {
    line.clear();
    let mut any = false;
    loop {
        let buf = match reader.fill_buf() {
            Ok(b) => b,
            Err(e) if e.kind() == ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if buf.is_empty() {
            return Ok(if any { Some(true) } else { None });
        }
        any = true;
        let (take, done) = match buf.iter().position(|&b| b == b'\n') {
            Some(i) => (i, true),
            None => (buf.len(), false),
        };
        if line.len() + take > limit {
            return Ok(Some(false));
        }
        line.extend_from_slice(&buf[..take]);
        reader.consume(if done { take + 1 } else { take });
        if done {
            return Ok(Some(true));
        }
    }
}

/// Writes records as they come; a closed pipe ends the run quietly.
struct Sink<W: Write> {
    out: W,
    format: Format,
    written: usize,
}

enum Flow {
    Go,
    Closed,
}

fn io(result: std::io::Result<()>) -> CliResult<Flow> {
    match result {
        Ok(()) => Ok(Flow::Go),
        Err(e) if e.kind() == ErrorKind::BrokenPipe => Ok(Flow::Closed),
        Err(e) => err(format!("stdout: {e}")),
    }
}

impl<W: Write> Sink<W> {
    fn header(&mut self) -> CliResult<Flow> {
        io(match self.format {
            Format::Json => self.out.write_all(b"["),
            Format::Csv => self.out.write_all(b"g_n [m/s],eps_n,status\n"),
            Format::Table => writeln!(
                self.out,
                "{:>24}  {:>24}  {:>17}",
                "g_n [m/s]", "eps_n", "status"
            ),
        })
    }

    fn record(&mut self, g: f64, eps: f64, status: Status) -> CliResult<Flow> {
        let (g_s, e_s, status) = (output::num(g), output::num(eps), status.name());
        let r = match self.format {
            Format::Json => {
                let sep = if self.written == 0 { "\n" } else { ",\n" };
                let (g, e) = (serde_json::Value::from(g), serde_json::Value::from(eps));
                write!(
                    self.out,
                    "{sep}  {{\"g_n\": {g}, \"eps_n\": {e}, \"status\": \"{status}\"}}"
                )
            }
            Format::Csv => writeln!(self.out, "{g_s},{e_s},{status}"),
            Format::Table => writeln!(self.out, "{g_s:>24}  {e_s:>24}  {status:>17}"),
        };
        self.written += 1;
        io(r)
    }

    fn footer(&mut self) -> CliResult<Flow> {
        let r = match self.format {
            Format::Json if self.written == 0 => self.out.write_all(b"]\n"),
            Format::Json => self.out.write_all(b"\n]\n"),
            _ => Ok(()),
        };
        io(r.and_then(|()| self.out.flush()))
    }
}

/// The status of a batch value: the same names and thresholds as `Contact::normal`.
fn status(contact: &Contact, g: f64, eps: f64, common: &Common) -> CliResult<Status> {
    if eps == 0.0 {
        // Stuck (layer or adhesion): which one is `normal`'s call (cheap when stuck).
        let n = contact
            .normal(g, common.accuracy)
            .map_err(|e| CliError::from(e).context(format!("g_n = {}", Number(g))))?;
        return Ok(match n.status {
            Status::Rebound if contact.adhesion.is_some() => Status::StuckByAdhesion,
            Status::Rebound => Status::Overdamped,
            s => s,
        });
    }
    Ok(if eps < rime_core::normal::OVERDAMPED_THRESHOLD {
        Status::Overdamped
    } else {
        Status::Rebound
    })
}

/// Runs `rime eps --g-file PATH`, writing to stdout as it goes.
pub fn run(common: &Common, path: &Path) -> CliResult<()> {
    let shown = path.display();
    let meta =
        std::fs::metadata(path).map_err(|e| CliError::input(format!("--g-file {shown}: {e}")))?;
    if !meta.is_file() {
        return err(format!(
            "--g-file {shown}: not a regular file (devices, FIFOs and directories are refused)"
        ));
    }
    let file =
        std::fs::File::open(path).map_err(|e| CliError::input(format!("--g-file {shown}: {e}")))?;
    let contact = args::contact(common)?;
    let law = BatchLaw::new(&contact, common.accuracy);
    let mut reader = BufReader::with_capacity(1 << 16, file);
    let mut sink = Sink {
        out: std::io::BufWriter::with_capacity(1 << 16, std::io::stdout().lock()),
        format: common.format,
        written: 0,
    };
    let mut line = Vec::with_capacity(MAX_LINE);
    let (mut g, mut eps) = (Vec::with_capacity(CHUNK), vec![0.0; CHUNK]);
    let mut number = 0usize;
    let mut started = false;
    loop {
        let more = match read_line_bounded(&mut reader, &mut line, MAX_LINE) {
            Ok(m) => m,
            Err(e) => return err(format!("--g-file {shown}: line {}: {e}", number + 1)),
        };
        if let Some(complete) = more {
            number += 1;
            if !complete {
                return err(format!(
                    "--g-file {shown}: line {number} is longer than {MAX_LINE} bytes"
                ));
            }
            let Ok(text) = std::str::from_utf8(&line) else {
                return err(format!("--g-file {shown}: line {number} is not UTF-8 text"));
            };
            let text = text.split('#').next().unwrap_or("").trim();
            if text.is_empty() {
                continue;
            }
            g.push(args::speed(
                &format!("--g-file {shown}: line {number}"),
                text,
                false,
            )?);
        }
        if g.len() == CHUNK || (more.is_none() && !g.is_empty()) {
            let out = &mut eps[..g.len()];
            law.fill(&g, out)?;
            if !started {
                started = true;
                if let Flow::Closed = sink.header()? {
                    return Ok(());
                }
            }
            for (&gi, &e) in g.iter().zip(out.iter()) {
                if let Flow::Closed = sink.record(gi, e, status(&contact, gi, e, common)?)? {
                    return Ok(());
                }
            }
            g.clear();
        }
        if more.is_none() {
            break;
        }
    }
    if !started {
        return err(format!(
            "--g-file {shown}: no speeds (one per line, # comments)"
        ));
    }
    sink.footer()?;
    Ok(())
}
