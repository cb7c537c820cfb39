"""rime_grains.dustpy.attach inside DustPy 1.0.9 (issue 39).

The disks are DustPy's own: a box of two radial cells at 1 AU (plus DustPy's two boundary cells)
held at 150 K and 200 K, with gas evolution, radial drift and diffusion switched off the way
DustPy's own coagulation tests do it, so that every active cell is a closed coagulation problem;
and a small disk with all of DustPy's physics on. Expected values come from

* conservation of mass (DustPy's sticking matrix conserves it to 1e-13 per collision, the bound
  its ``checkmassconservation`` prints);
* DustPy's own default run (its updaters, its arrays), which v_stick = ∞ must reproduce bit for bit;
* the ``rime`` command line (``rime stick``, the core's bisection on the full model, through its
  own parser) for the sticking speeds: the model sees a pair only through R_eff and m_eff, so the
  pair (a_i, a_j) sticks up to the v_stick of two equal grains of radius 2 R_eff and the density
  that gives them the pair's m_eff;
* DustPy's relative velocities and the Maxwell–Boltzmann formula of its ``pfrag``, written out
  here in numpy;
* for the stall, the two curves: the first mass bin i where DustPy's Δv(a_i, a_{i+1}) exceeds
  rime's v_stick(a_i, a_{i+1}) (neighbouring sizes: for equal sizes DustPy's drift and settling
  terms vanish and its turbulent term switches on abruptly).
"""
import json
import math
import subprocess
import warnings

import numpy as np
import pytest

from conftest import import_dustpy_offline, rime_binary

# DustPy is pinned in the test environment: a missing DustPy fails here rather than skipping.
dustpy = import_dustpy_offline()
from dustpy import constants as c  # noqa: E402
from dustpy.std import dust as std_dust  # noqa: E402

import rime_grains as rime  # noqa: E402
from rime_grains.dustpy import DensityWarning, GammaRangeWarning, attach  # noqa: E402

ICE = 0.9  # g/cm³, the `ice` preset's density (900 kg/m³)
YEAR = c.year
NO_FRAGMENTATION = 1e4  # cm/s: far above every Δv of the box (< 1.2 m/s)
SOURCE = "test: fragmentation out of reach, so that bouncing is the only barrier"


def box(temperatures=(150.0, 200.0), density=ICE, mmin=1e-10, mmax=10.0):
    """DustPy's disk at 1 AU, one active cell per temperature, as a closed coagulation problem."""
    sim = dustpy.Simulation()
    sim.ini.grid.Nr = len(temperatures) + 2
    sim.ini.grid.rmin, sim.ini.grid.rmax = 0.9 * c.au, 1.1 * c.au
    sim.ini.grid.mmin, sim.ini.grid.mmax = mmin, mmax
    sim.ini.dust.rhoMonomer = density
    # Monomers only: every grain starts in the first mass bins.
    sim.ini.dust.aIniMax = 2.0 * (3.0 * mmin / (4.0 * math.pi * density)) ** (1.0 / 3.0)
    sim.initialize()
    # As DustPy's analytical-kernel tests: no gas evolution, no radial transport.
    del sim.integrator.instructions[1]
    sim.gas.S.tot[...] = 0.0
    sim.gas.S.tot.updater = None
    sim.dust.v.rad[...] = 0.0
    sim.dust.v.rad.updater = None
    sim.dust.D[...] = 0.0
    sim.dust.D.updater = None
    sim.gas.T.updater = None
    sim.gas.T[...] = [temperatures[0], *temperatures, temperatures[-1]]
    sim.writer = None
    sim.verbosity = 0
    sim.update()
    return sim


def run_to(sim, years):
    sim.t.snapshots = [years * YEAR]
    sim.run()


def attach_quietly(sim, scene, **kwargs):
    """attach, expecting the warning that 150 K lies below γ(T)'s measured range."""
    with pytest.warns(GammaRangeWarning, match=r"1 cells at 150–150 K use γ held at its 175 K value"):
        return attach(sim, scene, **kwargs)


def cli_v_stick(a1_cm, a2_cm, temperature, density):
    """rime's sticking speed [cm/s] of the pairs (a1, a2) [cm] of grains of ``density`` [g/cm³]
    from `rime stick`: two equal grains of radius 2 R_eff whose density gives them the pair's
    m_eff (R_eff and m_eff are all the model sees of a pair)."""
    a1, a2 = np.asarray(a1_cm, float) / 100.0, np.asarray(a2_cm, float) / 100.0
    r_eff = a1 * a2 / (a1 + a2)
    m1, m2 = density * 1000.0 * a1**3, density * 1000.0 * a2**3  # (4/3)π cancels below
    m_eff = m1 * m2 / (m1 + m2)
    radius = 2.0 * r_eff
    rho = 2.0 * m_eff / radius**3
    out = np.empty(len(a1))
    # One call per distinct equivalent density (one for neighbours on DustPy's logarithmic grid).
    keys = np.round(rho, 6)
    for key in np.unique(keys):
        idx = np.nonzero(keys == key)[0]
        rho_k = float(np.mean(rho[idx]))
        assert np.allclose(rho[idx], rho_k, rtol=1e-12, atol=0)
        args = [rime_binary(), "stick", "--radius", ",".join(f"{r:.17g}" for r in radius[idx]),
                "--temperature", f"{temperature:.17g}", "--set", f"grains.density={rho_k:.17g}",
                "--format", "json"]
        rows = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
        assert len(rows) == len(idx)
        for k, row in zip(idx, rows):
            out[k] = math.inf if row["v_stick"] is None else 100.0 * row["v_stick"]
    return out


def maxwell_exceeds(v, dv):
    """DustPy 1.0.9's pfrag: the chance that a collision at rms speed dv exceeds v."""
    with np.errstate(divide="ignore", invalid="ignore"):
        x = 1.5 * (v / dv) ** 2
        return np.where(dv == 0, 0.0, np.where(np.isinf(v), 0.0, (1.0 + x) * np.exp(-x)))


@pytest.fixture(scope="module")
def stalled():
    """The box with rime's updaters (DustPy's Maxwell–Boltzmann speeds), run to 100 and 300 yr."""
    sim = box()
    att = attach_quietly(sim, rime.Scene.preset("ice"), v_frag=NO_FRAGMENTATION,
                         v_frag_source=SOURCE)
    sim.update()
    area = np.asarray(sim.grid.A)
    mass0 = np.asarray(sim.dust.Sigma).sum(axis=1) * area
    run_to(sim, 100.0)
    sigma100 = np.array(sim.dust.Sigma)
    run_to(sim, 300.0)
    return {"sim": sim, "att": att, "mass0": mass0, "sigma100": sigma100,
            "sigma300": np.array(sim.dust.Sigma)}


def test_issue_39_probabilities_match_rime_and_dustpys_distribution():
    sim = box()
    att = attach_quietly(sim, rime.Scene.preset("ice"))
    sim.update()
    p_s, p_f = np.asarray(sim.dust.p.stick), np.asarray(sim.dust.p.frag)
    # Symmetric, bounded, 0 at DustPy's boundary cells.
    assert np.array_equal(p_s, p_s.transpose(0, 2, 1))
    assert np.all(p_s >= 0) and np.all(p_s + p_f <= 1.0)
    assert not p_s[0].any() and not p_s[-1].any()
    # DustPy's fragmentation is its own: the p_frag updater was left as DustPy set it.
    assert np.array_equal(p_f, std_dust.p_frag(sim))
    a = np.asarray(sim.dust.a)[1]
    n = len(a)
    i = np.arange(n - 1)
    for cell, temperature in ((1, 150.0), (2, 200.0)):
        dv = np.asarray(sim.dust.v.rel.tot)[cell]
        # rime's tables in cgs against the command line (m/s → cm/s by hand).
        table = att.v_stick(temperature)
        for rows, cols in ((i, i + 1), (np.arange(n), np.arange(n))):
            expected = cli_v_stick(a[rows], a[cols], temperature, ICE)
            got = table[rows, cols]
            assert np.array_equal(np.isinf(got), np.isinf(expected))
            finite = np.isfinite(expected)
            assert finite.sum() > 10
            np.testing.assert_allclose(got[finite], expected[finite], rtol=1e-8)
            # p_stick = 1 − F(min(v_stick, v_frag)) with DustPy's F, written out here.
            v_frag = float(np.asarray(sim.dust.v.frag)[cell])
            want = 1.0 - np.maximum(maxwell_exceeds(expected, dv[rows, cols]),
                                    maxwell_exceeds(v_frag, dv[rows, cols]))
            np.testing.assert_allclose(p_s[cell, rows, cols], want, rtol=1e-7, atol=1e-12)
        # Bouncing is there: pairs that neither stick nor fragment.
        assert np.max(1.0 - p_s[cell] - p_f[cell]) > 0.5
    att.detach()


def test_issue_39_without_a_distribution_the_steps_are_at_v_stick_and_v_frag():
    sim = box()
    att = attach_quietly(sim, rime.Scene.preset("ice"), velocity_distribution="none")
    sim.update()
    p_s, p_f = np.asarray(sim.dust.p.stick), np.asarray(sim.dust.p.frag)
    dv = np.asarray(sim.dust.v.rel.tot)
    v_frag = np.asarray(sim.dust.v.frag)
    assert set(np.unique(p_s)) <= {0.0, 1.0} and set(np.unique(p_f)) <= {0.0, 1.0}
    assert np.array_equal(p_s, p_s.transpose(0, 2, 1)) and np.array_equal(p_f, p_f.transpose(0, 2, 1))
    for cell, temperature in ((1, 150.0), (2, 200.0)):
        v_stick = att.v_stick(temperature)
        # Upper triangle (DustPy's pfrag reads that one; the lower is its mirror).
        upper = np.triu(np.ones_like(v_stick, dtype=bool))
        d = dv[cell][upper]
        assert np.array_equal(p_f[cell][upper] == 1.0, d >= v_frag[cell])
        assert np.array_equal(p_s[cell][upper] == 1.0, (d < v_stick[upper]) & (d < v_frag[cell]))
        assert p_f[cell].any() and (p_s[cell] == 0).any() and (p_s[cell] == 1).any()
    assert not p_f[0].any() and not p_f[-1].any() and not p_s[0].any() and not p_s[-1].any()
    att.detach()
    assert np.array_equal(np.asarray(sim.dust.p.frag.updater.updater._func(sim)), std_dust.p_frag(sim))


def test_issue_39_v_stick_infinite_reproduces_dustpys_default_run():
    """In the box (fragmentation at DustPy's 1 m/s) and in a small disk with all of DustPy's
    physics (drift, diffusion, gas evolution, boundary cells): the same arrays, bit for bit."""
    def disk():
        sim = dustpy.Simulation()
        sim.ini.grid.Nr = 6
        sim.ini.grid.rmin, sim.ini.grid.rmax = 3.0 * c.au, 30.0 * c.au
        sim.ini.grid.mmax = 1e2
        sim.initialize()
        sim.writer = None
        sim.verbosity = 0
        return sim

    for make, years in ((box, 100.0), (disk, 300.0)):
        default, ours = make(), make()
        att = attach(ours, None, v_stick=np.inf)
        assert att.provenance["sticking"]["v_stick_constant"] == {"value": math.inf, "unit": "cm/s"}
        run_to(default, years)
        run_to(ours, years)
        for field in ("Sigma", "a", "v.rel.tot"):
            x, y = default.dust, ours.dust
            for part in field.split("."):
                x, y = getattr(x, part), getattr(y, part)
            assert np.array_equal(np.asarray(x), np.asarray(y)), field
        assert np.array_equal(np.asarray(default.dust.p.stick), np.asarray(ours.dust.p.stick))
        assert np.array_equal(np.asarray(default.gas.Sigma), np.asarray(ours.gas.Sigma))
        # Not a vacuous comparison: the grains grew to where they fragment.
        assert np.asarray(default.dust.p.frag).max() > 0.5
        assert float(default.t) == float(ours.t) == years * YEAR


def test_issue_39_mass_is_conserved_with_rimes_updaters(stalled):
    sim, att = stalled["sim"], stalled["att"]
    mass = np.asarray(sim.dust.Sigma).sum(axis=1) * np.asarray(sim.grid.A)
    updates = att.cache_info()["updates"]
    assert updates > 50
    # DustPy's sticking matrix conserves mass to 1e-13 per collision (its checkmassconservation
    # bound); every step collides at most all the mass once.
    for cell in (1, 2):
        assert abs(mass[cell] / stalled["mass0"][cell] - 1.0) <= 1e-13 * updates
    assert np.all(np.asarray(sim.dust.Sigma) >= 0)


def stall_bins(sim, sigma, temperatures=(150.0, 200.0)):
    """(predicted, measured, median) bin per cell: the first i where Δv(a_i, a_{i+1}) ≥ v_stick
    (from the command line), the first bin holding ≥ 0.1 % of the mass, the median bin."""
    a = np.asarray(sim.dust.a)[1]
    i = np.arange(len(a) - 1)
    out = []
    for cell, temperature in zip((1, 2), temperatures):
        dv = np.asarray(sim.dust.v.rel.tot)[cell, i, i + 1]
        v_stick = cli_v_stick(a[i], a[i + 1], temperature, ICE)
        bounce = np.nonzero(dv >= v_stick)[0]
        predicted = int(bounce[0])
        # Beyond the first bounce every neighbouring pair bounces (no second window of sticking).
        assert np.all(np.diff(bounce) == 1) and bounce[-1] == len(i) - 1
        fraction = sigma[cell] / sigma[cell].sum()
        measured = int(np.nonzero(fraction >= 1e-3)[0][0])
        median = int(np.searchsorted(np.cumsum(fraction), 0.5))
        out.append((predicted, measured, median, a))
    return out


def test_issue_39_growth_stalls_where_v_stick_falls_below_dustpys_relative_velocity(stalled):
    sim = stalled["sim"]
    bins100 = stall_bins(sim, stalled["sigma100"])
    bins300 = stall_bins(sim, stalled["sigma300"])
    for (predicted, measured, median, a), (_, _, median100, _) in zip(bins300, bins100):
        # Every grain below the barrier grew past it; none is left more than one bin below it.
        assert abs(measured - predicted) <= 1, (predicted, measured, a[predicted], a[measured])
        # Stalled: the median size moved by at most one bin while the time tripled (the control
        # below, without bouncing, grows to the top of the mass grid in that time).
        assert median - median100 <= 1
        # Above the barrier the mass piles up (grains that crossed it swept up smaller ones).
        assert median >= predicted
    # Where γ is larger (200 K) the grains stick up to larger sizes.
    assert bins300[1][0] > bins300[0][0] + 5
    # Control: the same box without bouncing grows to the top of the mass grid in the same time.
    control = box()
    attach(control, None, v_stick=np.inf, v_frag=NO_FRAGMENTATION, v_frag_source=SOURCE)
    run_to(control, 300.0)
    sigma = np.asarray(control.dust.Sigma)
    for cell, (predicted, _, _, _) in zip((1, 2), bins300):
        fraction = sigma[cell] / sigma[cell].sum()
        assert int(np.searchsorted(np.cumsum(fraction), 0.5)) >= predicted + 15


def test_issue_39_the_simulations_density_is_used_and_said():
    sim = box(temperatures=(185.0,), density=1.67)
    with pytest.warns(DensityWarning, match=r"DustPy's grain density 1\.67 g/cm³.*not the scene's 0\.9 g/cm³"):
        att = attach(sim, rime.Scene.preset("ice"))
    assert att.density == 1.67
    assert att.provenance["density"] == {
        "value": 1.67, "unit": "g/cm3", "scene_value": 0.9,
        "source": "sim.dust.rhos × sim.dust.fill (DustPy; its sizes and masses use it)"}
    a = np.asarray(sim.dust.a)[1]
    k = np.arange(30, len(a), 7)
    expected = cli_v_stick(a[k], a[k], 185.0, 1.67)
    np.testing.assert_allclose(att.v_stick(185.0)[k, k], expected, rtol=1e-8)
    # With ice's density the sticking speed differs (not a vacuous check).
    assert not np.allclose(cli_v_stick(a[k], a[k], 185.0, ICE), expected, rtol=1e-3)


def test_issue_39_tables_are_cached_on_rounded_temperatures():
    sim = box(temperatures=(100.0, 150.0, 185.0, 185.004))
    with pytest.warns(GammaRangeWarning, match=r"2 cells at 100–150 K use γ held at its 175 K value"):
        att = attach(sim, rime.Scene.preset("ice"))
    # 100 K and 150 K share the table of 175 K (γ held); 185.004 K rounds to 185 K.
    assert att.cache_info()["tables"] == 2
    assert list(att.gamma_ranges) == ["boundary", "held_cold", "held_cold", "measured", "measured",
                                      "boundary"]
    assert np.array_equal(att.v_stick(100.0), att.v_stick(175.0))
    assert np.array_equal(att.v_stick(185.004), att.v_stick(185.0))
    assert not np.array_equal(att.v_stick(185.0), att.v_stick(190.0))
    misses = att.cache_info()["misses"]
    for _ in range(3):
        sim.update()
    assert att.cache_info()["misses"] == misses and att.cache_info()["updates"] == 3
    sim.gas.T[3] = 186.0
    sim.update()
    assert att.cache_info()["misses"] == misses + 1
    assert att.temperatures[3] == 186.0 and math.isnan(att.temperatures[0])
    # Exact temperatures on request.
    exact = attach(box(temperatures=(185.0, 185.004)), rime.Scene.preset("ice"), temperature_step=0)
    assert exact.cache_info()["tables"] == 2


def test_issue_39_provenance_says_what_is_rimes_and_what_is_dustpys():
    sim = box(temperatures=(185.0,))
    att = attach(sim, rime.Scene.preset("ice"), a_rule="fit_measured", v_frag=300.0,
                 v_frag_source="Gundlach & Blum (2015): ice fragments above ~10 m/s (here 3 m/s)")
    p = att.provenance
    assert p["rime_version"] == rime.__version__ and p["dustpy_version"] == "1.0.9"
    assert p["sticking"]["a_rule"] == "fit_measured"
    fit = p["sticking"]["fit"]
    assert fit["entry"] == "gundlach2015" and fit["speed"] == 9.6 and fit["radius"] == 1.5e-6
    assert abs(fit["achieved"] / 9.6 - 1.0) < 1e-6
    assert p["sticking"]["damping_time"]["value"] == fit["damping_time"]
    assert p["fragmentation"]["v_frag"]["source"].startswith("Gundlach & Blum (2015)")
    assert np.all(np.asarray(sim.dust.v.frag) == 300.0)
    assert any("porous" in x for x in p["not_modelled"])
    assert any("fragmentation" in x for x in p["not_modelled"])
    assert "Musiolik & Wurm (2019)" in p["sticking"]["gamma"]["source"]
    assert p["sticking"]["gamma"]["cells"] == {"measured": 1, "held_cold": 0, "held_warm": 0,
                                              "boundary": 2}
    assert "rime" in sim.dust.p.stick.description
    json.dumps(p)  # plain data, storable beside a run
    # A user's own measurement, with its source.
    own = attach(box(temperatures=(185.0,)), rime.Scene.preset("ice"), a_rule="fit_measured",
                 fit={"radius": 1e-6, "temperature": 190.0, "speed": 5.0, "source": "my lab, 2026"})
    assert own.provenance["sticking"]["fit"]["entry"] == "my lab, 2026"
    # detach gives DustPy back its own updaters and fragmentation speed.
    att.detach()
    assert sim.dust.p.stick.updater.updater._func is std_dust.p_stick
    assert np.all(np.asarray(sim.dust.v.frag) == 100.0)
    sim.update()
    assert np.array_equal(np.asarray(sim.dust.p.stick), std_dust.p_stick(sim))


def test_issue_39_bad_input_names_the_argument():
    sim = box(temperatures=(185.0,))
    ice = rime.Scene.preset("ice")
    before = np.array(sim.dust.v.frag)
    cases = [
        (dict(v_frag=300.0), "v_frag_source"),
        (dict(v_frag_source="x"), "v_frag_source"),
        (dict(v_frag=-1.0, v_frag_source="x"), "v_frag"),
        (dict(velocity_distribution="gauss"), "velocity_distribution"),
        (dict(a_rule="fitted"), "a_rule"),
        (dict(fit={"radius": 1e-6, "temperature": 190.0, "speed": 5.0, "source": "x"}), "fit"),
        (dict(a_rule="fit_measured", fit={"radius": 1e-6, "speed": 5.0, "source": "x"}),
         "fit.temperature"),
        (dict(temperature_step=-1.0), "temperature_step"),
        (dict(cache_size=0), "cache_size"),
        (dict(v_stick=0.0), "v_stick"),
        (dict(accuracy="sloppy"), "accuracy"),
        (dict(temperature_rule="extrapolate"), "temperature_rule"),
        (dict(convention="energy"), "convention"),
    ]
    for kwargs, field in cases:
        with pytest.raises(ValueError, match=rf"^{field}: "):
            attach(sim, ice, **kwargs)
    with pytest.raises(ValueError, match=r"^scene: expected a rime_grains.Scene"):
        attach(sim, "ice")
    with pytest.raises(ValueError, match=r"^sim: expected a dustpy.Simulation"):
        attach(object(), ice)
    with pytest.raises(ValueError, match=r"^sim: call sim.initialize\(\) before attach"):
        attach(dustpy.Simulation(), ice)
    cold = box(temperatures=(150.0,))
    with pytest.raises(ValueError, match=r"^temperatures: .*175, 200"):
        attach(cold, ice, temperature_rule="refuse")
    mixed = box(temperatures=(185.0,))
    mixed.dust.rhos[:, 3] = 2.0
    with pytest.raises(ValueError, match=r"^sim.dust.rhos: rime's sticking speed is for grains of one"):
        attach(mixed, ice)
    # Nothing was changed by the refusals.
    assert sim.dust.p.stick.updater.updater._func is std_dust.p_stick
    assert np.array_equal(np.asarray(sim.dust.v.frag), before)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        attach(sim, ice).detach()


def test_issue_39_kernel_equals_the_command_line():
    """rime_grains.kernel and `rime kernel` are the same core function behind two front ends:
    every record, to the digit (JSON keeps every digit), with the same provenance numbers."""
    ice = rime.Scene.preset("ice")
    for rule, fit_args in (("given", []), ("fit_measured", ["--fit-radius", "2e-6"])):
        args = [rime_binary(), "kernel", "--radii", "1um..1cm", "--points", "9", "--temperatures",
                "150,180,200", "--a-rule", rule, *fit_args, "--format", "json"]
        cli = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
        radii = sorted({r["radius_1"] for r in cli["records"]})
        fit = None if rule == "given" else {"radius": 2e-6, "temperature": 200.0, "speed": 9.6,
                                            "source": "gundlach2015"}
        k = rime.kernel(radii, [150.0, 180.0, 200.0], ice, a_rule=rule, fit=fit)
        n = len(radii)
        assert len(cli["records"]) == 3 * n * n
        for index, record in enumerate(cli["records"]):
            t, i, j = index // (n * n), index // n % n, index % n
            assert (record["radius_1"], record["radius_2"]) == (radii[i], radii[j])
            assert record["temperature"] == k["temperatures"][t]
            got = k["v_stick"][t, i, j]
            assert record["status"] == k["status"][t, i, j]
            assert (record["v_stick"] is None and got == math.inf) or record["v_stick"] == got
        assert [g["range"] for g in k["gammas"]] == [g["gamma_range"] for g in cli["temperatures"]]
        assert k["damping_time"] == cli["provenance"]["damping_time"]
        # Both outcomes compared (with the fitted A of 7 ns every pair has a threshold).
        assert any(r["status"] == "threshold" for r in cli["records"])
        assert any(r["status"] == "always_sticks" for r in cli["records"]) == (rule == "given")


def test_import_offline_touches_no_network_and_keeps_the_timeout():
    """`rime_grains.dustpy.import_offline` in a fresh process: DustPy imported with every
    connection refused (none is attempted past it) and the default socket timeout unchanged."""
    code = """
import socket, sys
attempts = []
def recording(self, address):
    attempts.append(address)
    raise OSError("no network in this test")
socket.socket.connect = recording
socket.setdefaulttimeout(7.0)
from rime_grains.dustpy import import_offline
dustpy = import_offline()
assert "dustpy" in sys.modules and dustpy is sys.modules["dustpy"]
assert attempts == [], attempts
assert socket.getdefaulttimeout() == 7.0, socket.getdefaulttimeout()
assert socket.socket.connect is recording
print("ok")
"""
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr[-2000:]
    assert done.stdout.strip() == "ok"
