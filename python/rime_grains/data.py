"""Measured restitution laws of ice (rime's atlas; ``rime data``).

>>> import rime_grains as rime
>>> bridges = rime.data.law("bridges1984")
>>> e = bridges([1e-4, 1e-3, 1e-2])
>>> bool(e[0] > e[1] > e[2])     # the measured law falls with speed
True

Bridges et al. (1984) write ε = (v / v_c)^(-0.234) with v_c = 0.0077 cm/s:

>>> bool(abs(bridges(0.01) - (1.0 / 0.0077) ** -0.234) < 1e-12)
True
"""

from . import _native

__all__ = ["law", "laws"]


def laws():
    """The measured laws: a list of dicts with ``id``, ``citation``, ``formula``, ``valid_speed``
    [m/s] and ``needs_radius``."""
    return _native.laws()


def law(id):
    """The measured law ``id`` as a function of speed: ``law(id)(g, radius=None)`` gives ε_N at
    speeds ``g`` [m/s] (same shape). Laws that depend on the grain size need ``radius`` [m].
    Outside the measured speeds the law is extrapolated as the source writes it.

    >>> import rime_grains as rime
    >>> rime.data.law("no-such-law")
    Traceback (most recent call last):
    ...
    ValueError: id: unknown law 'no-such-law' (one of ...)
    """
    ids = [entry["id"] for entry in _native.laws()]
    if id not in ids:
        raise ValueError(f"id: unknown law {id!r} (one of {', '.join(ids)})")

    def evaluate(g, radius=None):
        return _native.law_eval(id, g, radius)

    evaluate.__name__ = f"law_{id}"
    evaluate.__doc__ = f"ε_N of the measured law {id!r} at speeds g [m/s]."
    return evaluate
