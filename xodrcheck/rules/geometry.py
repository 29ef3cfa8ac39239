"""Plan view and lane-section geometry (``G0xx``-``G8xx``; the lane-width rules ``G010``/``G011`` are in
:mod:`.lane_shape`).

Plan view: consecutive elements must join in position (``G001``) and heading (``G002``), their ``s`` must run on
without jumps (``G003``) up to the road's length (``G004``); elements must not be degenerate (``G006``, ``G007``); what
one element says about itself (a paramPoly3's length, ``G005``) is :mod:`.elements`'. Lane sections must have a
length (``G012``). A section so long that the geometric rules' samples would exceed ``max_samples_per_section`` is
sampled more coarsely, and says so (``G013``). The elevation, superelevation and laneOffset profiles must not jump
where a record starts (``G014``).
"""

from __future__ import annotations

import itertools
import math
from typing import Any

import numpy as np

from xodrcheck.config import Tolerances
from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.geometry import profile
from xodrcheck.geometry.planview import ReferenceLine, evaluate_element
from xodrcheck.geometry.sampling import capped
from xodrcheck.model import Cubic, Geometry, Road, Spiral
from xodrcheck.rules.registry import NO_UID, rule
from xodrcheck.rules.shared import road_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.lane_uids import SECTION_VALID_LENGTH
from xodrcheck.rules.shared.places import element_place, finite
from xodrcheck.rules.shared.sampled import angle_between, grid_step, warning_note
from xodrcheck.support.quantities import metres

_KIND = {"Line": "line", "Arc": "arc", "Spiral": "spiral", "Poly3": "poly3", "ParamPoly3": "paramPoly3"}


def _kind(g: Geometry) -> str:
    return _KIND.get(type(g).__name__, type(g).__name__)


def _pairs(road: Road):
    """Consecutive plan-view elements (sorted by ``s`` as the reference line uses them) with finite attributes."""
    elements = ReferenceLine(road.plan_view).elements
    for a, b in itertools.pairwise(elements):
        if finite(a.s, a.x, a.y, a.hdg, a.length, b.s, b.x, b.y, b.hdg) and a.length >= 0:
            yield a, b


def _end_of(g: Geometry):
    pose = evaluate_element(g, np.array([g.length]))
    return float(pose.x[0]), float(pose.y[0]), float(pose.hdg[0])


@rule(
    "G001",
    "plan-view-gap",
    Category.GEOMETRY,
    Severity.ERROR,
    uids=(U.GEOMETRY_NO_GAPS,),
    every_version=True,
    basis=Basis.PLAUSIBILITY,
)
def plan_view_gap(ctx: Context):
    """A plan-view element does not start where the previous one ends: the reference line has a gap.

    The end point of each ``<geometry>`` (evaluated exactly) must be the next one's ``x``, ``y`` (Annex F
    ``road.geometry.refline_no_gaps``, "shall"). Graded: a gap over ``gap`` (1 cm, ASAM's checker's threshold) is an
    error, one over ``position`` (1 mm) a warning (naming no rule of the standard); ``--profile strict`` makes errors
    of gaps over ``position``.

    Passes (a 10 m line along x, then the next element at x=10)::

        <geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry>
        <geometry s="10" x="10" y="0" hdg="0" length="10"><line/></geometry>

    Fails (the second element starts 5 cm further on; 5 mm would be a warning)::

        <geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry>
        <geometry s="10" x="10.05" y="0" hdg="0" length="10"><line/></geometry>
    """
    tol = ctx.tolerances
    for road in ctx.document.roads:
        for a, b in _pairs(road):
            x, y, _ = _end_of(a)
            gap = math.hypot(b.x - x, b.y - y)
            severity = tol.grade(gap)
            if severity is not None:
                yield plan_view_gap.finding(
                    f"road {road.id}: the {_kind(a)} at s={metres(a.s)} ends at ({x:.4f}, {y:.4f}) but the next "
                    f"element starts at ({b.x:.4f}, {b.y:.4f}), a gap of {gap:.4g} m; correct the x/y of the element "
                    f"at s={metres(b.s)} or the previous element's parameters{warning_note(severity, tol)}",
                    severity=severity,
                    uid=None if severity is Severity.ERROR else NO_UID,
                    **element_place(road, b),
                )


@rule(
    "G002",
    "plan-view-kink",
    Category.GEOMETRY,
    Severity.ERROR,
    uids=(U.GEOMETRY_NO_KINKS,),
    every_version=True,
    basis=Basis.PLAUSIBILITY,
)
def plan_view_kink(ctx: Context):
    """A plan-view element does not start in the direction the previous one ends: the reference line has a kink.

    The heading at the end of each ``<geometry>`` must be the next one's ``hdg`` (modulo 2 pi) (Annex F
    ``road.geometry.refline_no_kinks``, a "should": a warning under the default profile). Graded: a kink over ``kink``
    (0.01 rad, 0.57 deg) names the UID, an error under ``--profile strict`` or ``generator``; one over ``heading``
    (1 mrad) is a warning naming no rule of the standard. A kink without a gap is invisible to position checks but
    makes every lane border jump (a gap on the outside of the turn, an overlap on the inside, w * angle wide).

    Passes::

        <geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry>
        <geometry s="10" x="10" y="0" hdg="0" length="10"><line/></geometry>

    Fails (the second element turns 0.1 rad)::

        <geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry>
        <geometry s="10" x="10" y="0" hdg="0.1" length="10"><line/></geometry>
    """
    tol = ctx.tolerances
    for road in ctx.document.roads:
        for a, b in _pairs(road):
            _, _, hdg = _end_of(a)
            kink = angle_between(hdg, b.hdg)
            severity = tol.grade(kink, "heading")
            if severity is not None:
                yield plan_view_kink.finding(
                    f"road {road.id}: the {_kind(a)} at s={metres(a.s)} ends with heading {hdg:.5f} rad but the next "
                    f"element starts with hdg={b.hdg:.5f}, a kink of {math.degrees(kink):.3g} deg; make the headings "
                    f"agree{warning_note(severity, tol, 'heading')}",
                    severity=severity,
                    uid=None if severity is Severity.ERROR else NO_UID,
                    **element_place(road, b),
                )


@rule("G003", "plan-view-s-jump", Category.GEOMETRY, Severity.ERROR, uids=(U.GEOMETRY_S_VALUE_SUM,), every_version=True)
def plan_view_s_jump(ctx: Context):
    """The ``s`` of a plan-view element is not the previous element's ``s`` plus its length (or the first is not 0).

    ``s`` is the arc length along the reference line, so it starts at 0 and each element starts where the previous
    one ends (within the ``length_abs`` tolerance): the sum of the lengths of the elements before it (Annex F
    ``road.geometry.s-value_sum``, 1.9).

    Passes::

        <geometry s="0" ... length="10"><line/></geometry>
        <geometry s="10" ... length="10"><line/></geometry>

    Fails (s jumps from 10 to 12)::

        <geometry s="0" ... length="10"><line/></geometry>
        <geometry s="12" ... length="10"><line/></geometry>
    """
    tol = ctx.tolerances.length_abs
    for road in ctx.document.roads:
        elements = ReferenceLine(road.plan_view).elements
        if elements and math.isfinite(elements[0].s) and abs(elements[0].s) > tol:
            first = elements[0]
            yield plan_view_s_jump.finding(
                f"road {road.id}: the plan view starts at s={metres(first.s)}, not at s=0",
                **element_place(road, first),
            )
        for a, b in _pairs(road):
            expected = a.s + a.length
            # s and length are decimals: 202.082 + 161.953 against 364.036 differs from 1 mm by 3e-14 in binary
            if round(abs(b.s - expected), 9) > tol:
                yield plan_view_s_jump.finding(
                    f"road {road.id}: the element at s={metres(b.s)} follows a {_kind(a)} at s={metres(a.s)} of length "
                    f"{metres(a.length)}, so it should start at s={metres(expected)} "
                    f"({'overlap' if b.s < expected else 'gap'} of {abs(b.s - expected):.4g} m in s)",
                    **element_place(road, b),
                )


@rule(
    "G004",
    "road-length-mismatch",
    Category.GEOMETRY,
    Severity.ERROR,
    uids=(U.LENGTH_SUM_GEOMETRIES,),
    every_version=True,
)
def road_length_mismatch(ctx: Context):
    """A road's ``length`` is not where its plan view ends.

    The last element's ``s + length``, and the sum of the elements' lengths, must equal the road's ``length`` within
    ``length_abs + length_rel * length``: lanes, objects and links are placed by ``s`` up to the road's length (Annex F
    ``road.length_sum_geometries``, 1.9: a "should", so a warning under the default profile; an error under
    ``--profile strict`` or ``generator``, as where the road's end is not where its geometry ends, links join where
    there is no road).

    Passes::

        <road id="1" length="20"> ... <geometry s="0" length="10"/> <geometry s="10" length="10"/>

    Fails (the plan view ends at s=20)::

        <road id="1" length="25"> ... <geometry s="0" length="10"/> <geometry s="10" length="10"/>
    """
    tol = ctx.tolerances
    for road in ctx.document.roads:
        elements = ReferenceLine(road.plan_view).elements
        if not elements or not finite(road.length, elements[-1].s, elements[-1].length):
            continue
        end = elements[-1].s + elements[-1].length
        total = math.fsum(g.length for g in elements)
        slack = tol.length_abs + tol.length_rel * abs(road.length)
        if abs(end - road.length) > slack:
            yield road_length_mismatch.finding(
                f"road {road.id}: length is {metres(road.length)} but its plan view ends at s={metres(end)} "
                f"(difference {end - road.length:+.4g} m); set the road's length to the sum of its elements' lengths",
                road=road.id,
                s=min(end, road.length),
                line=road.line or None,
            )
        elif math.isfinite(total) and abs(total - road.length) > slack:
            yield road_length_mismatch.finding(
                f"road {road.id}: length is {metres(road.length)} and its plan view ends there, but the lengths of its "
                f"{len(elements)} elements add up to {metres(total)} (difference {total - road.length:+.4g} m): their "
                "s values skip or overlap (see plan-view-s-jump); the road's length is the sum of its elements' "
                "lengths",
                road=road.id,
                s=road.length,
                line=road.line or None,
            )


@rule("G006", "degenerate-geometry", Category.GEOMETRY, Severity.ERROR, basis=Basis.PLAUSIBILITY)
def degenerate_geometry(ctx: Context):
    """A plan-view element has no length: zero or negative (an error), or shorter than ``length_abs`` (a warning).

    Such an element has no direction of its own; readers divide by its length.

    Plausibility: from 1.7 the schema requires a length above zero (``schema-invalid`` reports that); an element
    shorter than ``length_abs`` is valid but has no direction worth the name. A warning under the default profile,
    the rule's error under ``--profile strict`` or ``generator``.

    Passes::

        <geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry>

    Fails::

        <geometry s="0" x="0" y="0" hdg="0" length="0"><line/></geometry>
    """
    tol = ctx.tolerances.length_abs
    for road in ctx.document.roads:
        for g in road.plan_view:
            if not math.isfinite(g.length) or g.length >= tol:
                continue
            where: dict[str, Any] = {"road": road.id, "s": g.s, "x": g.x, "y": g.y, "line": g.line or road.line or None}
            if g.length <= 0:
                yield degenerate_geometry.finding(
                    f"road {road.id}: the {_kind(g)} at s={metres(g.s)} has length {metres(g.length)}; remove it or "
                    "give it a positive length",
                    **where,
                )
            else:
                yield degenerate_geometry.finding(
                    f"road {road.id}: the {_kind(g)} at s={metres(g.s)} is only {g.length:.3g} m long; merge it into a "
                    "neighbouring element",
                    severity=Severity.WARNING,
                    **where,
                )


@rule(
    "G007",
    "spiral-constant-curvature",
    Category.GEOMETRY,
    Severity.WARNING,
    uids=(U.SPIRAL_CURVATURE_CHANGE,),
    every_version=True,
)
def spiral_constant_curvature(ctx: Context):
    """A spiral's start and end curvature are equal: it is a line or an arc written as a degenerate clothoid.

    A clothoid's curvature changes linearly; with no change its parameter is infinite, and readers that compute it
    divide by zero (Annex F ``road.geometry.spiral.curvature_change``, 1.9).

    Passes::

        <geometry ... length="10"><spiral curvStart="0" curvEnd="0.01"/></geometry>

    Fails (write ``<arc curvature="0.01"/>``)::

        <geometry ... length="10"><spiral curvStart="0.01" curvEnd="0.01"/></geometry>
    """
    for road in ctx.document.roads:
        for g in road.plan_view:
            if isinstance(g, Spiral) and g.curv_start == g.curv_end:
                shape = "<line/>" if g.curv_start == 0 else f'<arc curvature="{g.curv_start:g}"/>'
                yield spiral_constant_curvature.finding(
                    f"road {road.id}: the spiral at s={metres(g.s)} has curvStart = curvEnd = {g.curv_start:g}; write "
                    f"{shape} instead",
                    **element_place(road, g),
                )


@rule(
    "G012",
    "short-lane-section",
    Category.GEOMETRY,
    Severity.WARNING,
    uids=(SECTION_VALID_LENGTH,),
    every_version=True,
    basis=Basis.PLAUSIBILITY,
)
def short_lane_section(ctx: Context):
    """A lane section is shorter than ``min_section_length`` (1 cm by default), or has no length at all.

    Such a section describes no road; tools that build lane polylines fail on it (pyxodr does). A section of zero or
    negative length (the next one starts where it starts, or the road ends there) is an error: Annex F
    ``road.lane_section.valid_length`` wants every lane section longer than zero. A shorter one than the tolerance is a
    warning.

    Passes::

        <laneSection s="0"> ... <laneSection s="50"> ...   (road length 100)

    Fails::

        <laneSection s="0"> ... <laneSection s="0.001"> ...
    """
    tol = ctx.tolerances.min_section_length
    for road in ctx.document.roads:
        if not math.isfinite(road.length):
            continue
        for index, section in enumerate(road.lane_sections):
            length = road.section_end(index) - section.s
            if math.isfinite(length) and length < tol:
                empty = length <= 0.0
                yield short_lane_section.finding(
                    f"road {road.id}: the lane section at s={metres(section.s)} is {length:.3g} m long; remove it or "
                    "merge it with its neighbour" + (" (a lane section is longer than zero)" if empty else ""),
                    severity=Severity.ERROR if empty else None,
                    uid=SECTION_VALID_LENGTH if empty else NO_UID,
                    road=road.id,
                    section_s=section.s,
                    s=section.s,
                    line=section.line or road.line or None,
                )


@rule("G013", "sampling-capped", Category.GEOMETRY, Severity.WARNING, basis=Basis.INCOMPLETE)
def sampling_capped(ctx: Context):
    """A lane section is too long to sample at the geometric rules' step within ``max_samples_per_section``.

    The sampled rules (lane joints, curvature, overlaps) then step proportionally further apart, so that an absurdly
    long road (1e9 m) still costs bounded time and memory; what they find there is less precise. Raise the budget
    (``max_samples_per_section``) to check such a road at full resolution.

    Passes (100 m)::

        <road id="1" length="100"> ... <laneSection s="0">

    Fails (1e9 m: 1.6e9 steps of 0.63 m)::

        <road id="1" length="1e9"> ... <laneSection s="0">
    """
    tol = ctx.tolerances
    step = grid_step(tol)
    budget = tol.max_samples_per_section
    for road, geometry, index, section in ctx.usable_sections():
        cuts = geometry.knots(index)
        if not capped(np.diff(cuts), step, budget):
            continue
        length = road.section_end(index) - section.s
        yield sampling_capped.finding(
            f"road {road.id}: the lane section at s={metres(section.s)} is {length:.4g} m long; the geometric "
            f"rules sample it with about {budget:,} points, a {length / max(budget, 1):.4g} m step instead of "
            f"{step:.3g} m (max_samples_per_section): their findings there are less precise",
            road=road.id,
            section_s=section.s,
            s=section.s,
            line=section.line or road.line or None,
        )


#: The road-level profiles G014 checks: attribute of :class:`Road`, element name, unit and kind of deviation.
_PROFILES = (
    ("elevation", "elevation", "m", "position"),
    ("superelevation", "superelevation", "rad", "heading"),
    ("lane_offset", "laneOffset", "m", "position"),
)


def profile_steps(road: Road, tolerances: Tolerances) -> list[tuple[str, str, Cubic, float, float, Severity]]:
    """(element name, unit, record, value reached before it, value it starts with, severity) for every jump of a road's
    elevation, superelevation or laneOffset graded as a finding (:meth:`Tolerances.grade`: positions for metres,
    headings for radians)."""
    out = []
    section_starts = {section.s for section in road.lane_sections}
    for attribute, element, unit, kind in _PROFILES:
        for record, reached, starts in profile.jumps(getattr(road, attribute)):
            if attribute == "lane_offset" and record.s in section_starts:
                continue  # lanes change there too: whether their borders continue is lane-border-discontinuous's
            severity = tolerances.grade(abs(starts - reached), kind)
            if severity is not None:
                out.append((element, unit, record, reached, starts, severity))
    return out


@rule("G014", "profile-step", Category.GEOMETRY, Severity.ERROR, basis=Basis.PLAUSIBILITY)
def profile_step(ctx: Context):
    """The elevation, superelevation or laneOffset of a road jumps where a record starts: the surface steps.

    Each ``<elevation>``, ``<superelevation>`` and ``<laneOffset>`` record holds until the next one starts; the next
    one must start with the value the previous one reaches there (ASAM OpenDRIVE Annex D.1.4.1: "no vertical gaps in
    the elevation definition and lateral profile definition of the road"; a laneOffset jump moves every lane sideways).
    Graded: heights and offsets step by more than ``gap`` (1 cm) is an error, by more than ``position`` (1 mm) a
    warning; superelevation (an angle) likewise with ``kink`` (0.01 rad) and ``heading`` (1 mrad). Where a
    lane section starts, the laneOffset may jump with the lanes (their borders are checked by
    ``lane-border-discontinuous``).

    Plausibility: Annex D says so in words, but Annex F gives it no checker rule, so a warning under the default
    profile; ``--profile strict`` or ``generator`` makes steps over ``gap`` errors.

    Passes (the second record starts at 0 + 0.02 * 50 = 1 m)::

        <elevation s="0" a="0" b="0.02" c="0" d="0"/><elevation s="50" a="1.0" b="0.02" c="0" d="0"/>

    Fails (it starts at 1.05 m: a 5 cm step)::

        <elevation s="0" a="0" b="0.02" c="0" d="0"/><elevation s="50" a="1.05" b="0.02" c="0" d="0"/>
    """
    for road in ctx.document.roads:
        for element, unit, record, reached, starts, severity in profile_steps(road, ctx.tolerances):
            size = abs(starts - reached)
            shown = f"{math.degrees(size):.3g} deg ({size:.4g} rad)" if unit == "rad" else f"{size:.4g} m"
            kind = "heading" if unit == "rad" else "position"
            yield profile_step.finding(
                f"road {road.id}: the {element} jumps by {shown} at s={metres(record.s)}: the record before reaches "
                f"{reached:.6g} {unit} there, the <{element}> at s={metres(record.s)} starts at {starts:.6g} {unit}; "
                f"make it start where the previous one ends{warning_note(severity, ctx.tolerances, kind)}",
                severity=severity,
                road=road.id,
                s=record.s,
                line=record.line or road.line or None,
            )
