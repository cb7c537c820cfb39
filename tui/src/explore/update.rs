//! `update`: one event applied to the state, one method per action of the keymap.

use super::compute::{SWEEPS, Sweep};
use super::keymap::{self, Action};
use super::line_input::{LineEdit, LineInput};
use super::state::*;
use crossterm::event::{KeyCode, KeyEvent, KeyEventKind, KeyModifiers, MouseEvent, MouseEventKind};
use rime_core::explorer::figures::Pinned;
use rime_core::explorer::frame::{self, Request};
use rime_core::params::{Kind, PARAMETERS, Value};
use rime_core::{Accuracy, Preset, Scene};

/// Applies one event to the state.
pub fn update(app: &mut App, event: Event) {
    match event {
        Event::Key(k) => app.handle_key(k),
        Event::Mouse(m) => app.handle_mouse(m),
        Event::Resize(w, h) => app.size = (w, h),
        Event::Computed(data) => {
            // Drop stale results: a newer request is on its way. A preview never replaces the
            // refined frame of its own request.
            let refined_shown = app
                .data
                .as_ref()
                .is_some_and(|d| d.generation == data.generation && !d.preview);
            if data.generation == app.generation && !(data.preview && refined_shown) {
                if let Some(g) = app.cursor_at.take() {
                    app.cursor = nearest(&data.g, g);
                }
                app.data = Some(*data);
            }
        }
    }
    app.refresh_inside();
    app.refresh_ring();
}

impl App {
    /// Replaces the scene (an edit: undoable) and queues a recomputation.
    pub(crate) fn scene_changed(&mut self, next: Scene) {
        self.replace_scene(next, None);
    }

    /// Replaces the scene and the preset it is, remembering the old ones for undo.
    pub(crate) fn replace_scene(&mut self, next: Scene, preset: Option<usize>) {
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

    /// Undo (`back`) or redo one scene edit.
    pub(crate) fn history(&mut self, back: bool) {
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
        let what = scene_change(&self.scene, &state.scene);
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
            "{}: {what} ({left} more) · {}",
            if back { "undone" } else { "redone" },
            if back { "U redoes" } else { "u undoes" }
        ));
    }

    pub(crate) fn set_text(&mut self, path: &str, text: &str) -> bool {
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
    pub(crate) fn step(&mut self, dir: f64, fine: bool) {
        let Some(p) = PARAMETERS.get(self.selected) else {
            return;
        };
        match (p.kind, self.scene.get(p.path)) {
            (Kind::Number { .. }, Ok(Value::Number(v))) => {
                // The core's one notch rule (the page's arrow keys take the same steps).
                let next = match rime_core::params::notch(p.kind, v, dir > 0.0, fine) {
                    Ok(next) => next,
                    Err(_) => {
                        self.error(format!(
                            "{}: is 0; press e to type a value (log steps cannot leave 0)",
                            p.path
                        ));
                        return;
                    }
                };
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

    pub(crate) fn cycle_choice(&mut self, path: &str, options: &[&str], dir: f64) {
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
    pub(crate) fn activate(&mut self) {
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
    pub(crate) fn start_input(&mut self) {
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

    pub(crate) fn cycle_preset(&mut self) {
        let i = self.preset.map_or(0, |i| (i + 1) % Preset::ALL.len());
        let p = Preset::ALL[i % Preset::ALL.len()];
        self.replace_scene(p.scene(), Some(i));
        self.sweep = Sweep::default_for(&self.scene);
        self.map_max = None;
        self.info(format!("preset {}: {}", p.name(), p.description()));
        self.request();
    }

    pub(crate) fn move_cursor(&mut self, delta: i64) {
        let max = Request::POINTS as i64 - 1;
        self.cursor = (self.cursor as i64 + delta).clamp(0, max) as usize;
    }

    pub(crate) fn move_map(&mut self, di: i64, dj: i64) {
        let max = Request::MAP_N as i64 - 1;
        let (i, j) = self.map_cursor;
        self.map_cursor = (
            (i as i64 + di).clamp(0, max) as usize,
            (j as i64 + dj).clamp(0, max) as usize,
        );
    }

    pub(crate) fn handle_input_key(&mut self, key: KeyEvent) {
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

    pub(crate) fn handle_open_key(&mut self, key: KeyEvent) {
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

    pub(crate) fn handle_confirm_key(&mut self, question: Confirm, key: KeyEvent) {
        self.confirm = None;
        let yes = matches!(key.code, KeyCode::Char('y' | 'Y'));
        let ctrl_c =
            key.code == KeyCode::Char('c') && key.modifiers.contains(KeyModifiers::CONTROL);
        match question {
            Confirm::Quit if yes || ctrl_c => self.quit = true,
            Confirm::Quit => self.info("not quitting · w saves the scene"),
            Confirm::Leave if yes || ctrl_c => self.quit = true,
            Confirm::Leave => self.info("not quitting · q quits"),
            Confirm::Overwrite if yes => self.write_scene(),
            Confirm::Overwrite => self.info(format!("{SCENE_FILE} kept, scene not saved")),
        }
    }

    /// Keys while the help is open: arrows and pages scroll, any other key (`q` and Esc too)
    /// closes it; only Ctrl-C, handled before, asks to quit (issue 37: `q` in the overlay quit).
    pub(crate) fn handle_help_key(&mut self, key: KeyEvent) {
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
                self.info("help closed · ? opens it again · q quits");
                return;
            }
        };
    }

    pub(crate) fn handle_key(&mut self, key: KeyEvent) {
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
    pub(crate) fn perform(&mut self, action: Action, shift: bool) {
        let n = PARAMETERS.len();
        let map_step = (Request::MAP_N / 20).max(1) as i64;
        let map_step = if shift { 1 } else { map_step };
        match (action, self.focus) {
            (Action::Back, _) if self.tidal => self.close_tidal(),
            // Esc closes an open panel before it asks to quit (it quit from the `v` and `i`
            // panels at once).
            (Action::Back, _) if self.stick.is_some() => self.close_stick(),
            (Action::Back, _) if self.inside.is_some() => self.close_inside(),
            (Action::Back, _) if self.ring => self.toggle_ring(),
            // Esc with nothing to close: it asks when the view (pin, zoom, comparison, ring τ)
            // or unsaved edits would be lost, rather than dropping them (issue 37).
            (Action::Back, _) => self.ask_leave(),
            // Ctrl-C acts as q: it asks before dropping unsaved edits (issue 22 item 8).
            (Action::Interrupt, _) => self.ask_quit(),
            (Action::Quit, _) => self.ask_quit(),
            (Action::Help, _) => self.open_help(),
            (Action::FocusNext, _) => self.focus_next(),
            (Action::FocusPrev, _) => self.focus_prev(),
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
            (Action::Activate, _) => self.activate_selected(),
            (Action::Edit, _) => self.edit_selected(),
            (Action::Preset, _) => self.cycle_preset(),
            (Action::Accuracy, _) => self.cycle_accuracy(),
            (Action::Sweep, _) => self.cycle_sweep(),
            (Action::Cursor(d), _) => self.move_cursor(i64::from(d)),
            (Action::ZoomIn | Action::ZoomOut, Focus::Panel | Focus::Chart) => {
                self.zoom_speeds(if action == Action::ZoomIn { 0.5 } else { 2.0 }, None);
            }
            (Action::Pan(d), _) => self.pan_speeds(f64::from(d) * 0.25),
            (Action::ZoomAuto, Focus::Panel | Focus::Chart) => self.automatic_speeds(),
            (Action::ZoomIn | Action::ZoomOut, Focus::Map) => self.zoom_map(action),
            (Action::ZoomAuto, Focus::Map) => self.automatic_map_range(),
            (Action::Compare, _) => self.cycle_comparison(),
            (Action::FitToLaw, _) => self.fit_to_law(),
            (Action::Stick, _) => self.toggle_thresholds(),
            (Action::Inside, _) => self.toggle_collision_panel(),
            (Action::Experiments, _) => self.toggle_experiments(),
            (Action::Tidal, _) => self.toggle_tidal(),
            (Action::Ring, _) => self.toggle_ring(),
            (Action::RingThinner | Action::RingDenser, _) if self.ring => self.ring_depth(action),
            (Action::RingThinner | Action::RingDenser, _) => {
                self.info("( ) change the ring card's optical depth: press r first");
            }
            (Action::RingSizes, _) if self.ring => {
                self.ring_sizes = self.ring_sizes.next();
                self.info(format!(
                    "ring: grain sizes {}",
                    match self.ring_sizes.sizes(self.scene.grains.radius_1) {
                        Some(_) => format!(
                            "{} (dN/dR ∝ R^−3 in {} bins, A the same for every pair)",
                            self.ring_sizes.label(),
                            rime_core::explorer::ring::CardSizeChoice::BINS
                        ),
                        None => "one size (the scene's grains)".to_string(),
                    }
                ));
            }
            (Action::RingSizes, _) => {
                self.info("g changes the ring card's grain sizes: press r first");
            }
            (Action::TidalNearer | Action::TidalFarther, _) if self.tidal || self.ring => {
                self.tidal_distance(action)
            }
            (Action::TidalNearer | Action::TidalFarther, _) => {
                self.info(
                    "< > change the planet distance of the tidal appendix (t) or the ring card (r)",
                );
            }
            (Action::Open, _) => self.open_prompt(),
            (Action::Export, _) => self.export(),
            (Action::Save, _) => self.save(),
            (Action::YScale, _) => self.toggle_y_scale(),
            (Action::Pin, _) => self.pin(),
            (Action::Walton, _) => self.toggle_walton(),
            (Action::Undo, _) => self.history(true),
            (Action::Redo, _) => self.history(false),
        }
    }

    pub(crate) fn close_tidal(&mut self) {
        self.tidal = false;
        self.info("tidal appendix closed · q quits");
    }

    pub(crate) fn close_stick(&mut self) {
        self.stick = None;
        self.info("sticking thresholds closed · q quits");
    }

    pub(crate) fn close_inside(&mut self) {
        self.inside = None;
        self.info("collision panel closed · q quits");
    }

    pub(crate) fn open_help(&mut self) {
        self.help = true;
        self.help_scroll = 0;
    }

    pub(crate) fn focus_next(&mut self) {
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

    pub(crate) fn focus_prev(&mut self) {
        self.focus = match self.focus {
            Focus::Panel => Focus::Map,
            Focus::Chart => Focus::Panel,
            Focus::Map => Focus::Chart,
        };
        self.focus_changed();
    }

    pub(crate) fn activate_selected(&mut self) {
        self.focus = Focus::Panel;
        self.activate();
    }

    pub(crate) fn edit_selected(&mut self) {
        self.focus = Focus::Panel;
        self.start_input();
    }

    pub(crate) fn cycle_accuracy(&mut self) {
        self.accuracy = self.accuracy.next();
        self.info(format!(
            "accuracy: {} ({})",
            self.accuracy.name(),
            self.accuracy.trade()
        ));
        self.request();
    }

    pub(crate) fn cycle_sweep(&mut self) {
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

    pub(crate) fn automatic_speeds(&mut self) {
        self.cursor_at = self.cursor_speed();
        self.speeds = None;
        self.request();
        self.info("speed range: automatic");
    }

    pub(crate) fn zoom_map(&mut self, action: Action) {
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

    pub(crate) fn automatic_map_range(&mut self) {
        self.map_max = None;
        self.info("stick map range: automatic");
        self.request();
    }

    pub(crate) fn cycle_comparison(&mut self) {
        let sets = frame::COMPARISONS;
        self.overlay_set = (self.overlay_set + 1) % sets.len();
        self.request();
        self.info(format!(
            "ε_N chart compared with: {} (c cycles)",
            sets[self.overlay_set].0
        ));
    }

    pub(crate) fn fit_to_law(&mut self) {
        // The first law of the comparison shown (measured ice), else Bridges et al. 1984 where
        // the experiments draw it on the chart; with no measured law on the chart, nothing is
        // fitted (issue 37: `f` fitted to Bridges while the chart showed no comparison).
        let compared = frame::COMPARISONS[self.overlay_set]
            .1
            .iter()
            .filter_map(|k| k.strip_prefix("atlas:"))
            .find(|id| {
                rime_core::atlas::find(id).is_some_and(|e| e.kind == rime_core::atlas::Kind::Law)
            });
        let bridges_drawn = self.overlay_set == 0
            && self.experiments
            && self.speed_range().is_some_and(|(lo, hi)| {
                let [a, b] = rime_core::atlas::PENDULUM_SPEED;
                lo.max(a) < hi.min(b)
            });
        let Some(id) = compared.or(bridges_drawn.then_some("bridges1984")) else {
            self.info("f: no measured law on the chart to fit A to · c shows measured ice");
            return;
        };
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
                let p = &f.params[0];
                // An edit like any other: `u` undoes it. A fit that lands on the scene's A (the
                // same fit twice moves it by float noise, far below its standard error and the
                // digits shown) keeps the scene and is no undo step.
                let unchanged = (p.value - before).abs() <= 1e-6 * before.abs();
                if !unchanged {
                    self.replace_scene(f.scene, None);
                }
                self.info(format!(
                    "A fitted to {id}: {} ({}){}, rms {} over its measured speeds",
                    super::format::qty3(p.value, "s"),
                    if unchanged {
                        "unchanged: already the fit, no undo step".to_string()
                    } else {
                        format!("was {}", super::format::qty3(before, "s"))
                    },
                    p.standard_error
                        .map(|e| format!(" ± {}", super::format::qty3(e, "s")))
                        .unwrap_or_default(),
                    super::format::sig(f.rms_error, 2)
                ));
            }
            Err(e) => self.error(format!("fit A to {id}: {e} (scene unchanged)")),
        }
    }

    pub(crate) fn toggle_thresholds(&mut self) {
        if self.stick.take().is_some() {
            self.info("sticking thresholds closed");
        } else {
            self.stick = Some(rime_core::stick::ThresholdTable::explorer(
                &self.scene,
                Accuracy::Fast,
            ));
            self.info(
                "sticking thresholds of this material, γ(T) of Musiolik & Wurm 2019 · v closes",
            );
        }
    }

    pub(crate) fn toggle_collision_panel(&mut self) {
        if self.inside.is_some() {
            self.inside = None;
            self.info("collision panel closed");
        } else {
            self.inside = Some((0.0, Err(String::from("computing…"))));
            self.refresh_inside();
            self.info("inside one collision at the ε_N cursor ([ ] { } move it) · i closes");
        }
    }

    pub(crate) fn toggle_experiments(&mut self) {
        self.experiments = !self.experiments;
        self.info(if self.experiments {
            "experiments shown on the ε_N chart: Bridges et al. 1984, Heißelmann et al. 2010, Hill et al. 2015"
        } else {
            "experiments hidden (b shows them)"
        });
    }

    pub(crate) fn toggle_tidal(&mut self) {
        self.tidal = !self.tidal;
        self.info(if self.tidal {
            "tidal appendix for this scene's grains · < > planet distance · t closes"
        } else {
            "tidal appendix closed"
        });
    }

    pub(crate) fn tidal_distance(&mut self, action: Action) {
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

    pub(crate) fn open_prompt(&mut self) {
        self.open = Some(LineInput::prefilled(SCENE_FILE));
    }

    pub(crate) fn toggle_y_scale(&mut self) {
        self.y_log = !self.y_log;
        self.info(if self.y_log {
            "ε_N axis: logarithmic (y: linear, shows sticking)"
        } else {
            "ε_N axis: linear, sticking (ε_N = 0) on the bottom line (y: logarithmic)"
        });
    }

    /// In a shared layout the right-hand pane follows the focus to the chart or the map.
    pub(crate) fn focus_changed(&mut self) {
        match self.focus {
            Focus::Chart => self.map_shown = false,
            Focus::Map => self.map_shown = true,
            Focus::Panel => {}
        }
    }

    /// Sets the chart's speed range (clamped to the core's limits, at least a quarter decade wide)
    /// and keeps the cursor on the same speed.
    pub(crate) fn set_speeds(&mut self, lo: f64, hi: f64) {
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
    pub(crate) fn pan_speeds(&mut self, fraction: f64) {
        let Some((lo, hi)) = self.speed_range() else {
            return;
        };
        let (l, h) = (lo.log10(), hi.log10());
        let d = (h - l) * fraction;
        self.set_speeds(l + d, h + d);
    }

    /// `P`: pins the current ε_N curve, or unpins it.
    pub(crate) fn pin(&mut self) {
        if self.pinned.take().is_some() {
            self.info("pinned curve removed");
            return;
        }
        if self.previewing() {
            self.info(format!(
                "a fast preview is on screen — press P again once the {} frame is in",
                self.accuracy.name()
            ));
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
    pub(crate) fn toggle_walton(&mut self) {
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
    // Long by design: one mouse event routed by the pane under it; the panes share the hit-testing
    // closures.
    pub(crate) fn handle_mouse(&mut self, m: MouseEvent) {
        let Some(layout) = super::layout::layout(self.size.0, self.size.1) else {
            return;
        };
        let inside = |r: ratatui::layout::Rect| {
            m.column >= r.x && m.column < r.x + r.width && m.row >= r.y && m.row < r.y + r.height
        };
        if self.help {
            self.mouse_in_help(m.kind);
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
                    if let Some(r) = drawn.map_plot.filter(|r| inside(*r)) {
                        self.click_map(r, m.column, m.row);
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

    /// The mouse over the help screen: the wheel scrolls, a click closes it.
    fn mouse_in_help(&mut self, kind: MouseEventKind) {
        let max = super::view::help::max_scroll(self.size.0, self.size.1);
        match kind {
            MouseEventKind::ScrollUp => self.help_scroll = self.help_scroll.saturating_sub(2),
            MouseEventKind::ScrollDown => self.help_scroll = (self.help_scroll + 2).min(max),
            MouseEventKind::Down(_) => self.help = false,
            _ => {}
        }
    }

    /// A click at (`column`, `row`) inside the stick map's plot `r` moves the map cursor there.
    fn click_map(&mut self, r: ratatui::layout::Rect, column: u16, row: u16) {
        let Some(n) = self
            .data
            .as_ref()
            .and_then(|d| d.stick_map())
            .map(|m| m.n())
            .filter(|n| *n > 1)
        else {
            return;
        };
        let pick = |k: u16, len: u16| -> usize {
            if len <= 1 {
                0
            } else {
                ((f64::from(k) * (n - 1) as f64 / f64::from(len - 1)).round() as usize).min(n - 1)
            }
        };
        let j = pick(column - r.x, r.width);
        let i = pick(r.height - 1 - (row - r.y), r.height);
        self.map_cursor = (i, j);
    }

    /// `r`: the ring card on or off.
    pub(crate) fn toggle_ring(&mut self) {
        self.ring = !self.ring;
        self.info(if self.ring {
            "ring card: ε_cr(τ) on the ε_N chart · ( ) optical depth · < > planet distance · g grain sizes · r closes"
        } else {
            "ring card closed"
        });
    }

    /// `(` / `)`: the ring card's optical depth ÷/× [`RING_TAU_STEP`], within the card's domain.
    pub(crate) fn ring_depth(&mut self, action: Action) {
        let f = if action == Action::RingDenser {
            RING_TAU_STEP
        } else {
            1.0 / RING_TAU_STEP
        };
        self.ring_tau = (self.ring_tau * f).clamp(1e-3, 5.0);
        self.info(format!(
            "ring: optical depth τ = {}",
            super::format::sig(self.ring_tau, 3)
        ));
    }
}

/// What changes from `from` to `to`, as a person reads it: `A 2 ms → 100 µs`, each changed
/// parameter (symbol, old value, new value); the first three and how many more (issue 37: undo
/// said only "undone").
pub(crate) fn scene_change(from: &rime_core::Scene, to: &rime_core::Scene) -> String {
    use super::view::panel::value_text;
    let changed: Vec<String> = PARAMETERS
        .iter()
        .filter(|p| from.get(p.path) != to.get(p.path))
        .map(|p| {
            let symbol = p.label.split_whitespace().next().unwrap_or(p.path);
            let (a, _) = value_text(from, p.path, p.unit);
            let (b, _) = value_text(to, p.path, p.unit);
            format!("{symbol} {a} → {b}")
        })
        .collect();
    match changed.len() {
        0 => "no parameter changed".to_string(),
        1..=3 => changed.join(", "),
        n => format!("{} and {} more", changed[..3].join(", "), n - 3),
    }
}
