//! Tests of the explorer: `update` logic, `TestBackend` buffer assertions and insta snapshots.

use super::compute::{SWEEPS, compute};
use super::state::{App, Confirm, Event, Focus, RING_TAU, RING_TAU_STEP, TIDAL_STEP, Tone};
use super::update::update;
use super::view::render;
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use rime_core::normal::memo::NoMemo;
use rime_core::params::{PARAMETERS, Value};
use rime_core::{Accuracy, Preset, Scene};
use std::time::Duration;

fn key(c: KeyCode) -> Event {
    Event::Key(KeyEvent::new(c, KeyModifiers::NONE))
}

fn ch(c: char) -> Event {
    key(KeyCode::Char(c))
}

/// Runs the pending request synchronously, as the worker would.
fn settle(app: &mut App) {
    if let Some(req) = app.take_request() {
        let data = compute(&req, &|| false, &NoMemo).expect("not cancelled");
        update(app, Event::Computed(Box::new(data)));
    }
}

fn app_on(scene: Scene) -> App {
    let mut app = App::new(scene, Accuracy::Fast);
    app.fixed_elapsed = Some(Duration::from_millis(3));
    settle(&mut app);
    app
}

fn screen(app: &App, w: u16, h: u16) -> Terminal<TestBackend> {
    let mut t = Terminal::new(TestBackend::new(w, h)).expect("terminal");
    t.draw(|f| render(app, f)).expect("draw");
    t
}

fn text(t: &Terminal<TestBackend>) -> String {
    let buf = t.backend().buffer();
    let mut s = String::new();
    for y in 0..buf.area.height {
        for x in 0..buf.area.width {
            // Non-breaking spaces (kept together by the legend's wrapping) read as spaces.
            s.push_str(&buf[(x, y)].symbol().replace('\u{a0}', " "));
        }
        s.push('\n');
    }
    s
}

fn select(app: &mut App, path: &str) {
    app.selected = PARAMETERS
        .iter()
        .position(|p| p.path == path)
        .expect("known path");
    app.focus = Focus::Panel;
}

fn number(app: &App, path: &str) -> f64 {
    match app.scene.get(path) {
        Ok(Value::Number(v)) => v,
        other => panic!("{path}: {other:?}"),
    }
}

#[test]
fn main_screen_snapshot() {
    let app = app_on(Scene::default());
    let t = screen(&app, 100, 30);
    insta::assert_snapshot!("main_100x30", text(&t));
}

#[test]
fn main_screen_frost_snapshot() {
    let app = app_on(Preset::IceFrost.scene());
    let t = screen(&app, 100, 30);
    insta::assert_snapshot!("frost_100x30", text(&t));
}

#[test]
fn help_overlay_snapshot() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('?'));
    assert!(app.help);
    let t = screen(&app, 100, 30);
    let s = text(&t);
    assert!(s.contains("rime — keys"));
    insta::assert_snapshot!("help_100x30", s);
    update(&mut app, ch('j'));
    assert!(app.help && app.help_scroll == 1, "j scrolls the help");
    update(&mut app, ch('x'));
    assert!(!app.help, "any other key closes the help");
    assert!(!app.quit);
}

#[test]
fn too_small_snapshot() {
    let app = app_on(Scene::default());
    let t = screen(&app, 50, 15);
    let s = text(&t);
    assert!(s.contains("terminal too small (need 60×20)"));
    insta::assert_snapshot!("too_small_50x15", s);
}

#[test]
fn main_screen_shows_every_parameter_and_class() {
    let app = app_on(Preset::IceFrost.scene());
    let s = text(&screen(&app, 120, 40));
    for p in PARAMETERS {
        let head: String = p.label.chars().take(8).collect();
        assert!(s.contains(&head), "missing parameter {}", p.path);
    }
    for c in rime_core::StickClass::ALL {
        assert!(
            s.contains(&c.name().replace('_', " ")),
            "missing class {c:?}"
        );
    }
    assert!(s.contains("g_N [m/s]"), "the speed axis names its unit");
    assert!(s.contains("g_s layer 6.6"), "critical velocity marker");
    assert!(!s.contains("NaN") && !s.contains("inf"));
}

#[test]
fn every_size_from_minimum_renders_without_panic() {
    let app = app_on(Preset::IceSticky.scene());
    for (w, h) in [(60, 20), (80, 24), (61, 23), (200, 60), (59, 40), (1, 1)] {
        let s = text(&screen(&app, w, h));
        assert!(!s.contains("NaN"), "{w}×{h}");
    }
}

#[test]
fn changing_a_parameter_changes_the_scene() {
    let mut app = app_on(Preset::IceFrost.scene());
    select(&mut app, "layer.viscosity");
    let g0 = app.generation;
    update(&mut app, ch('l'));
    assert!((number(&app, "layer.viscosity") - 1250.0).abs() < 1e-9);
    assert!(app.generation > g0, "a recomputation is requested");
    update(&mut app, key(KeyCode::Left));
    assert!((number(&app, "layer.viscosity") - 1000.0).abs() < 1e-9);
    update(&mut app, ch('L'));
    assert!((number(&app, "layer.viscosity") - 1020.0).abs() < 1e-9);
    // Linear parameter: ±0.05.
    select(&mut app, "friction.coefficient");
    update(&mut app, ch('l'));
    assert!((number(&app, "friction.coefficient") - 0.35).abs() < 1e-12);
    // Toggle: layer off and on.
    select(&mut app, "layer");
    update(&mut app, key(KeyCode::Enter));
    assert!(app.scene.layer.is_none());
    update(&mut app, ch(' '));
    assert!(app.scene.layer.is_some());
    // Choice cycles.
    select(&mut app, "contact_end");
    update(&mut app, key(KeyCode::Enter));
    assert_eq!(
        app.scene.get("contact_end"),
        Ok(Value::Choice("zero_overlap"))
    );
}

#[test]
fn typed_value_with_units_is_applied() {
    let mut app = app_on(Preset::IceFrost.scene());
    select(&mut app, "layer.thickness");
    update(&mut app, ch('e'));
    assert!(app.input.is_some());
    for c in "2 um".chars() {
        update(&mut app, ch(c));
    }
    update(&mut app, key(KeyCode::Enter));
    assert!(app.input.is_none());
    assert!((number(&app, "layer.thickness") - 2e-6).abs() < 1e-18);
}

#[test]
fn typed_bad_value_keeps_scene_and_names_the_field() {
    let mut app = app_on(Preset::IceFrost.scene());
    let before = app.scene;
    select(&mut app, "grains.density");
    update(&mut app, ch('e'));
    for c in "-5".chars() {
        update(&mut app, ch(c));
    }
    update(&mut app, key(KeyCode::Enter));
    assert_eq!(app.scene, before);
    let (msg, tone) = app.message.clone().expect("a message");
    assert_eq!(tone, Tone::Error);
    assert!(msg.contains("grains.density"), "{msg}");
    let s = text(&screen(&app, 100, 30));
    assert!(s.contains("grains.density"), "error shown on screen");
    // Wrong unit.
    select(&mut app, "layer.thickness");
    update(&mut app, ch('e'));
    for c in "1 Pa".chars() {
        update(&mut app, ch(c));
    }
    update(&mut app, key(KeyCode::Enter));
    assert_eq!(app.scene, before);
    assert!(
        app.message
            .as_ref()
            .is_some_and(|m| m.0.contains("layer.thickness"))
    );
}

#[test]
fn escape_cancels_input_without_quitting() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('e'));
    update(&mut app, key(KeyCode::Esc));
    assert!(app.input.is_none());
    assert!(!app.quit);
    update(&mut app, key(KeyCode::Esc));
    assert!(app.quit);
}

#[test]
fn preset_cycling() {
    let mut app = app_on(Scene::default());
    assert_eq!(app.preset, Some(0));
    update(&mut app, ch('p'));
    assert_eq!(app.scene, Preset::IceFrost.scene());
    assert_eq!(SWEEPS[app.sweep].path, "layer.viscosity");
    update(&mut app, ch('p'));
    assert_eq!(app.scene, Preset::IceSticky.scene());
    assert_eq!(SWEEPS[app.sweep].path, "adhesion.surface_energy");
    update(&mut app, ch('p'));
    assert_eq!(app.scene, Preset::IcePaperViscosities.scene());
    assert_eq!(SWEEPS[app.sweep].path, "bulk.damping.time");
    update(&mut app, ch('p'));
    assert_eq!(app.scene, Preset::Ice.scene());
}

#[test]
fn accuracy_cycling() {
    let mut app = app_on(Scene::default());
    assert_eq!(app.accuracy, Accuracy::Fast);
    let g = app.generation;
    update(&mut app, ch('a'));
    assert_eq!(app.accuracy, Accuracy::Precise);
    assert!(app.generation > g);
    update(&mut app, ch('a'));
    assert_eq!(app.accuracy, Accuracy::Balanced);
    update(&mut app, ch('a'));
    assert_eq!(app.accuracy, Accuracy::Fast);
}

#[test]
fn sweep_cycling_skips_unavailable_parameters() {
    let mut app = app_on(Scene::default());
    assert_eq!(SWEEPS[app.sweep].path, "bulk.damping.time");
    for _ in 0..10 {
        update(&mut app, ch('s'));
        assert!(SWEEPS[app.sweep].available(&app.scene));
    }
}

#[test]
fn stale_results_are_dropped() {
    let mut app = App::new(Scene::default(), Accuracy::Fast);
    let old = app.take_request().expect("initial request");
    update(&mut app, ch('a'));
    let data = compute(&old, &|| false, &NoMemo).expect("computed");
    update(&mut app, Event::Computed(Box::new(data)));
    assert!(app.data.is_none(), "stale frame ignored");
    settle(&mut app);
    assert!(app.data.is_some());
    assert!(!app.computing());
}

#[test]
fn cancelled_computation_returns_nothing() {
    let app = App::new(Preset::IceFrost.scene(), Accuracy::Fast);
    let req = app.pending.clone().expect("request");
    assert!(compute(&req, &|| true, &NoMemo).is_none());
}

#[test]
fn cursor_moves_and_readout_has_no_nan() {
    let mut app = app_on(Preset::IceFrost.scene());
    let c = app.cursor;
    update(&mut app, ch(']'));
    assert_eq!(app.cursor, c + 1);
    update(&mut app, ch('{'));
    assert_eq!(app.cursor, c - 9);
    for _ in 0..100 {
        update(&mut app, ch('{'));
    }
    assert_eq!(app.cursor, 0);
    let s = text(&screen(&app, 100, 30));
    assert!(s.contains("stuck in layer"), "stuck at the slowest speed");
    assert!(s.contains("t_c — (stuck)"));
    update(&mut app, key(KeyCode::Tab));
    update(&mut app, key(KeyCode::Tab));
    assert_eq!(app.focus, Focus::Map);
    let m = app.map_cursor;
    update(&mut app, key(KeyCode::Up));
    assert!(app.map_cursor.0 > m.0);
}

/// Issue 12 item 4 / issue 11: `x` exports what the screen shows — the ε_N axis mode (`y`) and the
/// pinned curve (`P`) reach the exported figure.
#[test]
fn export_shows_what_the_screen_shows_issue_12() {
    let dir = std::env::temp_dir().join(format!("rime-tui-test-screen-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp");
    let svg_after = |app: &mut App| -> String {
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("tmp");
        update(app, ch('x'));
        let export = std::fs::read_dir(&dir)
            .expect("read")
            .filter_map(|e| e.ok())
            .find(|e| e.file_name().to_string_lossy().starts_with("rime-export-"))
            .expect("export folder")
            .path();
        std::fs::read_to_string(export.join("eps_n.svg")).expect("figure")
    };
    let mut app = app_on(Preset::IceFrost.scene());
    app.out_dir = dir.clone();
    let first = svg_after(&mut app);
    let log_first = first.contains("(log;");
    assert_eq!(log_first, app.y_log, "the figure's axis follows the screen");
    assert!(!first.contains("pinned:"));
    update(&mut app, ch('y'));
    update(&mut app, ch('P'));
    assert!(app.pinned.is_some());
    let second = svg_after(&mut app);
    assert_eq!(second.contains("(log;"), app.y_log);
    assert_ne!(log_first, app.y_log, "y toggled the axis");
    assert!(second.contains("pinned:"), "the pinned curve is exported");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn export_writes_csvs_and_scene() {
    let dir = std::env::temp_dir().join(format!("rime-tui-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp");
    let mut app = app_on(Preset::IceFrost.scene());
    app.out_dir = dir.clone();
    update(&mut app, ch('x'));
    let (msg, tone) = app.message.clone().expect("message");
    assert_eq!(tone, Tone::Info, "{msg}");
    assert!(msg.contains("rime-export-"));
    let export = std::fs::read_dir(&dir)
        .expect("read")
        .filter_map(|e| e.ok())
        .find(|e| e.file_name().to_string_lossy().starts_with("rime-export-"))
        .expect("export folder")
        .path();
    let data = |name: &str| -> Vec<String> {
        let text = std::fs::read_to_string(export.join(name)).expect(name);
        assert!(text.starts_with("# "), "{name} starts with its context");
        assert!(text.contains("Hertzsch (2002)"), "{name} cites the model");
        text.lines()
            .filter(|l| !l.starts_with('#'))
            .map(String::from)
            .collect()
    };
    let curve = data("eps_curve.csv");
    assert_eq!(
        curve[0],
        "g_n [m/s],eps_n,status,t_c [s],xi_max [m],error_estimate"
    );
    assert_eq!(curve.len(), 1 + rime_core::explorer::frame::Request::POINTS);
    let family = data("eps_family.csv");
    assert!(
        family[0].starts_with("g_n [m/s],eps_n,eps_n clean surfaces,eps_n [η* = 500 Pa s]"),
        "{}",
        family[0]
    );
    let map = data("stick_map.csv");
    assert_eq!(map[0], "g_n [m/s],g_t [m/s],eps_t,class");
    for figure in ["eps_n.svg", "eps_n.png", "stick_map.svg", "stick_map.png"] {
        let bytes = std::fs::read(export.join(figure)).expect("figure written");
        assert!(bytes.len() > 1000, "{figure} is suspiciously small");
    }
    let scene = std::fs::read_to_string(export.join("scene.json")).expect("scene");
    assert_eq!(
        crate::scene_io::parse_scene(&scene).expect("valid scene"),
        app.scene
    );
    update(&mut app, ch('w'));
    assert!(dir.join("rime-scene.json").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn paper_inconsistent_options_are_flagged() {
    let mut app = app_on(Preset::IceFrost.scene());
    app.scene.set("layer.reading", "literal").expect("set");
    app.scene
        .set("friction.sliding_law", "walton")
        .expect("set");
    // The core's warnings of the frame name it (Walton's law is an option, not a departure).
    app.request();
    settle(&mut app);
    let flagged = |app: &App| -> Vec<&'static str> {
        app.data
            .as_ref()
            .expect("data")
            .warnings
            .iter()
            .filter(|w| w.is_paper_option())
            .map(|w| w.short())
            .collect()
    };
    assert_eq!(flagged(&app), vec!["Eq. (8) read literally"]);
    let s = text(&screen(&app, 120, 40));
    assert!(
        s.contains("paper-inconsistent option in use: Eq. (8) read literally"),
        "{s}"
    );
    // Issue 21: the terminal flagged 3 of the core's 5 warnings; the adhesion modulus is one it
    // missed (setting it switches adhesion on).
    app.scene
        .set("adhesion.modulus", "consistent")
        .expect("set");
    assert!(app.scene.adhesion.is_some());
    app.request();
    settle(&mut app);
    assert_eq!(
        flagged(&app),
        vec!["Eq. (8) read literally", "adhesion modulus consistent"]
    );
}

#[test]
fn tidal_panel_snapshot() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('t'));
    assert!(app.tidal);
    let s = text(&screen(&app, 100, 30));
    // The paper's example: every quantity with its unit and the printed number beside it.
    for needle in [
        "ΔF tide A.1",
        "3.84e-11 N",
        "3.142e-3 N",
        "6.283e-3 N",
        "6.28e-3 N",
        "1.341e8 m",
        "3.077e5 m",
        "5.43e4 m",
        "37.72 m",
        "37.6 m",
        "adhesion is off",
    ] {
        assert!(s.contains(needle), "missing {needle}\n{s}");
    }
    insta::assert_snapshot!("tidal_100x30", s);
    // Further out than the Roche distance: no r_max.
    update(&mut app, ch('>'));
    assert!((app.tidal_factor - super::state::TIDAL_STEP).abs() < 1e-12);
    let s = text(&screen(&app, 100, 30));
    assert!(s.contains("none: at or outside d_Roche"), "{s}");
    assert!(s.contains("not comparable"));
    // The scene's adhesion supplies γ.
    update(&mut app, ch('<'));
    app.scene = Preset::IceSticky.scene();
    let view = super::tidal::view(&app.scene, app.tidal_factor);
    assert!(!view.gamma_from_paper);
    assert_eq!(
        view.input.surface_energy,
        app.scene.adhesion.map_or(0.0, |a| a.surface_energy)
    );
    // Esc closes the panel before it quits.
    update(&mut app, key(KeyCode::Esc));
    assert!(!app.tidal && !app.quit);
}

#[test]
fn tidal_panel_fits_80x24() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('t'));
    let s = text(&screen(&app, 80, 24));
    for needle in ["ΔF tide", "r_max A.5", "³ r_max", "t/Esc closes"] {
        assert!(s.contains(needle), "missing {needle}\n{s}");
    }
}

fn tmp_dir(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("rime-tui-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp");
    dir
}

fn type_open(app: &mut App, path: &str) {
    update(app, ch('o'));
    assert_eq!(
        app.open.as_ref().map(|i| i.text.as_str()),
        Some(super::state::SCENE_FILE)
    );
    update(
        app,
        Event::Key(KeyEvent::new(KeyCode::Char('u'), KeyModifiers::CONTROL)),
    );
    for c in path.chars() {
        update(app, ch(c));
    }
    update(app, key(KeyCode::Enter));
    assert!(app.open.is_none());
}

#[test]
fn open_bad_file_keeps_scene_and_names_the_field() {
    let dir = tmp_dir("open-bad");
    let bad = dir.join("bad.json");
    let mut json: serde_json::Value =
        serde_json::from_str(&crate::scene_io::scene_json(&Scene::default()).expect("json"))
            .expect("parse");
    json["grains"]["density"] = serde_json::json!(-3.0);
    std::fs::write(&bad, json.to_string()).expect("write");
    let mut app = app_on(Preset::IceFrost.scene());
    let before = app.scene;
    let g = app.generation;
    type_open(&mut app, &bad.display().to_string());
    assert_eq!(app.scene, before, "scene kept");
    assert_eq!(app.generation, g, "nothing recomputed");
    let (msg, tone) = app.message.clone().expect("message");
    assert_eq!(tone, Tone::Error);
    assert!(msg.contains("density"), "{msg}");
    assert!(msg.contains("scene unchanged"), "{msg}");
    let s = text(&screen(&app, 100, 30));
    assert!(s.contains("density"), "error shown in the status line\n{s}");
    // A missing file is an error too, and Esc cancels typing.
    type_open(&mut app, &dir.join("nope.json").display().to_string());
    assert_eq!(app.scene, before);
    assert_eq!(app.message.as_ref().map(|m| m.1), Some(Tone::Error));
    update(&mut app, ch('o'));
    update(&mut app, key(KeyCode::Esc));
    assert!(app.open.is_none() && !app.quit);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn open_good_file_replaces_scene() {
    let dir = tmp_dir("open-good");
    let mut app = app_on(Preset::IceFrost.scene());
    app.out_dir = dir.clone();
    update(&mut app, ch('w'));
    let saved = app.scene;
    update(&mut app, ch('p'));
    assert_ne!(app.scene, saved);
    let g = app.generation;
    // The default name resolves in the folder `w` writes to.
    update(&mut app, ch('o'));
    update(&mut app, key(KeyCode::Enter));
    assert_eq!(app.scene, saved);
    assert!(app.generation > g, "recomputation requested");
    assert_eq!(app.preset, Some(1), "recognised as the frost preset");
    let (msg, tone) = app.message.clone().expect("message");
    assert_eq!(tone, Tone::Info, "{msg}");
    assert!(msg.contains("rime-scene.json"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn toggling_experiments_changes_the_chart() {
    let mut app = app_on(Scene::default());
    assert!(app.experiments, "on by default");
    let on = text(&screen(&app, 100, 30));
    assert!(
        on.contains("bridges1984") && on.contains("heisselmann2010") && on.contains("hill2015")
    );
    update(&mut app, ch('b'));
    assert!(!app.experiments);
    let off = text(&screen(&app, 100, 30));
    assert!(!off.contains("bridges1984"));
    // Not only the legend: the plotted cells differ too.
    let plot = |s: &str| -> String {
        s.lines()
            .skip(3)
            .take(10)
            .map(|l| l.chars().skip(37).collect::<String>())
            .collect::<Vec<_>>()
            .join("\n")
    };
    assert_ne!(plot(&on), plot(&off));
    update(&mut app, ch('b'));
    assert_eq!(plot(&text(&screen(&app, 100, 30))), plot(&on));
}

/// Every page of the help at `w × h`, scrolled with PgDn from the top (the help stays open).
fn help_pages(app: &mut App, w: u16, h: u16) -> String {
    app.size = (w, h);
    update(app, ch('?'));
    let mut all = String::new();
    let mut last = String::new();
    for _ in 0..40 {
        let s = text(&screen(app, w, h));
        if s == last {
            break;
        }
        all.push_str(&s);
        last = s;
        update(app, key(KeyCode::PageDown));
        assert!(app.help, "PgDn scrolls, it does not close the help");
    }
    update(app, ch('x'));
    assert!(!app.help, "another key closes the help");
    all
}

#[test]
fn help_names_new_keys_and_sources() {
    let mut app = app_on(Scene::default());
    let s = help_pages(&mut app, 100, 30);
    for needle in [
        "tidal appendix",
        "experiments",
        "open",
        "undo / redo",
        "pin this ε_N curve",
        "Walton",
        "linear shows sticking",
        "Bridges",
        "Heißelmann",
        "Hill",
    ] {
        assert!(s.contains(needle), "missing {needle}\n{s}");
    }
    // Issue 12, item 8: at 80×24 and 60×20 every line is reachable (it was cut before "quit").
    for (w, h) in [(80, 24), (60, 20)] {
        let s = help_pages(&mut app, w, h);
        for row in super::keymap::KEYMAP {
            let head: String = row.does.chars().take(12).collect();
            assert!(s.contains(&head), "{w}×{h}: missing '{}'\n{s}", row.does);
        }
        assert!(s.contains("quit") && s.contains("Hill"), "{w}×{h}\n{s}");
        // The first page says how to scroll and that q closes it (issue 37: it quit).
        update(&mut app, ch('?'));
        let first = text(&screen(&app, w, h));
        assert!(
            first.contains("scroll") && first.contains("q Esc or any other key closes"),
            "{first}"
        );
        update(&mut app, ch('x'));
    }
}

#[test]
fn readme_key_list_is_the_keymap_table() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../README.md"))
        .expect("README.md");
    let start = readme
        .find("<!-- keys: generated from tui/src/explore/keymap.rs -->\n")
        .expect("README key list start marker");
    let rest = &readme[start..];
    let body_start = rest.find('\n').expect("marker line") + 1;
    let end = rest
        .find("<!-- /keys -->")
        .expect("README key list end marker");
    assert_eq!(
        &rest[body_start..end],
        super::keymap::readme_list(),
        "README.md's key list differs from tui/src/explore/keymap.rs: paste readme_list()"
    );
}

#[test]
fn every_key_in_the_keymap_is_handled() {
    use super::keymap::{KEYMAP, Key};
    let dir = tmp_dir("keymap");
    let mut seen = Vec::new();
    for row in KEYMAP {
        for (k, action) in row.bindings {
            assert!(!seen.contains(k), "{k:?} bound twice");
            seen.push(*k);
            assert_eq!(super::keymap::action(k.event()), Some(*action), "{k:?}");
            // Every key changes something visible in some pane (the tidal keys with the panel open).
            let mut changed = false;
            for focus in [Focus::Panel, Focus::Chart, Focus::Map] {
                let mut app = app_on(Preset::IceFrost.scene());
                app.out_dir = dir.clone();
                app.focus = focus;
                app.message = None;
                select(&mut app, "layer.viscosity");
                app.focus = focus;
                if matches!(k, Key::Char('<' | '>')) {
                    app.tidal = true;
                }
                let before = format!("{app:?}");
                update(&mut app, Event::Key(k.event()));
                changed |= format!("{app:?}") != before;
            }
            assert!(changed, "{k:?} ({}) does nothing", row.keys);
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 12, item 1: `e` pre-filled "0.000199999999999999982" and typing appended to it.
#[test]
fn typing_after_e_replaces_the_prefill() {
    let mut app = app_on(Scene::default());
    select(&mut app, "bulk.damping.time");
    // A damping time with float noise, as viscosities give it.
    let noisy = 2e-4 * (1.0 - f64::EPSILON);
    app.scene
        .set_number("bulk.damping.time", noisy)
        .expect("set");
    update(&mut app, ch('e'));
    let input = app.input.clone().expect("input open");
    assert_eq!(input.text, "200 µs", "pre-fill without float noise");
    let s = text(&screen(&app, 100, 30));
    assert!(s.contains("200 µs") && s.contains("typing replaces"), "{s}");
    for c in "2 ms".chars() {
        update(&mut app, ch(c));
    }
    update(&mut app, key(KeyCode::Enter));
    assert_eq!(number(&app, "bulk.damping.time"), 2e-3);
    // Editing keys keep the pre-fill: End, ←, Backspace, then a digit.
    update(&mut app, ch('e'));
    assert_eq!(app.input.as_ref().map(|i| i.text.as_str()), Some("2 ms"));
    for k in [KeyCode::End, KeyCode::Left, KeyCode::Left, KeyCode::Left] {
        update(&mut app, key(k));
    }
    update(&mut app, key(KeyCode::Backspace));
    update(&mut app, ch('5'));
    assert_eq!(app.input.as_ref().map(|i| i.text.as_str()), Some("5 ms"));
    update(&mut app, key(KeyCode::Home));
    update(&mut app, ch('1'));
    update(&mut app, key(KeyCode::Enter));
    assert_eq!(number(&app, "bulk.damping.time"), 15e-3);
    let s = text(&screen(&app, 100, 30));
    assert!(!s.contains("999999"), "{s}");
}

/// Issue 12, item 2: the ε_N chart's decade labels sat up to 0.4 decade from their values (ratatui
/// spreads labels evenly), so the 6.6 µm/s marker read like 3–4 µm/s. The marker (drawn by the
/// canvas) must fall between the labels where its value says, within one cell, at every width.
#[test]
fn chart_x_labels_sit_at_their_values() {
    let app = app_on(Preset::IceFrost.scene());
    let g_s = app
        .data
        .as_ref()
        .and_then(|d| d.contact)
        .and_then(|c| c.layer)
        .map(|l| l.critical_velocity)
        .expect("g_s of the layer");
    assert!((g_s - 6.6e-6).abs() < 0.1e-6, "{g_s}");
    let marker = super::view::plot::Colors::Rgb.color(rime_core::explorer::palette::CRITICAL);
    let decade = |s: &str| -> Option<f64> {
        match s {
            "0.01" => Some(-2.0),
            "0.1" => Some(-1.0),
            "1" => Some(0.0),
            "10" => Some(1.0),
            "100" => Some(2.0),
            _ => s.strip_prefix("1e").and_then(|e| e.parse().ok()),
        }
    };
    for (w, h) in [(60, 20), (80, 24), (100, 30), (120, 40), (200, 60)] {
        let t = screen(&app, w, h);
        let buf = t.backend().buffer();
        let chart = super::layout::layout(w, h).expect("layout").chart;
        let (corner, axis_row) = (chart.y..chart.bottom())
            .flat_map(|y| (chart.x..chart.right()).map(move |x| (x, y)))
            .find(|&(x, y)| buf[(x, y)].symbol() == "└")
            .expect("x axis");
        // The labels: runs of text on the row below the axis, each centred on its column.
        let mut labels: Vec<(f64, f64)> = Vec::new();
        let mut run = String::new();
        for x in chart.x..=chart.right() {
            let sym = if x < chart.right() {
                buf[(x, axis_row + 1)].symbol().to_string()
            } else {
                " ".to_string()
            };
            if sym.trim().is_empty() {
                if !run.is_empty() {
                    let n = run.chars().count() as u16;
                    let start = x - n;
                    // The axis title's end (`g_N [m/s]`) may share the row.
                    if decade(&run).is_none() && run.chars().any(|c| !"0123456789.e-".contains(c)) {
                        run.clear();
                        continue;
                    }
                    let k = decade(&run).unwrap_or_else(|| panic!("label {run} at {w}×{h}"));
                    labels.push((k, f64::from(start + n / 2)));
                    // Each label stands on a major tick.
                    let tick = buf[(start + n / 2, axis_row)].symbol();
                    assert_eq!(tick, "┼", "{run} at {w}×{h}");
                    run.clear();
                }
            } else {
                run.push_str(&sym);
            }
        }
        assert!(labels.len() >= 3, "{w}×{h}: {labels:?}");
        // Labels evenly spaced per decade (they are log positions), within one cell.
        let (k0, c0) = labels[0];
        let (k1, c1) = labels[labels.len() - 1];
        let per_decade = (c1 - c0) / (k1 - k0);
        for (k, c) in &labels {
            let expected = c0 + (k - k0) * per_decade;
            assert!(
                (c - expected).abs() <= 1.0,
                "{w}×{h}: label {k} at {c}, not {expected}"
            );
        }
        // The marker: the column with the most cells in the marker colour.
        let marker_col = (corner + 1..chart.right())
            .max_by_key(|&x| {
                (chart.y..axis_row)
                    .filter(|&y| buf[(x, y)].fg == marker && buf[(x, y)].symbol() != " ")
                    .count()
            })
            .expect("marker column");
        let expected = c0 + (g_s.log10() - k0) * per_decade;
        assert!(
            (f64::from(marker_col) - expected).abs() <= 1.0,
            "{w}×{h}: 6.6 µm/s marker at column {marker_col}, the labels put it at {expected:.1}"
        );
    }
}

#[test]
fn collision_panel_follows_the_cursor_and_its_ledger_closes_issue_13() {
    let mut app = app_on(Preset::IceSticky.scene());
    update(&mut app, ch('i'));
    let (g, first) = app.inside.clone().expect("panel open");
    let t = first.expect("trajectory");
    let c = rime_core::Contact::new(&app.scene).expect("contact");
    let n = c.normal(g, app.accuracy).expect("normal");
    // The panel shows the collision the ε_N chart's cursor points at, as the core computes it.
    assert_eq!(g, app.data.as_ref().expect("data").g[app.cursor]);
    assert_eq!((t.eps_n, t.t_c), (n.eps, n.t_c));
    assert!(t.ledger.closure.abs() < 1e-6, "{:?}", t.ledger);
    // With adhesion the dynamic JKR model's loop is drawn beside it, neck (ξ < 0, tensile) included.
    assert!(
        app.inside_dynamic
            .iter()
            .any(|&(xi, f)| xi < 0.0 && f < 0.0),
        "no neck in {} points",
        app.inside_dynamic.len()
    );
    let s = text(&screen(&app, 80, 24));
    for needle in [
        "inside one collision",
        "kinetic out",
        "bulk, Eq. (4)",
        "closure",
        "i closes",
    ] {
        assert!(s.contains(needle), "missing {needle}\n{s}");
    }
    // Moving the cursor recomputes it; `i` closes it.
    update(&mut app, ch('{'));
    let (g2, _) = app.inside.clone().expect("still open");
    assert!(g2 < g, "{g2} vs {g}");
    // With the stick map focused, the panel follows the map cursor's g_N.
    app.focus = Focus::Map;
    update(
        &mut app,
        Event::Key(KeyEvent::new(KeyCode::Up, KeyModifiers::NONE)),
    );
    let (g3, _) = app.inside.clone().expect("still open");
    let map = app.data.as_ref().and_then(|d| d.stick_map()).expect("map");
    assert_eq!(g3, map.g[app.map_cursor.0]);
    update(&mut app, ch('i'));
    assert!(app.inside.is_none());
}

#[test]
fn compare_key_overlays_measured_ice_then_other_models_issues_15_16() {
    let mut app = app_on(Preset::IceSticky.scene());
    update(&mut app, ch('c'));
    let req = app.take_request().expect("a new request");
    let data = compute(&req, &|| false, &NoMemo).expect("frame");
    let law = data
        .overlays
        .iter()
        .find(|o| o.overlay.key() == "atlas:bridges1984")
        .expect("bridges1984 drawn");
    let entry = rime_core::atlas::find("bridges1984").expect("entry");
    // Only over the speeds it was measured at, with the scene's score.
    assert_eq!(law.g.first(), Some(&entry.valid_speed[0]));
    assert_eq!(law.g.last(), Some(&entry.valid_speed[1]));
    assert!(law.score.is_some_and(|r| r.is_finite() && r >= 0.0));
    update(&mut app, Event::Computed(Box::new(data)));
    let s = text(&screen(&app, 80, 24));
    assert!(s.contains("bridges1984 (") && s.contains(" rms "), "{s}");
    update(&mut app, ch('c'));
    let req = app.take_request().expect("a new request");
    let data = compute(&req, &|| false, &NoMemo).expect("frame");
    let model = data
        .overlays
        .iter()
        .find(|o| o.overlay.key() == "model:brilliantov2007")
        .expect("brilliantov2007 drawn");
    assert!(model.speeds.iter().any(|(n, g)| *n == "g_cr" && *g > 0.0));
    assert_eq!(model.g, data.g);
    // No plasticity section in the preset: thornton1997 is left out, not an error.
    assert!(data.problem().is_none(), "{:?}", data.problem());
    update(&mut app, ch('c'));
    assert_eq!(app.overlay_set, 0);
}

#[test]
fn fit_key_fits_a_to_the_first_measured_law_issue_15() {
    let mut app = app_on(Preset::Ice.scene());
    update(&mut app, ch('c'));
    update(&mut app, ch('f'));
    let (msg, tone) = app.message.clone().expect("message");
    assert_eq!(tone, Tone::Info, "{msg}");
    assert!(msg.starts_with("A fitted to bridges1984"), "{msg}");
    // The scene now has the A that fit_to_entry finds (the core's fit, not one of the explorer's).
    let expected = rime_core::fit_scene::fit_to_entry(
        &Preset::Ice.scene(),
        rime_core::atlas::find("bridges1984").expect("entry"),
        &["bulk.damping.time"],
        app.accuracy,
    )
    .expect("fit");
    assert_eq!(app.scene, expected.scene);
    // With A from viscosities there is no A to fit: the scene stays, the error says why.
    let mut app = app_on(Preset::IcePaperViscosities.scene());
    let before = app.scene;
    update(&mut app, ch('f'));
    assert_eq!(app.scene, before);
    assert_eq!(app.message.clone().expect("message").1, Tone::Error);
}

#[test]
fn fit_key_is_undoable_issue_22() {
    let mut app = app_on(Preset::Ice.scene());
    let before = app.scene;
    update(&mut app, ch('f'));
    assert_ne!(app.scene, before, "the fit changed nothing");
    let fitted = app.scene;
    update(&mut app, ch('u'));
    assert_eq!(app.scene, before);
    update(&mut app, ch('U'));
    assert_eq!(app.scene, fitted);
}

#[test]
fn stick_panel_tabulates_the_cores_thresholds_issue_15() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('v'));
    let table = app.stick.clone().expect("panel open");
    let t = rime_core::stick::threshold(
        &Scene::default(),
        1e-6,
        200.0,
        rime_core::stick::Convention::SurfaceEnergy,
        Accuracy::Fast,
    )
    .expect("threshold");
    assert_eq!(
        table.cell(0, 2).and_then(|c| c.threshold.as_ref()),
        Some(&t)
    );
    let s = text(&screen(&app, 80, 24));
    for needle in [
        "sticking thresholds",
        "v_stick, the scene's A",
        "Eq. (15)",
        "9.6 m/s",
    ] {
        assert!(s.contains(needle), "missing {needle}\n{s}");
    }
    update(&mut app, ch('v'));
    assert!(app.stick.is_none());
}

#[test]
fn the_thresholds_panel_draws_the_cores_figure_when_tall_issue_21() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('v'));
    let table = app.stick.clone().expect("panel open");
    let fig = rime_core::explorer::thresholds::thresholds_figure(&table);
    // Tall: every series of the core's figure is in the legend on screen, with the axis titles.
    let tall = text(&screen(&app, 200, 60));
    for s in &fig.series {
        assert!(tall.contains(&s.short), "missing {}\n{tall}", s.short);
    }
    for label in [&fig.x.label, &fig.y.label] {
        assert!(tall.contains(label.as_str()), "missing {label}\n{tall}");
    }
    // Small: the tables alone (no room for a readable figure), still whole.
    let small = text(&screen(&app, 80, 24));
    assert!(!small.contains(&fig.series[0].short), "{small}");
    assert!(small.contains("9.6 m/s"), "{small}");
}

#[test]
fn the_ring_card_opens_on_r_and_draws_eps_cr_on_the_chart_issue_24() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('r'));
    let card = match app.ring_card.clone() {
        Some(Ok(card)) => card,
        other => panic!("no ring card: {other:?}"),
    };
    let s = text(&screen(&app, 160, 45));
    assert!(s.contains("ring: what the law does to it"), "{s}");
    assert!(
        s.contains(&card.eps_cr_line.short),
        "ε_cr line not in the legend\n{s}"
    );
    for row in &card.rows {
        assert!(
            s.contains(&row.text),
            "missing {}: {}\n{s}",
            row.label,
            row.text
        );
    }
    // τ and the planet distance are inputs: the card follows them.
    update(&mut app, ch(')'));
    assert_eq!(app.ring_tau, RING_TAU * RING_TAU_STEP);
    assert!(matches!(&app.ring_card, Some(Ok(c)) if c.record.tau == app.ring_tau));
    let omega = |app: &App| match &app.ring_card {
        Some(Ok(c)) => c.record.omega,
        _ => f64::NAN,
    };
    let before = omega(&app);
    update(&mut app, ch('>'));
    // Ω ∝ d^(-3/2): one step of 1.05 farther.
    let expected = before * TIDAL_STEP.powf(-1.5);
    assert!(
        (omega(&app) - expected).abs() <= 1e-12 * expected,
        "{} vs {expected}",
        omega(&app)
    );
    update(&mut app, ch('r'));
    assert!(!text(&screen(&app, 160, 45)).contains("ring: what the law does to it"));
}

/// Issue 38: `g` cycles the ring card's grain sizes (one, R–5R, R–10R, one); a distribution's rows
/// show on the screen, start at the scene's radius and end at 5R; leaving asks about them.
#[test]
fn issue_38_g_cycles_the_ring_cards_grain_sizes() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('g'));
    assert!(app.ring_sizes == Default::default(), "g without the card");
    update(&mut app, ch('r'));
    assert!(matches!(&app.ring_card, Some(Ok(c)) if c.sizes.is_none()));
    update(&mut app, ch('g'));
    let card = match app.ring_card.clone() {
        Some(Ok(card)) => card,
        other => panic!("no ring card: {other:?}"),
    };
    let rec = card.sizes.clone().expect("a distribution");
    let r = app.scene.grains.radius_1;
    assert_eq!(rec.size_bins.len(), 3);
    assert_eq!(rec.size_bins[0].radius_min, r);
    assert!((rec.size_bins[2].radius_max - 5.0 * r).abs() <= 1e-15 * r);
    assert_eq!(card.verdict, rec.verdict.words());
    let s = text(&screen(&app, 160, 60));
    // Every row's label is on the screen (texts wrap), and the ring-wide c in its words.
    for row in &card.rows {
        assert!(s.contains(&row.label), "missing {}\n{s}", row.label);
    }
    let c = rime_core::explorer::format::qty(rec.velocity_dispersion, "m/s");
    assert!(s.contains(&format!("c = {c}")), "{c}\n{s}");
    assert!(app.view_to_lose().contains(&"the ring's sizes"));
    update(&mut app, ch('g'));
    assert!(
        matches!(&app.ring_card, Some(Ok(c)) if c.sizes.as_ref().is_some_and(|s| s.size_bins[2].radius_max > 9.9 * r))
    );
    update(&mut app, ch('g'));
    assert!(matches!(&app.ring_card, Some(Ok(c)) if c.sizes.is_none()));
}

/// Issue 22: the `v` panel is computed for the scene's A (it kept the A it was opened with): at
/// A = 0 the full model sticks exactly up to Eq. (15)'s g_s, evaluated here from the closed form;
/// at A = 100 µs damping raises the threshold; the titles say which A each table uses.
#[test]
fn thresholds_panel_follows_the_scenes_damping_time_issue_22() {
    let mut elastic = Scene::default();
    elastic.bulk.damping = rime_core::Damping::Time(0.0);
    let mut app = app_on(elastic);
    update(&mut app, ch('v'));
    // Eq. (15) for two 1 µm ice grains at 200 K (γ_s = 0.19 J/m², w = 2γ_s, E = Y/(1 − ν²),
    // as printed): g_s = (14.18/m_eff)^(1/2) (w⁵ R_eff⁴/E²)^(1/6).
    let (r, rho, y, nu, w): (f64, f64, f64, f64, f64) = (1e-6, 900.0, 1e10, 0.3, 0.38);
    let m_eff = 0.5 * 4.0 / 3.0 * std::f64::consts::PI * r.powi(3) * rho;
    let e = y / (1.0 - nu * nu);
    let g_s = (14.18 / m_eff).sqrt() * (w.powi(5) * (0.5 * r).powi(4) / (e * e)).powf(1.0 / 6.0);
    let at_zero = app.stick.clone().expect("panel open");
    let cell = at_zero.cell(0, 2).and_then(|c| c.threshold).expect("cell");
    assert!(
        (cell.v_elastic / g_s - 1.0).abs() < 1e-9,
        "{cell:?} vs {g_s}"
    );
    assert!(
        (cell.v_stick.expect("rebounds") / g_s - 1.0).abs() < 1e-6,
        "{cell:?}"
    );
    assert!(text(&screen(&app, 100, 30)).contains("the scene's A = 0 s"));
    // An edit of A with the panel open: the table follows it.
    select(&mut app, "bulk.damping.time");
    update(&mut app, ch('e'));
    for c in "100 us".chars() {
        update(&mut app, ch(c));
    }
    update(&mut app, key(KeyCode::Enter));
    assert_eq!(number(&app, "bulk.damping.time"), 1e-4);
    let at_a = app.stick.clone().expect("panel open");
    assert_eq!(at_a.damping_time, 1e-4);
    let cell = at_a.cell(3, 2).and_then(|c| c.threshold).expect("cell");
    assert!(
        cell.v_stick.is_none_or(|v| v > 1.01 * cell.v_elastic),
        "{cell:?}"
    );
    let s = text(&screen(&app, 100, 30));
    assert!(s.contains("the scene's A = 100 µs"), "{s}");
    assert!(s.contains("A = 0, no layer"), "{s}");
}

fn click(column: u16, row: u16) -> Event {
    Event::Mouse(crossterm::event::MouseEvent {
        kind: crossterm::event::MouseEventKind::Down(crossterm::event::MouseButton::Left),
        column,
        row,
        modifiers: KeyModifiers::NONE,
    })
}

fn wheel(up: bool, column: u16, row: u16) -> Event {
    Event::Mouse(crossterm::event::MouseEvent {
        kind: if up {
            crossterm::event::MouseEventKind::ScrollUp
        } else {
            crossterm::event::MouseEventKind::ScrollDown
        },
        column,
        row,
        modifiers: KeyModifiers::NONE,
    })
}

/// Rows of the ε_N chart's plot (the y axis line above the x axis), as drawn.
fn chart_rows(app: &App, w: u16, h: u16) -> usize {
    let t = screen(app, w, h);
    let axis = app.drawn.get().chart_axis.expect("chart drawn");
    let buf = t.backend().buffer();
    (0..axis.axis_row)
        .filter(|y| matches!(buf[(axis.x - 1, *y)].symbol(), "│" | "┤"))
        .count()
}

/// Issue 12, item 8: at 80×24 the chart had 5 rows; the chart and the map now share the right-hand
/// pane on short terminals (Tab switches), so the chart gets the whole height.
#[test]
fn chart_gets_a_useful_height_at_80x24_issue_12_item_8() {
    let mut app = app_on(Scene::default());
    app.size = (80, 24);
    let rows = chart_rows(&app, 80, 24);
    // 13: the x axis' title (with its unit) has a row of its own since issue 21.
    assert!(rows >= 13, "chart rows at 80×24: {rows}");
    assert!(chart_rows(&app, 60, 20) >= 10);
    // Tall terminals keep both views.
    let s = text(&screen(&app, 120, 40));
    assert!(s.contains("ε_N(g_N)") && s.contains("stick map"));
    let s = text(&screen(&app, 80, 24));
    assert!(s.contains("stick map: Tab"), "{s}");
    // Tab: chart, then the map in the same pane, with every class in its legend.
    update(&mut app, key(KeyCode::Tab));
    update(&mut app, key(KeyCode::Tab));
    assert_eq!(app.focus, Focus::Map);
    let s = text(&screen(&app, 80, 24));
    assert!(
        s.contains("ε_N chart: Tab") && !s.contains("ε_N(g_N)"),
        "{s}"
    );
    for c in rime_core::StickClass::ALL {
        let label = super::view::map::legend_label(c, 17);
        assert!(s.contains(&label), "missing {label}\n{s}");
    }
    // A click on the pane's title row switches back to the chart.
    update(&mut app, click(50, 0));
    assert_eq!(app.focus, Focus::Chart);
    assert!(text(&screen(&app, 80, 24)).contains("ε_N(g_N)"));
}

/// Issue 12, item 6: every class explained in the legend and the help, the sliding gap marked as an
/// artifact, and Walton's law one key (`W`) away.
#[test]
fn stick_classes_explained_gap_is_an_artifact_walton_one_key_issue_12_item_6() {
    use rime_core::StickClass;
    use rime_core::scene::SlidingLaw;
    let mut app = app_on(Scene::default());
    let s = text(&screen(&app, 120, 40));
    assert!(s.contains("sliding gap: artifact"), "{s}");
    let help = help_pages(&mut app, 100, 30);
    for c in StickClass::ALL {
        let (meaning, _) = super::view::help::class_meaning(c);
        let head: String = meaning.chars().take(20).collect();
        assert!(help.contains(&head), "help misses {c:?}\n{help}");
    }
    assert!(help.contains("an artifact of the printed law, not a regime"));
    let gaps = |app: &App| {
        let m = app.data.as_ref().and_then(|d| d.stick_map()).expect("map");
        m.class
            .iter()
            .filter(|c| **c == StickClass::SlidingGap)
            .count()
    };
    assert!(gaps(&app) > 0, "the default scene shows the gap");
    update(&mut app, ch('W'));
    settle(&mut app);
    assert_eq!(
        app.scene.friction.map(|f| f.sliding_law),
        Some(SlidingLaw::Walton)
    );
    assert_eq!(gaps(&app), 0, "Walton's law has no gap");
    update(&mut app, ch('W'));
    assert_eq!(
        app.scene.friction.map(|f| f.sliding_law),
        Some(SlidingLaw::Paper)
    );
    // The readout at a gap cell says so.
    settle(&mut app);
    let m = app
        .data
        .as_ref()
        .and_then(|d| d.stick_map().cloned())
        .expect("map");
    let k = m
        .class
        .iter()
        .position(|c| *c == StickClass::SlidingGap)
        .expect("a gap cell");
    app.map_cursor = (k / m.n(), k % m.n());
    let s = text(&screen(&app, 120, 40));
    assert!(s.contains("artifact of Eq. (23)"), "{s}");
    // Without friction, W says why it does nothing.
    select(&mut app, "friction");
    update(&mut app, key(KeyCode::Enter));
    update(&mut app, ch('W'));
    assert_eq!(app.message.as_ref().map(|m| m.1), Some(Tone::Error));
}

/// Issue 12, item 9: a glossary, human labels, a labelled timing, the adhesion g_s note and the
/// tidal warning inside Saturn.
#[test]
fn glossary_human_labels_timing_and_warnings_issue_12_item_9() {
    let mut app = app_on(Preset::IceSticky.scene());
    let s = text(&screen(&app, 100, 30));
    for raw in ["force_zero", "as_printed", "zero_overlap"] {
        assert!(!s.contains(raw), "raw enum name {raw} on screen\n{s}");
    }
    assert!(s.contains("force returns to zero"), "{s}");
    assert!(s.contains("as printed"), "{s}");
    assert!(s.contains("computed in 3 ms at fast"), "{s}");
    let s = text(&screen(&app, 160, 40));
    assert!(s.contains("g_s adhesion, on the rebound speed"), "{s}");
    let help = help_pages(&mut app, 100, 30);
    for sym in [
        "δ, δ(g)",
        "tan ψ₀",
        "g_s adhesion",
        "ε_N",
        "ε_T",
        "g_N, g_T",
    ] {
        assert!(help.contains(sym), "glossary misses {sym}");
    }
    assert!(help.contains("a rebound speed (Eq. (15))"));
    // Cycling a choice names it in words.
    select(&mut app, "contact_end");
    update(&mut app, key(KeyCode::Enter));
    let msg = app.message.clone().expect("message").0;
    assert!(msg.contains("overlap returns to zero"), "{msg}");
    // The tidal view warns inside the planet.
    update(&mut app, ch('t'));
    assert!(!text(&screen(&app, 100, 30)).contains("inside Saturn"));
    app.tidal_factor = 0.3;
    let s = text(&screen(&app, 100, 30));
    assert!(s.contains("inside Saturn"), "{s}");
}

/// Issue 12, item 10: undo/redo (a preset too), asking before overwriting the scene file and
/// before quitting with unsaved edits.
#[test]
fn undo_redo_and_confirmations_issue_12_item_10() {
    let dir = tmp_dir("undo");
    let mut app = app_on(Scene::default());
    app.out_dir = dir.clone();
    let start = app.scene;
    // A clean scene quits at once.
    let mut clean = app.clone();
    update(&mut clean, ch('q'));
    assert!(clean.quit);
    select(&mut app, "friction.coefficient");
    update(&mut app, ch('l'));
    let edited = app.scene;
    assert_ne!(edited, start);
    // p until a preset that is neither the start nor the edit (the first may be the default).
    update(&mut app, ch('p'));
    let mut presses = 1;
    while app.scene == start || app.scene == edited {
        update(&mut app, ch('p'));
        presses += 1;
    }
    let preset = app.scene;
    update(&mut app, ch('u'));
    assert_ne!(app.scene, preset, "u undoes the preset");
    for _ in 1..presses {
        update(&mut app, ch('u'));
    }
    assert_eq!(app.scene, edited);
    update(
        &mut app,
        Event::Key(KeyEvent::new(KeyCode::Char('z'), KeyModifiers::CONTROL)),
    );
    assert_eq!(app.scene, start);
    update(&mut app, ch('U'));
    assert_eq!(app.scene, edited);
    for _ in 0..presses {
        update(
            &mut app,
            Event::Key(KeyEvent::new(KeyCode::Char('y'), KeyModifiers::CONTROL)),
        );
    }
    assert_eq!(app.scene, preset);
    assert!(app.preset.is_some(), "redo restores the preset's name");
    // q with unsaved edits asks; n stays.
    update(&mut app, ch('q'));
    assert!(!app.quit);
    assert!(text(&screen(&app, 100, 30)).contains("quit anyway?"));
    update(&mut app, ch('n'));
    assert!(!app.quit && app.confirm.is_none());
    update(&mut app, key(KeyCode::Esc));
    assert!(app.confirm.is_some(), "Esc asks too");
    update(&mut app, ch('n'));
    // w over an existing file asks; n keeps it.
    let file = dir.join("rime-scene.json");
    std::fs::write(&file, "keep me").expect("write");
    update(&mut app, ch('w'));
    assert!(text(&screen(&app, 100, 30)).contains("exists: overwrite it?"));
    update(&mut app, ch('n'));
    assert_eq!(std::fs::read_to_string(&file).expect("read"), "keep me");
    update(&mut app, ch('w'));
    update(&mut app, ch('y'));
    assert!(
        std::fs::read_to_string(&file)
            .expect("read")
            .contains("grains")
    );
    // Saved: q quits at once.
    update(&mut app, ch('q'));
    assert!(app.quit);
    // An edit after saving asks again; y quits.
    let mut app2 = app_on(Scene::default());
    select(&mut app2, "friction.coefficient");
    update(&mut app2, ch('l'));
    update(&mut app2, ch('q'));
    update(&mut app2, ch('y'));
    assert!(app2.quit);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 12, item 11: clicks focus a pane, select a parameter and place the cursors; `+` zooms in;
/// the focused pane's border is thick and highlighted.
#[test]
fn mouse_clicks_focus_select_and_place_cursors_issue_12_item_11() {
    let mut app = app_on(Preset::IceFrost.scene());
    app.size = (100, 30);
    let t = screen(&app, 100, 30);
    let l = super::layout::layout(100, 30).expect("layout");
    // The focused panel's border is thick and cyan; the chart's is thin.
    let buf = t.backend().buffer();
    let edge = &buf[(l.panel.right() - 1, 5)];
    assert_eq!(edge.symbol(), "┃");
    assert_eq!(edge.fg, ratatui::style::Color::Cyan);
    assert_eq!(buf[(l.chart.right() - 1, l.chart.y)].symbol(), "─");
    // Click the fifth parameter row.
    let (y0, offset) = app.drawn.get().panel_rows.expect("panel drawn");
    update(&mut app, click(3, y0 + 4));
    assert_eq!(app.selected, offset + 4);
    // Click in the chart at a column: focus and cursor there.
    let axis = app.drawn.get().chart_axis.expect("chart drawn");
    let col = axis.x + axis.width / 4;
    update(&mut app, click(col, axis.axis_row - 2));
    assert_eq!(app.focus, Focus::Chart);
    let t = screen(&app, 100, 30);
    assert_eq!(
        t.backend().buffer()[(l.chart.right() - 1, l.chart.y)].symbol(),
        "━"
    );
    let g = app.data.as_ref().expect("data").g[app.cursor].log10();
    let want =
        axis.lo + (f64::from(col - axis.x) + 0.5) / f64::from(axis.width) * (axis.hi - axis.lo);
    assert!((g - want).abs() < 0.05, "cursor at {g}, clicked {want}");
    // Click in the map: focus and map cursor there.
    let r = app.drawn.get().map_plot.expect("map drawn");
    update(&mut app, click(r.x, r.y + r.height - 1));
    assert_eq!(app.focus, Focus::Map);
    assert_eq!(app.map_cursor, (0, 0));
    update(&mut app, click(r.x + r.width - 1, r.y));
    assert_eq!(app.map_cursor, (80, 80));
    // `+` zooms the map in (range halves), `-` out.
    settle(&mut app);
    let before = app.data.as_ref().and_then(|d| d.map_max()).expect("data");
    update(&mut app, ch('+'));
    assert!((app.map_max.expect("set") - before / 2.0).abs() < 1e-12 * before);
    update(&mut app, ch('-'));
    assert!((app.map_max.expect("set") - before).abs() < 1e-12 * before);
}

/// Issue 12, item 4: the ε_N axis toggles linear/log (`y`); the speed range zooms and pans (keys
/// and the wheel on the axis) and lives in the request.
#[test]
fn y_axis_toggle_and_speed_zoom_pan_issue_12_item_4() {
    let mut app = app_on(Preset::IceFrost.scene());
    app.size = (100, 30);
    assert!(app.y_log);
    update(&mut app, ch('y'));
    assert!(!app.y_log);
    let s = text(&screen(&app, 100, 30));
    assert!(s.contains("0.5") && s.contains("linear"), "{s}");
    // Sticking (below g_s of the layer) sits on the ε_N = 0 line: the bottom row of the plot has
    // Braille dots left of the marker.
    let axis = app.drawn.get().chart_axis.expect("axis");
    let t = screen(&app, 100, 30);
    let bottom: String = (axis.x..axis.x + axis.width / 3)
        .map(|x| {
            t.backend().buffer()[(x, axis.axis_row - 1)]
                .symbol()
                .to_string()
        })
        .collect();
    assert!(
        bottom
            .chars()
            .any(|c| ('\u{2801}'..='\u{28ff}').contains(&c)),
        "{bottom}"
    );
    // Zoom in around the cursor: half the decades, in the request, computed.
    app.focus = Focus::Chart;
    let (lo, hi) = super::compute::auto_speeds(app.data.as_deref().expect("data"));
    let g = app.data.as_ref().expect("data").g[app.cursor];
    update(&mut app, ch('+'));
    let (zlo, zhi) = app.speeds.expect("zoomed");
    assert!(((zhi / zlo).log10() - (hi / lo).log10() / 2.0).abs() < 1e-9);
    assert_eq!(
        app.pending.as_ref().and_then(|r| r.request.speeds),
        Some((zlo, zhi))
    );
    settle(&mut app);
    let d = app.data.as_ref().expect("data");
    assert!((d.g[0] / zlo - 1.0).abs() < 1e-9 && (d.g[d.g.len() - 1] / zhi - 1.0).abs() < 1e-9);
    assert!(
        (d.g[app.cursor] / g).log10().abs() < 0.05,
        "the cursor stays on its speed"
    );
    // Pan right by a quarter.
    update(&mut app, ch('.'));
    let (plo, phi) = app.speeds.expect("panned");
    let q = (zhi / zlo).log10() / 4.0;
    assert!(((plo / zlo).log10() - q).abs() < 1e-9 && ((phi / zhi).log10() - q).abs() < 1e-9);
    settle(&mut app);
    // The wheel on the axis zooms; elsewhere it moves the cursor.
    let axis = app.drawn.get().chart_axis.expect("axis");
    let _ = screen(&app, 100, 30);
    let before = app.speeds;
    update(
        &mut app,
        wheel(true, axis.x + axis.width / 2, axis.label_row),
    );
    assert_ne!(app.speeds, before);
    // 0: automatic again.
    update(&mut app, ch('0'));
    assert_eq!(app.speeds, None);
    settle(&mut app);
    assert_eq!(
        super::compute::auto_speeds(app.data.as_deref().expect("data")),
        (lo, hi)
    );
}

/// Issue 12, item 20: a pinned curve stays as the scene changes, drawn dashed with a legend entry;
/// the family's legend says what it is.
#[test]
fn pinned_curve_and_family_meaning_issue_12_item_20() {
    let mut app = app_on(Scene::default());
    let s = text(&screen(&app, 120, 40));
    assert!(s.contains("A varied around this scene"), "{s}");
    update(&mut app, ch('P'));
    let pinned = app.pinned.clone().expect("pinned");
    select(&mut app, "bulk.damping.time");
    update(&mut app, ch('l'));
    update(&mut app, ch('l'));
    settle(&mut app);
    assert_eq!(app.pinned.as_ref(), Some(&pinned), "the pin survives edits");
    let s = text(&screen(&app, 120, 40));
    assert!(s.contains("pinned: A 100 µs"), "{s}");
    // Dashed: the pinned colour appears in several separate runs on the plot.
    let t = screen(&app, 120, 40);
    let axis = app.drawn.get().chart_axis.expect("axis");
    let buf = t.backend().buffer();
    let white = (0..axis.axis_row)
        .flat_map(|y| (axis.x..axis.x + axis.width).map(move |x| (x, y)))
        .filter(|p| {
            buf[*p].fg == super::view::plot::Colors::Rgb.color(rime_core::explorer::palette::PINNED)
                && buf[*p].symbol() != " "
        })
        .count();
    assert!(white > 10, "pinned curve drawn ({white} cells)");
    update(&mut app, ch('P'));
    assert!(app.pinned.is_none());
}

/// Exports the frame with `x` into a fresh folder and returns the ε_N chart's SVG.
fn exported_svg(app: &mut App, tag: &str) -> String {
    let dir = std::env::temp_dir().join(format!("rime-tui-test-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("tmp");
    app.out_dir = dir.clone();
    update(app, ch('x'));
    let export = std::fs::read_dir(&dir)
        .expect("read")
        .filter_map(|e| e.ok())
        .find(|e| e.file_name().to_string_lossy().starts_with("rime-export-"))
        .expect("export folder")
        .path();
    let svg = std::fs::read_to_string(export.join("eps_n.svg")).expect("figure");
    let _ = std::fs::remove_dir_all(&dir);
    svg
}

/// Runs of one foreground colour on row `y` from `x0` to `x1` (spaces end a run only where two
/// follow each other), with their colour.
fn colour_runs(
    buf: &ratatui::buffer::Buffer,
    y: u16,
    x0: u16,
    x1: u16,
) -> Vec<(String, ratatui::style::Color)> {
    let mut out: Vec<(String, ratatui::style::Color)> = Vec::new();
    for x in x0..x1 {
        let c = &buf[(x, y)];
        let sym = c.symbol().replace('\u{a0}', " ");
        match out.last_mut() {
            Some((text, fg)) if *fg == c.fg || sym == " " => text.push_str(&sym),
            _ => out.push((sym, c.fg)),
        }
    }
    out.into_iter()
        .flat_map(|(t, fg)| {
            t.split("  ")
                .map(|p| p.trim().to_string())
                .filter(|p| !p.is_empty())
                .map(|p| (p, fg))
                .collect::<Vec<_>>()
        })
        .collect()
}

/// Issue 21: the screen is the figure `x` exports. The ε_N chart at 120×40 against the core's
/// figure for the same view and its SVG: every legend entry on screen is in the SVG (or is the
/// core's short label of something the SVG draws), every colour on the plot is a role the SVG
/// draws in, every axis label on screen is one of the SVG's, and every series of the SVG is on
/// screen (its colour on the plot and its label in the legend).
#[test]
fn the_screen_draws_the_exported_figure_issue_21() {
    use rime_core::explorer::figures;
    use rime_core::explorer::palette;
    let mut app = app_on(Preset::IceFrost.scene());
    let svg = exported_svg(&mut app, "figure");
    let t = screen(&app, 120, 40);
    let buf = t.backend().buffer();
    let data = app.data.as_ref().expect("data");
    let view = figures::View {
        y_log: app.y_log,
        experiments: app.experiments,
        pinned: app.pinned.clone(),
    };
    let fig = figures::eps_figure(&data.frame, &view, env!("CARGO_PKG_VERSION"));
    let hex = |c: palette::Rgb| format!("#{:02X}{:02X}{:02X}", c.r, c.g, c.b);
    let rgb_of = |c: ratatui::style::Color| match c {
        ratatui::style::Color::Rgb(r, g, b) => Some(palette::Rgb { r, g, b }),
        _ => None,
    };
    // The SVG's text, entities decoded.
    let decoded = svg
        .replace("&amp;", "&")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&apos;", "'")
        .replace("&quot;", "\"");
    // The SVG's legend wraps long labels at word boundaries (one <text> a line): its texts joined
    // with spaces hold each label whole.
    let joined: Vec<&str> = decoded
        .split("<text")
        .skip(1)
        .filter_map(|t| {
            t.split_once('>')
                .and_then(|(_, rest)| rest.split_once("</text>"))
        })
        .map(|(inner, _)| inner.trim())
        .collect();
    let svg_text = format!("{decoded}\n{}", joined.join(" "));
    let shorts: Vec<&str> = fig
        .series
        .iter()
        .map(|s| s.short.as_str())
        .chain(fig.bands.iter().map(|b| b.short.as_str()))
        .chain(fig.markers.iter().map(|m| m.short.as_str()))
        .collect();
    let axis = app.drawn.get().chart_axis.expect("chart drawn");
    let chart = super::layout::layout(120, 40).expect("layout").chart;
    // The plot's first row: the y axis line's top.
    let plot_top = (chart.y..axis.axis_row)
        .find(|&y| matches!(buf[(axis.x - 1, y)].symbol(), "│" | "┤"))
        .expect("y axis");

    // Legend rows: above the plot.
    let mut legend_colours = Vec::new();
    let mut legend_text = String::new();
    for y in chart.y + 1..plot_top {
        for (run, fg) in colour_runs(buf, y, chart.x, chart.right()) {
            let label = run
                .trim_start_matches(['━', '╍', '┈', '┊', '▭', '×', ' '])
                .to_string();
            legend_text.push_str(&label);
            legend_text.push('\n');
            if label.is_empty() || label.starts_with('+') {
                continue;
            }
            let in_svg = svg_text.contains(&label);
            // A group's later members show their value only (`1 kPa s`): part of a short label.
            let short = shorts.iter().any(|s| s.contains(&label));
            assert!(in_svg || short, "legend entry {label:?} is not in the SVG");
            let c = rgb_of(fg).expect("a palette colour");
            assert!(
                svg.contains(&hex(c)),
                "legend colour {} not drawn in the SVG",
                hex(c)
            );
            legend_colours.push(c);
        }
    }
    // Every colour on the plot is a role the SVG draws (the cursor is the terminal's own white).
    let mut plot_colours = std::collections::BTreeSet::new();
    for y in plot_top..axis.axis_row {
        for x in axis.x..axis.x + axis.width {
            let c = &buf[(x, y)];
            if c.symbol() != " "
                && let Some(rgb) = rgb_of(c.fg)
            {
                plot_colours.insert(hex(rgb));
            }
        }
    }
    for c in &plot_colours {
        assert!(svg.contains(c.as_str()), "plot colour {c} not in the SVG");
    }
    // Axis labels: y labels left of their ticks, x labels under the axis, the x title.
    let row_text = |y: u16, x0: u16, x1: u16| -> String {
        (x0..x1).map(|x| buf[(x, y)].symbol().to_string()).collect()
    };
    let mut axis_labels: Vec<String> = Vec::new();
    for y in plot_top..axis.axis_row {
        if buf[(axis.x - 1, y)].symbol() == "┤" {
            axis_labels.push(row_text(y, chart.x, axis.x - 1).trim().to_string());
        }
    }
    assert!(axis_labels.len() >= 2, "y labels: {axis_labels:?}");
    for y in [axis.label_row, axis.label_row + 1] {
        axis_labels.extend(
            row_text(y, chart.x, chart.right())
                .split("  ")
                .map(|s| s.trim().to_string())
                .filter(|s| !s.is_empty()),
        );
    }
    assert!(
        axis_labels.iter().any(|l| l == &fig.x.label),
        "the x axis' title {:?} is on screen: {axis_labels:?}",
        fig.x.label
    );
    for l in &axis_labels {
        assert!(
            svg_text.contains(&format!(">{l}<")) || svg_text.contains(l.as_str()),
            "axis label {l:?} not in the SVG"
        );
    }
    // Every series of the SVG is on screen: its name in the SVG, its colour on the plot and in
    // the legend, its label (or its group's value) in the legend.
    for (k, s) in fig.series.iter().enumerate() {
        assert!(svg_text.contains(&s.name), "{} not in the SVG", s.name);
        // A family member that is this scene lies under this scene's curve (drawn later, on
        // top), on screen as in the SVG: then the curve on top is what shows.
        let on_top = fig.series[k + 1..]
            .iter()
            .rfind(|t| t.points == s.points)
            .unwrap_or(s);
        let c = hex(palette::SERIES[on_top.color]);
        assert!(
            plot_colours.contains(&c),
            "{} ({c}) not drawn on screen",
            s.name
        );
        let value = s
            .short
            .split_once(" = ")
            .map_or(s.short.as_str(), |(_, v)| v);
        assert!(
            legend_text.contains(value),
            "{} not in the legend:\n{legend_text}",
            s.short
        );
    }
    for b in &fig.bands {
        assert!(svg_text.contains(&b.label) && legend_text.contains(&b.short));
    }
}

/// Issue 21: in compare mode a compared law took a family member's colour, on screen and in the
/// PNG. Now no two series share both colour and stroke in the figure (which the PNG draws), on
/// screen (legend swatches and colours), and without colour the swatches (with their tags) differ.
#[test]
fn compare_mode_never_repeats_a_colour_and_a_stroke_issue_21() {
    use super::view::plot::{self, Colors};
    use rime_core::explorer::figures;
    let mut app = app_on(Preset::IceFrost.scene());
    update(&mut app, ch('P'));
    for _ in 0..2 {
        update(&mut app, ch('c'));
        settle(&mut app);
        let data = app.data.as_ref().expect("data");
        assert!(!data.overlays.is_empty(), "a comparison is shown");
        let view = figures::View {
            y_log: app.y_log,
            experiments: app.experiments,
            pinned: app.pinned.clone(),
        };
        let fig = figures::eps_figure(&data.frame, &view, env!("CARGO_PKG_VERSION"));
        let mut seen = std::collections::HashSet::new();
        for s in &fig.series {
            let key = (rime_core::explorer::palette::SERIES[s.color], s.stroke);
            assert!(seen.insert(key), "{} repeats {key:?}", s.name);
        }
        // The screen's legend: one swatch and colour per series.
        let mut seen = std::collections::HashSet::new();
        for e in plot::legend(&fig, &plot::tags(&fig, Colors::Rgb)) {
            let mut members = vec![(e.text.clone(), e.rgb)];
            members.extend(e.more.clone());
            // Markers (┊) are vertical lines named by their speed, not series.
            for (text, rgb) in members.into_iter().filter(|_| e.swatch != "┊") {
                assert!(seen.insert((e.swatch.clone(), rgb)), "{text} repeats");
            }
        }
        // Without colour: the swatch and tag alone tell every series apart.
        let tags = plot::tags(&fig, Colors::None);
        let mut seen = std::collections::HashSet::new();
        for (s, tag) in fig.series.iter().zip(&tags) {
            assert!(seen.insert((s.stroke, *tag)), "{} needs a tag", s.name);
        }
        // And the screen draws each comparison in its dotted stroke: its colour on the plot.
        let t = screen(&app, 120, 40);
        let s = text(&t);
        for o in &data.overlays {
            let key = o.overlay.key();
            let name = key.split_once(':').map_or(key.as_str(), |(_, n)| n);
            assert!(s.contains(name), "{name} not in the legend\n{s}");
        }
    }
}

/// Found trying the merged explorer at 80×24: Esc with the `v` or `i` panel open quit the program
/// (it closes the tidal panel first); it closes either panel first, and quits only after that.
#[test]
fn esc_closes_the_thresholds_and_collision_panels_before_quitting() {
    for panel in ['v', 'i'] {
        let mut app = app_on(Scene::default());
        update(&mut app, key(KeyCode::Char(panel)));
        assert!(
            app.stick.is_some() || app.inside.is_some(),
            "{panel} opened nothing"
        );
        update(&mut app, key(KeyCode::Esc));
        assert!(
            app.stick.is_none() && app.inside.is_none(),
            "{panel}: Esc left it open"
        );
        assert!(!app.quit, "{panel}: Esc quit with the panel open");
        update(&mut app, key(KeyCode::Esc));
        assert!(app.quit, "{panel}: a second Esc (no unsaved edits) quits");
    }
}

fn ctrl_c() -> Event {
    Event::Key(KeyEvent::new(KeyCode::Char('c'), KeyModifiers::CONTROL))
}

/// Issue 22 item 8: Ctrl-C acts as q. With unsaved edits it asks (n stays, the edit is kept); in
/// the `e` prompt it cancels the prompt first, then asks.
#[test]
fn ctrl_c_asks_before_dropping_unsaved_edits_even_in_the_prompt_issue_22() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('l')); // an edit: R₁ × 1.25
    assert!(app.unsaved());
    update(&mut app, ctrl_c());
    assert!(
        !app.quit && app.confirm == Some(Confirm::Quit),
        "Ctrl-C quit with unsaved edits"
    );
    update(&mut app, ch('n'));
    assert!(
        !app.quit && app.unsaved(),
        "n keeps the session and the edit"
    );
    update(&mut app, ch('e'));
    assert!(app.input.is_some(), "e opens the prompt");
    update(&mut app, ctrl_c());
    assert!(app.input.is_none(), "Ctrl-C cancels the prompt");
    assert!(!app.quit && app.confirm == Some(Confirm::Quit), "then asks");
    update(&mut app, ch('y'));
    assert!(app.quit);
    // Without unsaved edits Ctrl-C quits at once, as q does.
    let mut clean = app_on(Scene::default());
    update(&mut clean, ctrl_c());
    assert!(clean.quit);
}

/// Issue 22 item 8: `w` asks before overwriting a scene file that changed since this session
/// wrote it (it overwrote silently once the session had written the file once).
#[test]
fn w_asks_again_when_the_file_changed_since_it_was_written_issue_22() {
    let dir = std::env::temp_dir().join(format!("rime-tui-w-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp");
    let file = dir.join("rime-scene.json");
    let _ = std::fs::remove_file(&file);
    let mut app = app_on(Scene::default());
    app.out_dir = dir.clone();
    update(&mut app, ch('w'));
    assert!(
        app.confirm.is_none() && file.exists(),
        "a new file is written at once"
    );
    update(&mut app, ch('l'));
    update(&mut app, ch('w'));
    assert!(
        app.confirm.is_none(),
        "our own file is overwritten without asking"
    );
    std::fs::write(&file, "{\"someone\": \"else\"}\n").expect("write");
    update(&mut app, ch('l'));
    update(&mut app, ch('w'));
    assert_eq!(
        app.confirm,
        Some(Confirm::Overwrite),
        "a changed file is asked about"
    );
    update(&mut app, ch('n'));
    assert_eq!(
        std::fs::read_to_string(&file).expect("read"),
        "{\"someone\": \"else\"}\n",
        "n keeps the other file"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 22 item 8: `~` in a typed path is the home directory, as in a shell.
#[test]
fn a_leading_tilde_is_the_home_directory_issue_22() {
    let home = std::env::var_os("HOME").map(std::path::PathBuf::from);
    if let Some(home) = home.filter(|h| !h.as_os_str().is_empty()) {
        assert_eq!(super::line_input::expand_home("~"), home);
        assert_eq!(
            super::line_input::expand_home("~/a/b.json"),
            home.join("a/b.json")
        );
    }
    // Only a leading `~` or `~/` is the home directory.
    assert_eq!(
        super::line_input::expand_home("a/~/b.json"),
        std::path::PathBuf::from("a/~/b.json")
    );
    assert_eq!(
        super::line_input::expand_home("~user/b.json"),
        std::path::PathBuf::from("~user/b.json")
    );
}

/// Issue 22 item 8: a status or message line longer than the terminal says it is cut (`… ? lists
/// all` on the status line, `…` on messages) instead of stopping mid-word at the last column.
#[test]
fn a_cut_status_line_says_so_issue_22() {
    let line = super::view::lines::fit(
        vec![ratatui::text::Span::raw("x".repeat(100))],
        80,
        super::view::lines::STATUS_CUT,
    );
    let shown: String = line.spans.iter().map(|s| s.content.as_ref()).collect();
    assert_eq!(shown.chars().count(), 80);
    assert!(shown.ends_with("… ? lists all"));
}

/// Issue 26: the frame computed on several threads is the core's sequential frame, bit for bit
/// (compared through `Debug`, which prints every f64 exactly and NaN as NaN), on several scenes,
/// levels, comparisons and forced failures, whatever the number of threads.
#[test]
fn parallel_frames_equal_the_sequential_reference_issue_26() {
    use rime_core::explorer::frame::{self, Request};
    let frost = Preset::IceFrost.scene();
    let literal = frost.with_layer_reading(rime_core::LayerReading::Literal);
    let cases = [
        (Preset::Ice.scene(), Accuracy::Balanced, 2, vec![]),
        (frost, Accuracy::Precise, 0, vec!["curve", "map"]),
        (literal, Accuracy::Fast, 0, vec![]),
        (
            Preset::IceSticky.scene(),
            Accuracy::Precise,
            1,
            vec!["family"],
        ),
        (Preset::Ice.scene(), Accuracy::Precise, 2, vec![]),
    ];
    for (k, (scene, accuracy, set, fail)) in cases.into_iter().enumerate() {
        let mut req = Request::new(scene, accuracy);
        req.overlays = frame::comparison(set, &scene);
        req.fail = fail.iter().map(|s| s.to_string()).collect();
        if accuracy == Accuracy::Balanced {
            req.points = 97; // live integration: fewer points keep the test short
        }
        let reference = format!("{:?}", frame::compute(&req, &|| false).expect("computed"));
        for threads in [2, 3, 8] {
            let parallel =
                super::compute::frame(&req, &|| false, threads, &NoMemo).expect("computed");
            assert!(
                format!("{parallel:?}") == reference,
                "case {k} at {accuracy:?} on {threads} threads differs"
            );
        }
    }
}

/// Issue 26: the parallel frame stays cancellable: cancelled before it starts or part-way through
/// (after some units ran), it returns nothing.
#[test]
fn parallel_frames_are_cancellable_issue_26() {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let req = rime_core::explorer::frame::Request::new(Preset::IceFrost.scene(), Accuracy::Precise);
    assert!(super::compute::frame(&req, &|| true, 2, &NoMemo).is_none());
    let asked = AtomicUsize::new(0);
    let later = || asked.fetch_add(1, Ordering::Relaxed) > 20;
    assert!(super::compute::frame(&req, &later, 2, &NoMemo).is_none());
    assert!(
        asked.load(Ordering::Relaxed) > 20,
        "it was asked part-way through"
    );
}

/// The frames the worker sends for the pending request (a preview first when the level is not
/// `fast`), computed as the worker computes them.
fn worker_frames(app: &mut App) -> Vec<super::compute::Computed> {
    let job = app.take_request().expect("a request");
    let mut frames = Vec::new();
    // A fresh rule: the kind is new, so a level other than `fast` gets its preview.
    let mut rule = super::compute::PreviewRule::default();
    super::compute::progressive(&job, &|| false, 2, &NoMemo, &mut rule, &mut |c| {
        frames.push(c);
        true
    });
    frames
}

/// Issue 26: after an edit at `precise` the worker sends a `fast` preview, marked as one, then the
/// refined frame; the status line says "refining to precise…" over the preview; drawn in sequence
/// on one terminal, the preview already shows the curves and the swap to the refined frame
/// changes nothing but the status line (no blank or "computing…" frame between).
#[test]
fn preview_then_refined_frame_without_flicker_issue_26() {
    let mut app = App::new(Preset::IceFrost.scene(), Accuracy::Precise);
    app.fixed_elapsed = Some(Duration::from_millis(3));
    for c in worker_frames(&mut app) {
        update(&mut app, Event::Computed(Box::new(c)));
    }
    let mut t = Terminal::new(TestBackend::new(120, 40)).expect("terminal");
    t.draw(|f| render(&app, f)).expect("draw");
    let before = app.scene;
    update(&mut app, key(KeyCode::Right)); // the panel's selected parameter, one step up
    assert_ne!(app.scene, before, "an edit");
    let frames = worker_frames(&mut app);
    let kinds: Vec<(bool, Accuracy)> = frames
        .iter()
        .map(|c| (c.preview, c.request.accuracy))
        .collect();
    assert_eq!(
        kinds,
        [(true, Accuracy::Fast), (false, Accuracy::Precise)],
        "preview first, then the requested level"
    );
    let mut screens = Vec::new();
    for c in frames {
        update(&mut app, Event::Computed(Box::new(c)));
        t.draw(|f| render(&app, f)).expect("draw");
        screens.push(text(&t));
    }
    let (preview, refined) = (&screens[0], &screens[1]);
    assert!(preview.contains("refining to precise…"), "{preview}");
    assert!(
        !refined.contains("refining") && !refined.contains("computing…"),
        "{refined}"
    );
    assert!(
        !preview.contains("computing…"),
        "the preview is drawn in full: {preview}"
    );
    let rows = |s: &str| s.lines().map(str::to_owned).collect::<Vec<_>>();
    let (p, r) = (rows(preview), rows(refined));
    let changed: Vec<usize> = (0..p.len()).filter(|&i| p[i] != r[i]).collect();
    assert!(
        changed.len() == 1 && p[changed[0]].contains("refining to precise"),
        "only the status line changes: rows {changed:?}\n{preview}\n{refined}"
    );
}

/// Issue 26: `x` and `P` never take a preview: with only the preview on screen `x` says so and
/// writes nothing; once the refined frame is in, it exports.
#[test]
fn a_preview_is_never_exported_issue_26() {
    let dir = std::env::temp_dir().join(format!("rime-tui-test-preview-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("tmp");
    let mut app = App::new(Preset::IceSticky.scene(), Accuracy::Balanced);
    app.out_dir = dir.clone();
    let mut frames = worker_frames(&mut app).into_iter();
    let preview = frames.next().expect("preview");
    assert!(preview.preview);
    update(&mut app, Event::Computed(Box::new(preview)));
    assert!(app.previewing() && app.computing());
    update(&mut app, ch('x'));
    let (msg, _) = app.message.clone().expect("message");
    assert!(
        msg.contains("preview") && msg.contains("integrated"),
        "{msg}"
    );
    assert_eq!(
        std::fs::read_dir(&dir).expect("read").count(),
        0,
        "nothing exported"
    );
    update(&mut app, ch('P'));
    assert!(app.pinned.is_none(), "a preview is not pinned");
    update(
        &mut app,
        Event::Computed(Box::new(frames.next().expect("refined"))),
    );
    assert!(!app.previewing() && !app.computing());
    update(&mut app, ch('x'));
    let (msg, _) = app.message.clone().expect("message");
    assert!(msg.contains("exported"), "{msg}");
    assert_eq!(std::fs::read_dir(&dir).expect("read").count(), 1);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 26: a preview that arrives after its refined frame (it cannot, but a stale one must not
/// win) leaves the refined frame on screen.
#[test]
fn a_late_preview_never_replaces_the_refined_frame_issue_26() {
    let mut app = App::new(Preset::Ice.scene(), Accuracy::Precise);
    let mut frames = worker_frames(&mut app);
    let refined = frames.pop().expect("refined");
    let preview = frames.pop().expect("preview");
    update(&mut app, Event::Computed(Box::new(refined)));
    update(&mut app, Event::Computed(Box::new(preview)));
    assert!(app.data.as_ref().is_some_and(|d| !d.preview));
}

/// Issue 26: quitting cancels the worker's refinement: once the preview is in and the event loop
/// tells the worker it quits, the refined frame (a long live integration here) is never sent and
/// the worker ends.
#[test]
fn quitting_cancels_the_refinement_issue_26() {
    use std::sync::Arc;
    use std::sync::atomic::{AtomicU64, Ordering};
    use std::sync::mpsc;
    let frost = Preset::IceFrost.scene();
    let literal = frost.with_layer_reading(rime_core::LayerReading::Literal);
    let mut request = rime_core::explorer::frame::Request::new(literal, Accuracy::Balanced);
    request.points = 4000; // minutes of live integration if it were not cancelled
    let (job_tx, job_rx) = mpsc::channel();
    let (event_tx, event_rx) = mpsc::channel();
    let latest = Arc::new(AtomicU64::new(1));
    let worker = {
        let latest = Arc::clone(&latest);
        std::thread::spawn(move || super::worker(job_rx, event_tx, latest))
    };
    job_tx
        .send(super::compute::Job {
            generation: 1,
            request,
        })
        .expect("send");
    // Hang guard: the fast preview of 4000 points takes well under a second even on a loaded
    // machine.
    let first = event_rx
        .recv_timeout(Duration::from_secs(60))
        .expect("preview");
    assert!(matches!(first, Event::Computed(c) if c.preview));
    latest.store(super::QUIT, Ordering::Relaxed);
    drop(job_tx);
    worker.join().expect("the worker ends");
    assert!(
        event_rx.try_recv().is_err(),
        "no refined frame after quitting"
    );
}

/// Issue 36: the terminal lays out the core's tidal card: every compared row shows the card's own
/// mark (the page receives the same card, wasm's `tidal_json`), so r_max (Eq. (A.5): 37.72 m
/// against the printed 37.6 m) reads ⚠ on both, where the terminal said "≈ +0.3 %" and the page ⚠.
#[test]
fn issue_36_the_tidal_marks_are_the_cores() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('t'));
    let s = text(&screen(&app, 100, 30));
    let card = super::tidal::view(&app.scene, app.tidal_factor)
        .card
        .expect("the paper's example evaluates");
    let mut compared = 0;
    for row in &card.rows {
        let Some(c) = &row.comparison else { continue };
        let name = format!("{} {}", row.short.trim(), row.equation);
        let line = s
            .lines()
            .find(|l| l.contains(name.trim()))
            .unwrap_or_else(|| panic!("no row {name}\n{s}"));
        assert!(line.contains(&c.mark), "{name}: {} not in {line}", c.mark);
        compared += 1;
    }
    assert_eq!(
        compared, 6,
        "every printed number is compared on the paper's example"
    );
    assert!(s.contains("37.6 m     ⚠ +0.32 %"), "{s}");
    assert!(s.contains(&card.verdict));
}

/// Exports the frame with `x` into a fresh folder and returns the folder's files by name.
fn exported_files(app: &mut App, tag: &str) -> std::collections::BTreeMap<String, String> {
    let dir = std::env::temp_dir().join(format!("rime-tui-test-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("tmp");
    app.out_dir = dir.clone();
    update(app, ch('x'));
    let export = std::fs::read_dir(&dir)
        .expect("read")
        .filter_map(|e| e.ok())
        .find(|e| e.file_name().to_string_lossy().starts_with("rime-export-"))
        .unwrap_or_else(|| panic!("no export folder: {:?}", app.message))
        .path();
    let files = std::fs::read_dir(&export)
        .expect("read")
        .filter_map(|e| e.ok())
        .filter(|e| !e.file_name().to_string_lossy().ends_with(".png"))
        .map(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            (name, std::fs::read_to_string(e.path()).expect("text"))
        })
        .collect();
    let _ = std::fs::remove_dir_all(&dir);
    files
}

/// Issue 37 item 7: the export is the screen. With the ring card open, `x` draws its ε_cr line
/// and the √π c marker; once the card is closed (`r` again) neither is on screen nor in the
/// exported figure.
#[test]
fn issue_37_a_closed_ring_card_is_not_exported() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('r'));
    let card = match app.ring_card.clone() {
        Some(Ok(card)) => card,
        other => panic!("no ring card: {other:?}"),
    };
    let open = exported_files(&mut app, "ring-open");
    let svg = &open["eps_n.svg"];
    assert!(
        svg.contains("of the ring at τ"),
        "ε_cr line exported while open"
    );
    assert!(
        svg.contains("mean impact speed"),
        "√π c marker in the legend while open"
    );
    update(&mut app, ch('r'));
    assert!(!app.ring);
    let on_screen = text(&screen(&app, 160, 45));
    assert!(!on_screen.contains(&card.eps_cr_line.short), "{on_screen}");
    let closed = exported_files(&mut app, "ring-closed");
    let svg = &closed["eps_n.svg"];
    for ring_text in ["of the ring", "ε_cr", "mean impact speed", "√π"] {
        assert!(
            !svg.contains(ring_text),
            "{ring_text} exported after r closed the card"
        );
    }
}

/// Issue 37 item 7: `eps_family.csv` has every curve the exported figure draws, the pinned one
/// included; pinned, then zoomed (other speeds), its own speeds are rows of their own and every
/// one of its values is in the table.
#[test]
fn issue_37_the_family_table_has_the_pinned_curve() {
    let mut app = app_on(Preset::IceFrost.scene());
    // Without the experiments' law (its speeds are rows of their own since issue 37 F2.5).
    update(&mut app, ch('b'));
    assert!(!app.experiments);
    update(&mut app, ch('P'));
    let pinned = app.pinned.clone().expect("pinned");
    let rows = |files: &std::collections::BTreeMap<String, String>| -> Vec<Vec<String>> {
        files["eps_family.csv"]
            .lines()
            .filter(|l| !l.starts_with('#'))
            .map(|l| l.split(',').map(String::from).collect())
            .collect()
    };
    let same = rows(&exported_files(&mut app, "pinned-same"));
    let last = same[0].len() - 1;
    assert_eq!(same[0][last], format!("eps_n [pinned: {}]", pinned.label));
    assert_eq!(
        same.len() - 1,
        pinned.g.len(),
        "one row per speed when the speeds agree"
    );
    for (row, (g, e)) in same[1..].iter().zip(pinned.g.iter().zip(&pinned.eps)) {
        assert_eq!(row[0].parse::<f64>().expect("g"), *g);
        assert_eq!(row[last].parse::<f64>().expect("eps"), *e);
        // The pinned curve is this scene's: the same numbers in the scene's column.
        assert_eq!(row[1], row[last]);
    }
    // Zoomed in: the frame's speeds change, the pinned curve keeps its own.
    update(&mut app, ch('+'));
    settle(&mut app);
    assert_ne!(app.data.as_ref().expect("frame").g, pinned.g);
    let zoomed = rows(&exported_files(&mut app, "pinned-zoomed"));
    let g_col: Vec<f64> = zoomed[1..]
        .iter()
        .map(|r| r[0].parse().expect("g"))
        .collect();
    assert!(
        g_col.windows(2).all(|w| w[0] < w[1]),
        "rows in order of speed"
    );
    let pinned_cells: Vec<(f64, f64)> = zoomed[1..]
        .iter()
        .filter(|r| !r[last].is_empty())
        .map(|r| (r[0].parse().expect("g"), r[last].parse().expect("eps")))
        .collect();
    let expected: Vec<(f64, f64)> = pinned
        .g
        .iter()
        .copied()
        .zip(pinned.eps.iter().copied())
        .collect();
    assert_eq!(pinned_cells, expected);
    let frame_rows = zoomed[1..].iter().filter(|r| !r[1].is_empty()).count();
    assert_eq!(frame_rows, app.data.as_ref().expect("frame").g.len());
}

/// Issue 37 item 9: the chart's cursor readout at 80 columns drops fields whole: with A = 3 s,
/// δ is 2.25e4 and the readout showed `δ 2.`; now δ is either whole or absent.
#[test]
fn issue_37_the_cursor_readout_is_never_cut_mid_number() {
    let mut scene = Scene::default();
    scene.set_number("bulk.damping.time", 3.0).expect("set");
    let app = app_on(scene);
    let data = app.data.as_ref().expect("frame");
    let g = data.g[app.cursor];
    let delta = super::format::num3(data.contact.expect("contact").delta(g));
    assert!(delta.len() > 3, "a long δ: {delta}");
    for (w, h) in [(80, 24), (100, 30), (160, 45)] {
        let s = text(&screen(&app, w, h));
        let line = s
            .lines()
            .find(|l| l.contains('▸') && l.contains("ε_N"))
            .unwrap_or_else(|| panic!("no readout at {w}×{h}\n{s}"));
        if let Some((_, after)) = line.split_once("δ ") {
            assert!(after.starts_with(&delta), "δ cut at {w}×{h}: {line}");
        }
        if w >= 160 {
            assert!(line.contains(&format!("δ {delta}")), "{line}");
        }
    }
}

/// Issue 37 item 9: at 80×24 the ring card does not fit; its last row says how many lines are
/// left out instead of ending mid-card with no hint.
#[test]
fn issue_37_a_cut_ring_card_says_so() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('r'));
    let card = match app.ring_card.clone() {
        Some(Ok(card)) => card,
        other => panic!("no ring card: {other:?}"),
    };
    let small = text(&screen(&app, 80, 24));
    let sentence_start: String = card.sentence.chars().take(20).collect();
    assert!(
        small.contains("more lines") || small.contains(&sentence_start),
        "the card is cut without a hint\n{small}"
    );
    assert!(
        small.contains("more lines"),
        "80×24 is too small for the card\n{small}"
    );
    let large = text(&screen(&app, 160, 45));
    assert!(!large.contains("more lines"), "{large}");
}

/// Issue 37 item 9: the export message puts the folder first, so an 80-column status row shows
/// it whole.
#[test]
fn issue_37_the_export_message_shows_the_folder_at_80_columns() {
    let dir = std::env::temp_dir().join(format!("rime-tui-test-msg-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("tmp");
    let mut app = app_on(Scene::default());
    app.out_dir = dir.clone();
    update(&mut app, ch('x'));
    let (msg, _) = app.message.clone().expect("message");
    let folder = msg
        .split_whitespace()
        .find(|w| w.contains("rime-export-"))
        .expect("folder in the message")
        .to_string();
    let s = text(&screen(&app, 80, 24));
    assert!(s.contains(&folder), "{folder} not whole on screen\n{s}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 37 item 9: the `i` panel's phase line keeps whole phases (each `name time`) and counts
/// the ones left out, at 80 and 120 columns.
#[test]
fn issue_37_the_phase_line_keeps_whole_phases() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('i'));
    for (w, h) in [(80, 24), (120, 40), (200, 60)] {
        let s = text(&screen(&app, w, h));
        let Some(line) = s.lines().find(|l| l.contains("ξ_max")) else {
            continue;
        };
        let (_, after) = line.split_once("ξ_max").expect("ξ_max");
        let (_, phases) = after.split_once('│').expect("phases after │");
        // The panel's border closes the row.
        let phases = phases.trim().trim_end_matches(['│', '┃', '║']).trim();
        for part in phases.split(" · ") {
            let part = part.trim();
            let more =
                part.starts_with('+') && (part.ends_with("more") || part.ends_with("phases"));
            assert!(
                part.is_empty() || more || part.ends_with('s'),
                "a phase cut at {w}×{h}: {part:?} in {line}"
            );
        }
        if w >= 200 {
            assert!(!phases.contains("more"), "{line}");
        }
    }
}

/// Issue 37 item 10: `f` fits A to the measured law the chart shows; with none shown (no
/// comparison and the experiments off, or the other models) it says so and keeps the scene.
#[test]
fn issue_37_f_fits_only_to_a_law_on_the_chart() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('b'));
    assert!(!app.experiments);
    let before = app.scene;
    update(&mut app, ch('f'));
    assert_eq!(app.scene, before, "fitted to a law not on the chart");
    assert!(app.undo.is_empty());
    let (msg, _) = app.message.clone().expect("message");
    assert!(msg.contains("no measured law on the chart"), "{msg}");
    // The other models: no measured law either.
    update(&mut app, ch('c'));
    update(&mut app, ch('c'));
    assert_eq!(app.overlay_set, 2);
    update(&mut app, ch('f'));
    assert_eq!(app.scene, before);
    // Measured ice: the fit runs (Bridges et al. 1984, the set's first law).
    update(&mut app, ch('c'));
    update(&mut app, ch('c'));
    assert_eq!(app.overlay_set, 1);
    update(&mut app, ch('f'));
    let (msg, _) = app.message.clone().expect("message");
    assert!(msg.contains("A fitted to bridges1984"), "{msg}");
    assert_ne!(app.scene, before);
    // With the experiments on and no comparison, the Bridges law is on the chart: f fits to it.
    let mut app = app_on(Scene::default());
    assert!(app.experiments && app.overlay_set == 0);
    update(&mut app, ch('f'));
    let (msg, _) = app.message.clone().expect("message");
    assert!(msg.contains("A fitted to bridges1984"), "{msg}");
}

/// Issue 37 item 10: a fit that lands on the scene's A (the same fit twice) is no undo step.
#[test]
fn issue_37_a_fit_that_changes_nothing_is_no_undo_step() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('f'));
    assert_eq!(app.undo.len(), 1);
    let fitted = app.scene;
    update(&mut app, ch('f'));
    assert_eq!(
        app.undo.len(),
        1,
        "a second, identical fit added an undo step"
    );
    assert_eq!(app.scene, fitted);
    let (msg, _) = app.message.clone().expect("message");
    assert!(msg.contains("unchanged"), "{msg}");
}

/// Issue 37 item 10: undo and redo say what they undid (`A 100 µs → 2 ms`).
#[test]
fn issue_37_undo_says_what_it_undid() {
    let mut app = app_on(Scene::default());
    select(&mut app, "bulk.damping.time");
    let before = super::format::qty3(number(&app, "bulk.damping.time"), "s");
    update(&mut app, key(KeyCode::Right));
    let after = super::format::qty3(number(&app, "bulk.damping.time"), "s");
    assert_ne!(before, after);
    update(&mut app, ch('u'));
    let (msg, _) = app.message.clone().expect("message");
    assert!(
        msg.contains(&format!("undone: A {after} → {before}")),
        "{msg}"
    );
    update(&mut app, ch('U'));
    let (msg, _) = app.message.clone().expect("message");
    assert!(
        msg.contains(&format!("redone: A {before} → {after}")),
        "{msg}"
    );
}

/// Issue 37 item 10: `q` inside the `?` overlay closes it (it quit the program).
#[test]
fn issue_37_q_closes_the_help() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('?'));
    assert!(app.help);
    update(&mut app, ch('q'));
    assert!(!app.help, "q left the help open");
    assert!(!app.quit && app.confirm.is_none(), "q in the help quit");
    update(&mut app, ch('?'));
    update(&mut app, key(KeyCode::Esc));
    assert!(!app.help && !app.quit && app.confirm.is_none());
    let s = text(&screen(&app, 80, 24));
    assert!(!s.contains("Glossary"), "{s}");
}

/// Issue 37 item 10: a second Esc no longer drops a pin, a zoom or a comparison silently: it
/// asks, names what would go, and `n` keeps it all; Esc closes the ring card first.
#[test]
fn issue_37_esc_asks_before_dropping_the_view() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('P'));
    update(&mut app, ch('+'));
    settle(&mut app);
    update(&mut app, ch('c'));
    settle(&mut app);
    update(&mut app, ch('r'));
    update(&mut app, key(KeyCode::Esc));
    assert!(!app.ring, "Esc closes the ring card first");
    assert!(!app.quit && app.confirm.is_none());
    update(&mut app, key(KeyCode::Esc));
    assert!(!app.quit, "Esc dropped the pin, zoom and comparison");
    assert_eq!(app.confirm, Some(Confirm::Leave));
    let s = text(&screen(&app, 120, 40));
    for lost in ["pinned curve", "zoom", "comparison"] {
        assert!(
            s.contains(lost),
            "{lost} not named
{s}"
        );
    }
    update(&mut app, ch('n'));
    assert!(!app.quit && app.pinned.is_some() && app.speeds.is_some() && app.overlay_set == 1);
    update(&mut app, key(KeyCode::Esc));
    update(&mut app, ch('y'));
    assert!(app.quit);
    // Nothing to lose: Esc quits at once, as before.
    let mut plain = app_on(Scene::default());
    update(&mut plain, key(KeyCode::Esc));
    assert!(plain.quit);
}

/// Issue 37 item 10: the page's preview rule in the terminal. A frame of a kind not seen yet, or
/// whose last frame took longer than `PREVIEW_SLOW`, gets a `fast` preview; one whose last frame
/// was quick does not (its first frame is its final one).
#[test]
fn issue_37_a_preview_only_when_the_last_frame_of_its_kind_was_dear() {
    use super::compute::{Job, PREVIEW_SLOW, PreviewRule, progressive};
    let mut rule = PreviewRule::default();
    let request = rime_core::explorer::frame::Request::new(Scene::default(), Accuracy::Precise);
    let kind = rule.kind(&request);
    assert!(rule.wants_preview(&kind), "a new kind");
    rule.record(kind.clone(), PREVIEW_SLOW / 8);
    assert!(!rule.wants_preview(&kind), "a quick kind");
    rule.record(kind.clone(), PREVIEW_SLOW * 3);
    assert!(rule.wants_preview(&kind), "a dear kind");
    // Another level, another scene shape: other kinds.
    let mut fast_rule = PreviewRule::default();
    let fast = rime_core::explorer::frame::Request::new(Scene::default(), Accuracy::Fast);
    assert_ne!(fast_rule.kind(&fast), kind);
    let frost =
        rime_core::explorer::frame::Request::new(Preset::IceFrost.scene(), Accuracy::Precise);
    assert_ne!(PreviewRule::default().kind(&frost), kind);
    // The worker: with the kind known to be quick, one frame (the requested level), no preview.
    let mut rule = PreviewRule::default();
    let job = Job {
        generation: 1,
        request: request.clone(),
    };
    let mut first = Vec::new();
    progressive(&job, &|| false, 2, &NoMemo, &mut rule, &mut |c| {
        first.push(c.preview);
        true
    });
    assert_eq!(first, [true, false], "a new kind: preview, then the frame");
    let kind = rule.kind(&request);
    rule.record(kind, PREVIEW_SLOW / 8);
    let mut second = Vec::new();
    progressive(&job, &|| false, 2, &NoMemo, &mut rule, &mut |c| {
        second.push((c.preview, c.request.accuracy));
        true
    });
    assert_eq!(second, [(false, Accuracy::Precise)]);
}

/// Issue 37 item 10: a measured range the scene lies within does not read "rms 0" (a perfect
/// fit); it says the scene is within it.
#[test]
fn issue_37_measured_ranges_do_not_show_rms_0() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('c'));
    settle(&mut app);
    let s = text(&screen(&app, 200, 60));
    for (k, _) in s.match_indices("rms 0") {
        assert!(s[k + 5..].starts_with('.'), "a bare rms 0\n{s}");
    }
    let fig = rime_core::explorer::figures::eps_figure(
        &app.data.as_ref().expect("frame").frame,
        &rime_core::explorer::figures::View::default(),
        "test",
    );
    let ranges: Vec<&str> = fig.bands.iter().map(|b| b.short.as_str()).collect();
    assert!(!ranges.is_empty(), "measured ranges on the chart");
    for r in ranges {
        assert!(!r.ends_with("rms 0"), "{r}");
    }
}

/// The hue angle of a terminal colour (24-bit), in degrees.
fn hue_of(c: ratatui::style::Color) -> Option<f64> {
    let ratatui::style::Color::Rgb(r, g, b) = c else {
        return None;
    };
    let (r, g, b) = (f64::from(r), f64::from(g), f64::from(b));
    let (max, min) = (r.max(g).max(b), r.min(g).min(b));
    let d = max - min;
    if d == 0.0 {
        return None;
    }
    let h = if max == r {
        60.0 * ((g - b) / d)
    } else if max == g {
        60.0 * ((b - r) / d + 2.0)
    } else {
        60.0 * ((r - g) / d + 4.0)
    };
    Some((h + 360.0) % 360.0)
}

/// Issue 37 item 8: with the other models compared, no model's colour on screen shares a hue
/// with a family member's (`muller_poschel2011` was #0072B2 beside the family's #3A7DC9): read
/// from the terminal's cells, at 80×24 and 200×60.
#[test]
fn issue_37_no_compared_model_shares_a_hue_with_the_family_on_screen() {
    let mut app = app_on(Scene::default());
    update(&mut app, ch('c'));
    update(&mut app, ch('c'));
    settle(&mut app);
    assert_eq!(app.overlay_set, 2, "other models");
    for (w, h) in [(200, 60), (120, 40)] {
        let t = screen(&app, w, h);
        let buf = t.backend().buffer();
        let rows: Vec<String> = text(&t).lines().map(String::from).collect();
        // The colour of the cells under `needle` on the first row that has it.
        let colours_of = |needle: &str, span: usize| -> Vec<ratatui::style::Color> {
            let Some((y, row)) = rows.iter().enumerate().find(|(_, r)| r.contains(needle)) else {
                return Vec::new();
            };
            let byte = row.find(needle).unwrap_or(0);
            let x0 = row[..byte].chars().count();
            (x0..x0 + span)
                .map(|x| buf[(x as u16, y as u16)].fg)
                .filter(|c| hue_of(*c).is_some())
                .collect()
        };
        let models: Vec<_> = ["brilliantov2007", "muller_poschel2011"]
            .iter()
            .flat_map(|m| colours_of(m, m.chars().count()))
            .collect();
        // The family entry: `A = 10 µs 30 µs …`, each value in its member's colour.
        let family = colours_of("A = ", 40);
        assert!(
            !models.is_empty() && !family.is_empty(),
            "{w}×{h}\n{}",
            rows.join("\n")
        );
        for m in &models {
            for f in &family {
                let (a, b) = (hue_of(*m).unwrap_or(0.0), hue_of(*f).unwrap_or(0.0));
                let gap = (a - b).abs().min(360.0 - (a - b).abs());
                assert!(
                    gap >= 20.0,
                    "{w}×{h}: model {m:?} vs family {f:?}: {gap:.0}°"
                );
            }
        }
    }
}

/// Issue 37 (review E11, E17): at 80 and 100 columns, without colour, the legend's count of left
/// out entries is whole (`+1 more`, `+1`), never `+1 m`; an entry cut at the edge ends in `…`.
#[test]
fn issue_37_the_legend_is_never_cut_mid_word() {
    for (w, h, scene) in [
        (80, 24, Scene::default()),
        (100, 30, Preset::IceFrost.scene()),
    ] {
        let mut app = app_on(scene);
        app.colors = super::colors::Colors::None;
        for sets in 0..3 {
            let s = text(&screen(&app, w, h));
            for line in s.lines() {
                if let Some((_, tail)) = line.split_once(" +") {
                    let count: String = tail.chars().take_while(char::is_ascii_digit).collect();
                    if count.is_empty() {
                        continue;
                    }
                    let rest = tail[count.len()..].trim_end();
                    let rest = rest.split(" ─").next().unwrap_or(rest).trim_end();
                    assert!(
                        rest.is_empty()
                            || rest.starts_with(" more")
                                && (rest == " more" || rest.ends_with("(x exports all)")),
                        "{w}×{h}, set {sets}: cut count in {line:?}"
                    );
                }
            }
            update(&mut app, ch('c'));
            settle(&mut app);
        }
    }
}

/// Issue 37 (review E16): the ring card opens on the Ω of the README's worked example and of the
/// page's card (Saturn's A ring; it took the tidal card's Encke division and printed c = 5.046
/// µm/s against the README's 5.26 µm/s for the same preset), and says which Ω it is. The numbers
/// are read from README.md and www/ring.js; c at the monolayer floor is 2RΩ.
#[test]
fn issue_37_the_ring_card_opens_on_the_readmes_omega_and_names_it() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    let readme = std::fs::read_to_string(format!("{root}/README.md")).expect("README");
    let after = readme
        .split("Worked example, Saturn's A ring\n(Ω = ")
        .nth(1)
        .expect("the README's worked example names its Ω");
    let readme_omega: f64 = after.split(' ').next().unwrap().parse().expect("Ω");
    let page = std::fs::read_to_string(format!("{root}/www/ring.js")).expect("ring.js");
    let page_omega: f64 = page
        .split("omega: ")
        .nth(1)
        .and_then(|s| s.split(',').next())
        .expect("the page's default Ω")
        .parse()
        .expect("Ω");
    assert_eq!(readme_omega, page_omega);
    let mut app = app_on(Scene::default());
    update(&mut app, ch('r'));
    let card = match app.ring_card.clone() {
        Some(Ok(card)) => card,
        other => panic!("no ring card: {other:?}"),
    };
    assert_eq!(card.record.omega, readme_omega);
    let s = text(&screen(&app, 120, 40));
    assert!(s.contains("(Saturn's A ring)"), "{s}");
    // The ice preset's 2 cm grains sit at the floor, c = 2RΩ (README: 5.26 µm/s).
    let floor = 2.0 * 0.02 * readme_omega;
    assert!((floor * 1e6 - 5.257).abs() < 5e-4, "{floor}");
    assert!(
        s.contains("velocity dispersion c: 5.257 µm/s (2 RΩ)"),
        "{s}"
    );
    // Moved with the planet, the card says how far.
    update(&mut app, ch('>'));
    let s = text(&screen(&app, 120, 40));
    assert!(s.contains("(A ring, d ×1.05)"), "{s}");
}

/// Issue 37 (review E12): the stick map's x axis carries its title (g_T), as its y axis carries
/// "g_N ↑" and the exported stick_map.png "tangential speed g_T [m/s]": on the row of the x tick
/// labels, at 80×24 (the map in the shared pane), 120×40 and 200×60.
#[test]
fn issue_37_the_stick_map_names_its_x_axis() {
    for (w, h) in [(80u16, 24u16), (120, 40), (200, 60)] {
        let mut app = app_on(Scene::default());
        app.size = (w, h);
        if w == 80 {
            update(&mut app, key(KeyCode::Tab));
            update(&mut app, key(KeyCode::Tab));
        }
        let s = text(&screen(&app, w, h));
        let lines: Vec<&str> = s.lines().collect();
        let top = lines
            .iter()
            .position(|l| l.contains("stick map"))
            .unwrap_or_else(|| panic!("{w}×{h}: no map\n{s}"));
        // The x tick row: the map's "0 … 0.5 … 1" below its top; the title is on it.
        let ticks = lines[top..]
            .iter()
            .find(|l| {
                // Right of the parameters' pane: "0 … 1" (g_T from 0 to the map's 1 m/s).
                let pane = l.rsplit(['│', '┃']).next().unwrap_or(l);
                let words: Vec<&str> = pane.split_whitespace().collect();
                words.first() == Some(&"0") && words.last() == Some(&"1")
            })
            .unwrap_or_else(|| panic!("{w}×{h}: no x tick row\n{s}"));
        assert!(ticks.contains("g_T"), "{w}×{h}: {ticks}\n{s}");
    }
}

/// Issue 37 (review E13): the `i` panel's F(ξ) plot labels its origin `0` on the frosted preset,
/// whose overlap starts at a float-noise 2.7e-26 m (the tick at 0 fell off the axis: the row read
/// `5e-7  1e-6  1.5e-6` with nothing under the origin).
#[test]
fn issue_37_the_force_overlap_plot_labels_its_origin() {
    let mut app = app_on(Preset::IceFrost.scene());
    update(&mut app, ch('i'));
    settle(&mut app);
    let s = text(&screen(&app, 120, 40));
    let title = s
        .lines()
        .position(|l| l.contains("overlap ξ [m]") && l.contains("time t [s]"))
        .unwrap_or_else(|| panic!("no F(ξ) plot\n{s}"));
    let ticks = s.lines().nth(title - 1).unwrap();
    let axis = s.lines().nth(title - 2).unwrap();
    // The F(ξ) plot is the right one: its axis line starts at the second └.
    let origin = axis.char_indices().filter(|(_, c)| *c == '└').nth(1);
    let (byte, _) = origin.unwrap_or_else(|| panic!("no second axis\n{s}"));
    let column = axis[..byte].chars().count();
    let right: String = ticks.chars().skip(column).collect();
    let words: Vec<&str> = right.split_whitespace().collect();
    assert_eq!(words.first(), Some(&"0"), "{right}\n{s}");
    assert!(
        axis.chars().nth(column + 1) == Some('┼'),
        "no tick at the origin: {axis}"
    );
}

/// Issue 37 (review E14): an open or a save names its file one way, the path it used (`./…` under
/// the working folder, absolute elsewhere): a missing file read `./nothere.json` and an existing
/// one `bad-scene.json`.
#[test]
fn issue_37_open_and_save_name_the_file_they_used() {
    // The tests run in the crate's folder: Cargo.toml exists there (and is no scene), the other
    // name does not.
    let mut app = app_on(Scene::default());
    for name in ["Cargo.toml", "nothere-issue-37.json"] {
        app.open_scene(name);
        let (msg, tone) = app.message.clone().expect("message");
        assert_eq!(tone, Tone::Error);
        assert!(
            msg.starts_with(&format!("open ./{name}: ")),
            "{name}: {msg}"
        );
        assert!(msg.ends_with("(scene unchanged)"), "{msg}");
    }
    // Outside the working folder: the absolute path, for a save and the open of what it wrote.
    let dir = std::env::temp_dir().join(format!("rime-issue-37-e14-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    app.out_dir = dir.clone();
    update(&mut app, ch('w'));
    let file = dir.join("rime-scene.json");
    let (msg, _) = app.message.clone().expect("message");
    assert_eq!(msg, format!("saved scene to {}", file.display()));
    app.open_scene(&file.display().to_string());
    let (msg, tone) = app.message.clone().expect("message");
    assert_eq!(tone, Tone::Info, "{msg}");
    assert_eq!(msg, format!("opened scene {} (u undoes)", file.display()));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 37 (review E1): a length typed where a time is expected names both kinds before the
/// examples (a status line of 80 columns cuts the end): "expected a time, not a length"; the
/// scene is unchanged.
#[test]
fn issue_37_a_length_typed_for_a_time_says_so() {
    let mut app = app_on(Scene::default());
    let before = app.scene;
    select(&mut app, "bulk.damping.time");
    update(&mut app, ch('e'));
    update(
        &mut app,
        Event::Key(KeyEvent::new(KeyCode::Char('u'), KeyModifiers::CONTROL)),
    );
    for c in "2 um".chars() {
        update(&mut app, ch(c));
    }
    update(&mut app, key(KeyCode::Enter));
    let (msg, tone) = app.message.clone().expect("message");
    assert_eq!(tone, Tone::Error);
    assert!(
        msg.starts_with("bulk.damping.time: expected a time, not a length"),
        "{msg}"
    );
    assert!(msg.ends_with("(scene unchanged)"), "{msg}");
    assert_eq!(app.scene, before);
}

/// Issue 37 (review E6): a source has one name on every small surface: the chart's experiments
/// (`b`) said `Bridges'84`, `Heißelmann'10`, `Hill'15` where the measured-ice comparison (`c`),
/// `rime data`, the CSV columns and the fit message say `bridges1984`, `heisselmann2010`,
/// `hill2015`: now the atlas id in both legends.
#[test]
fn issue_37_one_name_per_source_in_both_legends() {
    let ids = ["bridges1984", "heisselmann2010", "hill2015"];
    for id in ids {
        assert!(rime_core::atlas::find(id).is_some(), "{id} is an atlas id");
    }
    let mut app = app_on(Scene::default());
    let experiments = text(&screen(&app, 160, 45));
    update(&mut app, ch('c'));
    let req = app.take_request().expect("a new request");
    let data = compute(&req, &|| false, &NoMemo).expect("frame");
    update(&mut app, Event::Computed(Box::new(data)));
    let compared = text(&screen(&app, 160, 45));
    for id in ids {
        assert!(
            experiments.contains(id),
            "experiments: no {id}\n{experiments}"
        );
        assert!(compared.contains(id), "comparison: no {id}\n{compared}");
    }
    for old in ["Bridges'84", "Heißelmann'10", "Hill'15"] {
        assert!(
            !experiments.contains(old) && !compared.contains(old),
            "{old}"
        );
    }
}

/// Issue 37 (review F2.5): `eps_family.csv` ("every ε_N curve of the chart") holds the measured
/// law the chart draws (the experiments' Bridges law over its measured speeds, 0.15–20 mm/s) and,
/// with the ring card open, the ring's ε_cr line on every row of the chart's speeds. The law's
/// values are checked against its printed form, ε = 0.32 (v / 1 cm/s)^−0.234, written here.
#[test]
fn issue_37_the_all_curves_table_has_the_measured_law_and_the_ring_line() {
    let mut app = app_on(Scene::default());
    assert!(app.experiments);
    let table = |files: &std::collections::BTreeMap<String, String>| -> Vec<Vec<String>> {
        files["eps_family.csv"]
            .lines()
            .filter(|l| !l.starts_with('#'))
            .map(|l| l.split(',').map(str::to_string).collect())
            .collect()
    };
    let rows = table(&exported_files(&mut app, "f25-law"));
    let law = rows[0]
        .iter()
        .position(|h| h == "eps_n:bridges1984")
        .unwrap_or_else(|| panic!("no law column: {:?}", rows[0]));
    let mut cells = 0;
    for r in &rows[1..] {
        let g: f64 = r[0].parse().expect("g");
        if let Some(c) = r.get(law).filter(|c| !c.is_empty()) {
            let eps: f64 = c.parse().expect("eps");
            assert!(
                (1.5e-4 * (1.0 - 1e-12)..=2e-2 * (1.0 + 1e-12)).contains(&g),
                "{g}"
            );
            let printed = 0.32 * (g / 0.01).powf(-0.234);
            assert!(
                (eps / printed - 1.0).abs() < 1e-12,
                "{g}: {eps} vs {printed}"
            );
            cells += 1;
        }
    }
    assert!(cells >= 20, "{cells} law cells");
    // The ring card open: its ε_cr on every row of the chart's speeds.
    update(&mut app, ch('r'));
    let card = match app.ring_card.clone() {
        Some(Ok(card)) => card,
        other => panic!("no ring card: {other:?}"),
    };
    let eps_cr = card.record.prediction().eps_cr;
    let rows = table(&exported_files(&mut app, "f25-ring"));
    let head = format!("eps_cr [ring τ = {}]", card.record.tau);
    let col = rows[0]
        .iter()
        .position(|h| *h == head)
        .unwrap_or_else(|| panic!("no {head}: {:?}", rows[0]));
    let frame_rows = rows[1..].iter().filter(|r| !r[1].is_empty()).count();
    assert!(frame_rows > 50);
    for r in rows[1..].iter().filter(|r| !r[1].is_empty()) {
        assert_eq!(r[col].parse::<f64>().ok(), Some(eps_cr), "{r:?}");
    }
}

/// Issue 37 (review web F1.1): the adhesion marker says what g_s is a threshold of — a rebound
/// slower than it sticks — not "g_s …, a rebound speed", which read as a contradiction next to a
/// sticking speed; the short legend says it is on the rebound speed.
#[test]
fn issue_37_the_adhesion_marker_says_what_it_holds() {
    let mut app = app_on(Preset::IceSticky.scene());
    let files = exported_files(&mut app, "f11");
    // The SVG's words, its wrapped lines joined.
    let svg = &files["eps_n.svg"];
    let words: String = svg
        .split('<')
        .filter_map(|t| t.split_once('>').map(|(_, w)| w))
        .collect::<Vec<_>>()
        .join(" ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    assert!(
        words.contains("g_s adhesion (Eq. (15)): a rebound slower than g_s sticks; g_s = "),
        "{words}"
    );
    assert!(!words.contains("a rebound speed ="), "{words}");
    let s = text(&screen(&app, 160, 40));
    assert!(s.contains("g_s adhesion, on the rebound speed"), "{s}");
}
