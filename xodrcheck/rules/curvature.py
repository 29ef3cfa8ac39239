"""Curvature (``C0xx``): curves a vehicle can follow and lane borders that do not fold.

Every lane section is sampled and evaluated once (:func:`xodrcheck.rules.shared.sampled.section_lines`: every knot, and
steps keeping the chord error under ``chord`` for curves within the radius bound) and the curvature of the lines is
evaluated exactly there
(offset-curve curvature with the lane's width change, :mod:`xodrcheck.geometry.lanes`).

Decisions
---------
* The bound is ``min_radius`` (5 m by default): a radius under it is reported for the centre line of every drivable
  lane (``C001``) and for the lane-0 line (the reference line shifted by the laneOffset) where it borders a drivable
  lane, i.e. where lane 1 or lane -1 is drivable (``C002``). A reference line that runs beside the lanes, away from
  any drivable lane, is a construction line: its own curvature is no one's path, and the lanes' own curvature is
  checked by ``C001``.
* A border at lateral offset ``t`` folds back where ``t * k >= 1`` (``k`` the reference line's curvature): it then
  reaches or passes the centre of curvature, its length per metre of ``s`` (``1 - t k``) is zero or negative, and the
  lane turns inside out (``C003``). Only the inner side of a curve folds: on the outer side (``t k <= -1``) a border
  is a larger circle. ``t`` is taken before superelevation, which can only bring a border closer to the reference
  line.
"""

from __future__ import annotations

import math

import numpy as np

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.geometry.batch import centre_lines
from xodrcheck.geometry.lines import tightest
from xodrcheck.model import Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.sampled import BATCH_SAMPLES, lines_in_order, section_lines, section_samples
from xodrcheck.support.quantities import metres


def _sections(ctx: Context):
    """(road, section index, geometry, s samples) for every usable road's lane sections."""
    for road in ctx.document.roads:
        geometry = ctx.usable_geometry(road)
        if geometry is None:
            continue
        for index in range(len(road.lane_sections)):
            s = section_samples(ctx, road, index)
            if len(s):
                yield road, index, geometry, s


def _where(road: Road, index: int, lane_id: int | None, s: float, x: float, y: float, line: int) -> dict:
    return {
        "road": road.id,
        "lane": lane_id,
        "section_s": road.lane_sections[index].s,
        "s": s,
        "x": x,
        "y": y,
        "line": line or road.lane_sections[index].line or road.line or None,
    }


@rule("C001", "lane-radius-too-small", Category.CURVATURE, Severity.ERROR, basis=Basis.PLAUSIBILITY)
def lane_radius_too_small(ctx: Context):
    """The centre line of a drivable lane curves tighter than ``min_radius`` (5 m by default).

    Reported once per lane and lane section, at the tightest sampled point. A lane whose inner or outer border folds
    in the section (``border-folds``: the curve is too tight for the lane) is reported there only, once for one cause.

    Plausibility: the standard sets no minimum radius; 5 m is this checker's bound for a lane a vehicle can follow
    (the JunctionArt generator keeps every lane above it). A warning under the default profile, an error under
    ``--profile strict`` or ``generator``.

    Passes (an arc of radius 50 m)::

        <geometry ... length="20"><arc curvature="0.02"/></geometry>

    Fails (an arc of radius 0.5 m)::

        <geometry ... length="1"><arc curvature="2"/></geometry>
    """
    bound = 1.0 / ctx.tolerances.min_radius if ctx.tolerances.min_radius > 0 else math.inf
    together = _centre_hits(ctx, bound)
    for road, index, geometry, s in _sections(ctx):
        placed = geometry.placed_lane_ids(index)
        hits = together[(road.id, index)]
        for lane in road.lane_sections[index].lanes:
            if lane.id not in placed or not lane.drivable:
                continue  # lane 0, and lanes filed on the wrong side (lane-id-sequence reports those)
            hit = hits.get(lane.id)
            if hit is None or _folds(ctx, road, index, lane.id):
                continue
            i, curvature, x, y = hit
            yield lane_radius_too_small.finding(
                f"road {road.id}: the centre of {lane.type.value} lane {lane.id} has a radius of "
                f"{1.0 / abs(curvature):.3g} m at s={metres(s[i])}, under the {metres(ctx.tolerances.min_radius)} m "
                "minimum; widen the curve",
                **_where(road, index, lane.id, float(s[i]), x, y, lane.line),
            )


def _folds(ctx: Context, road: Road, index: int, lane_id: int) -> bool:
    """Whether the lane's inner or outer border folds in the section (``border-folds`` reports it: the curve is too
    tight for the lane, and the radius of its centre line is a consequence, not a second defect)."""
    lines = section_lines(ctx, road, index)
    step = 1 if lane_id > 0 else -1
    for border in (lane_id - step, lane_id):
        t = lines.t.get(border)
        if t is not None and np.nanmax(np.nan_to_num(t * lines.curvature, nan=0.0), initial=0.0) >= 1.0:
            return True
    return False


#: The tightest point of a lane's centre line above the bound: (sample index, curvature, x, y).
_Hit = tuple[int, float, float, float]


def _centre_hits(ctx: Context, bound: float) -> dict[tuple[str, int], dict[int, _Hit]]:
    """The tightest centre point above ``bound`` of each drivable lane (none: not listed) of every lane section, by
    (road id, section index) and lane id, evaluated together in batches of samples
    (:func:`xodrcheck.geometry.batch.centre_lines`: the numbers of ``lane_points`` lane by lane)."""
    entries, keys, grids, wanted = [], [], [], []
    out: dict[tuple[str, int], dict[int, _Hit]] = {}
    for road, index, geometry, s in _sections(ctx):
        placed = geometry.placed_lane_ids(index)
        lanes = [lane.id for lane in road.lane_sections[index].lanes if lane.id in placed and lane.drivable]
        out[(road.id, index)] = {}
        if lanes:
            entries.append(geometry.rows(index))
            keys.append((road.id, index))
            grids.append(s)
            wanted.append(list(dict.fromkeys(lanes)))
    for lo, hi, found in centre_lines(entries, grids, wanted, BATCH_SAMPLES):
        lanes = [(k, lane_id) for k in range(hi - lo) for lane_id in wanted[lo + k]]
        hits = [(j, hit) for j, hit in enumerate(found.tightest(bound)) if hit is not None]
        x, y = found.xy(np.array([pair for _, (pair, _) in hits], dtype=np.int64))
        curvature = found.bend()[2]
        for (j, (pair, i)), xj, yj in zip(hits, x.tolist(), y.tolist()):
            k, lane_id = lanes[j]
            out[keys[lo + k]][lane_id] = (i, float(curvature[pair]), xj, yj)
    return out


@rule("C002", "reference-radius-too-small", Category.CURVATURE, Severity.ERROR, basis=Basis.PLAUSIBILITY)
def reference_radius_too_small(ctx: Context):
    """The lane-0 line curves tighter than ``min_radius`` where it borders a drivable lane.

    The lane-0 line is the reference line shifted by the laneOffset; it bounds lane 1 and lane -1, and is checked
    where one of them is drivable (see the module's decisions).

    Plausibility: the standard sets no minimum radius (see ``lane-radius-too-small``); a warning under the default
    profile, an error under ``--profile strict`` or ``generator``.

    Passes (radius 50 m, driving lanes on both sides)::

        <geometry ... length="20"><arc curvature="0.02"/></geometry>

    Fails (radius 0.5 m)::

        <geometry ... length="1"><arc curvature="2"/></geometry>
    """
    bound = 1.0 / ctx.tolerances.min_radius if ctx.tolerances.min_radius > 0 else math.inf
    for road, index, _geometry, lines in lines_in_order(ctx):
        section = road.lane_sections[index]
        if not len(lines.s) or not any((lane := section.lane(i)) is not None and lane.drivable for i in (1, -1)):
            continue
        s, points = lines.s, lines.borders[0]
        hit = tightest(points.curvature, points.speed, np.array([0, len(s)]), bound)[0]
        if hit is None:
            continue
        i = hit[1]
        radius = 1.0 / abs(float(points.curvature[i]))
        yield reference_radius_too_small.finding(
            f"road {road.id}: the lane-0 line (reference line plus laneOffset) has a radius of {radius:.3g} m at "
            f"s={metres(s[i])}, under the {metres(ctx.tolerances.min_radius)} m minimum, beside a drivable lane",
            **_where(road, index, None, float(s[i]), float(points.x[i]), float(points.y[i]), 0),
        )


@rule("C003", "border-folds", Category.CURVATURE, Severity.ERROR, basis=Basis.PLAUSIBILITY)
def border_folds(ctx: Context):
    """A lane border reaches the centre of curvature of the reference line and folds back (``t * k >= 1``).

    A border at lateral offset ``t`` on the inner side of a curve of curvature ``k`` shrinks to a point where
    ``t k = 1`` and runs backwards beyond: the lane turns inside out. Equivalently, the width outside a tight curve's
    centre is more than the radius. Any lane type.

    Plausibility: the standard has no checker rule for a border folding at the centre of curvature (the overlap it
    makes is ``lane-fold``'s, ``road.no_overlap_self``); a warning under the default profile, an error under
    ``--profile strict`` or ``generator``.

    Passes (radius 50 m, lanes 3.5 m wide)::

        <geometry ... length="20"><arc curvature="0.02"/></geometry>

    Fails (radius 2 m, lane 1 reaches 3.5 m to the left, past the centre)::

        <geometry ... length="3"><arc curvature="0.5"/></geometry>
    """
    for road, index, _geometry, lines in lines_in_order(ctx):
        s, k = lines.s, lines.curvature
        for lane_id, t in lines.t.items():
            fold = np.nan_to_num(t * k, nan=0.0)
            i = int(np.argmax(fold))
            if not fold[i] >= 1.0:
                continue
            lane = road.lane_sections[index].lane(lane_id)
            points = lines.borders[lane_id]
            what = "the lane-0 line" if lane_id == 0 else f"the outer border of lane {lane_id}"
            yield border_folds.finding(
                f"road {road.id}: {what} lies {abs(float(t[i])):.3g} m to the {'left' if t[i] > 0 else 'right'} of a "
                f"reference line turning with radius {1.0 / abs(float(k[i])):.3g} m at s={metres(s[i])}: the border "
                "passes the centre of curvature and folds back; widen the curve or narrow the lanes",
                **_where(
                    road,
                    index,
                    lane_id,
                    float(s[i]),
                    float(points.x[i]),
                    float(points.y[i]),
                    lane.line if lane is not None else 0,
                ),
            )
