//! The figure of a kernel: v_stick(a, a) against a, one curve per temperature, with the atlas's
//! measured sticking speed (`rime kernel --svg`).

use super::{Kernel, StickStatus};
use crate::error::{Error, Result};
use crate::figure::format::qty;
use crate::figure::{Axis, Figure, Series, Stroke};
use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec::Vec;

/// Palette indices of the temperatures' curves (the family, then the overlays).
const COLORS: [usize; 9] = [0, 1, 2, 3, 8, 9, 10, 11, 12];
/// Strokes, cycled once the colours are used.
const STROKES: [Stroke; 4] = [
    Stroke::Solid,
    Stroke::Dashed,
    Stroke::Dotted,
    Stroke::LongDash,
];
/// Highest speed drawn \[m/s\]: far above any disk's relative speeds (the table keeps every
/// value up to 1e6 m/s).
const Y_MAX: f64 = 1e3;
/// Most temperatures a figure draws (every curve keeps its own colour and stroke).
pub const MAX_CURVES: usize = COLORS.len() * STROKES.len();

/// `v_stick(a, a)` of `k`'s diagonal against `a`, one curve per temperature (a gap where the
/// grains stick at every speed), and Gundlach & Blum (2015)'s measured 9.6 m/s of µm ice over
/// their grain radii (the atlas' `gundlach2015`). Errors name `temperatures` when there are more
/// than [`MAX_CURVES`].
pub fn diagonal_figure(k: &Kernel) -> Result<Figure> {
    if k.gammas.len() > MAX_CURVES {
        return Err(Error::InvalidValue {
            field: "temperatures",
            expected: "at most 36 temperatures in one figure",
        });
    }
    let n = k.n();
    let mut series = Vec::new();
    let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
    for (t, g) in k.gammas.iter().enumerate() {
        let points: Vec<(f64, f64)> = (0..n)
            .map(|i| {
                let idx = k.index(t, i, i);
                let v = match k.status[idx] {
                    StickStatus::Threshold if k.v_stick[idx] <= Y_MAX => k.v_stick[idx],
                    _ => f64::NAN,
                };
                if v.is_finite() {
                    lo = lo.min(v);
                    hi = hi.max(v);
                }
                (k.radii[i], v)
            })
            .collect();
        let held = match g.range {
            super::GammaRange::Measured => "",
            super::GammaRange::HeldCold => ", γ held at its 175 K value",
            super::GammaRange::HeldWarm => ", γ held at its 200 K value",
        };
        series.push(Series {
            name: format!(
                "T = {} (γ = {}{held})",
                qty(g.temperature, "K"),
                qty(g.gamma_source, "J/m²")
            ),
            short: format!("{} K", crate::figure::format::sig(g.temperature, 4)),
            points,
            color: COLORS[t % COLORS.len()],
            stroke: STROKES[(t / COLORS.len()) % STROKES.len()],
        });
    }
    let x_lo = k.radii.iter().copied().fold(f64::INFINITY, f64::min);
    let x_hi = k.radii.iter().copied().fold(0.0, f64::max);
    if let Some(e) = crate::atlas::find("gundlach2015") {
        let [r_lo, r_hi] = e.radius;
        let v = crate::stick::MEASURED_UM_ICE;
        if r_hi >= x_lo && r_lo <= x_hi {
            lo = lo.min(v);
            hi = hi.max(v);
            series.push(Series {
                name: format!(
                    "measured: µm ice sticks below {} (Gundlach & Blum 2015, T ≲ 210 K, radii {}–{})",
                    qty(v, "m/s"),
                    qty(r_lo, "m"),
                    qty(r_hi, "m")
                ),
                short: "Gundlach'15".to_string(),
                points: alloc::vec![(r_lo.max(x_lo), v), (r_hi.min(x_hi), v)],
                color: crate::figure::palette::SERIES_EXPERIMENT,
                stroke: Stroke::Dashed,
            });
            let at = super::MeasuredSpeed::GUNDLACH_2015.radius;
            if (x_lo..=x_hi).contains(&at) {
                series.push(Series {
                    name: format!(
                        "Gundlach & Blum 2015 at {} (their mean grain)",
                        qty(at, "m")
                    ),
                    short: "Gundlach'15".to_string(),
                    points: alloc::vec![(at, v)],
                    color: crate::figure::palette::SERIES_EXPERIMENT,
                    stroke: Stroke::Points,
                });
            }
        }
    }
    if !(lo <= hi) {
        // Nothing rebounds anywhere: an empty decade around 1 m/s keeps the axes valid.
        (lo, hi) = (0.1, 10.0);
    }
    let (y_lo, y_hi) = (lo / 3.0, (hi * 3.0).min(Y_MAX));
    let fit = k.fit.map_or(String::new(), |f| {
        format!(
            " (fitted: v_stick = {} at two {} grains, {})",
            qty(f.reference.speed, "m/s"),
            qty(f.reference.radius, "m"),
            qty(f.reference.temperature, "K")
        )
    });
    Ok(Figure {
        name: "kernel-v-stick".to_string(),
        title: "Sticking speed of two equal compact ice grains".to_string(),
        caption: format!(
            "v_stick(a, a): the first speed at which the full model (Hertzsch 2002: viscous Eq. (4), \
             adhesion Eq. (15)/(17)) rebounds, drawn up to 1 km/s; gaps: sticks at every speed up to 1 km/s. γ(T): \
             Musiolik & Wurm 2019 (measured 175–200 K, {} outside), {} convention. A rule: {}, \
             A = {}{fit}. Not modelled: porous aggregates, fragmentation, erosion.",
            k.temperature_rule.name(),
            k.convention.name(),
            k.a_rule.name(),
            qty(k.damping_time, "s"),
        ),
        x: Axis {
            label: "grain radius a [m]".to_string(),
            log: true,
            min: x_lo,
            max: x_hi.max(x_lo * 10.0),
        },
        y: Axis {
            label: "v_stick(a, a) [m/s]".to_string(),
            log: true,
            min: y_lo,
            max: y_hi,
        },
        series,
        markers: Vec::new(),
        bands: Vec::new(),
        map: None,
    })
}
