//! One update of the web page in one call: a whole frame (curve, family, clean-surface curve,
//! critical speeds, stick map, warnings, tidal appendix) computed from a scene and a view.
//!
//! Every part fails on its own: a part that errors is left out and its message is listed in
//! `errors` (`{part, message}`), the other parts are still computed. A speed on a curve whose ε_N
//! fails becomes a gap (NaN, status code [`FAILED`]), not a failed frame. The numbers are packed into
//! two flat arrays (`f64` and `u8`); the JSON gives each array as `{"at": offset, "len": n}` into them.

use crate::explorer::{class_code, parse_scene, tidal_json};
use rime_core::explorer::frame::{Curve, Request, SWEEPS, compute_with};
use rime_core::explorer::{figures, records};
use rime_core::figure::Figure;
use rime_core::normal::memo::SharedLayerMemo;
use rime_core::params::{PARAMETERS, Value};
use rime_core::tidal::TidalInput;
use rime_core::{Scene, Status};
use serde::Deserialize;
use serde_json::{Value as Json, json};

/// Status code of a speed whose ε_N could not be computed (a gap on the curve).
pub const FAILED: u8 = u8::MAX;

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

#[derive(Default)]
struct Pack {
    numbers: Vec<f64>,
    codes: Vec<u8>,
}

impl Pack {
    fn f(&mut self, v: &[f64]) -> Json {
        let at = self.numbers.len();
        self.numbers.extend_from_slice(v);
        json!({"at": at, "len": v.len()})
    }
    fn u(&mut self, v: &[u8]) -> Json {
        let at = self.codes.len();
        self.codes.extend_from_slice(v);
        json!({"at": at, "len": v.len()})
    }
}

struct Errors(Vec<Json>);

impl Errors {
    fn push(&mut self, part: &str, message: impl Into<String>) {
        self.0
            .push(json!({"part": part, "message": message.into()}));
    }
}

/// A core curve as JSON: ε_N (NaN in the gaps) and status codes ([`FAILED`] in the gaps).
fn curve_json(pack: &mut Pack, c: &Curve) -> Json {
    let status: Vec<u8> = c
        .points
        .iter()
        .map(|p| p.map_or(FAILED, |n| n.status.code()))
        .collect();
    json!({"eps": pack.f(&c.eps()), "status": pack.u(&status), "failed": c.failed()})
}

/// A figure description as JSON; each series' points go into the number array as `x`, `y`.
fn figure_json(pack: &mut Pack, fig: &Figure) -> Json {
    let axis = |a: &rime_core::figure::Axis| json!({"label": a.label, "log": a.log, "min": a.min, "max": a.max});
    let series: Vec<Json> = fig
        .series
        .iter()
        .map(|s| {
            let x: Vec<f64> = s.points.iter().map(|p| p.0).collect();
            let y: Vec<f64> = s.points.iter().map(|p| p.1).collect();
            json!({"name": s.name, "short": s.short, "color": s.color,
                   "dashed": s.stroke.is_broken(), "stroke": s.stroke.name(),
                   "x": pack.f(&x), "y": pack.f(&y)})
        })
        .collect();
    let markers: Vec<Json> = fig
        .markers
        .iter()
        .map(|m| json!({"x": m.x, "label": m.label, "short": m.short, "color": m.color}))
        .collect();
    let bands: Vec<Json> = fig
        .bands
        .iter()
        .map(|b| json!({"x": [b.x.0, b.x.1], "y": [b.y.0, b.y.1], "label": b.label, "short": b.short, "color": b.color}))
        .collect();
    json!({"name": fig.name, "title": fig.title, "caption": fig.caption, "x": axis(&fig.x),
           "y": axis(&fig.y), "series": series, "markers": markers, "bands": bands,
           "map": fig.map.is_some()})
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

/// The page's frame (JSON, arrays, records) of the core's frame `f` of `req` seen through `view`.
// Long by design: packs every part of one frame into the page's JSON in one place.
pub(crate) fn pack_frame(
    view: &View,
    req: &Request,
    f: &rime_core::explorer::frame::Frame,
) -> Result<Frame, String> {
    let scene = req.scene;
    let force = |part: &str| part == "tidal" && view.fail_tidal;
    let mut pack = Pack::default();
    let mut errors = Errors(Vec::new());
    let mut out = serde_json::Map::new();
    out.insert("values".into(), values(&scene));
    out.insert("g".into(), pack.f(&f.g));
    for e in &f.errors {
        errors.push(&e.part, e.message.clone());
    }
    let curve = f.curve.as_ref().map(|c| curve_json(&mut pack, c));
    out.insert("curve".into(), curve.unwrap_or(Json::Null));
    let clean = f.clean.as_ref().map(|c| curve_json(&mut pack, c));
    out.insert("clean".into(), clean.unwrap_or(Json::Null));
    let family = if f.family.is_empty() {
        Json::Null
    } else {
        let s = SWEEPS[f.sweep];
        let curves: Vec<Json> = f
            .family
            .iter()
            .map(|m| {
                m.curve
                    .as_ref()
                    .map_or(Json::Null, |c| curve_json(&mut pack, c))
            })
            .collect();
        let values: Vec<f64> = f.family.iter().map(|m| m.value).collect();
        let is_scene: Vec<bool> = f.family.iter().map(|m| m.is_scene).collect();
        json!({"path": s.path, "sym": s.symbol, "unit": s.unit, "values": values,
               "isScene": is_scene, "curves": curves})
    };
    out.insert("family".into(), family);
    let critical: Vec<Json> = f
        .markers
        .iter()
        .map(|m| json!({"key": m.key, "label": m.label, "value": m.value}))
        .collect();
    out.insert("critical".into(), Json::from(critical));
    // The core's warnings: their sentences, and each with its short text, help and equation.
    let texts: Vec<String> = f.warnings.iter().map(|w| w.text()).collect();
    out.insert("warnings".into(), Json::from(texts));
    let details: Vec<Json> = f
        .warnings
        .iter()
        .map(|w| {
            json!({"key": w.key(), "short": w.short(), "text": w.text(), "help": w.help(),
                   "equation": w.equation()})
        })
        .collect();
    out.insert("warningDetails".into(), Json::from(details));
    let map = match &f.map {
        None => Json::Null,
        Some(part) => {
            let note = part.auto.and_then(|a| a.note());
            match &part.map {
                Some(m) => {
                    let class: Vec<u8> = m.class.iter().map(|c| class_code(*c)).collect();
                    json!({"n": req.map_n, "max": part.max, "auto": part.auto.is_some(), "note": note,
                           "g": pack.f(&m.g), "epsN": pack.f(&m.eps_n), "epsT": pack.f(&m.eps_t),
                           "class": pack.u(&class)})
                }
                None => {
                    let e = f
                        .errors
                        .iter()
                        .find(|e| e.part == "stick map")
                        .map_or(String::new(), |e| e.message.clone());
                    json!({"n": req.map_n, "max": part.max, "auto": part.auto.is_some(), "note": note,
                           "error": e})
                }
            }
        }
    };
    out.insert("map".into(), map);
    let overlays: Vec<Json> = f
        .overlays
        .iter()
        .map(|o| {
            let speeds: Vec<Json> = o
                .speeds
                .iter()
                .map(|(name, value)| json!({"name": name, "value": value}))
                .collect();
            json!({"key": o.overlay.key(), "label": o.label, "band": o.band, "score": o.score,
                   "g": pack.f(&o.g), "eps": pack.f(&o.eps), "speeds": speeds})
        })
        .collect();
    out.insert("overlays".into(), Json::from(overlays));
    out.insert("friction".into(), Json::from(scene.friction.is_some()));
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
    // The one CSV contract and the figure descriptions, built by the core for every surface.
    let version = env!("CARGO_PKG_VERSION");
    let record_json = if view.records {
        let ctx = |what: &str| records::context(f, what, version, &view.date);
        json!({
            "curve": records::frame_curve_csv(f),
            // Every curve the chart draws, the pinned one included (issue 37).
            "family": records::family_csv_pinned(f, pinned.as_ref()),
            // The map's records are formatted on download (`mapRecords`), not every frame.
            "map": Json::Null,
            "context": {
                "curve": ctx(records::CURVE_WHAT),
                "family": ctx(records::FAMILY_WHAT),
                "map": ctx(records::MAP_WHAT),
            },
        })
    } else {
        Json::Null
    };
    let fig_view = figures::View {
        y_log: view.y_log,
        experiments: view.experiments,
        pinned,
    };
    let figs: Vec<Json> = figures::frame_figures(f, &fig_view, version)
        .iter()
        .map(|fig| figure_json(&mut pack, fig))
        .collect();
    out.insert("figures".into(), Json::from(figs));
    out.insert(
        "tidal".into(),
        match if force("tidal") {
            Err(forced("tidal"))
        } else {
            tidal_json(&scene, view.tidal)
        } {
            Ok(t) => t,
            Err(e) => {
                errors.push("tidal", e.clone());
                json!({"error": e})
            }
        },
    );
    out.insert(
        "statusNames".into(),
        Json::from(Status::ALL.map(Status::name).to_vec()),
    );
    out.insert("errors".into(), Json::from(errors.0));
    Ok(Frame {
        json: Json::Object(out).to_string(),
        numbers: pack.numbers,
        codes: pack.codes,
        records: record_json.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use rime_core::explorer::range::auto_map_range;
    use rime_core::{Accuracy, Contact};

    fn get<'a>(f: &'a Frame, j: &Json) -> &'a [f64] {
        let at = j["at"].as_u64().unwrap() as usize;
        let len = j["len"].as_u64().unwrap() as usize;
        &f.numbers[at..at + len]
    }

    fn frost() -> Scene {
        rime_core::Preset::IceFrost.scene()
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
        assert_eq!(j["family"]["values"].as_array().unwrap().len(), 4);
        assert!(j["clean"]["eps"].is_object());
        assert_eq!(j["map"]["n"], 20);
        assert_eq!(j["map"]["max"], auto_map_range(&contact).max);
        assert_eq!(j["values"]["layer.viscosity"], 1000.0);
        assert_eq!(j["values"]["layer"], true);
        assert!(j["tidal"]["result"]["d_roche"].as_f64().unwrap() > 1e8);
        assert_eq!(j["critical"].as_array().unwrap().len(), 2);
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
        let codes = &f.codes[m["class"]["at"].as_u64().unwrap() as usize..][..36];
        let csv = crate::explorer::map_records(get(&f, &m["g"]), get(&f, &m["epsT"]), codes);
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
        assert!(j["map"]["note"].as_str().unwrap().contains("speed limit"));
        assert!(j["map"]["class"].is_object(), "{}", j["map"]);
        assert!(j["curve"]["eps"].is_object());
    }

    #[test]
    fn a_failing_part_leaves_the_others() {
        let scene = frost();
        let text = serde_json::to_string(&scene).unwrap();
        // A map range the core refuses: the map alone fails, named.
        let f = frame(&text, r#"{"points": 20, "mapN": 10, "mapMax": 2e6}"#).unwrap();
        let j: Json = serde_json::from_str(&f.json).unwrap();
        assert!(
            j["map"]["error"].as_str().unwrap().contains("max"),
            "{}",
            j["map"]
        );
        assert_eq!(j["errors"][0]["part"], "stick map");
        assert!(j["curve"]["eps"].is_object());
        assert!(j["family"]["curves"][0]["eps"].is_object());
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
            .map(|f| f.json.contains("\"part\":\"tidal\""))
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
        assert_eq!(parts.len(), 8, "{parts:?}");
        assert!(parts.contains(&"stick map") && parts.contains(&"tidal"));
        let eps = get(&f, &j["curve"]["eps"]);
        assert_eq!(j["curve"]["failed"], 2);
        assert!(eps[20].is_nan() && eps[60].is_nan() && eps[21].is_finite());
        assert!(j["clean"]["eps"].is_object());
        assert_eq!(
            j["critical"].as_array().unwrap().len(),
            1,
            "{}",
            j["critical"]
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
            serde_json::from_str::<Json>(&f.json).unwrap()["family"].clone()
        };
        let f = family(&Scene::default());
        assert_eq!(f["path"], "bulk.damping.time");
        let v: Vec<f64> = serde_json::from_value(f["values"].clone()).unwrap();
        let expected = [1e-5, 3e-5, 3e-4, 1e-3];
        assert!(
            v.iter()
                .zip(expected)
                .all(|(a, b)| (a / b - 1.0).abs() < 1e-12),
            "{v:?}"
        );
        assert_eq!(family(&frost())["path"], "layer.viscosity");
        assert_eq!(
            family(&frost())["isScene"],
            json!([false, true, false, false])
        );
    }
}
