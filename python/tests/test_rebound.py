"""rime_grains.rebound.attach inside REBOUND 5.2.2 (issue 23).

REBOUND's integrator moves the grains and calls the native handler. Expected values come from the
`rime` command line (`rime eps`, `rime tangential`: the core through its own parser), from
conservation laws (momentum, angular momentum orbital + spin, mass, volume), from Eq. (2) (the
spin change of an impulse at the contact point) and from unit conversion by hand.
"""
import ctypes
import math

import numpy as np
import pytest
import rebound

import rime_grains as rime
from conftest import cli

DENSITY, RADIUS = 900.0, 0.02
MASS = DENSITY * 4.0 / 3.0 * math.pi * RADIUS**3


def pair_sim(x1, v1, x2, v2, mass=MASS, radius=RADIUS, dt=1e-3):
    sim = rebound.Simulation()
    sim.gravity = "none"
    sim.integrator = "leapfrog"
    sim.collision = "direct"
    sim.dt = dt
    for x, v in ((x1, v1), (x2, v2)):
        sim.add(m=mass, r=radius, x=x[0], y=x[1], z=x[2], vx=v[0], vy=v[1], vz=v[2])
    return sim


def state(sim, att):
    w = att.spins
    return [(np.array(p.xyz), np.array(p.vxyz), w[k].copy(), p.m, p.r) for k, p in enumerate(sim.particles)]


def arms(s1, s2):
    """The lever arms: REBOUND finds the pair overlapping, and the contact point splits the line
    of centres (length d) in the ratio of the radii, a_i d/(a_i + a_j) (the radii when touching)."""
    d = np.linalg.norm(s1[0] - s2[0])
    return s1[4] * d / (s1[4] + s2[4]), s2[4] * d / (s1[4] + s2[4])


def surface_velocity(s1, s2, n, lever):
    """Eq. (2): g = (v_i − ω_i × n a_i) − (v_j + ω_j × n a_j), with the lever arms a_i, a_j."""
    return (s1[1] - np.cross(s1[2], n) * lever[0]) - (s2[1] + np.cross(s2[2], n) * lever[1])


def step_to_collision(sim, att):
    before = state(sim, att)
    for _ in range(200000):
        sim.steps(1)
        after = state(sim, att)
        if sim.N != len(before) or not np.array_equal(after[0][1], before[0][1]):
            return before, after
        before = after
    pytest.fail("no collision")


def momenta(sim, att):
    p, l = np.zeros(3), np.zeros(3)
    w = att.spins
    for k, q in enumerate(sim.particles):
        v, x = np.array(q.vxyz), np.array(q.xyz)
        p += q.m * v
        l += q.m * np.cross(x, v) + 0.4 * q.m * q.r**2 * w[k]
    return p, l


CASES = {
    "head-on": ([-0.021, 0, 0], [0.005, 0, 0], [0, 0, 0], [0.021, 0, 0], [-0.005, 0, 0], [0, 0, 0]),
    # g_T < (μ/κ) g_N: the rolling branch, ε_T = −ε_N(g_T) (Eq. (26), top).
    "oblique, rolling": ([-0.021, 0.012, 0.003], [0.004, -0.0015, 0.0005], [0.02, -0.01, 0.03],
                         [0.021, 0, 0], [-0.003, 0.001, 0.0], [-0.01, 0.04, 0.005]),
    # g_T ~ 5 g_N: the sliding branch.
    "oblique, sliding": ([-0.04, 0.0, 0.0], [0.002, 0.02, 0.004], [0.1, -0.2, 0.3],
                         [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [-0.1, 0.2, 0.05]),
    # Grazing: the centres pass at 0.995 of the contact distance, g_T ≫ g_N.
    "grazing": ([-0.05, 0.0398, 0.0], [0.03, 0.0, 0.0], [0, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 0]),
}


@pytest.mark.parametrize("name", list(CASES))
def test_two_body_hits_reproduce_rime(name):
    x1, v1, w1, x2, v2, w2 = CASES[name]
    sim = pair_sim(x1, v1, x2, v2)
    att = rime.rebound.attach(sim, rime.Scene.preset("ice"), length_unit=1, time_unit=1, mass_unit=1,
                              spins=np.array([w1, w2], dtype=float))
    p0, l0 = momenta(sim, att)
    before, after = step_to_collision(sim, att)
    # REBOUND resolves at the end of the step: the normal is that of the positions there.
    d = after[0][0] - after[1][0]
    n = d / np.linalg.norm(d)
    lever = arms(after[0], after[1])
    g0, g1 = surface_velocity(before[0], before[1], n, lever), surface_velocity(after[0], after[1], n, lever)
    gn0, gn1 = g0 @ n, g1 @ n
    gt0, gt1 = g0 - gn0 * n, g1 - gn1 * n
    want = cli("tangential", "--preset", "ice", "--gn", repr(float(abs(gn0))), "--gt",
               repr(float(np.linalg.norm(gt0))), "--accuracy", "precise")[0]
    assert -gn1 / gn0 == pytest.approx(want["eps_n"], rel=1e-12)
    if np.linalg.norm(gt0) > 0:
        assert np.linalg.norm(gt1 - want["eps_t"] * gt0) / np.linalg.norm(gt0) < 1e-12
    # The spins: the torque of the contact impulse at the contact point, I Δω = (∓a n) × m Δv.
    inertia = 0.4 * MASS * RADIUS**2
    for k, arm in ((0, -lever[0]), (1, lever[1])):
        dv = after[k][1] - before[k][1]
        want_w = before[k][2] + np.cross(arm * n, MASS * dv) / inertia
        change = np.linalg.norm(want_w - before[k][2])
        assert np.linalg.norm(after[k][2] - want_w) <= 1e-12 * max(change, 1e-300) + 1e-300
    p1, l1 = momenta(sim, att)
    assert np.linalg.norm(p1 - p0) <= 1e-15 * MASS * np.linalg.norm(np.subtract(v1, v2))
    assert np.linalg.norm(l1 - l0) <= 1e-12 * max(np.linalg.norm(l0), MASS * RADIUS * np.linalg.norm(v1))
    assert att.counts()["bounces"] == 1 and att.error is None


def head_on_eps(scene, mass, units=(1.0, 1.0, 1.0), speed=0.005, density="particles", radius=RADIUS,
                omega=None):
    L, T, M = (rime.rebound.orbit(omega) if u == "orbit" else rime.rebound.unit(f, u)
               for f, u in zip(("length_unit", "time_unit", "mass_unit"), units))
    sim = pair_sim([-(radius + 1e-3) / L, 0, 0], [speed * T / L, 0, 0],
                   [(radius + 1e-3) / L, 0, 0], [-speed * T / L, 0, 0],
                   mass=mass / M, radius=radius / L, dt=1e-3 / T)
    att = rime.rebound.attach(sim, scene, length_unit=units[0], time_unit=units[1], mass_unit=units[2],
                              density=density, omega=omega)
    before, after = step_to_collision(sim, att)
    return (after[1][1][0] - after[0][1][0]) / (before[0][1][0] - before[1][1][0]), sim, att


def test_units_cm_minutes_grams_give_si_results():
    ice = rime.Scene.preset("ice")
    want = cli("eps", "--preset", "ice", "--g", "0.01")[0]["eps_n"]
    eps_si, sim_si, _ = head_on_eps(ice, MASS)
    eps_cgs, sim_cgs, _ = head_on_eps(ice, MASS, units=(0.01, 60.0, 1e-3))
    eps_str, _, _ = head_on_eps(ice, MASS, units=("cm", "min", "g"))
    assert eps_si == pytest.approx(want, rel=1e-12)
    assert eps_cgs == pytest.approx(want, rel=1e-12)
    assert eps_str == eps_cgs
    # The velocities after, converted back to SI by hand, are the SI run's.
    for p_si, p_cgs in zip(sim_si.particles, sim_cgs.particles):
        assert p_cgs.vx * 0.01 / 60.0 == pytest.approx(p_si.vx, rel=1e-12)


def test_density_400_gives_the_density_400_eps():
    ice = rime.Scene.preset("ice")
    mass_400 = 400.0 * 4.0 / 3.0 * math.pi * RADIUS**3
    want_400 = cli("eps", "--preset", "ice", "--set", "grains.density=400", "--g", "0.01")[0]["eps_n"]
    want_900 = cli("eps", "--preset", "ice", "--g", "0.01")[0]["eps_n"]
    assert abs(want_400 / want_900 - 1) > 1e-2  # the test can tell the two apart
    eps, _, _ = head_on_eps(ice, mass_400)
    assert eps == pytest.approx(want_400, rel=1e-12)
    # density="scene" keeps the scene's 900 for ε_N (the impulses still use the masses), and says so.
    eps_scene, _, att = head_on_eps(ice, mass_400, density="scene")
    assert eps_scene == pytest.approx(want_900, rel=1e-12)
    assert "the scene's density 900 kg/m³ (impulses use the particles' masses)" in repr(att)


def test_particle_radii_are_used_not_the_scenes():
    ice = rime.Scene.preset("ice")  # grains.radius_* = 2 cm
    r = 0.5
    mass = 900.0 * 4.0 / 3.0 * math.pi * r**3
    want = cli("eps", "--preset", "ice", "--set", "grains.radius_1=0.5", "--set", "grains.radius_2=0.5",
               "--g", "0.01")[0]["eps_n"]
    eps, _, att = head_on_eps(ice, mass, radius=r)
    assert eps == pytest.approx(want, rel=1e-12)
    assert att.cached_pairs == 1


def sticky_pair(sticking, g_n=2e-5, g_t=0.0, **kw):
    """A slow ice-sticky collision (stuck by adhesion) with spins, at tangential speed g_t."""
    # Nearly touching (a 2e-8 m gap, the centres offset by (3, 1) mm in y, z), g_T perpendicular to
    # the line of centres: contact after ~1 ms, before the tangential motion opens the gap.
    x = math.sqrt(0.04000002**2 - 0.003**2 - 0.001**2) / 2
    t = np.array([0.0, 1.0, -3.0]) / math.sqrt(10.0) * g_t / 2
    sim = pair_sim([-x, 0.003, 0.001], [g_n / 2 + t[0], t[1], t[2]], [x, 0.0, 0.0], [-g_n / 2 - t[0], -t[1], -t[2]])
    spins = np.array([[0.001, -0.002, 0.0005], [-0.001, 0.0005, 0.002]])
    att = rime.rebound.attach(sim, rime.Scene.preset("ice-sticky"), length_unit=1, time_unit=1,
                              mass_unit=1, sticking=sticking, spins=spins, **kw)
    return sim, att


def test_merge_keeps_mass_volume_momentum_angular_momentum():
    status = cli("eps", "--preset", "ice-sticky", "--g", "2e-5")[0]["status"]
    assert status == "stuck_by_adhesion"
    sim, att = sticky_pair("merge", g_t=3e-6)
    m0 = sum(p.m for p in sim.particles)
    v0 = sum(p.r**3 for p in sim.particles)
    p0, l0 = momenta(sim, att)
    sim.integrate(50.0)
    assert sim.N == 1 and att.counts()["merges"] == 1
    p1, l1 = momenta(sim, att)
    assert sim.particles[0].m == pytest.approx(m0, rel=1e-15)
    assert sim.particles[0].r ** 3 == pytest.approx(v0, rel=1e-14)
    assert np.linalg.norm(p1 - p0) <= 1e-15 * np.linalg.norm(p0) + 1e-25
    assert np.linalg.norm(l1 - l0) <= 1e-12 * np.linalg.norm(l0)


def test_merge_across_a_periodic_boundary_uses_the_ghost_shift():
    """A sticky pair meets across the edge of a periodic box (REBOUND passes the ghost-box shift):
    one grain at the pair's centre of mass, with their mass, volume and momentum."""
    box = 1.0
    sim = rebound.Simulation()
    sim.gravity, sim.integrator, sim.collision, sim.boundary = "none", "leapfrog", "direct", "periodic"
    sim.root_size = box
    sim.N_ghost_x = 1
    sim.dt = 1e-3
    gap = 2e-8
    edge = box / 2 - RADIUS - gap / 2
    sim.add(m=MASS, r=RADIUS, x=edge, vx=1e-5, vy=3e-6)
    sim.add(m=MASS, r=RADIUS, x=-edge, vx=-1e-5)
    att = rime.rebound.attach(sim, rime.Scene.preset("ice-sticky"), length_unit=1, time_unit=1, mass_unit=1)
    p0, v0 = np.array(sim.particles[0].vxyz) + np.array(sim.particles[1].vxyz), 2 * RADIUS**3
    sim.integrate(0.05)
    assert sim.N == 1 and att.counts()["merges"] == 1, att.counts()
    q = sim.particles[0]
    assert q.m == pytest.approx(2 * MASS, rel=1e-15) and q.r**3 == pytest.approx(v0, rel=1e-14)
    assert np.linalg.norm(np.array(q.vxyz) * 2 - p0) <= 1e-15 * np.linalg.norm(p0) + 1e-22
    assert abs(abs(q.x) - box / 2) < 1e-3  # on the edge, not in the middle of the box


def test_stay_keeps_both_with_the_cores_tangential_outcome():
    g_n, g_t = 2e-5, 0.01
    sim, att = sticky_pair("stay", g_n=g_n, g_t=g_t)
    p0, l0 = momenta(sim, att)
    before, after = step_to_collision(sim, att)
    assert sim.N == 2 and att.counts()["stays"] == 1 and att.counts()["bounces"] == 0
    d = after[0][0] - after[1][0]
    n = d / np.linalg.norm(d)
    lever = arms(after[0], after[1])
    g0, g1 = surface_velocity(before[0], before[1], n, lever), surface_velocity(after[0], after[1], n, lever)
    gn0 = g0 @ n
    gt0, gt1 = g0 - gn0 * n, g1 - (g1 @ n) * n
    want = cli("tangential", "--preset", "ice-sticky", "--gn", repr(float(abs(gn0))), "--gt",
               repr(float(np.linalg.norm(gt0))))[0]
    assert want["eps_n"] == 0.0
    assert abs(g1 @ n) <= 1e-12 * abs(gn0)  # ε_N = 0: no normal rebound
    assert np.linalg.norm(gt1 - want["eps_t"] * gt0) <= 1e-12 * np.linalg.norm(gt0)
    p1, l1 = momenta(sim, att)
    assert np.linalg.norm(p1 - p0) <= 1e-15 * np.linalg.norm(p0)
    assert np.linalg.norm(l1 - l0) <= 1e-12 * np.linalg.norm(l0)


def test_stay_honours_minimum_collision_velocity():
    sim, att = sticky_pair("stay")
    sim.minimum_collision_velocity = 1e-6
    before, after = step_to_collision(sim, att)
    d = after[0][0] - after[1][0]
    n = d / np.linalg.norm(d)
    g1 = surface_velocity(after[0], after[1], n, arms(after[0], after[1]))
    assert g1 @ n == pytest.approx(1e-6, rel=1e-9)


def test_merge_if_slow_merges_only_below_the_sticking_speed():
    scene = rime.Scene.preset("ice-sticky")
    v_stick = rime.thresholds(scene)["stick"]  # the pair's radii are the scene's (2 cm)
    slow_sim, slow = sticky_pair("merge_if_slow", g_t=0.5 * v_stick)
    slow_sim.integrate(50.0)
    assert slow_sim.N == 1 and slow.counts()["merges"] == 1
    fast_sim, fast = sticky_pair("merge_if_slow", g_t=20 * v_stick)
    fast_sim.integrate(50.0)
    assert fast_sim.N == 2 and fast.counts()["stays"] >= 1 and fast.counts()["merges"] == 0


def ring(att_kwargs=None, n=36, orbits=1.0, seed=14, collision="tree"):
    rng = np.random.default_rng(seed)
    omega = 0.00013143527  # Saturn's A ring [1/s]
    sim = rebound.Simulation()
    sim.OMEGA = omega
    sim.dt = 1e-3 * 2 * math.pi / omega
    box = 20.0
    sim.root_size = box
    sim.N_ghost_x, sim.N_ghost_y = 2, 2
    sim.integrator, sim.boundary, sim.gravity, sim.collision = "sei", "shear", "none", collision
    placed = []
    while len(placed) < n:
        x = [rng.uniform(-box / 2, box / 2), rng.uniform(-box / 2, box / 2), rng.normal(0, 1)]
        if all(np.linalg.norm(np.subtract(x, q)) > 2.2 for q in placed):
            placed.append(x)
            sim.add(m=400 * 4 / 3 * math.pi, r=1.0, x=x[0], y=x[1], z=x[2], vx=rng.normal(0, 2e-3),
                    vy=-1.5 * x[0] * omega + rng.normal(0, 2e-3), vz=rng.normal(0, 2e-3))
    att = rime.rebound.attach(sim, rime.Scene.preset("ice"), length_unit=1, time_unit=1, mass_unit=1,
                              **(att_kwargs or {}))
    sim.integrate(orbits * 2 * math.pi / omega)
    return sim, att


def test_reattaching_keeps_the_spins():
    sim = pair_sim([-0.021, 0, 0], [0.005, 0, 0], [0.021, 0, 0], [-0.005, 0, 0])
    spins = np.array([[1.0, 2.0, 3.0], [-1.0, 0.5, 0.25]])
    first = rime.rebound.attach(sim, rime.Scene(), length_unit=1, time_unit=1, mass_unit=1, spins=spins)
    second = rime.rebound.attach(sim, rime.Scene.preset("ice-frost"), length_unit=1, time_unit=1, mass_unit=1)
    assert np.array_equal(second.spins, spins) and np.array_equal(first.spins, spins)


def test_particles_added_later_get_a_spin_from_track_spins():
    sim = pair_sim([-0.021, 0, 0], [0.005, 0, 0], [0.021, 0, 0], [-0.005, 0, 0])
    spins = np.array([[1.0, 2.0, 3.0], [-1.0, 0.5, 0.25]])
    att = rime.rebound.attach(sim, rime.Scene(), length_unit=1, time_unit=1, mass_unit=1, spins=spins)
    sim.add(m=MASS, r=RADIUS, x=1.0)
    assert np.array_equal(att.spins, [*spins, [0, 0, 0]])
    att.track_spins([[1.0, 2.0, 3.0], [-1.0, 0.5, 0.25], [7.0, 8.0, 9.0]])
    assert np.array_equal(att.spins[2], [7, 8, 9]) and not sim.particles[2].ap  # ap is not used
    with pytest.raises(ValueError, match="^spins: expected shape"):
        att.track_spins(np.zeros((2, 3)))

def test_ring_patch_runs_and_spins_up():
    sim, att = ring()
    values = np.concatenate([np.array([(*p.xyz, *p.vxyz) for p in sim.particles]).ravel(), att.spins.ravel()])
    assert np.all(np.isfinite(values)) and sim.N == 36
    assert np.count_nonzero(np.linalg.norm(att.spins, axis=1)) > 0
    assert att.counts()["bounces"] > 0 and att.cached_pairs == 1 and att.error is None


def test_save_and_reload_keep_spins(tmp_path):
    sim, att = ring(orbits=0.5, collision="direct")
    spins = att.spins
    assert np.count_nonzero(spins) > 0
    path = str(tmp_path / "ring.bin")
    att.save(path)
    with pytest.warns(RuntimeWarning, match="reset function pointers"):
        loaded = rebound.Simulation(path)  # REBOUND's reminder: attach again
    restored = rime.rebound.attach(loaded, rime.Scene.preset("ice"), length_unit=1, time_unit=1,
                                   mass_unit=1, spins=rime.rebound.load_spins(path, loaded))
    assert np.array_equal(restored.spins, spins)
    # Both go on and stay identical: the reloaded run is the run.
    t = sim.t + 0.25 * 2 * math.pi / sim.OMEGA
    sim.integrate(t)
    loaded.integrate(t)
    assert np.array_equal(restored.spins, att.spins)
    assert np.array_equal([p.vxyz for p in loaded.particles], [p.vxyz for p in sim.particles])


def test_load_spins_refuses_a_mismatched_snapshot(tmp_path):
    sim, att = ring(orbits=0.05)
    path = str(tmp_path / "ring.bin")
    att.save(path)
    other = rebound.Simulation()
    other.add(m=1.0)
    with pytest.raises(ValueError, match="^filename"):
        rime.rebound.load_spins(path, other)


def test_collision_layout_matches_rebound_ctypes():
    size, offsets = rime._native.collision_layout()
    c = rebound.CollisionS
    assert (size, list(offsets)) == (ctypes.sizeof(c), [c.p1.offset, c.p2.offset, c.gb.offset, c.ri.offset])


def test_other_rebound_versions_are_refused(monkeypatch):
    monkeypatch.setattr(rebound, "__version__", "5.3.0")
    with pytest.raises(RuntimeError, match=r"supports rebound 5\.2\.2.*this is rebound 5\.3\.0"):
        rime.rebound.attach(rebound.Simulation(), rime.Scene(), length_unit=1, time_unit=1, mass_unit=1)


def test_issue_35_ap_set_by_someone_else_is_left_alone():
    sim = pair_sim([-0.021, 0, 0], [0.005, 0, 0], [0.021, 0, 0], [-0.005, 0, 0])
    dummy = (ctypes.c_double * 3)(1.0, 2.0, 3.0)
    sim.particles[0].ap = ctypes.addressof(dummy)
    att = rime.rebound.attach(sim, rime.Scene(), length_unit=1, time_unit=1, mass_unit=1)
    sim.integrate(1.0)
    assert att.counts()["bounces"] == 1 and sim.particles[0].ap == ctypes.addressof(dummy)
    assert list(dummy) == [1.0, 2.0, 3.0]
    sim.particles[0].ap = None


def test_a_speed_beyond_the_models_stops_the_integration_with_a_message():
    sim = pair_sim([-0.03, 0, 0], [2e6, 0, 0], [0.03, 0, 0], [-2e6, 0, 0], dt=1e-9)
    att = rime.rebound.attach(sim, rime.Scene(), length_unit=1, time_unit=1, mass_unit=1)
    with pytest.raises(rebound.GenericError):
        sim.integrate(1e-7)
    assert att.error.startswith("collision of particles ") and "g_N = 4e6 m/s" in att.error
    assert "impact speed must lie in (0, 1e6] m/s" in att.error


@pytest.mark.parametrize("kwargs,field", [
    (dict(length_unit=0), "length_unit"),
    (dict(time_unit="cm"), "time_unit"),
    (dict(mass_unit=float("nan")), "mass_unit"),
    (dict(density="water"), "density"),
    (dict(sticking="glue"), "sticking"),
    (dict(accuracy="best"), "accuracy"),
    (dict(spins=np.zeros((3, 3))), "spins"),
    # Issue 38: the counters' settings.
    (dict(speed_edges=[0.01]), "speed_edges"),
    (dict(speed_edges=[0.02, 0.01]), "speed_edges"),
    (dict(speed_edges=[-1.0, 1.0]), "speed_edges"),
    (dict(speed_edges=[[0.0, 1.0]]), "speed_edges"),
    (dict(speed_edges="fast"), "speed_edges"),
    (dict(overlap_depth=1.5), "overlap_depth"),
    (dict(overlap_depth=float("nan")), "overlap_depth"),
    (dict(overlap_depth="deep"), "overlap_depth"),
])
def test_attach_bad_input_names_the_field(kwargs, field):
    sim = pair_sim([-0.021, 0, 0], [0.005, 0, 0], [0.021, 0, 0], [-0.005, 0, 0])
    args = dict(length_unit=1, time_unit=1, mass_unit=1)
    args.update(kwargs)
    with pytest.raises(ValueError, match=f"^{field}"):
        rime.rebound.attach(sim, rime.Scene(), **args)


# Issue 35: REBOUNDx beside the handler in either order. Run in a child process: a crash (the
# segfault of spins kept in `ap`, which REBOUNDx frees) then fails the test instead of pytest.
REBOUNDX_RUN = r"""
import gc, json, math, sys
import numpy as np
import rebound, reboundx
import rime_grains as rime

order, A = sys.argv[1], float(sys.argv[2])
radius, mass = 0.02, 900 * 4 / 3 * math.pi * 0.02**3
sim = rebound.Simulation()
sim.gravity, sim.integrator, sim.collision, sim.dt = "none", "leapfrog", "direct", 1e-3
# A heavy source at the origin; the pair approaches along the y axis at y = 10 m, so the central
# force A r^0 = A (gammacentral 0) pushes both grains by exactly A along +y and leaves their
# relative velocity alone; a far grain spins and never collides.
sim.add(m=1e20, r=1e-3)
sim.add(m=mass, r=radius, y=10 - 0.021, vy=0.005)
sim.add(m=mass, r=radius, y=10 + 0.021, vy=-0.005)
sim.add(m=mass, r=radius, x=5.0, y=10.0)
spins = np.array([[0.0, 0.0, 0.5], [0, 0, 0], [0, 0, 0], [1.0, 2.0, 3.0]])

def extras():
    rebx = reboundx.Extras(sim)
    force = rebx.load_force("central_force")
    rebx.add_force(force)
    sim.particles[0].params["Acentral"] = A
    sim.particles[0].params["gammacentral"] = 0.0
    return rebx

if order == "before":
    rebx = extras() if A else None
    att = rime.rebound.attach(sim, rime.Scene.preset("ice"), length_unit=1, time_unit=1, mass_unit=1, spins=spins)
else:
    att = rime.rebound.attach(sim, rime.Scene.preset("ice"), length_unit=1, time_unit=1, mass_unit=1, spins=spins)
    rebx = extras() if A else None
v_before = [sim.particles[k].vy for k in (1, 2)]
sim.integrate(1.0)
out = {
    "eps": (sim.particles[2].vy - sim.particles[1].vy) / (v_before[0] - v_before[1]),
    "com_vy": (sim.particles[1].vy + sim.particles[2].vy) / 2,
    "far_vy": sim.particles[3].vy,
    "spins": att.spins.tolist(),
    "counts": att.counts(),
    "error": att.error,
    "param": sim.particles[0].params["Acentral"] if A else None,
}
del rebx, att, sim
gc.collect()
out["freed"] = True
print(json.dumps(out))
"""


@pytest.mark.parametrize("order", ["before", "after"])
def test_issue_35_reboundx_beside_the_handler_in_either_order(order, tmp_path):
    import os
    import subprocess
    import sys

    script = tmp_path / "rebx.py"
    script.write_text(REBOUNDX_RUN)
    accel = 1e-3

    def run(a):
        done = subprocess.run([sys.executable, str(script), order, repr(a)], capture_output=True,
                              text=True, env=os.environ.copy(), timeout=120)
        assert done.returncode == 0, f"exit {done.returncode} (a negative code is a signal): {done.stderr[-2000:]}"
        return __import__("json").loads(done.stdout.strip().splitlines()[-1])

    with_force, without = run(accel), run(0.0)
    assert with_force["freed"] and with_force["error"] is None and with_force["param"] == accel
    assert with_force["counts"]["bounces"] == 1
    # rime's law: the relative velocity is the one of `rime eps` at 1 cm/s (the force adds none).
    want = cli("eps", "--preset", "ice", "--g", "0.01")[0]["eps_n"]
    assert with_force["eps"] == pytest.approx(want, rel=1e-12)
    assert without["eps"] == pytest.approx(want, rel=1e-12)
    # REBOUNDx's force: A t = 1e-3 m/s along +y on every grain after 1 s (the pair's centre of
    # mass, the far grain up to the direction of its offset, 5 m at 10 m: cos = 2/√5).
    assert with_force["com_vy"] - without["com_vy"] == pytest.approx(accel * 1.0, rel=1e-9)
    assert with_force["far_vy"] - without["far_vy"] == pytest.approx(accel * 2 / math.sqrt(5), rel=1e-6)
    # Spins kept: the far grain's and the source's, untouched by a head-on hit.
    assert with_force["spins"][3] == [1.0, 2.0, 3.0] and with_force["spins"][0] == [0.0, 0.0, 0.5]


def test_issue_35_spins_follow_a_merge_and_particles_added_later():
    """The spin table follows REBOUND's array: a merge of particles 0 and 1 removes 1 (the ones
    after it shift down), a particle added later starts at 0."""
    sim, att = sticky_pair("merge", g_t=3e-6)
    sim.add(m=MASS, r=RADIUS, x=5.0)
    sim.add(m=MASS, r=RADIUS, x=10.0)
    w = att.spins
    assert np.array_equal(w[2:], np.zeros((2, 3)))
    att.track_spins([w[0], w[1], [1.0, 2.0, 3.0], [4.0, 5.0, 6.0]])
    p0, l0 = momenta(sim, att)
    sim.integrate(50.0)
    assert sim.N == 3 and att.counts()["merges"] == 1
    assert np.array_equal(att.spins[1:], [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]])
    p1, l1 = momenta(sim, att)
    assert np.linalg.norm(l1 - l0) <= 1e-12 * np.linalg.norm(l0)


def test_issue_35_a_removal_behind_the_handlers_back_stops_with_a_message():
    sim = pair_sim([-0.021, 0, 0], [0.005, 0, 0], [0.021, 0, 0], [-0.005, 0, 0])
    sim.add(m=MASS, r=RADIUS, x=-1.0)
    att = rime.rebound.attach(sim, rime.Scene.preset("ice"), length_unit=1, time_unit=1, mass_unit=1,
                              spins=[[1, 0, 0], [2, 0, 0], [3, 0, 0]])
    sim.remove(2)
    with pytest.raises(ValueError, match="^spins: the simulation has 2 particles, the spin table 3"):
        att.spins
    with pytest.raises(rebound.GenericError):
        sim.integrate(1.0)
    assert "removed outside rime's handler" in att.error
    # Given again, they are used.
    att2 = rime.rebound.attach(sim, rime.Scene.preset("ice"), length_unit=1, time_unit=1, mass_unit=1,
                               spins=[[1, 0, 0], [2, 0, 0]])
    sim.integrate(2.0)
    assert att2.error is None and att2.counts()["bounces"] == 1


def test_issue_35_reload_without_spins_is_refused_and_spins_0_starts_from_rest(tmp_path):
    sim, att = ring(orbits=0.1, collision="direct")
    path = str(tmp_path / "ring.bin")
    att.save(path)
    with pytest.warns(RuntimeWarning, match="reset function pointers"):
        loaded = rebound.Simulation(path)
    kw = dict(length_unit=1, time_unit=1, mass_unit=1)
    with pytest.raises(ValueError, match=r"^spins: this simulation is at t = .*load_spins"):
        rime.rebound.attach(loaded, rime.Scene.preset("ice"), **kw)
    rest = rime.rebound.attach(loaded, rime.Scene.preset("ice"), spins=0, **kw)
    assert np.array_equal(rest.spins, np.zeros((loaded.N, 3)))
    kept = rime.rebound.attach(loaded, rime.Scene.preset("ice"), spins=rime.rebound.load_spins(path, loaded), **kw)
    assert np.array_equal(kept.spins, att.spins) and np.count_nonzero(kept.spins) > 0


def snapshot(archive, j):
    with pytest.warns(RuntimeWarning, match="reset function pointers"):
        return archive[j]


def test_issue_35_rebounds_periodic_archive_gets_the_spins(tmp_path):
    """sim.save_to_file(file, step=K): every snapshot has its spins beside it (the ones the
    attachment holds at that step), and a reload from the last one goes on bit for bit."""
    sim, att = ring(orbits=0.2, collision="direct")
    sim.rand_seed = 7
    path = str(tmp_path / "archive.bin")
    k = 50
    sim.save_to_file(path, step=k)
    held = []
    for _ in range(6):
        sim.steps(k)
        held.append((sim.t, att.spins))
    archive = rebound.Simulationarchive(path)
    assert len(archive) == 7  # the first snapshot is the state the archive started at
    for j, (t, spins) in enumerate(held, start=1):
        snap = snapshot(archive, j)
        assert snap.t == t
        assert np.array_equal(rime.rebound.load_spins(path, snap), spins)
    assert np.count_nonzero(held[-1][1]) > 0
    with pytest.warns(RuntimeWarning, match="reset function pointers"):
        loaded = rebound.Simulation(path)
    again = rime.rebound.attach(loaded, rime.Scene.preset("ice"), length_unit=1, time_unit=1,
                                mass_unit=1, spins=rime.rebound.load_spins(path, loaded))
    loaded.simulationarchive_auto_step = 0  # no second archive from the copy
    loaded._simulationarchive_filename = None
    t = sim.t + 0.1 * 2 * math.pi / sim.OMEGA
    sim.integrate(t)
    loaded.integrate(t)
    assert np.array_equal(again.spins, att.spins)
    assert np.array_equal([p.vxyz for p in loaded.particles], [p.vxyz for p in sim.particles])


def test_issue_35_archive_by_interval_and_an_earlier_heartbeat_still_runs(tmp_path):
    calls = []
    sim = ring(orbits=0.0, collision="direct")[0]
    sim.heartbeat = lambda s: calls.append(s.contents.t)
    att = rime.rebound.attach(sim, rime.Scene.preset("ice"), length_unit=1, time_unit=1, mass_unit=1)
    path = str(tmp_path / "interval.bin")
    orbit = 2 * math.pi / sim.OMEGA
    sim.save_to_file(path, interval=0.05 * orbit)
    sim.integrate(0.3 * orbit)
    assert len(calls) > 100  # the user's heartbeat, every step
    archive = rebound.Simulationarchive(path)
    assert len(archive) >= 6
    for j in range(len(archive)):
        rime.rebound.load_spins(path, snapshot(archive, j))  # each snapshot has its record
    assert np.count_nonzero(rime.rebound.load_spins(path, snapshot(archive, len(archive) - 1))) > 0
    att.detach()
    n = len(calls)
    sim.integrate(0.31 * orbit)
    assert len(calls) > n  # restored by detach


def test_issue_35_contact_cache_is_bounded_and_eviction_changes_nothing():
    """Continuous radii (one new pair per collision): a cache of 8 pairs stays at 8 and gives the
    run of an unbounded cache bit for bit."""
    def run(cache_size):
        rng = np.random.default_rng(3)
        sim = rebound.Simulation()
        sim.gravity, sim.integrator, sim.collision = "none", "leapfrog", "direct"
        sim.boundary, sim.root_size, sim.N_ghost_x, sim.N_ghost_y, sim.N_ghost_z = "periodic", 0.2, 1, 1, 1
        sim.dt, sim.rand_seed = 1e-3, 5
        placed = []
        while len(placed) < 40:
            x = rng.uniform(-0.08, 0.08, 3)
            if all(np.linalg.norm(x - q) > 0.045 for q in placed):
                placed.append(x)
                r = rng.uniform(0.01, 0.02)
                v = rng.normal(0, 0.05, 3)
                sim.add(m=900 * 4 / 3 * math.pi * r**3, r=r, x=x[0], y=x[1], z=x[2], vx=v[0], vy=v[1], vz=v[2])
        att = rime.rebound.attach(sim, rime.Scene.preset("ice"), length_unit=1, time_unit=1,
                                  mass_unit=1, cache_size=cache_size)
        sizes = []
        for _ in range(20):
            sim.integrate(sim.t + 0.1)
            sizes.append(att.cached_pairs)
        return sim, att, sizes

    small, small_att, sizes = run(8)
    big, big_att, _ = run(100000)
    info = small_att.cache_info()
    assert max(sizes) <= 8 and info["capacity"] == 8
    assert big_att.cached_pairs > 8 and info["misses"] > 8  # eviction happened
    assert info["hits"] + info["misses"] == big_att.cache_info()["hits"] + big_att.cache_info()["misses"]
    assert small_att.counts() == big_att.counts() and small_att.counts()["bounces"] > 20
    assert np.array_equal([p.vxyz for p in small.particles], [p.vxyz for p in big.particles])
    assert np.array_equal(small_att.spins, big_att.spins)
    with pytest.raises(ValueError, match="^cache_size"):
        rime.rebound.attach(small, rime.Scene(), length_unit=1, time_unit=1, mass_unit=1, cache_size=1, spins=0)


def test_issue_35_stay_sinks_without_a_floor_and_a_floor_keeps_grains_apart():
    """`stay` under a steady pull (the pair's own gravity, G = 1e-3): with REBOUND's default floor 0
    stuck grains sink into each other about ½ a dt² per step; with a floor v_min they leave at
    v_min and the overlap stays below 2 (v_min + a dt) dt, as the documentation says."""
    scene = rime.Scene.preset("ice-sticky")

    def run(v_min):
        sim, att = sticky_pair("stay")
        sim.gravity, sim.G = "basic", 1e-3
        sim.minimum_collision_velocity = v_min
        deepest = 0.0
        for _ in range(100):
            sim.integrate(sim.t + 0.1)
            d = np.linalg.norm(np.subtract(sim.particles[0].xyz, sim.particles[1].xyz))
            deepest = max(deepest, 2 * RADIUS - d)
        return deepest, att

    a = 2 * 1e-3 * MASS / (2 * RADIUS) ** 2  # relative acceleration at contact
    assert a * 1e-3 < rime.thresholds(scene)["stick"]  # each step's approach sticks
    sunk, att = run(0.0)
    assert att.counts()["stays"] > 1000 and att.counts()["bounces"] == 0
    assert sunk > 0.25 * 0.5 * a * 1e-3**2 * 9000  # ~½ a dt² per step over most of 10 000 steps
    v_min = 1e-4
    apart, att = run(v_min)
    assert apart <= 2 * (v_min + a * 1e-3) * 1e-3 and sunk > 100 * apart


@pytest.mark.parametrize("kwargs,message", [
    (dict(time_unit="orbit"), "^time_unit: 'orbit' needs omega="),
    (dict(time_unit="orbit", omega=-1.0), "^omega: the orbital frequency"),
    (dict(time_unit=1, omega=2e-4), r"^omega: sim.OMEGA = 0.00013143527 per code time unit"),
])
def test_issue_35_orbit_time_unit_is_validated(kwargs, message):
    sim = ring(orbits=0.0, collision="direct")[0]
    args = dict(length_unit=1, time_unit=1, mass_unit=1)
    args.update(kwargs)
    with pytest.raises(ValueError, match=message):
        rime.rebound.attach(sim, rime.Scene.preset("ice"), **args)


def test_issue_35_time_in_orbits_gives_the_si_result():
    """A head-on hit at 1 cm/s written in orbits of Ω (time_unit="orbit", omega=Ω): rime's ε_N at
    1 cm/s, and the velocities after, converted to SI by hand, those of the SI run."""
    omega = 0.00013143527
    period = 2 * math.pi / omega
    want = cli("eps", "--preset", "ice", "--g", "0.01")[0]["eps_n"]
    eps, sim, _ = head_on_eps(rime.Scene.preset("ice"), MASS, units=(1.0, "orbit", 1.0), omega=omega)
    eps_si, sim_si, _ = head_on_eps(rime.Scene.preset("ice"), MASS)
    assert eps == pytest.approx(want, rel=1e-12) and eps_si == pytest.approx(want, rel=1e-12)
    for p, q in zip(sim.particles, sim_si.particles):
        assert p.vx / period == pytest.approx(q.vx, rel=1e-12)


def test_issue_35_version_is_the_packages():
    import pathlib
    import re

    pyproject = (pathlib.Path(__file__).resolve().parents[1] / "pyproject.toml").read_text()
    assert rime.__version__ == re.search(r'^version = "([^"]+)"', pyproject, re.M).group(1)


def test_issue_35_detaching_a_replaced_attachment_leaves_the_newer_one():
    sim = pair_sim([-0.021, 0, 0], [0.005, 0, 0], [0.021, 0, 0], [-0.005, 0, 0])
    kw = dict(length_unit=1, time_unit=1, mass_unit=1)
    old = rime.rebound.attach(sim, rime.Scene.preset("ice"), **kw)
    new = rime.rebound.attach(sim, rime.Scene.preset("ice"), **kw)
    old.detach()
    sim.integrate(1.0)
    assert new.counts()["bounces"] == 1 and old.counts()["bounces"] == 0
    want = cli("eps", "--preset", "ice", "--g", "0.01")[0]["eps_n"]
    assert (sim.particles[1].vx - sim.particles[0].vx) / 0.01 == pytest.approx(want, rel=1e-12)


# Issue 38: the handler's counters. The brute-force side reads the particles' velocities before and
# after each step in Python and computes m₁ Δv₁,y (x₁ − x₂) itself.

def test_issue_38_two_body_flux_and_speeds_agree_with_a_brute_force_count():
    """An oblique hit with friction (Δv_y from both the normal and the tangential impulse)."""
    sim = pair_sim([-0.036, 0.012, 0.004], [0.01, 0.002, -0.001], [0.0, 0.0, 0.0], [-0.001, -0.003, 0.0])
    att = rime.rebound.attach(sim, rime.Scene.preset("ice"), length_unit=1, time_unit=1, mass_unit=1,
                              speed_edges=[0.0, 0.005, 0.01, 0.02], overlap_depth=0.0)
    before, after = step_to_collision(sim, att)
    dx = after[0][0] - after[1][0]  # positions where REBOUND found the pair (a bounce keeps them)
    dv1 = after[0][1] - before[0][1]
    want_flux = MASS * dv1[1] * dx[0]
    n = dx / np.linalg.norm(dx)
    want_gn = -(before[0][1] - before[1][1]) @ n  # the spins start at 0: Eq. (2) is v₁ − v₂
    got = att.counters()
    assert dv1[1] != 0 and dx[0] != 0
    assert got["collisions"] == got["bounces"] == 1 and got["stays"] == got["merges"] == 0
    assert got["angular_momentum_flux"] == pytest.approx(want_flux, rel=1e-12)
    # p₂'s side of the same transfer: m₂ Δv₂,y (x₂ − x₁), the same number.
    dv2 = after[1][1] - before[1][1]
    assert MASS * dv2[1] * -dx[0] == pytest.approx(want_flux, rel=1e-12)
    s = got["normal_speed"]
    assert s["count"] == 1 and s["sum"] == pytest.approx(want_gn, rel=1e-12)
    assert s["sum_squares"] == pytest.approx(want_gn**2, rel=1e-12) and s["max"] == s["sum"]
    g_rel = before[0][1] - before[1][1]
    assert got["tangential_speed"]["sum"] == pytest.approx(np.linalg.norm(g_rel - (g_rel @ n) * n), rel=1e-12)
    h = got["speed_histogram"]
    assert h["counts"] == [int(0 <= want_gn < 0.005), int(0.005 <= want_gn < 0.01), int(0.01 <= want_gn < 0.02)]
    assert h["below"] == 0 and h["above"] == int(want_gn >= 0.02)
    depth = 1 - np.linalg.norm(dx) / (2 * RADIUS)
    assert got["overlaps"]["max_depth"] == pytest.approx(depth, rel=1e-12, abs=1e-15)
    assert got["overlaps"]["deeper"] == 1 and got["overlaps"]["threshold"] == 0.0
    assert got["t_end"] == sim.t and got["t_start"] == 0.0 and got["duration"] == sim.t
    # The kinetic energy lost, translation and spin (the spins start at 0; I = 2/5 m r²).
    energy = [0.5 * MASS * (s[1] @ s[1] + 0.4 * RADIUS**2 * (s[2] @ s[2])) for s in before + after]
    assert got["energy_loss"] == pytest.approx(energy[0] + energy[1] - energy[2] - energy[3], rel=1e-9)
    assert got["energy_loss"] > 0
    # Not a shearing sheet: no viscosity from it.
    assert got["collisional_viscosity_si"] is None
    # Reset: a new window from now, the same edges.
    again = att.counters(reset=True)
    assert again["angular_momentum_flux"] == got["angular_momentum_flux"]
    fresh = att.counters()
    assert fresh["collisions"] == 0 and fresh["angular_momentum_flux"] == 0.0 and fresh["t_start"] == sim.t
    assert fresh["speed_histogram"]["edges"] == [0.0, 0.005, 0.01, 0.02]
    att.reset_counters(speed_edges=[])
    assert att.counters()["speed_histogram"] is None
    with pytest.raises(ValueError, match="^speed_edges: edges must increase"):
        att.reset_counters(speed_edges=[1.0, 1.0])
    with pytest.raises(ValueError, match="^reset: expected True or False"):
        att.counters(reset=1)
    # The cumulative counts are not windowed.
    assert att.counts()["bounces"] == 1


def test_issue_38_merge_flux_is_p1s_share_of_the_common_velocity():
    sim, att = sticky_pair("merge", g_t=3e-6)
    p = [(np.array(q.xyz), np.array(q.vxyz), q.m) for q in sim.particles]
    x1_end = x2_end = None
    for _ in range(200000):
        xs = [np.array(q.xyz) + np.array(q.vxyz) * sim.dt for q in sim.particles]  # leapfrog, no forces
        vs = [np.array(q.vxyz) for q in sim.particles]
        sim.steps(1)
        if sim.N == 1:
            x1_end, x2_end = xs
            break
    assert x1_end is not None and att.counts()["merges"] == 1
    (_, _, m1), (_, _, m2) = p
    v_common = (m1 * vs[0][1] + m2 * vs[1][1]) / (m1 + m2)
    want = m1 * (v_common - vs[0][1]) * (x1_end[0] - x2_end[0])
    got = att.counters()
    # The energy lost: before (both grains, their spins) minus the merged grain's, from momentum
    # and angular momentum (the merged spin read back from the handler).
    q = sim.particles[0]
    w_after = att.spins[0]
    v_after = np.array(q.vxyz)
    assert np.allclose(v_after, (m1 * vs[0] + m2 * vs[1]) / (m1 + m2), rtol=1e-12, atol=1e-20)
    after = 0.5 * q.m * (v_after @ v_after + 0.4 * q.r**2 * (w_after @ w_after))
    spins0 = np.array([[0.001, -0.002, 0.0005], [-0.001, 0.0005, 0.002]])
    before_e = sum(0.5 * m * (v @ v + 0.4 * RADIUS**2 * (w @ w)) for m, v, w in zip((m1, m2), vs, spins0))
    assert got["energy_loss"] == pytest.approx(before_e - after, rel=1e-9)
    assert got["merges"] == 1 and got["collisions"] == 1 and want != 0
    assert got["angular_momentum_flux"] == pytest.approx(want, rel=1e-9)


def test_issue_38_patch_flux_per_step_agrees_with_a_brute_force_count_across_ghost_boxes():
    """A shearing patch (sei, shear boundary, ghost boxes): every step with one collision, the
    handler's increment of the flux equals m_i Δv_i,y (x_i − x_j) from the two particles whose
    velocities differ from a copy stepped without collisions, x_i − x_j by the minimum image."""
    import warnings

    sim, att = ring(orbits=0.0, collision="direct", n=36)
    box = sim.root_size
    checked, crossing, total = 0, 0, 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # REBOUND's "reset function pointers" on copy
        for _ in range(400):
            free = sim.copy()
            free.collision = "none"
            c0 = att.counters()
            sim.steps(1)
            free.steps(1)
            c1 = att.counters()
            if c1["collisions"] - c0["collisions"] != 1:
                continue
            n = sim.N
            v, vf = np.zeros(3 * n), np.zeros(3 * n)
            x = np.zeros(3 * n)
            sim.serialize_particle_data(vxvyvz=v, xyz=x)
            free.serialize_particle_data(vxvyvz=vf)
            dv, x = (v - vf).reshape(n, 3), x.reshape(n, 3)
            moved = np.flatnonzero(np.linalg.norm(dv, axis=1) > 1e-9 * np.max(np.abs(v)))
            assert len(moved) == 2, moved
            i, j = moved
            dxij = x[i, 0] - x[j, 0]
            if abs(dxij) > box / 2:
                crossing += 1
            dxij -= box * np.round(dxij / box)
            want = sim.particles[int(i)].m * dv[i, 1] * dxij
            step = c1["angular_momentum_flux"] - c0["angular_momentum_flux"]
            assert step == pytest.approx(want, rel=1e-9, abs=1e-12), (i, j)
            total += want
            checked += 1
    assert checked >= 5, checked
    assert crossing >= 1, "no collision across the x edge in this patch: choose another seed"


def test_issue_38_a_new_simulation_at_a_freed_ones_address_starts_from_rest():
    """A simulation freed while attached leaves its registration under its address; a new one
    allocated there must not inherit its spins (the shearing-sheet runs of issue 38 did, so runs of
    a distribution depended on memory reuse). Reuse is simulated: B's address given A's link."""
    a = pair_sim([-0.021, 0, 0], [0.005, 0, 0], [0.021, 0, 0], [-0.005, 0, 0])
    spins = np.array([[1.0, 2.0, 3.0], [-1.0, 0.5, 0.25]])
    att_a = rime.rebound.attach(a, rime.Scene(), length_unit=1, time_unit=1, mass_unit=1, spins=spins)
    b = pair_sim([-0.021, 0, 0], [0.005, 0, 0], [0.021, 0, 0], [-0.005, 0, 0])
    rime.rebound._ATTACHED[ctypes.addressof(b)] = rime.rebound._ATTACHED[ctypes.addressof(a)]
    att_b = rime.rebound.attach(b, rime.Scene(), length_unit=1, time_unit=1, mass_unit=1)
    assert np.array_equal(att_b.spins, np.zeros((2, 3)))
    # A's handler is untouched: still registered, its spins kept, its collisions resolved.
    assert np.array_equal(att_a.spins, spins)
    a.integrate(1.0)
    assert att_a.counts()["bounces"] == 1 and att_a.error is None


def test_issue_38_viscosities_by_hand_in_cm_grams_seconds():
    """ν_coll = F / (T (3/2) Ω Σm) and ν_trans = Σ m u (v_y + 3/2 Ω x) / ((3/2) Ω Σm), by hand in
    code units (cm, g, s), then × 1e-4 to m²/s. Ω is only read (a leapfrog pair, not a sheet)."""
    omega = 2e-3  # per code second
    r, m = 2.0, MASS * 1e3  # cm, g
    sim = pair_sim([-3.6, 1.2, 0.4], [1.0, 0.2, -0.1], [0.0, 0.0, 0.0], [-0.1, -0.3, 0.0],
                   mass=m, radius=r, dt=1e-3)
    sim.OMEGA = omega
    att = rime.rebound.attach(sim, rime.Scene.preset("ice"), length_unit="cm", time_unit="s", mass_unit="g")
    before, after = step_to_collision(sim, att)
    sim.integrate(sim.t + 0.25)  # the window goes on after the hit
    c = att.counters()
    flux = m * (after[0][1][1] - before[0][1][1]) * (after[0][0][0] - after[1][0][0])
    assert c["angular_momentum_flux"] == pytest.approx(flux, rel=1e-12)
    want = flux / (sim.t * 1.5 * omega * 2 * m) * 1e-4
    assert c["collisional_viscosity_si"] == pytest.approx(want, rel=1e-12)
    p = [(np.array(q.xyz), np.array(q.vxyz)) for q in sim.particles]
    stress = sum(m * v[0] * (v[1] + 1.5 * omega * x[0]) for x, v in p)
    assert att.translational_viscosity() == pytest.approx(stress / (1.5 * omega * 2 * m) * 1e-4, rel=1e-12)
    sim.OMEGA = 0.0
    with pytest.raises(ValueError, match="^sim.OMEGA"):
        att.translational_viscosity()
    assert att.counters()["collisional_viscosity_si"] is None
