#!/usr/bin/env python3
"""Times scipy's solve_ivp(DOP853, rtol=1e-10) on the same dimensionless ODE rime integrates.

x'' + x^(3/2) + 1.5 δ √x x' = 0, x(0) = 0, x'(0) = 1, integrated in σ = √s (as rime does) until the
total force x + 1.5 δ x' vanishes; prints ε_N and the median wall time per evaluation. A dev-time
comparison only (scipy is not a build dependency): `python3 core/benches/scipy_compare.py`.
"""
import json
import statistics
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp


def eps_scipy(delta, rtol=1e-10):
    k = 1.5 * delta

    def rhs(sigma, y):
        x = max(y[0], 0.0)
        return [2 * sigma * y[1], -2 * sigma * np.sqrt(x) * (x + k * y[1])]

    def force_zero(sigma, y):
        return y[0] + k * y[1]

    force_zero.terminal = True
    force_zero.direction = -1
    # Start slightly after σ = 0, where the force event function is positive (1.5 δ) anyway.
    sol = solve_ivp(rhs, (0.0, 50.0), [0.0, 1.0], method="DOP853", rtol=rtol, atol=1e-16,
                    events=force_zero)
    y = sol.y_events[0][0]
    return -y[1]


def main():
    deltas = [0.01, 0.1, 0.749, 1.0]
    out = {}
    for d in deltas:
        times = []
        for _ in range(20):
            t0 = time.perf_counter()
            e = eps_scipy(d)
            times.append(time.perf_counter() - t0)
        out[d] = {"eps": e, "median_seconds": statistics.median(times)}
        print(f"delta={d}: eps={e:.15g} median={statistics.median(times)*1e3:.3f} ms", file=sys.stderr)
    print(json.dumps(out))


if __name__ == "__main__":
    main()
