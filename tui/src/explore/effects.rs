//! Effects: what the explorer does outside its state (files read and written, the collision panel's
//! integration).

use super::frame_export;
use super::line_input::expand_home;
use super::state::*;
use crate::scene_io;
use rime_core::Preset;

impl App {
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
                self.info(format!("opened scene {} (u undoes)", shown_path(&path)));
            }
            Err(e) => {
                // load_scene words its errors for the command line (`--scene FILE: …`); the
                // file is named as every open and save names it.
                let prefix = format!("--scene {}", path.display());
                let why = e.message.strip_prefix(&prefix).unwrap_or(&e.message);
                self.error(format!("open {}{why} (scene unchanged)", shown_path(&path)));
            }
        }
    }

    pub(crate) fn export(&mut self) {
        // Exports come from the requested level, never from a preview (issue 26).
        if self.previewing() {
            self.info(format!(
                "a fast preview is on screen — nothing exported; press x again once the {} \
                 frame is in",
                self.accuracy.name()
            ));
            return;
        }
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
        match frame_export::export(&self.out_dir, data, &view, self.ring_on_chart()) {
            // The folder first: a narrow terminal cuts the end of the line (issue 37).
            Ok(dir) => self.info(format!(
                "exported to {}/ : scene.json, CSV tables, SVG + PNG figures",
                dir.display()
            )),
            Err(e) => self.error(format!("export failed: {e}")),
        }
    }

    /// `w`: saves the scene, asking first when it would overwrite a file that is not exactly what
    /// this session last wrote there.
    pub(crate) fn save(&mut self) {
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

    pub(crate) fn write_scene(&mut self) {
        let path = self.out_dir.join(SCENE_FILE);
        let result = scene_io::scene_json(&self.scene).and_then(|json| {
            let bytes = (json + "\n").into_bytes();
            scene_io::write_atomic(&path, &bytes).map(|()| bytes)
        });
        match result {
            Ok(bytes) => {
                self.saved = self.scene;
                self.wrote_scene_file = Some(bytes);
                self.info(format!("saved scene to {}", shown_path(&path)));
            }
            Err(e) => self.error(format!("save failed: {e}")),
        }
    }

    /// Recomputes the collision panel's trajectory when its speed, scene or level changed (one live
    /// integration of a few hundred steps: cheap enough for the event loop).
    pub(crate) fn refresh_inside(&mut self) {
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

    /// Recomputes the ring card when its inputs changed: the scene, τ, the planet distance (`<` `>`
    /// move the A ring with the tidal card's planet) or the chart's speeds.
    pub(crate) fn refresh_ring(&mut self) {
        if !self.ring {
            return;
        }
        let Some(chart) = self
            .data
            .as_ref()
            .and_then(|d| Some((*d.g.first()?, *d.g.last()?)))
        else {
            return;
        };
        let key = (
            self.scene,
            self.ring_tau,
            self.ring_sizes,
            self.tidal_factor,
            chart,
        );
        if self.ring_key == Some(key) {
            return;
        }
        // Kepler: at `tidal_factor` × the A ring's distance, Ω ∝ d^(−3/2).
        let omega = super::state::RING_OMEGA * self.tidal_factor.powf(-1.5);
        let input = rime_core::ring::RingInput {
            tau: self.ring_tau,
            orbit: rime_core::ring::Orbit::Omega(omega),
            damping_set_for_radius: None,
        };
        self.ring_card = Some(
            rime_core::explorer::ring::ring_card_with_sizes(
                &self.scene,
                &input,
                self.ring_sizes.sizes(self.scene.grains.radius_1).as_ref(),
                chart,
            )
            .map_err(|e| e.to_string()),
        );
        self.ring_key = Some(key);
    }
}

/// A file as the explorer names it after an open or a save (issue 37 E14: a missing file read
/// `./nothere.json`, an existing one `bad-scene.json`): the path it used, `./…` under the working
/// folder, `~/…` under the home folder, else absolute.
pub(crate) fn shown_path(path: &std::path::Path) -> String {
    let Ok(full) = std::path::absolute(path) else {
        return path.display().to_string();
    };
    // `a/./b` and `./b` read as `a/b` and `b` (absolute keeps the `.` of a relative path).
    let full: std::path::PathBuf = full
        .components()
        .filter(|c| *c != std::path::Component::CurDir)
        .collect();
    if let Ok(rest) = std::env::current_dir()
        .map_err(|_| ())
        .and_then(|cwd| full.strip_prefix(cwd).map_err(|_| ()))
    {
        return format!("./{}", rest.display());
    }
    let home = std::env::var_os("HOME").filter(|h| !h.is_empty());
    if let Some(rest) = home.and_then(|h| full.strip_prefix(h).ok().map(|r| r.to_path_buf())) {
        return format!("~/{}", rest.display());
    }
    full.display().to_string()
}
