//! The worker's job: the core's request ([`frame::Request`]) tagged with the generation that
//! asked for it, computed by the one explorer model ([`frame::compute`]) into the core's
//! [`Frame`], which the views read as it is.

use rime_core::explorer::frame::{self, Frame};
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

/// Computes a job. Returns `None` as soon as `cancelled()` says a newer request is waiting.
pub fn compute(job: &Job, cancelled: &dyn Fn() -> bool) -> Option<Computed> {
    let start = Instant::now();
    let frame = frame::compute(&job.request, cancelled)?;
    Some(Computed {
        generation: job.generation,
        elapsed: start.elapsed(),
        frame,
    })
}
