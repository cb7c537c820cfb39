//! The binding, run in headless Chromium by wasm-bindgen-test (`scripts/test-all.d/30-web.sh`).
#![cfg(target_arch = "wasm32")]
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use rime_wasm::bindings::{Explorer, compute_frame};
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
    assert!(compute_frame(&before, r#"{"from": NaN}"#).is_err());
    assert!(compute_frame(&before, r#"{"points": 1e12}"#).is_err());
    assert!(compute_frame(&before, r#"{"points": 2.5}"#).is_err());
    assert!(compute_frame(&before, r#"{"mapN": -3}"#).is_err());
    assert!(compute_frame(&before, r#"{"accuracy": "nope"}"#).is_err());
    assert_eq!(e.to_json().unwrap(), before);
    // The module still works after the errors.
    assert!(compute_frame(&before, "{}").is_ok());
}

#[wasm_bindgen_test]
fn one_frame_per_call_with_parts_failing_alone() {
    let mut e = Explorer::new();
    e.load_preset("ice-frost").unwrap();
    let scene = e.to_json().unwrap();
    let mut f = compute_frame(&scene, r#"{"points": 64, "mapN": 16}"#).unwrap();
    let json = f.json();
    let numbers = f.numbers();
    let codes = f.codes();
    assert!(json.contains("\"errors\":[]"), "{json}");
    assert!(json.contains("\"key\":\"layer\""));
    // g (64), curve (64), clean (64), 4 family curves, map g, ε_N (16) and ε_T (256).
    assert_eq!(numbers.len(), 64 * 7 + 16 * 2 + 256);
    // statuses: curve, clean, 4 family curves; classes 256.
    assert_eq!(codes.len(), 64 * 6 + 256);
    assert_eq!(codes[0], 1, "stuck in layer at the lowest speed");
    let mut bad = compute_frame(&scene, r#"{"points": 8, "mapN": 4, "mapMax": 5e6}"#).unwrap();
    let j = bad.json();
    assert!(j.contains("\"part\":\"stick map\""), "{j}");
    assert!(bad.numbers().len() >= 8 * 2);
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
