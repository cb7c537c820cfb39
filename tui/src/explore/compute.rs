//! The data behind one frame: ε_N curves (current scene, a family over a swept parameter, the clean
//! surface) and the stick map. Pure functions of a [`Request`]; the worker thread calls [`compute`].

use rime_core::sweep::StickMap;
use rime_core::{Accuracy, Contact, Normal, Scene};
use std::time::{Duration, Instant};

/// Number of speeds on each ε_N curve.
pub const CURVE_POINTS: usize = 241;
/// Grid size of the stick map (`n × n`).
pub const MAP_POINTS: usize = 81;

pub use rime_core::explorer::frame::{SWEEPS, Sweep};

/// What the worker is asked to compute.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Request {
    /// Increases with every request; results of older requests are dropped.
    pub generation: u64,
    /// The scene.
    pub scene: Scene,
    /// Accuracy level.
    pub accuracy: Accuracy,
    /// Index into [`SWEEPS`].
    pub sweep: usize,
    /// Upper end of both stick-map axes \[m/s\], or `None` for automatic.
    pub map_max: Option<f64>,
    /// What is drawn over the chart beside the scene (`c` cycles): index into [`OVERLAY_SETS`].
    pub overlay_set: usize,
    /// The chart's speed range \[m/s\] (the core's `speeds`); `None`: automatic decades.
    pub speeds: Option<(f64, f64)>,
}

/// The overlay sets the explorer's `c` cycles through: nothing, the measured laws and ranges of the
/// data atlas (each only over the speeds it was measured at, with the scene's rms score), the other
/// collision models on the same grains (with their characteristic speeds).
pub const OVERLAY_SETS: [(&str, &[&str]); 3] = [
    ("no comparison", &[]),
    (
        "measured ice",
        &[
            "atlas:bridges1984",
            "atlas:hatzes1988_frost",
            "atlas:supulver1995",
            "atlas:heisselmann2010",
            "atlas:hill2015",
        ],
    ),
    (
        "other models",
        &[
            "model:brilliantov2007",
            "model:muller_poschel2011",
            "model:thornton1997",
        ],
    ),
];

/// One member of the family of curves.
#[derive(Debug, Clone, PartialEq)]
pub struct Member {
    /// Value of the swept parameter.
    pub value: f64,
    /// ε_N at the curve speeds (0 when stuck, NaN when it could not be computed).
    pub eps: Vec<f64>,
}

/// Everything one frame shows.
#[derive(Debug, Clone, PartialEq)]
pub struct FrameData {
    /// The request's generation.
    pub generation: u64,
    /// The scene the data belong to.
    pub scene: Scene,
    /// Accuracy used.
    pub accuracy: Accuracy,
    /// Index into [`SWEEPS`].
    pub sweep: usize,
    /// Derived constants (None if the scene cannot be evaluated).
    pub contact: Option<Contact>,
    /// Log-spaced impact speeds \[m/s\].
    pub g: Vec<f64>,
    /// The current scene's result at each speed (None where it failed).
    pub current: Vec<Option<Normal>>,
    /// ε_N of the clean surface (no layer, no adhesion), when the scene has a layer or adhesion.
    pub clean: Option<Vec<f64>>,
    /// The family of curves.
    pub family: Vec<Member>,
    /// The stick map (None without friction).
    pub map: Option<StickMap>,
    /// Upper end of the stick map's axes \[m/s\].
    pub map_max: f64,
    /// A problem to show (e.g. the contact could not be derived).
    pub error: Option<String>,
    /// Notes to show beside the views (e.g. a range cut to the speed limit).
    pub notes: Vec<String>,
    /// Measured laws or other models drawn over the chart (see [`OVERLAY_SETS`]).
    pub overlays: Vec<rime_core::explorer::frame::OverlayCurve>,
    /// Wall time of the computation.
    pub elapsed: Duration,
    /// The core's frame these views were adapted from: the records and figures of the `x` export
    /// are built from it by the same core functions the page and the subcommands use.
    pub frame: rime_core::explorer::frame::Frame,
}

/// The speed range a frame was computed over (its first and last speed).
pub fn auto_speeds(data: &FrameData) -> (f64, f64) {
    match (data.g.first(), data.g.last()) {
        (Some(lo), Some(hi)) if lo < hi => (*lo, *hi),
        _ => (1e-7, 10.0),
    }
}

/// Computes a frame with the one explorer model of the core ([`rime_core::explorer::frame`]), and
/// adapts it to what the terminal's views read. Returns `None` as soon as `cancelled()` says a newer
/// request is waiting.
pub fn compute(req: &Request, cancelled: &dyn Fn() -> bool) -> Option<FrameData> {
    use rime_core::explorer::frame;
    let start = Instant::now();
    let mut core_req = frame::Request::new(req.scene, req.accuracy);
    core_req.points = CURVE_POINTS;
    core_req.map_n = MAP_POINTS;
    core_req.sweep = Some(req.sweep).filter(|k| *k < SWEEPS.len());
    core_req.map_max = req.map_max;
    core_req.speeds = req.speeds;
    core_req.overlays = OVERLAY_SETS
        .get(req.overlay_set)
        .map(|(_, keys)| {
            keys.iter()
                .filter_map(|k| frame::Overlay::parse(k).ok())
                // thornton1997 only where the scene has the plasticity section it needs.
                .filter(|o| {
                    !matches!(
                        o,
                        frame::Overlay::Model(rime_core::models::Model::Thornton1997)
                    ) || req.scene.plasticity.is_some()
                })
                .collect()
        })
        .unwrap_or_default();
    let f = frame::compute(&core_req, cancelled)?;
    let core_frame = f.clone();
    let mut notes: Vec<String> = Vec::new();
    let mut map = None;
    let mut map_max = req.map_max.unwrap_or(1.0);
    if let Some(part) = f.map {
        map_max = part.max;
        notes.extend(part.auto.and_then(|a| a.note()).map(String::from));
        map = part.map;
    }
    // The terminal shows one problem line: the first failing part (the scene's own error when the
    // contact cannot be derived, which the chart shows in place of the curves).
    let error = f.errors.first().map(|e| {
        if e.part == "scene" {
            e.message.clone()
        } else {
            format!("{}: {}", e.part, e.message)
        }
    });
    Some(FrameData {
        generation: req.generation,
        scene: req.scene,
        accuracy: req.accuracy,
        sweep: f.sweep,
        contact: f.contact,
        current: f
            .curve
            .map(|c| c.points)
            .unwrap_or_else(|| vec![None; f.g.len()]),
        g: f.g,
        clean: f.clean.map(|c| c.eps()),
        family: f
            .family
            .into_iter()
            .filter_map(|m| {
                Some(Member {
                    value: m.value,
                    eps: m.curve?.eps(),
                })
            })
            .collect(),
        map,
        map_max,
        error,
        notes,
        overlays: f.overlays,
        elapsed: start.elapsed(),
        frame: core_frame,
    })
}
