"""The laws from Python against the `rime` command line (issue 23), and bad input.

Expected values come from the `rime` binary's JSON (the CLI's own parsing of presets, `--set` keys
with units and speeds), from closed forms (Eq. (10), (26) top) and from the documented accuracy
bounds; never from this package's own output.
"""
import json
import math
import sys
import threading
import time

import numpy as np
import pytest

import rime_grains as rime
from conftest import cli

PRESETS = ["ice", "ice-frost", "ice-sticky", "ice-paper-viscosities"]
SPEEDS = [1e-6, 3.3e-5, 1e-4, 2e-3, 0.01, 0.37, 5.0]


@pytest.mark.parametrize("preset", PRESETS)
def test_eps_n_matches_cli_every_preset(preset):
    want = cli("eps", "--preset", preset, "--g", ",".join(map(repr, SPEEDS)), "--accuracy", "precise")
    got = rime.eps_n(np.array(SPEEDS), rime.Scene.preset(preset))
    # The array path takes the core's hot path (one log, the table, one exp) where `rime eps`
    # reports the full record: the same table, so a few ulps apart (the level's bound is 1e-10).
    for w, g in zip(want, got):
        assert g == pytest.approx(w["eps_n"], rel=1e-13, abs=0.0), (preset, w["g_n"])


@pytest.mark.parametrize("preset", PRESETS)
def test_fast_batch_within_its_bound(preset):
    """The fast level (the batch path) keeps its documented bound 1e-6 against precise."""
    scene = rime.Scene.preset(preset)
    g = np.logspace(-6, 1, 2001)
    fast = rime.eps_n(g, scene, accuracy="fast")
    precise = rime.eps_n(g, scene)
    mask = precise > 1e-6
    assert np.all(np.abs(fast[mask] / precise[mask] - 1) <= 1e-6)
    assert np.array_equal(fast[~mask] == 0, precise[~mask] == 0)


def test_shapes_and_scalars():
    scene = rime.Scene.preset("ice")
    assert isinstance(rime.eps_n(0.01, scene), float)
    g = np.array([[1e-3, 1e-2, 0.1], [1.0, 2.0, 3.0]])
    out = rime.eps_n(g, scene)
    assert out.shape == (2, 3) and out.dtype == np.float64
    # A strided (non-contiguous) view gives the values of its elements.
    assert np.array_equal(rime.eps_n(g[:, ::2], scene), out[:, ::2])
    assert np.array_equal(rime.eps_n([1e-3, 1e-2], scene), out[0, :2])
    # 0 is the at-rest limit ε_N → 1 of the viscoelastic law.
    assert rime.eps_n(0.0, scene) == 1.0


def test_scene_set_with_units_matches_cli_set():
    scene = rime.Scene.preset("ice-frost")
    scene.set("layer.thickness", "2 um")
    scene.set("layer.viscosity", 2000)
    scene.set("grains.radius_1", "1 cm")
    want = cli("eps", "--preset", "ice-frost", "--set", "layer.thickness=2 um", "--set",
               "layer.viscosity=2000", "--set", "grains.radius_1=1 cm", "--g", "0.001,0.01,0.1")
    got = rime.eps_n([0.001, 0.01, 0.1], scene)
    assert list(got) == [w["eps_n"] for w in want]
    assert scene.get("layer.thickness") == 2e-6
    scene.set("adhesion", True)
    assert scene.get("adhesion") is True
    scene.set("adhesion", "off")
    assert scene.get("adhesion.surface_energy") is None


def test_from_json_round_trips_the_cli_scene():
    text = json.dumps(cli("scene", "--preset", "ice-sticky"))
    assert rime.Scene.from_json(text) == rime.Scene.preset("ice-sticky")
    assert rime.Scene.from_json(rime.Scene.preset("ice-frost").to_json()) == rime.Scene.preset("ice-frost")


@pytest.mark.parametrize("g_n,g_t", [(0.01, 0.0005), (0.01, 0.001), (0.002, 0.05), (1e-4, 0.03),
                                     (0.3, 0.2)])
@pytest.mark.parametrize("preset", ["ice", "ice-frost", "ice-sticky"])
def test_eps_t_matches_cli_tangential(preset, g_n, g_t):
    want = cli("tangential", "--preset", preset, "--gn", repr(g_n), "--gt", repr(g_t),
               "--accuracy", "precise")[0]
    scene = rime.Scene.preset(preset)
    assert rime.eps_t(g_n, g_t, scene) == pytest.approx(want["eps_t"], rel=1e-15, abs=1e-300)
    t = rime.tangential(g_n, [g_t], scene)
    assert t["class"] == [want["class"]]


def test_eps_t_rolling_branch_is_minus_eps_n_of_g_t():
    """Eq. (26), top: ε_T = −ε_N(g_T) while g_T < (μ/κ) g_N."""
    scene = rime.Scene.preset("ice")
    g_t = np.array([1e-4, 1e-3, 5e-3])
    assert np.allclose(rime.eps_t(0.01, g_t, scene), -rime.eps_n(g_t, scene), rtol=0, atol=1e-15)


def test_thresholds_closed_forms_and_cli_status():
    frost = rime.Scene.preset("ice-frost")
    r, rho = frost.get("grains.radius_1"), frost.get("grains.density")
    m_eff = 0.5 * rho * 4 / 3 * math.pi * r**3
    # Eq. (10): g_s = √R_eff η* D^(3/2) / m_eff.
    g_s = math.sqrt(r / 2) * frost.get("layer.viscosity") * frost.get("layer.thickness") ** 1.5 / m_eff
    t = rime.thresholds(frost)
    assert t["layer"] == pytest.approx(g_s, rel=1e-14)
    assert t["adhesion"] is None
    sticky = rime.thresholds(rime.Scene.preset("ice-sticky"))
    v = sticky["stick"]
    below, above = cli("eps", "--preset", "ice-sticky", "--g", f"{v * (1 - 1e-9)!r},{v * (1 + 1e-9)!r}")
    assert below["status"] == "stuck_by_adhesion" and above["status"] == "rebound"
    assert rime.thresholds(rime.Scene.preset("ice"))["stick"] is None


def test_collision_matches_cli():
    want = cli("collision", "--preset", "ice-frost", "--g", "0.01", "--gt", "0.005", "--points", "50")
    got = rime.collision(0.01, rime.Scene.preset("ice-frost"), g_t=0.005, points=50)
    assert sorted(got) == sorted(want)
    for key in ("g", "eps_n", "status", "t_c", "xi_max", "resolved", "ledger", "phases", "tangential"):
        assert got[key] == want[key], key
    for key in ("t", "xi", "xi_dot", "force"):
        assert list(got[key]) == want[key], key


def test_data_law_and_compare():
    g = np.array([1e-4, 1e-3, 1e-2])
    want = [r["eps_n"] for r in cli("data", "--law", "bridges1984", "--g", "0.0001,0.001,0.01")]
    assert list(rime.data.law("bridges1984")(g)) == pytest.approx(want, rel=1e-15)
    scene = rime.Scene.preset("ice")
    out = rime.compare(["hertzsch2002", "schwager_poschel2008"], g, scene)
    cmp = cli("compare", "--preset", "ice", "--models", "hertzsch2002,schwager_poschel2008",
              "--g", "0.0001,0.001,0.01")
    for name in ("hertzsch2002", "schwager_poschel2008"):
        want = [r["eps_n"] for r in cmp["records"] if r["model"] == name]
        assert list(out[name]) == pytest.approx(want, rel=1e-15)


def test_gil_is_released_while_computing():
    """Another Python thread runs while eps_n works through a large array.

    Whatever the machine's speed (issue 34): with a switch interval far longer than the call, a
    thread holding the GIL is never made to give it up, so the counting thread can only run
    inside the call if eps_n releases the GIL. It counts while it may (it gives the GIL back at
    every tick); the count read just before the call and just after it (the main thread holds the
    GIL between those reads and the call) differ only by ticks made inside the call."""
    scene = rime.Scene.preset("ice")
    g = np.logspace(-6, 0, 4_000_000)
    ticks = []
    done = threading.Event()
    running = threading.Event()

    def count():
        running.set()
        while not done.is_set():
            ticks.append(1)
            time.sleep(0)  # gives the GIL back: the main thread is never kept waiting for it

    interval = sys.getswitchinterval()
    t = threading.Thread(target=count)
    t.start()
    running.wait()
    sys.setswitchinterval(1000.0)
    try:
        before = len(ticks)
        rime.eps_n(g, scene, accuracy="precise")
        inside = len(ticks) - before
    finally:
        sys.setswitchinterval(interval)
        done.set()
        t.join()
    assert inside > 0


@pytest.mark.parametrize("call,field", [
    (lambda: rime.Scene.preset("granite"), "name: unknown preset 'granite'"),
    (lambda: rime.Scene.preset("ice").set("layer.thicknes", 1e-6), "layer.thicknes: unknown parameter"),
    (lambda: rime.Scene.preset("ice").set("grains.density", -5), "grains.density"),
    (lambda: rime.Scene.preset("ice").set("grains.radius_1", "2 kg"), "grains.radius_1"),
    (lambda: rime.Scene.preset("ice").set("grains.radius_1", [1]), "grains.radius_1"),
    (lambda: rime.Scene.from_json('{"grains": {"radius_1": 0.02, "radius_2": 0.02, "densty": 1}}'),
     "grains"),
    (lambda: rime.Scene.from_json("not json"), "scene"),
    (lambda: rime.eps_n([0.01, float("nan")], rime.Scene()), "g[1]"),
    (lambda: rime.eps_n([0.01, 2e6], rime.Scene()), "g[1]"),
    (lambda: rime.eps_n(["a"], rime.Scene()), "g:"),
    (lambda: rime.eps_n(0.01, rime.Scene(), accuracy="quick"), "accuracy"),
    (lambda: rime.eps_n(0.01, rime.Scene(), accuracy=1e-8), "accuracy"),
    (lambda: rime.eps_n(0.01, "ice"), "scene: expected a rime_grains.Scene"),
    (lambda: rime.thresholds(rime.Scene(), accuracy="1e-30"), "accuracy: a tolerance"),
    (lambda: rime.collision(float("nan"), rime.Scene()), "g[0]"),
    (lambda: rime.data.law("bridges1984")(0.01, radius=-1.0), "radius"),
    (lambda: rime.compare(["thornton1997"], [0.01], rime.Scene()), "thornton1997: plasticity.yield_pressure"),
    (lambda: rime.eps_t([0.01, 0.02], [0.1, 0.2, 0.3], rime.Scene()), "g_n, g_t"),
    (lambda: rime.eps_t(0.0, 0.01, rime.Scene()), "g_n[0]"),
    (lambda: rime.collision(0.01, rime.Scene(), points=1), "points"),
    (lambda: rime.data.law("nope"), "id: unknown law"),
    (lambda: rime.compare(["nope"], [0.01], rime.Scene()), "models: unknown model 'nope'"),
])
def test_bad_input_raises_value_error_naming_the_field(call, field):
    with pytest.raises(ValueError) as e:
        call()
    assert str(e.value).startswith(field) or field in str(e.value).split(":")[0], str(e.value)


def test_failed_set_leaves_the_scene_unchanged():
    scene = rime.Scene.preset("ice")
    with pytest.raises(ValueError):
        scene.set("bulk.poisson_ratio", 0.7)
    assert scene == rime.Scene.preset("ice")


def test_eps_t_needs_friction():
    scene = rime.Scene.preset("ice")
    scene.set("friction", "off")
    with pytest.raises(ValueError, match="^scene.friction"):
        rime.eps_t(0.01, 0.001, scene)


def test_type_stubs_are_shipped_and_cover_the_api():
    import ast
    import pathlib

    package = pathlib.Path(rime.__file__).parent
    assert (package / "py.typed").exists()
    for module, stub in ((rime, "__init__.pyi"), (rime.rebound, "rebound.pyi"), (rime.data, "data.pyi"),
                         (rime.dustpy, "dustpy.pyi")):
        tree = ast.parse((package / stub).read_text(encoding="utf-8"))
        names = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
        names |= {t.id for n in tree.body if isinstance(n, ast.AnnAssign) for t in [n.target]}
        names |= {a.asname or a.name for n in tree.body if isinstance(n, ast.ImportFrom) for a in n.names}
        missing = [name for name in module.__all__ if name not in names]
        assert not missing, (stub, missing)


def test_jkr_end_is_a_scene_key_issue_25():
    # Issue 25: where the JKR contact ends is a scene key in Python too; brilliantov2007 reads it.
    # Expected values: the `rime` binary's `compare` with the same --set (6.3e-4 m/s lies between
    # the pull-off end's g_cr, 0.579 mm/s, and the neck's, 0.692 mm/s, on ice-sticky).
    g = [6.3e-4, 0.01]
    for end in ["neck", "pull_off_force"]:
        scene = rime.Scene.preset("ice-sticky")
        scene.set("adhesion.jkr_end", end)
        assert scene.get("adhesion.jkr_end") == end
        want = cli("compare", "--preset", "ice-sticky", "--set", f"adhesion.jkr_end={end}",
                   "--models", "brilliantov2007", "--g", "6.3e-4,0.01")["records"]
        got = rime.compare(["brilliantov2007"], g, scene)["brilliantov2007"]
        assert list(got) == [w["eps_n"] for w in want]
        assert (got[0] == 0.0) == (end == "neck")
    with pytest.raises(ValueError, match="adhesion.jkr_end"):
        rime.Scene.preset("ice-sticky").set("adhesion.jkr_end", "halfway")
