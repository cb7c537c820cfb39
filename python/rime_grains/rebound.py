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
``"1 yr"``; ``time_unit="orbit"`` with ``omega=`` (Ω in 1/s) is one orbit, 2π/Ω, the unit of a
shearing sheet whose ``sim.OMEGA`` is 2π (checked when ``sim.OMEGA`` is set). Spins are in radians
per code time unit.

Sticking (ε_N = 0: stuck in the layer or by adhesion)
    * ``"merge"``: the two become one grain (mass, volume, momentum and angular momentum kept);
    * ``"stay"``: they stay two grains with ε_N = 0 and the tangential outcome the core gives
      (ε_T of the class ``normal_stick_only``, …); ``sim.minimum_collision_velocity`` is honoured
      as a floor on the normal separation speed (code units) of every bounce. With REBOUND's
      default floor 0, grains that stay stuck under a steady pull (gravity, the tidal field) sink
      into each other a little every step they touch (about 2 % of the radius per orbit in a 2 cm
      ring patch): set ``sim.minimum_collision_velocity`` to a speed well below the sticking speed
      (e.g. 1e-6 m/s in code units) to keep them apart; it turns a resting contact into slow
      bounces at that speed;
    * ``"merge_if_slow"``: merge only when the tangential speed is also below the pair's sticking
      speed (``rime.thresholds(scene)["stick"]`` for the pair's radii), else stay.

Spins live in the handler's own table, one per particle index (never in ``ap``, so REBOUNDx works
beside the handler whether it is created before or after ``attach``). The table follows REBOUND's
array: merges, and particles added at the end (spin 0); remove particles yourself only with
``att.track_spins(spins)`` afterwards (the handler stops with a message when N fell behind its
back). REBOUND's files keep no spins: ``Attachment.save(filename)`` writes them beside the snapshot,
and with REBOUND's periodic archive (``sim.save_to_file(filename, interval=...)``, ``step=``,
``walltime=``) the handler appends the spins of every snapshot to ``filename + ".spins"`` itself
(through ``sim.heartbeat``; a heartbeat set before attach still runs). ``load_spins(filename, sim)``
reads them back; ``attach`` refuses a simulation past t = 0 without ``spins=`` (a reloaded
simulation would otherwise restart its spins at 0 silently).

The contact constants of each pair of (radius, mass) are cached, at most ``cache_size`` pairs
(the least recently used go first); ``Attachment.cache_info()`` reports entries, hits and misses.

Counters over a window (issue 38; docs/physics.md#handler-counters)
    ``Attachment.counters(reset=False)`` reports, since the window began (``attach`` or the last
    reset), the collisions (bounces, stays, merges), the normal and tangential impact speeds
    (count, sum, sum of squares, max; a histogram of the normal speed with ``speed_edges=``), the
    overlaps REBOUND found them at (deeper than ``overlap_depth`` of r₁ + r₂, the deepest), and
    the collisional momentum transfer Σ m₁ Δv₁,y (x₁ − x₂) over the collisions (p₁'s change of
    y-velocity, x₁ − x₂ the radial distance across the pair, ghost-box shift included; positive
    when y-momentum flows toward +x). In a shearing sheet (``sim.OMEGA`` set) it gives
    ν_collisional = transfer / (duration · (3/2) Ω · Σ m), in m²/s; ``translational_viscosity()``
    gives ν_translational = Σ m u (v_y + (3/2) Ω x) / ((3/2) Ω Σ m) from the particles now. Per
    orbit: ``sim.integrate(t + orbit)`` then ``att.counters(reset=True)``, in a loop.
"""

import ctypes
import json
import os
import re

import numpy as np

from . import _native

__all__ = ["attach", "load_spins", "orbit", "Attachment", "REBOUND_VERSION", "unit"]

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

# Simulations with a handler: address -> _Link (keeps the handler and the heartbeat pointers alive
# while REBOUND may call them; not the simulation itself, so a simulation nobody refers to is still
# freed, and its registration is then dropped).
_ATTACHED = {}

#: The default number of (radius, mass) pairs whose contact constants are cached (~440 B each).
CACHE_SIZE = 4096


class _Link:
    def __init__(self, handler, previous_heartbeat):
        self.handler = handler
        # The heartbeat set before attach (restored by detach); its ctypes object stays alive here.
        self.previous_heartbeat = previous_heartbeat
        self.heartbeat = None


def orbit(omega):
    """Seconds of one orbit at the orbital frequency ``omega`` [1/s]: 2π/Ω (for ``time_unit``).

    >>> from rime_grains.rebound import orbit
    >>> round(orbit(1.3143527e-4))
    47804
    >>> orbit(0)
    Traceback (most recent call last):
    ...
    ValueError: omega: the orbital frequency must be finite and > 0 1/s (got 0)
    """
    try:
        w = float(omega)
    except (TypeError, ValueError):
        raise ValueError(f"omega: expected the orbital frequency in 1/s (got {omega!r})") from None
    if not (np.isfinite(w) and w > 0):
        raise ValueError(f"omega: the orbital frequency must be finite and > 0 1/s (got {omega!r})")
    return 2 * np.pi / w


def unit(field, value):
    """One code unit in SI: a positive number, or a string ``"[number] unit"``.

    >>> from rime_grains.rebound import unit
    >>> unit("length_unit", "cm"), unit("time_unit", "2 min"), unit("mass_unit", 1e-3)
    (0.01, 120.0, 0.001)
    >>> unit("time_unit", "cm")
    Traceback (most recent call last):
    ...
    ValueError: time_unit: 'cm' is not a time (use s, ms, min, h, hr, d, day, yr, year or 'orbit' with omega= or a number of seconds)
    """
    if isinstance(value, str):
        m = re.fullmatch(r"\s*([0-9.eE+-]+)?\s*([A-Za-zµ]+)\s*", value)
        allowed = _DIMENSION[field]
        if m is None or m.group(2) not in allowed:
            kind = {"length_unit": "length", "time_unit": "time", "mass_unit": "mass"}[field]
            si = {"length_unit": "metres", "time_unit": "seconds", "mass_unit": "kilograms"}[field]
            names = [u for u in _UNITS if u in allowed]
            extra = " or 'orbit' with omega=" if field == "time_unit" else ""
            raise ValueError(f"{field}: {value!r} is not a {kind} (use {', '.join(names)}{extra} or a number of {si})")
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
        "t": S.t.offset,
        "dt": S.dt.offset,
        "steps_done": S.steps_done.offset,
        "walltime": S.walltime.offset,
        "simulationarchive_filename": S._simulationarchive_filename.offset,
        "simulationarchive_auto_interval": S.simulationarchive_auto_interval.offset,
        "simulationarchive_auto_walltime": S.simulationarchive_auto_walltime.offset,
        "simulationarchive_auto_step": S.simulationarchive_auto_step.offset,
        "simulationarchive_next": S.simulationarchive_next.offset,
        "simulationarchive_next_step": S.simulationarchive_next_step.offset,
        "particle_size": ctypes.sizeof(P),
        "x": P.x.offset,
        "vx": P.vx.offset,
        "m": P.m.offset,
        "r": P.r.offset,
    }


class Attachment:
    """rime's handler on one simulation: its spins, counters and first error.

    Returned by ``attach``; the module keeps it alive until ``detach()`` or a new ``attach`` to the
    same simulation.
    """

    def __init__(self, sim, link, track_spins, description, units):
        self._units = units
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

    def counters(self, reset=False):
        """The counters of the present window (code units unless named ``_si``); ``reset=True``
        then starts a new window at ``sim.t`` (same histogram edges). Keys:

        * ``t_start``, ``t_end``, ``duration``: the window (code time);
        * ``collisions`` = ``bounces`` + ``stays`` + ``merges``;
        * ``normal_speed``, ``tangential_speed``: ``count``, ``sum``, ``sum_squares``, ``max`` of
          g_N and |g_T| (Eq. (2), at the contact point, spins included);
        * ``speed_histogram``: ``edges``, ``counts`` (edges[k] <= g_N < edges[k+1]), ``below``,
          ``above``; ``None`` without ``speed_edges``;
        * ``angular_momentum_flux``: Σ m₁ Δv₁,y (x₁ − x₂) over the collisions (mass × length² /
          time; for a merge, Δv₁ is p₁'s change to the pair's common velocity);
        * ``energy_loss``: the kinetic energy (translation + spin) the collisions took (mass ×
          length² / time², each pair's before minus after in one frame);
        * ``overlaps``: ``threshold`` (fraction of r₁ + r₂), ``deeper`` (collisions found deeper),
          ``max_depth``, ``sum_depth`` of 1 − d/(r₁ + r₂) when REBOUND found the pair;
        * ``collisional_viscosity_si`` [m²/s]: flux / (duration · (3/2) Ω · Σ m) with Ω =
          ``sim.OMEGA`` and the particles' mass now; ``None`` when ``sim.OMEGA`` is 0 or the
          window is empty.
        """
        if not isinstance(reset, bool):
            raise ValueError(f"reset: expected True or False (got {reset!r})")
        c = self._handler.counters()
        c["duration"] = c["t_end"] - c["t_start"]
        omega, mass = self._sim.OMEGA, self._total_mass()
        if omega > 0 and c["duration"] > 0 and mass > 0:
            nu = c["angular_momentum_flux"] / (c["duration"] * 1.5 * omega * mass)
            c["collisional_viscosity_si"] = nu * self._units[0] ** 2 / self._units[1]
        else:
            c["collisional_viscosity_si"] = None
        if reset:
            self._handler.reset_counters()
        return c

    def reset_counters(self, speed_edges=None):
        """Starts a new window of the counters at ``sim.t``; ``speed_edges`` (increasing normal
        speeds, code units; ``[]`` for none) replace the histogram's when given."""
        self._handler.reset_counters(None if speed_edges is None else _edges(speed_edges))

    def translational_viscosity(self):
        """ν_translational [m²/s] of the particles now: Σ m u (v_y + (3/2) Ω x) / ((3/2) Ω Σ m)
        (u = v_x; the velocity relative to the shear flow v_y = −(3/2) Ω x of REBOUND's
        shearing sheet, Ω = ``sim.OMEGA``). Average it over time as the counters average the
        collisional part."""
        omega = self._sim.OMEGA
        if not omega > 0:
            raise ValueError(f"sim.OMEGA: a shearing sheet needs Ω > 0 (got {omega!r})")
        n = self._sim.N
        m, xyz, v = np.zeros(n), np.zeros(3 * n), np.zeros(3 * n)
        self._sim.serialize_particle_data(m=m, xyz=xyz, vxvyvz=v)
        xyz, v = xyz.reshape(n, 3), v.reshape(n, 3)
        stress = float(np.sum(m * v[:, 0] * (v[:, 1] + 1.5 * omega * xyz[:, 0])))
        nu = stress / (1.5 * omega * float(np.sum(m)))
        return nu * self._units[0] ** 2 / self._units[1]

    def _total_mass(self):
        m = np.zeros(self._sim.N)
        self._sim.serialize_particle_data(m=m)
        return float(np.sum(m))

    @property
    def cached_pairs(self):
        """Number of (radius, mass) pairs whose contact constants are cached (at most
        ``cache_size``)."""
        return self._handler.cached_pairs

    def cache_info(self):
        """The contact cache: ``entries``, ``capacity``, ``hits`` and ``misses`` (pairs computed)."""
        return self._handler.cache_info()

    def track_spins(self, spins=None):
        """Sets the particles' spins, an (N, 3) array (rad per code time) or a number for all;
        ``None`` keeps them (particles added since get 0). Call it with the remaining spins after
        removing particles yourself. Returns the spins."""
        if not self._track:
            raise ValueError("track_spins: this attachment was made with track_spins=False")
        n = self._sim.N
        current = self.spins if spins is None else _spins(spins, n)
        self._handler.set_spins(current.tolist())
        return self.spins

    @property
    def spins(self):
        """The particles' angular velocities, an (N, 3) array [rad per code time] (a copy)."""
        if not self._track:
            return np.zeros((self._sim.N, 3))
        return np.array(self._handler.spins(), dtype=float).reshape(self._sim.N, 3)

    def save(self, filename):
        """Saves the simulation (``sim.save_to_file(filename)``, appending a snapshot) and its spins
        to ``filename + ".spins"`` (one JSON line per snapshot: time, N and the spins).

        Reload with ``sim = rebound.Simulation(filename)`` (the last snapshot) and
        ``attach(sim, scene, ..., spins=load_spins(filename, sim))``."""
        self._sim.save_to_file(filename)
        with open(filename + ".spins", "a", encoding="utf-8") as f:
            f.write(self._handler.spin_record() + "\n")

    def detach(self):
        """Unregisters the handler and restores REBOUND's default (``"hardsphere"``) and the
        heartbeat set before attach. An attachment replaced by a newer ``attach`` leaves the
        newer one in place."""
        address = ctypes.addressof(self._sim)
        self._handler.detach()
        if _ATTACHED.get(address) is not self._link:
            return
        self._sim.collision_resolve = "hardsphere"
        if self._link.heartbeat is not None:
            self._sim._heartbeat = self._link.previous_heartbeat
        del _ATTACHED[address]


def load_spins(filename, sim):
    """The spins saved by ``Attachment.save(filename)``, or beside REBOUND's periodic archive
    ``filename``, for the snapshot ``sim`` was loaded from (matched by time and N), as an (N, 3)
    array for ``attach(..., spins=...)``."""
    path = filename + ".spins"
    if not os.path.exists(path):
        raise ValueError(f"filename: no spin file {path!r} (save with Attachment.save, or attach "
                         "before sim.save_to_file(filename, interval=...))")
    found = None
    with open(path, encoding="utf-8") as f:
        for line in f:
            record = json.loads(line)
            if record["t"] == sim.t and record["N"] == sim.N:
                found = record
    if found is None:
        raise ValueError(f"filename: {path!r} has no spins for t = {sim.t!r}, N = {sim.N}")
    return np.array(found["spins"], dtype=float).reshape(sim.N, 3)


def _spins(spins, n):
    """An (N, 3) float array of spins from an array or one number for all."""
    try:
        w = np.asarray(spins, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"spins: expected an ({n}, 3) array or a number (got {type(spins).__name__})") from None
    if w.ndim == 0:
        w = np.full((n, 3), float(w))
    if w.shape != (n, 3):
        raise ValueError(f"spins: expected shape ({n}, 3) (got {w.shape})")
    if not np.all(np.isfinite(w)):
        raise ValueError("spins: every value must be finite")
    return np.ascontiguousarray(w)


def _still_attached(sim, link):
    """Whether ``link`` is ``sim``'s own attachment, not a freed simulation's at the same address:
    REBOUND still calls the handler's resolve or heartbeat (a new simulation starts without them)."""
    resolve = ctypes.cast(sim._collision_resolve, ctypes.c_void_p).value or 0
    beat = ctypes.cast(sim._heartbeat, ctypes.c_void_p).value or 0
    return resolve == link.handler.function_address or (
        link.heartbeat is not None and beat == link.handler.heartbeat_address)


def _edges(edges):
    """Histogram edges as a list of floats (checked by the native side)."""
    try:
        e = np.asarray(edges, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"speed_edges: expected increasing speeds (got {type(edges).__name__})") from None
    if e.ndim != 1:
        raise ValueError(f"speed_edges: expected a list of speeds (got shape {e.shape})")
    return e.tolist()


def _time_unit(sim, time_unit, omega):
    """The code time unit in seconds: ``time_unit``, or one orbit with ``omega``; ``sim.OMEGA``,
    when set, must be Ω in code units."""
    if isinstance(time_unit, str) and time_unit.strip() == "orbit":
        if omega is None:
            raise ValueError("time_unit: 'orbit' needs omega=, the orbital frequency Ω in 1/s "
                             "(one orbit is 2π/Ω seconds)")
        seconds = orbit(omega)
    else:
        seconds = unit("time_unit", time_unit)
    if omega is not None:
        w = 2 * np.pi / orbit(omega)  # checked
        if sim.OMEGA != 0 and abs(sim.OMEGA / seconds - w) > 1e-9 * w:
            raise ValueError(
                f"omega: sim.OMEGA = {sim.OMEGA!r} per code time unit is {sim.OMEGA / seconds:.6g} 1/s "
                f"with time_unit = {seconds:.6g} s, not omega = {w:.6g} 1/s (a time unit of one orbit "
                "needs sim.OMEGA = 2π)")
    return seconds


def attach(sim, scene, *, length_unit, time_unit, mass_unit, density="particles",
           sticking="merge", track_spins=True, accuracy="precise", spins=None, omega=None,
           cache_size=CACHE_SIZE, speed_edges=None, overlap_depth=0.1):
    """Sets ``sim.collision_resolve`` to rime's handler for ``scene``; returns the ``Attachment``.

    ``length_unit``, ``time_unit``, ``mass_unit``: one code unit in SI (a number) or as a string
    (``"cm"``, ``"min"``, ``"g"``, ``"1 AU"``); ``time_unit="orbit"`` with ``omega`` (Ω [1/s]) is
    2π/Ω seconds (``sim.OMEGA``, when set, must then be 2π). ``density``: ``"particles"`` or
    ``"scene"``; ``sticking``: ``"merge"``, ``"stay"`` or ``"merge_if_slow"`` (see the module
    documentation); ``accuracy``: the level of ε_N and ε_T (default ``"precise"``); ``spins``:
    initial spins, an (N, 3) array [rad per code time] or one number for all (required past
    t = 0: ``load_spins(filename, sim)`` for a reloaded simulation, 0 to start from rest);
    ``cache_size``: at most this many pairs' contact constants are kept; ``speed_edges``:
    increasing normal impact speeds (code units) for the counters' histogram; ``overlap_depth``:
    the counters count collisions found deeper than this fraction of r₁ + r₂ (see
    ``Attachment.counters``).

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
    units = {"length_unit": unit("length_unit", length_unit),
             "time_unit": _time_unit(sim, time_unit, omega),
             "mass_unit": unit("mass_unit", mass_unit)}
    if not isinstance(track_spins, bool):
        raise ValueError(f"track_spins: expected True or False (got {track_spins!r})")
    if isinstance(overlap_depth, bool) or not isinstance(overlap_depth, (int, float)):
        raise ValueError(f"overlap_depth: expected a fraction of r1 + r2 in [0, 1) (got {overlap_depth!r})")
    speed_edges = [] if speed_edges is None else _edges(speed_edges)
    if not isinstance(cache_size, int) or isinstance(cache_size, bool) or cache_size < 2:
        raise ValueError(f"cache_size: expected a whole number of pairs >= 2 (got {cache_size!r})")
    address = ctypes.addressof(sim)
    previous = _ATTACHED.get(address)
    if previous is not None and not _still_attached(sim, previous):
        # A simulation freed before left its registration at this address (issue 38: its spins
        # went to the next simulation allocated there): not this simulation's.
        del _ATTACHED[address]
        previous = None
    if spins is not None:
        if not track_spins:
            raise ValueError("spins: given with track_spins=False")
        spins = _spins(spins, sim.N)
    elif track_spins and previous is None and sim.t != 0:
        raise ValueError(
            f"spins: this simulation is at t = {sim.t!r}, not 0, and REBOUND keeps no spins: if it "
            "was loaded from a file, pass spins=rime_grains.rebound.load_spins(filename, sim) (saved "
            "by Attachment.save or beside the periodic archive); spins=0 starts them from rest")
    # The heartbeat before attach: kept (and called after rime's), unless it is an earlier rime one.
    from rebound.simulation import AFF

    current = ctypes.cast(sim._heartbeat, ctypes.c_void_p).value or 0
    if previous is not None and previous.heartbeat is not None and current == previous.handler.heartbeat_address:
        before = previous.previous_heartbeat
    else:
        before = AFF(current)
    handler = _native._attach(address, _layout(rebound), scene, units["length_unit"],
                              units["time_unit"], units["mass_unit"], density, sticking,
                              track_spins, accuracy, cache_size,
                              ctypes.cast(before, ctypes.c_void_p).value or 0,
                              speed_edges, float(overlap_depth))
    link = _Link(handler, before)
    g = scene.get("grains.density")
    description = (
        f"eps_N and eps_T from the scene with each pair's own radii and "
        + ("the particles' own density (m_eff of their masses)" if density == "particles"
           else f"the scene's density {g:g} kg/m³ (impulses use the particles' masses)")
        + f"; sticking={sticking!r}, accuracy={accuracy!r}, units: {units['length_unit']:g} m, "
        f"{units['time_unit']:g} s, {units['mass_unit']:g} kg; spins "
        + ("tracked (rime's own table)" if track_spins else "not tracked (0)"))
    attachment = Attachment(sim, link, track_spins, description,
                            (units["length_unit"], units["time_unit"], units["mass_unit"]))
    if track_spins:
        if spins is None and previous is not None and previous.handler is not None:
            try:
                spins = _spins(previous.handler.spins(), sim.N)  # the previous attachment's
            except ValueError:
                spins = None
        attachment.track_spins(spins if spins is not None else np.zeros((sim.N, 3)))
        # Spins beside REBOUND's periodic archive, then the earlier heartbeat.
        link.heartbeat = AFF(handler.heartbeat_address)
        sim._heartbeat = link.heartbeat
    elif previous is not None and previous.heartbeat is not None:
        sim._heartbeat = before
    sim.collision_resolve = handler.function_address
    if previous is not None:
        previous.handler.detach()
    _ATTACHED[address] = link
    return attachment
