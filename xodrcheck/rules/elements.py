"""Parameters of single plan-view elements (``G005``, ``G050``-``G051``): what one ``<geometry>`` says about itself,
apart from its length (``G006``) and its joints with its neighbours (``G001``-``G003``).
"""

from __future__ import annotations

import math
from typing import NamedTuple

from xodrcheck.findings import Category, Severity
from xodrcheck.geometry.cubic import CubicCurve
from xodrcheck.model import Arc, ParamPoly3, PRange
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import road_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.places import element_place, finite
from xodrcheck.support.quantities import metres


class LengthVerdict(NamedTuple):
    """How a paramPoly3's curve length compares with its declared ``@length`` (Annex F, 9.6 and 13.2.3)."""

    #: The UID the mismatch breaks, ``None`` when the lengths agree.
    uid_kind: str | None
    #: The curve's length over the declared parameter range.
    actual: float
    #: Whether the curve has the declared length over the other range (``[0, @length]`` for normalized, ``[0, 1]``
    #: for arcLength): the coefficients were written for the other ``pRange``.
    fits_other: bool


def length_verdict(u: tuple, v: tuple, normalized: bool, length: float, tol: float) -> LengthVerdict:
    """``uid_kind`` is ``"arcLength_range"`` (arcLength, lengths differ: an error), ``"normalized_range"``
    (normalized, the curve has the declared length over ``[0, @length]``: an error) or ``"length_match"``
    (normalized otherwise: a warning)."""
    actual = CubicCurve.build(u, v, 1.0 if normalized else length).total
    if abs(actual - length) <= tol:
        return LengthVerdict(None, actual, False)
    fits_other = abs(CubicCurve.build(u, v, length if normalized else 1.0).total - length) <= tol
    if not normalized:
        return LengthVerdict("arcLength_range", actual, fits_other)
    return LengthVerdict("normalized_range" if fits_other else "length_match", actual, fits_other)


_PP3_UIDS = (U.PARAMPOLY3_ARC_LENGTH_RANGE, U.PARAMPOLY3_NORMALIZED_RANGE, U.PARAMPOLY3_LENGTH_MATCH)
_PP3_UID = dict(zip(("arcLength_range", "normalized_range", "length_match"), _PP3_UIDS, strict=True))


@rule("G005", "parampoly3-length-mismatch", Category.GEOMETRY, Severity.ERROR, uids=_PP3_UIDS, every_version=True)
def parampoly3_length_mismatch(ctx: Context):
    """A paramPoly3's declared ``length`` is not the length of its curve over its parameter range.

    The curve's arc length is integrated (Gauss-Legendre, to 1e-15 relative) over ``p`` in ``[0, 1]`` for
    ``pRange="normalized"`` and over ``[0, @length]`` for ``pRange="arcLength"``, and compared with ``@length`` within
    the ``length_abs`` tolerance (1 mm, as ASAM's checker). Annex F (9.6):

    * ``pRange="arcLength"``: ``p`` runs over ``[0, @length]`` (``road.geometry.paramPoly3.arcLength_range``) exactly
      when the curve is ``@length`` long there: a mismatch is an error.
    * ``pRange="normalized"``, when the curve over ``p`` in ``[0, @length]`` has the declared length: the coefficients
      were written for ``arcLength``, not for ``p`` in ``[0, 1]`` (``.normalized_range``): an error.
    * ``pRange="normalized"`` otherwise: the curve's length "should match @length" (``.length_match``): a warning.

    Passes (a 10 m straight, normalized)::

        <geometry s="0" x="0" y="0" hdg="0" length="10">
          <paramPoly3 aU="0" bU="10" cU="0" dU="0" aV="0" bV="0" cV="0" dV="0" pRange="normalized"/></geometry>

    Fails (the same curve declared 12 m long: a warning)::

        <geometry s="0" x="0" y="0" hdg="0" length="12">
          <paramPoly3 aU="0" bU="10" cU="0" dU="0" aV="0" bV="0" cV="0" dV="0" pRange="normalized"/></geometry>
    """
    tol = ctx.tolerances.length_abs
    for road in ctx.document.roads:
        for g in road.plan_view:
            if not isinstance(g, ParamPoly3) or not g.length > 0 or not math.isfinite(g.length):
                continue
            if not finite(g.aU, g.bU, g.cU, g.dU, g.aV, g.bV, g.cV, g.dV):
                continue
            normalized = g.p_range is PRange.NORMALIZED
            verdict = length_verdict((g.aU, g.bU, g.cU, g.dU), (g.aV, g.bV, g.cV, g.dV), normalized, g.length, tol)
            if verdict.uid_kind is None:
                continue
            actual, fits_other = verdict.actual, verdict.fits_other
            p_range = "[0, 1]" if normalized else f"[0, {metres(g.length)}]"
            text = (
                f"road {road.id}: the paramPoly3 at s={metres(g.s)} is declared {metres(g.length)} m long but its "
                f"curve over p in {p_range} ({g.p_range.value}) is {metres(actual)} m long (difference "
                f"{actual - g.length:+.4g} m)"
            )
            uid = _PP3_UID[verdict.uid_kind]
            if not normalized:
                hint = '; over p in [0, 1] it is: declare pRange="normalized"' if fits_other else ""
                text += f": p does not run over [0, @length]{hint}; fix @length or the coefficients"
            elif fits_other:
                text += (
                    f"; over p in [0, {metres(g.length)}] it has the declared length: the coefficients are for "
                    'pRange="arcLength", not for p in [0, 1]'
                )
            else:
                text += "; fix @length or the coefficients"
            severity = Severity.WARNING if uid == U.PARAMPOLY3_LENGTH_MATCH else Severity.ERROR
            yield parampoly3_length_mismatch.finding(text, uid=uid, severity=severity, **element_place(road, g))


@rule(
    "G050",
    "parampoly3-not-aligned",
    Category.GEOMETRY,
    Severity.WARNING,
    uids=(U.PARAMPOLY3_VALID_PARAMETERS,),
)
def parampoly3_not_aligned(ctx: Context):
    """A paramPoly3's local u/v frame is not aligned with the element's start: ``aU``, ``aV``, ``bV`` are not 0, or
    ``bU`` is not positive.

    The curve should start at the geometry's ``x``, ``y`` in the direction ``hdg`` (Annex F
    ``road.geometry.paramPoly3.valid_parameters``, 9.6): ``aU = aV = 0`` puts ``p = 0`` at the start point (within the
    ``position`` tolerance), ``bV = 0`` and ``bU > 0`` make the curve leave it along ``hdg`` (within the ``heading``
    tolerance). Otherwise the element's start is not where ``x``, ``y`` and ``hdg`` say, and readers that trust them
    disagree with readers that evaluate the polynomial.

    Passes::

        <paramPoly3 aU="0" bU="10" cU="0" dU="0" aV="0" bV="0" cV="0.5" dV="0" pRange="normalized"/>

    Fails (the curve starts 0.5 m to the left of x, y)::

        <paramPoly3 aU="0" bU="10" cU="0" dU="0" aV="0.5" bV="0" cV="0.5" dV="0" pRange="normalized"/>
    """
    tol = ctx.tolerances
    for road in ctx.document.roads:
        for g in road.plan_view:
            if not isinstance(g, ParamPoly3) or not finite(g.aU, g.bU, g.aV, g.bV):
                continue
            wrong = []
            if math.hypot(g.aU, g.aV) > tol.position:
                wrong.append(
                    f"aU={metres(g.aU)}, aV={metres(g.aV)} move its start {math.hypot(g.aU, g.aV):.4g} m off x, y"
                )
            if not g.bU > 0:
                wrong.append(f"bU={g.bU:g} is not positive")
            elif abs(math.atan2(g.bV, g.bU)) > tol.heading:
                wrong.append(f"bV={g.bV:g} turns its start {math.degrees(math.atan2(g.bV, g.bU)):.3g} deg off hdg")
            if wrong:
                yield parampoly3_not_aligned.finding(
                    f"road {road.id}: the paramPoly3 at s={metres(g.s)} is not aligned with its start point: "
                    + "; ".join(wrong)
                    + "; write the curve with aU = aV = bV = 0 and bU > 0 (shift x, y and hdg instead)",
                    **element_place(road, g),
                )


@rule("G051", "arc-zero-curvature", Category.GEOMETRY, Severity.WARNING, uids=(U.ARC_NO_ZERO_CURVATURE,))
def arc_zero_curvature(ctx: Context):
    """An ``<arc>`` has ``curvature="0"``: it is a straight line written as an arc.

    An arc's curvature should not be zero (Annex F ``road.geometry.arc.no_zero_curvature``, 9.5): readers that
    compute its radius or centre divide by zero. Write ``<line/>`` instead.

    Passes::

        <geometry s="0" x="0" y="0" hdg="0" length="10"><arc curvature="0.01"/></geometry>

    Fails::

        <geometry s="0" x="0" y="0" hdg="0" length="10"><arc curvature="0"/></geometry>
    """
    for road in ctx.document.roads:
        for g in road.plan_view:
            if isinstance(g, Arc) and g.curvature == 0.0:
                yield arc_zero_curvature.finding(
                    f"road {road.id}: the arc at s={metres(g.s)} has curvature 0: it is a straight line; write <line/>",
                    **element_place(road, g),
                )
