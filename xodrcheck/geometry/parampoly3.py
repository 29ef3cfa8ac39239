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

from xodrcheck.geometry.cubic import CubicCurve, frame, parameters_at
from xodrcheck.geometry.pose import Pose, as_array, local_to_inertial
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
    p = parameter_at(g, ds)
    u, v, angle, curvature, dcurvature = frame(curve_of(g), p)
    x, y = local_to_inertial(g, u, v)
    return Pose(x, y, g.hdg + angle, curvature, dcurvature)


def evaluate_runs(elements: list[ParamPoly3], ds: np.ndarray, counts: np.ndarray) -> Pose:
    """``evaluate(elements[i], ds_i)`` of many calls at once (call ``i`` takes the next ``counts[i]`` values of
    ``ds``), as one flat :class:`Pose`: each call's numbers are its own to the last bit (see
    :func:`xodrcheck.geometry.cubic.parameters_at`)."""
    curves = [curve_of(g) for g in elements]
    scales = np.array([c.total / g.length if g.length > 0 else 0.0 for c, g in zip(curves, elements)])
    owner = np.repeat(np.arange(len(elements)), counts)
    p = parameters_at(curves, ds * scales[owner], counts)
    coef = np.array([(*c.u, *c.v) for c in curves])[owner]
    ua, ub, uc, ud, va, vb, vc, vd = coef.T
    # cubic.frame's arithmetic with each point's own coefficients
    u0, v0 = ua + p * (ub + p * (uc + p * ud)), va + p * (vb + p * (vc + p * vd))
    u1, v1 = ub + p * (2.0 * uc + p * (3.0 * ud)), vb + p * (2.0 * vc + p * (3.0 * vd))
    u2, v2 = 2.0 * uc + p * (6.0 * ud), 2.0 * vc + p * (6.0 * vd)
    u3, v3 = 6.0 * ud, 6.0 * vd
    speed2 = u1 * u1 + v1 * v1
    speed = np.sqrt(speed2)
    cross = u1 * v2 - v1 * u2
    dcross = u1 * v3 - v1 * u3
    moving = speed > 0
    dspeed = (u1 * u2 + v1 * v2) / np.where(moving, speed, np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        curvature = cross / (speed2 * speed)
        dcurvature = (dcross / (speed2 * speed) - 3.0 * cross * dspeed / (speed2 * speed2)) / speed
    angle = np.arctan2(v1, u1)
    hdg = np.array([g.hdg for g in elements])[owner]
    x0 = np.array([g.x for g in elements])[owner]
    y0 = np.array([g.y for g in elements])[owner]
    c, s = np.cos(hdg), np.sin(hdg)
    return Pose(x0 + c * u0 - s * v0, y0 + s * u0 + c * v0, hdg + angle, curvature, dcurvature)
