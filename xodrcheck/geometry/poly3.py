"""Cubic polynomial ``v(u) = a + b u + c u^2 + d u^3`` in the element's local (u, v) frame (deprecated since 1.6).

The curve is ``(u, v(u))`` rotated by ``hdg`` and moved to ``(x, y)``, literally as the standard writes it, so a
non-zero
``a`` shifts the start off ``(x, y)`` and a non-zero ``b`` turns the start tangent by ``atan(b)``. The element's
``@length`` is arc length along that curve, so ``ds`` is mapped to ``u`` by inverting the arc length
``integral_0^u sqrt(1 + v'(q)^2) dq`` numerically (see :mod:`xodrcheck.geometry.cubic`). Since arc length is never
shorter than ``u``, the element ends at some ``u <= @length``, the range over which the tables are built.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from xodrcheck.geometry import cubic
from xodrcheck.geometry.cubic import CubicCurve
from xodrcheck.geometry.pose import Pose, as_array
from xodrcheck.model import Poly3


@lru_cache(maxsize=8192)
def curve_of(g: Poly3) -> CubicCurve:
    return CubicCurve.build((0.0, 1.0, 0.0, 0.0), (g.a, g.b, g.c, g.d), max(g.length, 0.0))


def parameter_at(g: Poly3, ds) -> np.ndarray:
    """The local ``u`` reached ``ds`` metres (of arc length) into the element."""
    return curve_of(g).parameter_at(as_array(ds))


def evaluate(g: Poly3, ds) -> Pose:
    ds = as_array(ds)
    return evaluate_runs([g], ds, np.array([len(ds)]))


def evaluate_runs(elements: list[Poly3], ds: np.ndarray, counts: np.ndarray) -> Pose:
    """``evaluate(elements[i], ds_i)`` of many calls at once (call ``i`` takes the next ``counts[i]`` values of
    ``ds``): each call's numbers are its own to the last bit (:func:`cubic.poses`; ``ds`` is the arc length itself,
    scale 1)."""
    curves = [curve_of(g) for g in elements]
    return cubic.poses(curves, [1.0] * len(curves), [(g.x, g.y, g.hdg) for g in elements], ds, counts)
