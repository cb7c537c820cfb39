//! Curves and stick maps, written into caller-provided slices (no allocation needed) or, with
//! feature `alloc`, returned as `Vec`s.
//!
//! A stick map over an `n × n` grid needs ε_N only at the `n` grid speeds (ε_N(g_N) on one axis and,
//! on the rolling branch, ε_N(g_T) on the other, which is the same grid): one evaluation per grid
//! speed, never one per cell.

use crate::error::{Error, Result};
use crate::normal::Normal;
use crate::numerics::accuracy::Accuracy;
use crate::scene::contact::Contact;
use crate::tangential::{StickClass, classify};

/// The grids every sweep spaces its speeds on (they live with the numerics).
pub use crate::numerics::grid::{exact_decade, linear_space, log_space};

/// ε_N and the rest at every speed of `g` (each > 0).
pub fn curve_into(
    contact: &Contact,
    g: &[f64],
    accuracy: Accuracy,
    out: &mut [Normal],
) -> Result<()> {
    if out.len() != g.len() {
        return Err(Error::InvalidValue {
            field: "out",
            expected: "a slice as long as the speeds",
        });
    }
    for (o, &gi) in out.iter_mut().zip(g) {
        *o = contact.normal(gi, accuracy)?;
    }
    Ok(())
}

/// ε_N at every speed of `g` (0 allowed: the limit value). Returns the integrator's right-hand-side
/// evaluations spent (0 on table paths).
pub fn eps_n_into(
    contact: &Contact,
    g: &[f64],
    accuracy: Accuracy,
    out: &mut [f64],
) -> Result<usize> {
    eps_n_into_with(contact, g, accuracy, out, &crate::normal::memo::NoMemo)
}

/// [`eps_n_into`] with the literal layer reading's outcomes kept in `memo`.
pub fn eps_n_into_with(
    contact: &Contact,
    g: &[f64],
    accuracy: Accuracy,
    out: &mut [f64],
    memo: &dyn crate::normal::memo::LayerMemo,
) -> Result<usize> {
    if out.len() != g.len() {
        return Err(Error::InvalidValue {
            field: "out",
            expected: "a slice as long as the speeds",
        });
    }
    let mut evaluations = 0;
    for (o, &gi) in out.iter_mut().zip(g) {
        if gi == 0.0 {
            *o = contact.eps_n_at_rest();
        } else {
            let n = contact.normal_with(gi, accuracy, memo)?;
            *o = n.eps;
            evaluations += n.rhs_evaluations;
        }
    }
    Ok(evaluations)
}

/// Classifies every cell of the square grid `g × g` from ε_N at the grid speeds; row-major:
/// `class[i * n + j]` is at g_N = `g[i]`, g_T = `g[j]`.
pub fn stick_map_into(
    contact: &Contact,
    g: &[f64],
    eps_n: &[f64],
    class: &mut [StickClass],
    eps_t: &mut [f64],
) -> Result<()> {
    let n = g.len();
    if eps_n.len() != n || class.len() != n * n || eps_t.len() != n * n {
        return Err(Error::InvalidValue {
            field: "out",
            expected: "eps_n of length n and class, eps_t of length n²",
        });
    }
    stick_map_rows_into(contact, g, eps_n, 0, class, eps_t)
}

/// The rows `first_row..` of [`stick_map_into`]'s grid, as many as `class` holds (`class.len() /
/// g.len()`): the same cells, so that rows may be classified apart (on several threads) and put
/// together.
pub fn stick_map_rows_into(
    contact: &Contact,
    g: &[f64],
    eps_n: &[f64],
    first_row: usize,
    class: &mut [StickClass],
    eps_t: &mut [f64],
) -> Result<()> {
    let n = g.len();
    let friction = contact.friction.ok_or(Error::InvalidValue {
        field: "friction",
        expected: "friction to be on for tangential restitution",
    })?;
    let rows = class.len().checked_div(n).unwrap_or(0);
    if eps_n.len() != n
        || class.len() != rows * n
        || eps_t.len() != class.len()
        || first_row + rows > n
    {
        return Err(Error::InvalidValue {
            field: "out",
            expected: "eps_n of length n and class, eps_t of whole rows inside the grid",
        });
    }
    for r in 0..rows {
        let i = first_row + r;
        for j in 0..n {
            let t = classify(g[i], g[j], eps_n[i], eps_n[j], &friction);
            class[r * n + j] = t.class;
            eps_t[r * n + j] = t.eps_t;
        }
    }
    Ok(())
}

/// A stick map with its grid (feature `alloc`).
#[cfg(feature = "alloc")]
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct StickMap {
    /// Grid speeds, 0 to max inclusive [m/s].
    #[cfg_attr(feature = "serde", serde(serialize_with = "crate::wire::f64s"))]
    pub g: alloc::vec::Vec<f64>,
    /// ε_N at the grid speeds.
    #[cfg_attr(feature = "serde", serde(serialize_with = "crate::wire::f64s"))]
    pub eps_n: alloc::vec::Vec<f64>,
    /// Row-major classes: `class[i * n + j]` at g_N = `g[i]`, g_T = `g[j]`; they cross as codes
    /// (the index in [`StickClass::ALL`]).
    #[cfg_attr(feature = "serde", serde(serialize_with = "class_codes"))]
    pub class: alloc::vec::Vec<StickClass>,
    /// Row-major ε_T.
    #[cfg_attr(feature = "serde", serde(serialize_with = "crate::wire::f64s"))]
    pub eps_t: alloc::vec::Vec<f64>,
    /// Integrator right-hand-side evaluations spent (ε_N once per grid speed, never per cell).
    pub rhs_evaluations: usize,
}

#[cfg(all(feature = "alloc", feature = "serde"))]
fn class_codes<S: serde::Serializer>(
    class: &[StickClass],
    s: S,
) -> core::result::Result<S::Ok, S::Error> {
    let codes: alloc::vec::Vec<u8> = class.iter().map(|c| c.code()).collect();
    crate::wire::u8s(&codes, s)
}

#[cfg(feature = "alloc")]
impl StickMap {
    /// Computes an `n × n` map from 0 to `max` (one ε_N evaluation per grid speed).
    pub fn new(contact: &Contact, max: f64, n: usize, accuracy: Accuracy) -> Result<StickMap> {
        use alloc::vec;
        let mut g = vec![0.0; n];
        linear_space(max, &mut g);
        let mut eps_n = vec![0.0; n];
        let rhs_evaluations = eps_n_into(contact, &g, accuracy, &mut eps_n)?;
        let mut class = vec![StickClass::Undefined; n * n];
        let mut eps_t = vec![0.0; n * n];
        stick_map_into(contact, &g, &eps_n, &mut class, &mut eps_t)?;
        Ok(StickMap {
            g,
            eps_n,
            class,
            eps_t,
            rhs_evaluations,
        })
    }

    /// Grid size `n`.
    pub fn n(&self) -> usize {
        self.g.len()
    }
}

/// `n` log-spaced ε_N results from `from` to `to` (feature `alloc`).
#[cfg(feature = "alloc")]
pub fn curve(
    contact: &Contact,
    from: f64,
    to: f64,
    n: usize,
    accuracy: Accuracy,
) -> Result<(alloc::vec::Vec<f64>, alloc::vec::Vec<Normal>)> {
    use alloc::vec;
    let mut g = vec![0.0; n];
    log_space(from, to, &mut g);
    let mut out = vec![
        Normal {
            eps: 0.0,
            status: crate::Status::Rebound,
            t_c: 0.0,
            xi_max: 0.0,
            error_estimate: 0.0,
            rhs_evaluations: 0,
        };
        n
    ];
    curve_into(contact, &g, accuracy, &mut out)?;
    Ok((g, out))
}
