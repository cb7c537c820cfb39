"""rime's sticking speeds inside DustPy 1.0.9: its ``p.stick`` (and ``p.frag``) updaters.

``attach(sim, scene)`` replaces DustPy's sticking-probability updater, the recipe DustPy's
maintainers give for new collision physics. Every collision of sizes (a_i, a_j) at relative speed
Δv in a radial cell at gas temperature T then

* **fragments** with DustPy's own probability: its ``p.frag`` updater is left as it is (DustPy's
  ``pfrag`` at ``sim.dust.v.frag``, 1 m/s by default, or at a speed you give with its source:
  ``v_frag=``, ``v_frag_source=``); rime has no fragmentation model;
* **sticks** when its speed is below rime's sticking speed v_stick(a_i, a_j, T) of two compact
  spheres and it does not fragment: p_stick = min(1 − p_frag, P(v < v_stick)); v_stick is the
  smallest impact speed at which the scene's model rebounds, with γ(T) of Musiolik & Wurm (2019)
  and the rule for A across sizes you choose (``rime_grains.kernel``, ``rime kernel``);
* **bounces** otherwise: DustPy treats 1 − p_stick − p_frag as a collision without mass change.

The speed of a collision is DustPy's: Δv is ``sim.dust.v.rel.tot`` (the rms of its Brownian,
turbulent, drift and settling terms), and with ``velocity_distribution="maxwell"`` (default) the
collision speeds follow the Maxwell–Boltzmann distribution DustPy 1.0.9's ``pfrag`` assumes: a
collision exceeds v with probability F(v) = (1 + x)·exp(−x), x = 3/2 (v/Δv)², so with
p_frag = F(v_frag), p_stick = 1 − F(min(v_stick, v_frag)). With ``"none"`` every collision has
speed Δv: p_stick = [Δv < min(v_stick, v_frag)], and the p.frag updater is replaced by
p_frag = [Δv ≥ v_frag] (DustPy's own formula always carries the distribution). Where v_stick is
infinite (the pair sticks at every speed) p_stick is DustPy's own 1 − p_frag, bit for bit:
``v_stick=np.inf`` reproduces DustPy's default run. Both arrays are symmetric in (i, j),
p_stick + p_frag ≤ 1, and p_stick is 0 in the first and last radial cells (DustPy's boundary
convention; its p_frag is 0 there too).

Units: DustPy's side is cgs (sizes in cm, speeds in cm/s, density in g/cm³), in and out; rime's
side (the scene, ``fit``) is SI as everywhere in rime_grains. The grain density is the
simulation's (``sim.dust.rhos × sim.dust.fill``; DustPy's default is 1.67 g/cm³, the ``ice``
preset's 0.9 g/cm³): DustPy's sizes and masses are tied to it, so rime's sticking speeds use it
too (``Attachment.density``; a ``DensityWarning`` says so when it differs from the scene's). To
model compact ice, set ``sim.ini.dust.rhoMonomer`` before ``sim.initialize()``.

Temperatures: v_stick depends on T only through γ(T), measured over 175–200 K. Outside that range
``temperature_rule="hold"`` (default) holds γ at the nearer end value (a ``GammaRangeWarning`` says
how many cells) and ``"refuse"`` raises. Each cell's T is rounded to ``temperature_step`` (0.01 K:
at most 0.1 % in γ, and so in v_stick, inside the measured range) and one table of v_stick per
rounded temperature is kept (at most ``cache_size``): an update then costs the probabilities only.

What is not rime's model: porous aggregates (DustPy's grains here are compact spheres of one
density; rime's law is for compact spheres), fragmentation and erosion (DustPy's or your number,
never rime's), mass transfer, and the velocity distribution (DustPy's). ``Attachment.provenance``
records all of this with the numbers used; docs/physics.md#python-dustpy has the details.

>>> import dustpy, rime_grains as rime
>>> from rime_grains.dustpy import attach
>>> sim = dustpy.Simulation()
>>> sim.ini.grid.Nr, sim.ini.grid.mmax = 4, 1.0
>>> sim.ini.dust.rhoMonomer = 0.9      # the `ice` preset's density [g/cm³]
>>> sim.initialize()
>>> sim.gas.T.updater = None
>>> sim.gas.T[...] = 185.0             # inside γ(T)'s measured range
>>> att = attach(sim, rime.Scene.preset("ice"))
>>> sim.update()
>>> p_s, p_f = sim.dust.p.stick, sim.dust.p.frag
>>> bool((p_s == p_s.transpose(0, 2, 1)).all() and (p_s + p_f <= 1.0).all())
True
>>> float(p_s[0].max()), float(p_s[-1].max())   # DustPy's boundary cells
(0.0, 0.0)
>>> att.provenance["density"]["value"], att.provenance["density"]["unit"]
(0.9, 'g/cm3')
>>> att.detach()
"""

import collections
import math
import time
import warnings

import numpy as np

from . import _fit_reference, _native, _positive

__all__ = ["attach", "Attachment", "DensityWarning", "GammaRangeWarning", "DUSTPY_VERSION"]

#: The DustPy version these updaters are built and tested for (its ``pfrag``, boundary cells and
#: field layout); another version gets a warning.
DUSTPY_VERSION = "1.0.9"

#: What rime does not model in this coupling (also in ``Attachment.provenance``).
NOT_MODELLED = (
    "porous aggregates (rime's sticking speed is that of two compact spheres)",
    "fragmentation (DustPy's v_frag or the caller's, never rime's)",
    "erosion and mass transfer",
    "the distribution of collision speeds (DustPy's)",
)

_DISTRIBUTIONS = ("maxwell", "none")


class DensityWarning(UserWarning):
    """rime's sticking speeds use the simulation's grain density, not the scene's."""


class GammaRangeWarning(UserWarning):
    """Some radial cells lie outside the temperatures where γ(T) was measured."""


class Attachment:
    """rime's updaters on one DustPy simulation (returned by ``attach``).

    ``provenance`` is a dict of everything the sticking probabilities came from (rime's version,
    the scene, the A rule and A, γ(T)'s source and range, the density, DustPy's fields used, the
    fragmentation speed and its source, what is not modelled); ``density`` the grain density
    [g/cm³]; ``temperatures`` the temperature [K] each radial cell's table was computed at, at the
    last update (rounded; held at 175 K or 200 K beyond them under ``hold``; NaN at the boundary
    cells); ``gamma_ranges`` where each cell's own temperature lies (``measured``, ``held_cold``,
    ``held_warm``; ``boundary``); ``cache_info()`` the table cache; ``v_stick(T)`` rime's table at
    one temperature [cm/s]; ``detach()`` restores DustPy's own updaters.
    """

    def __init__(self, sim, scene, options, fit_source, maxwell, constant_v_stick,
                 temperature_step, cache_size, provenance, saved):
        self._sim = sim
        self._scene = scene.copy() if scene is not None else None
        self._options = options
        self._fit_source = fit_source
        self._maxwell = maxwell
        self._constant = constant_v_stick
        self._step = temperature_step
        self._cache_size = cache_size
        self._tables = collections.OrderedDict()  # (T key, sizes key) -> (Nm, Nm) [cm/s]
        self._stack_key = None
        self._stack = None
        self._sizes = None  # (bytes of one row of sizes [cm], radii [m]) of the last update
        self._density = None
        self._hits = self._misses = self._updates = 0
        self._buffer = None
        self._seconds = 0.0
        self._warned_ranges = set()
        self._saved = saved
        self._attached = True
        self.provenance = provenance
        self.temperatures = np.full(len(np.asarray(sim.grid.r)), np.nan)
        self.gamma_ranges = ["boundary"] * len(self.temperatures)
        self._measured_range = None
        self._check_density()
        if self._constant is None:
            # One small table: checks the options now and gives γ(T)'s measured range, which the
            # rounding of temperatures needs (γ is held constant beyond it).
            _, _, info = _native.kernel_table([1e-6], [190.0], self._scene, **self._native_options())
            self._measured_range = tuple(info["measured_range"])
            self._record(info)

    # -- the grain density -------------------------------------------------------------------
    def _check_density(self):
        """The simulation's density [g/cm³]: one value for every mass bin and cell (the model is
        one material); warns once when it differs from the scene's."""
        rho = np.asarray(self._sim.dust.rhos) * np.asarray(self._sim.dust.fill)
        values = np.unique(rho)
        if values.size != 1 or not (np.isfinite(values[0]) and values[0] > 0):
            raise ValueError(
                "sim.dust.rhos: rime's sticking speed is for grains of one material density; "
                f"sim.dust.rhos × sim.dust.fill takes {values.size} values "
                f"({values.min():.6g}–{values.max():.6g} g/cm³)")
        density = float(values[0])
        if density != self._density:
            self._density = density
            self._tables.clear()
            self._stack_key = None
            self.provenance["density"] = {
                "value": density, "unit": "g/cm3",
                "source": "sim.dust.rhos × sim.dust.fill (DustPy; its sizes and masses use it)"}
            if self._scene is not None:
                scene_density = self._scene.get("grains.density") / 1000.0
                self.provenance["density"]["scene_value"] = scene_density
                if not math.isclose(scene_density, density, rel_tol=1e-12):
                    warnings.warn(
                        f"rime_grains.dustpy: rime's sticking speeds use DustPy's grain density "
                        f"{density:.6g} g/cm³ (sim.dust.rhos × sim.dust.fill), not the scene's "
                        f"{scene_density:.6g} g/cm³; set sim.ini.dust.rhoMonomer before "
                        f"sim.initialize() to change it", DensityWarning, stacklevel=4)
                self._scene.set("grains.density", density * 1000.0)
        return density

    @property
    def density(self):
        """The grain density rime's sticking speeds use [g/cm³] (the simulation's)."""
        return self._density

    # -- the tables ---------------------------------------------------------------------------
    def _key(self, temperature):
        """The temperature a table is computed at: held at the measured range's ends under
        ``hold`` (γ is constant beyond them), rounded to ``temperature_step``."""
        t = float(temperature)
        if self._measured_range is not None and self._options["temperature_rule"] == "hold":
            lo, hi = self._measured_range
            t = min(max(t, lo), hi)
        if self._step > 0:
            t = round(t / self._step) * self._step
        return t

    def _compute(self, radii_m, temperatures):
        """Tables [cm/s] at ``temperatures`` for ``radii_m``; records the γ ranges."""
        n = len(radii_m)
        if self._constant is not None:
            return [np.full((n, n), self._constant) for _ in temperatures]
        start = time.perf_counter()
        v, _, info = _native.kernel_table(list(radii_m), list(temperatures), self._scene,
                                          **self._native_options())
        self._seconds += time.perf_counter() - start
        self._measured_range = tuple(info["measured_range"])
        self._record(info)
        return list(100.0 * v.reshape(len(temperatures), n, n))

    def _native_options(self):
        o = self._options
        return {"a_rule": o["a_rule"], "fit": o["fit"], "temperature_rule": o["temperature_rule"],
                "convention": o["convention"], "accuracy": o["accuracy"]}

    def _record(self, info):
        p = self.provenance["sticking"]
        p["damping_time"] = {"value": info["damping_time"], "unit": "s"}
        p["method"] = info["method"]
        p["gamma"]["measured_range"] = {"value": list(info["measured_range"]), "unit": "K"}
        fit = info["fit"]
        if fit is not None:
            fit = dict(fit)
            if fit["entry"] == "user":
                fit["entry"] = self._fit_source
            p["fit"] = fit

    def _tables_for(self, keys, radii_m, sizes_key):
        """The stacked tables of ``keys`` (one per distinct key) and each key's index."""
        distinct = list(dict.fromkeys(keys))
        missing = [t for t in distinct if (t, sizes_key) not in self._tables]
        if missing:
            self._misses += len(missing)
            for t, table in zip(missing, self._compute(radii_m, missing)):
                self._tables[(t, sizes_key)] = table
        self._hits += len(distinct) - len(missing)
        for t in distinct:
            self._tables.move_to_end((t, sizes_key))
        while len(self._tables) > max(self._cache_size, len(distinct)):
            self._tables.popitem(last=False)
        stack = np.stack([self._tables[(t, sizes_key)] for t in distinct])
        index = {t: k for k, t in enumerate(distinct)}
        return stack, index

    def _sizes_of(self):
        """DustPy's sizes [cm] (one row for every cell: its masses and one density) as radii [m]."""
        a = np.asarray(self._sim.dust.a)
        row = a[1] if len(a) > 2 else a[0]
        # One mass grid and one density: the same sizes in every cell, to DustPy's rounding (its
        # Fortran gives some cells sizes 1 ulp apart).
        if not np.allclose(a, row, rtol=1e-12, atol=0):
            raise ValueError("sim.dust.a: the sizes differ between radial cells; rime's tables "
                             "assume DustPy's one mass grid and one density")
        key = row.tobytes()
        if self._sizes is None or self._sizes[0] != key:
            self._sizes = (key, row * 0.01)
        return self._sizes

    def _cell_tables(self):
        """(tables [cm/s], cell_table) for the current temperatures and sizes."""
        self._check_density()
        sizes_key, radii_m = self._sizes_of()
        temperatures = np.asarray(self._sim.gas.T, dtype=float)
        nr = len(temperatures)
        keys = [self._key(t) for t in temperatures[1:nr - 1]]
        stack_key = (tuple(keys), sizes_key, self._density)
        if stack_key != self._stack_key:
            stack, index = self._tables_for(keys, radii_m, sizes_key)
            cells = np.full(nr, -1, dtype=np.int64)
            cells[1:nr - 1] = [index[t] for t in keys]
            self._stack_key, self._stack = stack_key, (stack, cells)
            self._update_ranges(temperatures, keys)
        else:
            self._hits += len(set(keys))
        return self._stack

    def _update_ranges(self, temperatures, keys):
        nr = len(temperatures)
        self.temperatures = np.full(nr, np.nan)
        self.temperatures[1:nr - 1] = keys
        ranges = ["boundary"] * nr
        if self._constant is None and self._measured_range is not None:
            lo, hi = self._measured_range
            for k in range(1, nr - 1):
                t = temperatures[k]
                ranges[k] = "held_cold" if t < lo else "held_warm" if t > hi else "measured"
            held = [r for r in ranges if r.startswith("held")]
            new = set(held) - self._warned_ranges
            if new and self._options["temperature_rule"] == "hold":
                self._warned_ranges |= new
                cold = [temperatures[k] for k in range(nr) if ranges[k] == "held_cold"]
                warm = [temperatures[k] for k in range(nr) if ranges[k] == "held_warm"]
                parts = []
                if cold:
                    parts.append(f"{len(cold)} cells at {min(cold):.5g}–{max(cold):.5g} K use γ "
                                 f"held at its {lo:g} K value")
                if warm:
                    parts.append(f"{len(warm)} cells at {min(warm):.5g}–{max(warm):.5g} K use γ "
                                 f"held at its {hi:g} K value")
                warnings.warn(
                    f"rime_grains.dustpy: γ(T) (Musiolik & Wurm 2019) is measured over "
                    f"{lo:g}–{hi:g} K; " + "; ".join(parts) + " (temperature_rule='hold')",
                    GammaRangeWarning, stacklevel=4)
        self.gamma_ranges = ranges
        self.provenance["sticking"]["gamma"]["cells"] = {
            r: ranges.count(r) for r in ("measured", "held_cold", "held_warm", "boundary")}

    # -- the updaters ---------------------------------------------------------------------------
    def p_frag_step(self, sim):
        """Fragmentation without a velocity distribution (``"none"``): [Δv ≥ v_frag]."""
        return _native.dustpy_p_frag_step(np.ascontiguousarray(sim.dust.v.rel.tot, dtype=float),
                                          np.ascontiguousarray(sim.dust.v.frag, dtype=float))

    def p_stick(self, sim):
        """The sticking probability with rime's sticking speeds (module docs): DustPy's
        ``p.stick`` updater. It returns a buffer that the next call overwrites (DustPy copies it
        into ``sim.dust.p.stick``); copy it to keep it."""
        self._updates += 1
        tables, cells = self._cell_tables()
        v_rel = np.ascontiguousarray(sim.dust.v.rel.tot, dtype=float)
        if self._buffer is None or self._buffer.shape != v_rel.shape:
            self._buffer = np.zeros(v_rel.shape)
        return _native.dustpy_p_stick(v_rel, np.ascontiguousarray(sim.dust.p.frag, dtype=float),
                                      tables, cells, self._maxwell, out=self._buffer)

    # -- inspection -------------------------------------------------------------------------------
    def v_stick(self, temperature):
        """rime's sticking speeds [cm/s] of every pair of the simulation's sizes at
        ``temperature`` [K] (rounded and held as the updaters do; infinite: always sticks)."""
        self._check_density()
        sizes_key, radii_m = self._sizes_of()
        key = self._key(_positive("temperature", temperature))
        stack, _ = self._tables_for([key], radii_m, sizes_key)
        return stack[0].copy()

    def cache_info(self):
        """Updates of p_stick so far, tables held, hits and misses (per distinct temperature and
        update), and the seconds spent computing tables."""
        return {"updates": self._updates, "tables": len(self._tables), "hits": self._hits,
                "misses": self._misses,
                "maxsize": self._cache_size, "seconds": self._seconds}

    def detach(self):
        """Restores DustPy's own updaters, fragmentation speeds and field descriptions."""
        if not self._attached:
            return
        sim, saved = self._sim, self._saved
        sim.dust.p.stick.updater = saved["stick"]
        sim.dust.p.frag.updater = saved["frag"]
        sim.dust.p.stick.description = saved["stick_description"]
        sim.dust.p.frag.description = saved["frag_description"]
        if saved["v_frag"] is not None:
            sim.dust.v.frag[...] = saved["v_frag"]
        self._attached = False


def import_offline():
    """Imports DustPy without its network check and returns the module.

    `import dustpy` (1.0.9) opens a socket to 8.8.8.8 and asks PyPI for a newer version, leaves
    that socket unclosed (a ResourceWarning) and the process's default socket timeout at 0.5 s.
    Here the connection is refused while DustPy is imported (DustPy then skips the check), and the
    default timeout is put back: for machines without a network (clusters, CI) and for runs that
    should not touch it. A DustPy already imported is returned as it is.
    """
    import socket
    import sys

    if "dustpy" in sys.modules:
        return sys.modules["dustpy"]
    connect, timeout = socket.socket.connect, socket.getdefaulttimeout()

    def refuse(self, address):
        raise OSError("rime_grains.dustpy.import_offline: no network for DustPy's version check")

    socket.socket.connect = refuse
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ResourceWarning)
            import dustpy
    finally:
        socket.socket.connect = connect
        socket.setdefaulttimeout(timeout)
    return dustpy


def attach(sim, scene, *, a_rule="given", fit=None, temperature_rule="hold", convention="surface",
           accuracy="precise", velocity_distribution="maxwell", v_frag=None, v_frag_source=None,
           v_stick=None, temperature_step=0.01, cache_size=256):
    """Sets ``sim.dust.p.stick`` and ``sim.dust.p.frag`` updaters from rime's sticking speed.

    ``sim`` is an initialized ``dustpy.Simulation`` (call ``sim.initialize()`` first); ``scene`` a
    ``rime_grains.Scene`` whose material (modulus, Poisson ratio, A, contact end, layer) gives the
    sticking speed; its radii are the reference pair of ``a_rule="keep_epsilon"`` and its density
    is replaced by the simulation's (module docs).

    * ``a_rule``: ``"given"`` (the scene's A for every pair), ``"keep_epsilon"`` (A scaled so that
      every pair keeps the scene's pair's ε_N(g)), ``"fit_measured"`` (one A fitted to a measured
      sticking speed: ``fit=None`` is Gundlach & Blum 2015, 9.6 m/s for two 1.5 µm grains at
      200 K; or ``fit={"radius": m, "temperature": K, "speed": m/s, "source": "citation"}``).
    * ``temperature_rule``: ``"hold"`` or ``"refuse"`` outside γ(T)'s measured 175–200 K;
      ``convention``: ``"surface"`` (the source's γ is a surface energy, w = 2γ) or ``"adhesion"``;
      ``accuracy``: ``"precise"`` (default) or ``"fast"`` (the scaling law on the master curve's fine
      or coarse table), or a slower level (bisection on the full model).
    * ``velocity_distribution``: ``"maxwell"`` (DustPy 1.0.9's, default) or ``"none"``.
    * ``v_frag`` [cm/s] (a number or one per radial cell) replaces ``sim.dust.v.frag`` and needs
      ``v_frag_source``, where the number comes from; default: DustPy's field as it is.
    * ``v_stick`` [cm/s]: one sticking speed for every pair instead of rime's (``np.inf``: DustPy's
      default run, every collision below v_frag sticks); for comparisons, the scene is then unused.
    * ``temperature_step`` [K] (0: exact temperatures) and ``cache_size`` (tables kept) set the cache.

    Returns an ``Attachment`` (its ``provenance``, ``density``, ``v_stick(T)``, ``cache_info()``,
    ``detach()``). Bad input raises ``ValueError`` naming the argument. The first tables are
    computed here, so an unusable temperature fails now rather than inside ``sim.run()``.
    """
    try:
        import dustpy
        from dustpy.std import dust as std_dust
    except ImportError as e:  # pragma: no cover - the test environment has DustPy
        raise ImportError(f"rime_grains.dustpy needs DustPy {DUSTPY_VERSION} (pip install "
                          f"dustpy=={DUSTPY_VERSION}; it builds with a Fortran compiler)") from e
    if not isinstance(sim, dustpy.Simulation):
        raise ValueError(f"sim: expected a dustpy.Simulation (got {type(sim).__name__})")
    if sim.dust.p.stick is None or sim.dust.p.frag is None or sim.dust.a is None:
        raise ValueError("sim: call sim.initialize() before attach (the fields it sets are missing)")
    if dustpy.__version__ != DUSTPY_VERSION:
        warnings.warn(f"rime_grains.dustpy is built and tested for DustPy {DUSTPY_VERSION} "
                      f"(this is {dustpy.__version__}): check p_frag and the boundary cells",
                      UserWarning, stacklevel=2)
    if velocity_distribution not in _DISTRIBUTIONS:
        raise ValueError(f"velocity_distribution: one of {', '.join(_DISTRIBUTIONS)} "
                         f"(got {velocity_distribution!r})")
    constant = None
    if v_stick is not None:
        try:
            constant = float(v_stick)
        except (TypeError, ValueError):
            raise ValueError(f"v_stick: expected a speed in cm/s or np.inf (got {v_stick!r})") from None
        if not constant > 0:
            raise ValueError(f"v_stick: must be > 0 cm/s (got {v_stick!r})")
    else:
        from . import Scene
        if not isinstance(scene, Scene):
            raise ValueError(f"scene: expected a rime_grains.Scene, e.g. Scene.preset('ice') "
                             f"(got {type(scene).__name__})")
    if temperature_rule not in ("hold", "refuse"):
        raise ValueError(f"temperature_rule: unknown rule {temperature_rule!r} (hold or refuse)")
    if convention not in ("surface", "adhesion"):
        raise ValueError(f"convention: unknown convention {convention!r} (surface or adhesion)")
    a_rule = a_rule.replace("-", "_") if isinstance(a_rule, str) else a_rule
    if a_rule not in ("given", "keep_epsilon", "fit_measured"):
        raise ValueError(f"a_rule: unknown rule {a_rule!r} (one of given, keep_epsilon, fit_measured)")
    native_fit, fit_source = _fit_reference(fit)
    if native_fit is not None and a_rule != "fit_measured":
        raise ValueError('fit: only with a_rule="fit_measured" (the other rules fit nothing)')
    step = float(temperature_step)
    if not (math.isfinite(step) and step >= 0):
        raise ValueError(f"temperature_step: must be finite and >= 0 K (got {temperature_step!r})")
    if not (isinstance(cache_size, int) and cache_size >= 1):
        raise ValueError(f"cache_size: must be an integer >= 1 (got {cache_size!r})")

    nr = len(np.asarray(sim.grid.r))
    saved = {"stick": sim.dust.p.stick.updater, "frag": sim.dust.p.frag.updater,
             "stick_description": sim.dust.p.stick.description,
             "frag_description": sim.dust.p.frag.description, "v_frag": None}
    frag_function = getattr(getattr(sim.dust.p.frag.updater, "updater", None), "_func", None)
    dustpy_frag = frag_function is std_dust.p_frag
    if v_frag is not None:
        if not isinstance(v_frag_source, str) or not v_frag_source.strip():
            raise ValueError("v_frag_source: name where the fragmentation speed comes from "
                             "(required with v_frag)")
        try:
            values = np.broadcast_to(np.asarray(v_frag, dtype=float), (nr,))
        except (TypeError, ValueError):
            raise ValueError(f"v_frag: expected a speed in cm/s or one per radial cell ({nr})") from None
        if not np.all(np.isfinite(values) & (values > 0)):
            raise ValueError(f"v_frag: must be finite and > 0 cm/s (got {v_frag!r})")
    elif v_frag_source is not None:
        raise ValueError("v_frag_source: only with v_frag (DustPy's own v_frag is used otherwise)")

    from . import __version__
    provenance = {
        "rime_version": __version__,
        "dustpy_version": dustpy.__version__,
        "units": "cgs (cm, g, s) on DustPy's side; the scene and fit in SI",
        "sticking": {
            "model": ("one constant sticking speed for every pair, given by the caller"
                      if constant is not None else
                      "rime: the smallest impact speed at which two compact spheres of the scene's "
                      "material rebound (Hertzsch 2002, adhesion Eq. (15)-(17))"),
            "v_stick_constant": None if constant is None else {"value": constant, "unit": "cm/s"},
            "scene": None if constant is not None else scene.to_json(),
            "a_rule": a_rule,
            "gamma": {"source": "Musiolik & Wurm (2019), atlas entry musiolik2019",
                      "temperature_rule": temperature_rule, "convention": convention},
            "accuracy": accuracy,
            "temperature_step": {"value": step, "unit": "K"},
        },
        "relative_velocity": "DustPy: sim.dust.v.rel.tot (rms of Brownian, turbulent (Ormel & "
                             "Cuzzi 2007), radial and azimuthal drift, settling)",
        "velocity_distribution": (
            "maxwell: DustPy 1.0.9's (its pfrag): P(v > u) = (1 + 3x/2) exp(-3x/2), x = (u/Δv)²"
            if velocity_distribution == "maxwell" else
            "none: every collision at Δv (step functions)"),
        "fragmentation": {
            "model": ("step at v_frag (rime_grains.dustpy)" if velocity_distribution == "none" else
                      "DustPy's pfrag (its p.frag updater, kept)" if dustpy_frag else
                      "the caller's own p.frag updater (kept)"),
            "v_frag": ("sim.dust.v.frag as DustPy set it (sim.ini.dust.vFrag = "
                       f"{sim.ini.dust.vFrag:g} cm/s unless changed)" if v_frag is None else
                       {"value": np.asarray(v_frag, dtype=float).tolist(), "unit": "cm/s",
                        "source": v_frag_source}),
        },
        "bouncing": "1 - p_stick - p_frag (DustPy: no mass change)",
        "boundary_cells": "p_stick = 0 in the first and last radial cells (DustPy's convention)",
        "not_modelled": list(NOT_MODELLED),
    }
    options = {"a_rule": a_rule, "fit": native_fit, "temperature_rule": temperature_rule,
               "convention": convention, "accuracy": accuracy}
    att = Attachment(sim, scene if constant is None else None, options, fit_source,
                     velocity_distribution == "maxwell", constant, step, cache_size, provenance,
                     saved)
    # The first tables now: errors (a refused temperature, a bad option) surface at attach.
    att._cell_tables()
    if v_frag is not None:
        saved["v_frag"] = np.array(sim.dust.v.frag, dtype=float)
        sim.dust.v.frag[...] = values
    if velocity_distribution == "none":
        sim.dust.p.frag.updater = att.p_frag_step
        sim.dust.p.frag.description = "Fragmentation probability (step at v_frag; rime_grains.dustpy)"
    sim.dust.p.stick.updater = att.p_stick
    sim.dust.p.stick.description = (
        f"Sticking probability (rime {__version__} v_stick, a_rule={a_rule}; rime_grains.dustpy)"
        if constant is None else "Sticking probability (constant v_stick; rime_grains.dustpy)")
    return att
