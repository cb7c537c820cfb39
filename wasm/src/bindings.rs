//! The JavaScript interface (wasm32 only). Every method delegates to [`crate::explorer`].
//!
//! Codes: statuses are indices into `Explorer.statusNames()` (rebound, stuck_in_layer,
//! stuck_by_adhesion, overdamped); classes are indices into `Explorer.classes()` (legend order of
//! the core's `StickClass::ALL`).

use crate::explorer::{self, CurveData, MapData};
use wasm_bindgen::prelude::*;

fn js(e: String) -> JsError {
    JsError::new(&e)
}

fn count(field: &str, n: f64) -> Result<usize, JsError> {
    if n.is_finite() && n >= 0.0 && n.fract() == 0.0 && n <= 1e9 {
        Ok(n as usize)
    } else {
        Err(JsError::new(&format!(
            "{field}: must be a whole number (got {n})"
        )))
    }
}

/// A scene being explored, with the last computed curve and stick map kept for the getters.
#[wasm_bindgen]
pub struct Explorer {
    inner: explorer::Explorer,
    curve: CurveData,
    map: MapData,
}

#[wasm_bindgen]
impl Explorer {
    /// The default (`ice`) scene.
    #[wasm_bindgen(constructor)]
    pub fn new() -> Explorer {
        Explorer {
            inner: explorer::Explorer::new(),
            curve: CurveData {
                g: Vec::new(),
                eps: Vec::new(),
                status: Vec::new(),
            },
            map: MapData {
                g: Vec::new(),
                eps_n: Vec::new(),
                class: Vec::new(),
                eps_t: Vec::new(),
            },
        }
    }

    /// An explorer for a scene given as JSON; throws naming the offending field.
    #[wasm_bindgen(js_name = fromJson)]
    pub fn from_json(text: &str) -> Result<Explorer, JsError> {
        let mut e = Explorer::new();
        e.inner = explorer::Explorer::from_json(text).map_err(js)?;
        Ok(e)
    }

    /// Replaces the scene from JSON; on error (thrown) the scene is unchanged.
    #[wasm_bindgen(js_name = setJson)]
    pub fn set_json(&mut self, text: &str) -> Result<(), JsError> {
        self.inner.set_json(text).map_err(js)
    }

    /// The scene as compact JSON.
    #[wasm_bindgen(js_name = toJson)]
    pub fn to_json(&self) -> Result<String, JsError> {
        self.inner.to_json().map_err(js)
    }

    /// Sets a parameter from text (`"2 kPa s"`, `"literal"`, `"off"`); throws naming the field and
    /// leaves the scene unchanged on error.
    pub fn set(&mut self, path: &str, text: &str) -> Result<(), JsError> {
        self.inner.set(path, text).map_err(js)
    }

    /// Sets a numeric parameter directly.
    #[wasm_bindgen(js_name = setNumber)]
    pub fn set_number(&mut self, path: &str, value: f64) -> Result<(), JsError> {
        self.inner.set_number(path, value).map_err(js)
    }

    /// A parameter's value as JSON text (number, choice name, boolean, or `null` when inactive).
    pub fn get(&self, path: &str) -> Result<String, JsError> {
        self.inner.get(path).map_err(js)
    }

    /// The parameter registry as JSON text.
    pub fn parameters() -> String {
        explorer::parameters_json()
    }

    /// The presets as JSON text (`[{name, description}]`).
    pub fn presets() -> String {
        explorer::presets_json()
    }

    /// The stick classes in code order as JSON text (`[{name, letter, description}]`).
    pub fn classes() -> String {
        explorer::classes_json()
    }

    /// The status names in code order as JSON text.
    #[wasm_bindgen(js_name = statusNames)]
    pub fn status_names() -> String {
        explorer::statuses_json()
    }

    /// The experimental context of the ε_N chart as JSON text: `{bridges: {a, b, g0, label},
    /// bands: [{x: [lo, hi], y: [lo, hi], label}]}` (Bridges et al. 1984; Heißelmann et al. 2010,
    /// Hill et al. 2015).
    pub fn experiments() -> String {
        explorer::experiments_json()
    }

    /// The crate version.
    pub fn version() -> String {
        crate::version().to_string()
    }

    /// The damping time `A` \[s\] of the scene (given or derived from viscosities).
    #[wasm_bindgen(js_name = dampingTime)]
    pub fn damping_time(&self) -> Result<f64, JsError> {
        self.inner.damping_time().map_err(js)
    }

    /// Loads a named preset (`ice`, `ice-frost`, `ice-sticky`, `ice-paper-viscosities`).
    #[wasm_bindgen(js_name = loadPreset)]
    pub fn load_preset(&mut self, name: &str) -> Result<(), JsError> {
        self.inner.load_preset(name).map_err(js)
    }

    /// `n` log-spaced speeds from `from` to `to` inclusive.
    pub fn speeds(from: f64, to: f64, n: f64) -> Result<Vec<f64>, JsError> {
        explorer::speeds(from, to, count("n", n)?).map_err(js)
    }

    /// ε_N at `n` log-spaced speeds from `from` to `to`; the statuses are then in `statuses()`.
    pub fn curve(
        &mut self,
        from: f64,
        to: f64,
        n: f64,
        accuracy: &str,
    ) -> Result<Vec<f64>, JsError> {
        self.curve = self
            .inner
            .curve(from, to, count("n", n)?, accuracy)
            .map_err(js)?;
        Ok(self.curve.eps.clone())
    }

    /// Status codes of the last `curve()`.
    pub fn statuses(&self) -> Vec<u8> {
        self.curve.status.clone()
    }

    /// Speeds of the last `curve()`.
    #[wasm_bindgen(js_name = curveSpeeds)]
    pub fn curve_speeds(&self) -> Vec<f64> {
        self.curve.g.clone()
    }

    /// ε_N curves with `path` set to each of `values` (row-major, `values.length × n`).
    pub fn family(
        &self,
        path: &str,
        values: Vec<f64>,
        from: f64,
        to: f64,
        n: f64,
        accuracy: &str,
    ) -> Result<Vec<f64>, JsError> {
        self.inner
            .family(path, &values, from, to, count("n", n)?, accuracy)
            .map_err(js)
    }

    /// ε_N of the scene without layer and adhesion.
    #[wasm_bindgen(js_name = cleanCurve)]
    pub fn clean_curve(
        &self,
        from: f64,
        to: f64,
        n: f64,
        accuracy: &str,
    ) -> Result<Vec<f64>, JsError> {
        self.inner
            .clean_curve(from, to, count("n", n)?, accuracy)
            .map_err(js)
    }

    /// The normal result at one speed as JSON text.
    pub fn normal(&self, g: f64, accuracy: &str) -> Result<String, JsError> {
        self.inner.normal(g, accuracy).map_err(js)
    }

    /// ε_N for a Float64Array of speeds (|g|; NaN → NaN, 0 → the at-rest limit, 0 when stuck)
    /// through the core's batch path (`rime_core::batch`); at most 1e7 speeds.
    #[wasm_bindgen(js_name = epsNBatch)]
    pub fn eps_n_batch(&self, speeds: &[f64], accuracy: &str) -> Result<Vec<f64>, JsError> {
        if speeds.len() > 10_000_000 {
            return Err(js(format!(
                "speeds: at most 1e7 values (got {})",
                speeds.len()
            )));
        }
        let accuracy = explorer::parse_accuracy(accuracy).map_err(js)?;
        let contact = rime_core::Contact::new(&self.inner.scene).map_err(|e| js(e.to_string()))?;
        let mut out = vec![0.0; speeds.len()];
        contact
            .eps_n_batch(speeds, &mut out, accuracy)
            .map_err(|e| js(format!("speeds: {e}")))?;
        Ok(out)
    }

    /// The tangential result at one point as JSON text.
    pub fn tangential(&self, g_n: f64, g_t: f64, accuracy: &str) -> Result<String, JsError> {
        self.inner.tangential(g_n, g_t, accuracy).map_err(js)
    }

    /// Class codes of an `n × n` stick map from 0 to `max` (row-major, `[i*n+j]` at g_N = g\[i\],
    /// g_T = g\[j\]); ε_T, ε_N and the grid are then in `mapEpsT()`, `mapEpsN()`, `mapSpeeds()`.
    #[wasm_bindgen(js_name = stickMap)]
    pub fn stick_map(&mut self, max: f64, n: f64, accuracy: &str) -> Result<Vec<u8>, JsError> {
        self.map = self
            .inner
            .stick_map(max, count("n", n)?, accuracy)
            .map_err(js)?;
        Ok(self.map.class.clone())
    }

    /// ε_T of the last stick map (row-major).
    #[wasm_bindgen(js_name = mapEpsT)]
    pub fn map_eps_t(&self) -> Vec<f64> {
        self.map.eps_t.clone()
    }

    /// ε_N at the grid speeds of the last stick map.
    #[wasm_bindgen(js_name = mapEpsN)]
    pub fn map_eps_n(&self) -> Vec<f64> {
        self.map.eps_n.clone()
    }

    /// Grid speeds of the last stick map.
    #[wasm_bindgen(js_name = mapSpeeds)]
    pub fn map_speeds(&self) -> Vec<f64> {
        self.map.g.clone()
    }

    /// Critical velocities as JSON text (`[{key, label, value}]`).
    #[wasm_bindgen(js_name = criticalVelocities)]
    pub fn critical_velocities(&self, accuracy: &str) -> Result<String, JsError> {
        self.inner.critical_velocities(accuracy).map_err(js)
    }

    /// Warnings for the scene over `[from, to]` as JSON text (a list of strings).
    pub fn warnings(&self, from: f64, to: f64) -> Result<String, JsError> {
        self.inner.warnings(from, to).map_err(js)
    }

    /// The appendix values as JSON text; `input` is a TidalInput JSON or empty for the scene's grains.
    pub fn tidal(&self, input: &str) -> Result<String, JsError> {
        self.inner.tidal(input).map_err(js)
    }
}

impl Default for Explorer {
    fn default() -> Self {
        Explorer::new()
    }
}
