//! The sticking-thresholds view (the terminal's `v`) as a figure: v_stick and the elastic JKR
//! threshold v_el (Eq. (15)) over the grain radius, one colour per temperature, beside the measured
//! threshold of µm ice. Every surface draws this one description (docs/physics.md#sticking).
//!
//! # Examples
//!
//! ```
//! use rime_core::explorer::thresholds::thresholds_figure;
//! use rime_core::stick::ThresholdTable;
//! use rime_core::{Accuracy, Preset};
//!
//! let table = ThresholdTable::explorer(&Preset::Ice.scene(), Accuracy::Fast);
//! let figure = thresholds_figure(&table);
//! // Two lines per temperature (v_stick, v_el) and the measurement.
//! assert_eq!(figure.series.len(), 2 * table.temperatures.len() + 1);
//! assert!(figure.x.log && figure.y.log);
//! ```

use crate::applications::stick::{MEASURED_UM_ICE, ThresholdTable};
use crate::explorer::palette;
use crate::figure::{Axis, Figure, Series, Stroke};
use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec::Vec;

/// The radius of the measured µm ice threshold's marker \[m\] (the µm grains of Gundlach & Blum
/// 2015, drawn at the table's 1 µm row).
const MEASURED_RADIUS: f64 = 1e-6;

/// A decade-aligned log axis over the positive finite values of `v`.
fn log_axis(label: &str, v: impl Iterator<Item = f64>) -> Axis {
    let (lo, hi) = v
        .filter(|x| x.is_finite() && *x > 0.0)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        });
    let (lo, hi) = if lo.is_finite() {
        (lo, hi)
    } else {
        (1e-3, 1.0)
    };
    let decade = |x: f64, up: bool| {
        let e = crate::numerics::math::log10(x);
        let e = if up { libm::ceil(e) } else { libm::floor(e) };
        libm::pow(10.0, e)
    };
    let (min, max) = (decade(lo, false), decade(hi, true));
    Axis {
        label: label.to_string(),
        log: true,
        min,
        max: if max > min { max } else { min * 10.0 },
    }
}

/// The figure of `table`: for each temperature, v_stick (solid; the scene's A and layer) and v_el
/// (dashed; Eq. (15), A = 0) over the radii, and the measured 9.6 m/s of µm ice as a point. A
/// radius where the grains stick at every speed (v_stick "always") is a gap, named in the legend.
pub fn thresholds_figure(table: &ThresholdTable) -> Figure {
    let nt = table.temperatures.len();
    let mut series = Vec::with_capacity(2 * nt + 1);
    for (j, t) in table.temperatures.iter().enumerate() {
        let color = palette::SERIES_OVERLAY + j % palette::OVERLAYS.len();
        let column =
            |f: &dyn Fn(&crate::applications::stick::Threshold) -> Option<f64>| -> Vec<(f64, f64)> {
                table
                    .radii
                    .iter()
                    .enumerate()
                    .map(|(i, r)| {
                        let v = table
                            .cell(i, j)
                            .and_then(|c| c.threshold.as_ref())
                            .and_then(f);
                        (*r, v.unwrap_or(f64::NAN))
                    })
                    .collect()
            };
        let stick = column(&|th| th.v_stick);
        let always = stick.iter().filter(|p| p.1.is_nan()).count();
        let note = if always > 0 {
            format!(" (sticks at every speed at {always} of the radii: a gap)")
        } else {
            String::new()
        };
        series.push(Series {
            name: format!("v_stick at {t} K, {}{note}", table.v_stick_note()),
            short: format!("v_stick {t} K"),
            points: stick,
            color,
            stroke: Stroke::Solid,
        });
        series.push(Series {
            name: format!("v_el at {t} K: Eq. (15), A = 0, no layer"),
            short: format!("v_el {t} K"),
            points: column(&|th| Some(th.v_elastic)),
            color,
            stroke: Stroke::Dashed,
        });
    }
    series.push(Series {
        name: format!(
            "measured, µm ice below ~210 K: {MEASURED_UM_ICE} m/s (Gundlach & Blum 2015)"
        ),
        short: "measured µm ice".to_string(),
        points: alloc::vec![(MEASURED_RADIUS, MEASURED_UM_ICE)],
        color: palette::SERIES_EXPERIMENT,
        stroke: Stroke::Points,
    });
    let speeds = series.iter().flat_map(|s| s.points.iter().map(|p| p.1));
    let y = log_axis(
        "sticking threshold [m/s]",
        speeds.collect::<Vec<_>>().into_iter(),
    );
    let x = log_axis("grain radius R [m]", table.radii.iter().copied());
    Figure {
        name: "sticking_thresholds".to_string(),
        title: "Sticking thresholds for dust codes".to_string(),
        caption: format!(
            "γ(T) of Musiolik & Wurm 2019 with each radius, this scene's material; v_stick uses {}.",
            table.v_stick_note()
        ),
        x,
        y,
        series,
        markers: Vec::new(),
        bands: Vec::new(),
        map: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Accuracy, Preset};

    #[test]
    fn the_figure_holds_the_tables_numbers_and_no_two_lines_look_alike_issue_21() {
        let table = ThresholdTable::explorer(&Preset::Ice.scene(), Accuracy::Fast);
        let fig = thresholds_figure(&table);
        // Every number of the table is on its line, at its radius.
        for (j, _) in table.temperatures.iter().enumerate() {
            for (i, r) in table.radii.iter().enumerate() {
                let th = table.cell(i, j).unwrap().threshold.unwrap();
                assert_eq!(fig.series[2 * j + 1].points[i], (*r, th.v_elastic));
                match th.v_stick {
                    Some(v) => assert_eq!(fig.series[2 * j].points[i], (*r, v)),
                    None => assert!(fig.series[2 * j].points[i].1.is_nan()),
                }
            }
        }
        // Colour and stroke together tell every line apart (it reads in grey and on NO_COLOR).
        for (a, sa) in fig.series.iter().enumerate() {
            for sb in &fig.series[a + 1..] {
                assert!(
                    (sa.color, sa.stroke) != (sb.color, sb.stroke),
                    "{} / {}",
                    sa.short,
                    sb.short
                );
            }
        }
        // The axes hold every point (decades around them).
        for s in &fig.series {
            for &(x, y) in s.points.iter().filter(|p| p.1.is_finite()) {
                assert!(fig.x.min <= x && x <= fig.x.max, "{x}");
                assert!(fig.y.min <= y && y <= fig.y.max, "{y}");
            }
        }
    }
}
