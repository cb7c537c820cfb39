//! One update of the web page in one call: a whole frame (curve, family, clean-surface curve,
//! critical speeds, stick map, warnings, tidal appendix) computed from a scene and a view.
//!
//! Every part fails on its own: a part that errors is left out and its message is listed in
//! `errors` (`{part, message}`), the other parts are still computed. A speed on a curve whose ε_N
//! fails becomes a gap (NaN, status code [`FAILED`]), not a failed frame. The frame is the core's
//! frame's serde form with what only the page shows beside it (`PageFrame`), in its wire form
//! (`rime_core::wire`): the number arrays in two flat buffers (`f64` and `u8`), the JSON
//! giving each as `{"$f64": [at, len]}` or `{"$u8": [at, len]}`.

use crate::explorer::{parse_scene, tidal_json};
use rime_core::explorer::frame::{Request, compute_with};
use rime_core::explorer::wire::to_wire;
use rime_core::explorer::{figures, records};
use rime_core::figure::Figure;
use rime_core::normal::memo::SharedLayerMemo;
use rime_core::params::{PARAMETERS, Value};
use rime_core::tidal::TidalInput;
use rime_core::{Scene, Status};
use serde::{Deserialize, Serialize};
use serde_json::Value as Json;

/// Status code of a speed whose ε_N could not be computed (a gap on the curve).
pub use rime_core::explorer::frame::FAILED;

/// What the page shows of a scene: the core's [`Request`] (accuracy, speeds, points, map, family,
/// overlays; parsed and checked by the core, so the page refuses what every surface refuses) and
/// what only the page's figures and records need.
#[derive(Debug, Clone)]
pub struct View {
    /// The core's request (its scene is replaced by the scene of the call).
    pub request: Request,
    /// The appendix input; `None` for the paper's example with the scene's grains.
    pub tidal: Option<TidalInput>,
    /// Whether the tidal part fails on purpose (`"tidal"` in `view.fail`; the core's parts are in
    /// the request).
    pub fail_tidal: bool,
    /// ε_N on a log axis (the figures follow the screen).
    pub y_log: bool,
    /// Whether the experimental context is drawn (when no overlay is chosen).
    pub experiments: bool,
    /// A curve pinned to compare with later edits: `{label, g: [...], eps: [...]}`.
    pub pinned: Option<PinnedCurve>,
    /// The date the records' context lines carry (the page's clock; the core has none).
    pub date: String,
    /// Whether the frame carries its records (the CSV of the downloads): a preview, never
    /// exported, goes without them (issue 26: formatting them was a fifth of a frame's time).
    pub records: bool,
}

/// The keys of a view that are the page's own (the others are the core request's).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "camelCase")]
struct PageKeys {
    #[serde(default)]
    tidal: Option<TidalInput>,
    #[serde(default)]
    y_log: bool,
    #[serde(default = "default_true")]
    experiments: bool,
    #[serde(default)]
    pinned: Option<PinnedCurve>,
    #[serde(default)]
    date: String,
    #[serde(default = "default_true")]
    records: bool,
}

fn default_true() -> bool {
    true
}

/// A pinned curve as the page sends it.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PinnedCurve {
    /// Legend text.
    pub label: String,
    /// Speeds \[m/s\].
    pub g: Vec<f64>,
    /// ε_N at `g` (`null` for a gap).
    pub eps: Vec<Option<f64>>,
}

/// The parts a view can fail on purpose (`curve` fails every 40th speed, a gap; the others whole).
pub const FORCIBLE: [&str; 5] = ["curve", "family", "marker", "map", "tidal"];

fn forced(part: &str) -> String {
    format!("failure forced for testing ({part} in view.fail)")
}

/// Parses a view; errors name the field (`view.from: ...`).
pub fn parse_view(text: &str) -> Result<View, String> {
    let named = |path: String, message: String| {
        if path == "." || path.is_empty() {
            // The core's checks name their field first (`mapN: …`).
            format!("view.{message}")
        } else {
            format!("view.{path}: {message}")
        }
    };
    let mut keys: serde_json::Map<String, Json> =
        serde_json::from_str(text).map_err(|e| format!("view: {e}"))?;
    let mut page = serde_json::Map::new();
    for k in ["tidal", "yLog", "experiments", "pinned", "date", "records"] {
        if let Some(v) = keys.remove(k) {
            page.insert(k.into(), v);
        }
    }
    let mut fail_tidal = false;
    if let Some(Json::Array(parts)) = keys.get_mut("fail") {
        if let Some(bad) = parts
            .iter()
            .find(|p| !p.as_str().is_some_and(|p| FORCIBLE.contains(&p)))
        {
            return Err(format!(
                "view.fail: unknown part {bad} (one of {})",
                FORCIBLE.join(", ")
            ));
        }
        fail_tidal = parts.iter().any(|p| p == "tidal");
        parts.retain(|p| p != "tidal");
    }
    let page: PageKeys = serde_path_to_error::deserialize(Json::Object(page))
        .map_err(|e| named(e.path().to_string(), e.into_inner().to_string()))?;
    let request: Request = serde_path_to_error::deserialize(Json::Object(keys))
        .map_err(|e| named(e.path().to_string(), e.into_inner().to_string()))?;
    Ok(View {
        request,
        tidal: page.tidal,
        fail_tidal,
        y_log: page.y_log,
        experiments: page.experiments,
        pinned: page.pinned,
        date: page.date,
        records: page.records,
    })
}

/// A computed frame: one JSON text and two flat arrays it points into.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Frame {
    /// The frame's description (see the module docs).
    pub json: String,
    /// Every floating-point array, concatenated.
    pub numbers: Vec<f64>,
    /// Every code array (statuses, stick classes), concatenated.
    pub codes: Vec<u8>,
    /// The records as JSON, `{curve, family, map: null, context: {curve, family, map}}` (the CSV of
    /// the downloads and their context lines), apart from `json` so that the page reads them only
    /// when a download asks; `null` when the view asked for none (`records: false`).
    pub records: String,
}

/// Every parameter's value (number, choice name, boolean, or `null` when inactive), by path.
fn values(scene: &Scene) -> Json {
    let mut m = serde_json::Map::new();
    for p in PARAMETERS.iter() {
        let v = match scene.get(p.path) {
            Ok(Value::Number(x)) => Json::from(x),
            Ok(Value::Choice(c)) => Json::from(c),
            Ok(Value::Enabled(b)) => Json::from(b),
            Ok(Value::Inactive) | Err(_) => Json::Null,
        };
        m.insert(p.path.to_string(), v);
    }
    Json::Object(m)
}

/// The literal layer reading's outcomes kept between this worker's frames (issue 26): an edit that
/// leaves the layer stage's inputs unchanged is answered without integrating again. Each worker
/// instantiates the module, so each has its own.
pub(crate) static LAYER_MEMO: SharedLayerMemo = SharedLayerMemo::new();

/// Computes the frame of `scene` as seen through `view`. Fails only for a request that is not
/// valid (scene or view naming the field); a part that fails is listed in `errors` instead.
pub fn frame(scene_json: &str, view_json: &str) -> Result<Frame, String> {
    let (view, req) = prepare(scene_json, view_json)?;
    // The one explorer model of the core computes every part; this binding only packs it.
    let f = compute_with(&req, &|| false, &LAYER_MEMO).ok_or("frame: cancelled")?;
    pack_frame(&view, &req, &f)
}

/// The view of `view_json` and the core's request for `scene_json` seen through it.
pub(crate) fn prepare(scene_json: &str, view_json: &str) -> Result<(View, Request), String> {
    let scene = parse_scene(scene_json)?;
    let view = parse_view(view_json)?;
    let mut req = view.request.clone();
    req.scene = scene;
    Ok((view, req))
}

/// What crosses to the page besides the core's frame: the scene's values, the figures, the tidal
/// card and the status names. Its wire form (`rime_core::wire`) is the page's frame.
#[derive(Serialize)]
struct PageFrame<'a> {
    /// The core's frame, field for field (its serde form).
    #[serde(flatten)]
    frame: &'a rime_core::explorer::frame::Frame,
    /// Every parameter's value by path.
    values: Json,
    /// The side of the stick map asked for.
    map_n: usize,
    /// The figure descriptions, built by the core for every surface.
    figures: Vec<Figure>,
    /// The tidal card, or `{"error": …}`.
    tidal: Tidal,
    /// The status names in code order ([`Status::ALL`]).
    status_names: [&'static str; 4],
}

/// The tidal card as it crosses: the card, or why there is none.
#[derive(Serialize)]
#[serde(untagged)]
enum Tidal {
    Card(Json),
    Error { error: String },
}

/// The frame's records, the CSV of the downloads (see [`Frame::records`]).
#[derive(Serialize)]
struct Records {
    curve: String,
    family: String,
    /// Formatted on download (`mapRecords`), never in the frame.
    map: Option<String>,
    context: RecordsContext,
}

/// Each record's context lines (what, version, date, scene).
#[derive(Serialize)]
struct RecordsContext {
    curve: String,
    family: String,
    map: String,
}

/// The page's frame (JSON, arrays, records) of the core's frame `f` of `req` seen through `view`.
pub(crate) fn pack_frame(
    view: &View,
    req: &Request,
    f: &rime_core::explorer::frame::Frame,
) -> Result<Frame, String> {
    let version = env!("CARGO_PKG_VERSION");
    let pinned = match &view.pinned {
        Some(p) if p.g.len() != p.eps.len() => {
            return Err("view.pinned: g and eps must have the same length".into());
        }
        Some(p) => Some(figures::Pinned {
            label: p.label.clone(),
            g: p.g.clone(),
            eps: p.eps.iter().map(|e| e.unwrap_or(f64::NAN)).collect(),
        }),
        None => None,
    };
    // The one CSV contract, built by the core for every surface; the map's records are formatted
    // on download (`mapRecords`), not every frame.
    // The one CSV contract, built by the core for every surface; the map's records are formatted
    // on download (`mapRecords`), not every frame.
    let records = if view.records {
        let ctx = |what: &str| records::context(f, what, version, &view.date);
        Some(Records {
            curve: records::frame_curve_csv(f),
            // Every curve the chart draws, the pinned one included (issue 37).
            // and the measured laws (issue 37 F2.5); the page adds the ring's ε_cr column.
            family: records::family_csv_drawn(
                f,
                &records::Drawn {
                    pinned: pinned.as_ref(),
                    experiments: view.experiments,
                    ring_eps_cr: None,
                },
            ),
            map: None,
            context: RecordsContext {
                curve: ctx(records::CURVE_WHAT),
                family: ctx(records::FAMILY_WHAT),
                map: ctx(records::MAP_WHAT),
            },
        })
    } else {
        None
    };
    let fig_view = figures::View {
        y_log: view.y_log,
        experiments: view.experiments,
        pinned,
    };
    let tidal = if view.fail_tidal {
        Err(forced("tidal"))
    } else {
        tidal_json(&req.scene, view.tidal)
    };
    let page = PageFrame {
        frame: f,
        values: values(&req.scene),
        map_n: req.map_n,
        figures: figures::frame_figures(f, &fig_view, version),
        tidal: tidal.map_or_else(|error| Tidal::Error { error }, Tidal::Card),
        status_names: Status::ALL.map(Status::name),
    };
    let wire = to_wire(&page).map_err(|e| e.to_string())?;
    Ok(Frame {
        json: wire.json,
        numbers: wire.numbers,
        codes: wire.codes,
        records: serde_json::to_string(&records).map_err(|e| format!("records: {e}"))?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rime_core::explorer::range::auto_map_range;
    use rime_core::{Accuracy, Contact};
    use serde_json::json;

    fn get<'a>(f: &'a Frame, j: &Json) -> &'a [f64] {
        let at = j["$f64"][0].as_u64().unwrap() as usize;
        let len = j["$f64"][1].as_u64().unwrap() as usize;
        &f.numbers[at..at + len]
    }

    fn frost() -> Scene {
        rime_core::Preset::IceFrost.scene()
    }

    /// The page's reader (www/app.js `decode`), written again: each `{"$f64": [at, len]}` or
    /// `{"$u8": [at, len]}` becomes the array it points at (NaN as `null`, as `serde_json` writes it).
    fn read(f: &Frame) -> Json {
        fn walk(v: Json, f: &Frame) -> Json {
            match v {
                Json::Object(m)
                    if m.len() == 1 && (m.contains_key("$f64") || m.contains_key("$u8")) =>
                {
                    let (key, r) = m.into_iter().next().unwrap();
                    let at = r[0].as_u64().unwrap() as usize;
                    let len = r[1].as_u64().unwrap() as usize;
                    if key == "$f64" {
                        json!(f.numbers[at..at + len])
                    } else {
                        json!(f.codes[at..at + len])
                    }
                }
                Json::Object(m) => {
                    Json::Object(m.into_iter().map(|(k, v)| (k, walk(v, f))).collect())
                }
                Json::Array(a) => Json::Array(a.into_iter().map(|v| walk(v, f)).collect()),
                v => v,
            }
        }
        walk(serde_json::from_str(&f.json).unwrap(), f)
    }

    #[test]
    fn issue_36_the_pages_frame_is_the_core_frames_serde_form() {
        // Each field of the frame is declared once, on the core's type: the page's frame, read
        // back, holds the core frame's serde form key for key, and only the page's own keys beside.
        let scene = frost();
        let mut req = rime_core::explorer::frame::Request::new(scene, Accuracy::Precise);
        req.points = 40;
        req.map_n = 8;
        req.overlays =
            vec![rime_core::explorer::frame::Overlay::parse("model:muller_poschel2011").unwrap()];
        let core = rime_core::explorer::frame::compute(&req, &|| false).unwrap();
        let expected = serde_json::to_value(&core).unwrap();
        let text = serde_json::to_string(&scene).unwrap();
        let page = read(
            &frame(
                &text,
                r#"{"points": 40, "mapN": 8, "overlays": ["model:muller_poschel2011"]}"#,
            )
            .unwrap(),
        );
        let expected = expected.as_object().unwrap();
        for (key, value) in expected {
            assert_eq!(&page[key], value, "{key}");
        }
        let own: Vec<&str> = page
            .as_object()
            .unwrap()
            .keys()
            .map(String::as_str)
            .filter(|k| !expected.contains_key(*k))
            .collect();
        assert_eq!(own, ["figures", "map_n", "status_names", "tidal", "values"]);
        // The arrays crossed as buffers, the gaps' NaN included.
        assert!(page["curve"]["eps"].as_array().unwrap().len() == 40);
        assert!(page["map"]["map"]["class"].as_array().unwrap().len() == 64);
    }

    #[test]
    fn frame_matches_the_core_and_the_old_getters() {
        let scene = frost();
        let text = serde_json::to_string(&scene).unwrap();
        let f = frame(&text, r#"{"points": 50, "mapN": 20}"#).unwrap();
        let j: Json = serde_json::from_str(&f.json).unwrap();
        assert_eq!(j["errors"], json!([]), "{}", j["errors"]);
        let g = get(&f, &j["g"]);
        let eps = get(&f, &j["curve"]["eps"]);
        let contact = Contact::new(&scene).unwrap();
        for (gi, e) in g.iter().zip(eps) {
            assert_eq!(contact.normal(*gi, Accuracy::Precise).unwrap().eps, *e);
        }
        assert_eq!(j["family"].as_array().unwrap().len(), 4);
        assert!(j["clean"]["eps"].is_object());
        assert_eq!(j["map_n"], 20);
        assert_eq!(j["map"]["max"], auto_map_range(&contact).max);
        assert_eq!(j["values"]["layer.viscosity"], 1000.0);
        assert_eq!(j["values"]["layer"], true);
        assert!(j["tidal"]["result"]["d_roche"].as_f64().unwrap() > 1e8);
        assert_eq!(j["markers"].as_array().unwrap().len(), 2);
    }

    #[test]
    fn the_frame_carries_the_cores_records_and_figures_issue_11() {
        let scene = frost();
        let text = serde_json::to_string(&scene).unwrap();
        let view = r#"{"points": 30, "mapN": 6, "from": 1e-6, "to": 1, "yLog": true, "date": "D"}"#;
        let f = frame(&text, view).unwrap();
        let j: Json = serde_json::from_str(&f.json).unwrap();
        let records: Json = serde_json::from_str(&f.records).unwrap();
        // The records are the CSV `rime curve` prints: built here from the core's normal results.
        let contact = Contact::new(&scene).unwrap();
        let mut g = vec![0.0; 30];
        rime_core::sweep::log_space(1e-6, 1.0, &mut g);
        let points: Vec<_> = g
            .iter()
            .map(|&gi| Some(contact.normal(gi, Accuracy::Precise).unwrap()))
            .collect();
        assert_eq!(
            records["curve"],
            rime_core::explorer::records::curve_csv(&g, &points)
        );
        assert!(
            records["context"]["curve"]
                .as_str()
                .unwrap()
                .contains("level precise, D")
        );
        // The map's records come on download, from the frame's arrays, equal to the core's.
        let m = &j["map"];
        let codes = &f.codes[m["map"]["class"]["$u8"][0].as_u64().unwrap() as usize..][..36];
        let csv = crate::explorer::map_records(
            get(&f, &m["map"]["g"]),
            get(&f, &m["map"]["eps_t"]),
            codes,
        );
        let mut req = rime_core::explorer::frame::Request::new(scene, Accuracy::Precise);
        req.speeds = Some((1e-6, 1.0));
        req.points = 30;
        req.map_n = 6;
        let core = rime_core::explorer::frame::compute(&req, &|| false).unwrap();
        assert_eq!(
            csv.unwrap(),
            rime_core::explorer::records::frame_map_csv(&core).unwrap()
        );
        let figs = j["figures"].as_array().unwrap();
        assert_eq!(figs.len(), 2);
        assert_eq!(figs[0]["y"]["log"], true, "the figure follows the view");
        assert_eq!(figs[1]["map"], true);
    }

    #[test]
    fn a_frame_without_records_is_the_same_frame_issue_26() {
        // A preview asks for no records (it is never exported): everything else is the frame with
        // them, bit for bit, and `records` says null.
        let text = serde_json::to_string(&frost()).unwrap();
        let with = frame(&text, r#"{"points": 30, "mapN": 6, "date": "D"}"#).unwrap();
        let without = frame(
            &text,
            r#"{"points": 30, "mapN": 6, "date": "D", "records": false}"#,
        )
        .unwrap();
        assert_eq!(without.records, "null");
        let records: Json = serde_json::from_str(&with.records).unwrap();
        assert!(
            records["curve"].as_str().unwrap().lines().count() > 30,
            "{records}"
        );
        assert_eq!(
            (&with.json, &with.numbers, &with.codes),
            (&without.json, &without.numbers, &without.codes)
        );
        assert!(
            !with.json.contains("\"records\""),
            "the records travel apart from the frame's JSON"
        );
        let bad = frame(&text, r#"{"records": 1}"#).unwrap_err();
        assert!(bad.starts_with("view.records:"), "{bad}");
    }

    #[test]
    fn the_map_range_is_the_cores_and_clamps_with_a_note_issue_10() {
        let mut scene = frost();
        scene.grains.radius_1 = 2e-6;
        scene.grains.radius_2 = 2e-6;
        scene.layer.as_mut().unwrap().thickness = 1e-5;
        let text = serde_json::to_string(&scene).unwrap();
        let f = frame(&text, r#"{"points": 20, "mapN": 10}"#).unwrap();
        let j: Json = serde_json::from_str(&f.json).unwrap();
        assert_eq!(j["map"]["max"], 1e6);
        assert!(
            j["map"]["auto"]["note"]
                .as_str()
                .unwrap()
                .contains("speed limit")
        );
        assert!(j["map"]["map"]["class"].is_object(), "{}", j["map"]);
        assert!(j["curve"]["eps"].is_object());
    }

    #[test]
    fn a_failing_part_leaves_the_others() {
        let scene = frost();
        let text = serde_json::to_string(&scene).unwrap();
        // A map range the core refuses: the map alone fails, named.
        let f = frame(&text, r#"{"points": 20, "mapN": 10, "mapMax": 2e6}"#).unwrap();
        let j: Json = serde_json::from_str(&f.json).unwrap();
        assert!(j["map"]["map"].is_null(), "{}", j["map"]);
        assert_eq!(j["errors"][0]["part"], "stick map");
        assert!(j["errors"][0]["message"].as_str().unwrap().contains("max"));
        assert!(j["curve"]["eps"].is_object());
        assert!(j["family"][0]["curve"]["eps"].is_object());
        // Bad requests name the field.
        assert!(
            frame(&text, r#"{"from": -1}"#)
                .unwrap_err()
                .starts_with("view.from")
        );
        assert!(
            frame(&text, r#"{"colour": 1}"#)
                .unwrap_err()
                .contains("colour")
        );
        assert!(
            frame(&text, r#"{"mapN": 1}"#)
                .unwrap_err()
                .starts_with("view.mapN")
        );
        assert!(frame("{", "{}").is_err());
        assert!(
            frame(
                &text,
                r#"{"tidal": {"planet_mass": 5.688e26, "distance": 1.336e8, "radius": -1,
                "density": 900, "surface_energy": 0.1}}"#
            )
            .map(|f| f.json.contains("\"tidal\":{\"error\":\"tidal."))
            .unwrap_or(false)
        );
    }

    #[test]
    fn forced_failures_fail_their_part_alone() {
        let text = serde_json::to_string(&frost()).unwrap();
        let f = frame(
            &text,
            r#"{"points": 80, "mapN": 10, "fail": ["curve", "map", "marker", "tidal", "family"]}"#,
        )
        .unwrap();
        let j: Json = serde_json::from_str(&f.json).unwrap();
        let parts: Vec<&str> = j["errors"]
            .as_array()
            .unwrap()
            .iter()
            .map(|e| e["part"].as_str().unwrap())
            .collect();
        assert_eq!(parts.len(), 7, "{parts:?}");
        assert!(parts.contains(&"stick map"));
        assert!(j["tidal"]["error"].as_str().unwrap().contains("forced"));
        let eps = get(&f, &j["curve"]["eps"]);
        assert_eq!(j["curve"]["failed"], 2);
        assert!(eps[20].is_nan() && eps[60].is_nan() && eps[21].is_finite());
        assert!(j["clean"]["eps"].is_object());
        assert_eq!(
            j["markers"].as_array().unwrap().len(),
            1,
            "{}",
            j["markers"]
        );
        assert!(
            frame(&text, r#"{"fail": ["chart"]}"#)
                .unwrap_err()
                .starts_with("view.fail")
        );
    }

    #[test]
    fn overlays_are_packed_and_bad_ones_name_the_field() {
        let text = serde_json::to_string(&Scene::default()).unwrap();
        let f = frame(
            &text,
            r#"{"points": 20, "mapN": 4, "overlays": ["atlas:bridges1984", "model:muller_poschel2011"]}"#,
        )
        .unwrap();
        let j: Json = serde_json::from_str(&f.json).unwrap();
        let o = &j["overlays"];
        assert_eq!(o[0]["key"], "atlas:bridges1984");
        assert!(o[0]["score"].as_f64().unwrap() >= 0.0);
        assert_eq!(get(&f, &o[1]["g"]), get(&f, &j["g"]));
        let e = frame(&text, r#"{"overlays": ["atlas:nope"]}"#).unwrap_err();
        assert!(e.starts_with("view.overlays") && e.contains("nope"), "{e}");
    }

    #[test]
    fn family_follows_the_effects() {
        // The core's sweep policy: η* with a layer, γ with adhesion, else A (×0.1, 0.3, 3, 10).
        let family = |scene: &Scene| -> Json {
            let text = serde_json::to_string(scene).unwrap();
            let f = frame(&text, r#"{"points": 10, "mapN": 4}"#).unwrap();
            serde_json::from_str::<Json>(&f.json).unwrap()
        };
        let f = family(&Scene::default());
        assert_eq!(f["sweep"]["path"], "bulk.damping.time");
        let v: Vec<f64> = f["family"]
            .as_array()
            .unwrap()
            .iter()
            .map(|m| m["value"].as_f64().unwrap())
            .collect();
        let expected = [1e-5, 3e-5, 3e-4, 1e-3];
        assert!(
            v.iter()
                .zip(expected)
                .all(|(a, b)| (a / b - 1.0).abs() < 1e-12),
            "{v:?}"
        );
        assert_eq!(family(&frost())["sweep"]["path"], "layer.viscosity");
        let is_scene: Vec<Json> = family(&frost())["family"]
            .as_array()
            .unwrap()
            .iter()
            .map(|m| m["is_scene"].clone())
            .collect();
        assert_eq!(is_scene, [false, true, false, false]);
    }

    #[test]
    fn issue_36_the_records_keep_their_keys() {
        let text = serde_json::to_string(&frost()).unwrap();
        let f = frame(&text, r#"{"points": 12, "mapN": 4, "date": "D"}"#).unwrap();
        let records: Json = serde_json::from_str(&f.records).unwrap();
        let keys = |j: &Json| {
            let mut k: Vec<String> = j.as_object().unwrap().keys().cloned().collect();
            k.sort();
            k
        };
        assert_eq!(keys(&records), ["context", "curve", "family", "map"]);
        assert!(
            records["map"].is_null(),
            "the map's records come on download"
        );
        assert_eq!(keys(&records["context"]), ["curve", "family", "map"]);
        for (key, what) in [
            ("curve", records::CURVE_WHAT),
            ("family", records::FAMILY_WHAT),
            ("map", records::MAP_WHAT),
        ] {
            let line = records["context"][key].as_str().unwrap();
            assert!(line.starts_with(&format!("# {what}")), "{key}: {line}");
        }
        assert!(
            records["family"]
                .as_str()
                .unwrap()
                .starts_with("g_n [m/s],eps_n")
        );
    }
}
