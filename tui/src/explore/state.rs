//! The explorer's state and its `update` function (the Elm-like core; no terminal I/O here apart
//! from the files that `x` and `w` write).

use super::colors::Colors;
use super::compute::{Computed, Job, SWEEPS, Sweep};
use super::line_input::LineInput;
use crossterm::event::{KeyEvent, MouseEvent};
use rime_core::explorer::figures::Pinned;
use rime_core::explorer::frame::{self, Request};
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

/// What a ring card was computed for: scene, τ, sizes, planet-distance factor, chart speeds.
pub type RingKey = (
    Scene,
    f64,
    rime_core::explorer::ring::CardSizeChoice,
    f64,
    (f64, f64),
);

/// The explorer's whole state.
#[derive(Debug, Clone)]
pub struct App {
    /// The scene being explored.
    pub scene: Scene,
    /// Accuracy level.
    pub accuracy: Accuracy,
    /// Index into [`Preset::ALL`] of the last preset chosen with `p` (None: scene from elsewhere).
    pub preset: Option<usize>,
    /// Selected row of [`PARAMETERS`](rime_core::params::PARAMETERS).
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
    /// Whether the ring card is shown (`r`).
    pub ring: bool,
    /// The ring card's optical depth τ.
    pub ring_tau: f64,
    /// The ring card's grain sizes (`g`): one size or a power law from the scene's radius.
    pub ring_sizes: rime_core::explorer::ring::CardSizeChoice,
    /// The ring card (or why it could not be computed), for [`App::ring_key`].
    pub ring_card: Option<Result<rime_core::explorer::ring::RingCard, String>>,
    /// What the ring card was computed for: scene, τ, sizes, planet-distance factor, chart speeds.
    pub ring_key: Option<RingKey>,
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
    /// Esc on the main view: quit although the view (pin, zoom, comparison, ring τ) would be
    /// lost with it.
    Leave,
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
pub(crate) fn nearest(g: &[f64], target: f64) -> usize {
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

/// The ring card's optical depth when it opens: Saturn's A ring.
pub const RING_TAU: f64 = 0.5;
/// The ring card's Ω when it opens, in 1/s: Saturn's A ring, the Ω of the README's worked example,
/// `rime ring --help` and the page's card (issue 37 E16: the card took the tidal card's Encke
/// division, 1.26153e-4 1/s, and printed another c than the README for the same preset). `<` `>`
/// move the ring with the planet distance: Ω ∝ d^(−3/2).
pub const RING_OMEGA: f64 = 1.3143527e-4;
/// Factor by which `(` / `)` change the ring card's optical depth.
pub const RING_TAU_STEP: f64 = 1.25;

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
            ring: false,
            ring_tau: RING_TAU,
            ring_card: None,
            ring_key: None,
            ring_sizes: Default::default(),
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

    /// Whether the shown data are older than the latest request, or only its preview.
    pub fn computing(&self) -> bool {
        self.data
            .as_ref()
            .is_none_or(|d| d.generation != self.generation || d.preview)
    }

    /// Whether the frame on screen is the `fast` preview of the latest request, its refinement to
    /// the requested level still computing.
    pub fn previewing(&self) -> bool {
        self.data
            .as_ref()
            .is_some_and(|d| d.generation == self.generation && d.preview)
    }

    /// The ring card drawn over the ε_N chart: only while the card is open (`r`) and computed. The
    /// chart and `x` both ask here, so the export draws the ring exactly when the screen does.
    pub fn ring_on_chart(&self) -> Option<&rime_core::explorer::ring::RingCard> {
        self.ring
            .then_some(self.ring_card.as_ref())
            .flatten()
            .and_then(|c| c.as_ref().ok())
    }

    pub(crate) fn info(&mut self, text: impl Into<String>) {
        self.message = Some((text.into(), Tone::Info));
    }

    pub(crate) fn error(&mut self, text: impl Into<String>) {
        self.message = Some((text.into(), Tone::Error));
    }

    /// The swept parameter.
    pub fn sweep_def(&self) -> Sweep {
        SWEEPS.get(self.sweep).copied().unwrap_or(SWEEPS[3])
    }

    /// Keeps the sweep valid after the scene changed (falls back to the scene's default).
    pub(crate) fn fix_sweep(&mut self) {
        if !self.sweep_def().available(&self.scene) {
            self.sweep = Sweep::default_for(&self.scene);
        }
    }

    /// Whether the scene differs from the one last saved, opened or started with.
    pub fn unsaved(&self) -> bool {
        self.scene != self.saved
    }

    /// `q`/Esc: quits, asking first when the scene has unsaved edits.
    pub(crate) fn ask_quit(&mut self) {
        if self.unsaved() {
            self.confirm = Some(Confirm::Quit);
        } else {
            self.quit = true;
        }
    }

    /// What quitting now loses besides the scene: the view the user set up (a pinned curve, a
    /// zoom, a comparison, the ring card's τ), in words; empty when the view is the default one.
    pub fn view_to_lose(&self) -> Vec<&'static str> {
        let mut lost = Vec::new();
        if self.pinned.is_some() {
            lost.push("the pinned curve");
        }
        if self.speeds.is_some() {
            lost.push("the zoom");
        }
        if self.overlay_set != 0 {
            lost.push("the comparison");
        }
        if self.ring_tau != RING_TAU {
            lost.push("the ring's τ");
        }
        if self.ring_sizes != Default::default() {
            lost.push("the ring's sizes");
        }
        lost
    }

    /// Esc on the main view: asks before quitting when unsaved edits or the view would be lost
    /// (a second Esc used to drop a pin, zoom and comparison silently); else quits.
    pub(crate) fn ask_leave(&mut self) {
        if self.unsaved() {
            self.confirm = Some(Confirm::Quit);
        } else if !self.view_to_lose().is_empty() {
            self.confirm = Some(Confirm::Leave);
        } else {
            self.quit = true;
        }
    }

    /// Speed at the chart cursor.
    pub(crate) fn cursor_speed(&self) -> Option<f64> {
        self.data
            .as_ref()
            .and_then(|d| d.g.get(self.cursor).copied())
    }

    /// The chart's speed range now: the user's, else the last frame's.
    pub(crate) fn speed_range(&self) -> Option<(f64, f64)> {
        self.speeds
            .or_else(|| self.data.as_deref().map(super::compute::auto_speeds))
    }
}
