//! `rime_grains.ring`: the ring's equilibrium (rime_core::ring, docs/physics.md#ring).

use crate::{PyScene, core_error, value_error};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rime_core::ring::{Orbit, Prediction, RingInput, equilibrium, scaled_damping_time};
use rime_core::scene::Damping;

fn prediction<'py>(py: Python<'py>, p: &Prediction) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("velocity_dispersion", p.velocity_dispersion)?;
    d.set_item("thickness", p.thickness)?;
    d.set_item("mean_impact_speed", p.mean_impact_speed)?;
    d.set_item("eps_effective", p.eps_effective)?;
    d.set_item("eps_cr", p.eps_cr)?;
    d.set_item("sticking_fraction", p.sticking_fraction)?;
    d.set_item("equilibration_orbits", p.equilibration_orbits)?;
    d.set_item("verdict", p.verdict.name())?;
    Ok(d)
}

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
    let p = rec.prediction();
    let d = PyDict::new(py);
    d.set_item("verdict", p.verdict.name())?;
    d.set_item("equilibrium", p.verdict.is_equilibrium())?;
    d.set_item("verdict_words", p.verdict.words())?;
    d.set_item("prediction", if rec.friction { "rough" } else { "smooth" })?;
    d.set_item("tau", rec.tau)?;
    d.set_item("omega", rec.omega)?;
    d.set_item("radius", rec.radius)?;
    d.set_item("eps_cr_dilute", rec.eps_cr)?;
    d.set_item("eps_cr", p.eps_cr)?;
    d.set_item("velocity_dispersion", p.velocity_dispersion)?;
    d.set_item(
        "velocity_dispersion_r_omega",
        p.velocity_dispersion / (rec.radius * rec.omega),
    )?;
    d.set_item("thickness", p.thickness)?;
    d.set_item("mean_impact_speed", p.mean_impact_speed)?;
    d.set_item("eps_effective", p.eps_effective)?;
    d.set_item("equilibration_orbits", p.equilibration_orbits)?;
    d.set_item("floor_dispersion", rec.floor_dispersion)?;
    d.set_item("damping_time", rec.damping_time)?;
    d.set_item("scaled_damping_time", rec.scaled_damping_time)?;
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
    d.set_item("damping_note", note)?;
    d.set_item("smooth", prediction(py, &rec.smooth)?)?;
    d.set_item("rough", prediction(py, &rec.rough)?)?;
    Ok(d)
}
