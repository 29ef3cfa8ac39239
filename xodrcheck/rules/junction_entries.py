"""Entries and exits of a junction with an elevation grid (``J032``): the roads meet the grid's surface smoothly.

Inside a junction with an ``<elevationGrid>`` the surface is the grid's (12.11: it overrides the heights of the
junction's roads; lane heights are superimposed on it, as on a road); outside, it is the roads'. Where a road enters
or leaves the junction the two meet. A *smooth transition* (``junctions.elevation_grid.entry_exit_smoothness``,
12.11) is read as the project's joints are read (``link-step`` K104, ``link-kink`` K102): the surface neither steps
nor kinks there, that is

* the grid's z equals the road surface's z (elevation and superelevation; a lane's height is superimposed on both
  sides alike) at every point across the road's end, within ``gap`` (1 cm, K104's error threshold and ASAM's), and
* the grid's grade along the road's direction equals the road's own grade there: the pitch, ``atan(grade)``, changes
  by at most ``grade_kink`` (0.01 rad, about 1 % of grade, as ``kink`` bounds a heading change in plan view).

The places are the boundary's joints (12.10, ``<segment type="joint">``: across the road's lanes from
``jointLaneStart`` to ``jointLaneEnd``), and, for an incoming road end with no joint (no boundary, or one that misses
it: ``boundary-roads`` says so), all its lanes. A joint with a ``transitionLength`` whose transition zone the boundary
builds (12.11.2: the lane segments on both sides of the joint reach that far) is smooth by construction: the zone's
cubic takes the road's z and grade at the joint and the grid's at its far side, so it is not compared. Points outside
the grid's complete squares are ``junction-area-coverage``'s; a grid without a usable reference line is
``junction-reference-line-shape``'s.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from xodrcheck.findings import Category, Finding, Severity
from xodrcheck.model import ContactPoint, JunctionType, Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import junction_uids as U
from xodrcheck.rules.shared.context import Context, describe_junction
from xodrcheck.rules.shared.junction_shapes import boundary_pieces, joint_lanes, reference_line
from xodrcheck.rules.shared.road_ends import end_s
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:
    from xodrcheck.geometry.junction_grid import GridSurface
    from xodrcheck.model import JointSegment, Junction
    from xodrcheck.rules.shared.junction_shapes import Piece, ReferenceLine

#: Step (m) into the road over which its grade at the end is measured (a difference quotient of the exact surface).
_DS = 1e-3
#: Points per lane across a joint, besides the borders (the road surface is straight across a lane).
_PER_LANE = 8


@dataclass(frozen=True)
class _Entry:
    """A road entering an elevation grid: its contact point and the joint segment there."""

    road: Road
    end: ContactPoint
    joint: JointSegment | None
    #: Why the joint's ``transitionLength`` is not applied ("": none, or none given).
    no_zone: str = ""


@dataclass(frozen=True)
class _Across:
    """Points across a road's end: x, y, the road surface's z and its grade outward, and the outward direction."""

    xy: np.ndarray
    z: np.ndarray
    grade: np.ndarray
    out: np.ndarray


def _zone(pieces: list[Piece], k: int, length: float, tol: float) -> str:
    """Why the transition zone of the joint ``pieces[k]`` cannot be built ("" when it can)."""
    from xodrcheck.model import LaneSegment

    n = len(pieces)
    for side, piece in (("before", pieces[k - 1]), ("after", pieces[(k + 1) % n])):
        if n < 3 or not isinstance(piece.segment, LaneSegment):
            return f"the segment {side} the joint is not a lane segment"
        reach = float(np.hypot(*np.diff(piece.xy, axis=0).T).sum())
        if reach + tol < length:
            return f"the lane segment {side} the joint (line {piece.segment.line}) is only {reach:.3g} m long"
    return ""


def _entries(ctx: Context, j: Junction) -> list[_Entry]:
    """The junction's entries and exits: its boundary's joints at road ends, then incoming road ends without one."""
    from xodrcheck.model import JointSegment

    out: list[_Entry] = []
    seen: set[tuple[str, ContactPoint]] = set()
    pieces = boundary_pieces(ctx, j.boundary) if j.boundary is not None and not j.boundary.unknown else None
    for k, piece in enumerate(pieces or ()):
        seg = piece.segment
        road = ctx.road(seg.road)
        if not isinstance(seg, JointSegment) or road is None or not isinstance(seg.contact, ContactPoint):
            continue
        end = seg.contact
        if road.junction == j.id or (road.id, end) in seen:
            continue
        seen.add((road.id, end))
        zone = _zone(pieces or [], k, seg.transition_length, ctx.tolerances.gap) if seg.transition_length else ""
        if seg.transition_length and not zone:
            continue  # 12.11.2's transition zone joins the road and the grid with matching z and grade
        out.append(_Entry(road, end, seg, zone))
    for road, end in ctx.junction_link_ends.get(j.id, ()):
        if road.junction != j.id and (road.id, end) not in seen:
            seen.add((road.id, end))
            out.append(_Entry(road, end, None))
    return out


def _across(ctx: Context, entry: _Entry) -> _Across | None:
    """The road surface across the entry's lanes at the road's end (``None`` when the road cannot be evaluated)."""
    from xodrcheck.model import JointSegment

    road, end = entry.road, entry.end
    geometry = ctx.usable_geometry(road)
    if geometry is None or not road.lane_sections:
        return None
    index = 0 if end is ContactPoint.START else len(road.lane_sections) - 1
    s = end_s(road, end)
    inward = min(_DS, 0.5 * float(road.length))
    curves = geometry.border_curves(index, np.array([s, s + inward if end is ContactPoint.START else s - inward]))
    joint = entry.joint or JointSegment(road.id, end, None, None)
    first, last = joint_lanes(geometry, index, joint)
    order = sorted(curves, reverse=True)  # the border lines from the outermost left to the outermost right
    if first not in curves or last not in curves:
        return None
    lo, hi = sorted((order.index(first), order.index(last)))
    lines = np.array([[[curves[i].x[k], curves[i].y[k], curves[i].z[k]] for k in (0, 1)] for i in order[lo : hi + 1]])
    if len(lines) > 1:  # straight across each lane between its borders
        f = np.linspace(0.0, 1.0, _PER_LANE + 1)[:-1, None, None, None]
        lines = np.concatenate(
            ((lines[:-1] + f * (lines[1:] - lines[:-1])).transpose(1, 0, 2, 3).reshape(-1, 2, 3), lines[-1:])
        )
    at, inside = lines[:, 0], lines[:, 1]
    step = at[:, :2] - inside[:, :2]
    run = np.hypot(step[:, 0], step[:, 1])
    keep = np.isfinite(lines).all(axis=(1, 2)) & (run > 0)
    if not keep.any():
        return None
    at, inside, step, run = at[keep], inside[keep], step[keep], run[keep]
    return _Across(at[:, :2], at[:, 2], (at[:, 2] - inside[:, 2]) / run, step / run[:, None])


def _grid_at(surface: GridSurface, line: ReferenceLine, across: _Across) -> tuple[np.ndarray, np.ndarray]:
    """The grid's z and its grade along the road's outward direction at the points across the road's end."""
    s, t = line.frame(across.xy)
    c, n = math.cos(line.hdg), math.sin(line.hdg)
    ds = across.out[:, 0] * c + across.out[:, 1] * n
    dt = -across.out[:, 0] * n + across.out[:, 1] * c
    z, dz_ds, dz_dt = surface.evaluate(s, t, (ds, dt))
    with np.errstate(over="ignore", invalid="ignore"):
        grade = dz_ds * ds + dz_dt * dt
    ok = np.isfinite(z) & np.isfinite(grade)  # absurd grid values count as no value (the schema rule's)
    return np.where(ok, z, np.nan), np.where(ok, grade, np.nan)


def _where(entry: _Entry) -> str:
    end = "start" if entry.end is ContactPoint.START else "end"
    seg = f" (joint segment, line {entry.joint.line})" if entry.joint is not None and entry.joint.line else ""
    return f"road {entry.road.id}'s {end}{seg}"


@rule(
    "J032",
    "elevation-grid-entry-exit",
    Category.JUNCTION,
    Severity.WARNING,
    uids=(U.GRID_SMOOTH,),
)
def elevation_grid_entry_exit(ctx: Context) -> Iterator[Finding]:
    """A road enters or leaves a junction's elevation grid with a step or a kink in the surface.

    For junction entries and exits, a smooth transition should be assured
    (``junctions.elevation_grid.entry_exit_smoothness``, 12.11). Across each road end where the road meets the grid
    (the boundary's joints, 12.10; incoming road ends without one), the grid's height (12.11.1's bicubic) is compared
    with the road surface's (elevation and superelevation) and its grade along the road with the road's: a step over
    ``gap`` (1 cm) or a change of pitch over ``grade_kink`` (0.01 rad) is a warning, one finding per entry and kind
    at its largest value. A joint with a ``transitionLength`` the boundary can build a zone for (12.11.2) is smooth
    by construction and not compared.

    Passes (road 1 rises 2 % eastward into the junction; the grid holds the same plane, z = 0.02 x)::

        <road id="1" ...><elevationProfile><elevation s="0" a="0" b="0.02" c="0" d="0"/></elevationProfile>
        <elevationGrid sStart="0" gridSpacing="5"><elevation left="0.9 0.9 0.9" center="0.9" right="0.9"/>
          <elevation left="1.0 1.0 1.0" center="1.0" right="1.0"/> ... (0.1 m higher each 5 m row)

    Fails (the grid lies 5 cm above the roads everywhere: every entry steps by 5 cm)::

        <elevation left="0.95 0.95 0.95" center="0.95" right="0.95"/> ...
    """
    tol = ctx.tolerances
    for j in ctx.document.junctions:
        grid, line = j.grid, reference_line(j)
        if grid is None or j.type is not JunctionType.DEFAULT:
            continue
        from xodrcheck.geometry.junction_grid import grid_surface  # here: only a junction with a grid loads it

        surface = grid_surface(grid)
        if surface is None or line is None:
            continue
        for entry in _entries(ctx, j):
            across = _across(ctx, entry)
            if across is None:
                continue
            z, grade = _grid_at(surface, line, across)
            yield from _step(ctx, j, entry, across, z, tol.gap)
            yield from _kink(ctx, j, entry, across, grade, tol.grade_kink)


def _place(entry: _Entry, across: _Across, k: int, z: float) -> dict:
    return {
        "road": entry.road.id,
        "s": 0.0 if entry.end is ContactPoint.START else float(entry.road.length),
        "x": float(across.xy[k, 0]),
        "y": float(across.xy[k, 1]),
        "z": z,
        "line": (entry.joint.line if entry.joint is not None else 0) or None,
    }


def _zone_note(entry: _Entry) -> str:
    if not entry.no_zone or entry.joint is None:
        return ""
    return (
        f" (its transitionLength {metres(entry.joint.transition_length)} m builds no transition zone: {entry.no_zone})"
    )


def _step(ctx: Context, j: Junction, entry: _Entry, across: _Across, z: np.ndarray, tol: float):
    step = np.abs(z - across.z)
    if not np.nanmax(step, initial=0.0) > tol:
        return
    k = int(np.nanargmax(step))
    over = int(np.sum(step > tol))
    yield elevation_grid_entry_exit.finding(
        f"{describe_junction(j)}: at {_where(entry)} the surface steps by {step[k]:.3g} m from the road onto the "
        f"elevation grid at ({across.xy[k, 0]:.3f}, {across.xy[k, 1]:.3f}): road z={across.z[k]:.3f}, grid "
        f"z={z[k]:.3f} ({over} of {len(step)} points across the road's end step over {metres(tol)} "
        f"m){_zone_note(entry)}; make the grid's heights there match the road's (elevation and superelevation), or "
        "give the joint a transitionLength",
        **_place(entry, across, k, float(across.z[k])),
    )


def _kink(ctx: Context, j: Junction, entry: _Entry, across: _Across, grade: np.ndarray, tol: float):
    turn = np.abs(np.arctan(grade) - np.arctan(across.grade))
    if not np.nanmax(turn, initial=0.0) > tol:
        return
    k = int(np.nanargmax(turn))
    yield elevation_grid_entry_exit.finding(
        f"{describe_junction(j)}: at {_where(entry)} the surface kinks from the road onto the elevation grid at "
        f"({across.xy[k, 0]:.3f}, {across.xy[k, 1]:.3f}), z={across.z[k]:.3f}: along the road into the junction the "
        f"road's grade is {100 * across.grade[k]:.3g} % and the grid's {100 * grade[k]:.3g} %, a {turn[k]:.3g} rad "
        f"change of pitch (over {tol:g} rad){_zone_note(entry)}; shape the grid's heights near the entry to continue "
        "the road's grade, or give the joint a transitionLength",
        **_place(entry, across, k, float(across.z[k])),
    )
