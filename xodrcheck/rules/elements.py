"""Parameters of single plan-view elements (``G050``-``G051``): what one ``<geometry>`` says about itself, apart from
its length (``G005``, ``G006``) and its joints with its neighbours (``G001``-``G003``).
"""

from __future__ import annotations

import math

from xodrcheck.findings import Category, Severity
from xodrcheck.model import ParamPoly3
from xodrcheck.rules import road_uids as U
from xodrcheck.rules.context import Context
from xodrcheck.rules.geometry import _at, _finite
from xodrcheck.rules.registry import rule


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
            if not isinstance(g, ParamPoly3) or not _finite(g.aU, g.bU, g.aV, g.bV):
                continue
            wrong = []
            if math.hypot(g.aU, g.aV) > tol.position:
                wrong.append(f"aU={g.aU:g}, aV={g.aV:g} move its start {math.hypot(g.aU, g.aV):.4g} m off x, y")
            if not g.bU > 0:
                wrong.append(f"bU={g.bU:g} is not positive")
            elif abs(math.atan2(g.bV, g.bU)) > tol.heading:
                wrong.append(f"bV={g.bV:g} turns its start {math.degrees(math.atan2(g.bV, g.bU)):.3g} deg off hdg")
            if wrong:
                yield parampoly3_not_aligned.finding(
                    f"road {road.id}: the paramPoly3 at s={g.s:g} is not aligned with its start point: "
                    + "; ".join(wrong)
                    + "; write the curve with aU = aV = bV = 0 and bU > 0 (shift x, y and hdg instead)",
                    **_at(road, g),
                )
