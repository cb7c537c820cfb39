"""Checks rime's exported REBOUND handler inside REBOUND itself (issue 14).

Usage: check.py RIME_BINARY EXPORT_DIR_ICE EXPORT_DIR_STICKY
Expected values come from the `rime` CLI at Precise (the core); REBOUND's integrator moves the
grains and applies the handler. Prints one line per check; exits non-zero on the first failure.
"""
import json
import math
import random
import subprocess
import sys

import rebound

RIME, ICE, STICKY = sys.argv[1], sys.argv[2], sys.argv[3]
DENSITY, RADIUS = 900.0, 0.02  # the presets' grains
MASS = DENSITY * 4.0 / 3.0 * math.pi * RADIUS**3


def load(directory):
    sys.path.insert(0, directory)
    import rime_rebound
    sys.path.pop(0)
    del sys.modules["rime_rebound"]
    return rime_rebound


def rime_tangential(preset, g_n, g_t):
    out = subprocess.run([RIME, "tangential", "--preset", preset, "--gn", repr(g_n), "--gt",
                          repr(g_t), "--accuracy", "precise", "--format", "json"],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)[0]


def sub(a, b): return [x - y for x, y in zip(a, b)]
def add(a, b): return [x + y for x, y in zip(a, b)]
def scale(a, s): return [x * s for x in a]
def dot(a, b): return sum(x * y for x, y in zip(a, b))
def norm(a): return math.sqrt(dot(a, a))
def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def check(name, value, limit):
    ok = value <= limit
    print(f"{'ok' if ok else 'FAILED'}: {name}: {value:.3e} (limit {limit:.0e})")
    if not ok:
        sys.exit(1)


def pair(recipe, x1, v1, w1, x2, v2, w2):
    sim = rebound.Simulation()
    sim.gravity = "none"
    sim.integrator = "leapfrog"
    sim.collision = "direct"
    sim.dt = 1e-3
    sim.add(m=MASS, r=RADIUS, x=x1[0], y=x1[1], z=x1[2], vx=v1[0], vy=v1[1], vz=v1[2])
    sim.add(m=MASS, r=RADIUS, x=x2[0], y=x2[1], z=x2[2], vx=v2[0], vy=v2[1], vz=v2[2])
    recipe.attach(sim)
    spins = recipe.track_spins(sim, [w1, w2])
    return sim, spins


def state(sim, recipe):
    return [(list(p.xyz), list(p.vxyz), list(recipe.spin(p)), p.m, p.r) for p in sim.particles]


def surface_velocity(s1, s2, n):
    """Eq. (2): g = (v_i - w_i x n a_i) - (v_j + w_j x n a_j)."""
    return sub(sub(s1[1], scale(cross(s1[2], n), s1[4])), add(s2[1], scale(cross(s2[2], n), s2[4])))


def bounce(name, preset, directory, x1, v1, w1, x2, v2, w2):
    recipe = load(directory)
    sim, spins = pair(recipe, x1, v1, w1, x2, v2, w2)
    before = state(sim, recipe)
    for _ in range(100000):
        sim.steps(1)
        after = state(sim, recipe)
        if after[0][1] != before[0][1]:
            break
        before = after
    else:
        sys.exit(f"FAILED: {name}: no collision")
    # REBOUND resolves at the end of the step: the normal is that of the positions there.
    d = sub(after[0][0], after[1][0])
    n = scale(d, 1.0 / norm(d))
    g0, g1 = surface_velocity(before[0], before[1], n), surface_velocity(after[0], after[1], n)
    gn0, gn1 = dot(g0, n), dot(g1, n)
    gt0, gt1 = sub(g0, scale(n, gn0)), sub(g1, scale(n, gn1))
    expected = rime_tangential(preset, abs(gn0), norm(gt0))
    check(f"{name}: eps_N = -g'_N/g_N against rime ({expected['eps_n']:.12f})",
          abs(-gn1 / gn0 - expected["eps_n"]), 1e-9)
    if norm(gt0) > 0:
        check(f"{name}: g'_T = eps_T g_T against rime (eps_T = {expected['eps_t']:.12f}, {expected['class']})",
              norm(sub(gt1, scale(gt0, expected["eps_t"]))) / norm(gt0), 1e-9)
    # Spins: the torque of the contact impulse, I dw = (-a_i n) x m_i dv_i, (+a_j n) x m_j dv_j.
    for k, arm in ((0, -RADIUS), (1, RADIUS)):
        inertia = 0.4 * MASS * RADIUS**2
        dv = sub(after[k][1], before[k][1])
        want = add(before[k][2], scale(cross(scale(n, arm), scale(dv, MASS)), 1.0 / inertia))
        change = norm(sub(want, before[k][2]))
        if change > 0:
            check(f"{name}: spin of grain {k + 1} (|dw| = {change:.3e} rad/s)",
                  norm(sub(after[k][2], want)) / change, 1e-9)
    p0 = add(scale(before[0][1], MASS), scale(before[1][1], MASS))
    p1 = add(scale(after[0][1], MASS), scale(after[1][1], MASS))
    check(f"{name}: momentum (relative to m |v1 - v2|)",
          norm(sub(p1, p0)) / (MASS * norm(sub(before[0][1], before[1][1]))), 1e-14)
    del spins


def momenta(sim, recipe):
    p, l, m, v3 = [0.0] * 3, [0.0] * 3, 0.0, 0.0
    for q in sim.particles:
        p = add(p, scale(list(q.vxyz), q.m))
        l = add(l, add(scale(cross(list(q.xyz), list(q.vxyz)), q.m),
                       scale(list(recipe.spin(q)), 0.4 * q.m * q.r**2)))
        m += q.m
        v3 += q.r**3
    return p, l, m, v3


def sticky():
    speed = 2e-5
    status = json.loads(subprocess.run([RIME, "eps", "--preset", "ice-sticky", "--g", repr(speed),
                                        "--format", "json"], check=True, capture_output=True,
                                       text=True).stdout)[0]["status"]
    if status != "stuck_by_adhesion":
        sys.exit(f"FAILED: sticky pair: rime says {status} at {speed} m/s")
    recipe = load(STICKY)
    sim, spins = pair(recipe, [-0.0201, 0.004, 0.001], [speed, 3e-6, -1e-6], [0.001, -0.002, 0.0005],
                      [0.0201, 0.0, 0.0], [-speed, 0.0, 1e-6], [-0.001, 0.0005, 0.002])
    p0, l0, m0, v0 = momenta(sim, recipe)
    sim.integrate(50.0)
    if sim.N != 1:
        sys.exit(f"FAILED: sticky pair: {sim.N} particles after the collision, expected 1 (merged)")
    p1, l1, m1, v1 = momenta(sim, recipe)
    print(f"ok: sticky pair ({status} at {speed} m/s) merged into one grain")
    check("sticky pair: mass", abs(m1 - m0) / m0, 1e-15)
    check("sticky pair: volume", abs(v1 - v0) / v0, 1e-14)
    check("sticky pair: momentum", norm(sub(p1, p0)) / norm(p0), 1e-12)
    check("sticky pair: angular momentum (orbital + spin)", norm(sub(l1, l0)) / norm(l0), 1e-9)
    del spins


def ring():
    recipe = load(ICE)
    random.seed(14)
    omega = 0.00013143527  # Saturn's A ring [1/s]
    sim = rebound.Simulation()
    sim.OMEGA = omega
    sim.dt = 1e-3 * 2 * math.pi / omega
    box = 20.0
    sim.root_size = box
    sim.N_ghost_x, sim.N_ghost_y = 2, 2
    sim.integrator, sim.boundary, sim.gravity, sim.collision = "sei", "shear", "none", "tree"
    placed = []
    while len(placed) < 36:
        x = [random.uniform(-box / 2, box / 2), random.uniform(-box / 2, box / 2), random.gauss(0, 1)]
        if all(norm(sub(x, q)) > 2.2 for q in placed):
            placed.append(x)
            sim.add(m=DENSITY * 4 / 3 * math.pi, r=1.0, x=x[0], y=x[1], z=x[2],
                    vx=random.gauss(0, 2e-3), vy=-1.5 * x[0] * omega + random.gauss(0, 2e-3),
                    vz=random.gauss(0, 2e-3))
    recipe.attach(sim)
    spins = recipe.track_spins(sim)
    sim.integrate(3 * 2 * math.pi / omega)
    values = [c for p in sim.particles for c in (*p.xyz, *p.vxyz, *recipe.spin(p))]
    bad = sum(not math.isfinite(v) for v in values)
    spinning = sum(norm(list(recipe.spin(p))) > 0 for p in sim.particles)
    # Spins start at 0: a spinning grain went through rime's handler.
    print(f"ring patch: {sim.N} particles, 3 orbits, {spinning} grains spun up by collisions")
    if bad or sim.N != 36 or spinning == 0:
        sys.exit(f"FAILED: ring patch: {bad} non-finite values, N = {sim.N}")
    print("ok: ring patch runs without NaN")
    del spins


def runtime_params():
    """rime_rebound_set_params (the recipe's attach(..., damping_time=)) reaches the handler."""
    recipe = load(ICE)
    sim = rebound.Simulation()
    sim.gravity, sim.integrator, sim.collision, sim.dt = "none", "leapfrog", "direct", 1e-3
    sim.add(m=MASS, r=RADIUS, x=-0.021, vx=0.005)
    sim.add(m=MASS, r=RADIUS, x=0.021, vx=-0.005)
    recipe.attach(sim, damping_time=2e-4)
    sim.integrate(10.0)
    eps = (sim.particles[1].vx - sim.particles[0].vx) / 0.01
    want = json.loads(subprocess.run([RIME, "eps", "--preset", "ice", "--set", "bulk.damping.time=2e-4",
                                      "--g", "0.01", "--format", "json"], check=True, capture_output=True,
                                     text=True).stdout)[0]["eps_n"]
    check(f"runtime A = 2e-4 s reaches the handler: eps_N against rime ({want:.12f})", abs(eps - want), 1e-9)
    try:
        recipe.attach(sim, layer_viscosity=-1.0)
    except ValueError as e:
        print(f"ok: a bad runtime parameter is refused: {e}")
    else:
        sys.exit("FAILED: layer_viscosity=-1 was accepted")
    recipe.attach(sim)  # back to the scene's values for the other checks (one set per library)


# The declarations of REBOUND 5.2.2's rebound.h that rime_rebound.c and rime_rebound.h use (the pip
# wheel has no header): the handler must match REBOUND's function-pointer type exactly (GCC 14 makes
# a mismatch an error).
REBOUND_H_DECLARATIONS = """
#ifndef _MAIN_H
#define _MAIN_H
#include <stddef.h>
struct reb_simulation;
struct reb_vec6d { double x, y, z, vx, vy, vz; };
struct reb_particle { double x, y, z, vx, vy, vz, ax, ay, az, m, r; const char *name; void *ap;
                      struct reb_simulation *sim; };
struct reb_collision { size_t p1; size_t p2; struct reb_vec6d gb; size_t ri; };
enum REB_COLLISION_RESOLVE_OUTCOME {
    REB_COLLISION_RESOLVE_OUTCOME_REMOVE_NONE = 0, REB_COLLISION_RESOLVE_OUTCOME_REMOVE_P1 = 1,
    REB_COLLISION_RESOLVE_OUTCOME_REMOVE_P2 = 2, REB_COLLISION_RESOLVE_OUTCOME_REMOVE_BOTH = 3 };
struct reb_simulation { struct reb_particle *particles;
    enum REB_COLLISION_RESOLVE_OUTCOME (*collision_resolve)(struct reb_simulation *const r,
                                                             struct reb_collision); };
#endif
"""


def c_route():
    """The C route: rime_rebound.c and a user's file compile against rebound.h with -Werror."""
    import os
    import tempfile
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "rebound.h"), "w") as f:
            f.write(REBOUND_H_DECLARATIONS)
        with open(os.path.join(d, "user.c"), "w") as f:
            f.write('#include "rebound.h"\n#include "rime_rebound.h"\n'
                    "int hook(struct reb_simulation *r) {\n"
                    "    r->collision_resolve = rime_collision_resolve;\n"
                    "    return rime_rebound_set_params(1e-4, 0.0, 0.0, 0.0);\n}\n")
        for source in (os.path.join(ICE, "rime_rebound.c"), os.path.join(d, "user.c")):
            subprocess.run(["cc", "-std=c99", "-Wall", "-Wextra", "-Werror", "-I", d, "-I", ICE, "-c",
                            source, "-o", os.path.join(d, "out.o")], check=True)
    print("ok: rime_rebound.c and a user of rime_rebound.h compile against rebound.h with -Werror")


print(f"rebound {rebound.__version__}")
c_route()
runtime_params()
bounce("head-on", "ice", ICE, [-0.021, 0, 0], [0.005, 0, 0], [0, 0, 0], [0.021, 0, 0], [-0.005, 0, 0],
       [0, 0, 0])
# g_T < (mu/kappa) g_N: the rolling branch, eps_T = -eps_N(g_T) (Eq. (26), top).
bounce("oblique, rolling", "ice", ICE, [-0.021, 0.012, 0.003], [0.004, -0.0015, 0.0005],
       [0.02, -0.01, 0.03], [0.021, 0, 0], [-0.003, 0.001, 0.0], [-0.01, 0.04, 0.005])
# g_T ~ 5 g_N: the sliding branch with a positive radicand of Eq. (23).
bounce("oblique, sliding", "ice", ICE, [-0.04, 0.0, 0.0], [0.002, 0.02, 0.004],
       [0.1, -0.2, 0.3], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [-0.1, 0.2, 0.05])
sticky()
ring()
