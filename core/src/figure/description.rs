//! The figure description: series, axes, bands, markers and maps, and the figures built from
//! the model ([`paper`], [`experiments`]).

use super::palette;
use crate::error::Result;
use crate::figure::sweep;
use crate::numerics::accuracy::Accuracy;
use crate::scene::Scene;
use crate::scene::contact::Contact;
use crate::tangential::StickClass;
use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec;
use alloc::vec::Vec;

/// An axis.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Axis {
    /// Label with unit, e.g. `g_N [m/s]`.
    pub label: String,
    /// Logarithmic scale.
    pub log: bool,
    /// Lower limit.
    pub min: f64,
    /// Upper limit.
    pub max: f64,
}

/// How a series is drawn. Colour alone never carries a difference: within a figure no two series
/// share both colour and stroke, so a figure reads in grey and on a terminal without colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
pub enum Stroke {
    /// A solid line (the model's curves).
    Solid,
    /// A dashed line (reference curves: clean surfaces, pinned, measured laws).
    Dashed,
    /// A dotted line (comparisons with other models and measured laws, `c`).
    Dotted,
    /// Unjoined points, each marked (instants, samples).
    Points,
    /// A line of long dashes (comparisons, once the hues have been used with dots and dashes).
    LongDash,
}

/// A series crosses with its points as two arrays, `x` and `y`, and whether its stroke is broken.
#[cfg(feature = "serde")]
impl serde::Serialize for Series {
    fn serialize<S: serde::Serializer>(&self, s: S) -> core::result::Result<S::Ok, S::Error> {
        use crate::wire::F64s;
        use serde::ser::SerializeStruct;
        let mut st = s.serialize_struct("Series", 7)?;
        st.serialize_field("name", &self.name)?;
        st.serialize_field("short", &self.short)?;
        st.serialize_field("color", &self.color)?;
        st.serialize_field("stroke", &self.stroke)?;
        st.serialize_field("dashed", &self.stroke.is_broken())?;
        st.serialize_field("x", &F64s(self.points.iter().map(|p| p.0).collect()))?;
        st.serialize_field("y", &F64s(self.points.iter().map(|p| p.1).collect()))?;
        st.end()
    }
}

/// The figure's stick map crosses as whether there is one (its grid is the frame's map).
#[cfg(feature = "serde")]
fn has_map<S: serde::Serializer>(
    map: &Option<ClassMap>,
    s: S,
) -> core::result::Result<S::Ok, S::Error> {
    s.serialize_bool(map.is_some())
}

impl Stroke {
    /// The name the page and JSON use: `solid`, `dashed`, `dotted`, `points`, `longdash`.
    pub const fn name(self) -> &'static str {
        match self {
            Stroke::Solid => "solid",
            Stroke::Dashed => "dashed",
            Stroke::Dotted => "dotted",
            Stroke::Points => "points",
            Stroke::LongDash => "longdash",
        }
    }

    /// Whether the line is broken (dashed, dotted or long-dashed).
    pub const fn is_broken(self) -> bool {
        matches!(self, Stroke::Dashed | Stroke::Dotted | Stroke::LongDash)
    }
}

/// A line.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend entry.
    pub name: String,
    /// The legend entry for small surfaces (a terminal pane): a few words the long name begins
    /// with or abbreviates.
    pub short: String,
    /// Points (x, y); a `NaN` y breaks the line (e.g. outside a log axis).
    pub points: Vec<(f64, f64)>,
    /// Index into [`PALETTE`]: the series' role ([`crate::figure::palette::SERIES`]).
    pub color: usize,
    /// How the line is drawn.
    pub stroke: Stroke,
}

/// A vertical line with a label (critical velocities).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Marker {
    /// Position on the x axis.
    pub x: f64,
    /// Label, e.g. `g_s = 6.6 µm/s`.
    pub label: String,
    /// The label for small surfaces.
    pub short: String,
    /// Index into [`PALETTE`].
    pub color: usize,
}

/// A shaded rectangle (an experimental range).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Band {
    /// x range.
    pub x: (f64, f64),
    /// y range.
    pub y: (f64, f64),
    /// Legend entry with source.
    pub label: String,
    /// The legend entry for small surfaces.
    pub short: String,
    /// Index into [`PALETTE`].
    pub color: usize,
}

/// Stick-map classes on a square grid of speeds (row-major, `classes[i * n + j]` at
/// x = g_T = `g[j]`, y = g_N = `g[i]`).
#[derive(Debug, Clone, PartialEq)]
pub struct ClassMap {
    /// Grid speeds.
    pub g: Vec<f64>,
    /// Classes.
    pub classes: Vec<StickClass>,
}

/// A complete figure.
///
/// # Examples
///
/// The explorer's ε_N chart of a frame (with the `explorer` feature):
///
/// ```
/// # #[cfg(feature = "explorer")] {
/// use rime_core::explorer::figures::{View, eps_figure};
/// use rime_core::explorer::frame::{Request, compute};
/// use rime_core::{Accuracy, Preset};
///
/// let frame = compute(&Request::new(Preset::Ice.scene(), Accuracy::Fast), &|| false).unwrap();
/// let figure = eps_figure(&frame, &View::default(), "doc");
/// // The speed axis is logarithmic and covers every speed of the frame.
/// assert!(figure.x.log);
/// assert!(figure.x.min <= frame.g[0] && frame.g[frame.g.len() - 1] <= figure.x.max);
/// assert!(!figure.series.is_empty());
/// # }
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Figure {
    /// File stem, e.g. `fig2-layer-viscosity`.
    pub name: String,
    /// Title.
    pub title: String,
    /// Caption: parameters and what the figure can and cannot show.
    pub caption: String,
    /// Horizontal axis.
    pub x: Axis,
    /// Vertical axis.
    pub y: Axis,
    /// Lines.
    pub series: Vec<Series>,
    /// Vertical markers.
    pub markers: Vec<Marker>,
    /// Shaded ranges.
    pub bands: Vec<Band>,
    /// A class map drawn under everything else.
    #[cfg_attr(feature = "serde", serde(serialize_with = "has_map"))]
    pub map: Option<ClassMap>,
}

impl Figure {
    /// A stick-map figure over `0…max` on both axes (g_T across, g_N up).
    pub fn stick_map(
        name: String,
        title: String,
        caption: String,
        g: Vec<f64>,
        classes: Vec<StickClass>,
        max: f64,
    ) -> Figure {
        let axis = |label: &str| Axis {
            label: label.to_string(),
            log: false,
            min: 0.0,
            max,
        };
        Figure {
            name,
            title,
            caption,
            x: axis("tangential speed g_T [m/s]"),
            y: axis("normal speed g_N [m/s]"),
            series: Vec::new(),
            markers: Vec::new(),
            bands: Vec::new(),
            map: Some(ClassMap { g, classes }),
        }
    }
}

/// Line colours (RGB) by [`Series::color`] index: the one palette of
/// [`crate::figure::palette::SERIES`] (Okabe–Ito; the family first, then this scene, blue, the
/// clean surface and the experiments).
pub const PALETTE: [(u8, u8, u8); palette::SERIES.len()] = {
    let s = palette::SERIES;
    let mut out = [(0, 0, 0); palette::SERIES.len()];
    let mut k = 0;
    while k < s.len() {
        out[k] = s[k].tuple();
        k += 1;
    }
    out
};

/// Colour of a stick-map class (RGB), from [`crate::figure::palette::class`].
pub fn class_color(c: StickClass) -> (u8, u8, u8) {
    palette::class(c).tuple()
}

/// Formats a speed with an SI prefix (`6.63 µm/s`).
pub fn speed_label(g: f64) -> String {
    let (v, unit) = if g >= 1.0 {
        (g, "m/s")
    } else if g >= 1e-3 {
        (g * 1e3, "mm/s")
    } else if g >= 1e-6 {
        (g * 1e6, "µm/s")
    } else {
        (g * 1e9, "nm/s")
    };
    format!("{} {unit}", three_digits(v))
}

fn three_digits(v: f64) -> String {
    if v >= 100.0 {
        format!("{v:.0}")
    } else if v >= 10.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.2}")
    }
}

/// ε_N on `n` log-spaced speeds (ε = 0 kept: the axes of these figures are linear in ε).
pub fn eps_points(
    scene: &Scene,
    from: f64,
    to: f64,
    n: usize,
    accuracy: Accuracy,
) -> Result<Vec<(f64, f64)>> {
    let contact = Contact::new(scene)?;
    let mut g = vec![0.0; n];
    sweep::log_space(from, to, &mut g);
    let mut points = Vec::with_capacity(n);
    for gi in g {
        points.push((gi, contact.eps_n(gi, accuracy)?));
    }
    Ok(points)
}

/// The experimental context of the ε_N charts.
pub mod experiments {
    use super::*;
    use crate::format::qty;

    /// The Bridges law's short name: its atlas id, as the comparisons, `rime data`, the CSV
    /// columns and the fit name it (issue 37: the chart's experiments said `Bridges'84` where the
    /// measured-ice comparison said `bridges1984`, for the same source).
    pub const BRIDGES_ID: &str = "bridges1984";

    /// Bridges, Hatzes & Lin (1984), Nature 309, 333: ε = 0.32 (v / 1 cm/s)^−0.234 (frosty ice at
    /// ~185 K), drawn over `from..to`.
    pub fn bridges(from: f64, to: f64, color: usize) -> Series {
        let mut g = vec![0.0; 60];
        sweep::log_space(from, to, &mut g);
        Series {
            name: "Bridges et al. 1984: 0.32 (v/1 cm/s)^-0.234".to_string(),
            short: BRIDGES_ID.to_string(),
            points: g
                .into_iter()
                .map(|v| (v, crate::fit::BRIDGES_1984.eval(v).min(1.0)))
                .collect(),
            color,
            stroke: Stroke::Dashed,
        }
    }

    /// The Bridges et al. (1984) law over the part of `from..to` where it was measured
    /// ([`crate::data::atlas::PENDULUM_SPEED`], 0.15–20 mm/s), unclamped (it stays below 1 there); `None`
    /// when the ranges do not overlap. Outside its speeds the law is an extrapolation that would
    /// read as data (below 77 µm/s it exceeds 1), so the explorer never draws it there.
    pub fn bridges_measured(from: f64, to: f64, color: usize) -> Option<Series> {
        let [lo, hi] = crate::data::atlas::PENDULUM_SPEED;
        let (a, b) = (from.max(lo), to.min(hi));
        if !(a < b) {
            return None;
        }
        let mut g = vec![0.0; 40];
        sweep::log_space(a, b, &mut g);
        Some(Series {
            name: "Bridges et al. 1984 (measured 0.15–20 mm/s): 0.32 (v/1 cm/s)^-0.234".to_string(),
            short: BRIDGES_ID.to_string(),
            points: g
                .into_iter()
                .map(|v| (v, crate::fit::BRIDGES_1984.eval(v)))
                .collect(),
            color,
            stroke: Stroke::Dashed,
        })
    }

    /// The measured ranges of the data atlas ([`crate::data::atlas::Kind::Range`]: the microgravity ice
    /// experiments of Heißelmann et al. 2010 and Hill et al. 2015) as boxes over their speeds and
    /// their ε, in palette colour `color` (the experiments' one colour). Labels are built from each
    /// entry's citation and grain size, so the chart says what the atlas says.
    pub fn bands(color: usize) -> Vec<Band> {
        crate::data::atlas::ENTRIES
            .iter()
            .filter_map(|e| {
                let [lo, hi] = e.band()?;
                let diameter = diameter_range(e.radius);
                Some(Band {
                    x: (e.valid_speed[0], e.valid_speed[1]),
                    y: (lo, hi),
                    label: format!(
                        "{} {} ({diameter} ice, µg)",
                        e.citation.short_authors(),
                        e.citation.year
                    ),
                    // The atlas id: the one name of a source on every small surface.
                    short: e.id.to_string(),
                    color,
                })
            })
            .collect()
    }

    /// `15 mm` or `4.7–10.8 mm`: the diameters of an entry's radius range, the unit written once.
    fn diameter_range([lo, hi]: [f64; 2]) -> String {
        let (a, b) = (qty(2.0 * lo, "m"), qty(2.0 * hi, "m"));
        if a == b {
            return a;
        }
        match (a.split_once(' '), b.split_once(' ')) {
            (Some((na, ua)), Some((_, ub))) if ua == ub => format!("{na}–{b}"),
            _ => format!("{a}–{b}"),
        }
    }
}

/// The paper's figures, rebuilt from the model.
pub mod paper {
    use super::*;
    use crate::scene::{Adhesion, Damping, Layer, Preset, Viscosities};

    const FROM: f64 = 1e-7;
    const TO: f64 = 1.0;
    const N: usize = 300;

    fn eps_axes() -> (Axis, Axis) {
        (
            Axis {
                label: "normal impact speed g_N [m/s]".to_string(),
                log: true,
                min: FROM,
                max: TO,
            },
            Axis {
                label: "normal restitution ε_N".to_string(),
                log: false,
                min: 0.0,
                max: 1.0,
            },
        )
    }

    /// A solid (or dashed) ε_N curve of `scene` over the paper's range.
    fn curve(
        scene: &Scene,
        accuracy: Accuracy,
        name: String,
        color: usize,
        stroke: Stroke,
    ) -> Result<Series> {
        Ok(Series {
            short: name.clone(),
            name,
            points: eps_points(scene, FROM, TO, N, accuracy)?,
            color,
            stroke,
        })
    }

    /// A family figure: one curve and one critical-speed marker per variant, then the clean
    /// surfaces, the Bridges law and the experimental ranges.
    fn family_figure(
        clean: &Scene,
        variants: &[(Scene, String)],
        accuracy: Accuracy,
        name: String,
        title: &str,
        caption: String,
    ) -> Result<Figure> {
        let (x, y) = eps_axes();
        let mut series = Vec::new();
        let mut markers = Vec::new();
        for (k, (scene, label)) in variants.iter().enumerate() {
            series.push(curve(scene, accuracy, label.clone(), k, Stroke::Solid)?);
            let c = Contact::new(scene)?;
            let g_s = c
                .layer
                .map(|l| l.critical_velocity)
                .or(c.adhesion.map(|a| a.critical_velocity))
                .unwrap_or(0.0);
            markers.push(Marker {
                x: g_s,
                label: format!("g_s = {}", speed_label(g_s)),
                short: format!("g_s = {}", speed_label(g_s)),
                color: k,
            });
        }
        series.push(curve(
            clean,
            accuracy,
            "clean surfaces".to_string(),
            palette::SERIES_CLEAN,
            Stroke::Dashed,
        )?);
        // Only where it was measured (as the explorer and the page draw it).
        series.extend(experiments::bridges_measured(
            FROM,
            TO,
            palette::SERIES_EXPERIMENT,
        ));
        Ok(Figure {
            name,
            title: title.to_string(),
            caption,
            x,
            y,
            series,
            markers,
            bands: experiments::bands(palette::SERIES_EXPERIMENT),
            map: None,
        })
    }

    fn with_damping(mut s: Scene, damping: Damping) -> Scene {
        s.bulk.damping = damping;
        s
    }

    /// Fig. 2: ε_N for layer viscosities η* = 500, 1000, 2000, 5000 Pa s at D = 1 µm, plus clean
    /// surfaces, for the calibrated A (default) and for the paper's literal viscosities.
    pub fn fig2(accuracy: Accuracy) -> Result<Vec<Figure>> {
        let mut out = Vec::new();
        let base = Preset::Ice.scene();
        for (suffix, damping, note) in [
            (
                "",
                base.bulk.damping,
                "A = 1e-4 s (calibrated to Bridges et al. 1984; docs/physics.md, decision 1).",
            ),
            (
                "-paper-viscosities",
                Damping::Viscosities(Viscosities::default()),
                "The paper's η1 = 1e6, η2 = 1e12 Pa s give A = 404 s: every collision is overdamped (ε_N < 1e-9), unlike the paper's Fig. 2.",
            ),
        ] {
            let clean = with_damping(base, damping);
            let variants: Vec<(Scene, String)> = [500.0, 1000.0, 2000.0, 5000.0]
                .into_iter()
                .map(|eta| {
                    let layer = Layer {
                        viscosity: eta,
                        ..Layer::default()
                    };
                    let s = Scene {
                        layer: Some(layer),
                        ..clean
                    };
                    (s, format!("η* = {eta} Pa s"))
                })
                .collect();
            out.push(family_figure(
                &clean,
                &variants,
                accuracy,
                format!("fig2-layer{suffix}"),
                "Fig. 2: soft surface layer, D = 1 µm",
                format!(
                    "ε_N vs g_N for layer viscosities η* = 500…5000 Pa s (offset reading, force-zero end) and clean surfaces. {note} Markers: critical speeds g_s of Eq. (10)."
                ),
            )?);
        }
        Ok(out)
    }

    /// Fig. 3: ε_N for surface energies γ = 0.05, 0.1, 0.2, 0.5 J/m², plus clean surfaces.
    pub fn fig3(accuracy: Accuracy) -> Result<Vec<Figure>> {
        let clean = Preset::Ice.scene();
        let variants: Vec<(Scene, String)> = [0.05, 0.1, 0.2, 0.5]
            .into_iter()
            .map(|gamma| {
                let adhesion = Adhesion {
                    surface_energy: gamma,
                    ..Adhesion::default()
                };
                let s = Scene {
                    adhesion: Some(adhesion),
                    ..clean
                };
                (s, format!("γ = {gamma} J/m²"))
            })
            .collect();
        Ok(vec![family_figure(
            &clean,
            &variants,
            accuracy,
            "fig3-adhesion".to_string(),
            "Fig. 3: adhesion",
            "ε_N vs g_N for surface energies γ = 0.05…0.5 J/m² (E as printed) and clean surfaces, A = 1e-4 s. Markers: critical rebound speeds g_s of Eq. (15); the grains stick when the rebound speed without adhesion is below g_s.".to_string(),
        )?])
    }

    /// Fig. 4: stick-map classes over (g_N, g_T) for hard, layered (η* = 1000 Pa s) and adhesive
    /// (γ = 0.1 J/m²) grains with μ = 0.3: at the paper's range 0–5 cm/s and zoomed to where the
    /// sticking regions of the stated parameters actually are.
    pub fn fig4(accuracy: Accuracy, n: usize) -> Result<Vec<Figure>> {
        let mut out = Vec::new();
        for (name, title, scene) in [
            ("hard", "hard spheres", Preset::Ice.scene()),
            (
                "layer",
                "layer D = 1 µm, η* = 1000 Pa s",
                Preset::IceFrost.scene(),
            ),
            (
                "adhesion",
                "adhesion γ = 0.1 J/m²",
                Preset::IceSticky.scene(),
            ),
        ] {
            let contact = Contact::new(&scene)?;
            let g_s = contact
                .layer
                .map(|l| l.critical_velocity)
                .or(contact.adhesion.map(|a| a.critical_velocity))
                .unwrap_or(0.0);
            let mut ranges = vec![(0.05, "paper's range 0–5 cm/s")];
            if g_s > 0.0 {
                ranges.push((20.0 * g_s, "zoomed to 20 g_s"));
            }
            for (max, range_note) in ranges {
                let map = sweep::StickMap::new(&contact, max, n, accuracy)?;
                let zoom = if max < 0.05 { "-zoom" } else { "" };
                let caption = format!(
                    "Stick-map classes of ε_T(g_N, g_T), μ = 0.3, κ = 2/7, paper sliding law. {}",
                    if g_s > 0.0 {
                        format!(
                            "The critical speed of these parameters is g_s = {}: at the paper's 0–5 cm/s range the sticking region is too small to see, so a zoomed map is shown too.",
                            speed_label(g_s)
                        )
                    } else {
                        format!(
                            "Hard spheres never stick; the {} wedge (sliding gap) is the negative radicand of Eq. (23) just above ψ0, an artifact of the printed law.",
                            palette::class(StickClass::SlidingGap).name()
                        )
                    }
                );
                out.push(Figure::stick_map(
                    format!("fig4-{name}{zoom}"),
                    format!("Fig. 4: {title} ({range_note})"),
                    caption,
                    map.g,
                    map.class,
                    max,
                ));
            }
        }
        Ok(out)
    }

    /// Every paper figure.
    pub fn all(accuracy: Accuracy, map_n: usize) -> Result<Vec<Figure>> {
        let mut v = fig2(accuracy)?;
        v.extend(fig3(accuracy)?);
        v.extend(fig4(accuracy, map_n)?);
        Ok(v)
    }
}

#[path = "figure/ticks.rs"]
#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 36: the experiments' boxes are read from the atlas, not restated. The numbers below are
    /// the sources' own (Hill et al. 2015, abstract: 4.7–10.8 mm, 0.27–0.51 m/s, ε 0.08–0.65;
    /// Heißelmann et al. 2010 as tabulated by Hill et al. 2015, Table 2: 15 mm, 0.06–0.22 m/s).
    #[test]
    fn issue_36_the_experiments_boxes_are_the_atlas_ranges() {
        let bands = experiments::bands(3);
        assert_eq!(bands.len(), 2);
        let (h10, h15) = (&bands[0], &bands[1]);
        assert_eq!((h10.x, h10.y), ((0.06, 0.22), (0.06, 0.84)));
        assert_eq!(h10.label, "Heißelmann et al. 2010 (15 mm ice, µg)");
        assert_eq!(h10.short, "heisselmann2010");
        assert_eq!((h15.x, h15.y), ((0.27, 0.51), (0.08, 0.65)));
        assert_eq!(h15.label, "Hill et al. 2015 (4.7–10.8 mm ice, µg)");
        assert_eq!(h15.short, "hill2015");
        assert!(bands.iter().all(|b| b.color == 3));
    }
}
