//! Batch ε_N: a slice of speeds in, a slice of ε_N out, a few nanoseconds per value at the fast level.
//!
//! The scalar fast path ([`Contact::eps_n`]) spends most of its ~50 ns in a logarithm, a Clenshaw sum
//! of ln ε and an exponential. The batch path needs none of them. ε depends on δ alone
//! (docs/physics.md#decision-3) and δ⁵ = A⁵ α² g is *linear* in the speed, so with `w = K g`,
//! `K = A⁵α²`, the float's own bits locate w on a universal grid: the exponent and the top
//! [`CELL_BITS`] bits of the mantissa pick a cell (2^CELL_BITS cells per binade of w, i.e. 0.015 in
//! u = log₁₀ δ), the remaining mantissa bits are a coordinate t ∈ [−1, 1) linear in w, and ε itself
//! (not ln ε) is a polynomial of degree [`BATCH_COEFFICIENTS`] − 1 in t. Per value: one multiply,
//! a few integer operations, one Horner sum; the offset layer (Eq. (9)–(10)) and adhesion (Eq. (17))
//! are composed in closed form exactly as [`Contact::normal`] composes them.
//!
//! The cells are fitted (Chebyshev interpolation, then the power basis) to the fine master table
//! ([`crate::normal::viscoelastic::master::Resolution::Fine`], ≤ 1e-10) and stored in the generated file
//! `batch_table.rs` (regenerate with `cargo run --release -p rime-core --example
//! generate_batch_table > core/src/normal/batch_table.rs`; after changing [`CELL_BITS`] or
//! [`BATCH_COEFFICIENTS`] first make both arrays empty of the new shape; a test fails when the file is
//! stale). Their relative
//! error against the fine table is ≤ [`TABLE_ERROR`].
//!
//! The rare speeds the cells do not cover go through the scalar path at
//! [`Accuracy::Precise`], value by value, so the result meets the fast level's bound (1e-6) at every
//! speed: below u ≈ −8.97 and beyond the tables' ends (the asymptotes), a zero or non-finite speed,
//! and rebounds within 5 % of the adhesion threshold in r² = (g_s/(ε_v g))² (there Eq. (17)
//! amplifies the error of ε_v by 1/(1 − r²); the fine table keeps it at the precise level's).
//! The literal layer reading and the levels without a table (balanced, precise, tolerances) go
//! through [`Contact::eps_n`] value by value.

use crate::error::{Error, Result};
use crate::numerics::accuracy::Accuracy;
use crate::numerics::math::powf;
use crate::scene::contact::Contact;
use crate::scene::{ContactEnd, LayerReading};

/// Cells per binade of w = δ⁵ are `2^CELL_BITS`.
pub const CELL_BITS: u32 = 2;
/// Power-basis coefficients per cell (polynomial degree + 1).
pub const BATCH_COEFFICIENTS: usize = 7;
/// Binary exponent of the lowest cell's w (u = log₁₀ δ ≥ −8.97, inside the master table).
pub const W_EXPONENT_MIN: i32 = -149;
/// One past the binary exponent of the highest force-zero cell (u < 6.99).
pub const W_EXPONENT_END_FORCE_ZERO: i32 = 116;
/// One past the binary exponent of the highest zero-overlap cell (u < 1.45).
pub const W_EXPONENT_END_ZERO_OVERLAP: i32 = 24;
/// Bound on the relative error of the cells against the fine master table (checked by a test).
pub const TABLE_ERROR: f64 = 1e-8;
/// Half-width in 1 − r² of the band around the adhesion threshold that the scalar path handles.
const ADHESION_BAND: f64 = 0.05;
/// Values processed per chunk (flags of the chunk live on the stack).
const CHUNK: usize = 256;

#[allow(clippy::all, missing_docs)]
mod generated {
    include!("batch_table.rs");
}

/// Number of cells of a table ending at binary exponent `end`.
pub const fn cells(end: i32) -> usize {
    ((end - W_EXPONENT_MIN) as usize) << CELL_BITS
}

/// The cells of a contact-end rule: `cells[i]` holds the power-basis coefficients in t.
pub fn table(end: ContactEnd) -> &'static [[f64; BATCH_COEFFICIENTS]] {
    match end {
        ContactEnd::ForceZero => &generated::FORCE_ZERO,
        ContactEnd::ZeroOverlap => &generated::ZERO_OVERLAP,
    }
}

/// The first cell's index in the bits of w: (biased exponent, top mantissa bits).
const BASE: u64 = ((W_EXPONENT_MIN + 1023) as u64) << CELL_BITS;
const MANTISSA: u64 = (1 << 52) - 1;
const ONE: u64 = 0x3ff0_0000_0000_0000;

/// Locates `w > 0` on the grid: (cell index, possibly out of range; t ∈ [−1, 1)).
#[inline(always)]
fn locate(w: f64) -> (usize, f64) {
    let bits = w.to_bits();
    let cell = ((bits >> (52 - CELL_BITS)).wrapping_sub(BASE)) as usize;
    let y = f64::from_bits(((bits << CELL_BITS) & MANTISSA) | ONE);
    (cell, 2.0 * y - 3.0)
}

#[inline(always)]
fn horner(c: &[f64; BATCH_COEFFICIENTS], t: f64) -> f64 {
    let mut p = c[BATCH_COEFFICIENTS - 1];
    for k in (0..BATCH_COEFFICIENTS - 1).rev() {
        p = p * t + c[k];
    }
    p
}

/// ε_N of one contact for many speeds, prepared once (see the module documentation).
#[derive(Debug, Clone, Copy)]
pub struct BatchLaw {
    contact: Contact,
    accuracy: Accuracy,
    /// The cells, or `None` when every value goes through [`Contact::eps_n`].
    table: Option<&'static [[f64; BATCH_COEFFICIENTS]]>,
    /// K = A⁵α² = δ⁵/g \[s/m\].
    scale: f64,
    /// g_s of the offset layer (0 without one), Eq. (10).
    layer_speed: f64,
    /// g_s of adhesion (0 without it), Eq. (15).
    adhesion_speed: f64,
}

impl BatchLaw {
    /// Prepares the batch law of `contact` at `accuracy` (cheap: a handful of constants).
    pub fn new(contact: &Contact, accuracy: Accuracy) -> BatchLaw {
        let literal = contact
            .layer
            .is_some_and(|l| l.reading == LayerReading::Literal && l.thickness > 0.0);
        let layer_speed = match contact.layer {
            Some(l) if l.reading == LayerReading::Offset && l.thickness > 0.0 => {
                l.critical_velocity
            }
            _ => 0.0,
        };
        let table = (accuracy == Accuracy::Fast && !literal).then(|| table(contact.contact_end));
        BatchLaw {
            contact: *contact,
            accuracy,
            table,
            // δ = 10^c g^(1/5) with c = log₁₀(A α^(2/5)), so δ⁵ = 10^(5c) g.
            scale: powf(10.0, 5.0 * contact.log10_delta_coefficient),
            layer_speed,
            adhesion_speed: contact.adhesion.map_or(0.0, |a| a.critical_velocity),
        }
    }

    /// Whether the batch cells serve this law (fast level, no literal layer).
    pub fn uses_table(&self) -> bool {
        self.table.is_some()
    }

    /// ε_N at one speed, value by value: |g| is the speed, NaN gives NaN, 0 the at-rest limit.
    pub fn eps_n_scalar(&self, g: f64) -> Result<f64> {
        let speed = g.abs();
        if speed.is_nan() {
            return Ok(f64::NAN);
        }
        let accuracy = if self.table.is_some() {
            Accuracy::Precise
        } else {
            self.accuracy
        };
        self.contact.eps_n(speed, accuracy)
    }

    /// Fills `out[i]` with ε_N at speed |`g[i]`| (NaN → NaN, 0 → the at-rest limit, 0 when the
    /// grains stick). Fails on mismatched lengths or a speed beyond 1e6 m/s; `out` is then only
    /// partly filled.
    pub fn fill(&self, g: &[f64], out: &mut [f64]) -> Result<()> {
        if g.len() != out.len() {
            return Err(Error::InvalidValue {
                field: "out",
                expected: "a slice as long as the speeds",
            });
        }
        let Some(table) = self.table else {
            for (o, &x) in out.iter_mut().zip(g) {
                *o = self.eps_n_scalar(x)?;
            }
            return Ok(());
        };
        match (self.layer_speed > 0.0, self.adhesion_speed > 0.0) {
            (false, false) => self.fill_table::<false, false>(table, g, out),
            (true, false) => self.fill_table::<true, false>(table, g, out),
            (false, true) => self.fill_table::<false, true>(table, g, out),
            (true, true) => self.fill_table::<true, true>(table, g, out),
        }
    }

    fn fill_table<const LAYER: bool, const ADHESION: bool>(
        &self,
        table: &[[f64; BATCH_COEFFICIENTS]],
        g: &[f64],
        out: &mut [f64],
    ) -> Result<()> {
        let n = table.len();
        let (scale, g_layer, g_adh) = (self.scale, self.layer_speed, self.adhesion_speed);
        let mut flags = [false; CHUNK];
        for (gc, oc) in g.chunks(CHUNK).zip(out.chunks_mut(CHUNK)) {
            let mut any = false;
            for ((&x, o), flag) in gc.iter().zip(oc.iter_mut()).zip(flags.iter_mut()) {
                let a = x.abs();
                // Eq. (9)–(10): the bulk is reached at g − g_s (stuck when g ≤ g_s).
                let bulk = if LAYER { a - g_layer } else { a };
                let (cell, t) = locate(bulk * scale);
                let inside = cell < n;
                let mut eps = horner(&table[if inside { cell } else { 0 }], t);
                let mut bad = !inside;
                if LAYER {
                    let stuck = a <= g_layer;
                    eps = if stuck { 0.0 } else { eps * bulk / a };
                    bad &= !stuck;
                }
                if ADHESION {
                    // Eq. (17) as `adhesion::apply`: ε_v √(1 − r²), r = g_s/(ε_v g).
                    let ratio = g_adh / (eps * a);
                    let q = (1.0 - ratio) * (1.0 + ratio);
                    eps = if q > 0.0 {
                        eps * crate::numerics::math::sqrt(q)
                    } else {
                        0.0
                    };
                    bad |= q.abs() < ADHESION_BAND;
                }
                bad |= !crate::scene::limits::speed_is_valid(a);
                *o = eps;
                *flag = bad;
                any |= bad;
            }
            if any {
                for ((&x, o), &flag) in gc.iter().zip(oc.iter_mut()).zip(flags.iter()) {
                    if flag {
                        *o = self.eps_n_scalar(x)?;
                    }
                }
            }
        }
        Ok(())
    }
}

impl Contact {
    /// ε_N for a slice of speeds (see [`crate::normal::batch`]): `out[i]` = ε_N(|`g[i]`|), with the bound of
    /// `accuracy` at every speed; NaN gives NaN, 0 the at-rest limit, 0 means the grains stick.
    /// At [`Accuracy::Fast`] this costs a few ns per value; prepare a [`BatchLaw`] to reuse it.
    pub fn eps_n_batch(&self, g: &[f64], out: &mut [f64], accuracy: Accuracy) -> Result<()> {
        BatchLaw::new(self, accuracy).fill(g, out)
    }
}

/// Generates the table source (the whole of `batch_table.rs`) from the fine master table.
#[cfg(feature = "std")]
pub fn generate_source() -> std::string::String {
    use core::fmt::Write;
    use std::string::String;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "// Generated by `cargo run --release -p rime-core --example generate_batch_table`. Do not edit.\n\
         // Power-basis coefficients of ε in t on cells of w = δ⁵ (crate::normal::batch)."
    );
    for (name, end, e_end) in [
        (
            "FORCE_ZERO",
            ContactEnd::ForceZero,
            W_EXPONENT_END_FORCE_ZERO,
        ),
        (
            "ZERO_OVERLAP",
            ContactEnd::ZeroOverlap,
            W_EXPONENT_END_ZERO_OVERLAP,
        ),
    ] {
        let n = cells(e_end);
        let _ = writeln!(
            out,
            "pub static {name}: [[f64; {BATCH_COEFFICIENTS}]; {n}] = ["
        );
        for cell in 0..n {
            let c = fit_cell(end, cell);
            let _ = write!(out, "    [");
            for (k, v) in c.iter().enumerate() {
                let _ = write!(out, "{}{v:e}", if k == 0 { "" } else { ", " });
            }
            let _ = writeln!(out, "],");
        }
        let _ = writeln!(out, "];");
    }
    out
}

/// w at coordinate `t` ∈ [−1, 1] of `cell`.
#[cfg(any(test, feature = "std"))]
fn cell_w(cell: usize, t: f64) -> f64 {
    let per = 1usize << CELL_BITS;
    let e = W_EXPONENT_MIN + (cell / per) as i32;
    let k = (cell % per) as f64;
    powf(2.0, e as f64) * (1.0 + (k + 0.5 * (t + 1.0)) / per as f64)
}

/// ε of the fine master table at w = δ⁵.
#[cfg(any(test, feature = "std"))]
fn fine_eps(w: f64, end: ContactEnd) -> f64 {
    let u = crate::numerics::math::log10(w) / 5.0;
    crate::normal::viscoelastic::master::eps_log10(
        u,
        end,
        crate::normal::viscoelastic::master::Resolution::Fine,
    )
}

/// Chebyshev interpolation of one cell, converted to the power basis.
#[cfg(feature = "std")]
fn fit_cell(end: ContactEnd, cell: usize) -> [f64; BATCH_COEFFICIENTS] {
    use core::f64::consts::PI;
    const N: usize = BATCH_COEFFICIENTS;
    let mut values = [0.0; N];
    for (j, v) in values.iter_mut().enumerate() {
        let t = libm::cos(PI * (j as f64 + 0.5) / N as f64);
        *v = fine_eps(cell_w(cell, t), end);
    }
    let mut cheb = [0.0; N];
    for (k, c) in cheb.iter_mut().enumerate() {
        let s: f64 = (0..N)
            .map(|j| values[j] * libm::cos(PI * k as f64 * (j as f64 + 0.5) / N as f64))
            .sum();
        *c = s * if k == 0 { 1.0 } else { 2.0 } / N as f64;
    }
    // Σ c_k T_k(t) in powers of t: T_{k+1} = 2t T_k − T_{k−1}.
    let mut power = [0.0; N];
    let (mut prev, mut cur) = ([0.0; N], [0.0; N]);
    prev[0] = 1.0; // T_0
    cur[1] = 1.0; // T_1
    for (k, &c) in cheb.iter().enumerate() {
        let tk = if k == 0 { prev } else { cur };
        for i in 0..N {
            power[i] += c * tk[i];
        }
        if k >= 1 && k + 1 < N {
            let mut next = [0.0; N];
            for i in 0..N {
                if i + 1 < N {
                    next[i + 1] += 2.0 * cur[i];
                }
                next[i] -= prev[i];
            }
            prev = cur;
            cur = next;
        }
    }
    power
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_match_the_fine_table_between_their_nodes() {
        let mut worst = 0.0f64;
        for end in [ContactEnd::ForceZero, ContactEnd::ZeroOverlap] {
            let t = table(end);
            for (i, c) in t.iter().enumerate() {
                for s in [-1.0, -0.71, -0.33, 0.05, 0.41, 0.77, 0.999] {
                    let w = cell_w(i, s);
                    let (cell, tt) = locate(w);
                    assert_eq!(cell, i);
                    let want = fine_eps(w, end);
                    worst = worst.max(((horner(c, tt) - want) / want).abs());
                }
            }
        }
        assert!(worst < TABLE_ERROR, "{worst:e}");
    }

    #[cfg(feature = "std")]
    #[test]
    fn batch_table_matches_a_fresh_generation() {
        let numbers = |text: &str| -> std::vec::Vec<f64> {
            text.lines()
                .filter(|l| l.trim_start().starts_with('['))
                .flat_map(|l| l.split(['[', ']', ',']))
                .filter_map(|t| t.trim().parse::<f64>().ok())
                .collect()
        };
        let fresh = numbers(&generate_source());
        let committed = numbers(include_str!("batch_table.rs"));
        assert_eq!(fresh.len(), committed.len(), "table shape changed");
        for (a, b) in fresh.iter().zip(&committed) {
            assert!(
                (a - b).abs() <= 1e-12 * (1.0 + b.abs()),
                "core/src/normal/batch_table.rs is stale ({a} vs {b}): regenerate it with \
                 `cargo run --release -p rime-core --example generate_batch_table > core/src/normal/batch_table.rs`"
            );
        }
    }
}
