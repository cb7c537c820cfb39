"""rime's laws as a REBOUND collision handler, set at run time (native code in this wheel).

``attach(sim, scene, length_unit=..., time_unit=..., mass_unit=...)`` sets
``sim.collision_resolve``: every collision REBOUND finds gets ε_N (Eq. (4)–(17)) and ε_T (Eq. (26))
of the scene for the two particles' radii, and the spin change of one impulse at the contact point
(Eq. (1)–(2)); pairs that stick merge or stay apart (``sticking``). No C compiler is needed.

What the handler uses
    * the radii of the two particles (``p.r``), not the scene's ``grains.radius_*``;
    * ``density="particles"`` (default): each particle's own density m / (4/3 π r³) — exactly, the
      model gets the effective mass m₁m₂/(m₁+m₂) of the two REBOUND masses; ``density="scene"``:
      the scene's ``grains.density`` for ε_N (the impulses always use the REBOUND masses, so
      momentum is exact either way);
    * every other parameter (Young's modulus, A, layer, adhesion, friction, …) from ``scene``,
      fixed at attach time (attach again to change it).

Units: ``length_unit``, ``time_unit`` and ``mass_unit`` say what one code unit is, as a number in
SI (metres, seconds, kilograms) or a string such as ``"cm"``, ``"min"``, ``"g"``, ``"1 AU"``,
``"1 yr"``. Spins are in radians per code time unit.

Sticking (ε_N = 0: stuck in the layer or by adhesion)
    * ``"merge"``: the two become one grain (mass, volume, momentum and angular momentum kept);
    * ``"stay"``: they stay two grains with ε_N = 0 and the tangential outcome the core gives
      (ε_T of the class ``normal_stick_only``, …); ``sim.minimum_collision_velocity`` is honoured
      as a floor on the normal separation speed (code units) of every bounce;
    * ``"merge_if_slow"``: merge only when the tangential speed is also below the pair's sticking
      speed (``rime.thresholds(scene)["stick"]`` for the pair's radii), else stay.

Spins live in an array owned by the returned ``Attachment``; each particle's ``ap`` points into it
(REBOUNDx uses ``ap`` too: with REBOUNDx attached, use ``track_spins=False``). REBOUND does not save
``ap``: use ``Attachment.save(filename)`` and ``load_spins(filename, sim)`` (see ``attach``).
"""

import ctypes
import json
import os
import re

import numpy as np

from . import _native

__all__ = ["attach", "load_spins", "Attachment", "REBOUND_VERSION", "unit"]

#: The REBOUND version this handler is built and tested for; others are refused.
REBOUND_VERSION = _native.REBOUND_VERSION

_UNITS = {
    # length [m]
    "m": 1.0, "km": 1e3, "cm": 1e-2, "mm": 1e-3, "um": 1e-6, "µm": 1e-6,
    "au": 1.495978707e11, "AU": 1.495978707e11,
    # time [s]
    "s": 1.0, "ms": 1e-3, "min": 60.0, "h": 3600.0, "hr": 3600.0, "d": 86400.0, "day": 86400.0,
    "yr": 365.25 * 86400.0, "year": 365.25 * 86400.0,
    # mass [kg]
    "kg": 1.0, "g": 1e-3, "mg": 1e-6, "t": 1e3,
}
_DIMENSION = {
    "length_unit": {"m", "km", "cm", "mm", "um", "µm", "au", "AU"},
    "time_unit": {"s", "ms", "min", "h", "hr", "d", "day", "yr", "year"},
    "mass_unit": {"kg", "g", "mg", "t"},
}

# Simulations with a handler: address -> _Link (keeps the handler and the spin arrays the particles'
# ap point to alive while REBOUND may call the handler; not the simulation itself, so a simulation
# nobody refers to is still freed).
_ATTACHED = {}


class _Link:
    def __init__(self, handler):
        self.handler = handler
        self.storage = []  # spin arrays (the particles' ap point into them)

    def owns(self, address):
        return any(a.ctypes.data <= address < a.ctypes.data + a.nbytes for a in self.storage)


def unit(field, value):
    """One code unit in SI: a positive number, or a string ``"[number] unit"``.

    >>> from rime_grains.rebound import unit
    >>> unit("length_unit", "cm"), unit("time_unit", "2 min"), unit("mass_unit", 1e-3)
    (0.01, 120.0, 0.001)
    >>> unit("time_unit", "cm")
    Traceback (most recent call last):
    ...
    ValueError: time_unit: 'cm' is not a time (use s, ms, min, h, hr, d, day, yr, year or a number of seconds)
    """
    if isinstance(value, str):
        m = re.fullmatch(r"\s*([0-9.eE+-]+)?\s*([A-Za-zµ]+)\s*", value)
        allowed = _DIMENSION[field]
        if m is None or m.group(2) not in allowed:
            kind = {"length_unit": "length", "time_unit": "time", "mass_unit": "mass"}[field]
            si = {"length_unit": "metres", "time_unit": "seconds", "mass_unit": "kilograms"}[field]
            names = [u for u in _UNITS if u in allowed]
            raise ValueError(f"{field}: {value!r} is not a {kind} (use {', '.join(names)} or a number of {si})")
        number = float(m.group(1)) if m.group(1) else 1.0
        value = number * _UNITS[m.group(2)]
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{field}: expected a positive number or a unit string (got {value!r})") from None
    if not (np.isfinite(v) and v > 0):
        raise ValueError(f"{field}: must be finite and > 0 (got {value!r})")
    return v


def _rebound():
    import rebound

    if rebound.__version__ != REBOUND_VERSION:
        raise RuntimeError(
            f"rime_grains.rebound supports rebound {REBOUND_VERSION} (the version it pins and is "
            f"tested with); this is rebound {rebound.__version__}: pip install rebound=={REBOUND_VERSION}"
        )
    return rebound


def _layout(rebound):
    """Byte offsets of the fields the handler reads, from rebound's own ctypes classes (rebound
    checks those against its C library), checked for the assumptions the handler makes."""
    P, S = rebound.Particle, rebound.Simulation
    for a, b in (("x", "y"), ("y", "z"), ("vx", "vy"), ("vy", "vz")):
        if getattr(P, b).offset != getattr(P, a).offset + 8:
            raise RuntimeError(f"rebound {rebound.__version__}: unexpected reb_particle layout ({a}, {b})")
    size, offsets = _native.collision_layout()
    C = rebound.CollisionS
    theirs = (ctypes.sizeof(C), [C.p1.offset, C.p2.offset, C.gb.offset, C.ri.offset])
    if (size, list(offsets)) != (theirs[0], theirs[1]):
        raise RuntimeError(f"rebound {rebound.__version__}: reb_collision is {theirs}, the handler's {(size, offsets)}")
    return {
        "particles": S._particles.offset,
        "N": S.N.offset,
        "status": S._status.offset,
        "minimum_collision_velocity": S.minimum_collision_velocity.offset,
        "particle_size": ctypes.sizeof(P),
        "x": P.x.offset,
        "vx": P.vx.offset,
        "m": P.m.offset,
        "r": P.r.offset,
        "ap": P.ap.offset,
    }


class Attachment:
    """rime's handler on one simulation: its spins, counters and first error.

    Returned by ``attach``; the module keeps it alive until ``detach()`` or a new ``attach`` to the
    same simulation.
    """

    def __init__(self, sim, link, track_spins, description):
        self._sim = sim
        self._link = link
        self._handler = link.handler
        self._track = track_spins
        self._description = description

    def __repr__(self):
        return f"<rime_grains.rebound.Attachment: {self._description}>"

    @property
    def error(self):
        """The first error the handler met, or ``None``. On an error the handler stops the
        integration (``sim.integrate`` raises ``rebound.GenericError``) and leaves the pair as it was."""
        return self._handler.error

    def counts(self):
        """How many collisions bounced, merged, or stuck and stayed apart."""
        return self._handler.counts()

    @property
    def cached_pairs(self):
        """Number of (radius, mass) pairs whose contact constants are cached."""
        return self._handler.cached_pairs

    def track_spins(self, spins=None):
        """Gives every particle a spin slot (``ap``), initialised from ``spins`` (an (N, 3) array,
        rad per code time) or from the particle's current spin. Call it again after adding
        particles; particles without a slot have spin 0 and their spin is not updated."""
        if not self._track:
            raise ValueError("track_spins: this attachment was made with track_spins=False")
        sim = self._sim
        n = sim.N
        current = self.spins if spins is None else np.asarray(spins, dtype=float)
        if current.shape != (n, 3):
            raise ValueError(f"spins: expected shape ({n}, 3) (got {current.shape})")
        if not np.all(np.isfinite(current)):
            raise ValueError("spins: every value must be finite")
        storage = np.ascontiguousarray(current, dtype=np.float64).copy()
        base = storage.ctypes.data
        for k in range(n):
            sim.particles[k].ap = base + 24 * k
        self._link.storage = [storage]  # older arrays are no longer pointed to
        return storage

    @property
    def spins(self):
        """The particles' angular velocities, an (N, 3) array [rad per code time] (a copy)."""
        sim = self._sim
        out = np.zeros((sim.N, 3))
        if not self._track:
            return out
        for k in range(sim.N):
            ap = sim.particles[k].ap
            if ap:
                w = ctypes.cast(ap, ctypes.POINTER(ctypes.c_double))
                out[k] = (w[0], w[1], w[2])
        return out

    def save(self, filename):
        """Saves the simulation (``sim.save_to_file(filename)``, appending a snapshot) and its spins
        to ``filename + ".spins"`` (one JSON line per snapshot: time, N and the spins).

        Reload with ``sim = rebound.Simulation(filename)`` (the last snapshot) and
        ``attach(sim, scene, ..., spins=load_spins(filename, sim))``."""
        self._sim.save_to_file(filename)
        record = {"t": self._sim.t, "N": self._sim.N, "spins": self.spins.tolist()}
        with open(filename + ".spins", "a", encoding="utf-8") as f:
            f.write(json.dumps(record) + "\n")

    def detach(self):
        """Unregisters the handler and restores REBOUND's default (``"hardsphere"``)."""
        self._sim.collision_resolve = "hardsphere"
        self._handler.detach()
        _ATTACHED.pop(ctypes.addressof(self._sim), None)


def load_spins(filename, sim):
    """The spins saved by ``Attachment.save(filename)`` for the snapshot ``sim`` was loaded from
    (matched by time and N), as an (N, 3) array for ``attach(..., spins=...)``."""
    path = filename + ".spins"
    if not os.path.exists(path):
        raise ValueError(f"filename: no spin file {path!r} (save with Attachment.save)")
    found = None
    with open(path, encoding="utf-8") as f:
        for line in f:
            record = json.loads(line)
            if record["t"] == sim.t and record["N"] == sim.N:
                found = record
    if found is None:
        raise ValueError(f"filename: {path!r} has no spins for t = {sim.t!r}, N = {sim.N}")
    return np.array(found["spins"], dtype=float).reshape(sim.N, 3)


def attach(sim, scene, *, length_unit, time_unit, mass_unit, density="particles",
           sticking="merge", track_spins=True, accuracy="precise", spins=None):
    """Sets ``sim.collision_resolve`` to rime's handler for ``scene``; returns the ``Attachment``.

    ``length_unit``, ``time_unit``, ``mass_unit``: one code unit in SI (a number) or as a string
    (``"cm"``, ``"min"``, ``"g"``, ``"1 AU"``). ``density``: ``"particles"`` or ``"scene"``;
    ``sticking``: ``"merge"``, ``"stay"`` or ``"merge_if_slow"`` (see the module documentation);
    ``accuracy``: the level of ε_N and ε_T (default ``"precise"``); ``spins``: initial spins, an
    (N, 3) array [rad per code time].

    >>> import rebound, rime_grains as rime
    >>> sim = rebound.Simulation()
    >>> sim.gravity, sim.collision = "none", "direct"
    >>> m = 900 * 4 / 3 * 3.141592653589793 * 0.02**3
    >>> sim.add(m=m, r=0.02, x=-0.021, vx=0.005)
    >>> sim.add(m=m, r=0.02, x=0.021, vx=-0.005)
    >>> ice = rime.Scene.preset("ice")
    >>> att = rime.rebound.attach(sim, ice, length_unit=1, time_unit=1, mass_unit=1)
    >>> sim.integrate(1.0)
    >>> eps = (sim.particles[1].vx - sim.particles[0].vx) / 0.01
    >>> bool(abs(eps - rime.eps_n(0.01, ice)) < 1e-12)
    True
    """
    rebound = _rebound()
    if not isinstance(sim, rebound.Simulation):
        raise ValueError(f"sim: expected a rebound.Simulation (got {type(sim).__name__})")
    if not isinstance(scene, _native.Scene):
        raise ValueError(f"scene: expected a rime_grains.Scene (got {type(scene).__name__})")
    units = {f: unit(f, v) for f, v in
             (("length_unit", length_unit), ("time_unit", time_unit), ("mass_unit", mass_unit))}
    if not isinstance(track_spins, bool):
        raise ValueError(f"track_spins: expected True or False (got {track_spins!r})")
    if spins is not None:
        if not track_spins:
            raise ValueError("spins: given with track_spins=False")
        spins = np.asarray(spins, dtype=float)
        if spins.shape != (sim.N, 3):
            raise ValueError(f"spins: expected shape ({sim.N}, 3) (got {spins.shape})")
        if not np.all(np.isfinite(spins)):
            raise ValueError("spins: every value must be finite")
    address = ctypes.addressof(sim)
    previous = _ATTACHED.get(address)
    if track_spins:
        if sim.extras:
            raise ValueError(
                "track_spins: this simulation has an extension attached (sim.extras is set, e.g. "
                "REBOUNDx), which uses the particles' ap pointers that rime's spins need; attach "
                "with track_spins=False (spins are then 0 and not updated)")
        for k in range(sim.N):
            ap = sim.particles[k].ap
            if ap and not (previous is not None and previous.owns(ap)):
                raise ValueError(
                    f"track_spins: particle {k} has an ap pointer rime did not set (REBOUNDx or user "
                    "data); attach with track_spins=False or clear it")
    handler = _native._attach(address, _layout(rebound), scene, units["length_unit"],
                              units["time_unit"], units["mass_unit"], density, sticking,
                              track_spins, accuracy)
    link = _Link(handler)
    g = scene.get("grains.density")
    description = (
        f"eps_N and eps_T from the scene with each pair's own radii and "
        + ("the particles' own density (m_eff of their masses)" if density == "particles"
           else f"the scene's density {g:g} kg/m3 (impulses use the particles' masses)")
        + f"; sticking={sticking!r}, accuracy={accuracy!r}, units: {units['length_unit']:g} m, "
        f"{units['time_unit']:g} s, {units['mass_unit']:g} kg; spins "
        + ("tracked through ap" if track_spins else "not tracked (0)"))
    attachment = Attachment(sim, link, track_spins, description)
    if track_spins:
        if spins is None and previous is not None:
            spins = attachment.spins  # the previous attachment's, read through ap
        attachment.track_spins(spins if spins is not None else np.zeros((sim.N, 3)))
    sim.collision_resolve = handler.function_address
    _ATTACHED[address] = link
    return attachment
