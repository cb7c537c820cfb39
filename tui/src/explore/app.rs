//! The explorer's state and its `update` function (the Elm-like core; no terminal I/O here apart
//! from the files that `x` and `w` write).

use super::colors::Colors;
use super::compute::{Computed, Job, SWEEPS, Sweep};
use super::frame_export;
use super::keymap::{self, Action};
use crate::scene_io;
use crossterm::event::{KeyCode, KeyEvent, KeyEventKind, KeyModifiers, MouseEvent, MouseEventKind};
use rime_core::explorer::figures::Pinned;
use rime_core::explorer::frame::{self, Request};
use rime_core::params::{Kind, PARAMETERS, Value};
use rime_core::{Accuracy, Preset, Scene};
use std::path::PathBuf;
use std::time::Duration;

/// Everything that can happen to the explorer.
#[derive(Debug)]
pub enum Event {
    /// A key press.
    Key(KeyEvent),
    /// A mouse event.
    Mouse(MouseEvent),
    /// The terminal was resized to (columns, rows).
    Resize(u16, u16),
    /// The worker finished a frame.
    Computed(Box<Computed>),
}

/// Which part of the screen the arrow keys act on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Focus {
    /// The parameter panel (arrows select and change parameters).
    Panel,
    /// The ε_N chart (←/→ move the cursor).
    Chart,
    /// The stick map (arrows move the map cursor).
    Map,
}

/// How a status message is shown.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Tone {
    /// Neutral information.
    Info,
    /// An error (e.g. a rejected value).
    Error,
}

/// The explorer's whole state.
#[derive(Debug, Clone)]
pub struct App {
    /// The scene being explored.
    pub scene: Scene,
    /// Accuracy level.
    pub accuracy: Accuracy,
    /// Index into [`Preset::ALL`] of the last preset chosen with `p` (None: scene from elsewhere).
    pub preset: Option<usize>,
    /// Selected row of [`PARAMETERS`].
    pub selected: usize,
    /// What the arrow keys act on.
    pub focus: Focus,
    /// Index into [`SWEEPS`].
    pub sweep: usize,
    /// Value being typed after `e` (None when not editing).
    pub input: Option<LineInput>,
    /// Whether the help overlay is shown.
    pub help: bool,
    /// Last status message.
    pub message: Option<(String, Tone)>,
    /// The latest computed frame.
    pub data: Option<Computed>,
    /// Generation of the latest request.
    pub generation: u64,
    /// A request waiting to be sent to the worker.
    pub pending: Option<Job>,
    /// Chart cursor: index into the curve speeds.
    pub cursor: usize,
    /// Map cursor: (row i for g_N, column j for g_T) into the map grid.
    pub map_cursor: (usize, usize),
    /// User-chosen stick-map range \[m/s\] (None: automatic).
    pub map_max: Option<f64>,
    /// Set when the user asked to quit.
    pub quit: bool,
    /// Terminal size (columns, rows).
    pub size: (u16, u16),
    /// Folder that exports and saved scenes go into.
    pub out_dir: PathBuf,
    /// Compute time to show instead of the measured one (tests use this for stable snapshots).
    pub fixed_elapsed: Option<Duration>,
    /// Whether the ε_N chart shows the experimental context (Bridges et al. 1984 law and the
    /// microgravity ice experiments); `b` toggles it.
    pub experiments: bool,
    /// Whether the tidal-appendix calculator is shown (`t`).
    pub tidal: bool,
    /// The collision panel (`i`): the cursor speed and its trajectory (or why there is none),
    /// recomputed whenever the scene, level or cursor changes.
    pub inside: Option<(f64, Result<rime_core::collision::Trajectory, String>)>,
    /// The sticking-thresholds panel (`v`): the table for this scene's material, when open.
    pub stick: Option<rime_core::stick::ThresholdTable>,
    /// What is drawn over the ε_N chart (`c`): index into the core's [`frame::COMPARISONS`].
    pub overlay_set: usize,
    /// The scene and level the panel's trajectory belongs to.
    pub inside_key: Option<(Scene, Accuracy)>,
    /// With adhesion, the dynamic JKR model's (ξ, F) loop at the same speed (issue 16).
    pub inside_dynamic: Vec<(f64, f64)>,
    /// Planet distance of the tidal calculator as a multiple of the paper's (Encke division).
    pub tidal_factor: f64,
    /// Path being typed after `o` (None when not opening a scene file).
    pub open: Option<LineInput>,
    /// In a shared layout ([`super::layout::Layout::shared`]), whether the right-hand pane shows
    /// the stick map (else the ε_N chart).
    pub map_shown: bool,
    /// First line of the help shown (the help scrolls when it is taller than the screen).
    pub help_scroll: u16,
    /// Whether the ε_N axis is logarithmic (`y`); linear shows sticking (ε_N = 0).
    pub y_log: bool,
    /// The chart's speed range \[m/s\] (zoom `+ -`, pan `, .`); `None`: automatic. It goes into
    /// the request as the core's `speeds`.
    pub speeds: Option<(f64, f64)>,
    /// A pinned ε_N curve (`P`), drawn dashed to compare with later edits.
    pub pinned: Option<Pinned>,
    /// Scene edits that `u` undoes (oldest first).
    pub undo: Vec<SceneState>,
    /// Undone edits that `U` redoes (most recent last).
    pub redo: Vec<SceneState>,
    /// The scene as last saved, opened or started with: quitting with another one asks first.
    pub saved: Scene,
    /// A yes/no question waiting for its answer.
    pub confirm: Option<Confirm>,
    /// What this session last wrote to the scene file: `w` overwrites without asking only while
    /// the file still holds exactly that (a file changed since, by anyone, is asked about again).
    pub wrote_scene_file: Option<Vec<u8>>,
    /// A speed to put the chart cursor on when the next frame arrives (after a range change).
    pub cursor_at: Option<f64>,
    /// Where the last frame drew what the mouse can click (written by the renderer).
    pub drawn: std::cell::Cell<Drawn>,
    /// The terminal's colours (24-bit, 16, or none with `NO_COLOR`).
    pub colors: Colors,
}

/// The part of the state that undo and redo restore.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SceneState {
    /// The scene.
    pub scene: Scene,
    /// The preset it was chosen as, if any.
    pub preset: Option<usize>,
}

/// A yes/no question on the message line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Confirm {
    /// Quit although the scene has unsaved edits.
    Quit,
    /// Overwrite the existing scene file.
    Overwrite,
}

/// Geometry of the last drawn frame that mouse clicks need (the renderer fills it in).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Drawn {
    /// The chart's log speed axis.
    pub chart_axis: Option<super::layout::LogAxis>,
    /// The stick map's grid cells: (x, y, width, height) in cells.
    pub map_plot: Option<ratatui::layout::Rect>,
    /// The parameter panel: first row of the list and index of the first parameter shown.
    pub panel_rows: Option<(u16, usize)>,
}

/// Default file that `o` offers (the one `w` writes).
pub const SCENE_FILE: &str = "rime-scene.json";

/// The narrowest speed range, in decades.
pub const MIN_SPAN_DECADES: f64 = 0.25;

/// Index of the speed nearest `g` on the chart's log grid from `lo` to `hi`.
pub fn grid_index(g: f64, lo: f64, hi: f64) -> usize {
    let t = (g.log10() - lo.log10()) / (hi.log10() - lo.log10());
    if !t.is_finite() {
        return 0;
    }
    (t.clamp(0.0, 1.0) * (Request::POINTS - 1) as f64).round() as usize
}

/// Index of the speed in `g` nearest `target` (in log).
fn nearest(g: &[f64], target: f64) -> usize {
    let t = target.log10();
    g.iter()
        .enumerate()
        .min_by(|a, b| {
            let da = (a.1.log10() - t).abs();
            let db = (b.1.log10() - t).abs();
            da.total_cmp(&db)
        })
        .map_or(0, |(i, _)| i)
}

/// Factor by which `<` / `>` change the tidal calculator's planet distance.
pub const TIDAL_STEP: f64 = 1.05;

impl App {
    /// A new explorer on `scene`; the first computation is queued in [`App::pending`].
    pub fn new(scene: Scene, accuracy: Accuracy) -> App {
        let preset = Preset::ALL.iter().position(|p| p.scene() == scene);
        let mut app = App {
            scene,
            accuracy,
            preset,
            selected: 0,
            focus: Focus::Panel,
            sweep: Sweep::default_for(&scene),
            input: None,
            help: false,
            message: Some(("? shows every key · q quits".into(), Tone::Info)),
            data: None,
            generation: 0,
            pending: None,
            // 1 cm/s on the default 1e-7…10 m/s grid.
            cursor: (Request::POINTS - 1) * 5 / 8,
            map_cursor: (Request::MAP_N / 2, Request::MAP_N / 4),
            map_max: None,
            quit: false,
            size: (100, 30),
            out_dir: PathBuf::from("."),
            fixed_elapsed: None,
            experiments: true,
            tidal: false,
            inside: None,
            inside_key: None,
            overlay_set: 0,
            stick: None,
            inside_dynamic: Vec::new(),
            tidal_factor: 1.0,
            open: None,
            map_shown: false,
            help_scroll: 0,
            y_log: true,
            speeds: None,
            pinned: None,
            undo: Vec::new(),
            redo: Vec::new(),
            saved: scene,
            confirm: None,
            wrote_scene_file: None,
            cursor_at: None,
            drawn: std::cell::Cell::new(Drawn::default()),
            colors: Colors::Rgb,
        };
        app.request();
        app
    }

    /// Queues a computation of the current state (superseding any earlier request).
    pub fn request(&mut self) {
        // The thresholds panel follows the scene (its A, its layer), as the chart does.
        if self.stick.as_ref().is_some_and(|t| t.scene != self.scene) {
            self.stick = Some(rime_core::stick::ThresholdTable::explorer(
                &self.scene,
                Accuracy::Fast,
            ));
        }
        self.generation += 1;
        let mut request = Request::new(self.scene, self.accuracy);
        request.sweep = Some(self.sweep).filter(|k| *k < SWEEPS.len());
        request.map_max = self.map_max;
        request.speeds = self.speeds;
        request.overlays = frame::comparison(self.overlay_set, &self.scene);
        self.pending = Some(Job {
            generation: self.generation,
            request,
        });
    }

    /// Takes the queued request, if any.
    pub fn take_request(&mut self) -> Option<Job> {
        self.pending.take()
    }

    /// Whether the shown data are older than the latest request.
    pub fn computing(&self) -> bool {
        self.data
            .as_ref()
            .is_none_or(|d| d.generation != self.generation)
    }

    fn info(&mut self, text: impl Into<String>) {
        self.message = Some((text.into(), Tone::Info));
    }

    fn error(&mut self, text: impl Into<String>) {
        self.message = Some((text.into(), Tone::Error));
    }

    /// The swept parameter.
    pub fn sweep_def(&self) -> Sweep {
        SWEEPS.get(self.sweep).copied().unwrap_or(SWEEPS[3])
    }

    /// Keeps the sweep valid after the scene changed (falls back to the scene's default).
    fn fix_sweep(&mut self) {
        if !self.sweep_def().available(&self.scene) {
            self.sweep = Sweep::default_for(&self.scene);
        }
    }

    /// Replaces the scene (an edit: undoable) and queues a recomputation.
    fn scene_changed(&mut self, next: Scene) {
        self.replace_scene(next, None);
    }

    /// Replaces the scene and the preset it is, remembering the old ones for undo.
    fn replace_scene(&mut self, next: Scene, preset: Option<usize>) {
        if next == self.scene && preset == self.preset {
            return;
        }
        self.undo.push(SceneState {
            scene: self.scene,
            preset: self.preset,
        });
        self.redo.clear();
        self.scene = next;
        self.preset = preset;
        self.fix_sweep();
        self.request();
    }

    /// Whether the scene differs from the one last saved, opened or started with.
    pub fn unsaved(&self) -> bool {
        self.scene != self.saved
    }

    /// Undo (`back`) or redo one scene edit.
    fn history(&mut self, back: bool) {
        let (from, to) = if back {
            (&mut self.undo, &mut self.redo)
        } else {
            (&mut self.redo, &mut self.undo)
        };
        let Some(state) = from.pop() else {
            self.info(if back {
                "nothing to undo"
            } else {
                "nothing to redo"
            });
            return;
        };
        to.push(SceneState {
            scene: self.scene,
            preset: self.preset,
        });
        self.scene = state.scene;
        self.preset = state.preset;
        self.fix_sweep();
        self.request();
        let left = if back {
            self.undo.len()
        } else {
            self.redo.len()
        };
        self.info(format!(
            "{} ({left} more) · {}",
            if back { "undone" } else { "redone" },
            if back { "U redoes" } else { "u undoes" }
        ));
    }

    fn set_text(&mut self, path: &str, text: &str) -> bool {
        let mut next = self.scene;
        match next.set(path, text) {
            Ok(()) => {
                self.scene_changed(next);
                true
            }
            Err(e) => {
                let e = e.to_string();
                // Core errors usually name the field already.
                if e.contains(path) {
                    self.error(format!("{e} (scene unchanged)"));
                } else {
                    self.error(format!("{path}: {e} (scene unchanged)"));
                }
                false
            }
        }
    }

    /// Changes the selected parameter one step up (`dir = 1`) or down (`-1`), fine or coarse.
    fn step(&mut self, dir: f64, fine: bool) {
        let Some(p) = PARAMETERS.get(self.selected) else {
            return;
        };
        match (p.kind, self.scene.get(p.path)) {
            (Kind::Number { min, max, log }, Ok(Value::Number(v))) => {
                let next = if log {
                    let f: f64 = if fine { 1.02 } else { 1.25 };
                    if v > 0.0 {
                        v * f.powf(dir)
                    } else if dir > 0.0 && min <= 0.0 {
                        self.error(format!(
                            "{}: is 0; press e to type a value (log steps cannot leave 0)",
                            p.path
                        ));
                        return;
                    } else {
                        v
                    }
                } else {
                    // 5 % of the range (1 % fine), at most 0.05 (0.01): steps a physicist can use
                    // for μ, κ and ν.
                    let span = (max - min).min(1.0);
                    v + dir * span * if fine { 0.01 } else { 0.05 }
                };
                let next = next.clamp(min, max);
                let mut s = self.scene;
                match s.set_number(p.path, next) {
                    Ok(()) => self.scene_changed(s),
                    Err(e) => self.error(format!("{}: {e} (scene unchanged)", p.path)),
                }
            }
            (Kind::Number { .. }, _) => self.info(format!(
                "{} is inactive; press e to type a value (switches it on)",
                p.path
            )),
            (Kind::Choice(options), _) => self.cycle_choice(p.path, options, dir),
            (Kind::Toggle, _) => self.activate(),
        }
    }

    fn cycle_choice(&mut self, path: &str, options: &[&str], dir: f64) {
        let current = match self.scene.get(path) {
            Ok(Value::Choice(c)) => options.iter().position(|o| *o == c),
            _ => None,
        };
        let n = options.len();
        let next = match current {
            Some(i) if dir < 0.0 => (i + n - 1) % n,
            Some(i) => (i + 1) % n,
            None => 0,
        };
        if let Some(o) = options.get(next)
            && self.set_text(path, o)
        {
            let (words, _) = super::view::panel::choice_label(o);
            let label = rime_core::params::parameter(path).map_or(path, |p| p.label);
            if words.is_empty() {
                self.info(format!("{label}: {o}"));
            } else {
                self.info(format!("{label}: {words} ({path} = {o}) · u undoes"));
            }
        }
    }

    /// Enter/space on the selected row: cycles a choice, switches a toggle, edits a number.
    fn activate(&mut self) {
        let Some(p) = PARAMETERS.get(self.selected) else {
            return;
        };
        match p.kind {
            Kind::Toggle => {
                let on = matches!(self.scene.get(p.path), Ok(Value::Enabled(true)));
                let text = if on { "off" } else { "on" };
                if self.set_text(p.path, text) {
                    self.info(format!("{} {text}", p.path));
                }
            }
            Kind::Choice(options) => self.cycle_choice(p.path, options, 1.0),
            Kind::Number { .. } => self.start_input(),
        }
    }

    /// Opens the value input on the selected parameter, pre-filled with its value without float
    /// noise ([`super::format::editable`]); the first typed character replaces the pre-fill.
    fn start_input(&mut self) {
        let current = match PARAMETERS
            .get(self.selected)
            .map(|p| (p, self.scene.get(p.path)))
        {
            Some((p, Ok(Value::Number(v)))) => super::format::editable(v, p.unit),
            Some((_, Ok(Value::Choice(c)))) => c.to_string(),
            Some((_, Ok(Value::Enabled(b)))) => (if b { "on" } else { "off" }).to_string(),
            _ => String::new(),
        };
        self.input = Some(LineInput::prefilled(current));
    }

    fn cycle_preset(&mut self) {
        let i = self.preset.map_or(0, |i| (i + 1) % Preset::ALL.len());
        let p = Preset::ALL[i % Preset::ALL.len()];
        self.replace_scene(p.scene(), Some(i));
        self.sweep = Sweep::default_for(&self.scene);
        self.map_max = None;
        self.info(format!("preset {}: {}", p.name(), p.description()));
        self.request();
    }

    fn move_cursor(&mut self, delta: i64) {
        let max = Request::POINTS as i64 - 1;
        self.cursor = (self.cursor as i64 + delta).clamp(0, max) as usize;
    }

    fn move_map(&mut self, di: i64, dj: i64) {
        let max = Request::MAP_N as i64 - 1;
        let (i, j) = self.map_cursor;
        self.map_cursor = (
            (i as i64 + di).clamp(0, max) as usize,
            (j as i64 + dj).clamp(0, max) as usize,
        );
    }

    fn handle_input_key(&mut self, key: KeyEvent) {
        let Some(input) = self.input.as_mut() else {
            return;
        };
        match input.key(key) {
            LineEdit::Editing => {}
            LineEdit::Quit => {
                // Ctrl-C in the prompt: the prompt is cancelled, then it is q's question.
                self.input = None;
                self.ask_quit();
            }
            LineEdit::Cancel => {
                self.input = None;
                self.info("edit cancelled");
            }
            LineEdit::Submit(text) => {
                self.input = None;
                if let Some(p) = PARAMETERS.get(self.selected)
                    && self.set_text(p.path, &text)
                {
                    self.info(format!("{} = {}", p.path, text.trim()));
                }
            }
        }
    }

    fn handle_open_key(&mut self, key: KeyEvent) {
        let Some(input) = self.open.as_mut() else {
            return;
        };
        match input.key(key) {
            LineEdit::Editing => {}
            LineEdit::Quit => {
                self.open = None;
                self.ask_quit();
            }
            LineEdit::Cancel => {
                self.open = None;
                self.info("open cancelled");
            }
            LineEdit::Submit(text) => {
                self.open = None;
                self.open_scene(text.trim());
            }
        }
    }

    /// Loads a scene JSON file; on error the status line names the problem and the scene is kept.
    pub fn open_scene(&mut self, path: &str) {
        if path.is_empty() {
            self.error("open: no file name given (scene unchanged)");
            return;
        }
        let given = expand_home(path);
        let path = if given.is_relative() && !given.exists() {
            self.out_dir.join(&given)
        } else {
            given
        };
        match scene_io::load_scene(&path) {
            Ok(next) => {
                let preset = Preset::ALL.iter().position(|p| p.scene() == next);
                self.replace_scene(next, preset);
                self.saved = next;
                self.info(format!("opened scene {} (u undoes)", path.display()));
            }
            Err(e) => {
                // load_scene words its errors for the command line (`--scene FILE: …`).
                let text = e
                    .message
                    .strip_prefix("--scene ")
                    .unwrap_or(&e.message)
                    .to_string();
                self.error(format!("open {text} (scene unchanged)"));
            }
        }
    }

    fn export(&mut self) {
        let Some(data) = self.data.as_ref().filter(|d| d.request.scene == self.scene) else {
            self.info("still computing — press x again in a moment");
            return;
        };
        // The figures show what the screen shows: axis mode, experiments, pinned curve (the
        // speed range is the frame's own).
        let view = rime_core::explorer::figures::View {
            y_log: self.y_log,
            experiments: self.experiments,
            pinned: self.pinned.clone(),
        };
        match frame_export::export(&self.out_dir, data, &view) {
            Ok(dir) => self.info(format!(
                "exported scene.json, CSV tables, SVG + PNG figures to {}/",
                dir.display()
            )),
            Err(e) => self.error(format!("export failed: {e}")),
        }
    }

    /// `w`: saves the scene, asking first when it would overwrite a file that is not exactly what
    /// this session last wrote there.
    fn save(&mut self) {
        let path = self.out_dir.join(SCENE_FILE);
        let ours = self
            .wrote_scene_file
            .as_ref()
            .is_some_and(|bytes| std::fs::read(&path).is_ok_and(|now| &now == bytes));
        if path.exists() && !ours {
            self.confirm = Some(Confirm::Overwrite);
            return;
        }
        self.write_scene();
    }

    fn write_scene(&mut self) {
        let path = self.out_dir.join(SCENE_FILE);
        let result = scene_io::scene_json(&self.scene).and_then(|json| {
            let bytes = (json + "\n").into_bytes();
            scene_io::write_atomic(&path, &bytes).map(|()| bytes)
        });
        match result {
            Ok(bytes) => {
                self.saved = self.scene;
                self.wrote_scene_file = Some(bytes);
                self.info(format!("saved scene to {}", path.display()));
            }
            Err(e) => self.error(format!("save failed: {e}")),
        }
    }

    /// `q`/Esc: quits, asking first when the scene has unsaved edits.
    fn ask_quit(&mut self) {
        if self.unsaved() {
            self.confirm = Some(Confirm::Quit);
        } else {
            self.quit = true;
        }
    }

    fn handle_confirm_key(&mut self, question: Confirm, key: KeyEvent) {
        self.confirm = None;
        let yes = matches!(key.code, KeyCode::Char('y' | 'Y'));
        let ctrl_c =
            key.code == KeyCode::Char('c') && key.modifiers.contains(KeyModifiers::CONTROL);
        match question {
            Confirm::Quit if yes || ctrl_c => self.quit = true,
            Confirm::Quit => self.info("not quitting · w saves the scene"),
            Confirm::Overwrite if yes => self.write_scene(),
            Confirm::Overwrite => self.info(format!("{SCENE_FILE} kept, scene not saved")),
        }
    }

    /// Keys while the help is open: arrows and pages scroll, `q` quits, any other key closes.
    fn handle_help_key(&mut self, key: KeyEvent) {
        let (w, h) = self.size;
        let max = super::view::help::max_scroll(w, h);
        let page = super::view::help::page_rows(w, h).max(1);
        let s = self.help_scroll;
        self.help_scroll = match key.code {
            KeyCode::Up | KeyCode::Char('k') => s.saturating_sub(1),
            KeyCode::Down | KeyCode::Char('j') => (s + 1).min(max),
            KeyCode::PageUp => s.saturating_sub(page),
            KeyCode::PageDown | KeyCode::Char(' ') => (s + page).min(max),
            KeyCode::Home => 0,
            KeyCode::End => max,
            _ => {
                self.help = false;
                if keymap::action(key) == Some(Action::Quit) {
                    self.ask_quit();
                }
                return;
            }
        };
    }

    fn handle_key(&mut self, key: KeyEvent) {
        if key.kind == KeyEventKind::Release {
            return;
        }
        if let Some(question) = self.confirm {
            self.handle_confirm_key(question, key);
            return;
        }
        if self.input.is_some() {
            self.handle_input_key(key);
            return;
        }
        if self.open.is_some() {
            self.handle_open_key(key);
            return;
        }
        let action = keymap::action(key);
        if self.help && !key.modifiers.contains(KeyModifiers::CONTROL) {
            self.handle_help_key(key);
            return;
        }
        let Some(action) = action else {
            return;
        };
        let shift = key.modifiers.contains(KeyModifiers::SHIFT);
        self.perform(action, shift);
    }

    /// Does what the keymap says `action` does, on the focused pane.
    fn perform(&mut self, action: Action, shift: bool) {
        let n = PARAMETERS.len();
        let map_step = (Request::MAP_N / 20).max(1) as i64;
        let map_step = if shift { 1 } else { map_step };
        match (action, self.focus) {
            (Action::Back, _) if self.tidal => {
                self.tidal = false;
                self.info("tidal appendix closed (Esc again quits)");
            }
            // Esc closes an open panel before it asks to quit (it quit from the `v` and `i`
            // panels at once).
            (Action::Back, _) if self.stick.is_some() => {
                self.stick = None;
                self.info("sticking thresholds closed (Esc again quits)");
            }
            (Action::Back, _) if self.inside.is_some() => {
                self.inside = None;
                self.info("collision panel closed (Esc again quits)");
            }
            // Ctrl-C acts as q: it asks before dropping unsaved edits (issue 22 item 8).
            (Action::Interrupt, _) => self.ask_quit(),
            (Action::Quit | Action::Back, _) => self.ask_quit(),
            (Action::Help, _) => {
                self.help = true;
                self.help_scroll = 0;
            }
            (Action::FocusNext, _) => {
                self.focus = match self.focus {
                    Focus::Panel => Focus::Chart,
                    Focus::Chart => Focus::Map,
                    Focus::Map => Focus::Panel,
                };
                self.focus_changed();
                self.info(match self.focus {
                    Focus::Panel => "focus: parameters (↑↓ select, ←→ change)",
                    Focus::Chart => "focus: chart (←→ move the g_N cursor)",
                    Focus::Map => "focus: stick map (arrows move the map cursor)",
                });
            }
            (Action::FocusPrev, _) => {
                self.focus = match self.focus {
                    Focus::Panel => Focus::Map,
                    Focus::Chart => Focus::Panel,
                    Focus::Map => Focus::Chart,
                };
                self.focus_changed();
            }
            (Action::Up, Focus::Panel) => self.selected = (self.selected + n - 1) % n,
            (Action::Down, Focus::Panel) => self.selected = (self.selected + 1) % n,
            (Action::Right, Focus::Panel) => self.step(1.0, shift),
            (Action::Left, Focus::Panel) => self.step(-1.0, shift),
            (Action::FineRight, Focus::Panel) => self.step(1.0, true),
            (Action::FineLeft, Focus::Panel) => self.step(-1.0, true),
            (Action::Right, Focus::Chart) => self.move_cursor(5),
            (Action::Left, Focus::Chart) => self.move_cursor(-5),
            (Action::FineRight, Focus::Chart) => self.move_cursor(1),
            (Action::FineLeft, Focus::Chart) => self.move_cursor(-1),
            (Action::Up, Focus::Map) => self.move_map(map_step, 0),
            (Action::Down, Focus::Map) => self.move_map(-map_step, 0),
            (Action::Right, Focus::Map) => self.move_map(0, map_step),
            (Action::Left, Focus::Map) => self.move_map(0, -map_step),
            (Action::FineRight, Focus::Map) => self.move_map(0, 1),
            (Action::FineLeft, Focus::Map) => self.move_map(0, -1),
            (Action::Up | Action::Down, Focus::Chart) => {
                self.focus = Focus::Panel;
                self.perform(action, shift);
            }
            (Action::Activate, _) => {
                self.focus = Focus::Panel;
                self.activate();
            }
            (Action::Edit, _) => {
                self.focus = Focus::Panel;
                self.start_input();
            }
            (Action::Preset, _) => self.cycle_preset(),
            (Action::Accuracy, _) => {
                self.accuracy = self.accuracy.next();
                self.info(format!(
                    "accuracy: {} ({})",
                    self.accuracy.name(),
                    self.accuracy.trade()
                ));
                self.request();
            }
            (Action::Sweep, _) => {
                let k = SWEEPS.len();
                for d in 1..=k {
                    let i = (self.sweep + d) % k;
                    if SWEEPS[i].available(&self.scene) {
                        self.sweep = i;
                        break;
                    }
                }
                let s = self.sweep_def();
                self.info(format!("family of curves: {} ({})", s.symbol, s.path));
                self.request();
            }
            (Action::Cursor(d), _) => self.move_cursor(i64::from(d)),
            (Action::ZoomIn | Action::ZoomOut, Focus::Panel | Focus::Chart) => {
                self.zoom_speeds(if action == Action::ZoomIn { 0.5 } else { 2.0 }, None);
            }
            (Action::Pan(d), _) => self.pan_speeds(f64::from(d) * 0.25),
            (Action::ZoomAuto, Focus::Panel | Focus::Chart) => {
                self.cursor_at = self.cursor_speed();
                self.speeds = None;
                self.request();
                self.info("speed range: automatic");
            }
            (Action::ZoomIn | Action::ZoomOut, Focus::Map) => {
                let shown = self
                    .map_max
                    .or_else(|| self.data.as_ref().and_then(|d| d.map_max()))
                    .unwrap_or(1.0);
                // Zooming in shows less: the range halves.
                let next = if action == Action::ZoomOut {
                    shown * 2.0
                } else {
                    shown / 2.0
                };
                self.map_max = Some(next.clamp(1e-9, rime_core::explorer::limits::SPEED_MAX));
                self.info(format!(
                    "stick map range 0 … {}",
                    super::format::qty(next, "m/s")
                ));
                self.request();
            }
            (Action::ZoomAuto, Focus::Map) => {
                self.map_max = None;
                self.info("stick map range: automatic");
                self.request();
            }
            (Action::Compare, _) => {
                let sets = frame::COMPARISONS;
                self.overlay_set = (self.overlay_set + 1) % sets.len();
                self.request();
                self.info(format!(
                    "ε_N chart compared with: {} (c cycles)",
                    sets[self.overlay_set].0
                ));
            }
            (Action::FitToLaw, _) => {
                // The first law of the comparison shown (measured ice), else Bridges et al. 1984.
                let id = frame::COMPARISONS[self.overlay_set]
                    .1
                    .iter()
                    .filter_map(|k| k.strip_prefix("atlas:"))
                    .find(|id| {
                        rime_core::atlas::find(id)
                            .is_some_and(|e| e.kind == rime_core::atlas::Kind::Law)
                    })
                    .unwrap_or("bridges1984");
                let Some(entry) = rime_core::atlas::find(id) else {
                    return;
                };
                match rime_core::fit_scene::fit_to_entry(
                    &self.scene,
                    entry,
                    &["bulk.damping.time"],
                    self.accuracy,
                ) {
                    Ok(f) => {
                        let before = self.scene.damping_time();
                        // An edit like any other: `u` undoes it.
                        self.replace_scene(f.scene, None);
                        let p = &f.params[0];
                        self.info(format!(
                            "A fitted to {id}: {} (was {}){}, rms {} over its measured speeds",
                            super::format::qty3(p.value, "s"),
                            super::format::qty3(before, "s"),
                            p.standard_error
                                .map(|e| format!(" ± {}", super::format::qty3(e, "s")))
                                .unwrap_or_default(),
                            super::format::sig(f.rms_error, 2)
                        ));
                    }
                    Err(e) => self.error(format!("fit A to {id}: {e} (scene unchanged)")),
                }
            }
            (Action::Stick, _) => {
                if self.stick.take().is_some() {
                    self.info("sticking thresholds closed");
                } else {
                    self.stick = Some(rime_core::stick::ThresholdTable::explorer(
                        &self.scene,
                        Accuracy::Fast,
                    ));
                    self.info("sticking thresholds of this material, γ(T) of Musiolik & Wurm 2019 · v closes");
                }
            }
            (Action::Inside, _) => {
                if self.inside.is_some() {
                    self.inside = None;
                    self.info("collision panel closed");
                } else {
                    self.inside = Some((0.0, Err(String::from("computing…"))));
                    self.refresh_inside();
                    self.info(
                        "inside one collision at the ε_N cursor ([ ] { } move it) · i closes",
                    );
                }
            }
            (Action::Experiments, _) => {
                self.experiments = !self.experiments;
                self.info(if self.experiments {
                    "experiments shown on the ε_N chart: Bridges et al. 1984, Heißelmann et al. 2010, Hill et al. 2015"
                } else {
                    "experiments hidden (b shows them)"
                });
            }
            (Action::Tidal, _) => {
                self.tidal = !self.tidal;
                self.info(if self.tidal {
                    "tidal appendix for this scene's grains · < > planet distance · t closes"
                } else {
                    "tidal appendix closed"
                });
            }
            (Action::TidalNearer | Action::TidalFarther, _) if self.tidal => {
                let f = if action == Action::TidalFarther {
                    TIDAL_STEP
                } else {
                    1.0 / TIDAL_STEP
                };
                self.tidal_factor = (self.tidal_factor * f).clamp(1e-3, 1e3);
                self.info(format!(
                    "tidal: planet distance ×{} of the paper's",
                    super::format::sig(self.tidal_factor, 4)
                ));
            }
            (Action::TidalNearer | Action::TidalFarther, _) => {
                self.info("< > change the tidal appendix's planet distance: press t first");
            }
            (Action::Open, _) => {
                self.open = Some(LineInput::prefilled(SCENE_FILE));
            }
            (Action::Export, _) => self.export(),
            (Action::Save, _) => self.save(),
            (Action::YScale, _) => {
                self.y_log = !self.y_log;
                self.info(if self.y_log {
                    "ε_N axis: logarithmic (y: linear, shows sticking)"
                } else {
                    "ε_N axis: linear, sticking (ε_N = 0) on the bottom line (y: logarithmic)"
                });
            }
            (Action::Pin, _) => self.pin(),
            (Action::Walton, _) => self.toggle_walton(),
            (Action::Undo, _) => self.history(true),
            (Action::Redo, _) => self.history(false),
        }
    }

    /// In a shared layout the right-hand pane follows the focus to the chart or the map.
    fn focus_changed(&mut self) {
        match self.focus {
            Focus::Chart => self.map_shown = false,
            Focus::Map => self.map_shown = true,
            Focus::Panel => {}
        }
    }

    /// Speed at the chart cursor.
    fn cursor_speed(&self) -> Option<f64> {
        self.data
            .as_ref()
            .and_then(|d| d.g.get(self.cursor).copied())
    }

    /// The chart's speed range now: the user's, else the last frame's.
    fn speed_range(&self) -> Option<(f64, f64)> {
        self.speeds
            .or_else(|| self.data.as_deref().map(super::compute::auto_speeds))
    }

    /// Sets the chart's speed range (clamped to the core's limits, at least a quarter decade wide)
    /// and keeps the cursor on the same speed.
    fn set_speeds(&mut self, lo: f64, hi: f64) {
        // The core's limits (the same the request's validation enforces).
        use rime_core::explorer::limits::{SPEED_MAX, SPEED_MIN};
        let (min, max) = (SPEED_MIN.log10(), SPEED_MAX.log10());
        let span = (hi - lo).clamp(MIN_SPAN_DECADES, max - min);
        let lo = lo.clamp(min, max - span);
        let (lo, hi) = (10f64.powf(lo), 10f64.powf(lo + span));
        let g = self.cursor_speed();
        self.speeds = Some((lo, hi));
        if let Some(g) = g {
            self.cursor = grid_index(g, lo, hi);
            self.cursor_at = Some(g);
        }
        self.request();
        self.info(format!(
            "speed range {} … {} · + - zoom · , . pan · 0 automatic",
            super::format::qty3(lo, "m/s"),
            super::format::qty3(hi, "m/s")
        ));
    }

    /// Zooms the speed range by `factor` (in decades) around `at` (default: the cursor).
    pub fn zoom_speeds(&mut self, factor: f64, at: Option<f64>) {
        let Some((lo, hi)) = self.speed_range() else {
            return;
        };
        let (l, h) = (lo.log10(), hi.log10());
        let c = at
            .or_else(|| self.cursor_speed())
            .map_or((l + h) / 2.0, f64::log10)
            .clamp(l, h);
        // The point under `c` stays where it is.
        let (nl, nh) = (c - (c - l) * factor, c + (h - c) * factor);
        self.set_speeds(nl, nh.max(nl + MIN_SPAN_DECADES));
    }

    /// Moves the speed range by `fraction` of its width.
    fn pan_speeds(&mut self, fraction: f64) {
        let Some((lo, hi)) = self.speed_range() else {
            return;
        };
        let (l, h) = (lo.log10(), hi.log10());
        let d = (h - l) * fraction;
        self.set_speeds(l + d, h + d);
    }

    /// `P`: pins the current ε_N curve, or unpins it.
    fn pin(&mut self) {
        if self.pinned.take().is_some() {
            self.info("pinned curve removed");
            return;
        }
        let Some(data) = self.data.as_ref().filter(|d| d.request.scene == self.scene) else {
            self.info("still computing — press P again in a moment");
            return;
        };
        let s = self.sweep_def();
        let label = if s.available(&self.scene) {
            format!(
                "{} {}",
                s.symbol,
                super::format::qty3(s.current(&self.scene), s.unit)
            )
        } else {
            "pinned".to_string()
        };
        let eps = data.curve.as_ref().map(|c| c.eps()).unwrap_or_default();
        self.pinned = Some(Pinned {
            label: label.clone(),
            g: data.g.clone(),
            eps,
        });
        self.info(format!(
            "pinned this curve ({label}), drawn dashed · edit and compare · P unpins"
        ));
    }

    /// `W`: switches the sliding law between the paper's Eq. (23) and Walton's.
    fn toggle_walton(&mut self) {
        use rime_core::scene::SlidingLaw;
        let Some(f) = self.scene.friction else {
            self.error("friction is off: no sliding law (select 'friction', press Enter)");
            return;
        };
        let mut next = self.scene;
        let law = match f.sliding_law {
            SlidingLaw::Paper => SlidingLaw::Walton,
            SlidingLaw::Walton => SlidingLaw::Paper,
        };
        if let Some(f) = next.friction.as_mut() {
            f.sliding_law = law;
        }
        self.scene_changed(next);
        self.info(match law {
            SlidingLaw::Walton => "sliding law: Walton's (linear Coulomb impulse, no sliding gap) · W: the paper's · u undoes",
            SlidingLaw::Paper => "sliding law: the paper's Eq. (23) (its gap is an artifact) · W: Walton's · u undoes",
        });
    }

    /// Mouse: a click focuses the pane under it and selects the parameter row or places the chart
    /// or map cursor there; the wheel moves the cursor (chart), zooms (over the g_N axis, or with
    /// Ctrl), pans (sideways wheel), selects (panel) or scrolls the help.
    fn handle_mouse(&mut self, m: MouseEvent) {
        let Some(layout) = super::layout::layout(self.size.0, self.size.1) else {
            return;
        };
        let inside = |r: ratatui::layout::Rect| {
            m.column >= r.x && m.column < r.x + r.width && m.row >= r.y && m.row < r.y + r.height
        };
        if self.help {
            let max = super::view::help::max_scroll(self.size.0, self.size.1);
            match m.kind {
                MouseEventKind::ScrollUp => self.help_scroll = self.help_scroll.saturating_sub(2),
                MouseEventKind::ScrollDown => self.help_scroll = (self.help_scroll + 2).min(max),
                MouseEventKind::Down(_) => self.help = false,
                _ => {}
            }
            return;
        }
        if self.confirm.is_some() || self.input.is_some() || self.open.is_some() {
            return;
        }
        let drawn = self.drawn.get();
        let on_map = if layout.shared {
            self.map_shown && inside(layout.map)
        } else {
            inside(layout.map)
        };
        let on_chart = inside(layout.chart) && !on_map;
        let axis_speed = |axis: &super::layout::LogAxis| -> Option<f64> {
            if axis.width == 0 || m.column < axis.x || m.column >= axis.x + axis.width {
                return None;
            }
            let t = (f64::from(m.column - axis.x) + 0.5) / f64::from(axis.width);
            Some(10f64.powf(axis.lo + t * (axis.hi - axis.lo)))
        };
        let on_axis =
            |axis: &super::layout::LogAxis| m.row == axis.axis_row || m.row == axis.label_row;
        let ctrl = m.modifiers.contains(KeyModifiers::CONTROL);
        match m.kind {
            MouseEventKind::Down(crossterm::event::MouseButton::Left) => {
                if inside(layout.panel) {
                    self.focus = Focus::Panel;
                    if let Some((y0, offset)) = drawn.panel_rows
                        && m.row >= y0
                    {
                        let k = offset + usize::from(m.row - y0);
                        if k < PARAMETERS.len() {
                            self.selected = k;
                        }
                    }
                } else if layout.shared && inside(layout.chart) && m.row == layout.chart.y {
                    // The shared pane's title row switches between the chart and the map.
                    self.focus = if self.map_shown {
                        Focus::Chart
                    } else {
                        Focus::Map
                    };
                    self.focus_changed();
                } else if on_map {
                    self.focus = Focus::Map;
                    self.focus_changed();
                    if let (Some(r), Some(n)) = (
                        drawn.map_plot,
                        self.data
                            .as_ref()
                            .and_then(|d| d.stick_map())
                            .map(|m| m.n()),
                    ) && inside(r)
                        && n > 1
                    {
                        let pick = |k: u16, len: u16| -> usize {
                            if len <= 1 {
                                0
                            } else {
                                ((f64::from(k) * (n - 1) as f64 / f64::from(len - 1)).round()
                                    as usize)
                                    .min(n - 1)
                            }
                        };
                        let j = pick(m.column - r.x, r.width);
                        let i = pick(r.height - 1 - (m.row - r.y), r.height);
                        self.map_cursor = (i, j);
                    }
                } else if on_chart {
                    self.focus = Focus::Chart;
                    self.focus_changed();
                    if let (Some(axis), Some(data)) = (drawn.chart_axis, self.data.as_ref())
                        && let Some(g) = axis_speed(&axis)
                    {
                        self.cursor = nearest(&data.g, g);
                    }
                }
            }
            MouseEventKind::ScrollUp | MouseEventKind::ScrollDown if on_chart => {
                let up = m.kind == MouseEventKind::ScrollUp;
                match drawn.chart_axis {
                    Some(axis) if ctrl || on_axis(&axis) => {
                        self.zoom_speeds(if up { 0.8 } else { 1.25 }, axis_speed(&axis));
                    }
                    _ => self.move_cursor(if up { 2 } else { -2 }),
                }
            }
            MouseEventKind::ScrollLeft if on_chart => self.pan_speeds(-0.1),
            MouseEventKind::ScrollRight if on_chart => self.pan_speeds(0.1),
            MouseEventKind::ScrollUp if inside(layout.panel) => {
                self.selected = self.selected.saturating_sub(1);
            }
            MouseEventKind::ScrollDown if inside(layout.panel) => {
                self.selected = (self.selected + 1).min(PARAMETERS.len() - 1);
            }
            _ => {}
        }
    }
}

/// Applies one event to the state.
pub fn update(app: &mut App, event: Event) {
    match event {
        Event::Key(k) => app.handle_key(k),
        Event::Mouse(m) => app.handle_mouse(m),
        Event::Resize(w, h) => app.size = (w, h),
        Event::Computed(data) => {
            // Drop stale results: a newer request is on its way.
            if data.generation == app.generation {
                if let Some(g) = app.cursor_at.take() {
                    app.cursor = nearest(&data.g, g);
                }
                app.data = Some(*data);
            }
        }
    }
    app.refresh_inside();
}

impl App {
    /// Recomputes the collision panel's trajectory when its speed, scene or level changed (one live
    /// integration of a few hundred steps: cheap enough for the event loop).
    fn refresh_inside(&mut self) {
        let Some((g_shown, _)) = &self.inside else {
            return;
        };
        let Some(data) = self.data.as_ref().filter(|d| d.request.scene == self.scene) else {
            return;
        };
        // The collision at the focused cursor: the stick map's g_N when the map has the focus,
        // else the ε_N chart's.
        let on_map = data
            .stick_map()
            .filter(|_| self.focus == Focus::Map)
            .and_then(|m| m.g.get(self.map_cursor.0).copied())
            .filter(|g| *g > 0.0);
        let Some(g) = on_map.or_else(|| data.g.get(self.cursor).copied()) else {
            return;
        };
        if *g_shown == g && self.inside_key == Some((self.scene, self.accuracy)) {
            return;
        }
        let contact = rime_core::Contact::new(&self.scene);
        let result = contact.as_ref().map_err(|e| e.to_string()).and_then(|c| {
            c.collision(g, 200, self.accuracy)
                .map_err(|e| e.to_string())
        });
        // With adhesion, the dynamic model of the same grains beside the paper's energy balance:
        // its loop shows the neck (ξ < 0) and the jump at pull-off.
        self.inside_dynamic = match (&contact, self.scene.adhesion) {
            (Ok(c), Some(a)) => {
                rime_core::models::brilliantov2007::Dynamic::new(c, a.surface_energy, a.jkr_end)
                    .and_then(|d| d.force_loop(g, 1e-9))
                    .map(|points| points.iter().map(|p| (p.xi, p.force)).collect())
                    .unwrap_or_default()
            }
            _ => Vec::new(),
        };
        self.inside = Some((g, result));
        self.inside_key = Some((self.scene, self.accuracy));
    }
}

/// What a key did to a one-line input.
enum LineEdit {
    /// The text changed (or nothing happened); keep editing.
    Editing,
    /// Esc: drop the input.
    Cancel,
    /// Enter: the finished text.
    Submit(String),
    /// Ctrl-C: quit the explorer.
    Quit,
}

/// A one-line input (`e` values, `o` file names): the text, a cursor, and whether the text is
/// still the pre-fill, which the first typed character replaces.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LineInput {
    /// The text.
    pub text: String,
    /// Cursor position in characters (0 … length).
    pub cursor: usize,
    /// True until the user edits: the text is the pre-fill and a typed character replaces it.
    pub fresh: bool,
}

impl LineInput {
    /// An input pre-filled with `text` (cursor at the end; the first typed character replaces it).
    pub fn prefilled(text: impl Into<String>) -> LineInput {
        let text = text.into();
        LineInput {
            cursor: text.chars().count(),
            text,
            fresh: true,
        }
    }

    /// The text before and after the cursor.
    pub fn split(&self) -> (String, String) {
        let before: String = self.text.chars().take(self.cursor).collect();
        let after: String = self.text.chars().skip(self.cursor).collect();
        (before, after)
    }

    fn byte(&self, chars: usize) -> usize {
        self.text
            .char_indices()
            .nth(chars)
            .map_or(self.text.len(), |(i, _)| i)
    }

    /// Applies one key: characters insert at the cursor (replacing a fresh pre-fill), Backspace and
    /// Delete remove, ←/→/Home/End (and Ctrl-A/E) move, Ctrl-U clears.
    fn key(&mut self, key: KeyEvent) -> LineEdit {
        let ctrl = key.modifiers.contains(KeyModifiers::CONTROL);
        let len = self.text.chars().count();
        let was_fresh = std::mem::replace(&mut self.fresh, false);
        match key.code {
            KeyCode::Esc => return LineEdit::Cancel,
            KeyCode::Enter => return LineEdit::Submit(std::mem::take(&mut self.text)),
            KeyCode::Char('c') if ctrl => return LineEdit::Quit,
            KeyCode::Char('u') if ctrl => {
                self.text.clear();
                self.cursor = 0;
            }
            KeyCode::Char('a') if ctrl => self.cursor = 0,
            KeyCode::Char('e') if ctrl => self.cursor = len,
            KeyCode::Home => self.cursor = 0,
            KeyCode::End => self.cursor = len,
            KeyCode::Left => self.cursor = self.cursor.saturating_sub(1),
            KeyCode::Right => self.cursor = (self.cursor + 1).min(len),
            KeyCode::Backspace if was_fresh => {
                self.text.clear();
                self.cursor = 0;
            }
            KeyCode::Backspace if self.cursor > 0 => {
                let at = self.byte(self.cursor - 1);
                self.text.remove(at);
                self.cursor -= 1;
            }
            KeyCode::Delete if self.cursor < len => {
                let at = self.byte(self.cursor);
                self.text.remove(at);
            }
            KeyCode::Char(c) if !ctrl => {
                if was_fresh {
                    self.text.clear();
                    self.cursor = 0;
                }
                let at = self.byte(self.cursor);
                self.text.insert(at, c);
                self.cursor += 1;
            }
            _ => self.fresh = was_fresh,
        }
        LineEdit::Editing
    }
}

/// A typed path with a leading `~` or `~/` read as the home directory (as a shell would), so
/// `~/scenes/a.json` opens what the user means; any other path is taken as typed.
pub fn expand_home(path: &str) -> PathBuf {
    let home = std::env::var_os("HOME").filter(|h| !h.is_empty());
    match (path.strip_prefix('~'), home) {
        (Some(""), Some(home)) => PathBuf::from(home),
        (Some(rest), Some(home)) if rest.starts_with('/') => {
            PathBuf::from(home).join(rest.trim_start_matches('/'))
        }
        _ => PathBuf::from(path),
    }
}
