"""Parametric cubic curve ``u(p) = aU + bU p + cU p^2 + dU p^3``, ``v(p) = aV + ...`` in the element's local frame.

What ``ds`` means (decision)
----------------------------
The standard (ASAM OpenDRIVE 1.8, 9.6) says only that ``p`` runs over ``[0, 1]`` for ``pRange="normalized"`` and over
``[0, @length]`` for ``pRange="arcLength"``. It never says that ``p`` *is* the arc length, and for a cubic it cannot be
one unless the curve is a straight line traversed at constant speed. Yet ``s`` along a road's reference line is arc
length everywhere else (8.3: "coordinate along road reference line, measured in [m]"), lanes, objects and links are
placed by it, and ``@length`` is "the length of the element's reference line".

So here ``ds`` is always true arc length along the curve, for both ``pRange`` values, and the element's end
(``p = 1`` or ``p = @length``) is reached at ``ds = @length``: ``ds`` is mapped to the arc length
``sigma = ds * L / @length``, with ``L`` the curve's computed length, then to ``p`` by inverting ``sigma(p)``. When
``@length`` equals the curve's length (the file is right) that is exactly arc length; when it does not, the mismatch is
spread evenly instead of leaving a gap or an overshoot at the element's end (a length rule reports it).

This is also what the two reference readers of the lane-centre oracle do: esmini's RoadManager tabulates the curve's
arc length and rescales it to ``@length``; CARLA tabulates arc length (without rescaling). libOpenDRIVE, in its older
releases, mapped ``ds`` linearly to ``p`` (``p = ds / @length`` or ``p = ds``), which departs from arc length by metres
on
strongly non-uniform curves; it is not followed.

Heading is ``hdg + atan2(v'(p), u'(p))``, curvature ``(u'v'' - v'u'') / |c'|^3`` (both independent of the
parametrisation), and the derivative of curvature is taken with respect to arc length.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from xodrcheck.geometry import cubic
from xodrcheck.geometry.cubic import CubicCurve
from xodrcheck.geometry.pose import Pose, as_array
from xodrcheck.model import ParamPoly3, PRange


@lru_cache(maxsize=8192)
def curve_of(g: ParamPoly3) -> CubicCurve:
    """The element's curve with its arc-length tables over the whole ``p`` range (cached per element)."""
    p_max = 1.0 if g.p_range is PRange.NORMALIZED else g.length
    return CubicCurve.build((g.aU, g.bU, g.cU, g.dU), (g.aV, g.bV, g.cV, g.dV), p_max)


def parameter_at(g: ParamPoly3, ds) -> np.ndarray:
    """The curve parameter ``p`` reached ``ds`` metres into the element (see the module docstring)."""
    ds = as_array(ds)
    curve = curve_of(g)
    scale = curve.total / g.length if g.length > 0 else 0.0
    return curve.parameter_at(ds * scale)


def evaluate(g: ParamPoly3, ds) -> Pose:
    ds = as_array(ds)
    return evaluate_runs([g], ds, np.array([len(ds)]))


def evaluate_runs(elements: list[ParamPoly3], ds: np.ndarray, counts: np.ndarray) -> Pose:
    """``evaluate(elements[i], ds_i)`` of many calls at once (call ``i`` takes the next ``counts[i]`` values of
    ``ds``), as one flat :class:`Pose`: each call's numbers are its own to the last bit (:func:`cubic.poses`)."""
    curves = [curve_of(g) for g in elements]
    scales = [c.total / g.length if g.length > 0 else 0.0 for c, g in zip(curves, elements)]
    return cubic.poses(curves, scales, [(g.x, g.y, g.hdg) for g in elements], ds, counts)
