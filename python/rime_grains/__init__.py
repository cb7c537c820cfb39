"""rime from Python: restitution laws of slow collisions of icy grains (Hertzsch 2002).

Everything is in SI units (m, s, kg). Speeds go in as numbers or numpy arrays and come out in the
same shape; the native code releases the GIL while it computes. Bad input raises ``ValueError``
whose message starts with the field it is about.

>>> import numpy as np
>>> import rime_grains as rime
>>> scene = rime.Scene.preset("ice")
>>> eps = rime.eps_n(np.logspace(-4, 0, 5), scene)
>>> eps.shape, bool(np.all((eps > 0) & (eps < 1)))
((5,), True)

A ``Scene`` is built from a preset, the ``rime scene`` JSON or ``set`` with the keys and units of
``rime --set``:

>>> frost = rime.Scene.preset("ice-frost")
>>> frost.set("layer.thickness", "2 um")
>>> frost.get("layer.thickness")
2e-06
>>> rime.Scene.from_json(frost.to_json()) == frost
True
>>> frost.set("layer.thickness", "2 kg")
Traceback (most recent call last):
...
ValueError: layer.thickness: expected a length, not a mass, e.g. 1e-6, 1 um, 2 cm

``rime_grains.rebound.attach`` sets a REBOUND collision handler (native code in this wheel);
``rime_grains.data.law`` evaluates measured laws of ice; ``rime_grains.kernel`` gives the sticking
speed of every pair of radii at every temperature, and ``rime_grains.dustpy.attach`` puts it into
DustPy (cgs on DustPy's side).
"""

from . import _native
from ._native import Scene

#: The package's version (``pip show rime-grains`` gives the same).
__version__ = _native.__version__

__all__ = [
    "Scene",
    "eps_n",
    "eps_t",
    "tangential",
    "collision",
    "thresholds",
    "compare",
    "kernel",
    "data",
    "dustpy",
    "rebound",
    "ring",
    "ACCURACY_LEVELS",
]

#: The accuracy names; a tolerance such as ``"1e-8"`` is accepted too.
ACCURACY_LEVELS = ("fast", "balanced", "precise", "integrated")


def _scene(scene):
    if not isinstance(scene, Scene):
        raise ValueError(f"scene: expected a rime_grains.Scene, e.g. Scene.preset('ice') (got {type(scene).__name__})")
    return scene


def _accuracy(accuracy):
    if not isinstance(accuracy, str):
        raise ValueError(f"accuracy: expected a level name or a tolerance as a string (got {accuracy!r})")
    return accuracy


def eps_n(g, scene, accuracy="precise"):
    """Normal restitution ε_N = −g'_N/g_N at impact speeds ``g`` [m/s] (Eq. (4)–(17)).

    ``g`` is a number or an array of speeds ≥ 0 (0 gives the at-rest limit); the result has its
    shape (a float for a number). ε_N = 0 means the grains stick (in a layer or by adhesion).
    ``accuracy="fast"`` takes the batch path (a few ns per value, relative error ≤ 1e-6);
    ``"precise"`` (default) keeps it ≤ 1e-10.

    >>> import numpy as np, rime_grains as rime
    >>> frost = rime.Scene.preset("ice-frost")
    >>> g_s = rime.thresholds(frost)["layer"]
    >>> float(rime.eps_n(0.5 * g_s, frost))   # below the layer's critical speed: stuck
    0.0
    >>> e = rime.eps_n(np.array([[1e-3, 1e-2], [0.1, 1.0]]), frost, accuracy="fast")
    >>> e.shape, bool(np.all(np.diff(e.ravel()) < 0))   # shape kept; ε_N falls with speed
    ((2, 2), True)
    >>> rime.eps_n(-1.0, frost)
    Traceback (most recent call last):
    ...
    ValueError: g[0]: a speed must be finite, >= 0 and at most 1e6 m/s (got -1)
    """
    return _native.eps_n(g, _scene(scene), _accuracy(accuracy))


def eps_t(g_n, g_t, scene, accuracy="precise"):
    """Tangential restitution ε_T = g'_T/g_T (Eq. (26)) at normal and tangential speeds [m/s].

    ``g_n`` and ``g_t`` broadcast like numpy arrays. The scene needs friction. In the rolling
    branch (g_T below (μ/κ)·g_N) ε_T = −ε_N(g_T), the paper's Eq. (26), top:

    >>> import rime_grains as rime
    >>> ice = rime.Scene.preset("ice")
    >>> et = rime.eps_t(0.01, 1e-3, ice)
    >>> bool(abs(et + rime.eps_n(1e-3, ice)) < 1e-12)
    True
    >>> rime.eps_t([0.01, 0.02], [0.001, 0.05], ice).shape
    (2,)
    """
    return _native.eps_t(g_n, g_t, _scene(scene), _accuracy(accuracy))


def tangential(g_n, g_t, scene, accuracy="precise"):
    """ε_T, ε_N and the stick-map class (``rolling``, ``sliding``, …) at (g_n, g_t), as a dict.

    >>> import rime_grains as rime
    >>> r = rime.tangential(0.01, [0.001, 0.05], rime.Scene.preset("ice"))
    >>> r["class"]
    ['rolling', 'sliding']
    """
    return _native.tangential(g_n, g_t, _scene(scene), _accuracy(accuracy))


def collision(g, scene, g_t=None, points=400, accuracy="precise"):
    """One collision from the inside, as ``rime collision``: a dict with the samples ``t``, ``xi``,
    ``xi_dot``, ``force`` (numpy arrays), ``phases``, ``eps_n``, ``status``, ``t_c`` and the energy
    ``ledger``; with ``g_t`` also ``tangential`` (ε_T, class, spin change, energies). The keys are
    those of ``rime collision --format json``.

    >>> import rime_grains as rime
    >>> c = rime.collision(0.01, rime.Scene.preset("ice"), points=50)
    >>> c["status"], bool(abs(c["ledger"]["closure"]) < 1e-6)   # the energy ledger closes
    ('rebound', True)
    """
    return _native.collision(g, _scene(scene), g_t, points, _accuracy(accuracy))


def thresholds(scene, accuracy="precise"):
    """The scene's critical speeds [m/s], as ``rime stick`` and the explorer's ``v`` panel give
    them: ``layer`` (Eq. (10)), ``adhesion`` (Eq. (15)) and ``stick``, the largest speed at which
    the grains stick; ``None`` where the scene has none.

    Eq. (10) by hand, g_s = √R_eff η* D^(3/2) / m_eff, for the ``ice-frost`` preset:

    >>> import math, rime_grains as rime
    >>> frost = rime.Scene.preset("ice-frost")
    >>> r, rho = frost.get("grains.radius_1"), frost.get("grains.density")
    >>> m_eff = 0.5 * rho * 4 / 3 * math.pi * r**3
    >>> d, eta = frost.get("layer.thickness"), frost.get("layer.viscosity")
    >>> g_s = math.sqrt(r / 2) * eta * d**1.5 / m_eff
    >>> t = rime.thresholds(frost)
    >>> bool(abs(t["layer"] / g_s - 1) < 1e-14), t["adhesion"]
    (True, None)
    """
    return _native.thresholds(_scene(scene), _accuracy(accuracy))


def compare(models, g, scene, accuracy="precise"):
    """ε_N of several models (``rime compare --list``: ``hertzsch2002``, ``thornton1997``, …) and
    measured laws (``"atlas:ID"``) at speeds ``g`` [m/s]: a dict from each name to an array.

    >>> import rime_grains as rime
    >>> ice = rime.Scene.preset("ice")
    >>> out = rime.compare(["hertzsch2002", "atlas:bridges1984"], [1e-3, 1e-2], ice)
    >>> sorted(out)
    ['atlas:bridges1984', 'hertzsch2002']
    >>> bool(abs(out["hertzsch2002"][1] - rime.eps_n(1e-2, ice)) < 1e-12)
    True
    """
    return _native.compare(list(models), g, _scene(scene), _accuracy(accuracy))


def _positive(field, value):
    import math

    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{field}: expected a number (got {value!r})") from None
    if not (math.isfinite(x) and x > 0):
        raise ValueError(f"{field}: must be finite and > 0 (got {value!r})")
    return x


def _fit_reference(fit):
    """``fit`` as the native (radius [m], temperature [K], speed [m/s]) and its source."""
    if fit is None:
        return None, None
    if not isinstance(fit, dict):
        raise ValueError("fit: expected a dict with radius [m], temperature [K], speed [m/s] and source")
    unknown = set(fit) - {"radius", "temperature", "speed", "source"}
    if unknown:
        raise ValueError(f"fit: unknown keys {sorted(unknown)} (radius, temperature, speed, source)")
    for key in ("radius", "temperature", "speed", "source"):
        if key not in fit:
            raise ValueError(f"fit.{key}: required (radius [m], temperature [K], speed [m/s], source)")
    source = fit["source"]
    if not isinstance(source, str) or not source.strip():
        raise ValueError("fit.source: name where the measured speed comes from (a citation)")
    return (_positive("fit.radius", fit["radius"]), _positive("fit.temperature", fit["temperature"]),
            _positive("fit.speed", fit["speed"])), source


def kernel(radii, temperatures, scene, *, a_rule="given", fit=None, temperature_rule="hold",
           convention="surface", accuracy="precise"):
    """The sticking speed of every pair of ``radii`` [m] at every temperature [K], as ``rime
    kernel``: a dict with ``v_stick`` [m/s], shape (T, N, N), symmetric in the last two axes and
    ``inf`` where the pair sticks at every speed (``status`` ``"always_sticks"``, else
    ``"threshold"``), and what it was computed with (``gammas``: γ(T) per temperature and whether
    it was measured there or held, ``damping_time``, ``fit``, ``method``, …).

    The pair's R_eff and m_eff come from the two radii and the scene's density; A across sizes
    follows ``a_rule`` (``"given"``, ``"keep_epsilon"``, ``"fit_measured"`` with ``fit=None`` for
    Gundlach & Blum 2015 or ``fit=(radius [m], temperature [K], speed [m/s])``); γ(T) is Musiolik &
    Wurm (2019), measured over 175–200 K and held at its ends outside (``temperature_rule="hold"``)
    or refused (``"refuse"``). ``fit`` is ``{"radius": m, "temperature": K, "speed": m/s,
    "source": "citation"}`` (the source is kept in the result's ``fit.entry``). Equal radii give
    ``thresholds``'s ``stick`` for that pair:

    >>> import numpy as np, rime_grains as rime
    >>> ice = rime.Scene.preset("ice")
    >>> k = rime.kernel([1e-4, 1e-3], [150.0, 200.0], ice)
    >>> k["v_stick"].shape, [g["range"] for g in k["gammas"]]
    ((2, 2, 2), ['held_cold', 'measured'])
    >>> bool(np.array_equal(k["v_stick"], k["v_stick"].transpose(0, 2, 1)))
    True
    >>> rime.kernel([1e-4], [150.0], ice, temperature_rule="refuse")
    Traceback (most recent call last):
    ...
    ValueError: temperatures: ...
    """
    import numpy as np

    radii = np.atleast_1d(np.asarray(radii, dtype=float)).ravel()
    temperatures = np.atleast_1d(np.asarray(temperatures, dtype=float)).ravel()
    reference, source = _fit_reference(fit)
    v, status, info = _native.kernel_table(list(radii), list(temperatures), _scene(scene),
                                           a_rule=a_rule, fit=reference,
                                           temperature_rule=temperature_rule,
                                           convention=convention, accuracy=_accuracy(accuracy))
    shape = (len(temperatures), len(radii), len(radii))
    names = np.array(["threshold", "always_sticks"])
    if info["fit"] is not None and source is not None:
        info["fit"]["entry"] = source
    return {"radii": radii, "temperatures": temperatures, "v_stick": v.reshape(shape),
            "status": names[status.reshape(shape)], **info}


from . import data  # noqa: E402
from . import ring  # noqa: E402
from . import rebound  # noqa: E402
from . import dustpy  # noqa: E402
