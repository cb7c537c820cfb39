//! The frame as figure descriptions ([`crate::figure::Figure`]): what the ε_N chart and the stick
//! map show, built once here for every surface — the terminal's `x` export and the page's
//! downloads render these, `rime figures --scene` writes them, and each surface's screen follows
//! the same [`View`] (axis mode, overlays, experiments, pinned curve), so what is exported is what
//! is on screen.
//!
//! Draw order is part of the description: measured data (bands, the Bridges law, atlas laws)
//! first, beneath the model curves; this scene's curve last, on top.

use super::frame::{Frame, SWEEPS};
use super::palette;
use super::records::{CITATION, scene_line};
use crate::figure::{Axis, Band, Figure, Marker, Series, Stroke, experiments, speed_label};
use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec::Vec;

/// The strokes of the comparisons, one per round of [`palette::OVERLAYS`]' hues: all broken, so
/// that no comparison looks like a model curve of this scene (solid).
pub const OVERLAY_STROKES: [Stroke; 3] = [Stroke::Dotted, Stroke::Dashed, Stroke::LongDash];
/// How many comparisons can be told apart by colour and stroke together.
pub const OVERLAY_STYLES: usize = palette::OVERLAYS.len() * OVERLAY_STROKES.len();

/// The series colour index ([`palette::SERIES`]) and the stroke of the `k`-th comparison of a
/// figure: every hue with dots, then with dashes, then with long dashes — distinct for
/// `k < OVERLAY_STYLES` (issue 22: with five hues cycling, Bridges, Higa and Schwager were all one
/// vermillion dotted line).
pub const fn overlay_style(k: usize) -> (usize, Stroke) {
    let k = k % OVERLAY_STYLES;
    (
        palette::SERIES_OVERLAY + k % palette::OVERLAYS.len(),
        OVERLAY_STROKES[k / palette::OVERLAYS.len()],
    )
}

pub use super::frame::Pinned;

/// How a surface shows the frame; exports take the same value, so they show what the screen shows.
#[derive(Debug, Clone, PartialEq)]
pub struct View {
    /// ε_N on a logarithmic axis (sticking, ε_N = 0, cannot be shown there) instead of 0…1.
    pub y_log: bool,
    /// Whether the experimental context (Bridges et al. 1984 law over its measured speeds, the
    /// microgravity boxes) is drawn when no comparison overlay is chosen.
    pub experiments: bool,
    /// A pinned curve drawn dashed beneath this scene's.
    pub pinned: Option<Pinned>,
}

impl Default for View {
    fn default() -> Self {
        View {
            y_log: false,
            experiments: true,
            pinned: None,
        }
    }
}

/// The lowest decade of a logarithmic ε_N axis: a decade below the smallest positive value drawn,
/// between 1e-12 and 0.1 (the one rule of every surface).
pub fn eps_log_floor<'a>(curves: impl IntoIterator<Item = &'a [f64]>) -> i32 {
    let min = curves
        .into_iter()
        .flat_map(|c| c.iter().copied())
        .filter(|e| e.is_finite() && *e > 0.0)
        .fold(f64::INFINITY, f64::min);
    if min.is_finite() {
        (libm::floor(crate::numerics::math::log10(min)) as i32).clamp(-12, -1)
    } else {
        -3
    }
}

/// What the family means, for its legend: `η* varied around this scene`.
pub fn family_meaning(frame: &Frame) -> Option<String> {
    let s = SWEEPS.get(frame.sweep)?;
    (!frame.family.is_empty()).then(|| format!("{} varied around this scene", s.symbol))
}

fn member_name(frame: &Frame, value: f64, is_scene: bool) -> String {
    let s = SWEEPS.get(frame.sweep);
    let symbol = s.map_or("p", |s| s.symbol);
    let unit = s.map_or("", |s| s.unit);
    let mark = if is_scene { " (this scene)" } else { "" };
    // Text people read: four digits with an SI prefix (0.1 × 3e-3 reads 300 µs, not
    // 3.0000000000000003e-4).
    format!("{symbol} = {}{mark}", super::format::qty(value, unit))
}

/// A comparison's legend entry on small surfaces: its key's name, temperature and geometry for
/// measured data (docs/physics.md#data-atlas), and the scene's rms against it (for a measured
/// range: whether the scene lies within it, else its rms distance from it).
/// Whether an overlay model's `g_cr` is the status "always sticks" (a value of `+∞`,
/// [`crate::models::SpeedStatus::AlwaysSticks`]): it has no marker, so its legend says it.
fn always_sticks(o: &super::frame::OverlayCurve) -> bool {
    o.speeds
        .iter()
        .any(|(name, g)| *name == "g_cr" && *g == f64::INFINITY)
}

fn overlay_short(o: &super::frame::OverlayCurve) -> String {
    let key = o.overlay.key();
    let name = key.split_once(':').map_or(key.as_str(), |(_, n)| n);
    let context = match o.overlay {
        super::frame::Overlay::Atlas(e) => {
            let [lo, hi] = e.temperature;
            if !hi.is_finite() {
                format!(" ({})", e.geometry.name())
            } else if lo == hi {
                format!(" ({lo} K, {})", e.geometry.name())
            } else {
                format!(" ({lo}–{hi} K, {})", e.geometry.name())
            }
        }
        super::frame::Overlay::Model(_) if always_sticks(o) => " (always sticks)".to_string(),
        super::frame::Overlay::Model(_) => String::new(),
    };
    // A measured range's score is the distance to its band, 0 inside it: "rms 0" read as a
    // perfect fit (issue 37), so a range says whether this scene lies within it.
    let score = match o.score {
        Some(r) if o.band && r == 0.0 => " scene in range".to_string(),
        Some(r) if o.band => format!(" rms off range {}", super::format::sig(r, 2)),
        Some(r) => format!(" rms {}", super::format::sig(r, 2)),
        None => String::new(),
    };
    format!("{name}{context}{score}")
}

/// A frame marker's legend name on small surfaces.
fn marker_short(key: &str) -> &'static str {
    match key {
        "layer" => "g_s layer",
        "adhesion" => "g_s adhesion, on the rebound speed",
        _ => "sticks below",
    }
}

/// The caption every figure of a frame carries: level, scene, program and model — enough to
/// reproduce the figure from itself.
pub fn caption(frame: &Frame, version: &str) -> String {
    format!(
        "rime {version}, level {}. Scene: {}. Model: {CITATION}.",
        frame.request.accuracy.name(),
        scene_line(&frame.request.scene)
    )
}

/// The ε_N chart of a frame, as `view` shows it.
// Long by design: the ε_N figure's parts in drawing order (family, clean, scene, overlays,
// experiments, pinned, markers), each a short block.
pub fn eps_figure(frame: &Frame, view: &View, version: &str) -> Figure {
    let g = &frame.g;
    let (g0, g1) = (
        g.first().copied().unwrap_or(1e-7),
        g.last().copied().unwrap_or(10.0),
    );
    let pts = |gs: &[f64], eps: &[f64]| -> Vec<(f64, f64)> {
        gs.iter()
            .zip(eps)
            .map(|(&x, &y)| (x, if y.is_finite() { y } else { f64::NAN }))
            .collect()
    };
    let mut series = Vec::new();
    let mut bands = Vec::new();
    let mut drawn: Vec<Vec<f64>> = Vec::new();
    let mut overlay_markers = Vec::new();

    // Measured data first, beneath the model curves.
    if view.experiments && frame.overlays.is_empty() {
        if let Some(b) = experiments::bridges_measured(g0, g1, palette::SERIES_EXPERIMENT) {
            series.push(b);
        }
        bands.extend(
            experiments::bands(palette::SERIES_EXPERIMENT)
                .into_iter()
                .filter(|b| b.x.1 > g0 && b.x.0 < g1),
        );
    }
    for (k, o) in frame.overlays.iter().enumerate() {
        let (color, stroke) = overlay_style(k);
        if o.band {
            if let (Some(&x0), Some(&x1), Some(&y0), Some(&y1)) =
                (o.g.first(), o.g.last(), o.eps.first(), o.eps.last())
            {
                bands.push(Band {
                    x: (x0, x1),
                    y: (y0.min(y1), y0.max(y1)),
                    label: o.label.clone(),
                    short: overlay_short(o),
                    color,
                });
            }
        } else {
            // Broken: a comparison may share a hue with a family member (solid), never a hue and
            // a stroke.
            let name = if always_sticks(o) {
                format!(
                    "{} — always sticks (g_cr beyond every accepted speed)",
                    o.label
                )
            } else {
                o.label.clone()
            };
            series.push(Series {
                name,
                short: overlay_short(o),
                points: pts(&o.g, &o.eps),
                color,
                stroke,
            });
        }
        for (name, g) in &o.speeds {
            if g.is_finite() && *g > 0.0 {
                let who = o.overlay.key();
                let who = who.split_once(':').map_or(who.as_str(), |(_, n)| n);
                overlay_markers.push(Marker {
                    x: *g,
                    label: format!("{name} of {who} = {}", speed_label(*g)),
                    short: format!("{name} {}", speed_label(*g)),
                    color,
                });
            }
        }
    }

    // The model: family, clean surfaces, pinned, this scene on top. The member that is this
    // scene is its curve, drawn on top as "this scene (γ = 0.1 J/m²)": drawn as a member too it
    // lay hidden under it with a legend entry of its own (issue 22).
    let meaning = family_meaning(frame);
    let mut scene_member = None;
    let mut first_member = true;
    for (k, m) in frame.family.iter().enumerate() {
        let Some(c) = &m.curve else { continue };
        if m.is_scene && frame.curve.is_some() {
            scene_member = Some(member_name(frame, m.value, false));
            continue;
        }
        let eps = c.eps();
        let short = member_name(frame, m.value, m.is_scene);
        let name = match (first_member, &meaning) {
            (true, Some(meaning)) => format!("{short} (family: {meaning})"),
            _ => short.clone(),
        };
        first_member = false;
        series.push(Series {
            name,
            short,
            points: pts(g, &eps),
            color: k % palette::FAMILY.len(),
            stroke: Stroke::Solid,
        });
        drawn.push(eps);
    }
    if let Some(c) = &frame.clean {
        let eps = c.eps();
        series.push(Series {
            name: "clean surfaces (no layer, no adhesion)".to_string(),
            short: "clean surfaces".to_string(),
            points: pts(g, &eps),
            color: palette::SERIES_CLEAN,
            stroke: Stroke::Dashed,
        });
        drawn.push(eps);
    }
    if let Some(p) = &view.pinned {
        series.push(Series {
            name: format!("pinned: {}", p.label),
            short: format!("pinned: {}", p.label),
            points: pts(&p.g, &p.eps),
            color: palette::SERIES_PINNED,
            stroke: Stroke::Dashed,
        });
        // Only its part over this axis sets the log axis' floor (the axis follows a zoom).
        drawn.push(
            p.g.iter()
                .zip(&p.eps)
                .filter(|(x, _)| **x >= g0 && **x <= g1)
                .map(|(_, e)| *e)
                .collect(),
        );
    }
    if let Some(c) = &frame.curve {
        let eps = c.eps();
        series.push(Series {
            name: scene_member
                .map_or_else(|| "this scene".to_string(), |m| format!("this scene ({m})")),
            short: "this scene".to_string(),
            points: pts(g, &eps),
            color: palette::SERIES_SCENE,
            stroke: Stroke::Solid,
        });
        drawn.push(eps);
    }

    let mut markers: Vec<Marker> = frame
        .markers
        .iter()
        .map(|m| Marker {
            x: m.value,
            label: format!("{} = {}", m.label, speed_label(m.value)),
            short: format!("{} {}", marker_short(m.key), speed_label(m.value)),
            color: palette::SERIES_SCENE,
        })
        .collect();
    markers.extend(overlay_markers);
    let y = if view.y_log {
        let floor = eps_log_floor(drawn.iter().map(|v| &v[..]));
        Axis {
            label: "normal restitution ε_N (log; sticking, ε_N = 0, not shown)".to_string(),
            log: true,
            min: crate::numerics::grid::exact_decade(floor),
            max: 1.0,
        }
    } else {
        Axis {
            label: "normal restitution ε_N".to_string(),
            log: false,
            min: 0.0,
            max: 1.0,
        }
    };
    Figure {
        name: "eps_n".to_string(),
        title: "Normal restitution ε_N over the impact speed".to_string(),
        caption: caption(frame, version),
        x: Axis {
            label: "normal impact speed g_N [m/s]".to_string(),
            log: true,
            min: g0,
            max: g1,
        },
        y,
        series,
        markers,
        bands,
        map: None,
    }
}

/// The stick map of a frame (g_T across, g_N up), when the frame has one.
pub fn map_figure(frame: &Frame, version: &str) -> Option<Figure> {
    let part = frame.map.as_ref()?;
    let map = part.map.as_ref()?;
    Some(Figure::stick_map(
        "stick_map".to_string(),
        "Stick-map classes over (g_N, g_T)".to_string(),
        caption(frame, version),
        map.g.clone(),
        map.class.clone(),
        part.max,
    ))
}

/// Every figure of a frame, as `view` shows it: the ε_N chart, then the stick map if any.
pub fn frame_figures(frame: &Frame, view: &View, version: &str) -> Vec<Figure> {
    let mut out = alloc::vec![eps_figure(frame, view, version)];
    out.extend(map_figure(frame, version));
    out
}

/// The extent of `v` (finite values), or 0…1 when there is none.
fn extent(v: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = v
        .filter(|x| x.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        });
    if lo.is_finite() && hi > lo {
        (lo, hi)
    } else if lo.is_finite() {
        // One value: a unit around it (a flat line still has an axis).
        (
            lo - 0.5 * lo.abs().max(1e-300),
            lo + 0.5 * lo.abs().max(1e-300),
        )
    } else {
        (0.0, 1.0)
    }
}

fn linear(label: &str, (min, max): (f64, f64)) -> Axis {
    Axis {
        label: label.to_string(),
        log: false,
        min,
        max,
    }
}

/// The collision panel's figures (`i`) of one collision at impact speed `g`: the overlap over
/// time ξ(t) and the force–overlap loop F(ξ), each with the phase instants marked
/// (docs/physics.md#collision); with adhesion, `dynamic_loop` — the dynamic JKR model's (ξ, F)
/// loop of brilliantov2007 (docs/physics.md#models) — dotted beside the paper's.
// Long by design: the collision panel's two figures built side by side from one trajectory.
pub fn collision_figures(
    g: f64,
    t: &crate::collision::Trajectory,
    dynamic_loop: &[(f64, f64)],
) -> [Figure; 2] {
    let at_phase = |k: usize| t.phases.iter().any(|p| t.t.get(k) == Some(&p.t));
    let instants = t
        .phases
        .iter()
        .map(|p| {
            format!(
                "{} {}",
                p.name.replace('_', " "),
                super::format::qty3(p.t, "s")
            )
        })
        .collect::<Vec<_>>()
        .join(", ");
    let marks = |x: &[f64], y: &[f64]| Series {
        name: format!("phase instants: {instants}"),
        short: "phase instants".to_string(),
        points: (0..x.len().min(y.len()))
            .filter(|&k| at_phase(k))
            .map(|k| (x[k], y[k]))
            .collect(),
        color: palette::SERIES_EXPERIMENT,
        stroke: Stroke::Points,
    };
    let paper = |x: &[f64], y: &[f64]| Series {
        name: "paper's model, this scene".to_string(),
        short: "this scene".to_string(),
        points: x.iter().copied().zip(y.iter().copied()).collect(),
        color: palette::SERIES_SCENE,
        stroke: Stroke::Solid,
    };
    let caption = format!(
        "One collision at g_N = {}: ε_N = {}, {}.",
        speed_label(g),
        super::format::sig(t.eps_n, 4),
        t.status.label()
    );
    let overlap = Figure {
        name: "collision_overlap".to_string(),
        title: "Overlap over time".to_string(),
        caption: caption.clone(),
        x: linear("time t [s]", extent(t.t.iter().copied())),
        y: linear("overlap ξ [m]", extent(t.xi.iter().copied())),
        series: alloc::vec![paper(&t.t, &t.xi), marks(&t.t, &t.xi)],
        markers: Vec::new(),
        bands: Vec::new(),
        map: None,
    };
    let mut series = Vec::new();
    if !dynamic_loop.is_empty() {
        series.push(Series {
            name: "brilliantov2007 (dynamic JKR: neck and pull-off)".to_string(),
            short: "brilliantov2007".to_string(),
            points: dynamic_loop.to_vec(),
            color: overlay_style(3).0,
            stroke: overlay_style(3).1,
        });
    }
    series.push(paper(&t.xi, &t.force));
    series.push(marks(&t.xi, &t.force));
    let xs = t.xi.iter().copied().chain(dynamic_loop.iter().map(|p| p.0));
    let fs = t
        .force
        .iter()
        .copied()
        .chain(dynamic_loop.iter().map(|p| p.1));
    let force = Figure {
        name: "collision_force".to_string(),
        title: "Force over overlap".to_string(),
        caption,
        x: linear("overlap ξ [m]", extent(xs)),
        y: linear("force F [N]", extent(fs)),
        series,
        markers: Vec::new(),
        bands: Vec::new(),
        map: None,
    };
    [overlap, force]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Accuracy;
    use crate::explorer::frame::{Request, compute};
    use crate::scene::Preset;

    fn frame(scene: crate::Scene) -> Frame {
        let mut req = Request::new(scene, Accuracy::Fast);
        req.points = 40;
        req.map_n = 8;
        compute(&req, &|| false).expect("not cancelled")
    }

    #[test]
    fn measured_data_lie_beneath_the_model_and_only_over_their_speeds_issue_12() {
        let f = frame(Preset::IceFrost.scene());
        let fig = eps_figure(&f, &View::default(), "test");
        let bridges = fig
            .series
            .iter()
            .position(|s| s.name.starts_with("Bridges"))
            .expect("Bridges law drawn");
        let scene = fig
            .series
            .iter()
            .position(|s| s.short == "this scene" && s.color == palette::SERIES_SCENE)
            .expect("scene drawn");
        assert!(
            bridges < scene,
            "measured law must be drawn first (beneath)"
        );
        let [lo, hi] = crate::data::atlas::PENDULUM_SPEED;
        for &(g, e) in &fig.series[bridges].points {
            assert!(
                g >= lo && g <= hi,
                "Bridges law drawn at {g} m/s outside its measured speeds"
            );
            assert!(e < 1.0, "no clamp needed inside the measured speeds");
        }
    }

    /// Issue 21: the y axis was not rescaled on zoom. The log axis' floor is a decade below the
    /// smallest ε_N drawn over the speeds shown, so zooming to slow speeds (ε_N near 1) lifts it.
    #[test]
    fn the_log_axis_follows_a_zoom_issue_21() {
        let scene = Preset::Ice.scene();
        let view = View {
            y_log: true,
            ..View::default()
        };
        let full = eps_figure(&frame(scene), &view, "test");
        let mut req = Request::new(scene, Accuracy::Fast);
        req.points = 40;
        req.map_n = 8;
        req.speeds = Some((1e-6, 1e-4));
        let zoomed_frame = compute(&req, &|| false).expect("not cancelled");
        let zoomed = eps_figure(&zoomed_frame, &view, "test");
        // The floor from the curves themselves: the smallest positive ε_N of every model curve.
        let floor = |f: &Figure| {
            let min = f
                .series
                .iter()
                .flat_map(|s| s.points.iter().map(|p| p.1))
                .filter(|e| e.is_finite() && *e > 0.0)
                .fold(f64::INFINITY, f64::min);
            crate::numerics::grid::exact_decade(
                (libm::floor(crate::numerics::math::log10(min)) as i32).clamp(-12, -1),
            )
        };
        assert_eq!(zoomed.y.min, floor(&zoomed));
        assert!(
            zoomed.y.min > full.y.min,
            "{} vs {}",
            zoomed.y.min,
            full.y.min
        );
        assert_eq!((zoomed.x.min, zoomed.x.max), (1e-6, 1e-4));
    }

    #[test]
    fn the_y_axis_follows_the_view_issue_12() {
        let f = frame(Preset::IceSticky.scene());
        let lin = eps_figure(&f, &View::default(), "test");
        assert!(!lin.y.log && lin.y.min == 0.0 && lin.y.max == 1.0);
        let view = View {
            y_log: true,
            ..View::default()
        };
        let log = eps_figure(&f, &view, "test");
        assert!(log.y.log && log.y.min > 0.0 && log.y.max == 1.0);
        let floor = crate::numerics::math::log10(log.y.min);
        assert_eq!(floor, libm::round(floor), "a whole decade");
    }

    #[test]
    fn the_family_says_what_it_varies_and_marks_this_scene_issue_12() {
        let f = frame(Preset::IceFrost.scene());
        let fig = eps_figure(&f, &View::default(), "test");
        let names: Vec<&str> = fig.series.iter().map(|s| s.name.as_str()).collect();
        assert!(
            names.iter().any(|n| n.contains("varied around this scene")),
            "{names:?}"
        );
        // The member that is this scene is named once, on this scene's own curve (issue 22: it
        // was drawn as a member too, hidden under the scene's curve with a legend entry of its
        // own).
        assert_eq!(f.family.iter().filter(|m| m.is_scene).count(), 1);
        let member = f
            .family
            .iter()
            .find(|m| m.is_scene)
            .expect("a scene member");
        let value = member_name(&f, member.value, false);
        let scene: Vec<&str> = names
            .iter()
            .copied()
            .filter(|n| n.contains(value.as_str()))
            .collect();
        assert_eq!(scene, [format!("this scene ({value})")], "{names:?}");
        assert!(
            !names.iter().any(|n| n.contains("(this scene)")),
            "{names:?}"
        );
        // Every other member is drawn.
        let members = fig
            .series
            .iter()
            .filter(|s| s.color < palette::FAMILY.len())
            .count();
        assert_eq!(members, f.family.len() - 1, "{names:?}");
    }

    /// Every comparison the explorers offer: the terminal's sets and the page's whole list (the
    /// data atlas' laws and ranges, every other model).
    fn comparison_sets(scene: &crate::Scene) -> Vec<Vec<crate::explorer::frame::Overlay>> {
        use crate::explorer::frame::{COMPARISONS, Overlay, comparison};
        let mut sets: Vec<_> = (0..COMPARISONS.len())
            .map(|k| comparison(k, scene))
            .collect();
        let mut all: Vec<Overlay> = crate::data::atlas::ENTRIES
            .iter()
            .filter(|e| e.kind != crate::data::atlas::Kind::Threshold)
            .map(Overlay::Atlas)
            .collect();
        all.extend(
            crate::models::Model::ALL
                .iter()
                .filter(|m| **m != crate::models::Model::Hertzsch2002)
                .filter(|m| m.needs_section().is_none() || scene.plasticity.is_some())
                .map(|m| Overlay::Model(*m)),
        );
        sets.push(all);
        sets
    }

    /// Issues 21 and 22: in compare mode no two series share both colour and stroke, on screen or
    /// in an export (both draw this description); no two legend entries read alike; every
    /// comparison line reads on the white plot (≥ 3:1).
    #[test]
    fn no_two_series_share_colour_and_stroke_in_any_comparison_issue_22() {
        let mut plastic = Preset::IceSticky.scene();
        plastic.plasticity = Some(crate::scene::Plasticity::default());
        let mut checked = 0;
        for scene in [Preset::IceSticky.scene(), Preset::IceFrost.scene(), plastic] {
            for set in comparison_sets(&scene) {
                let mut req = Request::new(scene, Accuracy::Fast);
                req.points = 24;
                req.map_n = 4;
                req.overlays = set.clone();
                let f = compute(&req, &|| false).expect("not cancelled");
                assert!(f.errors.is_empty(), "{:?}", f.errors);
                assert_eq!(f.overlays.len(), set.len());
                let pinned = Pinned {
                    label: "γ 0.2 J/m²".to_string(),
                    g: f.g.clone(),
                    eps: f.g.iter().map(|_| 0.5).collect(),
                };
                for y_log in [false, true] {
                    let view = View {
                        y_log,
                        experiments: true,
                        pinned: Some(pinned.clone()),
                    };
                    let fig = eps_figure(&f, &view, "test");
                    for (i, a) in fig.series.iter().enumerate() {
                        for b in &fig.series[i + 1..] {
                            assert!(
                                (a.color, a.stroke) != (b.color, b.stroke),
                                "{} and {} are both colour {} {:?} ({} overlays)",
                                a.name,
                                b.name,
                                a.color,
                                a.stroke,
                                set.len()
                            );
                        }
                    }
                    let mut legend: Vec<&str> = fig
                        .series
                        .iter()
                        .map(|s| s.name.as_str())
                        .chain(fig.bands.iter().map(|b| b.label.as_str()))
                        .collect();
                    let n = legend.len();
                    legend.sort_unstable();
                    legend.dedup();
                    assert_eq!(legend.len(), n, "legend entries read alike: {legend:?}");
                    // Measured ranges chosen to compare have a colour each (the experimental
                    // context's two boxes share its one colour and carry their names inside).
                    let compared: Vec<&Band> = fig
                        .bands
                        .iter()
                        .filter(|b| b.color >= palette::SERIES_OVERLAY)
                        .collect();
                    for (i, a) in compared.iter().enumerate() {
                        for b in &compared[i + 1..] {
                            assert_ne!(a.color, b.color, "{} and {}", a.label, b.label);
                        }
                    }
                    for s in fig
                        .series
                        .iter()
                        .filter(|s| s.color >= palette::SERIES_OVERLAY)
                    {
                        let c = palette::SERIES[s.color];
                        assert!(c.contrast(palette::WHITE) >= 3.0, "{}: {c:?}", s.name);
                    }
                    checked += 1;
                }
            }
        }
        // 3 scenes × 4 sets × 2 axes; the page's whole list has 12 or 13 comparisons.
        assert_eq!(checked, 24);
        const { assert!(OVERLAY_STYLES >= 13) };
    }

    /// The check above can fail: with the old rule (five hues, all dotted) a long list repeats.
    #[test]
    fn overlay_styles_repeat_only_after_every_pair() {
        let styles: Vec<_> = (0..OVERLAY_STYLES).map(overlay_style).collect();
        for (i, a) in styles.iter().enumerate() {
            assert!(!styles[i + 1..].contains(a), "{a:?} repeats");
        }
        assert_eq!(overlay_style(OVERLAY_STYLES), overlay_style(0));
        let old = |k: usize| (palette::SERIES_OVERLAY + k % 5, Stroke::Dotted);
        assert_eq!(
            old(0),
            old(5),
            "the old rule gave Bridges and Higa one style"
        );
    }
}

#[cfg(all(test, feature = "plot"))]
mod render_tests {
    use super::*;
    use crate::Accuracy;
    use crate::explorer::frame::{Overlay, Request, compute};
    use crate::scene::Preset;

    /// `(x, y, text)` of every `<text>` of an SVG from plotters.
    fn texts(svg: &str) -> Vec<(f64, f64, String)> {
        let mut out = Vec::new();
        for part in svg.split("<text").skip(1) {
            let attr = |name: &str| {
                let key = format!(" {name}=\"");
                part.find(&key).and_then(|i| {
                    let rest = &part[i + key.len()..];
                    rest[..rest.find('"')?].parse::<f64>().ok()
                })
            };
            let body = part
                .split_once('>')
                .and_then(|(_, r)| r.split_once("</text>"))
                .map_or(String::new(), |(t, _)| t.trim().to_string());
            if let (Some(x), Some(y)) = (attr("x"), attr("y")) {
                out.push((x, y, body));
            }
        }
        out
    }

    /// Issue 22: with every comparison on, the legend grew past the figure (17 entries of full
    /// citations) and long labels were cut with "…". Every legend line now lies above the caption,
    /// no label is cut, and the plot keeps at least half the width.
    #[test]
    fn the_legend_of_every_comparison_fits_above_the_caption_issue_22() {
        let scene = Preset::IceSticky.scene();
        let mut req = Request::new(scene, Accuracy::Fast);
        req.points = 24;
        req.map_n = 4;
        req.overlays = crate::data::atlas::ENTRIES
            .iter()
            .filter(|e| e.kind != crate::data::atlas::Kind::Threshold)
            .map(Overlay::Atlas)
            .chain(
                [
                    crate::models::Model::Brilliantov2007,
                    crate::models::Model::SchwagerPoschel2008,
                    crate::models::Model::MullerPoschel2011,
                ]
                .map(Overlay::Model),
            )
            .collect();
        let f = compute(&req, &|| false).expect("not cancelled");
        let fig = eps_figure(&f, &View::default(), "test");
        assert!(fig.series.len() + fig.bands.len() >= 17);
        for (w, h) in [(1200, 800), (800, 500)] {
            let svg = crate::figure::render_svg(&fig, w, h).expect("rendered");
            let all = texts(&svg);
            // The caption's lines are the last texts, at x = 12; everything else lies above them.
            let caption_top = all
                .iter()
                .filter(|t| t.0 == 12.0 && fig.caption.contains(t.2.trim_end_matches(" …")))
                .map(|t| t.1)
                .fold(f64::INFINITY, f64::min);
            assert!(
                caption_top.is_finite() && caption_top < f64::from(h),
                "{caption_top}"
            );
            let legend: Vec<&(f64, f64, String)> =
                all.iter().filter(|t| t.0 > f64::from(w) / 2.0).collect();
            assert!(legend.len() >= 10, "{} legend lines", legend.len());
            for (_, y, text) in &legend {
                assert!(
                    *y < caption_top - 4.0,
                    "{w}×{h}: legend line {text:?} at y {y} reaches the caption at {caption_top}"
                );
                assert!(!text.ends_with('…'), "{w}×{h}: cut legend label {text:?}");
            }
            // Each drawn entry is in the legend, whole or in its short form, or counted as left out.
            let more = legend.iter().find_map(|t| {
                t.2.strip_prefix("… and ")
                    .and_then(|r| r.strip_suffix(" more"))
                    .and_then(|n| n.parse::<usize>().ok())
            });
            let first = |t: &str| t.split_whitespace().next().unwrap_or_default().to_string();
            let listed = fig
                .series
                .iter()
                .filter(|s| {
                    legend.iter().any(|t| {
                        t.2.starts_with(&first(&s.name)) || t.2.starts_with(&first(&s.short))
                    })
                })
                .count();
            assert!(
                listed + more.unwrap_or(0) >= fig.series.len(),
                "{w}×{h}: {listed} of {} series listed, {more:?} more",
                fig.series.len()
            );
        }
    }

    /// Issue 25: a model whose grains stick at every speed has no g_cr marker (there is no speed to
    /// mark) and says "always sticks" in its legend; a model with a threshold gets its marker.
    #[test]
    fn an_always_sticking_model_says_so_in_its_legend_issue_25() {
        let overlay = |a: f64| {
            let mut scene = Preset::IceSticky.scene();
            scene.bulk.damping = crate::Damping::Time(a);
            let mut req = Request::new(scene, Accuracy::Fast);
            req.points = 40;
            req.map_n = 8;
            req.overlays = alloc::vec![super::super::frame::Overlay::Model(
                crate::models::Model::Brilliantov2007
            )];
            let f = compute(&req, &|| false).expect("not cancelled");
            eps_figure(&f, &View::default(), "test")
        };
        let stuck = overlay(1e-3);
        let series = stuck
            .series
            .iter()
            .find(|s| s.short.starts_with("brilliantov2007"))
            .expect("model drawn");
        assert!(series.name.contains("always sticks"), "{}", series.name);
        assert_eq!(series.short, "brilliantov2007 (always sticks)");
        assert!(!stuck.markers.iter().any(|m| m.label.starts_with("g_cr")));
        let rebounds = overlay(1e-4);
        assert!(
            rebounds
                .markers
                .iter()
                .any(|m| m.label.starts_with("g_cr of brilliantov2007"))
        );
        assert!(
            !rebounds
                .series
                .iter()
                .any(|s| s.name.contains("always sticks"))
        );
    }
}
