//! The worker's job: the core's request ([`frame::Request`]) tagged with the generation that
//! asked for it, computed by the one explorer model into the core's [`Frame`], which the views read
//! as it is.
//!
//! The core's frame is a [`Plan`] of independent units (curve chunks, family members, map rows);
//! [`frame()`] runs them on every core with scoped threads and assembles the same frame, bit for bit,
//! as the core's sequential [`frame::compute`]. [`progressive`] first sends a preview at `fast`,
//! then the frame at the requested level (issue 26).

use rime_core::Accuracy;
use rime_core::explorer::frame::{self, Frame, Plan};
use rime_core::normal::memo::LayerMemo;
use std::time::{Duration, Instant};

pub use rime_core::explorer::frame::{SWEEPS, Sweep};

/// What the worker is asked to compute.
#[derive(Debug, Clone, PartialEq)]
pub struct Job {
    /// Increases with every request; results of older requests are dropped.
    pub generation: u64,
    /// The core's request.
    pub request: frame::Request,
}

/// A computed frame with the generation that asked for it and its wall time.
#[derive(Debug, Clone, PartialEq)]
pub struct Computed {
    /// The request's generation.
    pub generation: u64,
    /// Wall time of the computation.
    pub elapsed: Duration,
    /// The core's frame: what every view draws and the `x` export writes.
    pub frame: Frame,
    /// Whether this is the `fast` preview of a request at another level (never exported).
    pub preview: bool,
}

impl std::ops::Deref for Computed {
    type Target = Frame;

    fn deref(&self) -> &Frame {
        &self.frame
    }
}

/// The speed range a frame was computed over (its first and last speed).
pub fn auto_speeds(data: &Frame) -> (f64, f64) {
    match (data.g.first(), data.g.last()) {
        (Some(lo), Some(hi)) if lo < hi => (*lo, *hi),
        _ => (1e-7, 10.0),
    }
}

/// Threads a frame uses: the cores this process may use (as the subcommands).
pub use crate::parallel::threads;

/// Work a frame does alone before it calls in the other cores: a helper that takes a unit and then
/// waits for a core on a busy machine holds the frame back by a scheduler slice (milliseconds),
/// which only a frame longer than that can afford.
const SPAWN_AFTER: Duration = Duration::from_millis(2);

/// Computes `req` on `threads` threads (1: the core's sequential [`frame::compute`]); `None` as soon
/// as `cancelled()` says a newer request is waiting. The frame equals the sequential one bit for
/// bit: the units are the same and are assembled in the same order. `memo` keeps the literal layer
/// reading's outcomes between frames (the terminal's session keeps one; the same frame either way).
pub fn frame(
    req: &frame::Request,
    cancelled: &(dyn Fn() -> bool + Sync),
    threads: usize,
    memo: &dyn LayerMemo,
) -> Option<Frame> {
    if threads <= 1 {
        return frame::compute_with(req, cancelled, memo);
    }
    let plan = match Plan::new(req) {
        Ok(plan) => plan,
        Err(frame) => return Some(*frame),
    };
    let units = plan.units(Plan::UNIT_POINTS);
    // A unit that sees the cancellation returns `None`, which stops the other threads too.
    let outputs = crate::parallel::in_turn(units.len(), threads, Some(SPAWN_AFTER), |i| {
        plan.run_with(&units[i], cancelled, memo)
    })?;
    Some(plan.assemble(&units, outputs))
}

/// Computes a job at its level on every core. Returns `None` as soon as `cancelled()` says a newer
/// request is waiting.
pub fn compute(
    job: &Job,
    cancelled: &(dyn Fn() -> bool + Sync),
    memo: &dyn LayerMemo,
) -> Option<Computed> {
    compute_on(job, cancelled, threads(), memo)
}

/// [`compute`] on `threads` threads.
pub fn compute_on(
    job: &Job,
    cancelled: &(dyn Fn() -> bool + Sync),
    threads: usize,
    memo: &dyn LayerMemo,
) -> Option<Computed> {
    let start = Instant::now();
    let frame = frame(&job.request, cancelled, threads, memo)?;
    Some(Computed {
        generation: job.generation,
        elapsed: start.elapsed(),
        frame,
        preview: false,
    })
}
/// The preview of a request: the same request at `fast` (same speeds, so the chart's cursor keeps
/// its place); `None` when the request is already at `fast`.
pub fn preview_request(req: &frame::Request) -> Option<frame::Request> {
    (req.accuracy != Accuracy::Fast).then(|| frame::Request {
        accuracy: Accuracy::Fast,
        ..req.clone()
    })
}

/// A frame gets a `fast` preview first only when the last frame of its kind took longer than this
/// to compute, or its kind is new: a quicker one is on screen as soon as its preview would be, and
/// the preview only puts it a frame later (issue 37; the page's rule, `SLOW_MS` in www/app.js).
pub const PREVIEW_SLOW: Duration = Duration::from_millis(8);

/// The page's preview rule for the terminal's worker: what the last frame of each kind cost.
/// A frame's kind is what its cost depends on: its level, the compared overlays, the family's
/// sweep, the parameters whose edit asked for it (the literal layer reading's memo answers an edit
/// of μ and not one of E) and the scene with every number blanked.
#[derive(Debug, Default)]
pub struct PreviewRule {
    costs: std::collections::HashMap<String, Duration>,
    last_scene: Option<rime_core::Scene>,
}

impl PreviewRule {
    /// The kind of `req`, after the request before it (whose scene tells what was edited).
    pub fn kind(&mut self, req: &frame::Request) -> String {
        use rime_core::params::{PARAMETERS, Value};
        let edited: Vec<&str> = match &self.last_scene {
            Some(last) => PARAMETERS
                .iter()
                .filter(|p| last.get(p.path) != req.scene.get(p.path))
                .map(|p| p.path)
                .collect(),
            None => Vec::new(),
        };
        self.last_scene = Some(req.scene);
        let shape: Vec<String> = PARAMETERS
            .iter()
            .map(|p| match req.scene.get(p.path) {
                Ok(Value::Number(_)) => "#".to_string(),
                Ok(Value::Choice(c)) => c.to_string(),
                Ok(Value::Enabled(b)) => b.to_string(),
                Ok(Value::Inactive) | Err(_) => "-".to_string(),
            })
            .collect();
        format!(
            "{}|{:?}|{:?}|{}|{}|{}",
            req.accuracy.name(),
            req.overlays,
            req.sweep,
            req.family,
            edited.join(","),
            shape.join(",")
        )
    }

    /// Whether a frame of `kind` gets a preview: its kind is new, or its last frame was dear.
    pub fn wants_preview(&self, kind: &str) -> bool {
        self.costs.get(kind).is_none_or(|cost| *cost > PREVIEW_SLOW)
    }

    /// Remembers what a frame of `kind` cost.
    pub fn record(&mut self, kind: String, cost: Duration) {
        self.costs.insert(kind, cost);
    }
}

/// What the worker does with a job: a `fast` preview first (when the job asks for another level
/// and `rule` says its kind is dear or new), handed to `deliver` marked as a preview, then the
/// frame at the job's level, whose cost `rule` remembers. Stops as soon as `cancelled()` (a newer
/// edit, or quitting) or when `deliver` returns `false` (the receiver is gone); returns `false` in
/// that last case.
pub fn progressive(
    job: &Job,
    cancelled: &(dyn Fn() -> bool + Sync),
    threads: usize,
    memo: &dyn LayerMemo,
    rule: &mut PreviewRule,
    deliver: &mut dyn FnMut(Computed) -> bool,
) -> bool {
    let kind = rule.kind(&job.request);
    let preview = preview_request(&job.request).filter(|_| rule.wants_preview(&kind));
    if let Some(request) = preview {
        let start = Instant::now();
        let Some(frame) = frame(&request, cancelled, threads, memo) else {
            return true;
        };
        let preview = Computed {
            generation: job.generation,
            elapsed: start.elapsed(),
            frame,
            preview: true,
        };
        if !deliver(preview) {
            return false;
        }
    }
    match compute_on(job, cancelled, threads, memo) {
        Some(done) => {
            rule.record(kind, done.elapsed);
            deliver(done)
        }
        None => true,
    }
}
