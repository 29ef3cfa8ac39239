"""Where a virtual junction's connecting roads join its main road (``J027``, 12.7).

A connecting road of a virtual junction starts or ends inside its main road, at ``elementS`` of its link to it (the
main road is not cut). There the two roads meet as linked roads do (10.3): the same heading (``elementDir="+"``: the
connecting road runs the main road's way, ``"-"``: against it) and each linked lane's borders on the main road's lane
borders at ``elementS``, in plan view and in height. Deviations are graded as the joints of ``K102``-``K104`` are:
over ``kink``/``gap`` an error, over the strict ``heading``/``position`` a warning (naming no rule of the standard).
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np

from xodrcheck.findings import Basis, Category, Finding, Severity
from xodrcheck.geometry.lanes import RoadGeometry
from xodrcheck.model import ContactPoint, ElementType, Junction, JunctionType, Road
from xodrcheck.rules.registry import NO_UID, rule
from xodrcheck.rules.shared import junction_uids as U
from xodrcheck.rules.shared.context import Context, describe_junction
from xodrcheck.rules.shared.road_ends import end_s, left_of
from xodrcheck.rules.shared.sampled import angle_between, warning_note
from xodrcheck.support.quantities import metres


def _branches(ctx: Context) -> Iterator[tuple[Junction, Road, Road, ContactPoint, float, str | None, int]]:
    """(junction, main road, connecting road, its end at the main road, elementS, elementDir, link line)."""
    for j in ctx.document.junctions:
        if j.type is not JunctionType.VIRTUAL or j.main_road is None:
            continue
        main = ctx.road(j.main_road)
        if main is None or ctx.usable_geometry(main) is None:
            continue
        seen: set[str] = set()
        for c in j.connections:
            road = ctx.road(c.connecting_road)
            if road is None or road.id in seen or road.id == main.id or ctx.usable_geometry(road) is None:
                continue
            seen.add(road.id)
            for end in (ContactPoint.START, ContactPoint.END):
                link = road.link_at(end)
                if link is None or link.element_type is not ElementType.ROAD or link.element_id != main.id:
                    continue
                if link.element_s is None or not 0.0 <= link.element_s <= main.length:
                    continue
                direction = link.element_dir.value if link.element_dir is not None else None
                yield j, main, road, end, link.element_s, direction, link.line or 0


def _at(geometry: RoadGeometry, road: Road, s: float) -> tuple[int, np.ndarray]:
    s = min(max(s, 0.0), left_of(float(road.length)))
    return int(geometry.section_index(s)[0]), np.array([s])


def _lane_gap(
    mine: RoadGeometry, road: Road, at: float, lane: int, main_geometry: RoadGeometry, main: Road, s: float, other: int
) -> tuple[float, float, float, float] | None:
    """(plan gap, height step, x, y) between a lane's borders at ``at`` and the main road lane's at ``s``."""
    i, sa = _at(mine, road, at)
    k, sb = _at(main_geometry, main, s)
    if i < 0 or k < 0:
        return None
    try:
        a = [mine.lane_points(i, lane, sa, where) for where in ("inner", "outer")]
        b = [main_geometry.lane_points(k, other, sb, where) for where in ("inner", "outer")]
    except KeyError:
        return None  # a lane link to a lane that is not there: the reference rules report it

    def d(p, q) -> float:
        return math.hypot(float(p.x[0] - q.x[0]), float(p.y[0] - q.y[0]))

    def dz(p, q) -> float:
        return abs(float(p.z[0] - q.z[0]))

    same = max(d(a[0], b[0]), d(a[1], b[1]))
    crossed = max(d(a[0], b[1]), d(a[1], b[0]))
    pairs = ((a[0], b[0]), (a[1], b[1])) if same <= crossed else ((a[0], b[1]), (a[1], b[0]))
    step = max(dz(p, q) for p, q in pairs)
    return min(same, crossed), (step if math.isfinite(step) else 0.0), float(a[1].x[0]), float(a[1].y[0])


@rule(
    "J027",
    "virtual-junction-joint",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(U.VIRTUAL_HEADING, U.VIRTUAL_SMOOTH),
    basis=Basis.PLAUSIBILITY,
)
def virtual_junction_joint(ctx: Context) -> Iterator[Finding]:
    """A connecting road of a virtual junction does not join its main road smoothly at ``elementS``.

    The heading of a connecting road and of the main road are equal where they meet, at ``sStart`` and ``sEnd``
    (``junctions.virtual.heading_equal_mainroad``, 12.7; ``elementDir="-"``: opposite), and the linked lanes fit
    smoothly (``junctions.virtual.linked_lanes_smooth_fit``, as described for roads in 10.3): each lane of the
    connecting road whose predecessor (at its start) or successor (at its end) names a lane of the main road has its
    inner and outer border on that lane's borders at ``elementS``, at the same height. Over ``kink`` (0.01 rad) or
    ``gap`` (1 cm) an error; over the strict ``heading``/``position`` a warning.

    Passes (road 2 leaves main road 1 at s=50 heading east, as road 1 does there; its lane -1 continues lane -1)::

        <road id="2" junction="555"><link><predecessor elementType="road" elementId="1" elementS="50"
          elementDir="+"/> ...<geometry s="0" x="50" y="0" hdg="0" ...><arc curvature="-0.1"/></geometry>

    Fails (road 2 leaves at 0.3 rad to the main road, 1.5 m off its lane)::

        <geometry s="0" x="50" y="-1.5" hdg="-0.3" ...>
    """
    tol = ctx.tolerances
    for j, main, road, end, s, direction, line in _branches(ctx):
        geometry, main_geometry = ctx.geometry(road.id), ctx.geometry(main.id)
        if geometry is None or main_geometry is None:
            continue
        at = end_s(road, end)
        pose, main_pose = geometry.reference(np.array([at])), main_geometry.reference(_at(main_geometry, main, s)[1])
        hdg, main_hdg = float(pose.hdg[0]), float(main_pose.hdg[0])
        turn = angle_between(hdg, main_hdg + (math.pi if direction == "-" else 0.0))
        if direction is None:
            turn = min(turn, angle_between(hdg, main_hdg + math.pi))
        where = {"road": road.id, "s": at, "x": float(pose.x[0]), "y": float(pose.y[0]), "line": line or None}
        severity = tol.grade(turn, "heading")
        if severity is not None:
            yield virtual_junction_joint.finding(
                f"{describe_junction(j)}: connecting road {road.id} {_verb(end)} main road {main.id} at s={metres(s)} "
                f"heading {math.degrees(turn):.2f} deg off the main road's heading there ({math.degrees(main_hdg):.2f} "
                f"deg{', reversed' if direction == '-' else ''}); make the headings equal where they "
                f"meet{warning_note(severity, tol, 'heading')}",
                uid=U.VIRTUAL_HEADING if severity is Severity.ERROR else NO_UID,
                severity=severity,
                **where,
            )
        yield from _lanes(ctx, j, main, road, end, s, at, line)


def _verb(end: ContactPoint) -> str:
    return "leaves" if end is ContactPoint.START else "joins"


def _lanes(
    ctx: Context, j: Junction, main: Road, road: Road, end: ContactPoint, s: float, at: float, line: int
) -> Iterator[Finding]:
    tol = ctx.tolerances
    geometry, main_geometry = ctx.geometry(road.id), ctx.geometry(main.id)
    if geometry is None or main_geometry is None:
        return
    index = 0 if end is ContactPoint.START else len(road.lane_sections) - 1
    for side in geometry.side_lanes(index):
        for lane in side.lanes:
            for other in lane.predecessors if end is ContactPoint.START else lane.successors:
                found = _lane_gap(geometry, road, at, lane.id, main_geometry, main, s, other)
                if found is None:
                    continue
                gap, step, x, y = found
                plan, height = tol.grade(gap), tol.grade(step)
                severity = Severity.ERROR if Severity.ERROR in (plan, height) else plan or height
                if severity is None:
                    continue
                what = f"their borders are {gap:.4g} m apart" if plan is not None else ""
                if height is not None:
                    what += f"{' and ' if what else ''}their surfaces step by {step:.4g} m"
                yield virtual_junction_joint.finding(
                    f"{describe_junction(j)}: lane {lane.id} of connecting road {road.id} continues lane {other} of "
                    f"main road {main.id} at s={metres(s)}, but {what}; make the linked lanes meet where the road "
                    f"{_verb(end)} the main road{warning_note(severity, tol)}",
                    uid=U.VIRTUAL_SMOOTH if severity is Severity.ERROR else NO_UID,
                    severity=severity,
                    road=road.id,
                    lane=lane.id,
                    section_s=road.lane_sections[index].s,
                    s=at,
                    x=x,
                    y=y,
                    line=line or None,
                )
