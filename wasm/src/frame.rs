//! One update of the web page in one call: a whole frame (curve, family, clean-surface curve,
//! critical speeds, stick map, warnings, tidal appendix) computed from a scene and a view.
//!
//! Every part fails on its own: a part that errors is left out and its message is listed in
//! `errors` (`{part, message}`), the other parts are still computed. A speed on a curve whose ε_N
//! fails becomes a gap (NaN, status code [`FAILED`]), not a failed frame. The numbers are packed into
//! two flat arrays (`f64` and `u8`); the JSON gives each array as `{"at": offset, "len": n}` into them.

use crate::explorer::{
    MAX_MAP_SIDE, STATUSES, class_code, parse_accuracy, parse_scene, speeds, status_code,
};
use rime_core::explorer::range::auto_map_range;
use rime_core::params::{PARAMETERS, Value};
use rime_core::sweep::StickMap;
use rime_core::tidal::{PAPER_QUOTED, TidalInput, tidal};
use rime_core::{
    Accuracy, AdhesionModulus, Contact, ContactEnd, Damping, DampingFormula, LayerReading, Scene,
    Status,
};
use serde::Deserialize;
use serde_json::{Value as Json, json};

/// Status code of a speed whose ε_N could not be computed (a gap on the curve).
pub const FAILED: u8 = u8::MAX;

fn default_accuracy() -> String {
    "fast".into()
}
fn default_from() -> f64 {
    1e-7
}
fn default_to() -> f64 {
    10.0
}
fn default_points() -> usize {
    240
}
fn default_map_n() -> usize {
    120
}
fn default_true() -> bool {
    true
}

/// What the page shows of a scene: accuracy, speed range, map range and the tidal input.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "camelCase")]
pub struct View {
    /// `fast`, `balanced`, `precise` or a tolerance.
    #[serde(default = "default_accuracy")]
    pub accuracy: String,
    /// Lowest speed of the ε_N chart \[m/s\].
    #[serde(default = "default_from")]
    pub from: f64,
    /// Highest speed of the ε_N chart \[m/s\].
    #[serde(default = "default_to")]
    pub to: f64,
    /// Points per curve.
    #[serde(default = "default_points")]
    pub points: usize,
    /// Upper end of the stick-map axes \[m/s\]; `null` for the core's automatic range.
    #[serde(default)]
    pub map_max: Option<f64>,
    /// Stick-map side (`map_n²` cells).
    #[serde(default = "default_map_n")]
    pub map_n: usize,
    /// Whether to compute the family of curves.
    #[serde(default = "default_true")]
    pub family: bool,
    /// The appendix input; `null` for the paper's example with the scene's grains.
    #[serde(default)]
    pub tidal: Option<TidalInput>,
    /// Parts to fail on purpose, for testing the page's failure handling (see [`FORCIBLE`]).
    #[serde(default)]
    pub fail: Vec<String>,
}

/// The parts a view can fail on purpose (`curve` fails every 40th speed, a gap; the others whole).
pub const FORCIBLE: [&str; 5] = ["curve", "family", "marker", "map", "tidal"];

fn forced(part: &str) -> String {
    format!("failure forced for testing ({part} in view.fail)")
}

impl Default for View {
    fn default() -> Self {
        View {
            accuracy: default_accuracy(),
            from: default_from(),
            to: default_to(),
            points: default_points(),
            map_max: None,
            map_n: default_map_n(),
            family: true,
            tidal: None,
            fail: Vec::new(),
        }
    }
}

/// Parses a view; errors name the field (`view.from: ...`).
pub fn parse_view(text: &str) -> Result<View, String> {
    let de = &mut serde_json::Deserializer::from_str(text);
    serde_path_to_error::deserialize(de).map_err(|e| {
        let path = e.path().to_string();
        let path = if path == "." || path.is_empty() {
            "view".to_string()
        } else {
            format!("view.{path}")
        };
        format!("{path}: {}", e.into_inner())
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

/// ε_N and statuses along `g`; failed speeds are gaps (NaN, [`FAILED`]) and the first failure's
/// message is returned with their count.
fn curve_with_gaps(
    contact: &Contact,
    g: &[f64],
    accuracy: Accuracy,
    force: bool,
) -> (Vec<f64>, Vec<u8>, usize, Option<String>) {
    let mut eps = Vec::with_capacity(g.len());
    let mut status = Vec::with_capacity(g.len());
    let (mut failed, mut first) = (0, None);
    for (i, &gi) in g.iter().enumerate() {
        let r = if force && i % 40 == 20 {
            Err(forced("curve"))
        } else {
            contact.normal(gi, accuracy).map_err(|e| e.to_string())
        };
        match r {
            Ok(r) => {
                eps.push(r.eps);
                status.push(status_code(r.status));
            }
            Err(e) => {
                eps.push(f64::NAN);
                status.push(FAILED);
                failed += 1;
                first.get_or_insert_with(|| format!("at g_N = {gi:.4e} m/s: {e}"));
            }
        }
    }
    (eps, status, failed, first)
}

/// A curve part as JSON, its gaps reported in `errors` under `part`.
fn curve_part(
    pack: &mut Pack,
    errors: &mut Errors,
    part: &str,
    contact: &Contact,
    g: &[f64],
    accuracy: Accuracy,
    force: bool,
) -> (Json, Vec<u8>) {
    let (eps, status, failed, first) = curve_with_gaps(contact, g, accuracy, force);
    if let Some(msg) = &first {
        errors.push(
            part,
            format!("{failed} of {} speeds failed (gaps), first {msg}", g.len()),
        );
    }
    let j = json!({"eps": pack.f(&eps), "status": pack.u(&status), "failed": failed});
    (j, status)
}

/// The swept parameter of the family: η* with a layer, γ with adhesion, else the damping time A.
/// Returns `(path, symbol, unit, values)`.
pub fn family_spec(
    scene: &Scene,
    damping_time: Option<f64>,
) -> Option<(&'static str, &'static str, &'static str, Vec<f64>)> {
    if scene.layer.is_some() {
        return Some((
            "layer.viscosity",
            "η*",
            "Pa s",
            vec![500.0, 1000.0, 2000.0, 5000.0],
        ));
    }
    if scene.adhesion.is_some() {
        return Some((
            "adhesion.surface_energy",
            "γ",
            "J/m²",
            vec![0.05, 0.1, 0.2, 0.5],
        ));
    }
    let a = damping_time.filter(|a| a.is_finite() && *a > 0.0)?;
    let round3 = |v: f64| format!("{v:.2e}").parse::<f64>().unwrap_or(v);
    Some((
        "bulk.damping.time",
        "A",
        "s",
        [a / 10.0, a / 3.0, a * 3.0, a * 10.0]
            .into_iter()
            .map(round3)
            .collect(),
    ))
}

/// The impact speed below which the grains stick, by bisection in log speed on the status the core
/// reports (`None` when they never stick in [1e-12, 1e2] m/s, or always do).
pub fn stick_threshold(contact: &Contact, accuracy: Accuracy) -> Result<Option<f64>, String> {
    let stuck = |g: f64| -> Result<bool, String> {
        let r = contact.normal(g, accuracy).map_err(|e| e.to_string())?;
        Ok(matches!(
            r.status,
            Status::StuckInLayer | Status::StuckByAdhesion
        ))
    };
    let (mut lo, mut hi) = (1e-12_f64, 1e2_f64);
    if !stuck(lo)? || stuck(hi)? {
        return Ok(None);
    }
    for _ in 0..60 {
        let mid = (lo * hi).sqrt();
        if stuck(mid)? {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi / lo < 1.0 + 1e-12 {
            break;
        }
    }
    Ok(Some(hi))
}

/// Warnings about the scene: overdamped collisions among the speeds `g` (statuses `status`), and
/// options that deviate from (or expose inconsistencies of) the paper.
fn warnings(scene: &Scene, status: &[u8], damping_time: Option<f64>) -> Vec<String> {
    let mut w = Vec::new();
    let overdamped = status_code(Status::Overdamped);
    let over = status.iter().filter(|s| **s == overdamped).count();
    if over > 0 {
        let a = damping_time.map_or("?".to_string(), |a| format!("{a:.3e}"));
        w.push(format!(
            "overdamped: ε_N < 1e-9 over {} of the plotted range (A = {a} s); Eq. (4) never \
             sticks, the rebound is negligible",
            if over == status.len() { "all" } else { "part" }
        ));
    }
    if let Damping::Viscosities(v) = scene.bulk.damping
        && v.formula == DampingFormula::AsPrinted
    {
        w.push(
            "A formula as printed: the paper omits the factor (1−2ν) of Brilliantov et al.".into(),
        );
    }
    if scene.contact_end == ContactEnd::ZeroOverlap {
        w.push("contact end zero_overlap: Eq. (5) read literally, a tensile viscoelastic force acts while separating".into());
    }
    if scene
        .layer
        .is_some_and(|l| l.reading == LayerReading::Literal)
    {
        w.push("Eq. (8) literal reading: threshold ≈ 2 g_s and ε_N can exceed the clean value, contradicting the paper's text".into());
    }
    if scene
        .adhesion
        .is_some_and(|a| a.modulus == AdhesionModulus::Consistent)
    {
        w.push(
            "adhesion modulus consistent: E = Y/(2(1−ν²)) instead of the printed Y/(1−ν²)".into(),
        );
    }
    w
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

fn tidal_part(scene: &Scene, input: Option<TidalInput>) -> Result<Json, String> {
    let input = input.unwrap_or_else(|| TidalInput {
        radius: scene.grains.radius_1,
        density: scene.grains.density,
        surface_energy: scene
            .adhesion
            .map_or(TidalInput::default().surface_energy, |a| a.surface_energy),
        ..TidalInput::default()
    });
    let r = tidal(&input).map_err(|e| format!("tidal.{e}"))?;
    let q = PAPER_QUOTED;
    Ok(json!({
        "input": input,
        "result": r,
        "paper": {"delta_f": q.delta_f, "surface_force": q.surface_force, "d_roche": q.d_roche,
                  "d_min": q.d_min, "r_max": q.r_max},
    }))
}

/// Computes the frame of `scene` as seen through `view`. Fails only for a request that is not
/// valid (scene or view naming the field); a part that fails is listed in `errors` instead.
pub fn frame(scene_json: &str, view_json: &str) -> Result<Frame, String> {
    let scene = parse_scene(scene_json)?;
    let view = parse_view(view_json)?;
    let accuracy = parse_accuracy(&view.accuracy)?;
    let g = speeds(view.from, view.to, view.points).map_err(|e| format!("view.{e}"))?;
    if !(2..=MAX_MAP_SIDE).contains(&view.map_n) {
        return Err(format!(
            "view.mapN: must lie in [2, {MAX_MAP_SIDE}] (got {})",
            view.map_n
        ));
    }
    if let Some(bad) = view.fail.iter().find(|p| !FORCIBLE.contains(&p.as_str())) {
        return Err(format!(
            "view.fail: unknown part {bad:?} (one of {})",
            FORCIBLE.join(", ")
        ));
    }
    let force = |part: &str| view.fail.iter().any(|p| p == part);
    let mut pack = Pack::default();
    let mut errors = Errors(Vec::new());
    let mut out = serde_json::Map::new();
    out.insert("values".into(), values(&scene));
    out.insert("g".into(), pack.f(&g));

    let contact = Contact::new(&scene).map_err(|e| e.to_string());
    let damping_time = contact.as_ref().ok().map(|c| c.damping_time);
    match &contact {
        Err(e) => {
            // Without a contact nothing but the tidal appendix can be drawn.
            errors.push("scene", e.clone());
            for k in ["curve", "clean", "family", "map"] {
                out.insert(k.into(), Json::Null);
            }
            out.insert("critical".into(), json!([]));
            out.insert("warnings".into(), json!([]));
        }
        Ok(contact) => {
            let (curve, status) = curve_part(
                &mut pack,
                &mut errors,
                "curve",
                contact,
                &g,
                accuracy,
                force("curve"),
            );
            out.insert("curve".into(), curve);

            // The clean surface: the scene without layer and adhesion (drawn only with either).
            let clean = if scene.layer.is_some() || scene.adhesion.is_some() {
                let s = Scene {
                    layer: None,
                    adhesion: None,
                    ..scene
                };
                match Contact::new(&s) {
                    Ok(c) => curve_part(&mut pack, &mut errors, "clean", &c, &g, accuracy, false).0,
                    Err(e) => {
                        errors.push("clean", e.to_string());
                        Json::Null
                    }
                }
            } else {
                Json::Null
            };
            out.insert("clean".into(), clean);

            let family = match family_spec(&scene, damping_time).filter(|_| view.family) {
                None => Json::Null,
                Some((path, sym, unit, vals)) => {
                    let mut curves = Vec::new();
                    for &v in &vals {
                        let part = format!("family {sym} = {v}");
                        let mut s = scene;
                        let c = if force("family") {
                            Err(forced("family"))
                        } else {
                            s.set_number(path, v)
                                .and_then(|()| Contact::new(&s))
                                .map_err(|e| e.to_string())
                        };
                        match c {
                            Ok(c) => curves.push(
                                curve_part(&mut pack, &mut errors, &part, &c, &g, accuracy, false)
                                    .0,
                            ),
                            Err(e) => {
                                errors.push(&part, e);
                                curves.push(Json::Null);
                            }
                        }
                    }
                    json!({"path": path, "sym": sym, "unit": unit, "values": vals, "curves": curves})
                }
            };
            out.insert("family".into(), family);

            let mut critical = Vec::new();
            if let Some(l) = &contact.layer {
                critical.push(json!({"key": "layer", "label": "g_s layer (Eq. (10))", "value": l.critical_velocity}));
            }
            if let Some(a) = &contact.adhesion {
                critical.push(json!({"key": "adhesion", "label": "g_s adhesion (Eq. (15))", "value": a.critical_velocity}));
            }
            let threshold = if force("marker") {
                Err(forced("marker"))
            } else {
                stick_threshold(contact, accuracy)
            };
            match threshold {
                Ok(Some(t)) => {
                    critical.push(json!({"key": "stick", "label": "sticks below", "value": t}))
                }
                Ok(None) => {}
                Err(e) => errors.push("marker \"sticks below\"", e),
            }
            out.insert("critical".into(), Json::from(critical));
            out.insert(
                "warnings".into(),
                Json::from(warnings(&scene, &status, damping_time)),
            );

            let map = if contact.friction.is_none() {
                Json::Null
            } else {
                let auto = auto_map_range(contact);
                let (max, note) = match view.map_max {
                    Some(m) => (m, None),
                    None => (auto.max, auto.note()),
                };
                let m = crate::explorer::map_speeds(max, view.map_n).and_then(|_| {
                    if force("map") {
                        return Err(forced("map"));
                    }
                    StickMap::new(contact, max, view.map_n, accuracy).map_err(|e| e.to_string())
                });
                match m {
                    Ok(m) => {
                        let class: Vec<u8> = m.class.iter().map(|c| class_code(*c)).collect();
                        json!({"n": view.map_n, "max": max, "auto": view.map_max.is_none(), "note": note,
                               "g": pack.f(&m.g), "epsN": pack.f(&m.eps_n), "epsT": pack.f(&m.eps_t),
                               "class": pack.u(&class)})
                    }
                    Err(e) => {
                        errors.push("stick map", e.clone());
                        json!({"n": view.map_n, "max": max, "auto": view.map_max.is_none(), "note": note,
                               "error": e})
                    }
                }
            };
            out.insert("map".into(), map);
        }
    }
    out.insert("friction".into(), Json::from(scene.friction.is_some()));
    out.insert(
        "tidal".into(),
        match if force("tidal") {
            Err(forced("tidal"))
        } else {
            tidal_part(&scene, view.tidal)
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
        Json::from(STATUSES.map(Status::name).to_vec()),
    );
    out.insert("errors".into(), Json::from(errors.0));
    Ok(Frame {
        json: Json::Object(out).to_string(),
        numbers: pack.numbers,
        codes: pack.codes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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
            assert_eq!(contact.normal(*gi, Accuracy::Fast).unwrap().eps, *e);
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
    fn family_follows_the_effects() {
        let s = Scene::default();
        let (path, _, _, v) = family_spec(&s, Some(1e-4)).unwrap();
        assert_eq!(path, "bulk.damping.time");
        assert_eq!(v, vec![1e-5, 3.33e-5, 3e-4, 1e-3]);
        assert_eq!(family_spec(&frost(), None).unwrap().0, "layer.viscosity");
        assert!(family_spec(&s, None).is_none());
    }
}
