//! `rime_grains.kernel` and `rime_grains.dustpy`: the sticking speed of unequal pairs over radius ×
//! radius × temperature (rime_core::kernel, docs/physics.md#kernel), and the collision
//! probabilities DustPy's updaters return (docs/physics.md#python-dustpy).
//!
//! The physics is the core's; this file converts at the boundary (SI for the kernel, DustPy's cgs
//! for the probabilities) and names the field of every bad input.

use crate::{PyScene, core_error, value_error};
use numpy::{
    PyArray1, PyArray3, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray3, PyUntypedArrayMethods,
};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use rime_core::kernel::{self, ARule, KernelOptions, MeasuredSpeed, TemperatureRule};
use rime_core::stick::Convention;

/// The rule for A by name; `fit` (radius [m], temperature [K], speed [m/s]) only with
/// `fit_measured` (default there: Gundlach & Blum 2015).
fn a_rule(name: &str, fit: Option<(f64, f64, f64)>) -> PyResult<ARule> {
    // The command line's spellings (`keep-epsilon`) too.
    match (name.replace('-', "_").as_str(), fit) {
        ("given", None) => Ok(ARule::Given),
        ("keep_epsilon", None) => Ok(ARule::KeepEpsilon),
        ("fit_measured", None) => Ok(ARule::FitMeasured(MeasuredSpeed::GUNDLACH_2015)),
        ("fit_measured", Some((radius, temperature, speed))) => {
            Ok(ARule::FitMeasured(MeasuredSpeed {
                // The caller's own measurement: its source is kept by the Python side.
                entry: "user",
                radius,
                temperature,
                speed,
            }))
        }
        ("given" | "keep_epsilon", Some(_)) => Err(value_error(
            "fit",
            "only with a_rule=\"fit_measured\" (the other rules fit nothing)",
        )),
        (other, _) => Err(value_error(
            "a_rule",
            format!("unknown rule '{other}' (one of given, keep_epsilon, fit_measured)"),
        )),
    }
}

fn temperature_rule(name: &str) -> PyResult<TemperatureRule> {
    match name {
        "hold" => Ok(TemperatureRule::Hold),
        "refuse" => Ok(TemperatureRule::Refuse),
        other => Err(value_error(
            "temperature_rule",
            format!("unknown rule '{other}' (hold or refuse)"),
        )),
    }
}

fn convention(name: &str) -> PyResult<Convention> {
    match name {
        "surface" => Ok(Convention::SurfaceEnergy),
        "adhesion" => Ok(Convention::WorkOfAdhesion),
        other => Err(value_error(
            "convention",
            format!("unknown convention '{other}' (surface or adhesion)"),
        )),
    }
}

/// The sticking kernel: `v_stick` [m/s] flat, length T·N·N at `(t·N + i)·N + j` (infinite where
/// the pair sticks at every speed), the status codes (0 threshold, 1 always sticks) and a dict of
/// what it was computed with.
#[pyfunction]
#[pyo3(signature = (radii, temperatures, scene, *, a_rule = "given", fit = None, temperature_rule = "hold", convention = "surface", accuracy = "precise"))]
#[allow(clippy::too_many_arguments, clippy::type_complexity)]
// Long by design: every keyword checked at the boundary with a named error, then one call.
pub(crate) fn kernel_table<'py>(
    py: Python<'py>,
    radii: Vec<f64>,
    temperatures: Vec<f64>,
    scene: PyRef<'py, PyScene>,
    a_rule: &str,
    fit: Option<(f64, f64, f64)>,
    temperature_rule: &str,
    convention: &str,
    accuracy: &str,
) -> PyResult<(
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<u8>>,
    Bound<'py, PyDict>,
)> {
    let options = KernelOptions {
        a_rule: self::a_rule(a_rule, fit)?,
        convention: self::convention(convention)?,
        temperature_rule: self::temperature_rule(temperature_rule)?,
        accuracy: crate::accuracy(accuracy)?,
    };
    let base = scene.scene;
    // Temperatures spread over the machine's threads (bit for bit the one-thread table).
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let k = py
        .detach(|| kernel::table_parallel(&base, &radii, &temperatures, &options, threads))
        .map_err(core_error)?;
    let info = PyDict::new(py);
    let gammas = PyList::empty(py);
    for g in &k.gammas {
        let d = PyDict::new(py);
        d.set_item("temperature", g.temperature)?;
        d.set_item("gamma_source", g.gamma_source)?;
        d.set_item("gamma", g.gamma)?;
        d.set_item("range", g.range.name())?;
        gammas.append(d)?;
    }
    info.set_item("gammas", gammas)?;
    info.set_item("a_rule", k.a_rule.name())?;
    info.set_item("damping_time", k.damping_time)?;
    match k.fit {
        Some(f) => {
            let d = PyDict::new(py);
            d.set_item("entry", f.reference.entry)?;
            d.set_item("radius", f.reference.radius)?;
            d.set_item("temperature", f.reference.temperature)?;
            d.set_item("speed", f.reference.speed)?;
            d.set_item("damping_time", f.damping_time)?;
            d.set_item("achieved", f.achieved)?;
            d.set_item("v_elastic", f.v_elastic)?;
            info.set_item("fit", d)?;
        }
        None => info.set_item("fit", py.None())?,
    }
    info.set_item("convention", k.convention.name())?;
    info.set_item("temperature_rule", k.temperature_rule.name())?;
    info.set_item("method", k.method.name())?;
    info.set_item("gamma_entry", kernel::GAMMA_ENTRY)?;
    let measured = rime_core::atlas::find(kernel::GAMMA_ENTRY)
        .map(|e| e.temperature)
        .ok_or_else(|| value_error("atlas", "the musiolik2019 entry is missing"))?;
    info.set_item("measured_range", measured.to_vec())?;
    let status: Vec<u8> = k.status.iter().map(|s| s.code()).collect();
    Ok((
        PyArray1::from_vec(py, k.v_stick),
        PyArray1::from_vec(py, status),
        info,
    ))
}

/// The first entry of `values` that is not a relative speed (finite, ≥ 0), as an error naming
/// `field` and the index.
fn bad_speed(field: &str, values: &[f64], shape: [usize; 3]) -> Option<PyErr> {
    let at = values.iter().position(|v| !(v.is_finite() && *v >= 0.0))?;
    let (nm2, nm) = (shape[1] * shape[2], shape[2]);
    Some(value_error(
        &format!("{field}[{}, {}, {}]", at / nm2, at % nm2 / nm, at % nm),
        format!(
            "a relative speed must be finite and >= 0 cm/s (got {})",
            values[at]
        ),
    ))
}

/// P(v < v_s) for collision speeds with DustPy 1.0.9's distribution at rms speed Δv:
/// 1 − (1 + x) e^(−x), x = 3/2 (v_s/Δv)² (its `pfrag`'s F(v) = (1 + x) e^(−x) is the chance to
/// exceed v). Below x = 0.1 the series Σ_{n≥2} (−1)^n (n − 1) x^n / n! (to n = 10, truncation
/// below 1e-16 relative) avoids the cancellation of 1 − (1 + x) e^(−x).
fn maxwell_below(v_s: f64, dv: f64) -> f64 {
    let r = v_s / dv;
    let x = 1.5 * r * r;
    if x < 0.1 {
        // (−1)^n (n − 1)/n! for n = 2..10, Horner in x.
        const C: [f64; 9] = [
            0.5,
            -1.0 / 3.0,
            1.0 / 8.0,
            -1.0 / 30.0,
            1.0 / 144.0,
            -1.0 / 840.0,
            1.0 / 5760.0,
            -1.0 / 45360.0,
            1.0 / 403200.0,
        ];
        let mut sum = 0.0;
        for c in C.iter().rev() {
            sum = sum * x + c;
        }
        sum * x * x
    } else {
        1.0 - (1.0 + x) * (-x).exp()
    }
}

/// DustPy's sticking probability with rime's sticking speeds, every radial cell (cgs).
///
/// `v_rel` (Nr, Nm, Nm) [cm/s] is DustPy's `sim.dust.v.rel.tot` and `p_frag` its fragmentation
/// probability of this step; `tables` (K, Nm, Nm) [cm/s] are rime's sticking speeds (infinite:
/// always sticks), `cell_table` (Nr) the table of each cell (−1: none, the probability is 0 there,
/// DustPy's convention at its boundary cells). A collision sticks when its speed is below v_stick
/// and it does not fragment: p_stick = min(1 − p_frag, P(v < v_stick)). With `maxwell` the speeds
/// follow the distribution of DustPy 1.0.9's `pfrag` ([`maxwell_below`]), so with DustPy's
/// p_frag = F(v_frag), p_stick = 1 − F(min(v_stick, v_frag)); otherwise every collision has speed
/// Δv and P(v < v_stick) = [Δv < v_stick]. Where v_stick is infinite the result is DustPy's own
/// `1 − p_frag`, bit for bit. Computed from the upper triangle (j ≥ i, the one DustPy's `pfrag`
/// reads) and mirrored: symmetric in (i, j), p_stick + p_frag ≤ 1. Written into `out` (same shape)
/// when given, else into a new array, which is returned.
#[pyfunction]
#[pyo3(signature = (v_rel, p_frag, tables, cell_table, maxwell, out = None))]
pub(crate) fn dustpy_p_stick<'py>(
    py: Python<'py>,
    v_rel: PyReadonlyArray3<'py, f64>,
    p_frag: PyReadonlyArray3<'py, f64>,
    tables: PyReadonlyArray3<'py, f64>,
    cell_table: PyReadonlyArray1<'py, i64>,
    maxwell: bool,
    out: Option<Bound<'py, PyArray3<f64>>>,
) -> PyResult<Bound<'py, PyArray3<f64>>> {
    let shape = [v_rel.shape()[0], v_rel.shape()[1], v_rel.shape()[2]];
    let [nr, nm, _] = shape;
    if shape[2] != nm {
        return Err(value_error(
            "sim.dust.v.rel.tot",
            format!("expected shape (Nr, Nm, Nm) (got {shape:?})"),
        ));
    }
    if p_frag.shape() != shape {
        return Err(value_error(
            "sim.dust.p.frag",
            format!("expected shape {shape:?} (got {:?})", p_frag.shape()),
        ));
    }
    if cell_table.shape() != [nr] {
        return Err(value_error(
            "cell_table",
            format!("expected shape ({nr},) (got {:?})", cell_table.shape()),
        ));
    }
    let k = tables.shape()[0];
    if tables.shape()[1..] != [nm, nm] {
        return Err(value_error(
            "tables",
            format!("expected shape (K, {nm}, {nm}) (got {:?})", tables.shape()),
        ));
    }
    let v = v_rel
        .as_slice()
        .map_err(|e| value_error("sim.dust.v.rel.tot", e))?;
    let pf = p_frag
        .as_slice()
        .map_err(|e| value_error("sim.dust.p.frag", e))?;
    let tab = tables.as_slice().map_err(|e| value_error("tables", e))?;
    let cells = cell_table
        .as_slice()
        .map_err(|e| value_error("cell_table", e))?;
    if let Some(at) = cells.iter().position(|c| *c >= k as i64) {
        return Err(value_error(
            &format!("cell_table[{at}]"),
            format!("no table {} (there are {k})", cells[at]),
        ));
    }
    if let Some(at) = tab.iter().position(|x| x.is_nan() || *x <= 0.0) {
        return Err(value_error(
            &format!("tables[{at}]"),
            format!("a sticking speed must be > 0 cm/s (got {})", tab[at]),
        ));
    }
    let out = match out {
        Some(o) if o.shape() == shape => o,
        Some(o) => {
            return Err(value_error(
                "out",
                format!("expected shape {shape:?} (got {:?})", o.shape()),
            ));
        }
        None => PyArray1::from_vec(py, vec![0.0; nr * nm * nm]).reshape([nr, nm, nm])?,
    };
    let mut writable = out.try_readwrite().map_err(|e| value_error("out", e))?;
    let p = writable.as_slice_mut().map_err(|e| value_error("out", e))?;
    // The first entry read that is not a relative speed or a probability (index, which).
    let bad = py.detach(|| {
        for (ir, &table_of_cell) in cells.iter().enumerate() {
            let cell = ir * nm * nm;
            let Ok(t) = usize::try_from(table_of_cell) else {
                // No table: p_stick = 0 (DustPy's boundary cells).
                p[cell..cell + nm * nm].fill(0.0);
                continue;
            };
            let table = &tab[t * nm * nm..(t + 1) * nm * nm];
            for i in 0..nm {
                for j in i..nm {
                    let at = cell + i * nm + j;
                    let (v_s, dv, frag) = (table[i * nm + j], v[at], pf[at]);
                    if !(dv.is_finite() && dv >= 0.0) {
                        return Some((at, true));
                    }
                    if !(0.0..=1.0).contains(&frag) {
                        return Some((at, false));
                    }
                    // P(v < v_stick): 1 at v_stick = ∞ (and at Δv = 0), so 1 − p_frag exactly.
                    let below = if v_s == f64::INFINITY || dv == 0.0 {
                        1.0
                    } else if maxwell {
                        maxwell_below(v_s, dv)
                    } else if dv < v_s {
                        1.0
                    } else {
                        0.0
                    };
                    let value = (1.0 - frag).min(below);
                    p[at] = value;
                    p[cell + j * nm + i] = value;
                }
            }
        }
        None
    });
    if let Some((at, speed)) = bad {
        let (nm2, n) = (nm * nm, nm);
        let index = format!("[{}, {}, {}]", at / nm2, at % nm2 / n, at % n);
        return Err(if speed {
            value_error(
                &format!("sim.dust.v.rel.tot{index}"),
                format!(
                    "a relative speed must be finite and >= 0 cm/s (got {})",
                    v[at]
                ),
            )
        } else {
            value_error(
                &format!("sim.dust.p.frag{index}"),
                format!("a probability must lie in [0, 1] (got {})", pf[at]),
            )
        });
    }
    drop(writable);
    Ok(out)
}

/// Fragmentation without a velocity distribution: p_frag = 1 where Δv ≥ v_frag, else 0, from the
/// upper triangle and mirrored; 0 at the first and last radial cells (DustPy's `pfrag` computes
/// only the cells between).
#[pyfunction]
pub(crate) fn dustpy_p_frag_step<'py>(
    py: Python<'py>,
    v_rel: PyReadonlyArray3<'py, f64>,
    v_frag: PyReadonlyArray1<'py, f64>,
) -> PyResult<Bound<'py, PyArray3<f64>>> {
    let shape = [v_rel.shape()[0], v_rel.shape()[1], v_rel.shape()[2]];
    let [nr, nm, _] = shape;
    if shape[2] != nm || v_frag.shape() != [nr] {
        return Err(value_error(
            "sim.dust.v.rel.tot",
            format!(
                "expected shape (Nr, Nm, Nm) and v_frag (Nr,) (got {shape:?} and {:?})",
                v_frag.shape()
            ),
        ));
    }
    let v = v_rel
        .as_slice()
        .map_err(|e| value_error("sim.dust.v.rel.tot", e))?;
    let vf = v_frag
        .as_slice()
        .map_err(|e| value_error("sim.dust.v.frag", e))?;
    if let Some(e) = bad_speed("sim.dust.v.rel.tot", v, shape) {
        return Err(e);
    }
    let mut out = vec![0.0; nr * nm * nm];
    py.detach(|| {
        for (ir, &v_f) in vf.iter().enumerate().take(nr.saturating_sub(1)).skip(1) {
            let cell = ir * nm * nm;
            for i in 0..nm {
                for j in i..nm {
                    let p = if v[cell + i * nm + j] >= v_f {
                        1.0
                    } else {
                        0.0
                    };
                    out[cell + i * nm + j] = p;
                    out[cell + j * nm + i] = p;
                }
            }
        }
    });
    PyArray1::from_vec(py, out).reshape([nr, nm, nm])
}
