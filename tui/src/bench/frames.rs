//! `rime bench --frames`: input → first frame and input → final frame of the terminal explorer, for
//! every accuracy level × scene × terminal size (issue 26).
//!
//! Each case drives the explorer's own state ([`App`]) the way a key press does: an edit of one
//! parameter (the damping time A unless the case says otherwise; alternately up by about 10 % and
//! back, each edit to a value not seen before, so the scene never drifts and no edit finds the
//! worker's literal-layer memo warm by coming back to an earlier value), the request the edit
//! queues, the frame the worker computes from it (the same function as the terminal's worker, with
//! a memo of its own per case, as the terminal's session has), and
//! the terminal's render of the new state into a ratatui `TestBackend` of the case's size. The
//! terminal's request does not depend on the size (points and map side are fixed); the size
//! changes only what is drawn. At `precise` and `integrated` the worker first sends a `fast`
//! preview: `first_ms` is the preview drawn, `final_ms` the requested level drawn. Everything runs
//! on this thread in sequence, so `final_ms` includes the preview's compute and render too (in the
//! terminal that render overlaps the refinement).
//!
//! Times are medians of `runs` edits and are reported, never asserted.

use crate::explore::compute::{self, Computed};
use crate::explore::state::{App, Event};
use crate::explore::update::update;
use crate::scene_io::{CliError, CliResult, write_atomic};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use rime_core::explorer::frame::SWEEPS;
use rime_core::normal::memo::SharedLayerMemo;
use rime_core::params::Value;
use rime_core::{Accuracy, LayerReading, Preset, Scene};
use std::path::Path;
use std::time::Instant;

/// One case of the matrix.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Record {
    /// `terminal` (the page's script writes `page`).
    pub surface: &'static str,
    /// The scene (see [`scenes`]).
    pub scene: String,
    /// The parameter each edit changed (a scene path).
    pub edit: &'static str,
    /// Accuracy level requested.
    pub level: &'static str,
    /// Terminal size, `COLSxROWS`.
    pub size: String,
    /// Median input → first frame drawn \[ms\].
    pub first_ms: f64,
    /// Median input → final frame (at `level`) drawn \[ms\].
    pub final_ms: f64,
    /// Median input → final frame drawn with the frame computed sequentially (one core) \[ms\].
    pub sequential_final_ms: f64,
    /// Median compute time of the final frame alone, parallel \[ms\].
    pub compute_ms: f64,
    /// Median compute time of the final frame alone, sequential \[ms\].
    pub sequential_compute_ms: f64,
    /// Edits timed.
    pub runs: usize,
    /// Cores the machine reports (`available_parallelism`).
    pub cores: usize,
    /// 1-minute load average when the case ran (`/proc/loadavg`; NaN where there is none).
    pub load: f64,
}

/// A scene of the matrix: name, scene, sweep (index into [`SWEEPS`], `None`: the default),
/// comparison set (index into the core's `COMPARISONS`) and the parameter each edit changes.
pub struct Case {
    /// Name in the table and the JSON.
    pub name: &'static str,
    /// The scene.
    pub scene: Scene,
    /// The family's sweep.
    pub sweep: Option<usize>,
    /// The comparison set drawn over the chart.
    pub overlay_set: usize,
    /// The parameter an edit changes (a scene path).
    pub edit: &'static str,
}

/// The parameter edited unless a case says otherwise.
const DAMPING_TIME: &str = "bulk.damping.time";

/// The scenes of the matrix: the presets, the literal Eq. (8) layer reading, the two comparison
/// sets and a family swept over the grain radius.
pub fn scenes() -> Vec<Case> {
    let frost = Preset::IceFrost.scene();
    let literal = frost.with_layer_reading(LayerReading::Literal);
    let radius = SWEEPS.iter().position(|s| s.path == "grains.radius");
    let case = |name, scene, sweep, overlay_set| Case {
        name,
        scene,
        sweep,
        overlay_set,
        edit: DAMPING_TIME,
    };
    vec![
        case("ice", Preset::Ice.scene(), None, 0),
        case("ice-frost", frost, None, 0),
        case("ice-frost, layer.reading=literal", literal, None, 0),
        // An edit that leaves the literal layer stage's inputs unchanged: the friction coefficient
        // (the stick map is classified again; no contact is integrated again).
        Case {
            edit: "friction.coefficient",
            ..case("literal, edit of friction μ", literal, None, 0)
        },
        case("ice-sticky", Preset::IceSticky.scene(), None, 0),
        case("ice, compare other models", Preset::Ice.scene(), None, 2),
        case("ice, compare measured ice", Preset::Ice.scene(), None, 1),
        case("ice-frost, family over R₁=R₂", frost, radius, 0),
        // The paper's viscosities (A = 404 s, every contact overdamped): the issue's
        // "integrated ≤ 100 ms" case, still by live integration.
        case(
            "ice, the paper's viscosities",
            Preset::IcePaperViscosities.scene(),
            None,
            0,
        ),
    ]
}

/// The terminal sizes of the matrix.
pub const SIZES: [(u16, u16); 2] = [(80, 24), (200, 60)];

/// The levels of the matrix.
pub const LEVELS: [Accuracy; 3] = [Accuracy::Fast, Accuracy::Precise, Accuracy::Balanced];

/// 1-minute load average (NaN where `/proc/loadavg` is missing).
pub fn load_average() -> f64 {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse().ok())
        .unwrap_or(f64::NAN)
}

/// Cores this process may use.
pub fn cores() -> usize {
    std::thread::available_parallelism().map_or(1, |n| n.get())
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    match v.len() {
        0 => f64::NAN,
        n if n % 2 == 1 => v[n / 2],
        n => 0.5 * (v[n / 2 - 1] + v[n / 2]),
    }
}

/// How the worker computes a job.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mode {
    Parallel,
    Sequential,
}

/// Timings of one edit \[ms\]: first frame drawn, final frame drawn, final frame's compute.
struct Edit {
    first: f64,
    last: f64,
    compute: f64,
}

fn draw(app: &App, terminal: &mut Terminal<TestBackend>) -> CliResult<()> {
    terminal
        .draw(|f| crate::explore::view::render(app, f))
        .map(|_| ())
        .map_err(|e| CliError::input(format!("bench --frames: drawing failed: {e}")))
}

/// One edit: the key's state change, then the worker's frames (a `fast` preview where `rule` asks
/// for one, then the requested level, as [`compute::progressive`] sends them), each drawn as it
/// arrives.
fn edit(
    app: &mut App,
    terminal: &mut Terminal<TestBackend>,
    next: Scene,
    mode: Mode,
    memo: &SharedLayerMemo,
    rule: &mut compute::PreviewRule,
) -> CliResult<Edit> {
    let start = Instant::now();
    app.scene_changed(next);
    let job = app
        .take_request()
        .ok_or_else(|| CliError::input("bench --frames: the edit queued no request"))?;
    let threads = match mode {
        Mode::Parallel => compute::threads(),
        Mode::Sequential => 1,
    };
    let mut first = None;
    let mut compute_ms = 0.0;
    let mut drawn = Ok(());
    compute::progressive(&job, &|| false, threads, memo, rule, &mut |c: Computed| {
        if !c.preview {
            compute_ms = c.elapsed.as_secs_f64() * 1e3;
        }
        update(app, Event::Computed(Box::new(c)));
        drawn = draw(app, terminal);
        first.get_or_insert(start.elapsed().as_secs_f64() * 1e3);
        drawn.is_ok()
    });
    drawn?;
    let last = start.elapsed().as_secs_f64() * 1e3;
    let first = first.ok_or_else(|| CliError::input("bench --frames: no frame was computed"))?;
    Ok(Edit {
        first,
        last,
        compute: compute_ms,
    })
}

/// Times one case: `runs` edits in each mode, interleaved so both see the same load.
fn case(c: &Case, level: Accuracy, size: (u16, u16), runs: usize) -> CliResult<Record> {
    let mut app = App::new(c.scene, level);
    app.size = size;
    app.sweep = c.sweep.unwrap_or(app.sweep);
    app.overlay_set = c.overlay_set;
    app.request();
    let mut terminal = Terminal::new(TestBackend::new(size.0, size.1))
        .map_err(|e| CliError::input(format!("bench --frames: {e}")))?;
    // The first frame of the session (not timed), as the terminal shows it at start.
    let memo = SharedLayerMemo::new();
    if let Some(job) = app.take_request()
        && let Some(data) = compute::compute(&job, &|| false, &memo)
    {
        update(&mut app, Event::Computed(Box::new(data)));
    }
    draw(&app, &mut terminal)?;
    let base = c.scene;
    // A swept parameter is edited as the terminal's sweep edits it (the damping time of a scene
    // given by viscosities stays a scene of viscosities); any other as a scene path.
    let sweep = SWEEPS.iter().find(|s| s.path == c.edit);
    let value = match (sweep, base.get(c.edit)) {
        (Some(s), _) => s.current(&base),
        (None, Ok(Value::Number(v))) => v,
        _ => {
            return Err(CliError::input(format!(
                "bench --frames: {} is not a number of the scene",
                c.edit
            )));
        }
    };
    let set = |v: f64| -> CliResult<Scene> {
        Ok(match sweep {
            Some(s) => s.apply(&base, v)?,
            None => {
                let mut next = base;
                next.set_number(c.edit, v)?;
                next
            }
        })
    };
    let load = load_average();
    let mut by_mode = [Vec::new(), Vec::new()];
    // Each mode a session of its own: a preview only where the last frame of its kind was dear
    // (the terminal's rule), so a cheap level's first frame is its final one.
    let mut rules = [
        compute::PreviewRule::default(),
        compute::PreviewRule::default(),
    ];
    let mut edits = 0_u32;
    for _ in 0..runs {
        for (k, mode) in [Mode::Parallel, Mode::Sequential].into_iter().enumerate() {
            // Alternately about 10 % up and back near the start, each time to a new value: every
            // edit is a real change and none returns to a value the memo has seen.
            edits += 1;
            let factor = if edits % 2 == 1 { 1.1 } else { 1.0 } + 1e-3 * f64::from(edits);
            let next = set(factor * value)?;
            by_mode[k].push(edit(
                &mut app,
                &mut terminal,
                next,
                mode,
                &memo,
                &mut rules[k],
            )?);
        }
    }
    let [par, seq] = by_mode;
    Ok(Record {
        surface: "terminal",
        scene: c.name.to_string(),
        edit: c.edit,
        level: level.name(),
        size: format!("{}x{}", size.0, size.1),
        first_ms: median(par.iter().map(|e| e.first).collect()),
        final_ms: median(par.iter().map(|e| e.last).collect()),
        sequential_final_ms: median(seq.iter().map(|e| e.last).collect()),
        compute_ms: median(par.iter().map(|e| e.compute).collect()),
        sequential_compute_ms: median(seq.iter().map(|e| e.compute).collect()),
        runs,
        cores: cores(),
        load,
    })
}

/// Runs the matrix (`quick`: 3 edits per case and the 80×24 size only) and writes
/// `out_dir/frames.json`; returns the records and the table.
pub fn run(out_dir: &Path, quick: bool) -> CliResult<(Vec<Record>, String)> {
    let runs = if quick { 3 } else { 11 };
    let sizes: &[(u16, u16)] = if quick { &SIZES[..1] } else { &SIZES };
    let all = scenes();
    let mut progress =
        crate::progress::Progress::new("bench --frames", all.len() * LEVELS.len() * sizes.len());
    let mut records = Vec::new();
    for &size in sizes {
        for c in &all {
            for level in LEVELS {
                progress.step(&format!(
                    "{} at {} ({}×{})",
                    c.name,
                    level.name(),
                    size.0,
                    size.1
                ));
                records.push(case(c, level, size, runs)?);
            }
        }
    }
    std::fs::create_dir_all(out_dir)
        .map_err(|e| CliError::input(format!("--out {}: {e}", out_dir.display())))?;
    let json = serde_json::to_string_pretty(&records)
        .map_err(|e| CliError::input(format!("bench --frames: {e}")))?;
    write_atomic(&out_dir.join("frames.json"), format!("{json}\n").as_bytes())?;
    Ok((records.clone(), table(&records)))
}

/// The records as a table, one block per size, each scene on a line of its own with its levels
/// beneath: at most 80 columns (issue 37 R3: rows of 110 columns wrapped in an 80-column terminal).
pub fn table(records: &[Record]) -> String {
    let mut s = format!(
        "input → frame of the terminal explorer, median [ms] ({} cores, load average {:.2}\n\
         at the start); 1× = on one core\n",
        records.first().map_or(cores(), |r| r.cores),
        records.first().map_or(f64::NAN, |r| r.load)
    );
    let mut sizes: Vec<&str> = records.iter().map(|r| r.size.as_str()).collect();
    sizes.dedup();
    for size in sizes {
        s.push_str(&format!(
            "\n{size}\n{:<14} {:>8} {:>8} {:>9} {:>9} {:>11} {:>9}\n",
            "scene / level", "first", "final", "final 1×", "compute", "compute 1×", "speed-up"
        ));
        let mut scene = "";
        for r in records.iter().filter(|r| r.size == size) {
            if r.scene != scene {
                scene = &r.scene;
                s.push_str(&format!("{scene}\n"));
            }
            s.push_str(&format!(
                "  {:<12} {:>8.2} {:>8.2} {:>9.2} {:>9.2} {:>11.2} {:>8.2}×\n",
                r.level,
                r.first_ms,
                r.final_ms,
                r.sequential_final_ms,
                r.compute_ms,
                r.sequential_compute_ms,
                r.sequential_compute_ms / r.compute_ms
            ));
        }
    }
    s
}

#[cfg(test)]
mod issue_37_tests {
    use super::{Record, table};

    /// Issue 37 (review R3): the frames table fits 80 columns (it was 110 wide) and still carries
    /// every scene, level and number of its records.
    #[test]
    fn issue_37_the_frames_table_fits_80_columns() {
        let long = "ice-frost, layer.reading=literal";
        let records: Vec<Record> = ["fast", "precise", "integrated"]
            .iter()
            .enumerate()
            .map(|(k, level)| Record {
                surface: "terminal",
                scene: long.to_string(),
                edit: "bulk.damping.time",
                level,
                size: "80x24".into(),
                first_ms: 12345.67,
                final_ms: 23456.78 + k as f64,
                sequential_final_ms: 34567.89,
                compute_ms: 4567.8,
                sequential_compute_ms: 5678.9,
                runs: 3,
                cores: 2,
                load: 12.34,
            })
            .collect();
        let text = table(&records);
        for line in text.lines() {
            assert!(
                line.chars().count() <= 80,
                "{} columns: {line}",
                line.chars().count()
            );
        }
        assert!(text.lines().any(|l| l == long), "{text}");
        for (k, level) in ["fast", "precise", "integrated"].iter().enumerate() {
            let row = text
                .lines()
                .find(|l| l.trim_start().starts_with(level))
                .unwrap_or_else(|| panic!("{level}: {text}"));
            let cells: Vec<&str> = row.split_whitespace().collect();
            assert_eq!(cells[1], "12345.67");
            assert_eq!(cells[2], format!("{:.2}", 23456.78 + k as f64));
            assert_eq!(cells[6], format!("{:.2}×", 5678.9 / 4567.8));
        }
    }
}
