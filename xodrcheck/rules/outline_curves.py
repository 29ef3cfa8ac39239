"""Object outlines made of ``<curveLocal>`` curves (OpenDRIVE 1.9, 13.2.3): ``G060``-``G062``.

A ``<curveLocal>`` starts at (``u``, ``v``) in the object's local frame with heading ``hdg`` and runs ``length`` along
a line, an arc or a paramPoly3 (:mod:`xodrcheck.geometry.object_shape`, evaluated like the plan-view element of the same
kind). The objects themselves (positions, lane validity, corners) are the object rules'.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

import numpy as np

from xodrcheck.findings import Category, Severity
from xodrcheck.model import Arc, Line, ParamPoly3, PRange
from xodrcheck.rules.elements import length_verdict
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import road_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:
    from xodrcheck.model import CurveLocal, Outline, RoadObject


def _curve_outlines(ctx: Context) -> Iterator[tuple[RoadObject, Outline]]:
    for obj in ctx.road_objects():
        for outline in obj.outlines:
            if outline.curves:
                yield obj, outline


def _gap(a: CurveLocal, b: CurveLocal, tol: float) -> tuple[float, float, float] | None:
    """Where curve ``a`` ends (u, v) and how far that is from ``b``'s start, or ``None`` when that cannot be told
    (shape unknown, or an arcLength paramPoly3 without ``length``). Without ``length`` a curve "shall extend up to the
    next <curveLocal>": a line or arc then ends at ``b``'s start if that lies on it (ahead, for a line), a normalized
    paramPoly3 ends where ``p = 1`` takes it."""
    from xodrcheck.geometry.object_shape import curve_end

    shape = a.shape
    if shape is None:
        return None
    if a.length is not None:
        end = curve_end(a)
        return None if end is None else (end[0], end[1], math.hypot(b.u - end[0], b.v - end[1]))
    du, dv = b.u - a.u, b.v - a.v
    if isinstance(shape, Line) or (isinstance(shape, Arc) and shape.curvature == 0.0):
        along = du * math.cos(a.hdg) + dv * math.sin(a.hdg)
        across = -du * math.sin(a.hdg) + dv * math.cos(a.hdg)
        foot = (a.u + max(along, 0.0) * math.cos(a.hdg), a.v + max(along, 0.0) * math.sin(a.hdg))
        return foot[0], foot[1], math.hypot(across, min(along, 0.0))
    if isinstance(shape, Arc):
        radius = 1.0 / shape.curvature
        cu, cv = a.u - radius * math.sin(a.hdg), a.v + radius * math.cos(a.hdg)
        off = math.hypot(b.u - cu, b.v - cv) - abs(radius)
        return b.u, b.v, abs(off)
    if isinstance(shape, ParamPoly3) and shape.p_range is PRange.NORMALIZED:
        from xodrcheck.geometry.cubic import CubicCurve
        from xodrcheck.geometry.planview import evaluate_element

        total = CubicCurve.build(
            (shape.aU, shape.bU, shape.cU, shape.dU), (shape.aV, shape.bV, shape.cV, shape.dV), 1.0
        )
        if not total.total > 0:
            return None
        full = dataclasses.replace(shape, length=total.total)
        pose = evaluate_element(full, np.array([total.total]))
        u, v = float(pose.x[0]), float(pose.y[0])
        return u, v, math.hypot(b.u - u, b.v - v)
    return None


@rule(
    "G060",
    "curve-outline-discontinuous",
    Category.GEOMETRY,
    Severity.ERROR,
    uids=(U.CURVE_LOCAL_CONTINUOUS,),
)
def curve_outline_discontinuous(ctx: Context):
    """A ``<curveLocal>`` of an object outline does not start where the previous one ends.

    Outlines defined by ``<curveLocal>`` elements shall be continuous: each curve that has a predecessor starts at the
    end of the predecessor's curve (Annex F ``road.curve_local.continuous_curve_local``, 13.2.3), within the
    ``position`` tolerance. A curve without ``length`` extends up to the next curve, which must then lie on it. In a
    ``closed="true"`` outline the first curve follows the last.

    Passes (a 10 m line, then a half circle from its end)::

        <curveLocal u="0" v="0" z="0" height="0.2" hdg="0" length="10"><line/></curveLocal>
        <curveLocal u="10" v="0" z="0" height="0.2" hdg="0" length="6.283185307179586"><arc curvature="0.5"/>...

    Fails (the arc starts 1 m past the line's end)::

        <curveLocal u="0" v="0" z="0" height="0.2" hdg="0" length="10"><line/></curveLocal>
        <curveLocal u="11" v="0" z="0" height="0.2" hdg="0" length="6.283185307179586"><arc curvature="0.5"/>...
    """
    tol = ctx.tolerances.position
    for obj, outline in _curve_outlines(ctx):
        curves = list(outline.curves)
        pairs = list(itertools.pairwise(curves))
        if outline.closed and len(curves) > 1:
            pairs.append((curves[-1], curves[0]))
        for a, b in pairs:
            found = _gap(a, b, tol)
            if found is None or found[2] <= tol:
                continue
            u, v, gap = found
            yield curve_outline_discontinuous.finding(
                f"road {obj.road} object {obj.id}: the <curveLocal> at line {b.line} starts at u={metres(b.u)}, "
                f"v={metres(b.v)}, but the one before it (line {a.line}) ends at u={u:.4f}, v={v:.4f}, {gap:.4g} m "
                "away: the outline is not continuous; start each curve where the previous one ends",
                road=obj.road,
                s=obj.s,
                line=b.line,
            )


@rule("G061", "outline-empty", Category.GEOMETRY, Severity.ERROR, uids=(U.CURVE_LOCAL_MIN_AMOUNT,))
def outline_empty(ctx: Context):
    """An object's ``<outline>`` holds no ``<cornerRoad>``, ``<cornerLocal>`` or ``<curveLocal>``: it has no shape.

    An outline is made of corners or of curves; an outline without corners needs at least one ``<curveLocal>`` (Annex F
    ``road.curve_local.element_min_amount``, 13.2: "one or more <curveLocal> elements"). Too few corners is the corner
    rules' concern.

    Passes::

        <outline id="0"><curveLocal u="0" v="0" z="0" height="0.2" hdg="0" length="10"><line/></curveLocal></outline>

    Fails::

        <outline id="0"/>
    """
    for obj in ctx.road_objects():
        for outline in obj.outlines:
            if outline.points:
                continue
            yield outline_empty.finding(
                f"road {obj.road} object {obj.id}: the <outline> at line {outline.line} has no <cornerRoad>, "
                "<cornerLocal> or <curveLocal>: give its shape as at least one <curveLocal> (or its corners)",
                road=obj.road,
                line=outline.line,
            )


_CURVE_UIDS = (U.CURVE_LOCAL_ARC_LENGTH_RANGE, U.CURVE_LOCAL_NORMALIZED_RANGE, U.CURVE_LOCAL_LENGTH_MATCH)
_CURVE_UID = dict(zip(("arcLength_range", "normalized_range", "length_match"), _CURVE_UIDS, strict=True))


@rule("G062", "curve-local-length-mismatch", Category.GEOMETRY, Severity.ERROR, uids=_CURVE_UIDS)
def curve_local_length_mismatch(ctx: Context):
    """A ``<curveLocal>``'s paramPoly3 is not as long as the curve's ``length`` over its parameter range.

    As for plan-view paramPoly3s (``parampoly3-length-mismatch``), Annex F (13.2.3): with ``pRange="arcLength"``, ``p``
    runs over ``[0, @length]`` (``road.curve_local.paramPoly3.arcLength_range``: a mismatch, or no ``length`` at all,
    is an error); with ``pRange="normalized"`` over ``[0, 1]``: coefficients that have the declared length only over
    ``[0, @length]`` break ``.paramPoly3.normalized_range`` (an error), any other mismatch ``.length_match`` (a
    warning). Lengths are compared within ``length_abs``.

    Passes (a 10 m straight, normalized)::

        <curveLocal u="0" v="0" z="0" height="0.2" hdg="0" length="10">
          <paramPoly3 aU="0" bU="10" cU="0" dU="0" aV="0" bV="0" cV="0" dV="0" pRange="normalized"/></curveLocal>

    Fails (the same curve declared 12 m long: a warning)::

        <curveLocal u="0" v="0" z="0" height="0.2" hdg="0" length="12">
          <paramPoly3 aU="0" bU="10" cU="0" dU="0" aV="0" bV="0" cV="0" dV="0" pRange="normalized"/></curveLocal>
    """
    tol = ctx.tolerances.length_abs
    for obj, outline in _curve_outlines(ctx):
        for curve in outline.curves:
            g = curve.shape
            if not isinstance(g, ParamPoly3):
                continue
            where: dict[str, Any] = {"road": obj.road, "s": obj.s, "line": g.line or curve.line}
            mine = f"road {obj.road} object {obj.id}: the paramPoly3 of the <curveLocal> at line {curve.line}"
            normalized = g.p_range is PRange.NORMALIZED
            if curve.length is None:
                if not normalized:
                    yield curve_local_length_mismatch.finding(
                        f'{mine} has pRange="arcLength" but the curve has no length: p runs over [0, @length]; give '
                        "the <curveLocal> its length",
                        uid=U.CURVE_LOCAL_ARC_LENGTH_RANGE,
                        **where,
                    )
                continue
            verdict = length_verdict((g.aU, g.bU, g.cU, g.dU), (g.aV, g.bV, g.cV, g.dV), normalized, curve.length, tol)
            if verdict.uid_kind is None:
                continue
            uid = _CURVE_UID[verdict.uid_kind]
            p_range = "[0, 1]" if normalized else f"[0, {metres(curve.length)}]"
            text = (
                f"{mine} is {metres(verdict.actual)} m long over p in {p_range} ({g.p_range.value}), but the curve's "
                f"length is {metres(curve.length)}"
            )
            if verdict.uid_kind == "normalized_range":
                text += f"; over p in [0, {metres(curve.length)}] it is: the coefficients are for arcLength, not [0, 1]"
            elif verdict.uid_kind == "arcLength_range":
                text += ": p does not run over [0, @length]"
            severity = Severity.WARNING if uid == U.CURVE_LOCAL_LENGTH_MATCH else Severity.ERROR
            yield curve_local_length_mismatch.finding(
                text + "; fix the length or the coefficients", uid=uid, severity=severity, **where
            )
