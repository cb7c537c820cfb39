//! The one request (issue 21): its serde form, its limits, and the forms written before it.

use rime_core::explorer::frame::Overlay;
use rime_core::explorer::request::Request;
use rime_core::{Accuracy, Preset};

fn parse(text: &str) -> Result<Request, String> {
    serde_json::from_str::<Request>(text).map_err(|e| e.to_string())
}

#[test]
fn a_request_reads_back_what_it_writes_issue_21() {
    let mut r = Request::new(Preset::IceFrost.scene(), Accuracy::Tolerance(3e-9));
    r.speeds = Some((1e-6, 2.5));
    r.points = 17;
    r.map_n = 9;
    r.map_max = Some(0.3);
    r.sweep = Some(2);
    r.family = false;
    r.overlays = vec![Overlay::parse("atlas:bridges1984").unwrap()];
    r.fail = vec!["map".into()];
    let text = serde_json::to_string(&r).unwrap();
    assert_eq!(parse(&text).unwrap(), r, "{text}");
    // The keys are snake_case, as in every file record (issue 36), the sweep its parameter path.
    for key in [
        "\"map_n\":9",
        "\"map_max\":0.3",
        "\"from\":1e-6",
        "\"overlays\":[\"atlas:bridges1984\"]",
    ] {
        assert!(text.contains(key), "{key} missing in {text}");
    }
}

#[test]
fn an_empty_request_is_the_default_view_issue_21() {
    let r = parse("{}").unwrap();
    assert_eq!(r, Request::new(Preset::Ice.scene(), Accuracy::default()));
    assert_eq!((r.points, r.map_n), (Request::POINTS, Request::MAP_N));
}

#[test]
fn requests_written_before_the_one_request_still_load_issue_21() {
    // `balanced` was the name of `integrated`; the page's views wrote camelCase map keys until
    // issue 36.
    let r = parse(r#"{"accuracy": "balanced", "mapN": 12, "mapMax": 0.5}"#).unwrap();
    assert_eq!(r.accuracy, Accuracy::Balanced);
    assert_eq!((r.map_n, r.map_max), (12, Some(0.5)));
    let both = parse(r#"{"map_n": 12, "mapN": 13}"#).unwrap_err();
    assert!(both.contains("duplicate field"), "{both}");
}

#[test]
fn a_refused_request_names_its_field_issue_21() {
    for (text, field) in [
        (r#"{"map_n": 1001}"#, "map_n"),
        (r#"{"mapN": 1001}"#, "map_n"),
        (r#"{"points": 1}"#, "points"),
        (r#"{"points": 20001}"#, "points"),
        (r#"{"from": 1e-300, "to": 1}"#, "from"),
        (r#"{"from": 1, "to": 2e6}"#, "to"),
        (r#"{"from": 1, "to": 0.5}"#, "to"),
        (r#"{"from": 1}"#, "to"),
        (r#"{"sweep": "grains.colour"}"#, "sweep"),
        (r#"{"overlays": ["atlas:nope"]}"#, "overlays"),
        (r#"{"fail": ["everything"]}"#, "fail"),
        (r#"{"accuracy": "1e-20"}"#, "accuracy"),
        (r#"{"colour": 1}"#, "colour"),
    ] {
        let e = parse(text).unwrap_err();
        assert!(e.contains(field), "{text}: {e}");
    }
}

#[test]
fn the_limits_are_the_models_own_issue_21() {
    // The request's speed limit is the one the models enforce: a speed just above it is refused
    // by ε_N itself, so no surface can ask the chart for a speed the models refuse.
    let contact = rime_core::Contact::new(&Preset::Ice.scene()).unwrap();
    assert!(contact.normal(Request::SPEED_MAX, Accuracy::Fast).is_ok());
    assert!(
        contact
            .normal(Request::SPEED_MAX * (1.0 + 1e-15), Accuracy::Fast)
            .is_err()
    );
    let mut r = Request::new(Preset::Ice.scene(), Accuracy::Fast);
    r.speeds = Some((Request::SPEED_MIN, Request::SPEED_MAX));
    assert!(r.validate().is_ok());
    r.speeds = Some((Request::SPEED_MIN / 2.0, Request::SPEED_MAX));
    assert!(r.validate().is_err());
}
