//! The web page's frame and cards, from JSON text to the wire (`rime_core::wire`): the scene and
//! the view as the page sends them (errors name the field: `view.from: …`, `layer.viscosity: …`),
//! the core's frame with what only the page shows beside it ([`PageFrame`]), the records of the
//! downloads, the stick map's records on download and the ring card.
//!
//! Every part fails on its own: a part that errors is left out and its message is listed in
//! `errors` (`{part, message}`), the other parts are still computed. A speed on a curve whose ε_N
//! fails becomes a gap (NaN, status code [`FAILED`]), not a failed frame.

use super::frame::{Frame, Request, compute_with};
pub use super::json_path::{parse_scene, read_named};
use super::session::{ParamValue, tidal_card};
use super::tidal::TidalCard;
use super::{figures, records};
use crate::applications::tidal::TidalInput;
use crate::figure::Figure;
use crate::normal::memo::LayerMemo;
use crate::scene::params::PARAMETERS;
use crate::wire::{Wire, to_wire};
use crate::{Scene, Status, StickClass};
use alloc::collections::BTreeMap;
use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec::Vec;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use serde_json::Value as Json;

pub use super::frame::FAILED;

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

/// The keys of a view that are the page's own (the others are the core request's); `yLog` as
/// views were written before issue 36.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct PageKeys {
    #[serde(default)]
    tidal: Option<TidalInput>,
    #[serde(default, alias = "yLog")]
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

/// Parses a view; errors name the field (`view.from: ...`).
pub fn parse_view(text: &str) -> Result<View, String> {
    // Each part read from its own text, so that an error names the field in it.
    fn part<T: DeserializeOwned>(keys: serde_json::Map<String, Json>) -> Result<T, String> {
        let text = serde_json::to_string(&keys).map_err(|e| format!("view: {e}"))?;
        super::json_path::read(&text).map_err(|(path, message)| {
            if path.is_empty() {
                // The core's checks name their field first (`map_n: …`).
                format!("view.{message}")
            } else {
                format!("view.{path}: {message}")
            }
        })
    }
    let mut keys: serde_json::Map<String, Json> =
        serde_json::from_str(text).map_err(|e| format!("view: {e}"))?;
    let mut page = serde_json::Map::new();
    for k in [
        "tidal",
        "yLog",
        "y_log",
        "experiments",
        "pinned",
        "date",
        "records",
    ] {
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
    let page: PageKeys = part(page)?;
    let request: Request = part(keys)?;
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

/// The view of `view_json` and the core's request for `scene_json` seen through it.
pub fn prepare(scene_json: &str, view_json: &str) -> Result<(View, Request), String> {
    let scene = parse_scene(scene_json)?;
    let view = parse_view(view_json)?;
    let mut req = view.request.clone();
    req.scene = scene;
    Ok((view, req))
}

/// A frame as it crosses to the page: its wire form and, apart, its records.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct PageWire {
    /// The [`PageFrame`] in its wire form.
    pub wire: Wire,
    /// The records as JSON, `{curve, family, map: null, context: {curve, family, map}}` (the CSV of
    /// the downloads and their context lines), apart from the frame so that the page reads them
    /// only when a download asks; `null` when the view asked for none (`records: false`).
    pub records: String,
}

/// Computes the frame of `scene_json` as seen through `view_json`, with `memo` keeping the literal
/// layer reading's outcomes between frames. Fails only for a request that is not valid (scene or
/// view naming the field); a part that fails is listed in `errors` instead.
pub fn frame(scene_json: &str, view_json: &str, memo: &dyn LayerMemo) -> Result<PageWire, String> {
    let (view, req) = prepare(scene_json, view_json)?;
    let f = compute_with(&req, &|| false, memo).ok_or("frame: cancelled")?;
    page_wire(&view, &req, &f)
}

/// What crosses to the page besides the core's frame: the scene's values, the figures, the tidal
/// card and the status names. Its wire form is the page's frame.
#[derive(Serialize)]
pub struct PageFrame<'a> {
    /// The core's frame, field for field (its serde form).
    #[serde(flatten)]
    pub frame: &'a Frame,
    /// Every parameter's value by path.
    pub values: BTreeMap<&'static str, ParamValue>,
    /// The side of the stick map asked for.
    pub map_n: usize,
    /// The figure descriptions, built by the core for every surface.
    pub figures: Vec<Figure>,
    /// The tidal card, or `{"error": …}`.
    pub tidal: Tidal,
    /// The status names in code order ([`Status::ALL`]).
    pub status_names: [&'static str; 4],
}

/// The tidal card as it crosses: the card, or why there is none.
#[derive(Serialize)]
#[serde(untagged)]
pub enum Tidal {
    /// The card.
    Card(TidalCard),
    /// Why there is none.
    Error {
        /// The message, naming the field.
        error: String,
    },
}

/// The frame's records, the CSV of the downloads (see [`PageWire::records`]).
#[derive(Serialize)]
struct Records {
    curve: String,
    family: String,
    /// Formatted on download ([`map_records`]), never in the frame.
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

/// Every parameter's value (number, choice name, boolean, or `null` when inactive), by path.
fn values(scene: &Scene) -> BTreeMap<&'static str, ParamValue> {
    PARAMETERS
        .iter()
        .map(|p| {
            let v = scene.get(p.path).map_or(ParamValue::Inactive, Into::into);
            (p.path, v)
        })
        .collect()
}

/// The page's frame (wire, records) of the core's frame `f` of `req` seen through `view`.
pub fn page_wire(view: &View, req: &Request, f: &Frame) -> Result<PageWire, String> {
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
    // on download (`map_records`), not every frame.
    let records = view.records.then(|| {
        let ctx = |what: &str| records::context(f, what, version, &view.date);
        Records {
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
        }
    });
    let fig_view = figures::View {
        y_log: view.y_log,
        experiments: view.experiments,
        pinned,
    };
    let tidal = if view.fail_tidal {
        Err("failure forced for testing (tidal in view.fail)".to_string())
    } else {
        tidal_card(&req.scene, view.tidal)
    };
    let page = PageFrame {
        frame: f,
        values: values(&req.scene),
        map_n: req.map_n,
        figures: figures::frame_figures(f, &fig_view, version),
        tidal: tidal.map_or_else(|error| Tidal::Error { error }, Tidal::Card),
        status_names: Status::ALL.map(Status::name),
    };
    Ok(PageWire {
        wire: to_wire(&page).map_err(|e| e.to_string())?,
        records: serde_json::to_string(&records).map_err(|e| format!("records: {e}"))?,
    })
}

/// The stick map's records (`rime map --format csv`) from the frame's arrays: `g` (n speeds),
/// `eps_t` and class codes (n² each, row-major). Formatted only when the page downloads them:
/// 14 400 rows cost ~40 ms, too much for every frame.
pub fn map_records(g: &[f64], eps_t: &[f64], codes: &[u8]) -> Result<String, String> {
    let n = g.len();
    if eps_t.len() != n * n || codes.len() != n * n {
        return Err(format!(
            "mapRecords: epsT and class must hold n² = {} values (got {} and {})",
            n * n,
            eps_t.len(),
            codes.len()
        ));
    }
    let class = codes
        .iter()
        .map(|&c| {
            StickClass::ALL
                .get(usize::from(c))
                .copied()
                .ok_or_else(|| format!("mapRecords: unknown class code {c}"))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let map = crate::figure::sweep::StickMap {
        g: g.to_vec(),
        eps_n: Vec::new(),
        class,
        eps_t: eps_t.to_vec(),
        rhs_evaluations: 0,
    };
    Ok(records::map_csv(&map))
}

/// What the page's ring card sends (issue 24): τ, Ω or a planet and a distance, and the ε_N
/// chart's speed range `[from, to]` \[m/s\] for the ε_cr line.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RingRequest {
    tau: f64,
    omega: Option<f64>,
    planet_mass: Option<f64>,
    distance: Option<f64>,
    chart: (f64, f64),
    /// The grain sizes (issue 38): `one` (default), `to_5r`, `to_10r`.
    #[serde(default)]
    sizes: super::ring::CardSizeChoice,
}

/// The ring card as the page draws it: the core's card with the line's stroke by name.
#[derive(Serialize)]
pub struct RingPage {
    /// The card's verdict in words.
    pub verdict: &'static str,
    /// Whether the ring reaches an equilibrium.
    pub equilibrium: bool,
    /// The card's sentence.
    pub sentence: String,
    /// The printed rows.
    pub rows: Vec<super::ring::RingRow>,
    /// The ε_cr line.
    pub eps_cr_line: RingLine,
    /// Where the scene's curve meets the line, `[g, ε]`.
    pub meeting: Option<[f64; 2]>,
    /// The ring's mean impact speed.
    pub impact_marker: crate::figure::Marker,
    /// `rime ring`'s prediction record.
    pub record: crate::applications::ring::RingRecord,
    /// The ring's kinematic viscosity (of the distribution when the card has one).
    pub viscosity: crate::applications::ring_sizes::Viscosity,
    /// The ring of many sizes, when the card has one.
    pub sizes: Option<crate::applications::ring_sizes::SizeRingRecord>,
}

/// A chart line as the page draws it (`stroke` by name; `color` an index into the palette's series).
#[derive(Serialize)]
pub struct RingLine {
    /// Legend text.
    pub name: String,
    /// Short legend text.
    pub short: String,
    /// `[x, y]` pairs.
    pub points: Vec<(f64, f64)>,
    /// Palette index.
    pub color: usize,
    /// `solid`, `dashed`, ….
    pub stroke: &'static str,
}

/// The ring card for `scene` (JSON) and `input` (JSON `{tau, omega | planet_mass + distance,
/// chart: [from, to], sizes?}`), built by [`super::ring::ring_card_with_sizes`]. Errors name the field
/// (`ring.tau: …`).
pub fn ring_page(scene: &str, input: &str) -> Result<RingPage, String> {
    use crate::applications::ring::{Orbit, RingInput};
    let scene = parse_scene(scene)?;
    let req: RingRequest = read_named(input, "ring", true)?;
    let orbit = match (req.omega, req.planet_mass, req.distance) {
        (Some(o), None, None) => Orbit::Omega(o),
        (None, Some(m), Some(d)) => Orbit::Planet {
            planet_mass: m,
            distance: d,
        },
        _ => return Err("ring.omega: give omega, or planet_mass and distance".into()),
    };
    let input = RingInput {
        tau: req.tau,
        orbit,
        damping_set_for_radius: None,
    };
    let sizes = req.sizes.sizes(scene.grains.radius_1);
    let card = super::ring::ring_card_with_sizes(&scene, &input, sizes.as_ref(), req.chart)
        .map_err(|e| format!("ring.{e}"))?;
    let line = card.eps_cr_line;
    Ok(RingPage {
        verdict: card.verdict,
        equilibrium: card.equilibrium,
        sentence: card.sentence,
        rows: card.rows,
        eps_cr_line: RingLine {
            name: line.name,
            short: line.short,
            points: line.points,
            color: line.color,
            stroke: line.stroke.name(),
        },
        meeting: card.meeting.map(|(g, e)| [g, e]),
        impact_marker: card.impact_marker,
        record: card.record,
        viscosity: card.viscosity,
        sizes: card.sizes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::explorer::range::auto_map_range;
    use crate::normal::memo::NoMemo;
    use crate::{Accuracy, Contact};
    use alloc::vec;
    use serde_json::json;

    /// A frame in the page's three parts.
    #[derive(Debug)]
    struct Frame {
        json: String,
        numbers: Vec<f64>,
        codes: Vec<u8>,
        records: String,
    }

    fn frame(scene: &str, view: &str) -> Result<Frame, String> {
        let p = super::frame(scene, view, &NoMemo)?;
        Ok(Frame {
            json: p.wire.json,
            numbers: p.wire.numbers,
            codes: p.wire.codes,
            records: p.records,
        })
    }

    fn get<'a>(f: &'a Frame, j: &Json) -> &'a [f64] {
        let at = j["$f64"][0].as_u64().unwrap() as usize;
        let len = j["$f64"][1].as_u64().unwrap() as usize;
        &f.numbers[at..at + len]
    }

    fn frost() -> Scene {
        crate::Preset::IceFrost.scene()
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
        let mut req = Request::new(scene, Accuracy::Precise);
        req.points = 40;
        req.map_n = 8;
        req.overlays =
            vec![crate::explorer::frame::Overlay::parse("model:muller_poschel2011").unwrap()];
        let core = crate::explorer::frame::compute(&req, &|| false).unwrap();
        let expected = serde_json::to_value(&core).unwrap();
        let text = serde_json::to_string(&scene).unwrap();
        let page = read(
            &frame(
                &text,
                r#"{"points": 40, "map_n": 8, "overlays": ["model:muller_poschel2011"]}"#,
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
        let f = frame(&text, r#"{"points": 50, "map_n": 20}"#).unwrap();
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
        let view =
            r#"{"points": 30, "map_n": 6, "from": 1e-6, "to": 1, "y_log": true, "date": "D"}"#;
        let f = frame(&text, view).unwrap();
        let j: Json = serde_json::from_str(&f.json).unwrap();
        let records: Json = serde_json::from_str(&f.records).unwrap();
        // The records are the CSV `rime curve` prints: built here from the core's normal results.
        let contact = Contact::new(&scene).unwrap();
        let mut g = vec![0.0; 30];
        crate::figure::sweep::log_space(1e-6, 1.0, &mut g);
        let points: Vec<_> = g
            .iter()
            .map(|&gi| Some(contact.normal(gi, Accuracy::Precise).unwrap()))
            .collect();
        assert_eq!(
            records["curve"],
            crate::explorer::records::curve_csv(&g, &points)
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
        let csv = map_records(get(&f, &m["map"]["g"]), get(&f, &m["map"]["eps_t"]), codes);
        let mut req = Request::new(scene, Accuracy::Precise);
        req.speeds = Some((1e-6, 1.0));
        req.points = 30;
        req.map_n = 6;
        let core = crate::explorer::frame::compute(&req, &|| false).unwrap();
        assert_eq!(
            csv.unwrap(),
            crate::explorer::records::frame_map_csv(&core).unwrap()
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
        let with = frame(&text, r#"{"points": 30, "map_n": 6, "date": "D"}"#).unwrap();
        let without = frame(
            &text,
            r#"{"points": 30, "map_n": 6, "date": "D", "records": false}"#,
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
        let f = frame(&text, r#"{"points": 20, "map_n": 10}"#).unwrap();
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
        let f = frame(&text, r#"{"points": 20, "map_n": 10, "map_max": 2e6}"#).unwrap();
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
            frame(&text, r#"{"map_n": 1}"#)
                .unwrap_err()
                .starts_with("view.map_n")
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
            r#"{"points": 80, "map_n": 10, "fail": ["curve", "map", "marker", "tidal", "family"]}"#,
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
            r#"{"points": 20, "map_n": 4, "overlays": ["atlas:bridges1984", "model:muller_poschel2011"]}"#,
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
            let f = frame(&text, r#"{"points": 10, "map_n": 4}"#).unwrap();
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
        let f = frame(&text, r#"{"points": 12, "map_n": 4, "date": "D"}"#).unwrap();
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

    #[test]
    fn issue_36_an_old_links_view_still_loads() {
        // A view written before issue 36 (its keys camelCase, as the page wrote them) loads as
        // the snake_case view the page writes now, to the same frame.
        let text = serde_json::to_string(&frost()).unwrap();
        let old = r#"{"accuracy": "balanced", "from": 1e-6, "to": 1, "points": 20, "mapN": 6,
            "mapMax": 0.5, "yLog": true, "experiments": false, "family": true,
            "overlays": ["atlas:bridges1984"], "date": "D"}"#;
        let (view, req) = prepare(&text, old).unwrap();
        assert_eq!((req.map_n, req.map_max, req.points), (6, Some(0.5), 20));
        assert_eq!(req.speeds, Some((1e-6, 1.0)));
        assert_eq!(req.accuracy, Accuracy::Balanced);
        assert!(view.y_log && !view.experiments);
        let snake = old
            .replace("mapN", "map_n")
            .replace("mapMax", "map_max")
            .replace("yLog", "y_log");
        let (view2, req2) = prepare(&text, &snake).unwrap();
        assert_eq!((req2.map_n, req2.map_max), (6, Some(0.5)));
        assert!(view2.y_log);
        let a = frame(&text, old).unwrap();
        let b = frame(&text, &snake).unwrap();
        assert_eq!((&a.json, &a.codes), (&b.json, &b.codes));
    }

    #[test]
    fn issue_24_the_ring_card_is_the_cores_and_bad_input_names_the_field() {
        let scene = serde_json::to_string(&crate::Preset::Ice.scene()).unwrap();
        let input = r#"{"tau": 0.5, "omega": 1.3143527e-4, "chart": [1e-7, 1.0]}"#;
        let card = serde_json::to_value(ring_page(&scene, input).unwrap()).unwrap();
        let core = crate::explorer::ring::ring_card(
            &crate::Preset::Ice.scene(),
            &crate::applications::ring::RingInput {
                tau: 0.5,
                orbit: crate::applications::ring::Orbit::Omega(1.3143527e-4),
                damping_set_for_radius: None,
            },
            (1e-7, 1.0),
        )
        .unwrap();
        assert_eq!(card["sentence"], core.sentence);
        assert_eq!(card["verdict"], "equilibrium at the monolayer floor");
        assert_eq!(card["equilibrium"], true);
        assert_eq!(card["rows"][0]["text"], core.rows[0].text);
        assert_eq!(
            card["record"]["rough"]["velocity_dispersion"],
            core.record.rough.velocity_dispersion
        );
        assert_eq!(card["eps_cr_line"]["stroke"], "dashed");
        let keys = |j: &Json| {
            let mut k: Vec<String> = j.as_object().unwrap().keys().cloned().collect();
            k.sort();
            k
        };
        assert_eq!(
            keys(&card),
            [
                "eps_cr_line",
                "equilibrium",
                "impact_marker",
                "meeting",
                "record",
                "rows",
                "sentence",
                "sizes",
                "verdict",
                "viscosity"
            ]
        );
        assert_eq!(keys(&card["rows"][0]), ["label", "text"]);
        assert_eq!(
            keys(&card["eps_cr_line"]),
            ["color", "name", "points", "short", "stroke"]
        );
        assert_eq!(
            keys(&card["impact_marker"]),
            ["color", "label", "short", "x"]
        );
        // Points are [x, y] pairs.
        assert_eq!(
            card["eps_cr_line"]["points"][0].as_array().map(Vec::len),
            Some(2)
        );
        assert!(card["meeting"].is_null() || card["meeting"].as_array().map(Vec::len) == Some(2));
        for (bad, field) in [
            (
                r#"{"tau": 0, "omega": 1e-4, "chart": [1e-7, 1]}"#,
                "ring.tau:",
            ),
            (r#"{"tau": 0.5, "chart": [1e-7, 1]}"#, "ring.omega:"),
            (
                r#"{"tau": 0.5, "omega": 1e-4, "chart": [1, 0.1]}"#,
                "ring.chart:",
            ),
            (r#"{"tau": 0.5, "omega": 1e-4}"#, "ring:"),
            (
                r#"{"tau": "x", "omega": 1e-4, "chart": [1e-7, 1]}"#,
                "ring.tau:",
            ),
        ] {
            let e = ring_page(&scene, bad).err().unwrap();
            assert!(e.starts_with(field), "{bad}: {e}");
        }
    }

    /// Issue 38: the page's card takes the core's size choices by name; one size has no `sizes`,
    /// `to_5r` the core's distribution from the scene's radius; an unknown name is refused naming
    /// `ring.sizes`.
    #[test]
    fn issue_38_the_page_card_takes_the_size_choice() {
        let scene = serde_json::to_string(&crate::Preset::Ice.scene()).unwrap();
        let one = serde_json::to_value(
            ring_page(
                &scene,
                r#"{"tau": 0.5, "omega": 1.3143527e-4, "chart": [1e-7, 1.0]}"#,
            )
            .unwrap(),
        )
        .unwrap();
        assert!(one["sizes"].is_null());
        // The page offers the choices from the catalogue (`ringSizes`), by the names it sends.
        assert_eq!(crate::explorer::catalogue::ring_sizes()[1].name, "to_5r");
        let many = serde_json::to_value(
            ring_page(
                &scene,
                r#"{"tau": 0.5, "omega": 1.3143527e-4, "chart": [1e-7, 1.0], "sizes": "to_5r"}"#,
            )
            .unwrap(),
        )
        .unwrap();
        let r = crate::Preset::Ice.scene().grains.radius_1;
        let bins = many["sizes"]["size_bins"].as_array().unwrap();
        assert_eq!(bins.len(), 3);
        assert_eq!(bins[0]["radius_min"], r);
        assert_eq!(many["viscosity"], many["sizes"]["viscosity"]);
        let e = ring_page(
            &scene,
            r#"{"tau": 0.5, "omega": 1e-4, "chart": [1e-7, 1], "sizes": "huge"}"#,
        )
        .err()
        .unwrap();
        assert!(e.starts_with("ring.sizes:"), "{e}");
    }
}
