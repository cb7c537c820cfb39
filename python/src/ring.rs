//! `rime_grains.ring`: the ring's equilibrium (rime_core::ring, docs/physics.md#ring).

use crate::{PyScene, core_error, value_error};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rime_core::ring::{Orbit, RingInput, equilibrium, scaled_damping_time};
use rime_core::scene::Damping;

/// The ring's equilibrium: the same fields as `rime ring --format json`.
#[pyfunction]
#[pyo3(signature = (scene, *, tau, omega = None, planet_mass = None, distance = None, radius = None, scale_damping = false))]
#[allow(clippy::too_many_arguments)]
// Long by design: converts every Python argument at the boundary with a named error each, then one
// call.
pub(crate) fn ring_equilibrium<'py>(
    py: Python<'py>,
    scene: PyRef<'py, PyScene>,
    tau: f64,
    omega: Option<f64>,
    planet_mass: Option<f64>,
    distance: Option<f64>,
    radius: Option<f64>,
    scale_damping: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let orbit = match (omega, planet_mass, distance) {
        (Some(o), None, None) => Orbit::Omega(o),
        (None, Some(m), Some(d)) => Orbit::Planet {
            planet_mass: m,
            distance: d,
        },
        (Some(_), _, _) => {
            return Err(value_error(
                "omega",
                "give omega or planet_mass and distance, not both",
            ));
        }
        (None, Some(_), None) => return Err(value_error("distance", "required with planet_mass")),
        (None, None, Some(_)) => return Err(value_error("planet_mass", "required with distance")),
        (None, None, None) => {
            return Err(value_error(
                "omega",
                "required (or planet_mass and distance)",
            ));
        }
    };
    let mut s = scene.scene;
    let set_for = s.grains.radius_1;
    if let Some(r) = radius {
        s.grains.radius_1 = r;
        s.grains.radius_2 = r;
    }
    let r = s.grains.radius_1;
    if scale_damping {
        if r == set_for {
            return Err(value_error(
                "scale_damping",
                "only with a radius other than the scene's",
            ));
        }
        s.bulk.damping =
            Damping::Time(scaled_damping_time(s.damping_time(), set_for, r).map_err(core_error)?);
    }
    let input = RingInput {
        tau,
        orbit,
        damping_set_for_radius: (r != set_for && !scale_damping).then_some(set_for),
    };
    let rec = py.detach(|| equilibrium(&s, &input)).map_err(core_error)?;
    let note = if scale_damping {
        Some(format!(
            "A scaled to {} s = A·R/R_set for R = {} m (A was set for {} m grains): this keeps \
             ε_N(g) of the {} m grains and describes a different material",
            rec.damping_time, r, set_for, set_for
        ))
    } else {
        rec.scaled_damping_time.map(|a2| {
            format!(
                "the scene's A = {} s was set for {} m grains; grains of {} m keep that ε_N(g) \
                 with A' = {} s (scale_damping=True), a different material",
                rec.damping_time, set_for, r, a2
            )
        })
    };
    // The fields of the core's record, as `rime ring --format json` writes them: the flat ones
    // at the top, `smooth.*` and `rough.*` in their own dicts.
    let out = rime_core::explorer::records::RingOutput::new(&rec, note);
    let d = PyDict::new(py);
    let nested = [("smooth", PyDict::new(py)), ("rough", PyDict::new(py))];
    let put = |key: &str, value: Bound<'py, PyAny>| -> PyResult<()> {
        match key.split_once('.') {
            Some((outer, inner)) => match nested.iter().find(|(n, _)| *n == outer) {
                Some((_, m)) => m.set_item(inner, value),
                None => d.set_item(key, value),
            },
            None => d.set_item(key, value),
        }
    };
    for (k, v, _) in &out.values {
        put(k, v.into_pyobject(py)?.into_any())?;
    }
    for (k, w) in out.verdicts {
        put(k, w.into_pyobject(py)?.into_any())?;
    }
    d.set_item("equilibrium", out.equilibrium)?;
    d.set_item("verdict_words", out.verdict_words)?;
    d.set_item("damping_note", out.damping_note)?;
    for (k, m) in nested {
        d.set_item(k, m)?;
    }
    Ok(d)
}
