"""What the scene's law does to a ring: equilibrium velocity dispersion, thickness and verdict.

The model (a Grad-type moment closure of the non-gravitating shearing sheet: stress relaxation of
inelastic hard spheres, the Enskog collision rate, impacts averaged over a Gaussian velocity
distribution, a 2RΩ monolayer floor) and
where it stops holding are in docs/physics.md#ring of the repository; the fields are those of
``rime ring --format json`` (docs/cli.md#ring).

>>> import rime_grains as rime
>>> ice = rime.Scene.preset("ice")
>>> a_ring = rime.ring.equilibrium(ice, tau=0.5, omega=1.3143527e-4, radius=0.02)
>>> a_ring["verdict"], a_ring["equilibrium"], a_ring["smooth"]["verdict"]
('monolayer_floor', True, 'equilibrium')
>>> a_ring["verdict_words"]
'equilibrium at the monolayer floor'
>>> round(a_ring["velocity_dispersion_r_omega"], 6)
2.0
>>> metre = rime.ring.equilibrium(ice, tau=0.5, omega=1.3143527e-4, radius=1.0)
>>> metre["verdict"], metre["scaled_damping_time"]
('heats', 0.005)
>>> "different material" in metre["damping_note"]
True
>>> rime.ring.equilibrium(ice, tau=0.5, omega=1.3143527e-4, radius=1.0, scale_damping=True)["verdict"]
'monolayer_floor'
>>> rime.ring.equilibrium(ice, tau=0.0, omega=1e-4)
Traceback (most recent call last):
...
ValueError: tau: must lie in (0, 5] (got 0)
"""

from . import _native

__all__ = ["equilibrium", "scaled_damping_time"]


def equilibrium(scene, *, tau, omega=None, planet_mass=None, distance=None, radius=None,
                scale_damping=False, damping_set_for=None, radius_min=None, radius_max=None,
                q=None, bins=3, radii=None, fractions=None, damping_rule="same"):
    """The ring's equilibrium for ``scene`` at optical depth ``tau``.

    Give ``omega`` [1/s], or ``planet_mass`` [kg] and ``distance`` [m] (Ω = √(GM/d³)). ``radius``
    [m] sets both grains. ``scale_damping=True`` replaces A by A′ = A·R/R_scene, which keeps the
    scene's ε_N(g) for the new size: **a different material** (the result's ``damping_note`` says
    so). Without it, when ``radius`` differs from the scene's, ``scaled_damping_time`` reports A′.
    ``damping_set_for`` [m]: the grain radius the scene's A was given for, when not the scene's
    (``damping_set_for=radius`` after setting A for the ``radius`` grains: no A′, no note).

    Returns a dict: ``verdict`` (``equilibrium``, ``monolayer_floor``, ``aggregates``, ``heats``),
    ``equilibrium`` (True for the first two: the floor is a steady state too), ``verdict_words``,
    ``velocity_dispersion`` [m/s], ``thickness`` [m], ``mean_impact_speed`` [m/s], ``eps_cr``,
    ``eps_effective``, ``equilibration_orbits`` and the ``smooth`` and ``rough`` predictions.

    **A ring of many sizes** (issue 38; docs/physics.md#ring-sizes): ``radius_min``,
    ``radius_max`` [m] and ``q`` (dN/dR ∝ R^−q, ``bins`` bins equal in log R), or ``radii`` [m]
    with number ``fractions``; ``damping_rule`` is ``"same"`` (the scene's A for every pair) or
    ``"keep_epsilon"`` (every pair keeps the scene's ε_N(g)). Returns the dict of
    ``rime ring --radii … --format json``: ``size_bins`` (per bin ``radius_min``, ``radius_max``,
    ``velocity_dispersion``, ``thickness``, …), ``viscosity`` (``translational``, ``collisional``,
    ``total`` [m²/s], ``dlnnu_dlntau``, ``overstability``), the ring-wide number-weighted
    ``velocity_dispersion`` and ``thickness``, and the ``verdict``.

    >>> import rime_grains as rime
    >>> r = rime.ring.equilibrium(rime.Scene.preset("ice"), tau=0.5, omega=1.3143527e-4,
    ...                           radius_min=0.01, radius_max=0.05, q=3)
    >>> len(r["size_bins"]), r["verdict"], r["viscosity"]["overstability"]
    (3, 'equilibrium', 'not_assessed')
    """
    from . import _scene
    if any(v is not None for v in (radius_min, radius_max, q, radii, fractions)) \
            or damping_rule != "same":
        if radius is not None or scale_damping or damping_set_for is not None:
            raise ValueError("radii: a ring of many sizes takes no radius, scale_damping or "
                             "damping_set_for (choose the A rule with damping_rule)")
        import json
        return json.loads(_native.ring_sizes_equilibrium(
            _scene(scene), tau=tau, omega=omega, planet_mass=planet_mass, distance=distance,
            radius_min=radius_min, radius_max=radius_max, q=q, bins=bins,
            radii=None if radii is None else [float(r) for r in radii],
            fractions=None if fractions is None else [float(f) for f in fractions],
            damping_rule=damping_rule))
    return _native.ring_equilibrium(_scene(scene), tau=tau, omega=omega, planet_mass=planet_mass,
                                    distance=distance, radius=radius, scale_damping=scale_damping,
                                    damping_set_for=damping_set_for)


def scaled_damping_time(damping_time, radius, new_radius):
    """A′ = A·R′/R [s]: the damping time grains of ``new_radius`` need to keep the ε_N(g) of grains
    of ``radius`` with ``damping_time``. A is a material constant: A′ describes a different material.

    >>> scaled_damping_time(1e-4, 0.02, 1.0)
    0.005
    """
    for name, v in (("damping_time", damping_time), ("radius", radius), ("new_radius", new_radius)):
        if not (isinstance(v, (int, float)) and v > 0 and v < float("inf")):
            raise ValueError(f"{name}: must be a finite number > 0 (got {v!r})")
    return damping_time * (new_radius / radius)
