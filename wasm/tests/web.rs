//! The binding, run in headless Chromium by wasm-bindgen-test (`scripts/test-all.d/30-web.sh`).
#![cfg(target_arch = "wasm32")]
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use rime_wasm::bindings::Explorer;
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

#[wasm_bindgen_test]
fn scene_json_round_trips() {
    let mut e = Explorer::new();
    e.load_preset("ice-frost").unwrap();
    let text = e.to_json().unwrap();
    let back = Explorer::from_json(&text).unwrap();
    assert_eq!(back.to_json().unwrap(), text);
}

#[wasm_bindgen_test]
fn errors_are_exceptions_not_panics() {
    let mut e = Explorer::new();
    let before = e.to_json().unwrap();
    assert!(e.set("layer.viscosity", "-1").is_err());
    assert!(e.set("no.such", "1").is_err());
    assert!(Explorer::from_json("{").is_err());
    assert!(e.curve(f64::NAN, 1.0, 10.0, "fast").is_err());
    assert!(e.curve(1e-3, 1.0, 1e12, "fast").is_err());
    assert!(e.curve(1e-3, 1.0, 2.5, "fast").is_err());
    assert!(e.stick_map(0.1, -3.0, "fast").is_err());
    assert!(e.curve(1e-3, 1.0, 10.0, "nope").is_err());
    assert_eq!(e.to_json().unwrap(), before);
    // The module still works after the errors.
    assert_eq!(e.curve(1e-3, 1.0, 10.0, "fast").unwrap().len(), 10);
}

#[wasm_bindgen_test]
fn curve_family_and_map() {
    let mut e = Explorer::new();
    e.load_preset("ice-frost").unwrap();
    let eps = e.curve(1e-6, 1.0, 64.0, "fast").unwrap();
    let status = e.statuses();
    assert_eq!(eps.len(), 64);
    assert_eq!(status.len(), 64);
    assert_eq!(status[0], 1, "stuck in layer at 1 µm/s");
    assert!(eps[63] > 0.0 && eps[63] < 1.0);
    let fam = e
        .family(
            "layer.viscosity",
            vec![500.0, 1000.0],
            1e-6,
            1.0,
            64.0,
            "fast",
        )
        .unwrap();
    assert_eq!(&fam[64..], &eps[..]);
    let classes = e.stick_map(1e-3, 16.0, "fast").unwrap();
    assert_eq!(classes.len(), 256);
    assert_eq!(e.map_eps_t().len(), 256);
    assert_eq!(classes[0], 6, "undefined at the origin");
    let crit = e.critical_velocities("fast").unwrap();
    assert!(crit.contains("layer"));
}

#[wasm_bindgen_test]
fn metadata() {
    assert!(Explorer::parameters().contains("layer.viscosity"));
    assert!(Explorer::presets().contains("ice-paper-viscosities"));
    assert!(Explorer::classes().contains("normal_stick_only"));
    assert!(Explorer::status_names().contains("stuck_by_adhesion"));
    let e = Explorer::new();
    assert!(e.tidal("").unwrap().contains("d_roche"));
    assert_eq!(e.get("layer").unwrap(), "false");
}
