//! A REBOUND `collision_resolve` in native code, configured at run time.
//!
//! `rime_grains.rebound.attach` registers a [`State`] (scene, units, density and sticking rules, the
//! particle layout read from rebound's own ctypes classes) for one simulation's address and sets
//! `sim.collision_resolve` to [`collision_resolve`]. REBOUND calls it with the simulation and a
//! `struct reb_collision` by value; it applies ε_N (Eq. (4)–(17)), ε_T (Eq. (26)) and the spin change
//! of one impulse at the contact point (Eq. (1)–(2)) through the core's kinematics, or merges the
//! grains (mass, volume, momentum and angular momentum kept). Contact constants are cached per
//! pair of (radius, mass) behind a read–write lock, so the handler is safe when REBOUND resolves
//! collisions from several threads.

// Unsafe is needed here and only here: REBOUND hands the handler raw pointers to its simulation
// and particles (a C callback). Every access goes through the small helpers below, whose offsets
// come from rebound's ctypes classes and are checked at attach time against the particle size.
#![allow(unsafe_code)]

use crate::{core_error, value_error};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rime_core::kinematics::{GrainState, Vector3, collide};
use rime_core::{Accuracy, Contact, Scene};
use std::collections::HashMap;
use std::ffi::{c_int, c_void};
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

/// `REB_COLLISION_RESOLVE_OUTCOME`: keep both, remove p1, remove p2.
const KEEP_BOTH: c_int = 0;
const REMOVE_P1: c_int = 1;
const REMOVE_P2: c_int = 2;
/// `REB_STATUS_GENERIC_ERROR`: stops `sim.integrate`, which raises `rebound.GenericError`.
const STATUS_GENERIC_ERROR: c_int = 1;
/// Solid spheres: I = 2/5 m r².
const INERTIA_FACTOR: f64 = 0.4;

/// Byte offsets into `struct reb_simulation` and `struct reb_particle`.
#[derive(Clone, Copy, Debug)]
struct Layout {
    particles: usize,
    n: usize,
    status: usize,
    minimum_collision_velocity: usize,
    particle_size: usize,
    x: usize,
    vx: usize,
    m: usize,
    r: usize,
    ap: usize,
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
    cache: RwLock<HashMap<[u64; 4], Pair>>,
    error: Mutex<Option<String>>,
    bounces: AtomicU64,
    merges: AtomicU64,
    stays: AtomicU64,
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
    spin: *mut f64,
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
            let spin = if self.track_spins {
                *(base.add(l.ap) as *const *mut f64)
            } else {
                std::ptr::null_mut()
            };
            Some(Particle {
                base,
                x: [*d(l.x), *d(l.x + 8), *d(l.x + 16)],
                v: [*d(l.vx), *d(l.vx + 8), *d(l.vx + 16)],
                m: *d(l.m),
                r: *d(l.r),
                spin,
            })
        }
    }

    fn spin(p: &Particle) -> Vector3<f64> {
        if p.spin.is_null() {
            return Vector3::zeros();
        }
        // SAFETY: a non-null `ap` of a tracked particle points at 3 doubles of the attachment's
        // spin array (set by `Attachment.track_spins`, kept alive by the attachment).
        unsafe { Vector3::new(*p.spin, *p.spin.add(1), *p.spin.add(2)) }
    }

    /// Writes velocity, mass, radius, position and spin back into the particle.
    fn store(&self, p: &Particle, x: [f64; 3], v: [f64; 3], m: f64, r: f64, w: Vector3<f64>) {
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
            if !p.spin.is_null() {
                for k in 0..3 {
                    *p.spin.add(k) = w[k];
                }
            }
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
        if let Ok(cache) = self.cache.read()
            && let Some(p) = cache.get(&key)
        {
            return Ok(*p);
        }
        let mut scene = self.scene;
        scene.grains.radius_1 = r1 * self.length_unit;
        scene.grains.radius_2 = r2 * self.length_unit;
        if self.density == Density::Particles {
            // The model depends on the masses only through m_eff: the density that gives the
            // particles' m_eff with these radii (their own density when both share one).
            let volume = |r: f64| 4.0 / 3.0 * std::f64::consts::PI * r * r * r;
            let (v1, v2) = (volume(scene.grains.radius_1), volume(scene.grains.radius_2));
            let (ms1, ms2) = (m1 * self.mass_unit, m2 * self.mass_unit);
            let m_eff = ms1 * ms2 / (ms1 + ms2);
            scene.grains.density = m_eff * (v1 + v2) / (v1 * v2);
        }
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
        if let Ok(mut cache) = self.cache.write() {
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
        let (w1, w2) = (Self::spin(&p1), Self::spin(&p2));
        // REBOUND finds the pair overlapping at the end of a step. The impulse acts at the contact
        // point, which splits the line of centres in the ratio of the radii: the lever arms are
        // a_i d/(a_i + a_j) (the radii when touching), so angular momentum (orbital + spin) is kept
        // exactly; the moments of inertia stay 2/5 m a².
        let scale = dist / (p1.r + p2.r);
        let grain = |p: &Particle, v, w| GrainState {
            mass: p.m,
            radius: p.r * scale,
            inertia_factor: INERTIA_FACTOR / (scale * scale),
            velocity: v,
            spin: w,
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
                self.merges.fetch_add(1, Ordering::Relaxed);
                // Keep the grain that tracks a spin (p1 unless only p2 does).
                return Ok(if p1.spin.is_null() && !p2.spin.is_null() {
                    self.merge(&p2, &p1, [gb[0], gb[1], gb[2]], [gb[3], gb[4], gb[5]]);
                    REMOVE_P1
                } else {
                    self.merge(&p1, &p2, [-gb[0], -gb[1], -gb[2]], [-gb[3], -gb[4], -gb[5]]);
                    REMOVE_P2
                });
            }
            self.stays.fetch_add(1, Ordering::Relaxed);
        } else {
            self.bounces.fetch_add(1, Ordering::Relaxed);
        }
        // REBOUND's floor on the separation speed: the normal speed after is at least
        // sim.minimum_collision_velocity (code units), so resting grains do not sink into each other.
        // SAFETY: offset from rebound's ctypes class of struct reb_simulation.
        let v_min = unsafe { *(sim.add(self.layout.minimum_collision_velocity) as *const f64) };
        let mut eps = eps_n;
        if v_min > 0.0 && g_n < 0.0 {
            eps = eps.max((v_min / -g_n).min(1.0));
        }
        collide(&mut gi, &mut gj, &n, eps, eps_t).map_err(field)?;
        let v1_new = [
            gi.velocity[0] - gb[3],
            gi.velocity[1] - gb[4],
            gi.velocity[2] - gb[5],
        ];
        let v2_new = [gj.velocity[0], gj.velocity[1], gj.velocity[2]];
        self.store(&p1, p1.x, v1_new, p1.m, p1.r, gi.spin);
        self.store(&p2, p2.x, v2_new, p2.m, p2.r, gj.spin);
        Ok(KEEP_BOTH)
    }

    /// Merges `other` into `keep`; `(dx, dv)` moves `other` into `keep`'s ghost frame. Keeps mass,
    /// volume, momentum and angular momentum (orbital about the centre of mass plus spins).
    fn merge(&self, keep: &Particle, other: &Particle, dx: [f64; 3], dv: [f64; 3]) {
        let (m1, m2) = (keep.m, other.m);
        let mass = m1 + m2;
        let x1 = Vector3::from(keep.x);
        let v1 = Vector3::from(keep.v);
        let x2 = Vector3::from(other.x) + Vector3::from(dx);
        let v2 = Vector3::from(other.v) + Vector3::from(dv);
        let com = (x1 * m1 + x2 * m2) / mass;
        let vcom = (v1 * m1 + v2 * m2) / mass;
        let spin_l = |p: &Particle| Self::spin(p) * (INERTIA_FACTOR * p.m * p.r * p.r);
        let l = (x1 - com).cross(&(v1 - vcom)) * m1
            + (x2 - com).cross(&(v2 - vcom)) * m2
            + spin_l(keep)
            + spin_l(other);
        let radius = (keep.r.powi(3) + other.r.powi(3)).cbrt();
        let w = l / (INERTIA_FACTOR * mass * radius * radius);
        self.store(
            keep,
            [com[0], com[1], com[2]],
            [vcom[0], vcom[1], vcom[2]],
            mass,
            radius,
            w,
        );
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

    /// Number of (radius, mass) pairs whose contact constants are cached.
    #[getter]
    fn cached_pairs(&self) -> usize {
        self.state.cache.read().map(|c| c.len()).unwrap_or(0)
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
#[pyo3(signature = (sim, layout, scene, length_unit, time_unit, mass_unit, density, sticking, track_spins, accuracy))]
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
) -> PyResult<Handler> {
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
        particle_size: get("particle_size")?,
        x: get("x")?,
        vx: get("vx")?,
        m: get("m")?,
        r: get("r")?,
        ap: get("ap")?,
    };
    for (name, off, width) in [
        ("x", layout.x, 24),
        ("vx", layout.vx, 24),
        ("m", layout.m, 8),
        ("r", layout.r, 8),
        ("ap", layout.ap, 8),
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
        cache: RwLock::new(HashMap::new()),
        error: Mutex::new(None),
        bounces: AtomicU64::new(0),
        merges: AtomicU64::new(0),
        stays: AtomicU64::new(0),
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
