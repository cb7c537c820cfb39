//! The JavaScript interface (wasm32 only). Every function delegates to the core's page logic
//! (`rime_core::explorer::{page, session, catalogue, share}`); this module only crosses the
//! boundary: text in, JSON text or the wire's flat arrays out, errors as exceptions.
//!
//! Codes: statuses are indices into `Explorer.statusNames()` (rebound, stuck_in_layer,
//! stuck_by_adhesion, overdamped); classes are indices into `Explorer.classes()` (legend order of
//! the core's `StickClass::ALL`).

use rime_core::explorer::page::{self, PageWire};
use rime_core::explorer::session::{self, Session};
use rime_core::explorer::{catalogue, share};
use rime_core::normal::memo::SharedLayerMemo;
use rime_core::wire::Wire;
use serde::Serialize;
use wasm_bindgen::prelude::*;

fn js(e: String) -> JsError {
    JsError::new(&e)
}

/// `value` as JSON text; a record that cannot be written is an exception naming `what`.
fn json<T: Serialize>(what: &str, value: &T) -> Result<String, JsError> {
    serde_json::to_string(value).map_err(|e| js(format!("{what}: {e}")))
}

/// A catalogue as JSON text (its records are plain data and always write; `null` otherwise).
fn catalogue_json<T: Serialize>(value: &T) -> String {
    serde_json::to_string(value).unwrap_or_else(|_| "null".to_string())
}

/// The literal layer reading's outcomes kept between this worker's frames (issue 26): an edit that
/// leaves the layer stage's inputs unchanged is answered without integrating again. Each worker
/// instantiates the module, so each has its own.
static LAYER_MEMO: SharedLayerMemo = SharedLayerMemo::new();

/// One frame of the page (`rime_core::explorer::page`): its wire form, a JSON description and two
/// flat arrays it points into, and its records. Each getter hands its part over once (a second
/// call returns it empty).
#[wasm_bindgen]
pub struct Frame {
    inner: PageWire,
}

#[wasm_bindgen]
impl Frame {
    /// The frame's JSON: parts, `{at, len}` offsets into `numbers()`/`codes()`, and `errors`.
    pub fn json(&mut self) -> String {
        std::mem::take(&mut self.inner.wire.json)
    }

    /// Every floating-point array of the frame, concatenated.
    pub fn numbers(&mut self) -> Vec<f64> {
        std::mem::take(&mut self.inner.wire.numbers)
    }

    /// Every code array (statuses, stick classes), concatenated.
    pub fn codes(&mut self) -> Vec<u8> {
        std::mem::take(&mut self.inner.wire.codes)
    }

    /// The records (JSON, `null` for a view with `records: false`) as UTF-8 bytes: handed to the
    /// page without a copy and parsed only when a download asks for them.
    pub fn records(&mut self) -> Vec<u8> {
        std::mem::take(&mut self.inner.records).into_bytes()
    }
}

/// The whole frame of `scene` (JSON) seen through `view` (JSON) in one call. Throws only for a
/// request that is not valid (naming the field); a part that fails is listed in the frame's
/// `errors` and the other parts are drawn.
#[wasm_bindgen(js_name = computeFrame)]
pub fn compute_frame(scene: &str, view: &str) -> Result<Frame, JsError> {
    Ok(Frame {
        inner: page::frame(scene, view, &LAYER_MEMO).map_err(js)?,
    })
}

/// A frame computed with another worker's help (`rime_core::explorer::share`): `new PendingFrame(scene,
/// view, of)` plans it, `runNext()` computes this worker's units one at a time, `accept(numbers,
/// meta)` takes the helper's share, `finish()` computes what is missing and returns the [`Frame`],
/// the one `computeFrame` returns, bit for bit.
#[wasm_bindgen]
pub struct PendingFrame {
    inner: Option<share::Pending>,
}

#[wasm_bindgen]
impl PendingFrame {
    /// Plans the frame of `scene` seen through `view` with `of − 1` helpers.
    #[wasm_bindgen(constructor)]
    pub fn new(scene: &str, view: &str, of: usize) -> Result<PendingFrame, JsError> {
        Ok(PendingFrame {
            inner: Some(share::Pending::begin(scene, view, of).map_err(js)?),
        })
    }

    /// Computes this worker's next unit; false when none is left.
    #[wasm_bindgen(js_name = runNext)]
    pub fn run_next(&mut self) -> Result<bool, JsError> {
        self.pending()?.run_next(&LAYER_MEMO).map_err(js)
    }

    /// Takes a helper's share (its wire form); false when it is not a share of this frame's plan.
    pub fn accept(&mut self, numbers: &[f64], codes: &[u8], json: &str) -> Result<bool, JsError> {
        let share = Wire {
            json: json.to_string(),
            numbers: numbers.to_vec(),
            codes: codes.to_vec(),
        };
        Ok(self.pending()?.accept(&share))
    }

    /// Computes what is missing and returns the frame (once).
    pub fn finish(&mut self) -> Result<Frame, JsError> {
        let pending = self
            .inner
            .take()
            .ok_or_else(|| js("frame: already finished".into()))?;
        Ok(Frame {
            inner: pending.finish(&LAYER_MEMO).map_err(js)?,
        })
    }

    fn pending(&mut self) -> Result<&mut share::Pending, JsError> {
        self.inner
            .as_mut()
            .ok_or_else(|| js("frame: already finished".into()))
    }
}

/// A helper's share of another worker's frame (`rime_core::explorer::share`), a unit per `step()`.
#[wasm_bindgen]
pub struct FrameShare {
    inner: Option<share::ShareRun>,
    done: Wire,
}

#[wasm_bindgen]
impl FrameShare {
    /// Plans the frame of `scene` seen through `view` and lists the units of share `share` of `of`.
    #[wasm_bindgen(constructor)]
    pub fn new(scene: &str, view: &str, share: usize, of: usize) -> Result<FrameShare, JsError> {
        Ok(FrameShare {
            inner: Some(share::ShareRun::begin(scene, view, share, of).map_err(js)?),
            done: Wire::default(),
        })
    }

    /// Computes the next unit; false when the share is complete (then `numbers()`, `codes()` and
    /// `meta()`, its wire form).
    pub fn step(&mut self) -> Result<bool, JsError> {
        let Some(run) = self.inner.as_mut() else {
            return Ok(false);
        };
        let more = run.step(&LAYER_MEMO).map_err(js)?;
        if !more && let Some(run) = self.inner.take() {
            self.done = run.finish().map_err(js)?;
        }
        Ok(more)
    }

    /// The share's numbers (once complete; handed over once).
    pub fn numbers(&mut self) -> Vec<f64> {
        std::mem::take(&mut self.done.numbers)
    }

    /// The share's codes (once complete; handed over once).
    pub fn codes(&mut self) -> Vec<u8> {
        std::mem::take(&mut self.done.codes)
    }

    /// The share's JSON (once complete).
    pub fn meta(&mut self) -> String {
        std::mem::take(&mut self.done.json)
    }
}

/// The stick map's records from the frame's arrays (`rime_core::explorer::page::map_records`).
#[wasm_bindgen(js_name = mapRecords)]
pub fn map_records(g: &[f64], eps_t: &[f64], codes: &[u8]) -> Result<String, JsError> {
    page::map_records(g, eps_t, codes).map_err(js)
}

/// The ring card (issue 24) for `scene` and `input` (JSON; `rime_core::explorer::page::ring_page`):
/// `{verdict, equilibrium, sentence, rows: [{label, text}], eps_cr_line: {name, short, points,
/// color, stroke}, meeting: [g, ε] | null, impact_marker: {x, label, short, color}, record}`.
/// Throws naming the field (`ring.tau: …`).
#[wasm_bindgen(js_name = ringCard)]
pub fn ring_card(scene: &str, input: &str) -> Result<String, JsError> {
    json("ring", &page::ring_page(scene, input).map_err(js)?)
}

/// The one colour palette of every surface (`rime_core::explorer::palette::palette_json`).
#[wasm_bindgen]
pub fn palette() -> String {
    rime_core::explorer::palette::palette_json()
}

/// The page's words: citation, glossary, parameter help, option names
/// (`rime_core::explorer::catalogue::help`).
#[wasm_bindgen]
pub fn help() -> String {
    catalogue_json(&catalogue::help())
}

/// The ring card's grain-size choices `[{name, label}]` in order
/// (`rime_core::explorer::catalogue::ring_sizes`).
#[wasm_bindgen(js_name = ringSizes)]
pub fn ring_sizes() -> String {
    catalogue_json(&catalogue::ring_sizes())
}

/// `v` with `digits` significant digits (`rime_core::explorer::format::sig`); `—` when not finite.
#[wasm_bindgen(js_name = fmtSig)]
pub fn fmt_sig(v: f64, digits: i32) -> String {
    rime_core::explorer::format::sig(v, digits.clamp(1, 17))
}

/// A quantity with its unit and an SI prefix (`rime_core::explorer::format::qty_sig`).
#[wasm_bindgen(js_name = fmtQty)]
pub fn fmt_qty(v: f64, unit: &str, digits: i32) -> String {
    rime_core::explorer::format::qty_sig(v, unit, digits.clamp(1, 17))
}

/// The shortest text that reads back as `v` (`rime_core::explorer::format::shortest`).
#[wasm_bindgen(js_name = fmtShortest)]
pub fn fmt_shortest(v: f64) -> String {
    rime_core::explorer::format::shortest(v)
}

/// The value a user edits (`rime_core::explorer::format::editable`).
#[wasm_bindgen(js_name = fmtEditable)]
pub fn fmt_editable(v: f64, unit: &str) -> String {
    rime_core::explorer::format::editable(v, unit)
}

/// A decade label of a log axis (`rime_core::explorer::format::decade`).
#[wasm_bindgen(js_name = fmtDecade)]
pub fn fmt_decade(k: i32) -> String {
    rime_core::explorer::format::decade(k)
}

/// The ticks of an axis from `min` to `max` (log or linear) with at most `max_labels` labels, by
/// the core's one axis rule (`rime_core::figure::Axis::ticks`, which the terminal and the exported
/// SVG/PNG draw too; at most [`rime_core::figure::IMAGE_LABELS`] labels, the images' count) as
/// JSON `[[value, …], [label | null, …]]`.
#[wasm_bindgen(js_name = axisTicks)]
pub fn axis_ticks(min: f64, max: f64, log: bool, max_labels: usize) -> String {
    let axis = rime_core::figure::Axis {
        label: String::new(),
        log,
        min,
        max,
    };
    let ticks = axis.ticks(max_labels.min(rime_core::figure::IMAGE_LABELS));
    let values: Vec<f64> = ticks.iter().map(|t| t.value).collect();
    let labels: Vec<Option<&str>> = ticks.iter().map(|t| t.label.as_deref()).collect();
    serde_json::to_string(&(values, labels)).unwrap_or_default()
}

/// Whether `computed` reproduces `printed` to its printed digits
/// (`rime_core::explorer::format::agrees_to_printed`).
#[wasm_bindgen(js_name = agreesToPrinted)]
pub fn agrees_to_printed(computed: f64, printed: f64) -> bool {
    rime_core::explorer::format::agrees_to_printed(computed, printed)
}

/// The significant digits a number is printed with (`rime_core::explorer::format::printed_digits`).
#[wasm_bindgen(js_name = printedDigits)]
pub fn printed_digits(v: f64) -> i32 {
    rime_core::explorer::format::printed_digits(v)
}

/// A typed speed with optional units for the view field `field` (`session::parse_speed`).
#[wasm_bindgen(js_name = parseSpeed)]
pub fn parse_speed(field: &str, text: &str) -> Result<f64, JsError> {
    session::parse_speed(field, text).map_err(js)
}

/// A typed end of the chart's speed range (`session::parse_chart_speed`).
#[wasm_bindgen(js_name = parseChartSpeed)]
pub fn parse_chart_speed(field: &str, text: &str) -> Result<f64, JsError> {
    session::parse_chart_speed(field, text).map_err(js)
}

/// A typed quantity with optional units compatible with `unit` (`session::parse_quantity`).
#[wasm_bindgen(js_name = parseQuantity)]
pub fn parse_quantity(field: &str, text: &str, unit: &str) -> Result<f64, JsError> {
    session::parse_quantity(field, text, unit).map_err(js)
}

/// A scene being edited: validation of typed values, presets and readouts
/// (`rime_core::explorer::session::Session`).
#[wasm_bindgen]
pub struct Explorer {
    inner: Session,
}

#[wasm_bindgen]
impl Explorer {
    /// The default (`ice`) scene.
    #[wasm_bindgen(constructor)]
    pub fn new() -> Explorer {
        Explorer {
            inner: Session::new(),
        }
    }

    /// An explorer for a scene given as JSON; throws naming the offending field.
    #[wasm_bindgen(js_name = fromJson)]
    pub fn from_json(text: &str) -> Result<Explorer, JsError> {
        let mut e = Explorer::new();
        e.inner = Session::from_json(text).map_err(js)?;
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

    /// The name of the preset whose scene this is, or `undefined`.
    pub fn preset(&self) -> Option<String> {
        self.inner.preset().map(String::from)
    }

    /// A parameter's value as JSON text (number, choice name, boolean, or `null` when inactive).
    pub fn get(&self, path: &str) -> Result<String, JsError> {
        json(path, &self.inner.get(path).map_err(js)?)
    }

    /// The parameter registry as JSON text.
    pub fn parameters() -> String {
        catalogue_json(&catalogue::parameters())
    }

    /// What can be drawn over the ε_N chart (measured ice, other models) as JSON.
    pub fn overlays() -> String {
        catalogue_json(&catalogue::overlays())
    }

    /// The presets as JSON text (`[{name, description}]`).
    pub fn presets() -> String {
        catalogue_json(&catalogue::presets())
    }

    /// The stick classes in code order as JSON text (`[{name, letter, description}]`).
    pub fn classes() -> String {
        catalogue_json(&catalogue::classes())
    }

    /// The status names in code order as JSON text.
    #[wasm_bindgen(js_name = statusNames)]
    pub fn status_names() -> String {
        catalogue_json(&catalogue::statuses())
    }

    /// The experimental context of the ε_N chart as JSON text: `{bridges: {a, b, g0, label},
    /// bands: [{x: [lo, hi], y: [lo, hi], label}]}` (Bridges et al. 1984; Heißelmann et al. 2010,
    /// Hill et al. 2015).
    pub fn experiments() -> String {
        catalogue_json(&catalogue::experiments())
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

    /// The normal result at one speed as JSON text.
    pub fn normal(&self, g: f64, accuracy: &str) -> Result<String, JsError> {
        json("normal", &self.inner.normal(g, accuracy).map_err(js)?)
    }

    /// ε_N for a Float64Array of speeds (|g|; NaN → NaN, 0 → the at-rest limit, 0 when stuck)
    /// through the core's batch path (`rime_core::batch`); at most 1e7 speeds. Feature `batch`
    /// (not in the page's module, which does not call it).
    #[cfg(feature = "batch")]
    #[wasm_bindgen(js_name = epsNBatch)]
    pub fn eps_n_batch(&self, speeds: &[f64], accuracy: &str) -> Result<Vec<f64>, JsError> {
        self.inner.eps_n_batch(speeds, accuracy).map_err(js)
    }

    /// One collision from the inside at `g` for the current scene, as JSON
    /// (`Session::collision`).
    pub fn collision(&self, g: f64, points: f64, accuracy: &str) -> Result<String, JsError> {
        let points = session::whole("points", points).map_err(js)?;
        json(
            "collision",
            &self.inner.collision(g, points, accuracy).map_err(js)?,
        )
    }

    /// Fits A to a measured law (`id`) and makes the fitted scene current; JSON
    /// (`Session::fit_to_entry`). Throws naming the cause; the scene is then unchanged.
    #[wasm_bindgen(js_name = fitToEntry)]
    pub fn fit_to_entry(&mut self, id: &str, accuracy: &str) -> Result<String, JsError> {
        json("fit", &self.inner.fit_to_entry(id, accuracy).map_err(js)?)
    }

    /// The tangential result at one point as JSON text.
    pub fn tangential(&self, g_n: f64, g_t: f64, accuracy: &str) -> Result<String, JsError> {
        json(
            "tangential",
            &self.inner.tangential(g_n, g_t, accuracy).map_err(js)?,
        )
    }

    /// The appendix values as JSON text; `input` is a TidalInput JSON or empty for the scene's grains.
    pub fn tidal(&self, input: &str) -> Result<String, JsError> {
        json("tidal", &self.inner.tidal(input).map_err(js)?)
    }
}

impl Default for Explorer {
    fn default() -> Self {
        Explorer::new()
    }
}
