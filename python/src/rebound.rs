//! A REBOUND `collision_resolve` in native code, configured at run time.
//!
//! `rime_grains.rebound.attach` registers a [`State`] (scene, units, density and sticking rules, the
//! particle layout read from rebound's own ctypes classes) for one simulation's address and sets
//! `sim.collision_resolve` to [`collision_resolve`]. REBOUND calls it with the simulation and a
//! `struct reb_collision` by value; it applies ε_N (Eq. (4)–(17)), ε_T (Eq. (26)) and the spin change
//! of one impulse at the contact point (Eq. (1)–(2)) through the core's kinematics, or merges the
//! grains through the core's [`rime_core::merge`]. The physics lives in the core; this file maps
//! REBOUND's memory to it.
//!
//! Spins live in the handler's own table, one entry per particle index, never in `ap` (which
//! REBOUNDx owns and frees). The table follows REBOUND's particle array: a merge removes p2's entry
//! as REBOUND removes p2 (shifting the ones after it), particles added at the end get spin 0, and a
//! removal the handler did not make (N falls) stops the integration with a message rather than
//! giving the spins to the wrong grains. The contact constants of a pair of (radius, mass) are
//! cached in a bounded two-generation cache.

// Unsafe is needed here and only here: REBOUND hands the handler raw pointers to its simulation
// and particles (a C callback). Every access goes through the small helpers below, whose offsets
// come from rebound's ctypes classes and are checked at attach time against the particle size.
#![allow(unsafe_code)]

use crate::counters::{Counters, Hit, Outcome, check_edges};
use crate::{core_error, value_error};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rime_core::kinematics::{GrainState, Vector3, collide};
use rime_core::merge::{Body, merge};
use rime_core::{Accuracy, Contact, Grains, Scene};
use std::collections::HashMap;
use std::ffi::{CStr, c_char, c_int, c_void};
use std::io::Write;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, RwLock};

/// The REBOUND version whose layout and calling convention this handler is built and tested for.
pub const REBOUND_VERSION: &str = "5.2.2";

/// `struct reb_collision` of REBOUND 5.2.2 (rebound.h): p1, p2, the ghost-box shift, the root cell.
/// Its layout is checked against rebound's `CollisionS` by the test suite (`collision_layout`).
#[repr(C)]
#[derive(Clone, Copy)]
pub struct RebCollision {
    /// Index of the first particle.
    pub p1: usize,
    /// Index of the second particle.
    pub p2: usize,
    /// Ghost-box shift x, y, z, vx, vy, vz to add to p1.
    pub gb: [f64; 6],
    /// Root cell index (MPI only).
    pub ri: usize,
}

/// `REB_COLLISION_RESOLVE_OUTCOME`: keep both, remove p2.
const KEEP_BOTH: c_int = 0;
const REMOVE_P2: c_int = 2;
/// `REB_STATUS_GENERIC_ERROR`: stops `sim.integrate`, which raises `rebound.GenericError`.
const STATUS_GENERIC_ERROR: c_int = 1;
/// Byte offsets into `struct reb_simulation` and `struct reb_particle`.
#[derive(Clone, Copy, Debug)]
struct Layout {
    particles: usize,
    n: usize,
    status: usize,
    minimum_collision_velocity: usize,
    t: usize,
    dt: usize,
    steps_done: usize,
    walltime: usize,
    archive_filename: usize,
    archive_interval: usize,
    archive_walltime: usize,
    archive_step: usize,
    archive_next: usize,
    archive_next_step: usize,
    particle_size: usize,
    x: usize,
    vx: usize,
    m: usize,
    r: usize,
}

/// Contact constants of recent pairs: two generations, each at most half the capacity. A lookup
/// checks the young one, then the old one (moving a hit back to the young); when the young one is
/// full it becomes the old one and the oldest generation is dropped. Memory stays bounded and the
/// pairs in use stay cached (a least-recently-used cache in two steps).
struct PairCache {
    young: HashMap<[u64; 4], Pair, PairHashing>,
    old: HashMap<[u64; 4], Pair, PairHashing>,
    /// The pair of the last lookup: a ring of one size asks for it every time, without a hash.
    last: Option<([u64; 4], Pair)>,
    capacity: usize,
    hits: u64,
    misses: u64,
}

/// A multiply–rotate hash of the four words of a key (the bits of radii and masses): the keys are
/// not chosen by an adversary, so the standard library's SipHash buys nothing here.
#[derive(Default)]
struct PairHasher(u64);

impl std::hash::Hasher for PairHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for b in bytes {
            self.write_u64(u64::from(*b));
        }
    }

    fn write_u64(&mut self, x: u64) {
        self.0 = (self.0.rotate_left(5) ^ x).wrapping_mul(0x517c_c1b7_2722_0a95);
    }

    fn write_usize(&mut self, x: usize) {
        self.write_u64(x as u64);
    }
}

type PairHashing = std::hash::BuildHasherDefault<PairHasher>;

impl PairCache {
    fn new(capacity: usize) -> PairCache {
        PairCache {
            young: HashMap::default(),
            old: HashMap::default(),
            last: None,
            capacity,
            hits: 0,
            misses: 0,
        }
    }

    fn get(&mut self, key: &[u64; 4]) -> Option<Pair> {
        if let Some((k, p)) = &self.last
            && k == key
        {
            self.hits += 1;
            return Some(*p);
        }
        let p = match self.young.get(key) {
            Some(p) => *p,
            None => {
                let p = self.old.remove(key)?;
                self.insert(*key, p);
                p
            }
        };
        self.hits += 1;
        self.last = Some((*key, p));
        Some(p)
    }

    fn insert(&mut self, key: [u64; 4], pair: Pair) {
        if self.young.len() >= self.capacity.div_ceil(2) {
            self.old = std::mem::take(&mut self.young);
        }
        self.young.insert(key, pair);
        self.last = Some((key, pair));
    }

    fn len(&self) -> usize {
        self.young.len() + self.old.len()
    }
}

#[derive(Clone, Copy, PartialEq, Debug)]
enum Density {
    /// ρ from each particle's mass and radius (m_eff from the two masses).
    Particles,
    /// The scene's density for ε_N (impulses still use the particles' masses).
    Scene,
}

#[derive(Clone, Copy, PartialEq, Debug)]
enum Sticking {
    Merge,
    Stay,
    MergeIfSlow,
}

/// The cached constants of one pair.
#[derive(Clone, Copy)]
struct Pair {
    contact: Contact,
    /// Largest speed at which this pair sticks \[m/s\] (∞ when it always does), for `merge_if_slow`.
    stick_speed: f64,
}

struct State {
    layout: Layout,
    scene: Scene,
    accuracy: Accuracy,
    length_unit: f64,
    time_unit: f64,
    mass_unit: f64,
    density: Density,
    sticking: Sticking,
    track_spins: bool,
    /// The spin of particle k \[rad per code time\], for k below the length; particles added at
    /// the end since have spin 0.
    spins: Mutex<Vec<[f64; 3]>>,
    cache: Mutex<PairCache>,
    /// The heartbeat that was set before the handler's own (called after it), as an address.
    previous_heartbeat: usize,
    error: Mutex<Option<String>>,
    bounces: AtomicU64,
    merges: AtomicU64,
    stays: AtomicU64,
    /// The counters of the present window (`Attachment.counters`).
    counters: Mutex<Counters>,
}

/// The simulations with a handler attached: (address, state). A handful at most, so a scan.
static REGISTRY: RwLock<Vec<(usize, Arc<State>)>> = RwLock::new(Vec::new());

/// A particle's fields, read from REBOUND's particle array.
struct Particle {
    base: *mut u8,
    x: [f64; 3],
    v: [f64; 3],
    m: f64,
    r: f64,
    index: usize,
}

impl State {
    /// Reads particle `k` of the simulation at `sim`; `None` when `k` is not below `N`.
    ///
    /// # Safety
    /// `sim` must point to a live `struct reb_simulation` of the layout this state was attached with.
    unsafe fn particle(&self, sim: *mut u8, k: usize) -> Option<Particle> {
        let l = &self.layout;
        // SAFETY: `sim` is the simulation REBOUND passed to the handler; the offsets of N and of
        // the particle array pointer come from rebound's ctypes class of that struct.
        let (n, array) = unsafe {
            (
                *(sim.add(l.n) as *const usize),
                *(sim.add(l.particles) as *const *mut u8),
            )
        };
        if k >= n || array.is_null() {
            return None;
        }
        // SAFETY: k < N, so the particle lies inside the array REBOUND allocated; the field
        // offsets were checked at attach time to lie inside `particle_size` and be 8-aligned.
        unsafe {
            let base = array.add(k * l.particle_size);
            let d = |off: usize| base.add(off) as *const f64;
            Some(Particle {
                base,
                x: [*d(l.x), *d(l.x + 8), *d(l.x + 16)],
                v: [*d(l.vx), *d(l.vx + 8), *d(l.vx + 16)],
                m: *d(l.m),
                r: *d(l.r),
                index: k,
            })
        }
    }

    /// The number of particles of the simulation at `sim`.
    ///
    /// # Safety
    /// As [`State::particle`].
    unsafe fn count(&self, sim: *mut u8) -> usize {
        // SAFETY: the offset of N comes from rebound's ctypes class of the simulation.
        unsafe { *(sim.add(self.layout.n) as *const usize) }
    }

    /// The spin table checked against the simulation's N: grown with zeros for particles added at
    /// the end; an error when N fell (particles removed outside the handler).
    ///
    /// # Safety
    /// As [`State::particle`].
    unsafe fn spins_for(
        &self,
        sim: *mut u8,
    ) -> Result<std::sync::MutexGuard<'_, Vec<[f64; 3]>>, String> {
        // SAFETY: the caller's contract.
        let n = unsafe { self.count(sim) };
        let mut spins = self
            .spins
            .lock()
            .map_err(|_| "the spin table is unusable (a thread panicked)".to_string())?;
        if n < spins.len() {
            return Err(format!(
                "spins: the simulation has {n} particles, the spin table {}: particles were \
                 removed outside rime's handler (sim.remove, an open boundary), so the spins no \
                 longer match the particles; give them again with Attachment.track_spins(spins) \
                 after removing",
                spins.len()
            ));
        }
        spins.resize(n, [0.0; 3]);
        Ok(spins)
    }

    /// Writes velocity, mass, radius and position back into the particle, and its spin into the
    /// table (when spins are tracked).
    #[allow(clippy::too_many_arguments)]
    fn store(
        &self,
        spins: Option<&mut Vec<[f64; 3]>>,
        p: &Particle,
        x: [f64; 3],
        v: [f64; 3],
        m: f64,
        r: f64,
        w: Vector3<f64>,
    ) {
        let l = &self.layout;
        // SAFETY: `p.base` was read by `particle` for an index below N during this call; REBOUND
        // does not move the array while a collision is being resolved.
        unsafe {
            let d = |off: usize| p.base.add(off) as *mut f64;
            for k in 0..3 {
                *d(l.x + 8 * k) = x[k];
                *d(l.vx + 8 * k) = v[k];
            }
            *d(l.m) = m;
            *d(l.r) = r;
        }
        if let Some(slot) = spins.and_then(|s| s.get_mut(p.index)) {
            *slot = [w[0], w[1], w[2]];
        }
    }

    /// Reads a field of the simulation.
    ///
    /// # Safety
    /// `sim` as in [`State::particle`]; `offset` one of the layout's simulation offsets, of a
    /// field of type `T`.
    unsafe fn field<T: Copy>(sim: *mut u8, offset: usize) -> T {
        // SAFETY: see the function's contract.
        unsafe { *(sim.add(offset) as *const T) }
    }

    /// The spins of every particle in order, as one JSON line of the spin file: `{"t", "N",
    /// "spins"}`.
    ///
    /// # Safety
    /// As [`State::particle`].
    unsafe fn spin_record(&self, sim: *mut u8) -> String {
        // SAFETY: the caller's contract.
        let (t, n) = unsafe { (Self::field::<f64>(sim, self.layout.t), self.count(sim)) };
        // SAFETY: the caller's contract.
        let spins = match unsafe { self.spins_for(sim) } {
            Ok(s) if self.track_spins => s.clone(),
            _ => vec![[0.0; 3]; n],
        };
        serde_json::json!({"t": t, "N": n, "spins": spins}).to_string()
    }

    /// Whether REBOUND's periodic archive writes a snapshot before the next step: the test of
    /// `reb_simulationarchive_heartbeat` (REBOUND 5.2.2), which runs after this heartbeat and
    /// before the next step, so the snapshot and the spins are of one state.
    ///
    /// # Safety
    /// As [`State::particle`].
    unsafe fn archive_due(&self, sim: *mut u8) -> Option<String> {
        let l = &self.layout;
        // SAFETY: offsets from rebound's ctypes class of the simulation, of these types.
        unsafe {
            let name = Self::field::<*const c_char>(sim, l.archive_filename);
            if name.is_null() {
                return None;
            }
            let interval = Self::field::<f64>(sim, l.archive_interval);
            let step = Self::field::<u64>(sim, l.archive_step);
            let walltime = Self::field::<f64>(sim, l.archive_walltime);
            let next = Self::field::<f64>(sim, l.archive_next);
            let due = if interval != 0.0 {
                let sign = if Self::field::<f64>(sim, l.dt) > 0.0 {
                    1.0
                } else {
                    -1.0
                };
                sign * next <= sign * Self::field::<f64>(sim, l.t)
            } else if step != 0 {
                Self::field::<u64>(sim, l.archive_next_step)
                    <= Self::field::<u64>(sim, l.steps_done)
            } else if walltime != 0.0 {
                next <= Self::field::<f64>(sim, l.walltime)
            } else {
                false
            };
            due.then(|| CStr::from_ptr(name).to_string_lossy().into_owned())
        }
    }

    fn fail(&self, sim: *mut u8, message: String) {
        if let Ok(mut e) = self.error.lock() {
            e.get_or_insert(message);
        }
        // SAFETY: the status field's offset comes from rebound's ctypes class; setting it to
        // REB_STATUS_GENERIC_ERROR ends `sim.integrate` after this step, which then raises.
        unsafe { *(sim.add(self.layout.status) as *mut c_int) = STATUS_GENERIC_ERROR };
    }

    /// Adds one collision to the window's counters.
    fn tally(&self, outcome: Outcome, hit: &Hit) {
        if let Ok(mut c) = self.counters.lock() {
            c.add(outcome, hit);
        }
    }

    /// The contact constants of a pair (SI radii and masses), from the cache or computed once.
    fn pair(&self, r1: f64, m1: f64, r2: f64, m2: f64) -> rime_core::Result<Pair> {
        // Symmetric key: the pair sorted by (radius, mass); the scene's density ignores masses.
        let (a, b) = if (r1, m1) <= (r2, m2) {
            ((r1, m1), (r2, m2))
        } else {
            ((r2, m2), (r1, m1))
        };
        let key = match self.density {
            Density::Particles => [a.0.to_bits(), a.1.to_bits(), b.0.to_bits(), b.1.to_bits()],
            Density::Scene => [a.0.to_bits(), 0, b.0.to_bits(), 0],
        };
        if let Ok(mut cache) = self.cache.lock()
            && let Some(p) = cache.get(&key)
        {
            return Ok(p);
        }
        let mut scene = self.scene;
        let (r1, r2) = (r1 * self.length_unit, r2 * self.length_unit);
        scene.grains = match self.density {
            Density::Particles => {
                Grains::from_masses(r1, m1 * self.mass_unit, r2, m2 * self.mass_unit)?
            }
            Density::Scene => Grains {
                radius_1: r1,
                radius_2: r2,
                ..scene.grains
            },
        };
        let contact = Contact::new(&scene)?;
        let stick_speed = if self.sticking == Sticking::MergeIfSlow {
            rime_core::explorer::frame::stick_threshold(&contact, self.accuracy)?
                .unwrap_or(f64::INFINITY)
        } else {
            f64::INFINITY
        };
        let pair = Pair {
            contact,
            stick_speed,
        };
        if let Ok(mut cache) = self.cache.lock() {
            cache.misses += 1;
            cache.insert(key, pair);
        }
        Ok(pair)
    }

    /// Resolves one collision (see the module documentation).
    // Long by design: the C collision callback: one pass over both particles' state, no
    // allocation, shared by every branch.
    fn resolve(&self, sim: *mut u8, c: &RebCollision) -> Result<c_int, String> {
        // SAFETY: `sim` is the live simulation REBOUND passed to the handler.
        let (Some(p1), Some(p2)) = (unsafe { self.particle(sim, c.p1) }, unsafe {
            self.particle(sim, c.p2)
        }) else {
            return Ok(KEEP_BOTH);
        };
        let gb = c.gb;
        let x1 = Vector3::new(p1.x[0] + gb[0], p1.x[1] + gb[1], p1.x[2] + gb[2]);
        let v1 = Vector3::new(p1.v[0] + gb[3], p1.v[1] + gb[4], p1.v[2] + gb[5]);
        let (x2, v2) = (Vector3::from(p2.x), Vector3::from(p2.v));
        let d = x1 - x2;
        let dist = d.norm();
        let dv = v1 - v2;
        // Not touching, or not approaching: a pair that stuck and stays (ε_N = 0) is found again
        // while it overlaps, with a normal speed of rounding size that must not count as a hit.
        if dist.is_nan()
            || dist <= 0.0
            || dist > p1.r + p2.r
            || dv.dot(&d) >= -1e-12 * dv.norm() * dist
        {
            return Ok(KEEP_BOTH);
        }
        let n = d / dist; // from p2's centre to p1's
        let mut spins = if self.track_spins {
            // SAFETY: as above.
            Some(unsafe { self.spins_for(sim) }?)
        } else {
            None
        };
        let spin = |k: usize| Vector3::from(spins.as_ref().map_or([0.0; 3], |s| s[k]));
        let (w1, w2) = (spin(p1.index), spin(p2.index));
        // REBOUND finds the pair overlapping at the end of a step: the impulse acts at the contact
        // point, a_i d/(a_1 + a_2) from each centre (docs/physics.md#python-rebound).
        let scale = dist / (p1.r + p2.r);
        let grain = |p: &Particle, v, w| {
            GrainState::solid_sphere(p.m, p.r, v, w).with_lever_arm(p.r * scale)
        };
        let mut gi = grain(&p1, v1, w1);
        let mut gj = grain(&p2, v2, w2);
        // Eq. (2) in code units, then its split into g_N and |g_T| in SI.
        let g = rime_core::kinematics::relative_surface_velocity(&gi, &gj, &n);
        let (g_n, g_t) = rime_core::kinematics::decompose(&g, &n);
        let speed = self.length_unit / self.time_unit;
        let (gn_si, gt_si) = (-g_n * speed, g_t.norm() * speed);
        let field = |e: rime_core::Error| {
            format!(
                "collision of particles {} and {} (g_N = {gn_si:e} m/s, g_T = {gt_si:e} m/s, radii {:e}, {:e} m): {e}",
                c.p1,
                c.p2,
                p1.r * self.length_unit,
                p2.r * self.length_unit
            )
        };
        let pair = self.pair(p1.r, p1.m, p2.r, p2.m).map_err(field)?;
        let mut hit = Hit {
            normal_speed: -g_n,
            tangential_speed: g_t.norm(),
            depth: 1.0 - scale,
            transfer: 0.0,
            energy_loss: 0.0,
        };
        let contact = &pair.contact;
        let (eps_n, eps_t) = if contact.friction.is_some() && gt_si > 0.0 {
            let t = contact
                .tangential(gn_si, gt_si, self.accuracy)
                .map_err(field)?;
            (t.eps_n, t.eps_t)
        } else {
            // Without friction (or without a tangential motion) there is no tangential impulse.
            let e = contact.eps_n(gn_si, self.accuracy).map_err(field)?;
            (e, 1.0)
        };
        if eps_n == 0.0 {
            let merge = match self.sticking {
                Sticking::Merge => true,
                Sticking::Stay => false,
                Sticking::MergeIfSlow => gt_si <= pair.stick_speed,
            };
            if merge {
                // p1 takes the merged grain; p2 is removed (REBOUND shifts the particles after it).
                let (dx, dv) = ([-gb[0], -gb[1], -gb[2]], [-gb[3], -gb[4], -gb[5]]);
                hit.energy_loss = self
                    .merge(spins.as_deref_mut(), &p1, &p2, dx, dv, w1, w2)
                    .map_err(field)?;
                self.merges.fetch_add(1, Ordering::Relaxed);
                // p1's share of the common velocity: the y-momentum it received from p2.
                let v_common = (v1[1] * p1.m + v2[1] * p2.m) / (p1.m + p2.m);
                hit.transfer = p1.m * (v_common - v1[1]) * d[0];
                self.tally(Outcome::Merge, &hit);
                return Ok(REMOVE_P2);
            }
            self.stays.fetch_add(1, Ordering::Relaxed);
        } else {
            self.bounces.fetch_add(1, Ordering::Relaxed);
        }
        let outcome = if eps_n == 0.0 {
            Outcome::Stay
        } else {
            Outcome::Bounce
        };
        // REBOUND's floor on the separation speed (sim.minimum_collision_velocity, code units).
        // SAFETY: offset from rebound's ctypes class of struct reb_simulation.
        let v_min = unsafe { *(sim.add(self.layout.minimum_collision_velocity) as *const f64) };
        let eps = rime_core::kinematics::restitution_with_floor(eps_n, g_n, v_min);
        let energy_before = gi.kinetic_energy() + gj.kinetic_energy();
        collide(&mut gi, &mut gj, &n, eps, eps_t).map_err(field)?;
        hit.energy_loss = energy_before - gi.kinetic_energy() - gj.kinetic_energy();
        // The y-momentum p1 received, carried across the x-distance of the pair (ghost frame).
        hit.transfer = p1.m * (gi.velocity[1] - v1[1]) * d[0];
        self.tally(outcome, &hit);
        let v1_new = [
            gi.velocity[0] - gb[3],
            gi.velocity[1] - gb[4],
            gi.velocity[2] - gb[5],
        ];
        let v2_new = [gj.velocity[0], gj.velocity[1], gj.velocity[2]];
        self.store(spins.as_deref_mut(), &p1, p1.x, v1_new, p1.m, p1.r, gi.spin);
        self.store(spins.as_deref_mut(), &p2, p2.x, v2_new, p2.m, p2.r, gj.spin);
        Ok(KEEP_BOTH)
    }

    /// Merges `other` into `keep` through the core ([`rime_core::merge`]: mass, volume, momentum,
    /// angular momentum kept); `(dx, dv)` moves `other` into `keep`'s ghost frame.
    #[allow(clippy::too_many_arguments)]
    fn merge(
        &self,
        mut spins: Option<&mut Vec<[f64; 3]>>,
        keep: &Particle,
        other: &Particle,
        dx: [f64; 3],
        dv: [f64; 3],
        w_keep: Vector3<f64>,
        w_other: Vector3<f64>,
    ) -> rime_core::Result<f64> {
        let body = |p: &Particle, dx: [f64; 3], dv: [f64; 3], w| {
            Body::solid_sphere(
                p.m,
                p.r,
                Vector3::from(p.x) + Vector3::from(dx),
                Vector3::from(p.v) + Vector3::from(dv),
                w,
            )
        };
        let (a, b) = (
            body(keep, [0.0; 3], [0.0; 3], w_keep),
            body(other, dx, dv, w_other),
        );
        let one = merge(&a, &b)?;
        // Kinetic energy (translation + spin) before and after, in one frame.
        let energy = |x: &Body| {
            0.5 * x.mass
                * (x.velocity.norm_squared()
                    + x.inertia_factor * x.radius * x.radius * x.spin.norm_squared())
        };
        let lost = energy(&a) + energy(&b) - energy(&one);
        self.store(
            spins.as_deref_mut(),
            keep,
            one.position.into(),
            one.velocity.into(),
            one.mass,
            one.radius,
            one.spin,
        );
        // REBOUND removes `other` after this returns, shifting the particles after it down.
        if let Some(s) = spins
            && other.index < s.len()
        {
            s.remove(other.index);
        }
        Ok(lost)
    }
}

/// REBOUND's `collision_resolve` (returns `enum REB_COLLISION_RESOLVE_OUTCOME`).
extern "C" fn collision_resolve(sim: *mut c_void, c: RebCollision) -> c_int {
    // No panic may unwind into C: catch it and report it as an error of the simulation.
    let outcome = std::panic::catch_unwind(|| {
        // The read guard is held while resolving (attach and detach write; collisions only read).
        let Ok(registry) = REGISTRY.read() else {
            return KEEP_BOTH;
        };
        let Some((_, state)) = registry.iter().find(|(a, _)| *a == sim as usize) else {
            return KEEP_BOTH;
        };
        match state.resolve(sim as *mut u8, &c) {
            Ok(o) => o,
            Err(message) => {
                state.fail(sim as *mut u8, message);
                KEEP_BOTH
            }
        }
    });
    outcome.unwrap_or(KEEP_BOTH)
}

/// REBOUND's `heartbeat` (every step): when REBOUND's periodic archive (`sim.save_to_file(file,
/// interval=…)`, `step=`, `walltime=`) is about to write a snapshot, appends the spins of that state
/// to `file + ".spins"`; then calls the heartbeat that was set before attach.
extern "C" fn heartbeat(sim: *mut c_void) {
    let state = std::panic::catch_unwind(|| {
        let registry = REGISTRY.read().ok()?;
        let (_, state) = registry.iter().find(|(a, _)| *a == sim as usize)?;
        Some(Arc::clone(state))
    })
    .ok()
    .flatten();
    let Some(state) = state else {
        return;
    };
    // The registry's lock is released: the previous heartbeat may attach or detach.
    let _ = std::panic::catch_unwind(|| {
        // SAFETY: `sim` is the live simulation REBOUND passed to its heartbeat.
        if state.track_spins
            && let Some(file) = unsafe { state.archive_due(sim as *mut u8) }
        {
            let path = format!("{file}.spins");
            // SAFETY: as above.
            let line = unsafe { state.spin_record(sim as *mut u8) } + "\n";
            let written = std::fs::OpenOptions::new()
                .create(true)
                .append(true)
                .open(&path)
                .and_then(|mut f| f.write_all(line.as_bytes()));
            if let Err(e) = written {
                state.fail(
                    sim as *mut u8,
                    format!("spins of the periodic archive: cannot write {path}: {e}"),
                );
            }
        }
    });
    if state.previous_heartbeat != 0 {
        // SAFETY: the address was REBOUND's `heartbeat` pointer before attach (a C function or a
        // ctypes thunk that the simulation's Python object keeps alive), of this signature.
        let previous: extern "C" fn(*mut c_void) = unsafe {
            std::mem::transmute::<usize, extern "C" fn(*mut c_void)>(state.previous_heartbeat)
        };
        previous(sim);
    }
}

/// The handler attached to one simulation (returned by `_attach`; `rime_grains.rebound.Attachment`
/// wraps it).
#[pyclass(module = "rime_grains._native", name = "Handler")]
pub struct Handler {
    sim: usize,
    state: Arc<State>,
}

#[pymethods]
impl Handler {
    /// The address of the C function to assign to `sim.collision_resolve`.
    #[getter]
    fn function_address(&self) -> usize {
        collision_resolve as *const () as usize
    }

    /// The first error the handler met (it then stopped the integration), or `None`.
    #[getter]
    fn error(&self) -> Option<String> {
        self.state.error.lock().ok().and_then(|e| e.clone())
    }

    /// Counts of outcomes so far: bounces, merges, and pairs that stuck but stayed apart.
    fn counts<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("bounces", self.state.bounces.load(Ordering::Relaxed))?;
        d.set_item("merges", self.state.merges.load(Ordering::Relaxed))?;
        d.set_item("stays", self.state.stays.load(Ordering::Relaxed))?;
        Ok(d)
    }

    /// The counters of the present window (code units) up to the simulation's present time.
    fn counters<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        // SAFETY: the attachment holds the simulation's Python object, so `sim` is alive.
        let t = unsafe { State::field::<f64>(self.sim as *mut u8, self.state.layout.t) };
        let c = self
            .state
            .counters
            .lock()
            .map_err(|_| value_error("counters", "unusable (a thread panicked)"))?;
        c.to_dict(py, t)
    }

    /// Starts a new window at the simulation's present time; `edges` (normal speeds, code units)
    /// replace the histogram's when given (an empty list: no histogram).
    #[pyo3(signature = (edges=None))]
    fn reset_counters(&self, edges: Option<Vec<f64>>) -> PyResult<()> {
        if let Some(e) = &edges {
            check_edges(e).map_err(|m| value_error("speed_edges", m))?;
        }
        // SAFETY: the attachment holds the simulation's Python object, so `sim` is alive.
        let t = unsafe { State::field::<f64>(self.sim as *mut u8, self.state.layout.t) };
        let mut c = self
            .state
            .counters
            .lock()
            .map_err(|_| value_error("counters", "unusable (a thread panicked)"))?;
        *c = match edges {
            Some(e) => Counters::new(t, e, c.depth_threshold()),
            None => c.restarted(t),
        };
        Ok(())
    }

    /// Number of (radius, mass) pairs whose contact constants are cached.
    #[getter]
    fn cached_pairs(&self) -> usize {
        self.state.cache.lock().map(|c| c.len()).unwrap_or(0)
    }

    /// The contact cache: entries, capacity, hits and misses (pairs computed).
    fn cache_info<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        if let Ok(c) = self.state.cache.lock() {
            d.set_item("entries", c.len())?;
            d.set_item("capacity", c.capacity)?;
            d.set_item("hits", c.hits)?;
            d.set_item("misses", c.misses)?;
        }
        Ok(d)
    }

    /// The address of the C function to assign to `sim.heartbeat` (spins beside REBOUND's
    /// periodic archive, then the previous heartbeat).
    #[getter]
    fn heartbeat_address(&self) -> usize {
        heartbeat as *const () as usize
    }

    /// Sets the spins of the particles in order, an (N, 3) list.
    fn set_spins(&self, spins: Vec<[f64; 3]>) -> PyResult<()> {
        // SAFETY: the attachment holds the simulation's Python object, so `sim` is alive.
        let n = unsafe { self.state.count(self.sim as *mut u8) };
        if spins.len() != n {
            return Err(value_error(
                "spins",
                format!("expected shape ({n}, 3) (got ({}, 3))", spins.len()),
            ));
        }
        if let Some(bad) = spins.iter().flatten().find(|w| !w.is_finite()) {
            return Err(value_error(
                "spins",
                format!("every value must be finite (got {bad})"),
            ));
        }
        let mut table =
            self.state.spins.lock().map_err(|_| {
                value_error("spins", "the spin table is unusable (a thread panicked)")
            })?;
        *table = spins;
        Ok(())
    }

    /// The particles' spins in order, an (N, 3) list (0 for particles added since the last
    /// collision); an error when particles were removed outside the handler.
    fn spins(&self) -> PyResult<Vec<[f64; 3]>> {
        // SAFETY: the attachment holds the simulation's Python object, so `sim` is alive.
        let table = unsafe { self.state.spins_for(self.sim as *mut u8) }
            .map_err(|e| value_error("spins", e.trim_start_matches("spins: ")))?;
        Ok(table.clone())
    }

    /// The spin file's line for the simulation's present state (`Attachment.save`).
    fn spin_record(&self) -> String {
        // SAFETY: the attachment holds the simulation's Python object, so `sim` is alive.
        unsafe { self.state.spin_record(self.sim as *mut u8) }
    }

    /// Removes this handler's registration (the simulation must not call it afterwards).
    fn detach(&self) {
        if let Ok(mut r) = REGISTRY.write() {
            r.retain(|(a, s)| !(*a == self.sim && Arc::ptr_eq(s, &self.state)));
        }
    }
}

fn positive(field: &str, v: f64) -> PyResult<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(value_error(
            field,
            format!("must be finite and > 0 (got {v})"),
        ))
    }
}

/// Registers the handler for the simulation at `sim` (see `rime_grains.rebound.attach`).
#[pyfunction]
#[pyo3(signature = (sim, layout, scene, length_unit, time_unit, mass_unit, density, sticking, track_spins, accuracy, cache_size, previous_heartbeat, speed_edges, overlap_depth))]
#[allow(clippy::too_many_arguments)]
// Long by design: checks every argument of the REBOUND handler at the Python boundary, one named
// error each, before the C callback is registered.
fn _attach(
    sim: usize,
    layout: HashMap<String, usize>,
    scene: PyRef<'_, crate::PyScene>,
    length_unit: f64,
    time_unit: f64,
    mass_unit: f64,
    density: &str,
    sticking: &str,
    track_spins: bool,
    accuracy: &str,
    cache_size: usize,
    previous_heartbeat: usize,
    speed_edges: Vec<f64>,
    overlap_depth: f64,
) -> PyResult<Handler> {
    check_edges(&speed_edges).map_err(|m| value_error("speed_edges", m))?;
    if !(overlap_depth.is_finite() && (0.0..1.0).contains(&overlap_depth)) {
        return Err(value_error(
            "overlap_depth",
            format!("a fraction of r1 + r2 in [0, 1) (got {overlap_depth})"),
        ));
    }
    if cache_size < 2 {
        return Err(value_error(
            "cache_size",
            format!("must be at least 2 pairs (got {cache_size})"),
        ));
    }
    if sim == 0 {
        return Err(value_error("sim", "a null simulation"));
    }
    let get = |k: &str| {
        layout
            .get(k)
            .copied()
            .ok_or_else(|| value_error("layout", format!("missing offset '{k}'")))
    };
    let layout = Layout {
        particles: get("particles")?,
        n: get("N")?,
        status: get("status")?,
        minimum_collision_velocity: get("minimum_collision_velocity")?,
        t: get("t")?,
        dt: get("dt")?,
        steps_done: get("steps_done")?,
        walltime: get("walltime")?,
        archive_filename: get("simulationarchive_filename")?,
        archive_interval: get("simulationarchive_auto_interval")?,
        archive_walltime: get("simulationarchive_auto_walltime")?,
        archive_step: get("simulationarchive_auto_step")?,
        archive_next: get("simulationarchive_next")?,
        archive_next_step: get("simulationarchive_next_step")?,
        particle_size: get("particle_size")?,
        x: get("x")?,
        vx: get("vx")?,
        m: get("m")?,
        r: get("r")?,
    };
    for (name, off, width) in [
        ("x", layout.x, 24),
        ("vx", layout.vx, 24),
        ("m", layout.m, 8),
        ("r", layout.r, 8),
    ] {
        if off % 8 != 0 || off + width > layout.particle_size {
            return Err(value_error(
                "layout",
                format!(
                    "reb_particle.{name} at byte {off} does not fit a {}-byte particle",
                    layout.particle_size
                ),
            ));
        }
    }
    for (name, off) in [
        ("particles", layout.particles),
        ("N", layout.n),
        (
            "minimum_collision_velocity",
            layout.minimum_collision_velocity,
        ),
        ("t", layout.t),
        ("dt", layout.dt),
        ("steps_done", layout.steps_done),
        ("walltime", layout.walltime),
        ("simulationarchive_filename", layout.archive_filename),
        ("simulationarchive_auto_interval", layout.archive_interval),
        ("simulationarchive_auto_walltime", layout.archive_walltime),
        ("simulationarchive_auto_step", layout.archive_step),
        ("simulationarchive_next", layout.archive_next),
        ("simulationarchive_next_step", layout.archive_next_step),
    ] {
        if off % 8 != 0 {
            return Err(value_error(
                "layout",
                format!("reb_simulation.{name} at byte {off} is not 8-aligned"),
            ));
        }
    }
    let density = match density {
        "particles" => Density::Particles,
        "scene" => Density::Scene,
        other => {
            return Err(value_error(
                "density",
                format!("expected \"particles\" or \"scene\" (got {other:?})"),
            ));
        }
    };
    let sticking = match sticking {
        "merge" => Sticking::Merge,
        "stay" => Sticking::Stay,
        "merge_if_slow" => Sticking::MergeIfSlow,
        other => {
            return Err(value_error(
                "sticking",
                format!("expected \"merge\", \"stay\" or \"merge_if_slow\" (got {other:?})"),
            ));
        }
    };
    // SAFETY: `sim` is the address of the live simulation the caller passes (its t offset from
    // rebound's ctypes class, checked 8-aligned above).
    let t_now = unsafe { State::field::<f64>(sim as *mut u8, layout.t) };
    let state = Arc::new(State {
        layout,
        scene: scene.scene,
        accuracy: crate::accuracy(accuracy)?,
        length_unit: positive("length_unit", length_unit)?,
        time_unit: positive("time_unit", time_unit)?,
        mass_unit: positive("mass_unit", mass_unit)?,
        density,
        sticking,
        track_spins,
        spins: Mutex::new(Vec::new()),
        cache: Mutex::new(PairCache::new(cache_size)),
        previous_heartbeat: if previous_heartbeat == heartbeat as *const () as usize {
            0 // never call itself
        } else {
            previous_heartbeat
        },
        error: Mutex::new(None),
        bounces: AtomicU64::new(0),
        merges: AtomicU64::new(0),
        stays: AtomicU64::new(0),
        counters: Mutex::new(Counters::new(t_now, speed_edges, overlap_depth)),
    });
    scene.scene.validate().map_err(core_error)?;
    let mut registry = REGISTRY.write().map_err(|_| {
        value_error(
            "sim",
            "the handler registry is unusable (a thread panicked)",
        )
    })?;
    registry.retain(|(a, _)| *a != sim);
    registry.push((sim, Arc::clone(&state)));
    Ok(Handler { sim, state })
}

/// `struct reb_collision` as this module compiles it: (size, offsets of p1, p2, gb, ri).
#[pyfunction]
fn collision_layout() -> (usize, [usize; 4]) {
    (
        std::mem::size_of::<RebCollision>(),
        [
            std::mem::offset_of!(RebCollision, p1),
            std::mem::offset_of!(RebCollision, p2),
            std::mem::offset_of!(RebCollision, gb),
            std::mem::offset_of!(RebCollision, ri),
        ],
    )
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Handler>()?;
    m.add_function(wrap_pyfunction!(_attach, m)?)?;
    m.add_function(wrap_pyfunction!(collision_layout, m)?)?;
    m.add("REBOUND_VERSION", REBOUND_VERSION)?;
    Ok(())
}
