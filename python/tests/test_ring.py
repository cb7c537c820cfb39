"""Issue 24: `rime_grains.ring.equilibrium` against `rime ring`, and a reduced shearing-sheet check
(scripts/ring-nbody.py with 100 particles, 4 orbits, 3 seeds) with the script's tolerance."""
import importlib.util
import math

import numpy as np
import pytest

import rime_grains as rime
from conftest import ROOT, cli

spec = importlib.util.spec_from_file_location("ring_nbody", ROOT / "scripts" / "ring-nbody.py")
nbody = importlib.util.module_from_spec(spec)
spec.loader.exec_module(nbody)

OMEGA = nbody.OMEGA


def test_python_and_cli_agree_to_the_digit():
    for radius, extra, kwargs in [(0.02, [], {}), (1.0, [], {}),
                                  (1.0, ["--scale-damping"], {"scale_damping": True})]:
        py = rime.ring.equilibrium(rime.Scene.preset("ice"), tau=0.5, omega=OMEGA, radius=radius,
                                   **kwargs)
        js = cli("ring", "--preset", "ice", "--tau", 0.5, "--omega", OMEGA, "--radius", radius,
                 *extra)
        for key in ("verdict", "equilibrium", "verdict_words", "velocity_dispersion", "thickness",
                    "eps_cr", "scaled_damping_time"):
            assert py[key] == js[key], key
        # The note names the flag or the keyword: the same statement.
        assert (py["damping_note"] is None) == (js["damping_note"] is None)
        if py["damping_note"]:
            assert "different material" in py["damping_note"] and "different material" in js["damping_note"]
        assert py["smooth"] == js["smooth"] and py["rough"] == js["rough"]


def test_bad_input_names_the_field():
    ice = rime.Scene.preset("ice")
    with pytest.raises(ValueError, match="^omega: required"):
        rime.ring.equilibrium(ice, tau=0.5)
    with pytest.raises(ValueError, match="^distance: required"):
        rime.ring.equilibrium(ice, tau=0.5, planet_mass=5.7e26)
    with pytest.raises(ValueError, match="^scale_damping"):
        rime.ring.equilibrium(ice, tau=0.5, omega=OMEGA, scale_damping=True)
    with pytest.raises(ValueError, match="^new_radius"):
        rime.ring.scaled_damping_time(1e-4, 0.02, -1.0)


def measure(index, n=100, orbits=6.0, seeds=3):
    name, radius, tau, scale, friction, start, expect = nbody.CASES[index]
    pred = rime.ring.equilibrium(nbody.scene_for(0.02, False, friction), tau=tau, omega=OMEGA,
                                 radius=radius, scale_damping=scale)
    scene = nbody.scene_for(radius, scale, friction)
    c0 = pred["velocity_dispersion"] * start if start else 2 * radius * OMEGA
    room = 10.0 if expect == "stay" else 400.0
    runs = [nbody.run(radius, tau, scene, c0, n, orbits, 1000 + s, room) for s in range(seeds)]
    return pred, runs


# Index into scripts/ring-nbody.py's CASES: the dense patches (the floors and the 2 cm smooth
# balance). Not here: the dilute patch (it equilibrates over ~10² orbits; the script runs it).
@pytest.mark.parametrize("index", [1, 2, 3, 4])
def test_shearing_sheet_matches_the_prediction_within_a_factor_two(index):
    pred, runs = measure(index)
    c = np.mean([r[0] for r in runs]) / pred["velocity_dispersion"]
    h = np.mean([r[1] for r in runs]) / pred["thickness"]
    assert abs(math.log(c)) <= nbody.TOLERANCE and abs(math.log(h)) <= nbody.TOLERANCE, (c, h)


def test_the_metre_patch_with_the_preset_a_heats():
    pred, runs = measure(5)
    assert pred["verdict"] == "heats"
    assert all(r[2][-1] / r[2][0] > 2.0 for r in runs)


def test_issue_35_a_given_for_the_radius_grains_needs_no_scaling(rime_cli):
    """A set for the 1 m grains of `radius` (damping_set_for=1): no A', no note, the record of a
    scene whose own grains are 1 m, which is what `rime ring` gives for those grains."""
    ice = rime.Scene.preset("ice")
    ice.set("bulk.damping.time", 5e-3)
    given = rime.ring.equilibrium(ice, tau=0.5, omega=OMEGA, radius=1.0, damping_set_for=1.0)
    assert given["damping_note"] is None and given["scaled_damping_time"] is None
    want = rime_cli("ring", "--preset", "ice", "--set", "bulk.damping.time=5e-3", "--set", "grains.radius_1=1",
                    "--set", "grains.radius_2=1", "--tau", "0.5", "--omega", repr(OMEGA))
    assert given["velocity_dispersion"] == want["velocity_dispersion"] and given["verdict"] == want["verdict"]
    noted = rime.ring.equilibrium(ice, tau=0.5, omega=OMEGA, radius=1.0)
    assert noted["scaled_damping_time"] == pytest.approx(0.25, rel=1e-12)
    with pytest.raises(ValueError, match="^damping_set_for"):
        rime.ring.equilibrium(ice, tau=0.5, omega=OMEGA, radius=1.0, damping_set_for=-1.0)


def test_issue_38_a_ring_of_many_sizes_agrees_with_the_cli_to_the_digit():
    ice = rime.Scene.preset("ice")
    cases = [
        (dict(radius_min=0.01, radius_max=0.05, q=3),
         ["--radii", "0.01..0.05", "--q", 3]),
        (dict(radius_min=0.01, radius_max=0.05, q=3, bins=5, damping_rule="keep_epsilon"),
         ["--radii", "0.01..0.05", "--q", 3, "--bins", 5, "--damping-rule", "keep_epsilon"]),
        (dict(radii=[0.01, 0.02, 0.05], fractions=[0.6, 0.3, 0.1]),
         ["--radii", "0.01,0.02,0.05", "--fractions", "0.6,0.3,0.1"]),
    ]
    for kwargs, flags in cases:
        py = rime.ring.equilibrium(ice, tau=0.5, omega=OMEGA, **kwargs)
        js = cli("ring", "--preset", "ice", "--tau", 0.5, "--omega", OMEGA, *flags)
        assert py == js
        assert len(py["size_bins"]) == kwargs.get("bins", 3)
        nu = py["viscosity"]
        assert nu["total"] == nu["translational"] + nu["collisional"]
    # One size through radii is the one-size answer.
    one = rime.ring.equilibrium(ice, tau=0.5, omega=OMEGA, radii=[0.02])
    today = rime.ring.equilibrium(ice, tau=0.5, omega=OMEGA, radius=0.02)
    assert one["size_bins"][0]["velocity_dispersion"] == today["velocity_dispersion"]
    assert one["size_bins"][0]["thickness"] == today["thickness"]
    with pytest.raises(ValueError, match="^fractions:"):
        rime.ring.equilibrium(ice, tau=0.5, omega=OMEGA, radii=[0.01, 0.02], fractions=[0.5, 0.4])
    with pytest.raises(ValueError, match="^q:"):
        rime.ring.equilibrium(ice, tau=0.5, omega=OMEGA, radius_min=0.01, radius_max=0.05)
    with pytest.raises(ValueError, match="^damping_rule:"):
        rime.ring.equilibrium(ice, tau=0.5, omega=OMEGA, radii=[0.02], damping_rule="other")
    with pytest.raises(ValueError, match="^radii:"):
        rime.ring.equilibrium(ice, tau=0.5, omega=OMEGA, radii=[0.02], radius=0.02)
