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
    return [(list(p.xyz), list(p.vxyz), list(recipe.spin(sim, k)), p.m, p.r) for k, p in enumerate(sim.particles)]


def surface_velocity(s1, s2, n, arms):
    """Eq. (2) at the contact point: g = (v_i - w_i x n l_i) - (v_j + w_j x n l_j), with the lever
    arms l = a d/(a_i + a_j) of a pair found overlapping at centre distance d (a at touching)."""
    return sub(sub(s1[1], scale(cross(s1[2], n), arms[0])), add(s2[1], scale(cross(s2[2], n), arms[1])))


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
    arms = [after[k][4] * norm(d) / (after[0][4] + after[1][4]) for k in (0, 1)]
    g0, g1 = surface_velocity(before[0], before[1], n, arms), surface_velocity(after[0], after[1], n, arms)
    gn0, gn1 = dot(g0, n), dot(g1, n)
    gt0, gt1 = sub(g0, scale(n, gn0)), sub(g1, scale(n, gn1))
    expected = rime_tangential(preset, abs(gn0), norm(gt0))
    check(f"{name}: eps_N = -g'_N/g_N against rime ({expected['eps_n']:.12f})",
          abs(-gn1 / gn0 - expected["eps_n"]), 1e-9)
    if norm(gt0) > 0:
        check(f"{name}: g'_T = eps_T g_T against rime (eps_T = {expected['eps_t']:.12f}, {expected['class']})",
              norm(sub(gt1, scale(gt0, expected["eps_t"]))) / norm(gt0), 1e-9)
    # Spins: the torque of the contact impulse at the contact point, I dw = (-l_i n) x m_i dv_i,
    # (+l_j n) x m_j dv_j, with I = 2/5 m a^2 of the grain.
    for k, arm in ((0, -arms[0]), (1, arms[1])):
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
    # Angular momentum about the origin, orbital plus spins: the impulse at the contact point keeps
    # it exactly (with the radii as arms it would change by ~ the overlap over the radius).
    def ang(st):
        return add(add(scale(cross(st[0][0], st[0][1]), MASS), scale(cross(st[1][0], st[1][1]), MASS)),
                   scale(add(st[0][2], st[1][2]), 0.4 * MASS * RADIUS**2))
    scale_l = MASS * RADIUS * norm(sub(before[0][1], before[1][1]))
    check(f"{name}: angular momentum (relative to m a |v1 - v2|)", norm(sub(ang(after), ang(before))) / scale_l, 1e-12)
    del spins


def momenta(sim, recipe):
    p, l, m, v3 = [0.0] * 3, [0.0] * 3, 0.0, 0.0
    for k, q in enumerate(sim.particles):
        p = add(p, scale(list(q.vxyz), q.m))
        l = add(l, add(scale(cross(list(q.xyz), list(q.vxyz)), q.m),
                       scale(list(recipe.spin(sim, k)), 0.4 * q.m * q.r**2)))
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
    values = [c for k, p in enumerate(sim.particles) for c in (*p.xyz, *p.vxyz, *recipe.spin(sim, k))]
    bad = sum(not math.isfinite(v) for v in values)
    spinning = sum(norm(list(w)) > 0 for w in recipe.spins(sim))
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
enum REB_STATUS { REB_STATUS_RUNNING = -1, REB_STATUS_SUCCESS = 0, REB_STATUS_GENERIC_ERROR = 1 };
struct reb_simulation { struct reb_particle *particles; size_t N; volatile enum REB_STATUS status;
    double minimum_collision_velocity;
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
                    "    double w[3];\n"
                    "    r->collision_resolve = rime_collision_resolve;\n"
                    "    if (rime_rebound_track_spins(r, NULL) || rime_rebound_spin(r, 0, w)) return 1;\n"
                    "    if (rime_rebound_error(r)) return 2;\n"
                    "    rime_rebound_forget(r);\n"
                    "    return rime_rebound_set_params(1e-4, 0.0, 0.0, 0.0);\n}\n")
        for source in (os.path.join(ICE, "rime_rebound.c"), os.path.join(d, "user.c")):
            subprocess.run(["cc", "-std=c99", "-Wall", "-Wextra", "-Werror", "-I", d, "-I", ICE, "-c",
                            source, "-o", os.path.join(d, "out.o")], check=True)
    print("ok: rime_rebound.c and a user of rime_rebound.h compile against rebound.h with -Werror")


# Issue 35: REBOUNDx beside the exported handler in either order. Each run is a child process: a
# crash (spins kept in `ap`, which REBOUNDx owns and frees, segfaulted) then fails the check.
REBOUNDX_RUN = r"""
import json, math, sys
import rebound, reboundx
sys.path.insert(0, sys.argv[1])
import rime_rebound

order, A = sys.argv[2], float(sys.argv[3])
radius, mass = 0.02, 900 * 4 / 3 * math.pi * 0.02**3
sim = rebound.Simulation()
sim.gravity, sim.integrator, sim.collision, sim.dt = "none", "leapfrog", "direct", 1e-3
# A heavy source at the origin; the pair approaches along y at y = 10 m, so the central force
# A r^0 = A (gammacentral 0) pushes both grains by exactly A along +y and leaves their relative
# velocity alone; a far grain spins and never collides.
sim.add(m=1e20, r=1e-3)
sim.add(m=mass, r=radius, y=10 - 0.021, vy=0.005)
sim.add(m=mass, r=radius, y=10 + 0.021, vy=-0.005)
sim.add(m=mass, r=radius, x=5.0, y=10.0)
spins = [(0.0, 0.0, 0.5), (0, 0, 0), (0, 0, 0), (1.0, 2.0, 3.0)]

def extras():
    rebx = reboundx.Extras(sim)
    force = rebx.load_force("central_force")
    rebx.add_force(force)
    sim.particles[0].params["Acentral"] = A
    sim.particles[0].params["gammacentral"] = 0.0
    return rebx

if order == "before":
    rebx = extras() if A else None
    lib = rime_rebound.attach(sim, spins=spins)
else:
    lib = rime_rebound.attach(sim, spins=spins)
    rebx = extras() if A else None
v_before = [sim.particles[k].vy for k in (1, 2)]
sim.integrate(1.0)
out = {
    "eps": (sim.particles[2].vy - sim.particles[1].vy) / (v_before[0] - v_before[1]),
    "com_vy": (sim.particles[1].vy + sim.particles[2].vy) / 2,
    "far_vy": sim.particles[3].vy,
    "spins": rime_rebound.spins(sim),
    "error": rime_rebound.error(sim),
    "param": sim.particles[0].params["Acentral"] if A else None,
}
rime_rebound.forget(sim)
del rebx, sim
import gc
gc.collect()
out["freed"] = True
print(json.dumps(out))
"""


def issue_35_reboundx_beside_the_handler_in_either_order():
    import os
    import tempfile
    want = json.loads(subprocess.run([RIME, "eps", "--preset", "ice", "--g", "0.01", "--format", "json"],
                                     check=True, capture_output=True, text=True).stdout)[0]["eps_n"]
    accel = 1e-3
    with tempfile.TemporaryDirectory() as d:
        script = os.path.join(d, "rebx.py")
        with open(script, "w") as f:
            f.write(REBOUNDX_RUN)

        def run(order, a):
            done = subprocess.run([sys.executable, script, ICE, order, repr(a)], capture_output=True, text=True)
            if done.returncode != 0:
                sys.exit(f"FAILED: REBOUNDx {order} attach: exit {done.returncode} (negative: a signal): "
                         f"{done.stderr[-2000:]}")
            return json.loads(done.stdout.strip().splitlines()[-1])

        for order in ("before", "after"):
            with_force, without = run(order, accel), run(order, 0.0)
            if not (with_force["freed"] and with_force["error"] is None and with_force["param"] == accel):
                sys.exit(f"FAILED: REBOUNDx {order} attach: {with_force}")
            print(f"ok: REBOUNDx created {order} attach: no crash, the simulation freed, its parameter kept")
            # rime's law: the pair's relative velocity is the one of `rime eps` at 1 cm/s.
            check(f"REBOUNDx {order}: eps_N against rime ({want:.12f}), relative",
                  abs(with_force["eps"] - want) / want, 1e-12)
            check(f"REBOUNDx {order}: eps_N without the force, relative", abs(without["eps"] - want) / want, 1e-12)
            # REBOUNDx's force: A t = 1e-3 m/s along +y after 1 s on the pair's centre of mass, and
            # on the far grain (5 m off the axis at 10 m) its y part, A t 2/sqrt(5).
            check(f"REBOUNDx {order}: the central force acts on the pair (A t), relative",
                  abs(with_force["com_vy"] - without["com_vy"] - accel) / accel, 1e-9)
            check(f"REBOUNDx {order}: the central force acts on the far grain (A t 2/sqrt 5), relative",
                  abs(with_force["far_vy"] - without["far_vy"] - accel * 2 / math.sqrt(5)) / accel, 1e-6)
            if with_force["spins"][3] != [1.0, 2.0, 3.0] or with_force["spins"][0] != [0.0, 0.0, 0.5]:
                sys.exit(f"FAILED: REBOUNDx {order}: spins not kept: {with_force['spins']}")
            print(f"ok: REBOUNDx {order}: the spins of the grains that did not collide are kept exactly")


def issue_35_minimum_collision_velocity_is_a_floor_on_the_separation_speed():
    """REBOUND's minimum_collision_velocity, as the Python handler reads it: a bounce separates at
    max(eps_N |g_N|, v_min); here eps_N |g_N| = 3.6 mm/s < v_min = 5 mm/s."""
    recipe = load(ICE)
    for v_min, want in ((5e-3, 5e-3), (1e-3, None)):
        sim, _ = pair(recipe, [-0.021, 0, 0], [0.005, 0, 0], [0, 0, 0], [0.021, 0, 0], [-0.005, 0, 0], [0, 0, 0])
        sim.minimum_collision_velocity = v_min
        sim.integrate(10.0)
        apart = sim.particles[1].vx - sim.particles[0].vx
        if want is None:
            want = json.loads(subprocess.run([RIME, "eps", "--preset", "ice", "--g", "0.01", "--format", "json"],
                                             check=True, capture_output=True, text=True).stdout)[0]["eps_n"] * 0.01
        check(f"minimum_collision_velocity {v_min} m/s: separation speed {want:.6e} m/s, relative",
              abs(apart - want) / want, 1e-12)


def issue_35_reattach_keeps_the_spins_and_a_reload_must_give_them():
    import os
    import tempfile
    recipe = load(ICE)
    sim, _ = pair(recipe, [-0.021, 0.012, 0.003], [0.004, -0.0015, 0.0005], [0.02, -0.01, 0.03],
                  [0.021, 0, 0], [-0.003, 0.001, 0.0], [-0.01, 0.04, 0.005])
    sim.integrate(10.0)
    w = recipe.spins(sim)
    recipe.attach(sim, damping_time=1e-4)
    if recipe.spins(sim) != w:
        sys.exit(f"FAILED: attaching again changed the spins: {w} -> {recipe.spins(sim)}")
    print("ok: attaching again (new parameters) keeps the spins")
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "sim.bin")
        sim.save_to_file(path)
        import warnings
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)  # "reset function pointers": attach does
            reloaded = rebound.Simulation(path)
        try:
            recipe.attach(reloaded)
        except ValueError as e:
            print(f"ok: a reloaded simulation without spins= is refused: {e}")
        else:
            sys.exit("FAILED: a reloaded simulation was attached with its spins silently at 0")
        recipe.attach(reloaded, spins=w)
        if recipe.spins(reloaded) != w:
            sys.exit("FAILED: spins= of a reloaded simulation not taken")
        recipe.forget(reloaded)
    recipe.attach(sim)  # back to the scene's values (one set per library)
    recipe.forget(sim)
    print("ok: spins= restores a reloaded simulation's spins")


def issue_35_spins_follow_a_merge_and_particles_added_later():
    """The spin table follows REBOUND's array: a merge of particles 0 and 1 removes 1 (the ones
    after it shift down), particles added after attach start at 0."""
    speed = 2e-5
    recipe = load(STICKY)
    sim, _ = pair(recipe, [-0.0201, 0.004, 0.001], [speed, 3e-6, -1e-6], [0.001, -0.002, 0.0005],
                  [0.0201, 0.0, 0.0], [-speed, 0.0, 1e-6], [-0.001, 0.0005, 0.002])
    pair_l = norm(momenta(sim, recipe)[1])
    sim.add(m=MASS, r=RADIUS, x=5.0)
    sim.add(m=MASS, r=RADIUS, x=10.0)
    if recipe.spins(sim)[2:] != [(0.0, 0.0, 0.0)] * 2:
        sys.exit(f"FAILED: particles added after attach: spins {recipe.spins(sim)[2:]}, expected 0")
    w = recipe.spins(sim)
    recipe.track_spins(sim, [w[0], w[1], (1.0, 2.0, 3.0), (4.0, 5.0, 6.0)])
    p0, l0, m0, v0 = momenta(sim, recipe)
    sim.integrate(50.0)
    if sim.N != 3 or recipe.spins(sim)[1:] != [(1.0, 2.0, 3.0), (4.0, 5.0, 6.0)]:
        sys.exit(f"FAILED: after the merge: N = {sim.N}, spins {recipe.spins(sim)}")
    print("ok: a merge removes p2's spin and shifts the ones after it with REBOUND's particles")
    p1, l1, m1, v1 = momenta(sim, recipe)
    check("merge with bystanders: angular momentum (orbital + spin), relative to the pair's",
          norm(sub(l1, l0)) / pair_l, 1e-9)


def issue_35_a_removal_behind_the_handlers_back_stops_with_a_message():
    recipe = load(ICE)
    sim, _ = pair(recipe, [-0.021, 0, 0], [0.005, 0, 0], [1, 0, 0], [0.021, 0, 0], [-0.005, 0, 0], [2, 0, 0])
    sim.add(m=MASS, r=RADIUS, x=-1.0)
    recipe.track_spins(sim, [(1, 0, 0), (2, 0, 0), (3, 0, 0)])
    sim.remove(2)
    try:
        sim.integrate(10.0)
    except rebound.GenericError:
        pass
    else:
        sys.exit("FAILED: a removal outside the handler did not stop the integration")
    message = recipe.error(sim) or ""
    if not message.startswith("spins: the simulation has 2 particles, the spin table 3"):
        sys.exit(f"FAILED: the stop's message: {message!r}")
    print(f"ok: a removal outside the handler stops the integration: {message}")
    recipe.track_spins(sim, [(1, 0, 0), (2, 0, 0)])
    if recipe.error(sim) is not None or recipe.spin(sim, 1) != (2.0, 0.0, 0.0):
        sys.exit("FAILED: tracking the spins again did not clear the stop")
    print("ok: tracking the spins again clears the stop")


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
issue_35_reboundx_beside_the_handler_in_either_order()
issue_35_minimum_collision_velocity_is_a_floor_on_the_separation_speed()
issue_35_reattach_keeps_the_spins_and_a_reload_must_give_them()
issue_35_spins_follow_a_merge_and_particles_added_later()
issue_35_a_removal_behind_the_handlers_back_stops_with_a_message()
