"""Cost of rime_grains.dustpy's updaters inside DustPy 1.0.9 (issue 39): printed, never asserted.

DustPy's default disk is 100 radial cells × 120 mass bins (1.44e6 pairs), its temperature the
passively irradiated profile (every cell a different T). Measured, best of several calls each:

1. ``attach``: the first tables (one per distinct rounded temperature; under the default
   ``temperature_rule="hold"`` every cell colder than 175 K or warmer than 200 K shares its end's
   table) and the check of the options;
2. one update of p_stick with the tables cached (the cost of every DustPy step; target ≤ 50 ms),
   beside DustPy's own p_stick and p_frag updaters on the same arrays;
3. one update when every cell's temperature moves by more than ``temperature_step`` (every table
   recomputed: a disk whose temperature changes each step), with 100 distinct temperatures in the
   measured range;
4. one whole DustPy step (``sim.update()`` of every field) with rime's updaters, for scale.

Usage: python dustpy_bench.py [--quick]
"""
import sys
import time
import warnings

import numpy as np

import rime_grains as rime
from rime_grains.dustpy import attach


def best(f, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return min(times)


def import_dustpy_offline():
    """DustPy without its network check (`rime_grains.dustpy.import_offline`)."""
    from rime_grains.dustpy import import_offline

    return import_offline()


def main():
    quick = "--quick" in sys.argv
    repeats = 3 if quick else 7
    dustpy = import_dustpy_offline()
    from dustpy.std import dust as std_dust

    sim = dustpy.Simulation()
    sim.ini.dust.rhoMonomer = 0.9
    sim.initialize()
    nr, nm = np.asarray(sim.dust.a).shape
    temperatures = np.asarray(sim.gas.T)
    scene = rime.Scene.preset("ice")
    start = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # γ held outside 175–200 K, the density: reported below
        att = attach(sim, scene)
    first = time.perf_counter() - start
    info = att.cache_info()
    print(f"DustPy default disk: {nr} cells × {nm}² pairs, T = {temperatures.min():.4g}–"
          f"{temperatures.max():.4g} K; attach {first * 1e3:.1f} ms "
          f"({info['tables']} tables, {info['seconds'] * 1e3:.1f} ms in the kernel)")

    cached = best(lambda: att.p_stick(sim), repeats)
    own_stick = best(lambda: std_dust.p_stick(sim), repeats)
    own_frag = best(lambda: std_dust.p_frag(sim), repeats)
    print(f"p_stick update, tables cached: {cached * 1e3:.2f} ms ({cached / (nr * nm * nm) * 1e9:.2f} "
          f"ns/pair; target <= 50 ms); DustPy's own p_stick {own_stick * 1e3:.2f} ms, "
          f"p_frag {own_frag * 1e3:.2f} ms")

    # Every cell inside the measured range and every update at new temperatures: no cache hit.
    warm = np.linspace(175.5, 199.5, nr)
    sim.gas.T.updater = None
    shift = [0.0]

    def moved():
        shift[0] += 0.05
        sim.gas.T[...] = warm + (shift[0] % 0.4)
        att.p_stick(sim)

    moved()
    recomputed = best(moved, repeats)
    print(f"p_stick update, {nr} new temperatures every update (no cache hit): "
          f"{recomputed * 1e3:.1f} ms")

    sim.gas.T[...] = warm
    att.p_stick(sim)
    step = best(sim.update, repeats)
    print(f"one sim.update() of every DustPy field with rime's updaters: {step * 1e3:.1f} ms")
    att.detach()


if __name__ == "__main__":
    main()
