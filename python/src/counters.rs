//! The handler's counters over a window of time (issue 38): collisions, impact speeds, the
//! collisional transfer of y-momentum across x, and overlaps, as a shearing sheet needs them to
//! measure what kinetic theory predicts (docs/physics.md#handler-counters).
//!
//! Everything is in code units (the simulation's own), as REBOUND's particles are; the Python
//! side (`Attachment.counters`) turns the transfer into a viscosity.

use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Count, sum, sum of squares and largest value of a speed.
#[derive(Clone, Copy, Default, Debug)]
pub struct SpeedSums {
    count: u64,
    sum: f64,
    sum_squares: f64,
    max: f64,
}

impl SpeedSums {
    fn add(&mut self, v: f64) {
        self.count += 1;
        self.sum += v;
        self.sum_squares += v * v;
        self.max = self.max.max(v);
    }

    fn to_dict<'py>(self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("count", self.count)?;
        d.set_item("sum", self.sum)?;
        d.set_item("sum_squares", self.sum_squares)?;
        d.set_item("max", self.max)?;
        Ok(d)
    }
}

/// One collision as the counters see it (code units).
pub struct Hit {
    /// The normal impact speed g_N > 0 (Eq. (2), along the line of centres).
    pub normal_speed: f64,
    /// The tangential speed |g_T| at the contact point (Eq. (2), spins included).
    pub tangential_speed: f64,
    /// How deep the pair overlapped when REBOUND found it: 1 − d/(r₁ + r₂).
    pub depth: f64,
    /// m₁ Δv₁,y (x₁ − x₂): the y-momentum p₁ received from p₂ times the x-distance it crossed
    /// (x₁ with the ghost-box shift; the same as m₂ Δv₂,y (x₂ − x₁)).
    pub transfer: f64,
    /// The kinetic energy (translation + spin) the pair lost.
    pub energy_loss: f64,
}

/// What happened to the pair.
#[derive(Clone, Copy, PartialEq, Debug)]
pub enum Outcome {
    /// ε_N > 0.
    Bounce,
    /// ε_N = 0, kept apart.
    Stay,
    /// ε_N = 0, merged.
    Merge,
}

/// The counters of the window that started at `t_start` (code time).
#[derive(Clone, Debug)]
pub struct Counters {
    t_start: f64,
    bounces: u64,
    stays: u64,
    merges: u64,
    normal: SpeedSums,
    tangential: SpeedSums,
    /// Increasing edges of the normal-speed histogram (empty: no histogram).
    edges: Vec<f64>,
    counts: Vec<u64>,
    below: u64,
    above: u64,
    transfer: f64,
    energy_loss: f64,
    /// Overlaps deeper than this fraction of r₁ + r₂ are counted.
    depth_threshold: f64,
    deeper: u64,
    max_depth: f64,
    sum_depth: f64,
}

impl Counters {
    /// Empty counters starting at `t_start`, with histogram edges and an overlap threshold.
    pub fn new(t_start: f64, edges: Vec<f64>, depth_threshold: f64) -> Counters {
        let bins = edges.len().saturating_sub(1);
        Counters {
            t_start,
            bounces: 0,
            stays: 0,
            merges: 0,
            normal: SpeedSums::default(),
            tangential: SpeedSums::default(),
            edges,
            counts: vec![0; bins],
            below: 0,
            above: 0,
            transfer: 0.0,
            energy_loss: 0.0,
            depth_threshold,
            deeper: 0,
            max_depth: 0.0,
            sum_depth: 0.0,
        }
    }

    /// The overlap threshold (a fraction of r₁ + r₂).
    pub fn depth_threshold(&self) -> f64 {
        self.depth_threshold
    }

    /// The same settings, emptied, starting at `t_start`.
    pub fn restarted(&self, t_start: f64) -> Counters {
        Counters::new(t_start, self.edges.clone(), self.depth_threshold)
    }

    /// Adds one collision.
    pub fn add(&mut self, outcome: Outcome, hit: &Hit) {
        match outcome {
            Outcome::Bounce => self.bounces += 1,
            Outcome::Stay => self.stays += 1,
            Outcome::Merge => self.merges += 1,
        }
        self.normal.add(hit.normal_speed);
        self.tangential.add(hit.tangential_speed);
        if !self.counts.is_empty() {
            let g = hit.normal_speed;
            let last = self.edges.len() - 1;
            if g < self.edges[0] {
                self.below += 1;
            } else if g >= self.edges[last] {
                self.above += 1;
            } else {
                // The bin k with edges[k] <= g < edges[k + 1].
                let k = self.edges.partition_point(|e| *e <= g) - 1;
                self.counts[k] += 1;
            }
        }
        self.transfer += hit.transfer;
        self.energy_loss += hit.energy_loss;
        if hit.depth > self.depth_threshold {
            self.deeper += 1;
        }
        self.max_depth = self.max_depth.max(hit.depth);
        self.sum_depth += hit.depth;
    }

    /// The window as a dict (code units), ending at `t_end`.
    pub fn to_dict<'py>(&self, py: Python<'py>, t_end: f64) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("t_start", self.t_start)?;
        d.set_item("t_end", t_end)?;
        d.set_item("collisions", self.bounces + self.stays + self.merges)?;
        d.set_item("bounces", self.bounces)?;
        d.set_item("stays", self.stays)?;
        d.set_item("merges", self.merges)?;
        d.set_item("normal_speed", self.normal.to_dict(py)?)?;
        d.set_item("tangential_speed", self.tangential.to_dict(py)?)?;
        if self.counts.is_empty() {
            d.set_item("speed_histogram", py.None())?;
        } else {
            let h = PyDict::new(py);
            h.set_item("edges", self.edges.clone())?;
            h.set_item("counts", self.counts.clone())?;
            h.set_item("below", self.below)?;
            h.set_item("above", self.above)?;
            d.set_item("speed_histogram", h)?;
        }
        d.set_item("angular_momentum_flux", self.transfer)?;
        d.set_item("energy_loss", self.energy_loss)?;
        let o = PyDict::new(py);
        o.set_item("threshold", self.depth_threshold)?;
        o.set_item("deeper", self.deeper)?;
        o.set_item("max_depth", self.max_depth)?;
        o.set_item("sum_depth", self.sum_depth)?;
        d.set_item("overlaps", o)?;
        Ok(d)
    }
}

/// Checks histogram edges: finite, ≥ 0, strictly increasing, at least two (or none).
pub fn check_edges(edges: &[f64]) -> Result<(), String> {
    if edges.len() == 1 {
        return Err("give at least two edges (or none for no histogram)".into());
    }
    if let Some(bad) = edges.iter().find(|e| !e.is_finite() || **e < 0.0) {
        return Err(format!("every edge must be finite and >= 0 (got {bad})"));
    }
    if let Some(w) = edges.windows(2).find(|w| w[1] <= w[0]) {
        return Err(format!(
            "edges must increase strictly (got {} then {})",
            w[0], w[1]
        ));
    }
    Ok(())
}
