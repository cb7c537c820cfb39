"""Benchmarks of rime_grains (issue 23): printed, never asserted.

1. ε_N of 1e6 speeds at the fast level: `rime.eps_n` from Python against the Rust batch path
   alone (`_native.bench_batch`, no Python in the loop), best of 5 each, in one run. Target ≤ 3x.
2. Cost per collision inside REBOUND: rime's handler against REBOUND's own hard-sphere resolve
   with a compiled C Bridges et al. (1984) law (`cc` builds it; skipped without a C compiler).
   Many separated pairs that overlap and approach are resolved in one step; the same step with
   the pairs separating (every handler returns before resolving) is subtracted. Target ≤ 1.5x.

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
    python = best(lambda: rime.eps_n(g, scene, accuracy="fast"))
    rust = rime._native.bench_batch(g, scene, "fast", 5)
    print(f"eps_n, {n:.0e} speeds, fast, ice-frost: Python {python * 1e3:.2f} ms "
          f"({python / n * 1e9:.2f} ns/value), Rust batch {rust * 1e3:.2f} ms "
          f"({rust / n * 1e9:.2f} ns/value): ratio {python / rust:.2f} (target <= 3)")


BRIDGES_C = r"""
#include <math.h>
/* Bridges et al. (1984) as REBOUND's shearing-sheet example writes it (v in m/s), clamped. */
double rime_bench_bridges(const void* r, double v) {
    (void)r;
    double eps = 0.32 * pow(fabs(v) * 100.0, -0.234);
    if (eps > 1.0) eps = 1.0;
    if (eps < 0.0) eps = 0.0;
    return eps;
}
"""


def bridges_library():
    cc = shutil.which("cc") or shutil.which("gcc")
    if cc is None:
        return None
    d = tempfile.mkdtemp()
    src, lib = os.path.join(d, "bridges.c"), os.path.join(d, "libbridges.so")
    with open(src, "w") as f:
        f.write(BRIDGES_C)
    subprocess.run([cc, "-O2", "-shared", "-fPIC", src, "-o", lib, "-lm"], check=True)
    return ctypes.CDLL(lib)


def pairs_sim(n_pairs, approach):
    """n_pairs pairs of 1 m ice grains, 10 m apart, each overlapping by 1 mm, on a grid."""
    import rebound

    sim = rebound.Simulation()
    sim.gravity, sim.integrator, sim.collision = "none", "leapfrog", "tree"
    side = int(math.ceil(math.sqrt(n_pairs)))
    sim.root_size = 10.0 * side
    sim.dt = 1e-9
    m = 900 * 4 / 3 * math.pi
    k = 0
    for i in range(side):
        for j in range(side):
            if k == n_pairs:
                break
            x, y = 10.0 * (i - side / 2) + 5, 10.0 * (j - side / 2) + 5
            v = 0.005 if approach else -0.005
            sim.add(m=m, r=1.0, x=x - 0.9995, y=y, z=0.0, vx=v, vy=0.001)
            sim.add(m=m, r=1.0, x=x + 0.9995, y=y, z=0.0, vx=-v)
            k += 1
    return sim


def step_cost(sim, reps, attachment=None):
    """Seconds per step, the particles (and rime's spins) reset before every step (outside the
    timing)."""
    import rebound

    address = ctypes.cast(sim._particles, ctypes.c_void_p).value
    size = sim.N * ctypes.sizeof(rebound.Particle)
    saved = ctypes.string_at(address, size)
    total = 0.0
    for _ in range(reps):
        ctypes.memmove(address, saved, size)
        if attachment is not None:
            attachment._link.storage[0][:] = 0.0
        start = time.perf_counter()
        sim.steps(1)
        total += time.perf_counter() - start
    return total / reps


def collisions(n_pairs=2000, reps=100):
    try:
        import rebound  # noqa: F401
    except ImportError:
        print("per collision: rebound is not installed, skipped")
        return
    lib = bridges_library()
    if lib is None:
        print("per collision: no C compiler for the Bridges law, skipped")
        return
    scene = rime.Scene.preset("ice")
    rows = []
    for label, setup in (
        ("REBOUND hardsphere + C Bridges", lambda s: (setattr(s, "collision_resolve", "hardsphere"),
                                                      setattr(s, "coefficient_of_restitution",
                                                              ctypes.cast(lib.rime_bench_bridges, ctypes.c_void_p).value))),
        ("rime (precise, spins)", lambda s: rime.rebound.attach(s, scene, length_unit=1, time_unit=1, mass_unit=1)),
        ("rime (fast, spins)", lambda s: rime.rebound.attach(s, scene, length_unit=1, time_unit=1, mass_unit=1,
                                                              accuracy="fast")),
    ):
        costs = []
        for approach in (True, False):
            sim = pairs_sim(n_pairs, approach)
            att = setup(sim)
            costs.append(step_cost(sim, reps, att if isinstance(att, rime.rebound.Attachment) else None))
            if approach and isinstance(att, rime.rebound.Attachment) and att.counts()["bounces"] != n_pairs * reps:
                sys.exit(f"per collision: {label}: {att.counts()} is not one bounce per pair and step")
        rows.append((label, (costs[0] - costs[1]) / n_pairs))
    base = rows[0][1]
    for label, cost in rows:
        print(f"per collision: {label}: {cost * 1e9:.0f} ns ({cost / base:.2f}x REBOUND's; target <= 1.5x)")


if __name__ == "__main__":
    quick = "--quick" in sys.argv
    batch()
    collisions(n_pairs=1000 if quick else 2000, reps=40 if quick else 100)
