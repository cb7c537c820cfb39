//! A scene being explored on the web page: every operation of the page's `Explorer` (edits, presets,
//! point results, one collision from the inside, a fit, the appendix) as a method returning a typed
//! record or an error that names the field (`layer.viscosity: must lie in [0, 1e15] Pa s (got -1)`).
//! The wasm binding only turns these records into JSON.

use super::json_path::{parse_scene, read_named};
use super::limits::{CHART_SPEED_DOMAIN, MAX_CURVE_POINTS, chart_speed_is_valid, speed_is_valid};
use super::tidal::TidalCard;
use crate::applications::tidal::TidalInput;
use crate::collision::Trajectory;
use crate::figure::sweep::log_space;
use crate::scene::params::Value;
use crate::{Accuracy, Contact, Preset, Scene};
use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec;
use alloc::vec::Vec;

/// A core error as the page shows it.
fn core_err(e: crate::Error) -> String {
    e.to_string()
}

/// An error of a parameter `path`: an unknown path names itself.
fn param_err(path: &str, e: crate::Error) -> String {
    match e {
        crate::Error::UnknownParameter => format!("{path}: unknown parameter"),
        e => core_err(e),
    }
}

fn check_speed(field: &str, g: f64) -> Result<f64, String> {
    if crate::scene::limits::speed_is_valid(g) {
        Ok(g)
    } else {
        let domain = crate::scene::limits::SPEED_DOMAIN;
        Err(format!("{field}: speed must lie in {domain} m/s (got {g})"))
    }
}

fn check_map_speed(field: &str, g: f64) -> Result<f64, String> {
    if crate::scene::limits::speed_or_zero_is_valid(g) {
        Ok(g)
    } else {
        let domain = crate::scene::limits::SPEED_OR_ZERO_DOMAIN;
        Err(format!("{field}: speed must lie in {domain} m/s (got {g})"))
    }
}

/// `n` within `[lo, hi]`, or an error naming `field`.
pub fn check_count(field: &str, n: usize, lo: usize, hi: usize) -> Result<usize, String> {
    if (lo..=hi).contains(&n) {
        Ok(n)
    } else {
        Err(format!("{field}: must lie in [{lo}, {hi}] (got {n})"))
    }
}

/// A count the page sends as a JS number: a whole, non-negative one, else an error naming `field`.
pub fn whole(field: &str, x: f64) -> Result<usize, String> {
    if x.is_finite() && x >= 0.0 && x.fract() == 0.0 {
        Ok(x as usize)
    } else {
        Err(format!("{field}: {x} is not a whole number"))
    }
}

/// Parses an accuracy level (`fast`, `balanced`, `precise` or a tolerance).
pub fn parse_accuracy(text: &str) -> Result<Accuracy, String> {
    Accuracy::parse(text).map_err(core_err)
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

/// The most speeds one batch call takes.
pub const MAX_BATCH: usize = 10_000_000;

/// Parses a typed speed (`"1 um/s"`, `"0.02"`, `"5 cm/s"`) for the view field `field`; the value
/// must be a speed the models accept (`(0, 1e6]` m/s). Errors name the field and show the value
/// short (a 309-digit number reads `1e308`).
pub fn parse_speed(field: &str, text: &str) -> Result<f64, String> {
    speed_within(
        field,
        text,
        speed_is_valid,
        crate::scene::limits::SPEED_DOMAIN,
    )
}

/// Parses a typed end of the chart's speed range: as [`parse_speed`], within the core's chart
/// limits `[1e-12, 1e6]` m/s (a link with `view.from = 1e-300` drew 301 decades).
pub fn parse_chart_speed(field: &str, text: &str) -> Result<f64, String> {
    speed_within(field, text, chart_speed_is_valid, CHART_SPEED_DOMAIN)
}

/// A typed speed that `valid` accepts; the error names the field and the `domain`.
fn speed_within(
    field: &str,
    text: &str,
    valid: fn(f64) -> bool,
    domain: &str,
) -> Result<f64, String> {
    let v = parse_quantity(field, text, "m/s")?;
    if valid(v) {
        Ok(v)
    } else {
        Err(format!(
            "{field}: must be a speed in {domain} m/s (got {})",
            super::format::sig(v, 4)
        ))
    }
}

/// At most `n` characters of `text`, with `…` when cut.
fn shortened(text: &str, n: usize) -> String {
    if text.chars().count() > n {
        format!("{}…", text.chars().take(n).collect::<String>())
    } else {
        text.to_string()
    }
}

/// Parses a typed quantity with optional units compatible with `unit` (the core's unit parser);
/// errors name `field` and never carry the typed text at full length.
pub fn parse_quantity(field: &str, text: &str, unit: &str) -> Result<f64, String> {
    let shown = shortened(text, 24);
    let v = crate::scene::units::parse_quantity("value", text, unit).map_err(|e| {
        let msg = e.to_string();
        let msg = shortened(msg.strip_prefix("value: ").unwrap_or(&msg), 160);
        format!("{field}: {msg} (typed \"{shown}\")")
    })?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("{field}: not a finite number (typed \"{shown}\")"))
    }
}

/// A parameter's value as the page reads it: a number, a choice name, a boolean for effects,
/// `null` when inactive.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(untagged)]
pub enum ParamValue {
    /// A number in SI.
    Number(f64),
    /// A choice by name.
    Choice(&'static str),
    /// Whether an effect is on.
    Enabled(bool),
    /// Inactive (`null`).
    Inactive,
}

impl From<Value> for ParamValue {
    fn from(v: Value) -> Self {
        match v {
            Value::Number(x) => ParamValue::Number(x),
            Value::Choice(c) => ParamValue::Choice(c),
            Value::Enabled(b) => ParamValue::Enabled(b),
            Value::Inactive => ParamValue::Inactive,
        }
    }
}

/// [`Session::normal`]: the core's `Normal` under the page's names (`eps_n`, status by name;
/// infinities as `null`).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct NormalPoint {
    /// Impact speed \[m/s\].
    pub g_n: f64,
    /// ε_N.
    pub eps_n: f64,
    /// How the collision ended.
    pub status: &'static str,
    /// Contact duration \[s\] (`null` when the grains stick).
    pub t_c: f64,
    /// Maximum compression \[m\].
    pub xi_max: f64,
    /// The error estimate of ε_N.
    pub error_estimate: f64,
}

/// [`Session::tangential`]: one point of the stick map.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct TangentialPoint {
    /// Normal speed \[m/s\].
    pub g_n: f64,
    /// Tangential speed \[m/s\].
    pub g_t: f64,
    /// ε_T.
    pub eps_t: f64,
    /// ε_N.
    pub eps_n: f64,
    /// The stick class by name.
    pub class: &'static str,
}

/// [`Session::fit_to_entry`]: the fitted damping time and the fitted scene (as scene JSON text).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FitRecord {
    /// The atlas entry fitted to.
    pub id: String,
    /// The fitted damping time A \[s\].
    pub value: f64,
    /// Its standard error, when there is one.
    pub standard_error: Option<f64>,
    /// rms of the residuals.
    pub rms_error: f64,
    /// What the fit warns of.
    pub warnings: Vec<String>,
    /// The fitted scene as JSON text.
    pub scene: String,
}

/// The collision record the page's collision card reads: the core's trajectory (its serde form:
/// `t`, `xi`, `xi_dot`, `force`, `phases`, `t_c` — `null` when unresolved —, `xi_max`, `eps_n`,
/// `status`, `ledger`, `resolved`, `rhs_evaluations`) with the impact speed, the radii and, with
/// adhesion, the dynamic JKR model's loop.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct CollisionCard {
    /// Impact speed \[m/s\].
    pub g: f64,
    /// The trajectory.
    #[serde(flatten)]
    pub trajectory: Trajectory,
    /// Grain 1's radius \[m\].
    pub radius_1: f64,
    /// Grain 2's radius \[m\].
    pub radius_2: f64,
    /// The dynamic JKR model's force loop, with adhesion.
    pub dynamic: Option<ForceLoop>,
}

/// The dynamic JKR model's force loop (`Dynamic::force_loop`) as two arrays.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ForceLoop {
    /// Overlap \[m\].
    pub xi: Vec<f64>,
    /// Force \[N\].
    pub force: Vec<f64>,
}

/// A scene being explored.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Session {
    /// The current scene (always valid).
    pub scene: Scene,
}

impl Session {
    /// The default (`ice`) scene.
    pub fn new() -> Session {
        Session::default()
    }

    /// A scene from JSON.
    pub fn from_json(text: &str) -> Result<Session, String> {
        Ok(Session {
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
        let before = self.scene;
        self.scene.set(path, text).map_err(|e| param_err(path, e))?;
        self.check(path, before)
    }

    /// Sets a numeric parameter directly; same rules as [`Session::set`].
    pub fn set_number(&mut self, path: &str, value: f64) -> Result<(), String> {
        let before = self.scene;
        self.scene
            .set_number(path, value)
            .map_err(|e| param_err(path, e))?;
        self.check(path, before)
    }

    /// The core's full check of the scene after a change of `path` (`Contact::new`, which also
    /// checks derived quantities); on error the scene goes back to `before`.
    fn check(&mut self, path: &str, before: Scene) -> Result<(), String> {
        match Contact::new(&self.scene) {
            Ok(_) => Ok(()),
            Err(e) => {
                self.scene = before;
                let msg = core_err(e);
                Err(if msg.contains(path) {
                    msg
                } else {
                    format!("{path}: {msg}")
                })
            }
        }
    }

    /// The preset whose scene this is, if any (the page's preset menu names it on every edit
    /// without reading the scene's text back).
    pub fn preset(&self) -> Option<&'static str> {
        Preset::ALL
            .into_iter()
            .find(|p| p.scene() == self.scene)
            .map(Preset::name)
    }

    /// A parameter's value (a number, a choice name, a boolean for effects, `null` when inactive).
    pub fn get(&self, path: &str) -> Result<ParamValue, String> {
        self.scene
            .get(path)
            .map(ParamValue::from)
            .map_err(|e| param_err(path, e))
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

    /// The full normal result at one speed.
    pub fn normal(&self, g: f64, accuracy: &str) -> Result<NormalPoint, String> {
        let g = check_speed("g_n", g)?;
        let contact = Contact::new(&self.scene).map_err(core_err)?;
        let r = contact
            .normal(g, parse_accuracy(accuracy)?)
            .map_err(core_err)?;
        Ok(NormalPoint {
            g_n: g,
            eps_n: r.eps,
            status: r.status.name(),
            t_c: r.t_c,
            xi_max: r.xi_max,
            error_estimate: r.error_estimate,
        })
    }

    /// ε_N for `speeds` (|g|; NaN → NaN, 0 → the at-rest limit, 0 when stuck) through the core's
    /// batch path; at most [`MAX_BATCH`] speeds.
    pub fn eps_n_batch(&self, speeds: &[f64], accuracy: &str) -> Result<Vec<f64>, String> {
        if speeds.len() > MAX_BATCH {
            return Err(format!("speeds: at most 1e7 values (got {})", speeds.len()));
        }
        let accuracy = parse_accuracy(accuracy)?;
        let contact = Contact::new(&self.scene).map_err(core_err)?;
        let mut out = vec![0.0; speeds.len()];
        contact
            .eps_n_batch(speeds, &mut out, accuracy)
            .map_err(|e| format!("speeds: {e}"))?;
        Ok(out)
    }

    /// One collision from the inside at impact speed `g` (docs/physics.md#collision): `points`
    /// samples plus the phase instants, and with adhesion the dynamic JKR model's loop.
    pub fn collision(
        &self,
        g: f64,
        points: usize,
        accuracy: &str,
    ) -> Result<CollisionCard, String> {
        let g = check_speed("g_n", g)?;
        let points = check_count("points", points, 2, MAX_CURVE_POINTS)?;
        let contact = Contact::new(&self.scene).map_err(core_err)?;
        let trajectory = contact
            .collision(g, points, parse_accuracy(accuracy)?)
            .map_err(core_err)?;
        let dynamic = self.scene.adhesion.and_then(|a| {
            crate::models::brilliantov2007::Dynamic::new(&contact, a.surface_energy, a.jkr_end)
                .and_then(|d| d.force_loop(g, 1e-9))
                .ok()
                .map(|p| ForceLoop {
                    xi: p.iter().map(|q| q.xi).collect(),
                    force: p.iter().map(|q| q.force).collect(),
                })
        });
        Ok(CollisionCard {
            g,
            trajectory,
            radius_1: self.scene.grains.radius_1,
            radius_2: self.scene.grains.radius_2,
            dynamic,
        })
    }

    /// Fits the damping time A of the current scene to a measured law of the atlas (`id`) over the
    /// speeds it was measured at and, on success, makes the fitted scene current. On error the
    /// scene is unchanged.
    pub fn fit_to_entry(&mut self, id: &str, accuracy: &str) -> Result<FitRecord, String> {
        let entry = crate::data::atlas::find(id)
            .ok_or_else(|| format!("overlays: unknown entry {id:?}"))?;
        let f = crate::fit::scene::fit_to_entry(
            &self.scene,
            entry,
            &["bulk.damping.time"],
            parse_accuracy(accuracy)?,
        )
        .map_err(|e| format!("fit A to {id}: {e}"))?;
        let p = f
            .params
            .first()
            .ok_or_else(|| format!("fit A to {id}: no parameter fitted"))?;
        let record = FitRecord {
            id: id.to_string(),
            value: p.value,
            standard_error: p.standard_error,
            rms_error: f.rms_error,
            warnings: f.warnings.clone(),
            scene: serde_json::to_string(&f.scene).map_err(|e| e.to_string())?,
        };
        self.scene = f.scene;
        Ok(record)
    }

    /// Tangential restitution at one point.
    pub fn tangential(
        &self,
        g_n: f64,
        g_t: f64,
        accuracy: &str,
    ) -> Result<TangentialPoint, String> {
        let (g_n, g_t) = (check_map_speed("g_n", g_n)?, check_map_speed("g_t", g_t)?);
        let contact = Contact::new(&self.scene).map_err(core_err)?;
        let t = contact
            .tangential(g_n, g_t, parse_accuracy(accuracy)?)
            .map_err(core_err)?;
        Ok(TangentialPoint {
            g_n,
            g_t,
            eps_t: t.eps_t,
            eps_n: t.eps_n,
            class: t.class.name(),
        })
    }

    /// The appendix (Eq. (A.1)–(A.7)): the core's tidal card. `input_json` is a `TidalInput`;
    /// empty means the paper's planet and distance with the scene's grain 1 radius, density and
    /// surface energy (the paper's 0.1 J/m² without adhesion).
    pub fn tidal(&self, input_json: &str) -> Result<TidalCard, String> {
        let input: Option<TidalInput> = if input_json.trim().is_empty() {
            None
        } else {
            Some(read_named(input_json, "tidal", true)?)
        };
        tidal_card(&self.scene, input)
    }
}

/// The appendix card for `input`, or without one the paper's planet and distance with the scene's
/// grain 1 radius, density and surface energy (the paper's 0.1 J/m² without adhesion). One builder
/// for the frame and [`Session::tidal`].
pub fn tidal_card(scene: &Scene, input: Option<TidalInput>) -> Result<TidalCard, String> {
    use super::tidal::{card, input_for};
    let (input, gamma_from_paper) = match input {
        Some(typed) => (typed, false),
        None => input_for(scene, 1.0),
    };
    card(input, gamma_from_paper).map_err(|e| format!("tidal.{e}"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::Value as Json;

    fn json<T: serde::Serialize>(v: &T) -> Json {
        serde_json::to_value(v).expect("JSON")
    }

    /// The keys of a JSON object, sorted (the page reads by key; order is not part of the contract).
    fn keys(v: &Json) -> Vec<&str> {
        let mut k: Vec<&str> = v
            .as_object()
            .expect("an object")
            .keys()
            .map(String::as_str)
            .collect();
        k.sort_unstable();
        k
    }

    #[test]
    fn issue_36_the_preset_is_named_by_the_scene_not_its_text() {
        let mut e = Session::new();
        for p in Preset::ALL {
            e.load_preset(p.name()).unwrap();
            assert_eq!(e.preset(), Some(p.name()));
        }
        // Back from its text (as a link brings it), still that preset.
        let text = e.to_json().unwrap();
        let e2 = Session::from_json(&text).unwrap();
        assert_eq!(e2.preset(), e.preset());
        // One parameter changed: no preset; changed back: the preset again.
        e.load_preset("ice-frost").unwrap();
        let ParamValue::Number(eta) = e.get("layer.viscosity").unwrap() else {
            panic!("a number")
        };
        e.set("layer.viscosity", "2500").unwrap();
        assert_eq!(e.preset(), None);
        e.set_number("layer.viscosity", eta).unwrap();
        assert_eq!(e.preset(), Some("ice-frost"));
        // The Compare list asks whether a section is there the same way (`get` of its toggle).
        assert_eq!(e.get("plasticity").unwrap(), ParamValue::Enabled(false));
        e.set("plasticity", "true").unwrap();
        assert_eq!(e.get("plasticity").unwrap(), ParamValue::Enabled(true));
    }

    #[test]
    fn json_round_trips_and_errors_name_the_field() {
        let mut e = Session::new();
        e.load_preset("ice-frost").unwrap();
        let text = e.to_json().unwrap();
        assert_eq!(Session::from_json(&text).unwrap(), e);
        let bad = text.replace("1000.0", "-5.0");
        let err = Session::from_json(&bad).unwrap_err();
        assert!(err.starts_with("layer.viscosity:"), "{err}");
        let err = Session::from_json(r#"{"grains": {"radius_1": "x"}}"#).unwrap_err();
        assert!(err.starts_with("grains.radius_1:"), "{err}");
        let err = Session::from_json(&text.replace("\"layer\"", "\"layr\"")).unwrap_err();
        assert!(err.contains("layr"), "{err}");
        assert!(Session::from_json("garbage").is_err());
    }

    #[test]
    fn set_validates_and_keeps_the_scene() {
        let mut e = Session::new();
        let before = e.clone();
        let err = e.set("layer.viscosity", "-3").unwrap_err();
        assert!(err.starts_with("layer.viscosity:"), "{err}");
        assert_eq!(e, before);
        assert!(e.set("no.such", "1").unwrap_err().starts_with("no.such:"));
        assert!(e.set_number("grains.density", f64::NAN).is_err());
        assert_eq!(e, before);
        e.set("layer.viscosity", "2 kPa s").unwrap();
        // The page reads each kind of value as JSON.
        assert_eq!(json(&e.get("layer.viscosity").unwrap()), 2000.0);
        assert_eq!(json(&e.get("layer").unwrap()), true);
        assert!(json(&e.get("bulk.damping.viscosities.shear").unwrap()).is_null());
        assert_eq!(json(&e.get("contact_end").unwrap()), "force_zero");
        assert_eq!(Session::new().damping_time().unwrap(), 1e-4);
        assert!(e.load_preset("nope").unwrap_err().starts_with("preset:"));
    }

    #[test]
    fn one_collision_as_the_core_computes_it_issue_13() {
        let mut e = Session::new();
        e.load_preset("ice-sticky").unwrap();
        let c = json(&e.collision(1e-3, 50, "precise").unwrap());
        let contact = Contact::new(&e.scene).unwrap();
        let n = contact.normal(1e-3, Accuracy::Precise).unwrap();
        assert_eq!(c["eps_n"].as_f64().unwrap(), n.eps);
        assert_eq!(c["t_c"].as_f64().unwrap(), n.t_c);
        assert!(
            c["ledger"]["closure"].as_f64().unwrap().abs() < 1e-9,
            "{}",
            c["ledger"]
        );
        assert!(c["t"].as_array().unwrap().len() >= 50);
        assert!(c["dynamic"]["xi"].as_array().unwrap().len() > 10);
        assert_eq!(c["radius_1"].as_f64(), Some(e.scene.grains.radius_1));
        let err = e.collision(-1.0, 50, "fast").unwrap_err();
        assert!(err.starts_with("g_n"), "{err}");
        assert!(
            e.collision(0.01, 1, "fast")
                .unwrap_err()
                .starts_with("points")
        );
        assert!(whole("points", 2.5).unwrap_err().starts_with("points"));
        assert_eq!(whole("points", 40.0), Ok(40));
    }

    #[test]
    fn the_batch_is_the_cores_and_refuses_too_many_speeds() {
        let e = Session::new();
        let g = [1e-3, 0.1, f64::NAN];
        let eps = e.eps_n_batch(&g, "fast").unwrap();
        let contact = Contact::new(&e.scene).unwrap();
        // The batch path's own table, within the fast level's bound (relative 1e-6) of the
        // point path.
        let one = contact.normal(1e-3, Accuracy::Fast).unwrap().eps;
        assert!((eps[0] / one - 1.0).abs() <= 1e-6, "{} vs {one}", eps[0]);
        assert!(eps[2].is_nan());
        assert!(e.eps_n_batch(&g, "nope").is_err());
    }

    #[test]
    fn typed_speeds_take_units_and_bad_ones_name_the_field_issue_12() {
        assert_eq!(parse_speed("g from", "1 um/s").unwrap(), 1e-6);
        assert_eq!(parse_speed("g from", "5 cm/s").unwrap(), 0.05);
        assert_eq!(parse_speed("g to", "0.3").unwrap(), 0.3);
        let e = parse_speed("g to", "2e6 m/s").unwrap_err();
        assert!(e.starts_with("g to:") && e.contains("2e6"), "{e}");
        let huge = format!("1{}", "0".repeat(308));
        let e = parse_speed("g to", &huge).unwrap_err();
        assert!(e.starts_with("g to:") && e.len() < 200, "{e}");
        let e = parse_speed("g from", "fast").unwrap_err();
        assert!(e.starts_with("g from:"), "{e}");
        assert!(parse_speed("g from", "-1 m/s").is_err());
        assert!(parse_speed("g from", "3 kg").is_err());
        assert!(parse_chart_speed("view.from", "1e-300").is_err());
        assert_eq!(parse_chart_speed("view.from", "1e-12").unwrap(), 1e-12);
        assert_eq!(
            parse_quantity("tidal.distance", "1.5e5 km", "m").unwrap(),
            1.5e8
        );
        assert_eq!(speeds(1e-3, 1.0, 4).unwrap().len(), 4);
        assert!(speeds(1.0, 1e-3, 4).unwrap_err().starts_with("to:"));
    }

    #[test]
    fn issue_36_point_results_keep_their_keys() {
        let mut ex = Session::new();
        ex.load_preset("ice").expect("preset");
        let contact = Contact::new(&Preset::Ice.scene()).expect("contact");
        let n = json(&ex.normal(1e-3, "fast").expect("normal"));
        assert_eq!(
            keys(&n),
            ["eps_n", "error_estimate", "g_n", "status", "t_c", "xi_max"]
        );
        let core = contact.normal(1e-3, Accuracy::Fast).expect("core normal");
        assert_eq!(n["g_n"].as_f64(), Some(1e-3));
        assert_eq!(n["eps_n"].as_f64(), Some(core.eps));
        assert_eq!(n["status"], core.status.name());
        assert_eq!(n["t_c"].as_f64(), Some(core.t_c));
        assert_eq!(n["xi_max"].as_f64(), Some(core.xi_max));
        // A grain that sticks comes to rest asymptotically: its infinite t_c is sent as null.
        let stuck = json(&NormalPoint {
            g_n: 1e-9,
            eps_n: 0.0,
            status: "stuck",
            t_c: f64::INFINITY,
            xi_max: 1e-12,
            error_estimate: f64::INFINITY,
        });
        assert!(stuck["t_c"].is_null() && stuck["error_estimate"].is_null());
        let t = json(&ex.tangential(1e-3, 2e-3, "fast").expect("tangential"));
        assert_eq!(keys(&t), ["class", "eps_n", "eps_t", "g_n", "g_t"]);
        let core = contact
            .tangential(1e-3, 2e-3, Accuracy::Fast)
            .expect("core tangential");
        assert_eq!(
            (t["g_n"].as_f64(), t["g_t"].as_f64()),
            (Some(1e-3), Some(2e-3))
        );
        assert_eq!(t["eps_t"].as_f64(), Some(core.eps_t));
        assert_eq!(t["eps_n"].as_f64(), Some(core.eps_n));
        assert_eq!(t["class"], core.class.name());
        let f = json(&ex.fit_to_entry("bridges1984", "fast").expect("fit"));
        assert_eq!(
            keys(&f),
            [
                "id",
                "rms_error",
                "scene",
                "standard_error",
                "value",
                "warnings"
            ]
        );
        assert_eq!(f["id"], "bridges1984");
        let scene: Scene =
            serde_json::from_str(f["scene"].as_str().expect("scene text")).expect("scene");
        assert_eq!(scene, ex.scene);
        assert!(f["warnings"].is_array());
    }

    #[test]
    fn the_tidal_card_is_the_cores_issue_36() {
        // The page receives the core's card itself, so its marks are the terminal's.
        let t = Session::new().tidal("").unwrap();
        let (input, from_paper) = super::super::tidal::input_for(&Scene::default(), 1.0);
        assert_eq!(t, super::super::tidal::card(input, from_paper).unwrap());
        assert!(json(&t)["result"]["d_roche"].as_f64().unwrap() > 1e8);
        let e = Session::new().tidal(r#"{"radius": "x"}"#).unwrap_err();
        assert!(e.starts_with("tidal."), "{e}");
    }
}
