//! rime from Python: the native module `rime_grains._native` (PyO3 + rust-numpy).
//!
//! The Python package `rime_grains` wraps this module; its docstrings, type stubs and doctests
//! live in `python/rime_grains/`. Every function takes SI units, numpy in and numpy out, releases
//! the GIL while it computes, and raises `ValueError` naming the offending field (no panic reaches
//! Python: the crate denies `unwrap`/`expect`/`panic` like the rest of the workspace).

mod counters;
mod kernel;
mod rebound;
mod ring;

use numpy::{PyArray1, PyArrayDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString};
use rime_core::batch::BatchLaw;
use rime_core::explorer::limits::SPEED_MAX;
use rime_core::models::{Evaluator, Model};
use rime_core::params::Value;
use rime_core::{Accuracy, Contact, Preset, Scene, atlas};

/// A `ValueError` whose message starts with the field it is about.
pub(crate) fn value_error(field: &str, message: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(format!("{field}: {message}"))
}

/// The core's error as a `ValueError` (the core's messages already name the field).
pub(crate) fn core_error(e: rime_core::Error) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// Parses an accuracy name (`fast`, `balanced`, `precise`, `integrated`) or a tolerance (`1e-8`).
pub(crate) fn accuracy(text: &str) -> PyResult<Accuracy> {
    Accuracy::parse(text).map_err(|e| {
        let message = e.to_string();
        if message.starts_with("accuracy") {
            PyValueError::new_err(message)
        } else {
            value_error("accuracy", message)
        }
    })
}

/// A collision scene: two grains, the bulk, and optional layer, adhesion and friction (SI units).
#[pyclass(module = "rime_grains", name = "Scene", eq)]
#[derive(Clone, PartialEq)]
pub struct PyScene {
    pub(crate) scene: Scene,
}

#[pymethods]
impl PyScene {
    /// The `ice` preset.
    #[new]
    fn new() -> Self {
        PyScene {
            scene: Preset::Ice.scene(),
        }
    }

    /// A named preset: `ice`, `ice-frost`, `ice-sticky`, `ice-paper-viscosities`.
    #[staticmethod]
    fn preset(name: &str) -> PyResult<Self> {
        let preset = Preset::from_name(name).ok_or_else(|| {
            value_error(
                "name",
                format!(
                    "unknown preset '{name}' (one of {})",
                    preset_names().join(", ")
                ),
            )
        })?;
        Ok(PyScene {
            scene: preset.scene(),
        })
    }

    /// The preset names.
    #[staticmethod]
    fn presets() -> Vec<&'static str> {
        preset_names()
    }

    /// A scene from its JSON text (the `rime scene` form; unknown fields are refused).
    #[staticmethod]
    fn from_json(text: &str) -> PyResult<Self> {
        let mut de = serde_json::Deserializer::from_str(text);
        let scene: Scene = serde_path_to_error::deserialize(&mut de).map_err(|e| {
            let path = e.path().to_string();
            value_error(if path == "." { "scene" } else { &path }, e.into_inner())
        })?;
        scene.validate().map_err(core_error)?;
        Ok(PyScene { scene })
    }

    /// The scene as JSON text (what `rime scene` prints).
    fn to_json(&self) -> PyResult<String> {
        serde_json::to_string_pretty(&self.scene).map_err(|e| value_error("scene", e))
    }

    /// Sets one parameter by its dotted key, as `rime --set key=value`: a number in SI units, a
    /// string with units (`"2 um"`), a choice name, or `"on"`/`"off"` (also `True`/`False`) for an
    /// effect. The scene is checked as a whole; on error it is left unchanged.
    fn set(&mut self, key: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        let mut next = self.scene;
        let result = if value.is_instance_of::<PyBool>() {
            let on: bool = value.extract()?;
            next.set(key, if on { "on" } else { "off" })
        } else if value.is_instance_of::<PyString>() {
            let text: String = value.extract()?;
            next.set(key, &text)
        } else if value.is_instance_of::<PyFloat>() || value.is_instance_of::<PyInt>() {
            let v: f64 = value.extract()?;
            next.set_number(key, v)
        } else {
            return Err(value_error(
                key,
                format!(
                    "expected a number, a string or a bool (got {})",
                    value.get_type().name()?
                ),
            ));
        };
        result.map_err(|e| match e {
            rime_core::Error::UnknownParameter => value_error(
                key,
                "unknown parameter (see Scene.keys() or `rime help eps`)",
            ),
            other => {
                let text = other.to_string();
                if text.starts_with(key) {
                    PyValueError::new_err(text)
                } else {
                    value_error(key, text)
                }
            }
        })?;
        next.validate().map_err(core_error)?;
        self.scene = next;
        Ok(())
    }

    /// One parameter's value: a number (SI), a choice name, `True`/`False` for an effect, or `None`
    /// when it belongs to an effect that is off.
    fn get(&self, py: Python<'_>, key: &str) -> PyResult<Py<PyAny>> {
        let v = self.scene.get(key).map_err(|e| match e {
            rime_core::Error::UnknownParameter => value_error(key, "unknown parameter"),
            other => core_error(other),
        })?;
        Ok(match v {
            Value::Number(x) => x.into_pyobject(py)?.into_any().unbind(),
            Value::Choice(c) => c.into_pyobject(py)?.into_any().unbind(),
            Value::Enabled(b) => PyBool::new(py, b).to_owned().into_any().unbind(),
            Value::Inactive => py.None(),
        })
    }

    /// Every key `set` and `get` accept, with its SI unit.
    #[staticmethod]
    fn keys() -> Vec<(&'static str, &'static str)> {
        rime_core::params::PARAMETERS
            .iter()
            .map(|p| (p.path, p.unit))
            .collect()
    }

    /// A copy.
    fn copy(&self) -> Self {
        self.clone()
    }

    fn __copy__(&self) -> Self {
        self.clone()
    }

    fn __repr__(&self) -> String {
        let g = &self.scene.grains;
        let mut effects = Vec::new();
        if self.scene.layer.is_some() {
            effects.push("layer");
        }
        if self.scene.adhesion.is_some() {
            effects.push("adhesion");
        }
        if self.scene.friction.is_some() {
            effects.push("friction");
        }
        format!(
            "Scene(radius_1={:?} m, radius_2={:?} m, density={:?} kg/m³, A={:?} s, effects=[{}])",
            g.radius_1,
            g.radius_2,
            g.density,
            self.scene.damping_time(),
            effects.join(", ")
        )
    }
}

fn preset_names() -> Vec<&'static str> {
    [
        Preset::Ice,
        Preset::IceFrost,
        Preset::IceSticky,
        Preset::IcePaperViscosities,
    ]
    .iter()
    .map(|p| p.name())
    .collect()
}

fn contact_of(scene: &PyScene) -> PyResult<Contact> {
    Contact::new(&scene.scene).map_err(core_error)
}

/// `x` as a C-contiguous float64 numpy array of its own shape (a copy only when needed).
fn as_f64_array<'py>(
    py: Python<'py>,
    field: &str,
    x: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let np = py.import("numpy")?;
    let kwargs = PyDict::new(py);
    kwargs.set_item("dtype", "float64")?;
    kwargs.set_item("order", "C")?;
    // `asarray`, not `ascontiguousarray`: that one turns a number into a 1-d array.
    let a = np
        .getattr("asarray")?
        .call((x,), Some(&kwargs))
        .map_err(|e| {
            value_error(
                field,
                format!("expected numbers or an array of numbers ({e})"),
            )
        })?;
    a.cast_into::<PyArrayDyn<f64>>()
        .map_err(|e| value_error(field, e))
}

/// Checks that every value is an impact speed the models accept (0 allowed where `zero_ok`).
fn check_speeds(field: &str, g: &[f64], zero_ok: bool) -> PyResult<()> {
    for (i, &x) in g.iter().enumerate() {
        let ok = x.is_finite() && x <= SPEED_MAX && (x > 0.0 || (zero_ok && x == 0.0));
        if !ok {
            let lower = if zero_ok { ">= 0" } else { "> 0" };
            return Err(value_error(
                &format!("{field}[{i}]"),
                format!("a speed must be finite, {lower} and at most {SPEED_MAX:e} m/s (got {x})"),
            ));
        }
    }
    Ok(())
}

/// Reshapes a flat result to `shape`; a 0-d input gives a Python float.
fn shaped<'py>(py: Python<'py>, values: Vec<f64>, shape: &[usize]) -> PyResult<Bound<'py, PyAny>> {
    if shape.is_empty() {
        let v = values.first().copied().unwrap_or(f64::NAN);
        return Ok(PyFloat::new(py, v).into_any());
    }
    let flat = PyArray1::from_vec(py, values);
    Ok(flat.reshape(shape.to_vec())?.into_any())
}

/// ε_N at the impact speeds `g` [m/s].
#[pyfunction]
#[pyo3(signature = (g, scene, accuracy = "precise"))]
fn eps_n<'py>(
    py: Python<'py>,
    g: &Bound<'py, PyAny>,
    scene: PyRef<'py, PyScene>,
    accuracy: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let level = self::accuracy(accuracy)?;
    let contact = contact_of(&scene)?;
    let array = as_f64_array(py, "g", g)?;
    let shape = array.shape().to_vec();
    let ro = array.readonly();
    let speeds = ro.as_slice().map_err(|e| value_error("g", e))?;
    check_speeds("g", speeds, true)?;
    let mut out = vec![0.0; speeds.len()];
    let law = BatchLaw::new(&contact, level);
    py.detach(|| law.fill(speeds, &mut out))
        .map_err(core_error)?;
    shaped(py, out, &shape)
}

/// Broadcasts two inputs with numpy; returns both as flat float64 arrays and the shape.
fn broadcast_pair<'py>(
    py: Python<'py>,
    names: [&str; 2],
    a: &Bound<'py, PyAny>,
    b: &Bound<'py, PyAny>,
) -> PyResult<(Vec<f64>, Vec<f64>, Vec<usize>)> {
    let a = as_f64_array(py, names[0], a)?;
    let b = as_f64_array(py, names[1], b)?;
    let np = py.import("numpy")?;
    let pair = np
        .getattr("broadcast_arrays")?
        .call1((&a, &b))
        .map_err(|e| {
            value_error(
                &format!("{}, {}", names[0], names[1]),
                format!("shapes do not broadcast ({e})"),
            )
        })?;
    let mut flat = Vec::with_capacity(2);
    let mut shape = Vec::new();
    for (k, name) in names.iter().enumerate() {
        let x = as_f64_array(py, name, &pair.get_item(k)?)?;
        shape = x.shape().to_vec();
        flat.push(
            x.readonly()
                .as_slice()
                .map_err(|e| value_error(name, e))?
                .to_vec(),
        );
    }
    let second = flat.pop().unwrap_or_default();
    let first = flat.pop().unwrap_or_default();
    Ok((first, second, shape))
}

/// ε_T (Eq. (26)) at normal and tangential speeds `g_n`, `g_t` [m/s] (numpy broadcasting).
#[pyfunction]
#[pyo3(signature = (g_n, g_t, scene, accuracy = "precise"))]
fn eps_t<'py>(
    py: Python<'py>,
    g_n: &Bound<'py, PyAny>,
    g_t: &Bound<'py, PyAny>,
    scene: PyRef<'py, PyScene>,
    accuracy: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let (out, _, shape) = tangential_arrays(py, g_n, g_t, &scene, accuracy)?;
    shaped(py, out, &shape)
}

fn tangential_arrays<'py>(
    py: Python<'py>,
    g_n: &Bound<'py, PyAny>,
    g_t: &Bound<'py, PyAny>,
    scene: &PyScene,
    accuracy: &str,
) -> PyResult<(Vec<f64>, Vec<&'static str>, Vec<usize>)> {
    let level = self::accuracy(accuracy)?;
    let contact = contact_of(scene)?;
    if contact.friction.is_none() {
        return Err(value_error(
            "scene.friction",
            "ε_T needs friction (scene.set(\"friction\", \"on\"))",
        ));
    }
    let (gn, gt, shape) = broadcast_pair(py, ["g_n", "g_t"], g_n, g_t)?;
    check_speeds("g_n", &gn, false)?;
    check_speeds("g_t", &gt, true)?;
    let result = py.detach(|| -> rime_core::Result<(Vec<f64>, Vec<&'static str>)> {
        let mut eps = Vec::with_capacity(gn.len());
        let mut class = Vec::with_capacity(gn.len());
        for (&n, &t) in gn.iter().zip(&gt) {
            let r = contact.tangential(n, t, level)?;
            eps.push(r.eps_t);
            class.push(r.class.name());
        }
        Ok((eps, class))
    });
    let (eps, class) = result.map_err(core_error)?;
    Ok((eps, class, shape))
}

/// ε_T, ε_N and the stick-map class at (g_n, g_t): a dict of arrays (and a list of class names).
#[pyfunction]
#[pyo3(signature = (g_n, g_t, scene, accuracy = "precise"))]
fn tangential<'py>(
    py: Python<'py>,
    g_n: &Bound<'py, PyAny>,
    g_t: &Bound<'py, PyAny>,
    scene: PyRef<'py, PyScene>,
    accuracy: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let (eps, class, shape) = tangential_arrays(py, g_n, g_t, &scene, accuracy)?;
    let gn = as_f64_array(py, "g_n", g_n)?;
    let d = PyDict::new(py);
    d.set_item("eps_t", shaped(py, eps, &shape)?)?;
    d.set_item("eps_n", eps_n(py, gn.as_any(), scene, accuracy)?)?;
    d.set_item("class", PyList::new(py, class)?)?;
    Ok(d)
}

/// One collision from the inside, as `rime collision`: samples of ξ, ξ', F over the contact, the
/// phases, ε_N, the status and the energy ledger; with `g_t` also the tangential outcome.
#[pyfunction]
#[pyo3(signature = (g, scene, g_t = None, points = 400, accuracy = "precise"))]
fn collision<'py>(
    py: Python<'py>,
    g: f64,
    scene: PyRef<'py, PyScene>,
    g_t: Option<f64>,
    points: usize,
    accuracy: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let level = self::accuracy(accuracy)?;
    check_speeds("g", &[g], false)?;
    if !(2..=1_000_000).contains(&points) {
        return Err(value_error(
            "points",
            format!("must be an integer in [2, 1000000] (got {points})"),
        ));
    }
    let contact = contact_of(&scene)?;
    let tr = py
        .detach(|| contact.collision(g, points, level))
        .map_err(|e| value_error("g", e))?;
    let d = PyDict::new(py);
    d.set_item("g", g)?;
    d.set_item("eps_n", tr.eps_n)?;
    d.set_item("status", tr.status.name())?;
    d.set_item("t_c", tr.t_c)?;
    d.set_item("xi_max", tr.xi_max)?;
    d.set_item("resolved", tr.resolved)?;
    d.set_item("t", PyArray1::from_vec(py, tr.t))?;
    d.set_item("xi", PyArray1::from_vec(py, tr.xi))?;
    d.set_item("xi_dot", PyArray1::from_vec(py, tr.xi_dot))?;
    d.set_item("force", PyArray1::from_vec(py, tr.force))?;
    let phases = PyList::empty(py);
    for p in &tr.phases {
        let pd = PyDict::new(py);
        pd.set_item("name", p.name)?;
        pd.set_item("t", p.t)?;
        phases.append(pd)?;
    }
    d.set_item("phases", phases)?;
    let l = &tr.ledger;
    let ledger = PyDict::new(py);
    for (k, v) in [
        ("kinetic_in", l.kinetic_in),
        ("kinetic_out", l.kinetic_out),
        ("dissipated_bulk", l.dissipated_bulk),
        ("dissipated_layer", l.dissipated_layer),
        ("elastic_retained", l.elastic_retained),
        ("adhesion", l.adhesion),
        ("closure", l.closure),
    ] {
        ledger.set_item(k, v)?;
    }
    d.set_item("ledger", ledger)?;
    if let Some(gt) = g_t {
        check_speeds("g_t", &[gt], true)?;
        if contact.friction.is_none() {
            return Err(value_error(
                "g_t",
                "the scene has no friction (scene.set(\"friction\", \"on\"))",
            ));
        }
        let grains = &scene.scene.grains;
        let o = contact
            .oblique(grains.radius_1, grains.radius_2, g, gt, level)
            .map_err(|e| value_error("g_t", e))?;
        let od = PyDict::new(py);
        od.set_item("eps_t", o.eps_t)?;
        od.set_item("class", o.class.name())?;
        od.set_item("energy_before", o.energy_before)?;
        od.set_item("energy_after", o.energy_after)?;
        od.set_item("friction_work", o.friction_work)?;
        od.set_item("spin_change", o.spin_change.to_vec())?;
        d.set_item("tangential", od)?;
    }
    Ok(d)
}

/// The scene's critical speeds [m/s]: the layer's g_s (Eq. (10)), adhesion's g_s (Eq. (15)) and
/// the largest speed at which the grains stick (what the explorer's `v` panel marks); `None`
/// where the scene has no such speed.
#[pyfunction]
#[pyo3(signature = (scene, accuracy = "precise"))]
fn thresholds<'py>(
    py: Python<'py>,
    scene: PyRef<'py, PyScene>,
    accuracy: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let level = self::accuracy(accuracy)?;
    let contact = contact_of(&scene)?;
    let [layer, adhesion] = rime_core::explorer::range::critical_speeds(&contact);
    let stick = py
        .detach(|| rime_core::explorer::frame::stick_threshold(&contact, level))
        .map_err(core_error)?;
    let d = PyDict::new(py);
    d.set_item("layer", layer)?;
    d.set_item("adhesion", adhesion)?;
    d.set_item("stick", stick)?;
    Ok(d)
}

/// The measured laws' ids with their citations and formulas.
#[pyfunction]
fn laws(py: Python<'_>) -> PyResult<Bound<'_, PyList>> {
    let out = PyList::empty(py);
    for e in atlas::ENTRIES.iter().filter(|e| e.kind == atlas::Kind::Law) {
        let d = PyDict::new(py);
        d.set_item("id", e.id)?;
        d.set_item(
            "citation",
            format!(
                "{} ({}), {} {}",
                e.citation.authors, e.citation.year, e.citation.journal, e.citation.volume
            ),
        )?;
        d.set_item("formula", e.formula)?;
        d.set_item("valid_speed", e.valid_speed.to_vec())?;
        d.set_item("needs_radius", e.needs_radius())?;
        out.append(d)?;
    }
    Ok(out)
}

fn law_entry(id: &str) -> PyResult<&'static atlas::Entry> {
    atlas::find(id)
        .filter(|e| e.kind == atlas::Kind::Law)
        .ok_or_else(|| {
            let ids: Vec<&str> = atlas::ENTRIES
                .iter()
                .filter(|e| e.kind == atlas::Kind::Law)
                .map(|e| e.id)
                .collect();
            value_error(
                "id",
                format!("unknown law '{id}' (one of {})", ids.join(", ")),
            )
        })
}

/// A measured law evaluated at speeds `g` [m/s] (radius [m] for the laws that need one).
#[pyfunction]
#[pyo3(signature = (id, g, radius = None))]
fn law_eval<'py>(
    py: Python<'py>,
    id: &str,
    g: &Bound<'py, PyAny>,
    radius: Option<f64>,
) -> PyResult<Bound<'py, PyAny>> {
    let entry = law_entry(id)?;
    if entry.needs_radius() && radius.is_none() {
        return Err(value_error(
            "radius",
            format!("law '{id}' needs a grain radius [m]"),
        ));
    }
    if let Some(r) = radius
        && !(r.is_finite() && r > 0.0)
    {
        return Err(value_error(
            "radius",
            format!("must be finite and > 0 (got {r})"),
        ));
    }
    let array = as_f64_array(py, "g", g)?;
    let shape = array.shape().to_vec();
    let speeds = array
        .readonly()
        .as_slice()
        .map_err(|e| value_error("g", e))?
        .to_vec();
    check_speeds("g", &speeds, false)?;
    let out = speeds
        .iter()
        .map(|&x| entry.eval(x, radius).map(|v| v.eps))
        .collect::<rime_core::Result<Vec<f64>>>()
        .map_err(|e| value_error("g", e))?;
    shaped(py, out, &shape)
}

/// ε_N of several models (`rime compare --models`) and measured laws (`atlas:ID`) at speeds `g`:
/// a dict from each name to an array.
#[pyfunction]
#[pyo3(signature = (models, g, scene, accuracy = "precise"))]
fn compare<'py>(
    py: Python<'py>,
    models: Vec<String>,
    g: &Bound<'py, PyAny>,
    scene: PyRef<'py, PyScene>,
    accuracy: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let level = self::accuracy(accuracy)?;
    let array = as_f64_array(py, "g", g)?;
    let shape = array.shape().to_vec();
    let speeds = array
        .readonly()
        .as_slice()
        .map_err(|e| value_error("g", e))?
        .to_vec();
    check_speeds("g", &speeds, false)?;
    let contact = contact_of(&scene)?;
    let d = PyDict::new(py);
    if models.is_empty() {
        return Err(value_error("models", "name at least one model"));
    }
    for name in &models {
        let values = if let Some(id) = name.strip_prefix("atlas:") {
            let entry = law_entry(id)?;
            let radius = entry.needs_radius().then_some(contact.r_eff);
            speeds
                .iter()
                .map(|&x| entry.eval(x, radius).map(|v| v.eps))
                .collect::<rime_core::Result<Vec<f64>>>()
                .map_err(|e| value_error(name, e))?
        } else {
            let model = Model::from_name(name).ok_or_else(|| {
                let names: Vec<&str> = Model::ALL.iter().map(|m| m.name()).collect();
                value_error(
                    "models",
                    format!(
                        "unknown model '{name}' (one of {}, or atlas:ID)",
                        names.join(", ")
                    ),
                )
            })?;
            let ev = Evaluator::new(model, &scene.scene).map_err(|e| value_error(name, e))?;
            py.detach(|| {
                speeds
                    .iter()
                    .map(|&x| ev.eps(x, level).map(|r| r.eps))
                    .collect::<rime_core::Result<Vec<f64>>>()
            })
            .map_err(|e| value_error(name, e))?
        };
        d.set_item(name, shaped(py, values, &shape)?)?;
    }
    Ok(d)
}

/// Times ε_N over `g` at `accuracy` in Rust, without Python in the loop: seconds per call of the
/// batch path (the best of `repeats`), for the benchmark's comparison.
#[pyfunction]
#[pyo3(signature = (g, scene, accuracy = "fast", repeats = 5))]
fn bench_batch(
    py: Python<'_>,
    g: &Bound<'_, PyAny>,
    scene: PyRef<'_, PyScene>,
    accuracy: &str,
    repeats: usize,
) -> PyResult<f64> {
    let level = self::accuracy(accuracy)?;
    let contact = contact_of(&scene)?;
    let array = as_f64_array(py, "g", g)?;
    let speeds = array
        .readonly()
        .as_slice()
        .map_err(|e| value_error("g", e))?
        .to_vec();
    check_speeds("g", &speeds, true)?;
    let law = BatchLaw::new(&contact, level);
    let mut out = vec![0.0; speeds.len()];
    py.detach(|| {
        let mut best = f64::INFINITY;
        for _ in 0..repeats.max(1) {
            let start = std::time::Instant::now();
            law.fill(&speeds, &mut out)?;
            std::hint::black_box(&out);
            best = best.min(start.elapsed().as_secs_f64());
        }
        Ok(best)
    })
    .map_err(core_error)
}

/// The native module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyScene>()?;
    // The crate's version: the wheel's (pyproject.toml and the workspace agree, a test checks it).
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(eps_n, m)?)?;
    m.add_function(wrap_pyfunction!(ring::ring_equilibrium, m)?)?;
    m.add_function(wrap_pyfunction!(ring::ring_sizes_equilibrium, m)?)?;
    m.add_function(wrap_pyfunction!(eps_t, m)?)?;
    m.add_function(wrap_pyfunction!(tangential, m)?)?;
    m.add_function(wrap_pyfunction!(collision, m)?)?;
    m.add_function(wrap_pyfunction!(thresholds, m)?)?;
    m.add_function(wrap_pyfunction!(laws, m)?)?;
    m.add_function(wrap_pyfunction!(law_eval, m)?)?;
    m.add_function(wrap_pyfunction!(compare, m)?)?;
    m.add_function(wrap_pyfunction!(bench_batch, m)?)?;
    m.add_function(wrap_pyfunction!(kernel::kernel_table, m)?)?;
    m.add_function(wrap_pyfunction!(kernel::dustpy_p_stick, m)?)?;
    m.add_function(wrap_pyfunction!(kernel::dustpy_p_frag_step, m)?)?;
    rebound::register(m)?;
    Ok(())
}
