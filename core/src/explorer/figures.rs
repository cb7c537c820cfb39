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

/// A curve the user pinned to compare with later edits.
#[derive(Debug, Clone, PartialEq)]
pub struct Pinned {
    /// Legend text (e.g. what the scene was).
    pub label: String,
    /// Speeds \[m/s\].
    pub g: Vec<f64>,
    /// ε_N at `g`.
    pub eps: Vec<f64>,
}

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
        (libm::floor(crate::math::log10(min)) as i32).clamp(-12, -1)
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
/// measured data (docs/physics.md#data-atlas), and the scene's rms against it.
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
            if lo == hi {
                format!(" ({lo} K, {})", e.geometry.name())
            } else {
                format!(" ({lo}–{hi} K, {})", e.geometry.name())
            }
        }
        super::frame::Overlay::Model(_) if always_sticks(o) => " (always sticks)".to_string(),
        super::frame::Overlay::Model(_) => String::new(),
    };
    let score = o
        .score
        .map(|r| format!(" rms {}", super::format::sig(r, 2)))
        .unwrap_or_default();
    format!("{name}{context}{score}")
}

/// A frame marker's legend name on small surfaces.
fn marker_short(key: &str) -> &'static str {
    match key {
        "layer" => "g_s layer",
        "adhesion" => "g_s adhesion (a rebound speed)",
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
        let color = palette::SERIES_OVERLAY + k % palette::OVERLAYS.len();
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
            // Dotted: a comparison may share a hue with a family member (there are eight
            // colour-blind-safe hues), never a hue and a stroke.
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
                stroke: Stroke::Dotted,
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

    // The model: family, clean surfaces, pinned, this scene on top.
    let meaning = family_meaning(frame);
    for (k, m) in frame.family.iter().enumerate() {
        let Some(c) = &m.curve else { continue };
        let eps = c.eps();
        let short = member_name(frame, m.value, m.is_scene);
        let name = match (k, &meaning) {
            (0, Some(meaning)) => format!("{short} (family: {meaning})"),
            _ => short.clone(),
        };
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
            name: "this scene".to_string(),
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
            min: crate::sweep::exact_decade(floor),
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
            color: palette::SERIES_OVERLAY + 3,
            stroke: Stroke::Dotted,
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
            .position(|s| s.name == "this scene")
            .expect("scene drawn");
        assert!(
            bridges < scene,
            "measured law must be drawn first (beneath)"
        );
        let [lo, hi] = crate::atlas::PENDULUM_SPEED;
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
            crate::sweep::exact_decade((libm::floor(crate::math::log10(min)) as i32).clamp(-12, -1))
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
        let floor = crate::math::log10(log.y.min);
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
        let scene_members = f.family.iter().filter(|m| m.is_scene).count();
        let marked = names.iter().filter(|n| n.contains("(this scene)")).count();
        assert_eq!(marked, scene_members, "{names:?}");
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
