"""Benchmarks of rime_grains (issue 23): printed, never asserted.

1. ε_N of 1e6 speeds at the fast level: `rime.eps_n` from Python (array in, new array out)
   against the Rust batch path alone (`_native.bench_batch`: the core's `BatchLaw::fill` into a
   buffer), interleaved, best of 7 each, in one run. Target ≤ 3x.
2. Cost per collision: rime's handler against REBOUND's own hard-sphere resolve in C
   (`reb_collision_resolve_hardsphere` by its C address, so REBOUND calls C directly) with a
   compiled C Bridges et al. (1984) law, each called through its REBOUND function pointer by a C
   loop on one approaching pair that is restored before every call (`cc` builds the law and the
   loop; skipped without a C compiler); the loop's own cost (a handler that does nothing) is
   subtracted. Target ≤ 1.5x the C resolve. For information, the same resolve set the way
   REBOUND's Python setter does it (`sim.collision_resolve = "hardsphere"`), which stores a ctypes
   callback: every call goes C → Python → C.
3. A ring patch (1 m grains, τ = 0.5, 200 particles, shearing sheet, tree collisions): wall time
   with rime's handler against the C hard-sphere resolve with the C Bridges law, same start.

Usage: python bench.py [--quick]
"""
import ctypes
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

import rime_grains as rime


def best(f, repeats=5):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return min(times)


def batch(n=1_000_000):
    scene = rime.Scene.preset("ice-frost")
    g = np.logspace(-6, 0, n)
    rime.eps_n(g[:1000], scene, accuracy="fast")
    # Interleaved, best of 7 each: the machine's other load hits both alike.
    python, rust = math.inf, math.inf
    for _ in range(7):
        python = min(python, best(lambda: rime.eps_n(g, scene, accuracy="fast"), repeats=1))
        rust = min(rust, rime._native.bench_batch(g, scene, "fast", 1))
    print(f"eps_n, {n:.0e} speeds, fast, ice-frost: Python {python * 1e3:.2f} ms "
          f"({python / n * 1e9:.2f} ns/value), Rust batch {rust * 1e3:.2f} ms "
          f"({rust / n * 1e9:.2f} ns/value): ratio {python / rust:.2f} (target <= 3)")


BENCH_C = r"""
#include <math.h>
#include <string.h>
#include <stddef.h>
#include <time.h>

/* Bridges et al. (1984) as REBOUND's shearing-sheet example writes it (v in m/s), clamped. */
double rime_bench_bridges(const void *r, double v) {
    (void)r;
    double eps = 0.32 * pow(fabs(v) * 100.0, -0.234);
    if (eps > 1.0) eps = 1.0;
    if (eps < 0.0) eps = 0.0;
    return eps;
}

struct vec6 { double x, y, z, vx, vy, vz; };
struct coll { size_t p1, p2; struct vec6 gb; size_t ri; };  /* struct reb_collision */
typedef int (*resolve_t)(void *, struct coll);

/* Calls f(sim, {p1, p2}) n times, restoring the particles (and zeroing the spins) before each
 * call; returns the seconds of the whole loop. */
double rime_bench_loop(resolve_t f, void *sim, size_t p1, size_t p2, size_t n, void *particles,
                       const void *saved, size_t size, void *spins, size_t spins_size) {
    struct coll c;
    memset(&c, 0, sizeof c);
    c.p1 = p1;
    c.p2 = p2;
    struct timespec a, b;
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (size_t k = 0; k < n; k++) {
        memcpy(particles, saved, size);
        if (spins) memset(spins, 0, spins_size);
        f(sim, c);
    }
    clock_gettime(CLOCK_MONOTONIC, &b);
    return (double)(b.tv_sec - a.tv_sec) + 1e-9 * (double)(b.tv_nsec - a.tv_nsec);
}

/* A handler that does nothing: the loop's own cost. */
int rime_bench_noop(void *sim, struct coll c) { (void)sim; (void)c; return 0; }
"""


def bench_library():
    cc = shutil.which("cc") or shutil.which("gcc")
    if cc is None:
        return None
    d = tempfile.mkdtemp()
    src, lib = os.path.join(d, "bench.c"), os.path.join(d, "libbench.so")
    with open(src, "w") as f:
        f.write(BENCH_C)
    subprocess.run([cc, "-O2", "-shared", "-fPIC", src, "-o", lib, "-lm"], check=True)
    lib = ctypes.CDLL(lib)
    lib.rime_bench_loop.restype = ctypes.c_double
    lib.rime_bench_loop.argtypes = ([ctypes.c_void_p] * 2 + [ctypes.c_size_t] * 3
                                    + [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_size_t,
                                       ctypes.c_void_p, ctypes.c_size_t])
    return lib


def address_of(function):
    return ctypes.cast(function, ctypes.c_void_p).value


def per_call(lib, setup, n, g_t=0.001):
    """Seconds per call of the handler `setup` installs, on one approaching, overlapping pair of
    1 m ice grains (g_N = 1 cm/s, g_T = `g_t`), from a C loop that restores the pair every call.
    The loop cannot restore rime's spin table, so an oblique pair is timed with spins not tracked
    (the spin change is still computed; tracked spins would pile up call after call until g_T
    vanishes and time another branch); a head-on pair keeps its spins at 0."""
    import rebound

    sim = rebound.Simulation()
    sim.gravity = "none"
    m = 900 * 4 / 3 * math.pi
    sim.add(m=m, r=1.0, x=-0.9995, vx=0.005, vy=g_t)
    sim.add(m=m, r=1.0, x=0.9995, vx=-0.005)
    att = setup(sim)
    particles = address_of(sim._particles)
    size = sim.N * ctypes.sizeof(rebound.Particle)
    saved = ctypes.string_at(particles, size)
    seconds = lib.rime_bench_loop(address_of(sim._collision_resolve), ctypes.addressof(sim), 0, 1, n,
                                  particles, saved, size, None, 0)
    if isinstance(att, rime.rebound.Attachment) and att.counts()["bounces"] != n:
        sys.exit(f"per collision: {att.counts()} is not one bounce per call")
    return seconds / n


def c_hardsphere(rebound):
    """The C address of REBOUND's hard-sphere resolve (an int, so the setter stores it as is)."""
    return address_of(rebound.clibrebound.reb_collision_resolve_hardsphere)


def collisions(n=1_000_000):
    try:
        import rebound
    except ImportError:
        print("per collision: rebound is not installed, skipped")
        return
    lib = bench_library()
    if lib is None:
        print("per collision: no C compiler for the Bridges law and the loop, skipped")
        return
    scene = rime.Scene.preset("ice")

    def hardsphere_c(sim):
        sim.collision_resolve = c_hardsphere(rebound)
        sim.coefficient_of_restitution = address_of(lib.rime_bench_bridges)
        if address_of(sim._collision_resolve) != c_hardsphere(rebound):
            sys.exit("per collision: the C hard-sphere resolve is not stored as its C address")

    def hardsphere_setter(sim):
        sim.collision_resolve = "hardsphere"  # REBOUND's setter: a ctypes callback thunk
        sim.coefficient_of_restitution = address_of(lib.rime_bench_bridges)

    def noop(sim):
        sim.collision_resolve = address_of(lib.rime_bench_noop)

    def attach(accuracy, spins=False):
        return lambda sim: rime.rebound.attach(sim, scene, length_unit=1, time_unit=1, mass_unit=1,
                                               accuracy=accuracy, track_spins=spins)

    # Interleaved, best of 3 each: the machine's other load hits all alike. (label, setup, g_T)
    headline = "rime, precise, oblique (eps_N, eps_T and the spin change)"
    cases = [
        ("REBOUND's C hard-sphere resolve + C Bridges (the baseline)", hardsphere_c, 0.001),
        ('REBOUND "hardsphere" via its Python setter (C -> Python -> C) + C Bridges', hardsphere_setter, 0.001),
        (headline, attach("precise"), 0.001),
        ("rime, fast, oblique", attach("fast"), 0.001),
        ("rime, precise, head-on, spins tracked (eps_N only)", attach("precise", spins=True), 0.0),
    ]
    best_of = {label: math.inf for label, _, _ in cases}
    for _ in range(3):
        loop = per_call(lib, noop, n)
        for label, setup, g_t in cases:
            best_of[label] = min(best_of[label], per_call(lib, setup, n, g_t) - loop)
    base = best_of[cases[0][0]]
    for label, _, _ in cases:
        cost = best_of[label]
        print(f"per collision: {label}: {cost * 1e9:.0f} ns ({cost / base:.2f}x the C resolve)")
    rime_cost = best_of[headline]
    print(f"per collision: rime (precise, oblique) / REBOUND's C hard-sphere resolve = "
          f"{rime_cost / base:.2f} (target <= 1.5: {'met' if rime_cost <= 1.5 * base else 'NOT met'})")


def ring_patch(orbits):
    """Wall time of a ring patch with rime's handler against the C hard-sphere resolve with the
    C Bridges law (the same start, interleaved, best of 2)."""
    try:
        import rebound
    except ImportError:
        print("ring patch: rebound is not installed, skipped")
        return
    lib = bench_library()
    if lib is None:
        print("ring patch: no C compiler for the Bridges law, skipped")
        return
    omega, radius, tau, n = 1.3143527e-4, 1.0, 0.5, 200
    scene = rime.Scene.preset("ice")
    scene.set("bulk.damping.time", 5e-3)  # A for metre grains (README, "What the law does to a ring")

    def patch(resolve):
        rng = np.random.default_rng(1)
        sim = rebound.Simulation()
        sim.OMEGA, sim.dt, sim.rand_seed = omega, 1e-3 * 2 * math.pi / omega, 1
        box = math.sqrt(n * math.pi * radius**2 / tau)
        sim.root_size = box
        sim.N_ghost_x, sim.N_ghost_y = 2, 2
        sim.integrator, sim.boundary, sim.gravity, sim.collision = "sei", "shear", "none", "tree"
        floor = 2 * radius * omega
        for _ in range(n):
            x, y, z = rng.uniform(-box / 2, box / 2), rng.uniform(-box / 2, box / 2), rng.normal(0, 2 * radius)
            v = rng.normal(0, floor, 3)
            sim.add(m=900 * 4 / 3 * math.pi * radius**3, r=radius, x=x, y=y, z=z, vx=v[0],
                    vy=-1.5 * x * omega + v[1], vz=v[2])
        keep = resolve(sim)
        start = time.perf_counter()
        sim.integrate(orbits * 2 * math.pi / omega)
        return time.perf_counter() - start, keep

    def with_rime(sim):
        return rime.rebound.attach(sim, scene, length_unit=1, time_unit=1, mass_unit=1)

    def with_c(sim):
        sim.collision_resolve = c_hardsphere(rebound)
        sim.coefficient_of_restitution = address_of(lib.rime_bench_bridges)

    t_rime, t_c = math.inf, math.inf
    for _ in range(2):
        t_rime = min(t_rime, patch(with_rime)[0])
        t_c = min(t_c, patch(with_c)[0])
    print(f"ring patch (1 m ice, A = 5e-3 s, tau 0.5, {n} grains, {orbits:g} orbits): rime {t_rime:.3f} s, "
          f"C hard-sphere + C Bridges {t_c:.3f} s: ratio {t_rime / t_c:.2f}")


if __name__ == "__main__":
    quick = "--quick" in sys.argv
    batch()
    collisions(n=200_000 if quick else 1_000_000)
    ring_patch(orbits=0.5 if quick else 3.0)
