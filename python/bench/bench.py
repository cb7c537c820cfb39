"""Benchmarks of rime_grains (issue 23): printed, never asserted.

1. ε_N of 1e6 speeds at the fast level: `rime.eps_n` from Python (array in, new array out)
   against the Rust batch path alone (`_native.bench_batch`: the core's `BatchLaw::fill` into a
   buffer), interleaved, best of 7 each, in one run. Target ≤ 3x.
2. Cost per collision: rime's handler against REBOUND's own hard-sphere resolve with a compiled C
   Bridges et al. (1984) law, each called through its REBOUND function pointer by a C loop on one
   approaching pair that is restored before every call (`cc` builds the law and the loop; skipped
   without a C compiler); the loop's own cost (a handler that does nothing) is subtracted.
   Target ≤ 1.5x.

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


def per_call(lib, setup, n):
    """Seconds per call of the handler `setup` installs, on one approaching, overlapping pair of
    1 m ice grains (g_N = 1 cm/s, g_T = 1 mm/s), from a C loop that restores the pair every call."""
    import rebound

    sim = rebound.Simulation()
    sim.gravity = "none"
    m = 900 * 4 / 3 * math.pi
    sim.add(m=m, r=1.0, x=-0.9995, vx=0.005, vy=0.001)
    sim.add(m=m, r=1.0, x=0.9995, vx=-0.005)
    att = setup(sim)
    particles = address_of(sim._particles)
    size = sim.N * ctypes.sizeof(rebound.Particle)
    saved = ctypes.string_at(particles, size)
    spins = att._link.storage[0] if isinstance(att, rime.rebound.Attachment) else None
    seconds = lib.rime_bench_loop(address_of(sim._collision_resolve), ctypes.addressof(sim), 0, 1, n,
                                  particles, saved, size,
                                  None if spins is None else spins.ctypes.data,
                                  0 if spins is None else spins.nbytes)
    if isinstance(att, rime.rebound.Attachment) and att.counts()["bounces"] != n:
        sys.exit(f"per collision: {att.counts()} is not one bounce per call")
    return seconds / n


def collisions(n=1_000_000):
    try:
        import rebound  # noqa: F401
    except ImportError:
        print("per collision: rebound is not installed, skipped")
        return
    lib = bench_library()
    if lib is None:
        print("per collision: no C compiler for the Bridges law and the loop, skipped")
        return
    scene = rime.Scene.preset("ice")

    def hardsphere(sim):
        sim.collision_resolve = "hardsphere"
        sim.coefficient_of_restitution = address_of(lib.rime_bench_bridges)

    def noop(sim):
        sim.collision_resolve = address_of(lib.rime_bench_noop)

    def attach(accuracy):
        return lambda sim: rime.rebound.attach(sim, scene, length_unit=1, time_unit=1, mass_unit=1,
                                               accuracy=accuracy)

    loop = per_call(lib, noop, n)
    rows = [(label, per_call(lib, setup, n) - loop) for label, setup in (
        ("REBOUND hardsphere + C Bridges", hardsphere),
        ("rime, precise, with spins", attach("precise")),
        ("rime, fast, with spins", attach("fast")),
    )]
    base = rows[0][1]
    for label, cost in rows:
        print(f"per collision: {label}: {cost * 1e9:.0f} ns ({cost / base:.2f}x REBOUND's; "
              f"target <= 1.5x)")


if __name__ == "__main__":
    quick = "--quick" in sys.argv
    batch()
    collisions(n=200_000 if quick else 1_000_000)
