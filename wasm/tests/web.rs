//! The binding, run in headless Chromium by wasm-bindgen-test (`scripts/test-all.d/30-web.sh`).
#![cfg(target_arch = "wasm32")]
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use rime_wasm::bindings::{
    Explorer, agrees_to_printed, compute_frame, fmt_decade, fmt_editable, fmt_qty, fmt_shortest,
    fmt_sig, help, palette, parse_quantity, parse_speed,
};
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
    // g (64), curve (64), clean (64), 4 family curves, map g, ε_N (16) and ε_T (256), then the
    // figures' series (x and y of each).
    let j: serde_json::Value = serde_json::from_str(&json).unwrap();
    let figure_numbers: u64 = j["figures"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|f| f["series"].as_array().unwrap().iter())
        .map(|s| s["x"]["$f64"][1].as_u64().unwrap() + s["y"]["$f64"][1].as_u64().unwrap())
        .sum();
    assert_eq!(numbers.len() as u64, 64 * 7 + 16 * 2 + 256 + figure_numbers);
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

#[wasm_bindgen_test]
fn the_cores_palette_formatters_and_parsers_reach_the_page_issue_11() {
    let p: serde_json::Value = serde_json::from_str(&palette()).unwrap();
    assert_eq!(p["scene"], "#E69F00");
    assert_eq!(p["classes"]["aggregation"], "#D55E00");
    let h: serde_json::Value = serde_json::from_str(&help()).unwrap();
    assert_eq!(h["paper"]["year"], 2002);
    assert!(
        h["parameters"]["layer.viscosity"]["help"]
            .as_str()
            .unwrap()
            .len()
            > 10
    );
    // Values worked out by hand: 6.6e-6 m/s is 6.6 µm/s; 1e-7 m/s reads back from "1e-7".
    assert_eq!(fmt_qty(6.6e-6, "m/s", 4), "6.6 µm/s");
    assert_eq!(fmt_sig(f64::NAN, 4), "—");
    assert_eq!(fmt_sig(0.36019, 3), "0.36");
    assert_eq!(fmt_shortest(1e-7), "1e-7");
    assert_eq!(fmt_editable(2000.0, "Pa s"), "2 kPa s");
    assert_eq!(fmt_decade(-6), "1e-6");
    assert!(agrees_to_printed(1.3408e8, 1.341e8));
    assert!(!agrees_to_printed(37.72, 37.6));
    assert_eq!(parse_speed("g from", "1 um/s").unwrap(), 1e-6);
    assert!(parse_speed("g to", "2e6 m/s").is_err());
    assert_eq!(
        parse_quantity("tidal.distance", "1.5e5 km", "m").unwrap(),
        1.5e8
    );
}
