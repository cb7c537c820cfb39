#!/usr/bin/env python3
"""Force-zero contact duration for strong damping, integrated in scaled variables.

Independent of the rime sources and of taylor.py (a different method and different variables).
Writes tests/data/strong_damping.csv; run:  python3 tests/reference/strong_damping.py

Problem (the dimensionless Eq. (4), docs/physics.md#decision-3):
    x'' + x^(3/2) + 1.5 δ √x x' = 0,  x(0) = 0, x'(0) = 1,
    contact ends where the total force x + 1.5 δ x' returns to zero (force zero).

Scaled variables for δ ≫ 1: x = δ^(-2/3) y, s = δ^(-2/3) S, ε = δ^(-5/3). Then
    y'' + 1.5 √y y' + ε y^(3/2) = 0,   y(0) = 0, y'(0) = 1
(ε is the only parameter; every quantity is O(1) except the force), and with the scaled total force
H = y + 1.5 y'/ε (H = δ^(2/3) (x + 1.5 δ x')):
    y' = (2/3) ε (H − y),
    H' = −(1.5 √y − (2/3) ε) H − (2/3) ε y,        y(0) = 0, H(0) = 1.5/ε.
H is carried as a state so that the end of contact, H = 0, is found without cancellation.
The start is singular (√y at y = 0): up to y = 1/4 the independent variable is r = √y, in which
the unknowns S(r) and H(r) are analytic (dS/dr = 2r/y', y' → 1 at r = 0); then S itself.

Method: classical RK4 with mpmath (dps 40), fixed steps; the crossing H = 0 by secant on the
step length from the last step before it. Each δ is integrated with h, h/2 and h/4 and the
results Richardson-extrapolated (RK4: error ∝ h⁴); the file gets the extrapolated value and the
script prints the extrapolation's change (the error bound).

Asymptote (derived in docs/physics.md#decision-2, checked here): for ε → 0,
    S_c = (4/3) ln(1/ε) + (2/3) ln(27/8) + ln 3 − π/(3√3) + O(ε ln² ε)
        = (20/9) ln δ + C,   C = 1.304 9…,
    s_c = t_c/τ = δ^(-2/3) S_c,  ε_N = (2/3) ε y(S_c) → (2/3) δ^(-5/3),  x_max → δ^(-2/3).

Columns: delta, s_c (= t_c/τ), eps (ε_N), x_max (ξ_max/ξ*), S_c (scaled duration),
asymptote_S_c (the closed form above).
"""
import csv
import os
import sys

from mpmath import mp, mpf, sqrt, log, pi, nstr

mp.dps = 40
HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, '..', 'data', 'strong_damping.csv')


R_SWITCH = mpf('0.5')  # √y where the first stretch ends (y' ≈ 0.88 there: still monotone)


def rhs_r(r, S, H, eps):
    """d(S, H)/dr on the first stretch, r = √y the independent variable (analytic at r = 0)."""
    y_S = (mpf(2) / 3) * eps * (H - r * r)
    H_S = -(mpf('1.5') * r - (mpf(2) / 3) * eps) * H - (mpf(2) / 3) * eps * r * r
    return 2 * r / y_S, 2 * r * H_S / y_S


def rhs_s(S, y, H, eps):
    """d(y, H)/dS once y is bounded away from 0 (√y smooth there)."""
    dy = (mpf(2) / 3) * eps * (H - y)
    dH = -(mpf('1.5') * sqrt(y) - (mpf(2) / 3) * eps) * H - (mpf(2) / 3) * eps * y
    return dy, dH


def rk4_step(f, t, a, b, eps, h):
    k1 = f(t, a, b, eps)
    k2 = f(t + h / 2, a + h / 2 * k1[0], b + h / 2 * k1[1], eps)
    k3 = f(t + h / 2, a + h / 2 * k2[0], b + h / 2 * k2[1], eps)
    k4 = f(t + h, a + h * k3[0], b + h * k3[1], eps)
    return (a + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]),
            b + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]))


def contact(delta, h):
    """(S_c, y at S_c, y_max) of the scaled force-zero contact with RK4 step h (in S; the first
    stretch in r = √y uses h/4: same number of steps per unit of the variable's scale)."""
    eps = delta ** (-mpf(5) / 3)
    # First stretch: r from 0 to R_SWITCH, unknowns S(r), H(r).
    n1 = int(R_SWITCH / (h / 4)) + 1
    hr = R_SWITCH / n1
    r, S, H = mpf(0), mpf(0), mpf('1.5') / eps
    for _ in range(n1):
        S, H = rk4_step(rhs_r, r, S, H, eps, hr)
        r += hr
    y = r * r
    y_max = y
    while True:
        y1, H1 = rk4_step(rhs_s, S, y, H, eps, h)
        if H1 <= 0:
            break
        # x_max: y' = 0 where H = y; y rises until then and is flat there (y'' = −ε y^(3/2)), so
        # the running maximum is the maximum to the step's error plus ε h².
        y_max = max(y_max, y1)
        S, y, H = S + h, y1, H1
    # Secant (Illinois) on the step length a ∈ (0, h] for H(S + a) = 0.
    lo, hi = mpf(0), h
    f_lo, f_hi = H, H1
    side = 0
    for _ in range(200):
        a = hi - f_hi * (hi - lo) / (f_hi - f_lo)
        ya, Ha = rk4_step(rhs_s, S, y, H, eps, a)
        if Ha == 0 or hi - lo < mpf(10) ** (-36):
            break
        if Ha > 0:
            lo, f_lo = a, Ha
            if side == -1:
                f_hi /= 2
            side = -1
        else:
            hi, f_hi = a, Ha
            if side == 1:
                f_lo /= 2
            side = 1
        if abs(Ha) < abs(H) * mpf(10) ** (-mp.dps + 3):
            break
    return S + a, ya, y_max


def asymptote_S_c(delta):
    return (mpf(20) / 9) * log(delta) + (mpf(2) / 3) * log(mpf(27) / 8) + log(3) - pi / (3 * sqrt(3))


def richardson(a_h, a_h2, a_h4):
    """RK4 extrapolation from steps h, h/2, h/4; returns (value, change)."""
    r1 = a_h2 + (a_h2 - a_h) / 15
    r2 = a_h4 + (a_h4 - a_h2) / 15
    return r2, abs(r2 - r1)


def main():
    # 5.5 … 6.75 (issue 26): the range of the paper's viscosities, which `integrated` integrates live.
    exponents = [3, 4, 5, '5.5', 6, '6.25', '6.5', '6.75', 7, '7.5', 8, 9, 10, 11, 12]
    h = mpf('0.02')
    rows = []
    worst = 0
    for k in exponents:
        delta = mpf(10) ** mpf(str(k))
        results = [contact(delta, h / m) for m in (1, 2, 4)]
        S_c, dS = richardson(*[r[0] for r in results])
        y_c, _ = richardson(*[r[1] for r in results])
        y_max = results[2][2]
        s_c = S_c * delta ** (-mpf(2) / 3)
        eps_n = (mpf(2) / 3) * delta ** (-mpf(5) / 3) * y_c
        x_max = y_max * delta ** (-mpf(2) / 3)
        asym = asymptote_S_c(delta)
        worst = max(worst, dS / S_c)
        print(f"delta=1e{k}: S_c={nstr(S_c, 15)} (extrapolation change {nstr(dS / S_c, 2)}), "
              f"asymptote {nstr(asym, 15)}, diff {nstr(S_c - asym, 3)}, y_c={nstr(y_c, 12)}, "
              f"y_max={nstr(y_max, 12)}", flush=True)
        rows.append([nstr(delta, 17), nstr(s_c, 17), nstr(eps_n, 17), nstr(x_max, 12),
                     nstr(S_c, 17), nstr(asym, 17)])
    with open(OUT, 'w', newline='') as f:
        f.write('# force-zero contact for strong damping: tests/reference/strong_damping.py\n')
        w = csv.writer(f)
        w.writerow(['delta', 's_c', 'eps', 'x_max', 'S_c', 'asymptote_S_c'])
        w.writerows(rows)
    print(f"wrote {OUT}; worst relative extrapolation change of S_c: {nstr(worst, 2)}")
    return 0


if __name__ == '__main__':
    sys.exit(main())
