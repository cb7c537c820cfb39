//! The time course inside one collision (re-exported by [`crate::collision`], which describes it).

use crate::error::{Error, Result};
use crate::normal::trace::{Kind, Recorder, StateMap, Tail};
use crate::normal::{Normal, Status, layer, viscoelastic};
use crate::numerics::accuracy::Accuracy;
use crate::numerics::math::{powf, sqrt};
use crate::numerics::ode::DenseStep;
use crate::scene::contact::Contact;
use crate::scene::{ContactEnd, LayerReading};
use alloc::vec::Vec;

/// One named instant of a collision.
#[derive(Debug, Clone, Copy, PartialEq)]
// Serialize only: phase names are the core's own words (`&'static str`).
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Phase {
    /// `layer_crushing`, `bulk_loading`, `maximum_compression`, `unloading`, `coast`,
    /// `layer_exit`, `creep` or `end_of_contact`.
    pub name: &'static str,
    /// When it starts (or happens) \[s\] after first touch.
    pub t: f64,
}

/// Where the impact energy goes \[J\]; each term is computed from its own force.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Ledger {
    /// ½ m_eff g².
    pub kinetic_in: f64,
    /// ½ m_eff (ε_N g)².
    pub kinetic_out: f64,
    /// ∫ ρ_H 1.5 A √ξ ξ'² dt, the viscous term of Eq. (4) (Eq. (8) bottom in the literal reading).
    pub dissipated_bulk: f64,
    /// ∫ (3/2) m_eff (√R_eff η*/m_eff) √ξ ξ'² dt, the drag of Eq. (8) top.
    pub dissipated_layer: f64,
    /// The net work of the elastic force ρ_H ξ^(3/2) over the contact: the energy still stored in
    /// the deformation when the force-zero rule ends it (the bulk relaxes after separation); 0 with
    /// `zero_overlap` and for a layer whose bulk overlap returns to 0.
    pub elastic_retained: f64,
    /// W_s of Eq. (12) paid on the rebound (Eq. (17)), or all that remains when adhesion holds.
    pub adhesion: f64,
    /// (in − out − Σ dissipated − retained − adhesion)/in.
    pub closure: f64,
}

/// One collision, sampled.
#[derive(Debug, Clone, PartialEq)]
// Serialize only: phase names are the core's own words (`&'static str`).
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Trajectory {
    /// Sample times \[s\] (evenly spaced plus the phase instants, increasing).
    pub t: Vec<f64>,
    /// Total overlap ξ \[m\] (crushed layer included).
    pub xi: Vec<f64>,
    /// ξ' \[m/s\] (positive while approaching).
    pub xi_dot: Vec<f64>,
    /// Normal force \[N\] (positive: repulsive).
    pub force: Vec<f64>,
    /// The phases, in time order.
    pub phases: Vec<Phase>,
    /// Contact duration \[s\] as [`Contact::normal`] (infinite when the grains stick or the
    /// duration is unresolved).
    pub t_c: f64,
    /// Maximum compression \[m\] as [`Contact::normal`].
    pub xi_max: f64,
    /// ε_N as [`Contact::normal`].
    pub eps_n: f64,
    /// As [`Contact::normal`].
    pub status: Status,
    /// The energy ledger.
    pub ledger: Ledger,
    /// False where the end of the contact is known only through ε_N's closed form (a strongly
    /// overdamped creep): the samples then stop where the integration stopped.
    pub resolved: bool,
    /// Right-hand-side evaluations of the trajectory's integration.
    pub rhs_evaluations: usize,
}

/// Scales of one integrated stretch: its reference speed and where it sits in the collision.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Scale {
    /// Reference speed g (the impact speed, or g − g_s for the offset reading's bulk).
    g: f64,
    xi_star: f64,
    tau: f64,
    /// SI time and overlap at the stretch's s = 0.
    t_offset: f64,
    xi_offset: f64,
    /// 1.5 δ and λ = c ξ*^(3/2)/g at this speed.
    k: f64,
    lambda: f64,
}

/// A stretch of the trajectory with one law.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Piece {
    /// Integrated: one accepted step of the dense output on `[c0, c1]` (its own clock).
    Step {
        step: DenseStep<2>,
        map: StateMap,
        c0: f64,
        c1: f64,
        scale: Scale,
    },
    /// Eq. (9) in closed form through the layer in dimensionless w = √(x): speed `a + b w³`
    /// (in units of `scale.g`), x from `x0` to `x1` (decreasing on the way out), starting at SI
    /// time `t0`.
    Layer {
        a: f64,
        b: f64,
        x0: f64,
        x1: f64,
        t0: f64,
        t1: f64,
        scale: Scale,
    },
    /// No force: constant velocity `v` from overlap `xi0` \[SI\].
    Coast { t0: f64, t1: f64, xi0: f64, v: f64 },
}

/// Five-point Gauss–Legendre on [−1, 1]: exact for polynomials of degree 9.
const GAUSS: [(f64, f64); 5] = [
    (0.0, 0.568_888_888_888_888_9),
    (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];

fn gauss(lo: f64, hi: f64, f: impl Fn(f64) -> f64) -> f64 {
    let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
    GAUSS
        .iter()
        .map(|&(x, w)| w * f(mid + half * x))
        .sum::<f64>()
        * half
}

/// Collects the dense output of an integration.
struct Collector {
    scale: Scale,
    pieces: Vec<Piece>,
    tail: Option<Tail>,
}

impl Recorder for Collector {
    fn step(&mut self, step: &DenseStep<2>, map: &StateMap) {
        if step.h == 0.0 {
            return;
        }
        let s_start = map.s(step.t0);
        if let Some(Piece::Step {
            step: last,
            map: last_map,
            c1,
            ..
        }) = self.pieces.last_mut()
        {
            if last == step && last_map == map {
                return;
            }
            // A restart after an event: the previous step ran past it.
            if last_map.s(*c1) > s_start {
                *c1 = last_map.clock(s_start);
            }
        }
        self.pieces.push(Piece::Step {
            step: *step,
            map: *map,
            c0: step.t0,
            c1: step.t0 + step.h,
            scale: self.scale,
        });
    }

    fn tail(&mut self, tail: Tail) {
        self.tail = Some(tail);
    }
}

impl Collector {
    fn new(scale: Scale) -> Self {
        Collector {
            scale,
            pieces: Vec::new(),
            tail: None,
        }
    }

    /// Cuts the integrated steps at dimensionless time `s_end` of their own stretch.
    fn truncate(&mut self, s_end: f64) {
        self.pieces.retain(|p| match p {
            Piece::Step { map, c0, .. } => map.s(*c0) < s_end,
            _ => true,
        });
        if let Some(Piece::Step { map, c1, .. }) = self.pieces.last_mut()
            && map.s(*c1) > s_end
        {
            *c1 = map.clock(s_end);
        }
    }
}

fn scale(contact: &Contact, g: f64, t_offset: f64, xi_offset: f64) -> Scale {
    let xi_star = contact.length_scale(g);
    let drag = contact.layer.map_or(0.0, |l| l.drag);
    Scale {
        g,
        xi_star,
        tau: contact.time_scale(g),
        t_offset,
        xi_offset,
        k: 1.5 * contact.delta(g),
        lambda: drag * xi_star * sqrt(xi_star) / g,
    }
}

impl Piece {
    fn span(&self) -> (f64, f64) {
        match *self {
            Piece::Step {
                map, c0, c1, scale, ..
            } => (
                scale.t_offset + scale.tau * map.s(c0),
                scale.t_offset + scale.tau * map.s(c1),
            ),
            Piece::Layer { t0, t1, .. } | Piece::Coast { t0, t1, .. } => (t0, t1),
        }
    }

    /// (ξ, ξ', F) at SI time `t` inside the piece.
    fn sample(&self, t: f64, m_eff: f64) -> (f64, f64, f64) {
        match *self {
            Piece::Step {
                step, map, scale, ..
            } => {
                let clock = map.clock((t - scale.t_offset) / scale.tau);
                let y = step.eval(clock);
                let (x, v) = map.overlap_velocity(&y);
                let x = x.max(0.0);
                let unit = m_eff * scale.g * scale.g / scale.xi_star;
                let f = match map.kind {
                    // Eq. (4): ρ_H √ξ (ξ + 1.5 A ξ'), with the force form's h = x + k v itself.
                    Kind::Bulk => unit * sqrt(x) * map.force_k.map_or(x + scale.k * v, |_| y[1]),
                    // Eq. (8) top: (3/2) m_eff c √ξ ξ'.
                    Kind::Layer => unit * 1.5 * scale.lambda * sqrt(x) * v,
                    Kind::Coast => 0.0,
                };
                (scale.xi_offset + scale.xi_star * x, scale.g * v, f)
            }
            Piece::Layer {
                a,
                b,
                x0,
                x1,
                t0,
                scale,
                ..
            } => {
                // Invert the closed-form time t(x) = t0 + τ ∫ dx/|a + b x^(3/2)| by bisection.
                let elapsed = (t - t0) / scale.tau;
                let time_to = |x: f64| layer_time(a, b, x0, x);
                let (mut lo, mut hi) = (0.0, 1.0);
                for _ in 0..64 {
                    let mid = 0.5 * (lo + hi);
                    if time_to(x0 + mid * (x1 - x0)) < elapsed {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let x = x0 + 0.5 * (lo + hi) * (x1 - x0);
                let w = sqrt(x);
                let speed = a + b * w * w * w;
                let v = if x1 >= x0 { speed } else { -speed };
                let unit = m_eff * scale.g * scale.g / scale.xi_star;
                (
                    scale.xi_offset + scale.xi_star * x,
                    scale.g * v,
                    unit * 1.5 * scale.lambda * w * v,
                )
            }
            Piece::Coast { t0, xi0, v, .. } => (xi0 + v * (t - t0), v, 0.0),
        }
    }
}

/// Dimensionless time from x0 to x through the layer with speed `a + b x^(3/2)` (Eq. (9)).
fn layer_time(a: f64, b: f64, x0: f64, x: f64) -> f64 {
    // Both closed forms run from 0: crushing ∫₀^x dx/(1 − λ x^(3/2)); the way out
    // ∫₀^x dx/(ε + λ x^(3/2)) (`layer::exit_time`, here with the thickness x).
    let from_zero = |x: f64| {
        if x <= 0.0 {
            0.0
        } else if b < 0.0 {
            // a = 1 on the way in.
            let r = -b * x * sqrt(x);
            layer::crush_time_with_gap(x, r, 1.0 - r)
        } else {
            layer::exit_time(x, b * x * sqrt(x), a)
        }
    };
    (from_zero(x) - from_zero(x0)).abs()
}

/// Work of the layer's drag over x from `x0` to `x1` with speed `a + b x^(3/2)`, in units of
/// m_eff g²: ∫ (3/2) λ √x |x'| dx = ∫ 3 λ w² (a + b w³) dw over w = √x (a polynomial: exact).
fn layer_work(a: f64, b: f64, lambda: f64, x0: f64, x1: f64) -> f64 {
    let (lo, hi) = if x0 < x1 { (x0, x1) } else { (x1, x0) };
    gauss(sqrt(lo), sqrt(hi), |w| {
        3.0 * lambda * w * w * (a + b * w * w * w)
    })
}

impl Contact {
    /// One collision at impact speed `g` \[m/s\]: `points` samples evenly spaced in time over the
    /// contact (plus the phase instants), the phases and the energy ledger.
    // Long by design: one collision integrated phase by phase with one shared state; the phases
    // are commented in order.
    pub fn collision(&self, g: f64, points: usize, accuracy: Accuracy) -> Result<Trajectory> {
        let normal = self.normal(g, accuracy)?;
        if points < 2 {
            return Err(Error::OutOfRange {
                field: "points",
                value: points as f64,
                expected: "at least 2 samples",
            });
        }
        let rtol = accuracy.integrator_rtol();
        let mut phases: Vec<Phase> = Vec::new();
        let mut pieces: Vec<Piece> = Vec::new();
        let mut resolved = true;
        let mut rhs_evaluations = 0;
        let layer = self
            .layer
            .filter(|l| l.thickness > 0.0)
            .filter(|l| l.reading == LayerReading::Literal || l.critical_velocity > 0.0);
        match layer {
            None => {
                phases.push(Phase {
                    name: "bulk_loading",
                    t: 0.0,
                });
                let sc = scale(self, g, 0.0, 0.0);
                rhs_evaluations += self.bulk(sc, rtol, &mut pieces, &mut resolved)?;
            }
            Some(l) if l.reading == LayerReading::Offset => {
                let g_s = l.critical_velocity;
                let sc = scale(self, g, 0.0, 0.0);
                let d = l.thickness / sc.xi_star;
                phases.push(Phase {
                    name: "layer_crushing",
                    t: 0.0,
                });
                if g <= g_s {
                    // Eq. (9): stopped at x = λ^(−2/3) after an infinite time; sampled until the
                    // speed has fallen to 1e-6 g.
                    let x_stop = powf(sc.lambda, -2.0 / 3.0);
                    let x_end = powf((1.0 - 1e-6) / sc.lambda, 2.0 / 3.0);
                    let t1 = sc.tau * layer_time(1.0, -sc.lambda, 0.0, x_end);
                    pieces.push(Piece::Layer {
                        a: 1.0,
                        b: -sc.lambda,
                        x0: 0.0,
                        x1: x_stop,
                        t0: 0.0,
                        t1,
                        scale: sc,
                    });
                } else {
                    let t_crush = sc.tau * layer_time(1.0, -sc.lambda, 0.0, d);
                    pieces.push(Piece::Layer {
                        a: 1.0,
                        b: -sc.lambda,
                        x0: 0.0,
                        x1: d,
                        t0: 0.0,
                        t1: t_crush,
                        scale: sc,
                    });
                    phases.push(Phase {
                        name: "bulk_loading",
                        t: t_crush,
                    });
                    // The bulk is reached at g − g_s: Eq. (4) for the overlap ξ − D.
                    let bulk = scale(self, g - g_s, t_crush, l.thickness);
                    rhs_evaluations += self.bulk(bulk, rtol, &mut pieces, &mut resolved)?;
                }
            }
            Some(l) => {
                let sc = scale(self, g, 0.0, 0.0);
                let d = l.thickness / sc.xi_star;
                phases.push(Phase {
                    name: "layer_crushing",
                    t: 0.0,
                });
                let mut collector = Collector::new(sc);
                let out = if sc.lambda * d * sqrt(d) >= 1.0 {
                    // Stopped in the layer on the way in (Eq. (9)).
                    let x_stop = powf(sc.lambda, -2.0 / 3.0);
                    let x_end = powf((1.0 - 1e-6) / sc.lambda, 2.0 / 3.0);
                    pieces.push(Piece::Layer {
                        a: 1.0,
                        b: -sc.lambda,
                        x0: 0.0,
                        x1: x_stop,
                        t0: 0.0,
                        t1: sc.tau * layer_time(1.0, -sc.lambda, 0.0, x_end),
                        scale: sc,
                    });
                    None
                } else {
                    Some(layer::literal_recorded(
                        self.delta(g),
                        sc.lambda,
                        d,
                        self.contact_end,
                        rtol,
                        &mut collector,
                    )?)
                };
                if let Some(out) = out {
                    rhs_evaluations += out.rhs_evaluations;
                    self.literal_pieces(sc, d, collector, &mut pieces, &mut phases, &mut resolved);
                }
            }
        }
        self.finish(
            g,
            points,
            accuracy,
            normal,
            phases,
            pieces,
            resolved,
            rhs_evaluations,
        )
    }

    /// The bulk collision of Eq. (4) at the reference speed of `sc`, integrated live.
    fn bulk(
        &self,
        sc: Scale,
        rtol: f64,
        pieces: &mut Vec<Piece>,
        resolved: &mut bool,
    ) -> Result<usize> {
        let mut collector = Collector::new(sc);
        let delta = self.delta(sc.g);
        let r = viscoelastic::dimensionless_recorded(delta, self.contact_end, rtol, &mut collector);
        let r = match r {
            // Past the tables' end every level takes ε_N, t_c and ξ_max from the strong-damping
            // asymptotes (docs/physics.md#decision-2). The live integration of the long, nearly
            // force-free hold before the force vanishes reaches its end since the force tail's
            // error scale (issue 26; tried up to δ = 1e100), but should it ever run out of steps
            // the trajectory keeps what was integrated (the loading phase, the hold's start) and
            // is reported unresolved.
            Err(Error::StepBudgetExceeded { .. } | Error::StepSizeUnderflow { .. })
                if delta > crate::normal::DELTA_ASYMPTOTIC =>
            {
                *resolved = false;
                pieces.extend(collector.pieces);
                return Ok(0);
            }
            other => other?,
        };
        if r.s_c.is_finite() {
            collector.truncate(r.s_c);
        } else {
            *resolved = false;
        }
        pieces.extend(collector.pieces);
        Ok(r.rhs_evaluations)
    }

    /// The literal reading's integrated steps and its closed-form tail.
    // Long by design: the literal layer reading's contact pieces in time order with one shared
    // state.
    fn literal_pieces(
        &self,
        sc: Scale,
        d: f64,
        mut collector: Collector,
        pieces: &mut Vec<Piece>,
        phases: &mut Vec<Phase>,
        resolved: &mut bool,
    ) {
        let g_s = sc.lambda * d * sqrt(d);
        // Where the bulk is reached: the first bulk step.
        if let Some(t) = collector.pieces.iter().find_map(|p| match p {
            Piece::Step { map, .. } if map.kind == Kind::Bulk => Some(p.span().0),
            _ => None,
        }) {
            phases.push(Phase {
                name: "bulk_loading",
                t,
            });
        }
        let exit = |s: f64, v_d: f64, pieces: &mut Vec<Piece>, phases: &mut Vec<Phase>| {
            let t0 = sc.tau * s;
            phases.push(Phase {
                name: "layer_exit",
                t: t0,
            });
            // Eq. (9) on the way out: x' + λ x^(3/2) is constant, v_d + g_s at x = d, so the
            // speed is a + λ x^(3/2) with a = −v_d − g_s: the final speed ε when a > 0; else the
            // layer holds the grains where the speed vanishes (sampled until it is 1e-6 g).
            let a = -v_d - g_s;
            let x_end = if a > 0.0 {
                0.0
            } else {
                powf((1e-6 - a) / sc.lambda, 2.0 / 3.0).min(d)
            };
            pieces.push(Piece::Layer {
                a,
                b: sc.lambda,
                x0: d,
                x1: x_end,
                t0,
                // Held: the approach to rest takes an infinite time; the stretch is booked in
                // the ledger but not sampled.
                t1: if a > 0.0 {
                    t0 + sc.tau * layer_time(a, sc.lambda, d, x_end)
                } else {
                    t0
                },
                scale: sc,
            });
        };
        match collector.tail {
            Some(Tail::LayerExit { s, v, .. }) => {
                collector.truncate(s);
                pieces.append(&mut collector.pieces);
                exit(s, v, pieces, phases);
            }
            Some(Tail::Coast { s, u, v, .. }) => {
                collector.truncate(s);
                pieces.append(&mut collector.pieces);
                let t0 = sc.tau * s;
                let s_d = s + u / -v;
                phases.push(Phase {
                    name: "coast",
                    t: t0,
                });
                pieces.push(Piece::Coast {
                    t0,
                    t1: sc.tau * s_d,
                    xi0: sc.xi_star * (d + u),
                    v: sc.g * v,
                });
                exit(s_d, v, pieces, phases);
            }
            Some(Tail::End { s }) => {
                collector.truncate(s);
                pieces.append(&mut collector.pieces);
            }
            Some(Tail::Unresolved) | None => {
                *resolved = false;
                pieces.append(&mut collector.pieces);
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    // Long by design: assembles every field of a trajectory (samples, phases, ledger) from one
    // integration; each block fills one field.
    fn finish(
        &self,
        g: f64,
        points: usize,
        accuracy: Accuracy,
        normal: Normal,
        mut phases: Vec<Phase>,
        pieces: Vec<Piece>,
        resolved: bool,
        rhs_evaluations: usize,
    ) -> Result<Trajectory> {
        let m = self.m_eff;
        // Maximum compression and the start of the creep: roots on the dense output.
        let mut t_max = None;
        let mut t_creep = None;
        for p in &pieces {
            if let Piece::Step {
                step,
                map,
                c0,
                c1,
                scale,
            } = *p
            {
                if map.kind != Kind::Bulk {
                    continue;
                }
                let velocity = |c: f64| map.overlap_velocity(&step.eval(c)).1;
                let total = |c: f64| {
                    let y = step.eval(c);
                    let (x, v) = map.overlap_velocity(&y);
                    map.force_k.map_or(x + scale.k * v, |_| y[1])
                };
                let to_si = |c: f64| scale.t_offset + scale.tau * map.s(c);
                if t_max.is_none() && velocity(c0) > 0.0 && velocity(c1) <= 0.0 {
                    t_max = Some(to_si(bisect(c0, c1, velocity)));
                }
                if t_max.is_some()
                    && t_creep.is_none()
                    && self.contact_end == ContactEnd::ZeroOverlap
                    && total(c0) > 0.0
                    && total(c1) <= 0.0
                {
                    t_creep = Some(to_si(bisect(c0, c1, total)));
                }
            }
        }
        if let Some(t) = t_max {
            phases.push(Phase {
                name: "maximum_compression",
                t,
            });
            phases.push(Phase {
                name: "unloading",
                t,
            });
        }
        if let Some(t) = t_creep {
            phases.push(Phase { name: "creep", t });
        }
        let t_end_live = pieces.last().map_or(0.0, |p| p.span().1);
        if normal.t_c.is_finite() {
            phases.push(Phase {
                name: "end_of_contact",
                t: normal.t_c,
            });
        }
        phases.sort_by(|a, b| a.t.total_cmp(&b.t));
        // Samples: evenly spaced over the contact, plus the phase instants.
        let t_end = if normal.t_c.is_finite() {
            normal.t_c
        } else {
            t_end_live
        };
        let mut t: Vec<f64> = (0..points)
            .map(|i| t_end * i as f64 / (points - 1) as f64)
            .collect();
        t.extend(phases.iter().map(|p| p.t).filter(|&x| x <= t_end));
        t.sort_by(f64::total_cmp);
        t.dedup();
        let (mut xi, mut xi_dot, mut force) = (
            Vec::with_capacity(t.len()),
            Vec::with_capacity(t.len()),
            Vec::with_capacity(t.len()),
        );
        let mut k = 0;
        for &ti in &t {
            while k + 1 < pieces.len() && pieces[k].span().1 < ti {
                k += 1;
            }
            // Past the last piece (an unresolved hold, or the closed-form t_c a hair beyond the
            // integrated end) the last state holds: dense output is not extrapolated.
            let (a, b, c) = pieces
                .get(k)
                .map_or((0.0, 0.0, 0.0), |p| p.sample(ti.min(p.span().1), m));
            xi.push(a);
            xi_dot.push(b);
            force.push(c);
        }
        // The ledger: each term the quadrature of its own force over the trajectory.
        let (mut bulk, mut layer_drag, mut elastic) = (0.0, 0.0, 0.0);
        for p in &pieces {
            match *p {
                Piece::Step {
                    step,
                    map,
                    c0,
                    c1,
                    scale,
                } => {
                    let unit = m * scale.g * scale.g;
                    let at = |c: f64| {
                        let (x, v) = map.overlap_velocity(&step.eval(c));
                        (x.max(0.0), v, map.ds_dt(c))
                    };
                    match map.kind {
                        Kind::Bulk => {
                            // Eq. (4): viscous power 1.5 δ √x v², elastic power x^(3/2) v.
                            bulk += unit
                                * gauss(c0, c1, |c| {
                                    let (x, v, ds) = at(c);
                                    scale.k * sqrt(x) * v * v * ds
                                });
                            elastic += unit
                                * gauss(c0, c1, |c| {
                                    let (x, v, ds) = at(c);
                                    x * sqrt(x) * v * ds
                                });
                        }
                        Kind::Layer => {
                            layer_drag += unit
                                * gauss(c0, c1, |c| {
                                    let (x, v, ds) = at(c);
                                    1.5 * scale.lambda * sqrt(x) * v * v * ds
                                });
                        }
                        Kind::Coast => {}
                    }
                }
                Piece::Layer {
                    a,
                    b,
                    x0,
                    x1,
                    scale,
                    ..
                } => {
                    layer_drag += m * scale.g * scale.g * layer_work(a, b, scale.lambda, x0, x1);
                }
                Piece::Coast { .. } => {}
            }
        }
        let kinetic_in = 0.5 * m * g * g;
        let out_speed = normal.eps * g;
        let kinetic_out = 0.5 * m * out_speed * out_speed;
        let adhesion = match (&self.adhesion, normal.status) {
            (None, _) => 0.0,
            (Some(_), Status::StuckByAdhesion) => {
                // All the rebound without adhesion would have carried.
                let bare = Contact {
                    adhesion: None,
                    ..*self
                };
                let e = bare.normal(g, accuracy)?.eps * g;
                0.5 * m * e * e
            }
            (Some(a), Status::Rebound | Status::Overdamped) if a.critical_velocity > 0.0 => {
                a.separation_energy
            }
            _ => 0.0,
        };
        let closure =
            (kinetic_in - kinetic_out - bulk - layer_drag - elastic - adhesion) / kinetic_in;
        Ok(Trajectory {
            t,
            xi,
            xi_dot,
            force,
            phases,
            t_c: normal.t_c,
            xi_max: normal.xi_max,
            eps_n: normal.eps,
            status: normal.status,
            ledger: Ledger {
                kinetic_in,
                kinetic_out,
                dissipated_bulk: bulk,
                dissipated_layer: layer_drag,
                elastic_retained: elastic,
                adhesion,
                closure,
            },
            resolved,
            rhs_evaluations,
        })
    }
}

/// A sign change of `f` on `[lo, hi]` by bisection (f(lo) > 0 ≥ f(hi)).
fn bisect(mut lo: f64, mut hi: f64, f: impl Fn(f64) -> f64) -> f64 {
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The tangential side of an oblique impact (Eq. (1), (2), (26)) for two solid spheres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oblique {
    /// ε_T of Eq. (26).
    pub eps_t: f64,
    /// The stick-map class (docs/physics.md#decision-7).
    pub class: crate::tangential::StickClass,
    /// ½ m_t g_T² before \[J\], m_t = κ m_eff (Eq. (22)).
    pub energy_before: f64,
    /// ½ m_t (ε_T g_T)² after \[J\].
    pub energy_after: f64,
    /// Work of the tangential (friction) impulse J_T on the relative surface motion,
    /// J_T · (g_T + g'_T)/2 \[J\] (< 0: taken from the grains).
    pub friction_work: f64,
    /// Change of each grain's spin about the axis n × t \[rad/s\].
    pub spin_change: [f64; 2],
    /// Total momentum after minus before \[kg m/s\] (a check: 0 to rounding).
    pub momentum_change: f64,
    /// Kinetic energy (translation and spin of both grains) before and after \[J\].
    pub kinetic_before: f64,
    /// See `kinetic_before`.
    pub kinetic_after: f64,
}

impl Contact {
    /// An oblique impact of two solid spheres of radii `radius_1`, `radius_2` \[m\] at normal and
    /// tangential speeds `g_n`, `g_t` \[m/s\], without spin before: ε_N and ε_T from the scene,
    /// applied by the core's kinematics ([`crate::collision::kinematics::collide`], Eq. (2)).
    pub fn oblique(
        &self,
        radius_1: f64,
        radius_2: f64,
        g_n: f64,
        g_t: f64,
        accuracy: Accuracy,
    ) -> Result<Oblique> {
        use crate::collision::kinematics::{
            GrainState, Vector3, collide, effective_tangential_mass, relative_surface_velocity,
        };
        let tangential = self.tangential(g_n, g_t, accuracy)?;
        let (m1, m2) = (self.mass_1, self.mass_2);
        let total = m1 + m2;
        // Centre-of-mass frame; n from grain 2 to grain 1, grain 1 moves along −n: g = (g_t, 0, −g_n).
        let n = Vector3::new(0.0, 0.0, 1.0);
        let zero = Vector3::zeros();
        let mut a = GrainState::solid_sphere(
            m1,
            radius_1,
            Vector3::new(g_t * m2 / total, 0.0, -g_n * m2 / total),
            zero,
        );
        let mut b = GrainState::solid_sphere(
            m2,
            radius_2,
            Vector3::new(-g_t * m1 / total, 0.0, g_n * m1 / total),
            zero,
        );
        let before = (a, b);
        let g_before = relative_surface_velocity(&a, &b, &n);
        collide(&mut a, &mut b, &n, tangential.eps_n, tangential.eps_t)?;
        let g_after = relative_surface_velocity(&a, &b, &n);
        let m_t = effective_tangential_mass(&a, &b);
        // J_T on grain 1, from its change of momentum along the tangent.
        let impulse_t = m1 * (a.velocity.x - before.0.velocity.x);
        let momentum = (a.velocity * m1 + b.velocity * m2).norm();
        Ok(Oblique {
            eps_t: tangential.eps_t,
            class: tangential.class,
            energy_before: 0.5 * m_t * g_before.x * g_before.x,
            energy_after: 0.5 * m_t * g_after.x * g_after.x,
            friction_work: impulse_t * 0.5 * (g_before.x + g_after.x),
            spin_change: [a.spin.y - before.0.spin.y, b.spin.y - before.1.spin.y],
            momentum_change: momentum,
            kinetic_before: before.0.kinetic_energy() + before.1.kinetic_energy(),
            kinetic_after: a.kinetic_energy() + b.kinetic_energy(),
        })
    }
}
