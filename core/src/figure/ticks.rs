//! What every surface needs to draw a figure's axes and place its legend, decided once: tick
//! positions and their labels ([`Axis::ticks`]), and the corner where a legend of a given footprint
//! covers the fewest data ([`Figure::legend_corner`]).
//!
//! Labels are built from integers (a mantissa and a power of ten), never by printing a float, so
//! an axis reads `0`, `2e-9`, `4e-9` and not `2.7e-26` or `0.30000000000000004`.

use super::{Axis, Figure, Stroke};
use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec::Vec;

/// A tick on an axis.
#[derive(Debug, Clone, PartialEq)]
pub struct Tick {
    /// Where, in the axis' units (not log₁₀).
    pub value: f64,
    /// The label; `None` for a minor tick.
    pub label: Option<String>,
}

/// Labels an image axis carries at most (a terminal passes fewer; its labels are a subset).
pub const IMAGE_LABELS: usize = 11;

/// A corner of a figure's plot area.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Corner {
    /// Upper right (preferred on ties: ε_N curves fall to the right, so it is often free).
    TopRight,
    /// Upper left.
    TopLeft,
    /// Lower right.
    BottomRight,
    /// Lower left.
    BottomLeft,
}

impl Corner {
    /// Every corner, in the order of preference on ties.
    pub const ALL: [Corner; 4] = [
        Corner::TopRight,
        Corner::TopLeft,
        Corner::BottomRight,
        Corner::BottomLeft,
    ];
}

/// `n`·10^`e` written exactly: plain between 0.01 and 1e5 (`0.25`, `1500`), else with an
/// exponent (`2.5e-9`, `1e-3`, `1e6`), as [`crate::format::decade`] writes decades. Built from the digits of `n`, so no float noise can appear.
pub fn decimal_label(n: i64, e: i32) -> String {
    if n == 0 {
        return "0".to_string();
    }
    let sign = if n < 0 { "-" } else { "" };
    // Strip trailing zeros of the mantissa into the exponent.
    let (mut m, mut e) = (n.unsigned_abs(), e);
    while m % 10 == 0 {
        m /= 10;
        e += 1;
    }
    let digits = m.to_string();
    let len = digits.len() as i32;
    // The value's decade: the leading digit's power of ten.
    let lead = e + len - 1;
    if (-2..5).contains(&lead) {
        if e >= 0 {
            format!("{sign}{digits}{}", "0".repeat(e as usize))
        } else if -e < len {
            let (a, b) = digits.split_at((len + e) as usize);
            format!("{sign}{a}.{b}")
        } else {
            format!("{sign}0.{}{digits}", "0".repeat((-e - len) as usize))
        }
    } else {
        let (a, b) = digits.split_at(1);
        if b.is_empty() {
            format!("{sign}{a}e{lead}")
        } else {
            format!("{sign}{a}.{b}e{lead}")
        }
    }
}

/// `floor(log10(v))` for a positive finite `v`, exact at powers of ten.
fn decade_of(v: f64) -> i32 {
    let mut k = libm::floor(crate::numerics::math::log10(v)) as i32;
    // log10 can land a hair off at exact powers of ten.
    if crate::numerics::grid::exact_decade(k) > v {
        k -= 1;
    } else if crate::numerics::grid::exact_decade(k + 1) <= v {
        k += 1;
    }
    k
}

impl Axis {
    /// The ticks of this axis with at most `max_labels` labels (at least 2 are kept): a surface
    /// passes what fits (a terminal a few, an image about 11). The labels of a smaller
    /// `max_labels` are a subset of those of a larger one on log axes and, for 0…1, on linear ones.
    ///
    /// Log axes: labelled decades every 1, 2, 4, 8 … decades (those divisible by the step), minor
    /// ticks at 2…9 × 10^k; spans under three decades also label 2 and 5 × 10^k, spans under one
    /// every 1…9 × 10^k. Linear axes: multiples of 1, 2 or 5 × 10^k, labels written exactly.
    pub fn ticks(&self, max_labels: usize) -> Vec<Tick> {
        let max_labels = max_labels.max(2);
        if !(self.min.is_finite() && self.max.is_finite() && self.min < self.max) {
            return Vec::new();
        }
        if self.log {
            if self.min > 0.0 {
                log_ticks(self.min, self.max, max_labels)
            } else {
                Vec::new()
            }
        } else {
            linear_ticks(self.min, self.max, max_labels)
        }
    }
}

fn inside(v: f64, lo: f64, hi: f64) -> bool {
    // A relative tolerance: the ends of an axis are often exactly a tick.
    let tol = (hi - lo).abs() * 1e-9;
    v >= lo - tol && v <= hi + tol
}

fn log_ticks(lo: f64, hi: f64, max_labels: usize) -> Vec<Tick> {
    let (k_lo, k_hi) = (decade_of(lo), decade_of(hi));
    let span = crate::numerics::math::log10(hi) - crate::numerics::math::log10(lo);
    // Which mantissas carry labels: 1 (decades), 1 2 5, or 1…9.
    let mantissas: &[i64] = if span < 1.0 {
        &[1, 2, 3, 4, 5, 6, 7, 8, 9]
    } else if span < 3.0 {
        &[1, 2, 5]
    } else {
        &[1]
    };
    let labelled = |step: i32, ms: &[i64]| -> usize {
        (k_lo..=k_hi)
            .filter(|k| k.rem_euclid(step) == 0)
            .flat_map(|k| {
                ms.iter()
                    .map(move |m| (*m as f64) * crate::numerics::grid::exact_decade(k))
            })
            .filter(|v| inside(*v, lo, hi))
            .count()
    };
    // Fewer mantissas first, then sparser decades, until the labels fit.
    let mut ms = mantissas;
    while ms.len() > 1 && labelled(1, ms) > max_labels {
        ms = if ms.len() > 3 { &[1, 2, 5] } else { &[1] };
    }
    let mut step = 1;
    while labelled(step, ms) > max_labels && step < 64 {
        step *= 2;
    }
    let mut out = Vec::new();
    for k in k_lo..=k_hi {
        for m in 1..=9_i64 {
            let v = (m as f64) * crate::numerics::grid::exact_decade(k);
            if !inside(v, lo, hi) {
                continue;
            }
            let label = (k.rem_euclid(step) == 0 && ms.contains(&m)).then(|| decimal_label(m, k));
            out.push(Tick { value: v, label });
        }
    }
    out
}

fn linear_ticks(lo: f64, hi: f64, max_labels: usize) -> Vec<Tick> {
    let span = hi - lo;
    // The smallest step m·10^e (m = 1, 2, 5) that gives at most `max_labels` ticks.
    let mut e = decade_of(span / max_labels as f64) - 1;
    let mut m_idx = 0;
    const MS: [i64; 3] = [1, 2, 5];
    let count = |m: i64, e: i32| -> f64 {
        let step = (m as f64) * crate::numerics::grid::exact_decade(e);
        libm::floor(hi / step + 1e-9) - libm::ceil(lo / step - 1e-9) + 1.0
    };
    while count(MS[m_idx], e) > max_labels as f64 {
        m_idx += 1;
        if m_idx == MS.len() {
            m_idx = 0;
            e += 1;
        }
    }
    let m = MS[m_idx];
    let step = (m as f64) * crate::numerics::grid::exact_decade(e);
    let (i0, i1) = (
        libm::ceil(lo / step - 1e-9) as i64,
        libm::floor(hi / step + 1e-9) as i64,
    );
    let mut ticks: Vec<Tick> = (i0..=i1)
        .map(|i| Tick {
            value: (i * m) as f64 * crate::numerics::grid::exact_decade(e),
            label: Some(decimal_label(i * m, e)),
        })
        .collect();
    // One notation per axis (issue 37 X1: Fig. 4's axis read `5e-3, 0.01, 0.015`): where the
    // labels mix plain and exponent forms and every value lies between 1e-4 and 1e6, all plain.
    let exponent = |t: &Tick| t.label.as_deref().is_some_and(|l| l.contains('e'));
    let plain = |t: &Tick| {
        t.label
            .as_deref()
            .is_some_and(|l| l != "0" && !l.contains('e'))
    };
    let within = ticks
        .iter()
        .all(|t| t.value == 0.0 || (1e-4..1e6).contains(&libm::fabs(t.value)));
    if within && ticks.iter().any(exponent) && ticks.iter().any(plain) {
        for (t, i) in ticks.iter_mut().zip(i0..=i1) {
            t.label = Some(plain_label(i * m, e));
        }
    }
    ticks
}

/// `n`·10^`e` written exactly without an exponent (`0.005`, `150000`).
fn plain_label(n: i64, e: i32) -> String {
    if n == 0 {
        return "0".to_string();
    }
    let sign = if n < 0 { "-" } else { "" };
    let (mut m, mut e) = (n.unsigned_abs(), e);
    while m % 10 == 0 {
        m /= 10;
        e += 1;
    }
    let digits = m.to_string();
    let len = digits.len() as i32;
    if e >= 0 {
        format!("{sign}{digits}{}", "0".repeat(e as usize))
    } else if -e < len {
        let (a, b) = digits.split_at((len + e) as usize);
        format!("{sign}{a}.{b}")
    } else {
        format!("{sign}0.{}{digits}", "0".repeat((-e - len) as usize))
    }
}

impl Axis {
    /// Where `v` lies along the axis, 0 at `min` … 1 at `max` (log₁₀ on log axes); `None` when
    /// it cannot be placed (non-finite, or not positive on a log axis).
    pub fn fraction(&self, v: f64) -> Option<f64> {
        let t = |v: f64| {
            if self.log {
                (v > 0.0).then(|| crate::numerics::math::log10(v))
            } else {
                Some(v)
            }
        };
        let (a, b, x) = (t(self.min)?, t(self.max)?, t(v)?);
        let f = (x - a) / (b - a);
        f.is_finite().then_some(f)
    }
}

impl Figure {
    /// The corner where a legend `legend` = (width, height) large covers the fewest data, in a
    /// plot area `plot` = (width, height) large, both in the surface's units (terminal cells,
    /// pixels). Lines count by their length under the legend, bands by their area; ties go to the
    /// first of [`Corner::ALL`].
    pub fn legend_corner(&self, plot: (f64, f64), legend: (f64, f64)) -> Corner {
        let (w, h) = plot;
        let (lw, lh) = (legend.0.min(w), legend.1.min(h));
        let rect = |c: Corner| -> (f64, f64, f64, f64) {
            // (x0, y0, x1, y1) with y up from the bottom of the plot.
            match c {
                Corner::TopRight => (w - lw, h - lh, w, h),
                Corner::TopLeft => (0.0, h - lh, lw, h),
                Corner::BottomRight => (w - lw, 0.0, w, lh),
                Corner::BottomLeft => (0.0, 0.0, lw, lh),
            }
        };
        let to_plot = |(x, y): (f64, f64)| -> Option<(f64, f64)> {
            Some((self.x.fraction(x)? * w, self.y.fraction(y)? * h))
        };
        let mut cost = [0.0_f64; 4];
        for s in &self.series {
            let pts: Vec<Option<(f64, f64)>> = s.points.iter().map(|p| to_plot(*p)).collect();
            let weight = if s.stroke == Stroke::Solid { 1.0 } else { 0.8 };
            for pair in pts.windows(2) {
                let (Some(a), Some(b)) = (pair[0], pair[1]) else {
                    continue;
                };
                // Samples half a unit apart along the segment.
                let len = libm::hypot(b.0 - a.0, b.1 - a.1);
                let n = (len * 2.0).clamp(1.0, 10_000.0) as usize;
                for k in 0..n {
                    let t = (k as f64 + 0.5) / n as f64;
                    let (x, y) = (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t);
                    for (c, corner) in Corner::ALL.iter().enumerate() {
                        let (x0, y0, x1, y1) = rect(*corner);
                        if x >= x0 && x <= x1 && y >= y0 && y <= y1 {
                            cost[c] += weight * len / n as f64;
                        }
                    }
                }
            }
        }
        for b in &self.bands {
            let (Some(p0), Some(p1)) = (to_plot((b.x.0, b.y.0)), to_plot((b.x.1, b.y.1))) else {
                continue;
            };
            for (c, corner) in Corner::ALL.iter().enumerate() {
                let (x0, y0, x1, y1) = rect(*corner);
                let ox = (p1.0.min(x1) - p0.0.max(x0)).max(0.0);
                let oy = (p1.1.min(y1) - p0.1.max(y0)).max(0.0);
                // A band is shaded, not drawn: it counts less than a line through the legend.
                cost[c] += 0.1 * ox * oy;
            }
        }
        for m in &self.markers {
            let Some(f) = self.x.fraction(m.x) else {
                continue;
            };
            if !(0.0..=1.0).contains(&f) {
                continue;
            }
            for (c, corner) in Corner::ALL.iter().enumerate() {
                let (x0, _, x1, _) = rect(*corner);
                if f * w >= x0 && f * w <= x1 {
                    cost[c] += 0.5 * lh;
                }
            }
        }
        let mut best = 0;
        for c in 1..4 {
            if cost[c] < cost[best] - 1e-9 {
                best = c;
            }
        }
        Corner::ALL[best]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::figure::{Marker, Series};
    use alloc::vec;

    fn axis(log: bool, min: f64, max: f64) -> Axis {
        Axis {
            label: String::new(),
            log,
            min,
            max,
        }
    }

    fn labels(a: &Axis, max: usize) -> Vec<String> {
        a.ticks(max).into_iter().filter_map(|t| t.label).collect()
    }

    #[test]
    fn labels_are_written_exactly() {
        // Expected strings from the decimal expansion of n·10^e, by hand.
        for (n, e, s) in [
            (0, -26, "0"),
            (25, -10, "2.5e-9"),
            (2, -9, "2e-9"),
            (1, -3, "1e-3"),
            (1, -2, "0.01"),
            (1, 4, "10000"),
            (3, -1, "0.3"),
            (15, 2, "1500"),
            (1, 6, "1e6"),
            (-4, -1, "-0.4"),
            (125, -2, "1.25"),
            (10, -1, "1"),
        ] {
            assert_eq!(decimal_label(n, e), s, "{n}e{e}");
        }
    }

    #[test]
    fn linear_ticks_are_nice_and_noise_free_issue_21() {
        let l = labels(&axis(false, 0.0, 1.0), 11);
        assert_eq!(
            l,
            [
                "0", "0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7", "0.8", "0.9", "1"
            ]
        );
        assert_eq!(labels(&axis(false, 0.0, 1.0), 3), ["0", "0.5", "1"]);
        // The `i` panel's overlap axis printed 2.7e-26 (a float-noise zero) and colliding labels.
        let l = labels(&axis(false, -2.7e-26, 3.1e-9), 4);
        assert_eq!(l, ["0", "1e-9", "2e-9", "3e-9"]);
        let l = labels(&axis(false, -0.0123, 0.0456), 5);
        assert_eq!(l, ["0", "0.02", "0.04"]);
    }

    /// Issue 37 (review X1): one notation per axis: Fig. 4's 0–2 cm/s axis read
    /// `0, 5e-3, 0.01, 0.015, 0.02`; the values are exact decimals written by hand here.
    #[test]
    fn issue_37_an_axis_writes_its_labels_one_way() {
        assert_eq!(
            labels(&axis(false, 0.0, 0.02), 5),
            ["0", "0.005", "0.01", "0.015", "0.02"]
        );
        assert_eq!(
            labels(&axis(false, 0.0, 150000.0), 4),
            ["0", "50000", "100000", "150000"]
        );
        // All small or all large: the exponent form stays.
        assert_eq!(
            labels(&axis(false, 0.0, 3.1e-9), 4),
            ["0", "1e-9", "2e-9", "3e-9"]
        );
        assert_eq!(labels(&axis(false, 0.0, 1.0), 3), ["0", "0.5", "1"]);
    }

    #[test]
    fn log_ticks_label_decades_within_the_budget() {
        let a = axis(true, 1e-7, 10.0);
        let all = labels(&a, 11);
        assert_eq!(
            all,
            [
                "1e-7", "1e-6", "1e-5", "1e-4", "1e-3", "0.01", "0.1", "1", "10"
            ]
        );
        for max in 2..11 {
            let some = labels(&a, max);
            assert!(some.len() <= max.max(2), "{max}: {some:?}");
            assert!(some.iter().all(|l| all.contains(l)), "{max}: {some:?}");
        }
        // Minor ticks at 2…9 × 10^k, exactly 8 per whole decade.
        let minors = a.ticks(11).iter().filter(|t| t.label.is_none()).count();
        assert_eq!(minors, 8 * 8);
        // A zoom to under three decades labels 2 and 5 too.
        let z = labels(&axis(true, 1e-3, 0.1), 11);
        assert_eq!(z, ["1e-3", "2e-3", "5e-3", "0.01", "0.02", "0.05", "0.1"]);
        // Under one decade: every digit.
        let z = labels(&axis(true, 2e-5, 9e-5), 11);
        assert_eq!(
            z,
            [
                "2e-5", "3e-5", "4e-5", "5e-5", "6e-5", "7e-5", "8e-5", "9e-5"
            ]
        );
    }

    #[test]
    fn legend_goes_where_the_data_are_not_issue_21() {
        let line = |pts: Vec<(f64, f64)>| Series {
            name: String::new(),
            short: String::new(),
            points: pts,
            color: 0,
            stroke: Stroke::Solid,
        };
        let mut fig = Figure::stick_map(
            String::new(),
            String::new(),
            String::new(),
            vec![],
            vec![],
            1.0,
        );
        fig.map = None;
        // A falling line from the top left to the bottom right: both of those corners are taken.
        fig.series = vec![line(vec![(0.0, 1.0), (1.0, 0.0)])];
        let c = fig.legend_corner((100.0, 40.0), (30.0, 8.0));
        assert!(matches!(c, Corner::TopRight | Corner::BottomLeft), "{c:?}");
        // A rising line in the upper half: bottom right is free, the top right is not.
        fig.series = vec![line(vec![(0.0, 0.85), (1.0, 1.0)])];
        assert_eq!(
            fig.legend_corner((100.0, 40.0), (30.0, 8.0)),
            Corner::BottomRight
        );
        // A marker in the right quarter moves it off the right.
        fig.series = vec![line(vec![(0.0, 0.0), (1.0, 0.05)])];
        fig.markers = vec![Marker {
            x: 0.9,
            label: String::new(),
            short: String::new(),
            color: 0,
        }];
        assert_eq!(
            fig.legend_corner((100.0, 40.0), (30.0, 8.0)),
            Corner::TopLeft
        );
    }
}
