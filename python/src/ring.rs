//! `rime_grains.ring`: the ring's equilibrium (rime_core::ring, docs/physics.md#ring).

use crate::{PyScene, core_error, value_error};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rime_core::ring::{Orbit, RingPatch, equilibrium};

/// The orbit from Ω or a planet's mass and distance, refused naming the field (both functions of
/// this module take the same three keywords).
fn orbit_of(
    omega: Option<f64>,
    planet_mass: Option<f64>,
    distance: Option<f64>,
) -> PyResult<Orbit> {
    match (omega, planet_mass, distance) {
        (Some(o), None, None) => Ok(Orbit::Omega(o)),
        (None, Some(m), Some(d)) => Ok(Orbit::Planet {
            planet_mass: m,
            distance: d,
        }),
        (Some(_), _, _) => Err(value_error(
            "omega",
            "give omega or planet_mass and distance, not both",
        )),
        (None, Some(_), None) => Err(value_error("distance", "required with planet_mass")),
        (None, None, Some(_)) => Err(value_error("planet_mass", "required with distance")),
        (None, None, None) => Err(value_error(
            "omega",
            "required (or planet_mass and distance)",
        )),
    }
}

/// The ring's equilibrium: the same fields as `rime ring --format json`.
#[pyfunction]
#[pyo3(signature = (scene, *, tau, omega = None, planet_mass = None, distance = None, radius = None, scale_damping = false, damping_set_for = None))]
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
    damping_set_for: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let orbit = orbit_of(omega, planet_mass, distance)?;
    // core_error names the field (`scale_damping: expected a radius other than the scene's …`).
    // A given for other grains than the scene's (issue 35): `damping_set_for`, else the scene's.
    let set_for = damping_set_for.unwrap_or(scene.scene.grains.radius_1);
    let patch =
        RingPatch::with_damping_set_for(&scene.scene, tau, orbit, radius, scale_damping, set_for)
            .map_err(|e| match e {
            rime_core::Error::OutOfRange {
                field: "set_for", ..
            } => value_error(
                "damping_set_for",
                format!("must be a finite radius > 0 m (got {set_for})"),
            ),
            e => core_error(e),
        })?;
    let rec = py
        .detach(|| equilibrium(&patch.scene, &patch.input))
        .map_err(core_error)?;
    let note = patch.damping_note(&rec, "scale_damping=True");
    // The fields of the core's record, as `rime ring --format json` writes them: the flat ones
    // at the top, `smooth.*` and `rough.*` in their own dicts.
    let viscosity = py
        .detach(|| rime_core::ring_sizes::one_size_viscosity(&patch.scene, &patch.input))
        .map_err(core_error)?;
    let out = rime_core::explorer::records::RingOutput::new(&rec, note).with_viscosity(viscosity);
    let d = PyDict::new(py);
    let nested = [
        ("smooth", PyDict::new(py)),
        ("rough", PyDict::new(py)),
        ("viscosity", PyDict::new(py)),
    ];
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
    put(
        "viscosity.overstability",
        viscosity.overstability.into_pyobject(py)?.into_any(),
    )?;
    d.set_item("equilibrium", out.equilibrium)?;
    d.set_item("verdict_words", out.verdict_words)?;
    d.set_item("damping_note", out.damping_note)?;
    for (k, m) in nested {
        d.set_item(k, m)?;
    }
    Ok(d)
}

/// A ring of many sizes (issue 38): the same JSON as `rime ring --radii … --format json`, as text
/// (`rime_grains.ring.equilibrium` parses it).
#[pyfunction]
#[pyo3(signature = (scene, *, tau, omega = None, planet_mass = None, distance = None, radius_min = None, radius_max = None, q = None, bins = 3, radii = None, fractions = None, damping_rule = "same"))]
#[allow(clippy::too_many_arguments)]
// Long by design: every keyword checked at the boundary with a named error, then one call.
pub(crate) fn ring_sizes_equilibrium(
    py: Python<'_>,
    scene: PyRef<'_, PyScene>,
    tau: f64,
    omega: Option<f64>,
    planet_mass: Option<f64>,
    distance: Option<f64>,
    radius_min: Option<f64>,
    radius_max: Option<f64>,
    q: Option<f64>,
    bins: usize,
    radii: Option<Vec<f64>>,
    fractions: Option<Vec<f64>>,
    damping_rule: &str,
) -> PyResult<String> {
    use rime_core::ring_sizes::{DampingRule, SizeDistribution, SizeRingInput};
    let orbit = orbit_of(omega, planet_mass, distance)?;
    let rule = match damping_rule {
        "same" => DampingRule::Same,
        "keep_epsilon" => DampingRule::KeepEpsilon,
        other => {
            return Err(value_error(
                "damping_rule",
                format!("expected 'same' or 'keep_epsilon' (got {other:?})"),
            ));
        }
    };
    let sizes = match (radius_min, radius_max, q, radii, fractions) {
        (Some(a), Some(b), Some(q), None, None) => SizeDistribution::PowerLaw {
            q,
            radius_min: a,
            radius_max: b,
            bins,
        },
        (None, None, None, Some(radii), fractions) => {
            let fractions = match fractions {
                Some(f) => f,
                None if radii.len() == 1 => vec![1.0],
                None => return Err(value_error("fractions", "required with a list of radii")),
            };
            SizeDistribution::List { radii, fractions }
        }
        (Some(_), Some(_), None, None, None) => {
            return Err(value_error("q", "required with radius_min and radius_max"));
        }
        _ => {
            return Err(value_error(
                "radii",
                "give radius_min, radius_max and q (a power law) or radii (and fractions), not both",
            ));
        }
    };
    let input = SizeRingInput {
        tau,
        orbit,
        sizes,
        damping_rule: rule,
    };
    let material = scene.scene;
    let rec = py
        .detach(|| rime_core::ring_sizes::equilibrium(&material, &input))
        .map_err(core_error)?;
    let mut v = serde_json::to_value(&rec).map_err(|e| value_error("ring", e.to_string()))?;
    if let Some(map) = v.as_object_mut() {
        // The keys `rime ring --radii` adds (tui/src/commands/ring.rs).
        map.insert("equilibrium".into(), rec.verdict.is_equilibrium().into());
        map.insert("verdict_words".into(), rec.verdict.words().into());
        map.insert(
            "prediction".into(),
            if rec.friction { "rough" } else { "smooth" }.into(),
        );
    }
    serde_json::to_string(&v).map_err(|e| value_error("ring", e.to_string()))
}
