//! The host-testable part of the binding: a [`Explorer`] holding a scene, with every operation the
//! page needs as a plain Rust method returning `Result<_, String>` (the string names the field).
//!
//! No physics here: every number comes from `rime-core`; this module only validates arguments,
//! converts between JSON/text and core types, and packs results into flat arrays.

use rime_core::params::{Kind, PARAMETERS, Value};
use rime_core::sweep::{StickMap, linear_space, log_space};
use rime_core::tidal::{PAPER_QUOTED, TidalInput, tidal};
use rime_core::{
    Accuracy, AdhesionModulus, Contact, ContactEnd, Damping, DampingFormula, LayerReading, Preset,
    Scene, Status, StickClass,
};
use serde_json::{Value as Json, json};

/// Largest number of points on one curve.
pub const MAX_CURVE_POINTS: usize = 20_000;
/// Largest stick-map side (the map has `n²` cells).
pub const MAX_MAP_SIDE: usize = 1_000;
/// Largest number of curves in one family.
pub const MAX_FAMILY: usize = 32;
/// Largest accepted scene JSON text, in bytes.
pub const MAX_SCENE_BYTES: usize = 1 << 20;
/// Smallest and largest impact speeds the core accepts \[m/s\].
pub const SPEED_RANGE: (f64, f64) = (1e-300, 1e6);

/// The statuses in code order: `statuses()[i]` is the code of [`Status`] `STATUSES[i]`.
pub const STATUSES: [Status; 4] = [
    Status::Rebound,
    Status::StuckInLayer,
    Status::StuckByAdhesion,
    Status::Overdamped,
];

/// The code of a status (its index in [`STATUSES`]).
pub fn status_code(s: Status) -> u8 {
    match s {
        Status::Rebound => 0,
        Status::StuckInLayer => 1,
        Status::StuckByAdhesion => 2,
        Status::Overdamped => 3,
    }
}

/// The code of a stick class (its index in [`StickClass::ALL`]).
pub fn class_code(c: StickClass) -> u8 {
    StickClass::ALL
        .iter()
        .position(|x| *x == c)
        .map_or(u8::MAX, |i| i as u8)
}

fn core_err(e: rime_core::Error) -> String {
    e.to_string()
}

fn check_speed(field: &str, g: f64) -> Result<f64, String> {
    if g.is_finite() && g >= SPEED_RANGE.0 && g <= SPEED_RANGE.1 {
        Ok(g)
    } else {
        Err(format!("{field}: speed must lie in (0, 1e6] m/s (got {g})"))
    }
}

fn check_count(field: &str, n: usize, lo: usize, hi: usize) -> Result<usize, String> {
    if (lo..=hi).contains(&n) {
        Ok(n)
    } else {
        Err(format!("{field}: must lie in [{lo}, {hi}] (got {n})"))
    }
}

/// Parses an accuracy level (`fast`, `balanced`, `precise` or a tolerance).
pub fn parse_accuracy(text: &str) -> Result<Accuracy, String> {
    Accuracy::parse(text).map_err(core_err)
}

/// Parses scene JSON; errors name the JSON path (`layer.viscosity: ...`).
pub fn parse_scene(text: &str) -> Result<Scene, String> {
    if text.len() > MAX_SCENE_BYTES {
        return Err(format!(
            "scene: {} bytes; a scene is at most {MAX_SCENE_BYTES} bytes",
            text.len()
        ));
    }
    let de = &mut serde_json::Deserializer::from_str(text);
    let scene: Scene = serde_path_to_error::deserialize(de).map_err(|e| {
        let path = e.path().to_string();
        let path = if path == "." || path.is_empty() {
            "scene".to_string()
        } else {
            path
        };
        format!("{path}: {}", e.into_inner())
    })?;
    scene.validate().map_err(core_err)?;
    Ok(scene)
}

/// Log-spaced speeds from `from` to `to` inclusive (validated).
pub fn speeds(from: f64, to: f64, n: usize) -> Result<Vec<f64>, String> {
    let from = check_speed("from", from)?;
    let to = check_speed("to", to)?;
    if from >= to {
        return Err(format!("to: must be greater than from ({to} <= {from})"));
    }
    let n = check_count("n", n, 2, MAX_CURVE_POINTS)?;
    let mut g = vec![0.0; n];
    log_space(from, to, &mut g);
    Ok(g)
}

/// Evenly spaced speeds from 0 to `max` inclusive (the stick-map grid).
pub fn map_speeds(max: f64, n: usize) -> Result<Vec<f64>, String> {
    let max = check_speed("max", max)?;
    let n = check_count("n", n, 2, MAX_MAP_SIDE)?;
    let mut g = vec![0.0; n];
    linear_space(max, &mut g);
    Ok(g)
}

/// ε_N and status codes along a curve.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveData {
    /// The speeds \[m/s\].
    pub g: Vec<f64>,
    /// ε_N at each speed.
    pub eps: Vec<f64>,
    /// Status code at each speed (see [`STATUSES`]).
    pub status: Vec<u8>,
}

/// A stick map in flat arrays.
#[derive(Debug, Clone, PartialEq)]
pub struct MapData {
    /// Grid speeds, 0 to max \[m/s\].
    pub g: Vec<f64>,
    /// ε_N at the grid speeds.
    pub eps_n: Vec<f64>,
    /// Row-major class codes (`class[i*n+j]` at g_N = g\[i\], g_T = g\[j\]).
    pub class: Vec<u8>,
    /// Row-major ε_T.
    pub eps_t: Vec<f64>,
}

fn curve_for(
    scene: &Scene,
    from: f64,
    to: f64,
    n: usize,
    accuracy: Accuracy,
) -> Result<CurveData, String> {
    let g = speeds(from, to, n)?;
    let contact = Contact::new(scene).map_err(core_err)?;
    let mut eps = Vec::with_capacity(n);
    let mut status = Vec::with_capacity(n);
    for &gi in &g {
        let r = contact.normal(gi, accuracy).map_err(core_err)?;
        eps.push(r.eps);
        status.push(status_code(r.status));
    }
    Ok(CurveData { g, eps, status })
}

fn choice_name(v: Value) -> Option<&'static str> {
    match v {
        Value::Choice(c) => Some(c),
        _ => None,
    }
}

fn is_stuck(s: Status) -> bool {
    matches!(s, Status::StuckInLayer | Status::StuckByAdhesion)
}

/// A scene being explored.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Explorer {
    /// The current scene (always valid).
    pub scene: Scene,
}

impl Explorer {
    /// The default (`ice`) scene.
    pub fn new() -> Explorer {
        Explorer::default()
    }

    /// A scene from JSON.
    pub fn from_json(text: &str) -> Result<Explorer, String> {
        Ok(Explorer {
            scene: parse_scene(text)?,
        })
    }

    /// Replaces the scene from JSON; on error the scene is unchanged.
    pub fn set_json(&mut self, text: &str) -> Result<(), String> {
        self.scene = parse_scene(text)?;
        Ok(())
    }

    /// The scene as compact JSON (numbers round-trip exactly).
    pub fn to_json(&self) -> Result<String, String> {
        serde_json::to_string(&self.scene).map_err(|e| format!("scene: {e}"))
    }

    /// Sets a parameter from text (number with optional unit, choice, `on`/`off`); on error the
    /// scene is unchanged and the message names the field.
    pub fn set(&mut self, path: &str, text: &str) -> Result<(), String> {
        self.scene.set(path, text).map_err(|e| match e {
            rime_core::Error::UnknownParameter => format!("{path}: unknown parameter"),
            e => core_err(e),
        })
    }

    /// Sets a numeric parameter directly; same rules as [`Explorer::set`].
    pub fn set_number(&mut self, path: &str, value: f64) -> Result<(), String> {
        self.scene.set_number(path, value).map_err(|e| match e {
            rime_core::Error::UnknownParameter => format!("{path}: unknown parameter"),
            e => core_err(e),
        })
    }

    /// A parameter's value as JSON: a number, a choice name, a boolean for effects, `null` when
    /// inactive.
    pub fn get(&self, path: &str) -> Result<String, String> {
        let v = self.scene.get(path).map_err(|e| match e {
            rime_core::Error::UnknownParameter => format!("{path}: unknown parameter"),
            e => core_err(e),
        })?;
        Ok(match v {
            Value::Number(x) => Json::from(x),
            Value::Choice(c) => Json::from(c),
            Value::Enabled(b) => Json::from(b),
            Value::Inactive => Json::Null,
        }
        .to_string())
    }

    /// The damping time `A` \[s\] the scene gives (directly or from viscosities).
    pub fn damping_time(&self) -> Result<f64, String> {
        Ok(Contact::new(&self.scene).map_err(core_err)?.damping_time)
    }

    /// Loads a named preset.
    pub fn load_preset(&mut self, name: &str) -> Result<(), String> {
        let p = Preset::from_name(name).ok_or_else(|| {
            format!(
                "preset: unknown preset {name:?} (one of {})",
                Preset::ALL.map(Preset::name).join(", ")
            )
        })?;
        self.scene = p.scene();
        Ok(())
    }

    /// ε_N and statuses on `n` log-spaced speeds from `from` to `to`.
    pub fn curve(&self, from: f64, to: f64, n: usize, accuracy: &str) -> Result<CurveData, String> {
        curve_for(&self.scene, from, to, n, parse_accuracy(accuracy)?)
    }

    /// ε_N curves for the scene with `path` set to each of `values`, concatenated (`values.len() × n`).
    pub fn family(
        &self,
        path: &str,
        values: &[f64],
        from: f64,
        to: f64,
        n: usize,
        accuracy: &str,
    ) -> Result<Vec<f64>, String> {
        check_count("values", values.len(), 1, MAX_FAMILY)?;
        let accuracy = parse_accuracy(accuracy)?;
        let mut out = Vec::with_capacity(values.len() * n);
        for &v in values {
            let mut e = self.clone();
            e.set_number(path, v)?;
            out.extend(curve_for(&e.scene, from, to, n, accuracy)?.eps);
        }
        Ok(out)
    }

    /// The clean-surface curve: the scene without layer and adhesion.
    pub fn clean_curve(
        &self,
        from: f64,
        to: f64,
        n: usize,
        accuracy: &str,
    ) -> Result<Vec<f64>, String> {
        let scene = Scene {
            layer: None,
            adhesion: None,
            ..self.scene
        };
        Ok(curve_for(&scene, from, to, n, parse_accuracy(accuracy)?)?.eps)
    }

    /// The full normal result at one speed, as JSON (`g_n`, `eps_n`, `status`, `t_c`, `xi_max`,
    /// `error_estimate`; infinities as `null`).
    pub fn normal(&self, g: f64, accuracy: &str) -> Result<String, String> {
        let g = check_speed("g_n", g)?;
        let contact = Contact::new(&self.scene).map_err(core_err)?;
        let r = contact
            .normal(g, parse_accuracy(accuracy)?)
            .map_err(core_err)?;
        Ok(json!({
            "g_n": g, "eps_n": r.eps, "status": r.status.name(), "t_c": r.t_c,
            "xi_max": r.xi_max, "error_estimate": r.error_estimate,
        })
        .to_string())
    }

    /// Tangential restitution at one point, as JSON (`g_n`, `g_t`, `eps_t`, `eps_n`, `class`).
    pub fn tangential(&self, g_n: f64, g_t: f64, accuracy: &str) -> Result<String, String> {
        let (g_n, g_t) = (check_map_speed("g_n", g_n)?, check_map_speed("g_t", g_t)?);
        let contact = Contact::new(&self.scene).map_err(core_err)?;
        let t = contact
            .tangential(g_n, g_t, parse_accuracy(accuracy)?)
            .map_err(core_err)?;
        Ok(json!({"g_n": g_n, "g_t": g_t, "eps_t": t.eps_t, "eps_n": t.eps_n, "class": t.class.name()})
            .to_string())
    }

    /// An `n × n` stick map from 0 to `max`.
    pub fn stick_map(&self, max: f64, n: usize, accuracy: &str) -> Result<MapData, String> {
        let max = check_speed("max", max)?;
        let n = check_count("n", n, 2, MAX_MAP_SIDE)?;
        let accuracy = parse_accuracy(accuracy)?;
        let contact = Contact::new(&self.scene).map_err(core_err)?;
        let m = StickMap::new(&contact, max, n, accuracy).map_err(core_err)?;
        Ok(MapData {
            class: m.class.iter().map(|c| class_code(*c)).collect(),
            g: m.g,
            eps_n: m.eps_n,
            eps_t: m.eps_t,
        })
    }

    /// The critical velocities as JSON: a list of `{key, label, value}` with the layer's g_s
    /// (Eq. (10)), the adhesion's g_s (Eq. (15), a threshold on the rebound speed), and the impact speed
    /// below which the grains stick (found by bisection on the status the core reports).
    pub fn critical_velocities(&self, accuracy: &str) -> Result<String, String> {
        let accuracy = parse_accuracy(accuracy)?;
        let contact = Contact::new(&self.scene).map_err(core_err)?;
        let mut out = Vec::new();
        if let Some(l) = &contact.layer {
            out.push(json!({"key": "layer", "label": "g_s layer (Eq. (10))", "value": l.critical_velocity}));
        }
        if let Some(a) = &contact.adhesion {
            out.push(json!({"key": "adhesion", "label": "g_s adhesion (Eq. (15))", "value": a.critical_velocity}));
        }
        if let Some(t) = stick_threshold(&contact, accuracy)? {
            out.push(json!({"key": "stick", "label": "sticks below", "value": t}));
        }
        Ok(Json::from(out).to_string())
    }

    /// Warnings about the scene: overdamped collisions in `[from, to]`, and options that deviate
    /// from (or expose inconsistencies of) the paper. JSON list of strings.
    pub fn warnings(&self, from: f64, to: f64) -> Result<String, String> {
        let mut w: Vec<String> = Vec::new();
        let c = curve_for(&self.scene, from, to, 61, Accuracy::Fast)?;
        let over = c.status.iter().filter(|s| **s == 3).count();
        if over > 0 {
            let a = match self.scene.bulk.damping {
                Damping::Time(a) => a,
                Damping::Viscosities(_) => Contact::new(&self.scene)
                    .map(|c| c.damping_time)
                    .unwrap_or(f64::NAN),
            };
            w.push(format!(
                "overdamped: ε_N < 1e-9 over {} of the plotted range (A = {a:.3e} s); Eq. (4) never \
                 sticks, the rebound is negligible",
                if over == c.status.len() {
                    "all"
                } else {
                    "part"
                }
            ));
        }
        let s = &self.scene;
        if let Damping::Viscosities(v) = s.bulk.damping
            && v.formula == DampingFormula::AsPrinted
        {
            w.push(
                "A formula as printed: the paper omits the factor (1−2ν) of Brilliantov et al."
                    .into(),
            );
        }
        if s.contact_end == ContactEnd::ZeroOverlap {
            w.push("contact end zero_overlap: Eq. (5) read literally, a tensile viscoelastic force acts while separating".into());
        }
        if s.layer.is_some_and(|l| l.reading == LayerReading::Literal) {
            w.push("Eq. (8) literal reading: threshold ≈ 2 g_s and ε_N can exceed the clean value, contradicting the paper's text".into());
        }
        if s.adhesion
            .is_some_and(|a| a.modulus == AdhesionModulus::Consistent)
        {
            w.push(
                "adhesion modulus consistent: E = Y/(2(1−ν²)) instead of the printed Y/(1−ν²)"
                    .into(),
            );
        }
        Ok(Json::from(w).to_string())
    }

    /// The appendix (Eq. (A.1)–(A.7)) as JSON: `{input, result, paper}`. `input_json` is a
    /// `TidalInput`; empty means the paper's planet and distance with the scene's grain 1 radius,
    /// density and surface energy (the paper's 0.1 J/m² without adhesion).
    pub fn tidal(&self, input_json: &str) -> Result<String, String> {
        let input: TidalInput = if input_json.trim().is_empty() {
            TidalInput {
                radius: self.scene.grains.radius_1,
                density: self.scene.grains.density,
                surface_energy: self
                    .scene
                    .adhesion
                    .map_or(TidalInput::default().surface_energy, |a| a.surface_energy),
                ..TidalInput::default()
            }
        } else {
            let de = &mut serde_json::Deserializer::from_str(input_json);
            serde_path_to_error::deserialize(de).map_err(|e| {
                let path = e.path().to_string();
                format!("tidal.{path}: {}", e.into_inner())
            })?
        };
        let r = tidal(&input).map_err(|e| format!("tidal.{}", core_err(e)))?;
        let q = PAPER_QUOTED;
        Ok(json!({
            "input": input,
            "result": r,
            "paper": {"delta_f": q.delta_f, "surface_force": q.surface_force, "d_roche": q.d_roche,
                      "d_min": q.d_min, "r_max": q.r_max},
        })
        .to_string())
    }
}

fn check_map_speed(field: &str, g: f64) -> Result<f64, String> {
    if g.is_finite() && (0.0..=SPEED_RANGE.1).contains(&g) {
        Ok(g)
    } else {
        Err(format!("{field}: speed must lie in [0, 1e6] m/s (got {g})"))
    }
}

/// The impact speed below which the grains stick, by bisection in log speed on the status the core
/// reports (`None` when they never stick in [1e-12, 1e2] m/s, or always do).
fn stick_threshold(contact: &Contact, accuracy: Accuracy) -> Result<Option<f64>, String> {
    let stuck = |g: f64| -> Result<bool, String> {
        Ok(is_stuck(
            contact.normal(g, accuracy).map_err(core_err)?.status,
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

/// The parameter registry as JSON: a list of `{path, label, unit, kind, ...}` with `min`, `max`,
/// `log` for numbers and `options` for choices.
pub fn parameters_json() -> String {
    let list: Vec<Json> = PARAMETERS
        .iter()
        .map(|p| match p.kind {
            Kind::Number { min, max, log } => json!({
                "path": p.path, "label": p.label, "unit": p.unit, "kind": "number",
                "min": min, "max": max, "log": log,
            }),
            Kind::Choice(options) => json!({
                "path": p.path, "label": p.label, "unit": p.unit, "kind": "choice", "options": options,
            }),
            Kind::Toggle => json!({"path": p.path, "label": p.label, "unit": p.unit, "kind": "toggle"}),
        })
        .collect();
    Json::from(list).to_string()
}

/// The presets as JSON: a list of `{name, description}`.
pub fn presets_json() -> String {
    let list: Vec<Json> = Preset::ALL
        .iter()
        .map(|p| json!({"name": p.name(), "description": p.description()}))
        .collect();
    Json::from(list).to_string()
}

/// The stick classes in code order as JSON: a list of `{name, letter, description}`.
pub fn classes_json() -> String {
    let list: Vec<Json> = StickClass::ALL
        .iter()
        .map(|c| json!({"name": c.name(), "letter": c.letter().to_string(), "description": c.description()}))
        .collect();
    Json::from(list).to_string()
}

/// The status names in code order as JSON.
pub fn statuses_json() -> String {
    Json::from(STATUSES.map(Status::name).to_vec()).to_string()
}

/// The experimental context of the ε_N chart as JSON: the Bridges et al. (1984) law
/// (`{a, b, g0, label}`, ε = a (g/g0)^b) and the microgravity ice experiments' ranges
/// (`[{x: [lo, hi], y: [lo, hi], label}]`), from `rime_core::fit` and `rime_core::figure`.
pub fn experiments_json() -> String {
    let b = rime_core::fit::BRIDGES_1984;
    let bands: Vec<Json> = rime_core::figure::experiments::bands(0)
        .into_iter()
        .map(|band| json!({"x": [band.x.0, band.x.1], "y": [band.y.0, band.y.1], "label": band.label}))
        .collect();
    json!({
        "bridges": {"a": b.a, "b": b.b, "g0": b.g0,
                    "label": "Bridges et al. 1984: ε = 0.32 (v / 1 cm/s)^−0.234"},
        "bands": bands,
    })
    .to_string()
}

/// A choice parameter's current option, if active (used by the page to fill selects).
pub fn choice_of(scene: &Scene, path: &str) -> Option<&'static str> {
    scene.get(path).ok().and_then(choice_name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_round_trips_and_errors_name_the_field() {
        let mut e = Explorer::new();
        e.load_preset("ice-frost").unwrap();
        let text = e.to_json().unwrap();
        assert_eq!(Explorer::from_json(&text).unwrap(), e);
        let bad = text.replace("1000.0", "-5.0");
        let err = Explorer::from_json(&bad).unwrap_err();
        assert!(err.starts_with("layer.viscosity:"), "{err}");
        let err = Explorer::from_json(r#"{"grains": {"radius_1": "x"}}"#).unwrap_err();
        assert!(err.starts_with("grains.radius_1:"), "{err}");
        let err = Explorer::from_json(&text.replace("\"layer\"", "\"layr\"")).unwrap_err();
        assert!(err.contains("layr"), "{err}");
        assert!(Explorer::from_json("garbage").is_err());
    }

    #[test]
    fn set_validates_and_keeps_the_scene() {
        let mut e = Explorer::new();
        let before = e.clone();
        let err = e.set("layer.viscosity", "-3").unwrap_err();
        assert!(err.starts_with("layer.viscosity:"), "{err}");
        assert_eq!(e, before);
        assert!(e.set("no.such", "1").unwrap_err().starts_with("no.such:"));
        assert!(e.set_number("grains.density", f64::NAN).is_err());
        assert_eq!(e, before);
        e.set("layer.viscosity", "2 kPa s").unwrap();
        assert_eq!(e.get("layer.viscosity").unwrap(), "2000.0");
        assert_eq!(e.get("layer").unwrap(), "true");
        assert_eq!(e.get("bulk.damping.viscosities.shear").unwrap(), "null");
        assert_eq!(e.get("contact_end").unwrap(), "\"force_zero\"");
        assert_eq!(Explorer::new().damping_time().unwrap(), 1e-4);
        assert!(e.load_preset("nope").unwrap_err().starts_with("preset:"));
    }

    #[test]
    fn curve_matches_the_core() {
        let mut e = Explorer::new();
        e.load_preset("ice-frost").unwrap();
        let c = e.curve(1e-6, 1.0, 50, "fast").unwrap();
        let contact = Contact::new(&e.scene).unwrap();
        for (i, g) in c.g.iter().enumerate() {
            let r = contact.normal(*g, Accuracy::Fast).unwrap();
            assert_eq!(r.eps, c.eps[i]);
            assert_eq!(status_code(r.status), c.status[i]);
        }
        assert_eq!(c.status[0], 1, "stuck in layer at 1 µm/s");
        assert_eq!(c.g[0], 1e-6);
        assert_eq!(c.g[49], 1.0);
    }

    #[test]
    fn arguments_are_validated() {
        let e = Explorer::new();
        assert!(e.curve(f64::NAN, 1.0, 10, "fast").is_err());
        assert!(e.curve(1e-3, 1.0, 0, "fast").is_err());
        assert!(e.curve(1e-3, 1.0, usize::MAX, "fast").is_err());
        assert!(e.curve(1.0, 1e-3, 10, "fast").is_err());
        assert!(e.curve(1e-3, f64::INFINITY, 10, "fast").is_err());
        assert!(
            e.curve(1e-3, 1.0, 10, "sloppy")
                .unwrap_err()
                .starts_with("accuracy:")
        );
        assert!(e.stick_map(-1.0, 10, "fast").is_err());
        assert!(e.stick_map(0.1, 5000, "fast").is_err());
        assert!(
            e.family("layer.viscosity", &[], 1e-3, 1.0, 10, "fast")
                .is_err()
        );
        assert!(
            e.family("layer.viscosity", &[-1.0], 1e-3, 1.0, 10, "fast")
                .is_err()
        );
        assert!(e.family("layer", &[1.0], 1e-3, 1.0, 10, "fast").is_err());
        assert!(e.normal(0.0, "fast").is_err());
        assert!(e.tangential(-1.0, 0.0, "fast").is_err());
        assert!(e.tidal("{\"radius\": -1}").is_err());
    }

    #[test]
    fn family_and_map_shapes() {
        let mut e = Explorer::new();
        e.load_preset("ice-frost").unwrap();
        let f = e
            .family(
                "layer.viscosity",
                &[500.0, 1000.0, 2000.0],
                1e-6,
                1.0,
                40,
                "fast",
            )
            .unwrap();
        assert_eq!(f.len(), 120);
        let own = e.curve(1e-6, 1.0, 40, "fast").unwrap();
        assert_eq!(&f[40..80], &own.eps[..]);
        let m = e.stick_map(1e-3, 20, "fast").unwrap();
        assert_eq!(m.class.len(), 400);
        assert_eq!(m.eps_t.len(), 400);
        assert_eq!(m.class[0], class_code(StickClass::Undefined));
        assert!(
            m.class
                .iter()
                .all(|c| (*c as usize) < StickClass::ALL.len())
        );
        let mut off = e.clone();
        off.set("friction", "off").unwrap();
        assert!(
            off.stick_map(1e-3, 20, "fast")
                .unwrap_err()
                .starts_with("friction:")
        );
    }

    #[test]
    fn critical_velocities_and_warnings() {
        let mut e = Explorer::new();
        e.load_preset("ice-frost").unwrap();
        let v: Json = serde_json::from_str(&e.critical_velocities("fast").unwrap()).unwrap();
        let layer = v[0]["value"].as_f64().unwrap();
        let stick = v[1]["value"].as_f64().unwrap();
        assert!((stick / layer - 1.0).abs() < 1e-6, "{stick} vs {layer}");
        e.load_preset("ice-paper-viscosities").unwrap();
        let w: Vec<String> = serde_json::from_str(&e.warnings(1e-6, 1.0).unwrap()).unwrap();
        assert!(w.iter().any(|s| s.starts_with("overdamped")), "{w:?}");
        e.load_preset("ice").unwrap();
        assert_eq!(e.warnings(1e-6, 1.0).unwrap(), "[]");
        e.set("contact_end", "zero_overlap").unwrap();
        assert_eq!(choice_of(&e.scene, "contact_end"), Some("zero_overlap"));
        assert!(e.warnings(1e-6, 1.0).unwrap().contains("zero_overlap"));
    }

    #[test]
    fn metadata_is_json() {
        let p: Vec<Json> = serde_json::from_str(&parameters_json()).unwrap();
        assert_eq!(p.len(), PARAMETERS.len());
        let c: Vec<Json> = serde_json::from_str(&classes_json()).unwrap();
        assert_eq!(c.len(), 7);
        let s: Vec<String> = serde_json::from_str(&statuses_json()).unwrap();
        assert_eq!(s[3], "overdamped");
        let pr: Vec<Json> = serde_json::from_str(&presets_json()).unwrap();
        assert_eq!(pr.len(), 4);
        let x: Json = serde_json::from_str(&experiments_json()).unwrap();
        assert_eq!(x["bridges"]["a"], 0.32);
        assert_eq!(x["bands"].as_array().unwrap().len(), 2);
        let t: Json = serde_json::from_str(&Explorer::new().tidal("").unwrap()).unwrap();
        assert!(t["result"]["d_roche"].as_f64().unwrap() > 1e8);
        let n: Json = serde_json::from_str(&Explorer::new().normal(0.01, "fast").unwrap()).unwrap();
        assert_eq!(n["status"], "rebound");
    }
}
