//! One frame of the explorer, computed once for every surface: the ε_N curve of the scene, the
//! clean-surface curve, a family over a swept parameter, the critical-speed markers, the stick map
//! with its range policy, and the warnings.
//!
//! Every part fails on its own: a part that errors is left out and named in [`Frame::errors`], the
//! others are still computed; a speed whose ε_N fails is a gap (`None`) on its curve. The terminal
//! explorer and the web page call [`compute`] with the same [`Request`] and so draw the same numbers.
//! Pure: no I/O and no clock; cancellable between curves and every few points.

use super::limits::speed_is_valid;
use super::range::{MapRange, auto_map_range, chart_decades};
use crate::figure::sweep::{StickMap, log_space};
use crate::normal::memo::{LayerMemo, NoMemo};
use crate::normal::{Normal, Status};
use crate::{Accuracy, Contact};
use crate::{Scene, error::Error};
use alloc::format;
use alloc::string::String;
use alloc::vec::Vec;

pub use super::request::{
    COMPARISONS, FORCIBLE, Overlay, RELATIVE, Request, SWEEPS, Sweep, comparison,
};

/// An overlay as drawn.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct OverlayCurve {
    /// The overlay.
    #[cfg_attr(
        feature = "serde",
        serde(rename = "key", serialize_with = "overlay_key")
    )]
    pub overlay: Overlay,
    /// Legend text (source, temperature and geometry for measured data).
    pub label: String,
    /// Speeds \[m/s\]: the frame's speeds for a model; the measured speeds for a law (never
    /// beyond them); the two ends of the measured speeds for a range.
    #[cfg_attr(feature = "serde", serde(serialize_with = "super::wire::f64s"))]
    pub g: Vec<f64>,
    /// ε_N at `g` (NaN where the model failed); for a range, the band's low and high ε.
    #[cfg_attr(feature = "serde", serde(serialize_with = "super::wire::f64s"))]
    pub eps: Vec<f64>,
    /// Whether `eps` is a band (a measured range) rather than a curve.
    pub band: bool,
    /// rms of ε_scene − ε_entry over the entry's measured speeds (atlas laws and ranges).
    pub score: Option<f64>,
    /// The model's characteristic speeds (`g_cr`, `v_yield`, …) \[m/s\].
    #[cfg_attr(feature = "serde", serde(serialize_with = "named_speeds"))]
    pub speeds: Vec<(&'static str, f64)>,
}

/// A part of the frame that failed, and why.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct PartError {
    /// Which part (`curve`, `clean`, `family η* = 500`, `marker "sticks below"`, `stick map`, `scene`).
    pub part: String,
    /// The cause, naming the field where there is one.
    pub message: String,
}

/// One ε_N curve on the frame's speeds.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// The full result at each speed (`None` where it failed: a gap).
    pub points: Vec<Option<Normal>>,
}

/// A curve crosses as its ε_N (NaN in the gaps), its status codes ([`Status::code`];
/// [`FAILED`] in the gaps) and its number of gaps.
#[cfg(feature = "serde")]
impl serde::Serialize for Curve {
    fn serialize<S: serde::Serializer>(&self, s: S) -> core::result::Result<S::Ok, S::Error> {
        use crate::wire::F64s;
        use crate::wire::U8s;
        use serde::ser::SerializeStruct;
        let status: Vec<u8> = self
            .points
            .iter()
            .map(|p| p.map_or(FAILED, |n| n.status.code()))
            .collect();
        let mut st = s.serialize_struct("Curve", 3)?;
        st.serialize_field("eps", &F64s(self.eps()))?;
        st.serialize_field("status", &U8s(status))?;
        st.serialize_field("failed", &self.failed())?;
        st.end()
    }
}

/// The status code of a speed whose ε_N could not be computed (a gap on the curve).
pub const FAILED: u8 = u8::MAX;

#[cfg(feature = "serde")]
fn overlay_key<S: serde::Serializer>(o: &Overlay, s: S) -> core::result::Result<S::Ok, S::Error> {
    s.serialize_str(&o.key())
}

#[cfg(feature = "serde")]
fn named_speeds<S: serde::Serializer>(
    speeds: &[(&'static str, f64)],
    s: S,
) -> core::result::Result<S::Ok, S::Error> {
    use serde::ser::{SerializeMap, SerializeSeq};
    struct Named(&'static str, f64);
    impl serde::Serialize for Named {
        fn serialize<S: serde::Serializer>(&self, s: S) -> core::result::Result<S::Ok, S::Error> {
            let mut m = s.serialize_map(Some(2))?;
            m.serialize_entry("name", self.0)?;
            m.serialize_entry("value", &self.1)?;
            m.end()
        }
    }
    let mut seq = s.serialize_seq(Some(speeds.len()))?;
    for &(name, value) in speeds {
        seq.serialize_element(&Named(name, value))?;
    }
    seq.end()
}

/// The family's sweep crosses as its parameter: `{path, symbol, unit}`.
#[cfg(feature = "serde")]
fn sweep_form<S: serde::Serializer>(sweep: &usize, s: S) -> core::result::Result<S::Ok, S::Error> {
    use serde::ser::SerializeMap;
    let mut m = s.serialize_map(Some(3))?;
    if let Some(w) = SWEEPS.get(*sweep) {
        m.serialize_entry("path", w.path)?;
        m.serialize_entry("symbol", w.symbol)?;
        m.serialize_entry("unit", w.unit)?;
    }
    m.end()
}

impl Curve {
    /// ε_N at each speed, NaN in the gaps.
    pub fn eps(&self) -> Vec<f64> {
        self.points
            .iter()
            .map(|p| p.map_or(f64::NAN, |n| n.eps))
            .collect()
    }

    /// Number of gaps.
    pub fn failed(&self) -> usize {
        self.points.iter().filter(|p| p.is_none()).count()
    }
}

/// One member of the family of curves.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Member {
    /// Value of the swept parameter.
    pub value: f64,
    /// Whether this member is the scene itself (its value equals the scene's).
    pub is_scene: bool,
    /// Its curve (`None` when the member's scene is invalid).
    pub curve: Option<Curve>,
}

/// A marker on the speed axis.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Marker {
    /// `layer`, `adhesion` or `stick`.
    pub key: &'static str,
    /// Legend text.
    pub label: &'static str,
    /// Speed \[m/s\].
    pub value: f64,
}

/// The stick map part.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct MapPart {
    /// Upper end of both axes \[m/s\].
    pub max: f64,
    /// Whether the range is automatic, and its note (cut to the speed limit).
    pub auto: Option<MapRange>,
    /// The map, or why it could not be computed.
    pub map: Option<StickMap>,
}

/// Everything one frame shows. With `serde`, its serde form is what the page receives (through
/// [`super::wire`], its number arrays as typed buffers); the request and the contact stay behind.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Frame {
    /// The request it answers.
    #[cfg_attr(feature = "serde", serde(skip))]
    pub request: Request,
    /// Derived constants (`None` if the scene cannot be evaluated; see `errors`).
    #[cfg_attr(feature = "serde", serde(skip))]
    pub contact: Option<Contact>,
    /// The sweep of the family (index into [`SWEEPS`]).
    #[cfg_attr(feature = "serde", serde(serialize_with = "sweep_form"))]
    pub sweep: usize,
    /// Log-spaced impact speeds of every curve \[m/s\].
    #[cfg_attr(feature = "serde", serde(serialize_with = "super::wire::f64s"))]
    pub g: Vec<f64>,
    /// The scene's curve.
    pub curve: Option<Curve>,
    /// The clean surface (no layer, no adhesion), when the scene has either.
    pub clean: Option<Curve>,
    /// The family of curves (empty when the sweep does not apply).
    pub family: Vec<Member>,
    /// Critical speeds (Eq. (10), Eq. (15)) and where the grains stick.
    pub markers: Vec<Marker>,
    /// The stick map (`None` without friction).
    pub map: Option<MapPart>,
    /// Warnings about the scene (options that deviate from the paper, overdamped ranges).
    pub warnings: Vec<super::warning::Warning>,
    /// The requested overlays that could be computed (the others are named in `errors`).
    pub overlays: Vec<OverlayCurve>,
    /// Parts that failed.
    pub errors: Vec<PartError>,
}

impl Frame {
    /// This scene's result at speed index `i` (`None` in a gap or without a curve).
    pub fn point(&self, i: usize) -> Option<Normal> {
        self.curve.as_ref()?.points.get(i).copied().flatten()
    }

    /// The stick map, when there is one.
    pub fn stick_map(&self) -> Option<&StickMap> {
        self.map.as_ref()?.map.as_ref()
    }

    /// Upper end of the stick map's axes \[m/s\], when there is a map part.
    pub fn map_max(&self) -> Option<f64> {
        self.map.as_ref().map(|m| m.max)
    }

    /// The first problem, in one line: the scene's own error when the contact cannot be derived
    /// (a surface shows it in place of the curves), else `part: message`.
    pub fn problem(&self) -> Option<String> {
        self.errors.first().map(|e| {
            if e.part == "scene" {
                e.message.clone()
            } else {
                format!("{}: {}", e.part, e.message)
            }
        })
    }

    /// Notes to show beside the views (a map range cut to the speed limit).
    pub fn notes(&self) -> Option<&'static str> {
        self.map.as_ref()?.auto.as_ref()?.note()
    }
}

fn part_error(part: impl Into<String>, message: impl Into<String>) -> PartError {
    PartError {
        part: part.into(),
        message: message.into(),
    }
}

/// ε_N at every speed of `g`, the speeds `offset..` of a curve; `None` if cancelled. `force`
/// fails every 40th speed of the curve (a test of gaps).
fn curve(
    contact: &Contact,
    g: &[f64],
    offset: usize,
    accuracy: Accuracy,
    force: bool,
    cancelled: &dyn Fn() -> bool,
    memo: &dyn LayerMemo,
) -> Option<(Vec<Option<Normal>>, Option<String>)> {
    let mut points = Vec::with_capacity(g.len());
    let mut first = None;
    for (k, &gi) in g.iter().enumerate() {
        let i = offset + k;
        if i % 32 == 31 && cancelled() {
            return None;
        }
        let r = if force && i % 40 == 20 {
            Err(String::from("failure forced for testing"))
        } else {
            contact
                .normal_with(gi, accuracy, memo)
                .map_err(|e| format!("{e}"))
        };
        match r {
            Ok(n) => points.push(Some(n)),
            Err(e) => {
                first.get_or_insert_with(|| format!("at g_N = {gi:.4e} m/s: {e}"));
                points.push(None);
            }
        }
    }
    Some((points, first))
}

fn gap_error(part: &str, c: &Curve, first: Option<String>) -> Option<PartError> {
    first.map(|msg| {
        part_error(
            part,
            format!(
                "{} of {} speeds failed (gaps), first {msg}",
                c.failed(),
                c.points.len()
            ),
        )
    })
}

/// The largest impact speed at which the grains stick, by bisection in log speed on the status the
/// core reports (`None` when they never stick in \[1e-12, 1e2\] m/s, or always do).
pub fn stick_threshold(contact: &Contact, accuracy: Accuracy) -> crate::Result<Option<f64>> {
    stick_threshold_within(contact, accuracy, &NoMemo, STICK_THRESHOLD_RTOL)
}

/// The bisection's relative width at which [`stick_threshold`] stops.
pub const STICK_THRESHOLD_RTOL: f64 = 1e-12;

/// The relative width to which the explorer's "sticks below" marker is located at `accuracy`: the
/// level's own error bound on ε_N ([`Accuracy::error_bound`], 1e-6 at `fast` and `integrated`,
/// 1e-10 at `precise`), never below [`STICK_THRESHOLD_RTOL`]. Each halving is one contact; at
/// `fast` this takes 25 of them instead of 45, which on the literal layer reading is most of a
/// preview's time (issue 26).
pub fn marker_rtol(accuracy: Accuracy) -> f64 {
    accuracy.error_bound().max(STICK_THRESHOLD_RTOL)
}

/// [`stick_threshold`] with the literal layer reading's outcomes kept in `memo`, stopping when the
/// bracket's relative width is below `rtol`.
pub fn stick_threshold_within(
    contact: &Contact,
    accuracy: Accuracy,
    memo: &dyn LayerMemo,
    rtol: f64,
) -> crate::Result<Option<f64>> {
    let stuck = |g: f64| -> crate::Result<bool> {
        let r = contact.normal_with(g, accuracy, memo)?;
        Ok(matches!(
            r.status,
            Status::StuckInLayer | Status::StuckByAdhesion
        ))
    };
    let (mut lo, mut hi) = (1e-12_f64, 1e2_f64);
    if !stuck(lo)? || stuck(hi)? {
        return Ok(None);
    }
    for _ in 0..80 {
        let mid = crate::numerics::math::sqrt(lo * hi);
        if stuck(mid)? {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi / lo < 1.0 + rtol {
            break;
        }
    }
    Ok(Some(hi))
}

/// Points on an atlas law's measured speeds.
const OVERLAY_LAW_POINTS: usize = 64;

/// A model's ε_N at the speeds `g` (NaN where it fails).
fn model_eps(evaluator: &crate::models::Evaluator, g: &[f64], accuracy: Accuracy) -> Vec<f64> {
    g.iter()
        .map(|&gi| evaluator.eps(gi, accuracy).map_or(f64::NAN, |r| r.eps))
        .collect()
}

/// One overlay on the frame's speeds `g` (see [`OverlayCurve`]).
// Long by design: one overlay of each kind (measured law, range, model) with its own speeds and
// score; the kinds share the frame's grid.
pub fn overlay_curve(
    overlay: Overlay,
    scene: &Scene,
    contact: &Contact,
    g: &[f64],
    accuracy: Accuracy,
) -> crate::Result<OverlayCurve> {
    use crate::data::atlas::Kind;
    match overlay {
        Overlay::Atlas(entry) => {
            let [lo, hi] = entry.valid_speed;
            let t = entry.temperature;
            // An ansatz with no experiment (borderies1984) has no temperature: none is printed.
            let temperature = if !t[1].is_finite() {
                String::from("any temperature")
            } else if t[0] == t[1] {
                format!("{} K", t[0])
            } else {
                format!("{}–{} K", t[0], t[1])
            };
            // What tells entries of one paper apart (Hatzes et al. 1988 has three): the material.
            let label = format!(
                "{} {}, {} ({temperature}, {}, measured {}–{})",
                entry.citation.short_authors(),
                entry.citation.year,
                entry.material,
                entry.geometry.name(),
                crate::figure::speed_label(lo),
                crate::figure::speed_label(hi),
            );
            // An entry that needs a radius takes the scene's reduced radius.
            let radius = entry.needs_radius().then_some(contact.r_eff);
            match entry.kind {
                Kind::Threshold => Err(Error::InvalidValue {
                    field: "overlays",
                    expected: "a law or a range (a threshold is not a curve)",
                }),
                Kind::Range => {
                    let band = entry.band().ok_or(Error::InvalidValue {
                        field: "overlays",
                        expected: "a range entry with an ε band",
                    })?;
                    Ok(OverlayCurve {
                        overlay,
                        label,
                        g: alloc::vec![lo, hi],
                        eps: band.to_vec(),
                        band: true,
                        score: Some(crate::data::atlas::score(contact, accuracy, entry, radius)?),
                        speeds: Vec::new(),
                    })
                }
                Kind::Law => {
                    let mut gs = alloc::vec![0.0; OVERLAY_LAW_POINTS];
                    log_space(lo, hi, &mut gs);
                    let mut eps = Vec::with_capacity(gs.len());
                    for &gi in &gs {
                        eps.push(entry.eval(gi, radius)?.eps);
                    }
                    Ok(OverlayCurve {
                        overlay,
                        label,
                        g: gs,
                        eps,
                        band: false,
                        score: Some(crate::data::atlas::score(contact, accuracy, entry, radius)?),
                        speeds: Vec::new(),
                    })
                }
            }
        }
        Overlay::Model(model) => {
            let evaluator = crate::models::Evaluator::new(model, scene)?;
            let eps = model_eps(&evaluator, g, accuracy);
            let speeds = evaluator
                .characteristic_speeds(accuracy)
                .map(|s| s.iter().map(|c| (c.name, c.value)).collect())
                .unwrap_or_default();
            Ok(OverlayCurve {
                overlay,
                label: String::from(model.citation()),
                g: g.to_vec(),
                eps,
                band: false,
                score: None,
                speeds,
            })
        }
    }
}

/// Which curve of a frame a [`Unit`] computes points of.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CurveOf {
    /// The scene's curve.
    Scene,
    /// The clean surface's curve.
    Clean,
    /// Family member `k` (index into [`Plan::members`]).
    Member(usize),
}

/// One independent piece of a frame's work: a frame is the [`Plan::assemble`] of its plan's
/// units' outputs, in the order of [`Plan::units`], whichever order (or thread) computed them.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Unit {
    /// The points `from..to` of a curve.
    Curve {
        /// Which curve.
        of: CurveOf,
        /// First speed index.
        from: usize,
        /// One past the last speed index.
        to: usize,
    },
    /// The "sticks below" marker (a bisection on the scene's status).
    Threshold,
    /// Overlay `k` of the request (for a model: its label and characteristic speeds; its points
    /// are [`Unit::OverlayPoints`]).
    Overlay(usize),
    /// ε_N of model overlay `k` at the speeds `from..to`.
    OverlayPoints {
        /// Which overlay.
        k: usize,
        /// First speed index.
        from: usize,
        /// One past the last speed index.
        to: usize,
    },
    /// ε_N at the stick map's grid speeds `from..to` (its rows; the cells are classified from
    /// them when the frame is assembled).
    MapRows {
        /// First grid index.
        from: usize,
        /// One past the last grid index.
        to: usize,
    },
}

/// What a [`Unit`] computed.
#[derive(Debug, Clone, PartialEq)]
pub enum Output {
    /// Points of a curve and the first failure among them (`at g_N = …: cause`).
    Curve(Vec<Option<Normal>>, Option<String>),
    /// The stick threshold, or why it failed.
    Threshold(Result<Option<f64>, String>),
    /// An overlay, or why it failed.
    Overlay(Result<OverlayCurve, String>),
    /// ε_N of a model overlay at some speeds (NaN where the model failed).
    OverlayPoints(Vec<f64>),
    /// ε_N at the map rows and the right-hand-side evaluations spent, or the first failure.
    MapRows(Result<(Vec<f64>, usize), String>),
}

/// A member of the family before its curve is computed.
#[derive(Debug, Clone, PartialEq)]
pub struct PlannedMember {
    /// Value of the swept parameter.
    pub value: f64,
    /// Whether it is the scene itself.
    pub is_scene: bool,
    /// Its contact, or why it has none.
    pub contact: Result<Contact, String>,
}

/// The stick map before its rows are computed.
#[derive(Debug, Clone, PartialEq)]
pub struct PlannedMap {
    /// Upper end of both axes \[m/s\].
    pub max: f64,
    /// The automatic range, when it is one.
    pub auto: Option<MapRange>,
    /// The grid speeds, or why the map cannot be computed.
    pub grid: Result<Vec<f64>, String>,
}

/// A frame's work, split into independent [`Unit`]s: everything cheap is decided here (the
/// speeds, the contacts of the scene, the clean surface and the family members, the map's range);
/// the units do the expensive rest. `Plan` is `Sync`: threads may run its units side by side.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    /// The frame without its computed parts.
    pub frame: Frame,
    /// The scene's contact.
    pub contact: Contact,
    /// The clean surface's contact (or why it has none), when the scene has a layer or adhesion.
    pub clean: Option<Result<Contact, String>>,
    /// The family's members.
    pub members: Vec<PlannedMember>,
    /// The stick map, when the scene has friction.
    pub map: Option<PlannedMap>,
}

/// Points per curve unit below which a curve is not split further.
const MIN_CHUNK: usize = 16;

impl Plan {
    /// Points per curve unit and rows per map unit for a surface that runs the units side by side
    /// (the terminal's threads, the page's two workers): a 241-point curve is 8 units, so the cores
    /// share even a frame whose cost is one curve (a compared model's), and a unit is long enough
    /// (≥ 30 ε_N evaluations) that handing it out costs nothing.
    pub const UNIT_POINTS: usize = 32;

    /// Plans `req`; a request that is not valid or a scene that cannot be evaluated gives the
    /// finished frame (with its `request` or `scene` error) instead.
    // Long by design: every unit of the frame planned in the order compute() runs them, so the
    // two stay one reading.
    pub fn new(req: &Request) -> Result<Plan, alloc::boxed::Box<Frame>> {
        let scene = req.scene;
        let sweep = req.sweep.unwrap_or_else(|| Sweep::default_for(&scene));
        let contact = Contact::new(&scene);
        let mut frame = Frame {
            request: req.clone(),
            contact: contact.as_ref().ok().copied(),
            sweep,
            g: Vec::new(),
            curve: None,
            clean: None,
            family: Vec::new(),
            markers: Vec::new(),
            map: None,
            warnings: Vec::new(),
            overlays: Vec::new(),
            errors: Vec::new(),
        };
        if let Err(e) = req.validate() {
            frame.errors.push(part_error("request", format!("{e}")));
            return Err(alloc::boxed::Box::new(frame));
        }
        let (from, to) = req.speeds.unwrap_or_else(|| {
            let (lo, hi) = chart_decades(contact.as_ref().ok());
            (
                crate::numerics::grid::exact_decade(lo),
                crate::numerics::grid::exact_decade(hi),
            )
        });
        frame.g = alloc::vec![0.0; req.points];
        log_space(from, to, &mut frame.g);
        let contact = match contact {
            Ok(c) => c,
            Err(e) => {
                frame.errors.push(part_error("scene", format!("{e}")));
                return Err(alloc::boxed::Box::new(frame));
            }
        };
        let clean = (scene.layer.is_some() || scene.adhesion.is_some()).then(|| {
            Contact::new(&Scene {
                layer: None,
                adhesion: None,
                ..scene
            })
            .map_err(|e| format!("{e}"))
        });
        let s = SWEEPS[sweep];
        let mut members = Vec::new();
        if req.family && s.available(&scene) {
            let current = s.current(&scene);
            for v in s.values(&scene) {
                let contact = if req.forced("family") {
                    Err(String::from("failure forced for testing"))
                } else {
                    s.apply(&scene, v)
                        .and_then(|m| Contact::new(&m))
                        .map_err(|e| format!("{e}"))
                };
                members.push(PlannedMember {
                    value: v,
                    is_scene: v == current,
                    contact,
                });
            }
        }
        let map = contact.friction.is_some().then(|| {
            let auto = req.map_max.is_none().then(|| auto_map_range(&contact));
            let max = req.map_max.or(auto.map(|a| a.max)).unwrap_or(1.0);
            let grid = if req.forced("map") {
                Err(String::from("failure forced for testing"))
            } else if !speed_is_valid(max) {
                // A range the models refuse fails the map alone.
                Err(format!(
                    "map_max: {max} m/s is not a speed in {} m/s",
                    crate::scene::limits::SPEED_DOMAIN
                ))
            } else {
                let mut g = alloc::vec![0.0; req.map_n];
                crate::figure::sweep::linear_space(max, &mut g);
                Ok(g)
            };
            PlannedMap { max, auto, grid }
        });
        Ok(Plan {
            frame,
            contact,
            clean,
            members,
            map,
        })
    }

    /// The units of this frame, in the order their outputs are assembled. A curve is split into
    /// units of about `chunk` points (at least 16; `usize::MAX`: whole curves), the
    /// map's rows likewise.
    pub fn units(&self, chunk: usize) -> Vec<Unit> {
        let chunk = chunk.max(MIN_CHUNK);
        let ranges = |n: usize| {
            let parts = n.div_ceil(chunk).max(1);
            (0..parts).map(move |k| (k * n / parts, (k + 1) * n / parts))
        };
        let n = self.frame.g.len();
        let mut units = Vec::new();
        let curve = |of: CurveOf, units: &mut Vec<Unit>| {
            units.extend(ranges(n).map(|(from, to)| Unit::Curve { of, from, to }));
        };
        curve(CurveOf::Scene, &mut units);
        if matches!(self.clean, Some(Ok(_))) {
            curve(CurveOf::Clean, &mut units);
        }
        for (k, m) in self.members.iter().enumerate() {
            if m.contact.is_ok() {
                curve(CurveOf::Member(k), &mut units);
            }
        }
        units.push(Unit::Threshold);
        for (k, o) in self.frame.request.overlays.iter().enumerate() {
            units.push(Unit::Overlay(k));
            if matches!(o, Overlay::Model(_)) {
                units.extend(ranges(n).map(|(from, to)| Unit::OverlayPoints { k, from, to }));
            }
        }
        if let Some(PlannedMap { grid: Ok(g), .. }) = &self.map {
            units.extend(ranges(g.len()).map(|(from, to)| Unit::MapRows { from, to }));
        }
        units
    }

    /// Computes one unit; `None` if cancelled.
    pub fn run(&self, unit: &Unit, cancelled: &dyn Fn() -> bool) -> Option<Output> {
        self.run_with(unit, cancelled, &NoMemo)
    }

    /// [`Plan::run`] with the literal layer reading's outcomes kept in `memo` between frames
    /// (the same output, bit for bit; see [`crate::normal::memo`]).
    // Long by design: one arm per kind of unit, each reading its part of the plan.
    pub fn run_with(
        &self,
        unit: &Unit,
        cancelled: &dyn Fn() -> bool,
        memo: &dyn LayerMemo,
    ) -> Option<Output> {
        if cancelled() {
            return None;
        }
        let req = &self.frame.request;
        match *unit {
            Unit::Curve { of, from, to } => {
                let (contact, force) = match of {
                    CurveOf::Scene => (Some(&self.contact), req.forced("curve")),
                    CurveOf::Clean => (self.clean.as_ref().and_then(|c| c.as_ref().ok()), false),
                    CurveOf::Member(k) => (
                        self.members.get(k).and_then(|m| m.contact.as_ref().ok()),
                        false,
                    ),
                };
                let g = self.frame.g.get(from..to).unwrap_or_default();
                let (points, first) = match contact {
                    Some(c) => curve(c, g, from, req.accuracy, force, cancelled, memo)?,
                    None => (alloc::vec![None; g.len()], None),
                };
                Some(Output::Curve(points, first))
            }
            Unit::Threshold => {
                let threshold = if req.forced("marker") {
                    Err(String::from("failure forced for testing"))
                } else {
                    stick_threshold_within(
                        &self.contact,
                        req.accuracy,
                        memo,
                        marker_rtol(req.accuracy),
                    )
                    .map_err(|e| format!("{e}"))
                };
                Some(Output::Threshold(threshold))
            }
            Unit::Overlay(k) => {
                let o = req
                    .overlays
                    .get(k)
                    .ok_or_else(|| String::from("no such overlay"));
                Some(Output::Overlay(o.and_then(|o| {
                    // A model's points are units of their own: here only its label and speeds.
                    let g: &[f64] = match o {
                        Overlay::Model(_) => &[],
                        Overlay::Atlas(_) => &self.frame.g,
                    };
                    overlay_curve(*o, &req.scene, &self.contact, g, req.accuracy)
                        .map_err(|e| format!("{e}"))
                })))
            }
            Unit::OverlayPoints { k, from, to } => {
                let g = self.frame.g.get(from..to).unwrap_or_default();
                let eps = match req.overlays.get(k) {
                    Some(Overlay::Model(model)) => {
                        match crate::models::Evaluator::new(*model, &req.scene) {
                            Ok(evaluator) => model_eps(&evaluator, g, req.accuracy),
                            Err(_) => alloc::vec![f64::NAN; g.len()],
                        }
                    }
                    _ => alloc::vec![f64::NAN; g.len()],
                };
                Some(Output::OverlayPoints(eps))
            }
            Unit::MapRows { from, to } => {
                let g = match &self.map {
                    Some(PlannedMap { grid: Ok(g), .. }) => g.get(from..to).unwrap_or_default(),
                    _ => &[],
                };
                let mut eps = alloc::vec![0.0; g.len()];
                Some(Output::MapRows(
                    crate::figure::sweep::eps_n_into_with(
                        &self.contact,
                        g,
                        req.accuracy,
                        &mut eps,
                        memo,
                    )
                    .map(|evaluations| (eps, evaluations))
                    .map_err(|e| format!("{e}")),
                ))
            }
        }
    }

    /// The frame from the outputs of [`Plan::units`] (`outputs[i]` from `units[i]`), with its
    /// parts, errors and warnings in the order [`compute`] gives them.
    // Long by design: the frame's parts put back together in compute()'s order (curve, clean,
    // family, overlays, markers, map, warnings), each part's failure kept on its own.
    pub fn assemble(self, units: &[Unit], outputs: Vec<Output>) -> Frame {
        let Plan {
            mut frame,
            contact,
            clean,
            members,
            map,
        } = self;
        let mut curves: Vec<(CurveOf, Vec<Option<Normal>>, Option<String>)> = Vec::new();
        let mut threshold = Ok(None);
        let mut overlays = Vec::new();
        let mut rows: Result<(Vec<f64>, usize), String> = Ok((Vec::new(), 0));
        for (unit, output) in units.iter().zip(outputs) {
            match (unit, output) {
                (Unit::Curve { of, .. }, Output::Curve(points, first)) => {
                    match curves.last_mut().filter(|c| c.0 == *of) {
                        Some(c) => {
                            c.1.extend(points);
                            if c.2.is_none() {
                                c.2 = first;
                            }
                        }
                        None => curves.push((*of, points, first)),
                    }
                }
                (Unit::Threshold, Output::Threshold(t)) => threshold = t,
                (Unit::Overlay(k), Output::Overlay(o)) => overlays.push((*k, o)),
                (Unit::OverlayPoints { k, .. }, Output::OverlayPoints(eps)) => {
                    if let Some((_, Ok(o))) = overlays.last_mut().filter(|o| o.0 == *k) {
                        if o.g.is_empty() {
                            o.g = frame.g.clone();
                        }
                        o.eps.extend(eps);
                    }
                }
                (Unit::MapRows { .. }, Output::MapRows(r)) => {
                    if let Ok((all, evaluations)) = &mut rows {
                        match r {
                            Ok((eps, e)) => {
                                all.extend(eps);
                                *evaluations += e;
                            }
                            Err(e) => rows = Err(e),
                        }
                    }
                }
                _ => {}
            }
        }
        let mut curves = curves.into_iter().map(|(of, points, first)| {
            let c = Curve { points };
            (of, c, first)
        });
        let mut next_curve = |of: CurveOf| {
            curves
                .next()
                .filter(|c| c.0 == of)
                .map(|(_, c, first)| (c, first))
        };
        if let Some((c, first)) = next_curve(CurveOf::Scene) {
            frame.errors.extend(gap_error("curve", &c, first));
            frame.curve = Some(c);
        }
        match clean {
            Some(Ok(_)) => {
                if let Some((c, first)) = next_curve(CurveOf::Clean) {
                    frame.errors.extend(gap_error("clean", &c, first));
                    frame.clean = Some(c);
                }
            }
            Some(Err(e)) => frame.errors.push(part_error("clean", e)),
            None => {}
        }
        let symbol = SWEEPS[frame.sweep].symbol;
        for (k, m) in members.into_iter().enumerate() {
            let part = format!("family {symbol} = {}", m.value);
            let curve = match m.contact {
                Ok(_) => next_curve(CurveOf::Member(k)).map(|(c, first)| {
                    frame.errors.extend(gap_error(&part, &c, first));
                    c
                }),
                Err(e) => {
                    frame.errors.push(part_error(part, e));
                    None
                }
            };
            frame.family.push(Member {
                value: m.value,
                is_scene: m.is_scene,
                curve,
            });
        }
        if let Some(l) = &contact.layer {
            frame.markers.push(Marker {
                key: "layer",
                label: "g_s layer (Eq. (10))",
                value: l.critical_velocity,
            });
        }
        if let Some(a) = &contact.adhesion {
            frame.markers.push(Marker {
                key: "adhesion",
                label: "g_s adhesion (Eq. (15)): a rebound slower than g_s sticks; g_s",
                value: a.critical_velocity,
            });
        }
        match threshold {
            Ok(Some(t)) => frame.markers.push(Marker {
                key: "stick",
                label: "sticks below",
                value: t,
            }),
            Ok(None) => {}
            Err(e) => frame.errors.push(part_error("marker \"sticks below\"", e)),
        }
        frame.warnings = super::warning::warnings(
            &frame.request.scene,
            frame
                .curve
                .iter()
                .flat_map(|c| c.points.iter().map(|p| p.map(|n| n.status))),
            Some(contact.damping_time),
        );
        for (k, o) in overlays {
            match o {
                Ok(o) => frame.overlays.push(o),
                Err(e) => {
                    let part = frame.request.overlays.get(k).map(|o| o.key());
                    frame.errors.push(part_error(part.unwrap_or_default(), e));
                }
            }
        }
        if let Some(PlannedMap { max, auto, grid }) = map {
            let map = grid.and_then(|g| {
                let (eps_n, rhs_evaluations) = rows?;
                let n = g.len();
                let mut class = alloc::vec![crate::tangential::StickClass::Undefined; n * n];
                let mut eps_t = alloc::vec![0.0; n * n];
                crate::figure::sweep::stick_map_into(&contact, &g, &eps_n, &mut class, &mut eps_t)
                    .map_err(|e| format!("{e}"))?;
                Ok(StickMap {
                    g,
                    eps_n,
                    class,
                    eps_t,
                    rhs_evaluations,
                })
            });
            let map = match map {
                Ok(m) => Some(m),
                Err(e) => {
                    frame.errors.push(part_error("stick map", e));
                    None
                }
            };
            frame.map = Some(MapPart { max, auto, map });
        }
        frame
    }
}

/// Computes a frame. Returns `None` as soon as `cancelled()` says a newer request is waiting.
/// A request that is not valid (see [`Request::validate`]) is reported as a `request` part error.
///
/// This is the sequential reference: the [`Plan`]'s units one after another. A surface with
/// threads may run the units side by side and [`Plan::assemble`] their outputs: the frame is the
/// same, bit for bit.
///
/// # Examples
///
/// ```
/// use rime_core::explorer::frame::{Request, compute};
/// use rime_core::{Accuracy, Preset};
///
/// let mut request = Request::new(Preset::IceFrost.scene(), Accuracy::Fast);
/// request.points = 31;
/// request.map_n = 5;
/// let frame = compute(&request, &|| false).expect("not cancelled");
/// assert!(frame.errors.is_empty(), "{:?}", frame.errors);
/// assert_eq!(frame.g.len(), 31);
/// assert!(!frame.family.is_empty());
/// // A computation told to stop returns nothing.
/// assert!(compute(&request, &|| true).is_none());
/// ```
// Long by design: the frame's parts in order (contact, curve, clean, family, markers, map,
// warnings), each failing on its own; the cancellation checks sit between them.
pub fn compute(req: &Request, cancelled: &dyn Fn() -> bool) -> Option<Frame> {
    compute_with(req, cancelled, &NoMemo)
}

/// [`compute`] with the literal layer reading's outcomes kept in `memo` between frames: the same
/// frame, bit for bit, without integrating again what an earlier frame integrated.
pub fn compute_with(
    req: &Request,
    cancelled: &dyn Fn() -> bool,
    memo: &dyn LayerMemo,
) -> Option<Frame> {
    let plan = match Plan::new(req) {
        Ok(plan) => plan,
        Err(frame) => return Some(*frame),
    };
    let units = plan.units(usize::MAX);
    let mut outputs = Vec::with_capacity(units.len());
    for unit in &units {
        outputs.push(plan.run_with(unit, cancelled, memo)?);
    }
    Some(plan.assemble(&units, outputs))
}

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Preset;

    #[test]
    fn every_part_fails_on_its_own() {
        let mut req = Request::new(Preset::IceFrost.scene(), Accuracy::Fast);
        req.points = 81;
        req.map_n = 11;
        req.fail = alloc::vec![String::from("map"), String::from("marker")];
        let f = compute(&req, &|| false).unwrap();
        assert!(f.curve.is_some() && f.clean.is_some() && f.family.len() == 4);
        assert!(f.map.as_ref().is_some_and(|m| m.map.is_none()));
        assert!(f.markers.iter().any(|m| m.key == "layer"));
        assert!(!f.markers.iter().any(|m| m.key == "stick"));
        let parts: Vec<&str> = f.errors.iter().map(|e| e.part.as_str()).collect();
        assert_eq!(parts, ["marker \"sticks below\"", "stick map"]);
    }

    #[test]
    fn the_frame_equals_the_core_speed_by_speed() {
        // What every surface draws is exactly what `Contact::normal` gives at those speeds.
        let req = Request::new(Preset::IceSticky.scene(), Accuracy::Precise);
        let f = compute(&req, &|| false).unwrap();
        let c = Contact::new(&req.scene).unwrap();
        for (g, p) in f.g.iter().zip(&f.curve.unwrap().points) {
            assert_eq!(p.unwrap(), c.normal(*g, Accuracy::Precise).unwrap());
        }
        // The stick threshold lies above Eq. (15)'s g_s (a rebound speed): ε_v g = g_s there.
        let t = f.markers.iter().find(|m| m.key == "stick").unwrap().value;
        let g_s = c.adhesion.unwrap().critical_velocity;
        let eps_v = Contact::new(&Scene {
            adhesion: None,
            ..req.scene
        })
        .unwrap()
        .normal(t, Accuracy::Precise)
        .unwrap()
        .eps;
        assert!((eps_v * t / g_s - 1.0).abs() < 1e-9, "{t} {g_s} {eps_v}");
    }

    #[test]
    fn the_stick_marker_is_located_to_the_levels_own_bound_issue_26() {
        // Eq. (15): at the stick threshold t the rebound speed without adhesion equals g_s,
        // ε_v(t) t = g_s. The marker is bisected to `marker_rtol` of its level; with the level's
        // own ε_N error that puts ε_v(t) t / g_s within a few bounds of 1 (ε_v at `precise`).
        let scene = Preset::IceSticky.scene();
        let c = Contact::new(&scene).unwrap();
        let g_s = c.adhesion.unwrap().critical_velocity;
        let clean = Contact::new(&Scene {
            adhesion: None,
            ..scene
        })
        .unwrap();
        for level in [Accuracy::Fast, Accuracy::Balanced, Accuracy::Precise] {
            let mut req = Request::new(scene, level);
            req.points = 11;
            req.map_n = 3;
            let f = compute(&req, &|| false).unwrap();
            let t = f.markers.iter().find(|m| m.key == "stick").unwrap().value;
            let eps_v = clean.normal(t, Accuracy::Precise).unwrap().eps;
            let off = (eps_v * t / g_s - 1.0).abs();
            assert!(
                off < 4.0 * marker_rtol(level),
                "{level:?}: {t} off by {off:e}"
            );
            // And the bisection agrees with the library's 1e-12 threshold to its own width.
            let exact = stick_threshold(&c, Accuracy::Precise).unwrap().unwrap();
            assert!(
                (t / exact - 1.0).abs() < 4.0 * marker_rtol(level),
                "{level:?}: {t} vs {exact}"
            );
        }
        assert_eq!(marker_rtol(Accuracy::Fast), 1e-6);
        assert_eq!(marker_rtol(Accuracy::Precise), 1e-10);
        assert_eq!(
            marker_rtol(Accuracy::Tolerance(1e-13)),
            STICK_THRESHOLD_RTOL
        );
    }

    #[test]
    fn overlays_are_drawn_over_their_measured_speeds_only() {
        let mut req = Request::new(Preset::Ice.scene(), Accuracy::Fast);
        req.points = 41;
        req.map_n = 5;
        req.overlays = alloc::vec![
            Overlay::parse("atlas:bridges1984").unwrap(),
            Overlay::parse("model:thornton1997").unwrap(),
            Overlay::parse("model:muller_poschel2011").unwrap(),
        ];
        let f = compute(&req, &|| false).unwrap();
        // thornton1997 needs a plasticity section the preset lacks: that overlay alone fails.
        assert_eq!(f.overlays.len(), 2, "{:?}", f.errors);
        assert!(f.errors.iter().any(|e| e.part == "model:thornton1997"));
        let law = &f.overlays[0];
        let entry = crate::data::atlas::find("bridges1984").unwrap();
        assert_eq!(law.g.first(), Some(&entry.valid_speed[0]));
        assert_eq!(law.g.last(), Some(&entry.valid_speed[1]));
        for (g, e) in law.g.iter().zip(&law.eps) {
            assert_eq!(*e, entry.eval(*g, None).unwrap().eps);
        }
        let c = Contact::new(&req.scene).unwrap();
        assert_eq!(
            law.score,
            Some(crate::data::atlas::score(&c, Accuracy::Fast, entry, None).unwrap())
        );
        assert_eq!(f.overlays[1].g, f.g);
        assert!(Overlay::parse("atlas:nope").is_err() && Overlay::parse("bridges1984").is_err());
    }

    /// Issue 26: the plan's units, split finely and run in reverse order, assemble into the frame
    /// `compute` gives, bit for bit (compared through `Debug`, which prints every f64 exactly and
    /// NaN as NaN), gaps, forced failures, overlays and the map included.
    #[test]
    fn units_in_any_order_assemble_the_sequential_frame_issue_26() {
        let literal = Preset::IceFrost
            .scene()
            .with_layer_reading(crate::LayerReading::Literal);
        let scenes = [
            Preset::Ice.scene(),
            Preset::IceFrost.scene(),
            Preset::IceSticky.scene(),
            literal,
        ];
        for (k, scene) in scenes.into_iter().enumerate() {
            for accuracy in [Accuracy::Fast, Accuracy::Precise] {
                let mut req = Request::new(scene, accuracy);
                req.points = 57;
                req.map_n = 23;
                req.overlays = comparison(1 + k % 2, &scene);
                if k == 1 {
                    req.fail = alloc::vec![String::from("curve"), String::from("marker")];
                }
                let reference = compute(&req, &|| false).unwrap();
                let plan = Plan::new(&req).unwrap();
                let units = plan.units(MIN_CHUNK);
                assert!(units.len() > 8, "{units:?}");
                let mut outputs: Vec<Option<Output>> = alloc::vec![None; units.len()];
                for (i, u) in units.iter().enumerate().rev() {
                    outputs[i] = plan.run(u, &|| false);
                }
                let outputs = outputs.into_iter().map(Option::unwrap).collect();
                let frame = plan.assemble(&units, outputs);
                assert_eq!(
                    format!("{frame:?}"),
                    format!("{reference:?}"),
                    "{k} {accuracy:?}"
                );
            }
        }
    }

    /// A frame computed with a memo is the frame computed without one, bit for bit, whether the
    /// memo is cold, warm from the same request, or warm from a scene that differs only after the
    /// layer stage (adhesion, friction); and the warm frames integrate no literal contact again.
    #[cfg(feature = "std")]
    #[test]
    fn frames_with_the_literal_memo_equal_frames_without_it_issue_26() {
        use crate::normal::memo::SharedLayerMemo;
        let literal = Preset::IceFrost
            .scene()
            .with_layer_reading(crate::LayerReading::Literal);
        let mut sticky = literal;
        sticky.set_number("adhesion.surface_energy", 0.02).unwrap();
        let mut rough = literal;
        rough.set_number("friction.coefficient", 0.45).unwrap();
        // One memo for both levels: the integrator's tolerance is part of what is kept.
        let memo = SharedLayerMemo::new();
        for accuracy in [Accuracy::Fast, Accuracy::Precise] {
            let request = |scene: Scene| {
                let mut req = Request::new(scene, accuracy);
                req.points = 41;
                req.map_n = 17;
                req
            };
            let plain =
                |scene: Scene| format!("{:?}", compute(&request(scene), &|| false).unwrap());
            let kept = |scene: Scene| {
                format!(
                    "{:?}",
                    compute_with(&request(scene), &|| false, &memo).unwrap()
                )
            };
            let (_, before) = memo.hits_and_misses();
            assert_eq!(kept(literal), plain(literal), "cold, {accuracy:?}");
            let (_, cold_misses) = memo.hits_and_misses();
            assert!(cold_misses - before > 41, "{cold_misses} {before}");
            // The same request again, then an edit of friction: every literal contact is kept.
            for scene in [literal, rough] {
                assert_eq!(kept(scene), plain(scene), "warm, {accuracy:?}");
                assert_eq!(memo.hits_and_misses().1, cold_misses, "{accuracy:?}");
            }
            // An edit of adhesion keeps the curve and the map; only the stick threshold's
            // bisection (at most 2 ends + 80 halvings) may ask for new speeds.
            assert_eq!(kept(sticky), plain(sticky), "warm, {accuracy:?}");
            let (_, misses) = memo.hits_and_misses();
            assert!(misses - cold_misses <= 82, "{misses} {cold_misses}");
            // An edit of the layer stage's inputs (A) is integrated again, and still equal.
            let mut slower = literal;
            slower
                .set_number("bulk.damping.time", 1.1 * literal.damping_time())
                .unwrap();
            assert_eq!(kept(slower), plain(slower), "{accuracy:?}");
            assert!(memo.hits_and_misses().1 > misses + 41, "{accuracy:?}");
        }
    }

    #[test]
    fn a_bad_request_names_its_field() {
        let mut req = Request::new(Preset::Ice.scene(), Accuracy::Fast);
        req.speeds = Some((1.0, 1e-3));
        let f = compute(&req, &|| false).unwrap();
        assert_eq!(f.errors.len(), 1);
        assert!(f.errors[0].message.starts_with("to"), "{:?}", f.errors);
        assert!(compute(&req, &|| true).is_some()); // validation precedes any cancellation point
        let req = Request::new(Preset::Ice.scene(), Accuracy::Fast);
        assert!(compute(&req, &|| true).is_none());
    }
}
