"""Plan-view shapes of a map for drawing: per lane section, the reference line and every lane border as polylines.

Each lane section is sampled once under a chord tolerance (:meth:`~xodrcheck.geometry.lanes.RoadGeometry.sample_s`,
the exact lane geometry of :mod:`xodrcheck.geometry.lanes`, superelevation applied in plan view), with the road-mark
starts added as samples so that every mark begins on a sample. All lines of a section share those ``s``: line 0 is
the reference line, line 1 lane 0's line (the laneOffset line), then the outer border of each left lane from the
inside out, then of each right lane from the inside out. A lane's outline is its inner border forward and its outer
border backward.

A road whose geometry cannot be evaluated (damaged input; the rules report why) or whose points are not finite or lie
further than :data:`MAX_EXTENT` from the map's other points is left out and named in :attr:`MapShapes.skipped`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace

import numpy as np

from xodrcheck.geometry.lanes import RoadGeometry, SideLanes, geometry_of, road_geometry
from xodrcheck.model import Document, Lane, Road, RoadMark, lane_type_name

#: Default chord tolerance (m) of the drawn polylines: below a pixel at any useful zoom.
CHORD = 0.05
#: Longest step (m) between samples, so that hovering gives ``s`` within a few metres even on a straight road.
MAX_STEP = 5.0
#: Largest coordinate (m) drawn: points beyond it are damaged input (a width of 1e308, say).
MAX_EXTENT = 1e7


@dataclass(frozen=True)
class Mark:
    """A road mark drawn along one line of a section from sample ``start`` to sample ``stop`` (inclusive)."""

    line: int
    start: int
    stop: int
    type: str
    color: str
    width: float


@dataclass(frozen=True)
class SectionShape:
    """The drawable lines of one lane section (see the module docstring for the order of :attr:`lines`)."""

    road: int  # index into MapShapes.roads
    index: int  # lane-section index within its road
    s0: float  # the section's start s (as in a LaneKey)
    s: np.ndarray  # (n,) sample s
    lines: np.ndarray  # (2 + left + right, n, 2) plan-view x, y
    left: tuple[tuple[int, str], ...]  # (lane id, lane type) inner to outer
    right: tuple[tuple[int, str], ...]
    marks: tuple[Mark, ...] = ()


@dataclass
class MapShapes:
    """Every drawable lane section of a document."""

    #: (road id, junction id or None, road name or None) per road, in file order.
    roads: list[tuple[str, str | None, str | None]] = field(default_factory=list)
    sections: list[SectionShape] = field(default_factory=list)
    #: Ids of roads left out (geometry not finite, too far away, or not evaluable).
    skipped: list[str] = field(default_factory=list)

    def bounds(self) -> tuple[float, float, float, float] | None:
        """(xmin, ymin, xmax, ymax) of every line, ``None`` without sections."""
        if not self.sections:
            return None
        lo = np.min([sec.lines.reshape(-1, 2).min(axis=0) for sec in self.sections], axis=0)
        hi = np.max([sec.lines.reshape(-1, 2).max(axis=0) for sec in self.sections], axis=0)
        return float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1])


def _lane_list(side: SideLanes) -> tuple[tuple[int, str], ...]:
    return tuple((lane.id, lane_type_name(lane)) for lane in side.lanes)


def _mark_starts(lane: Lane, origin: float) -> list[tuple[float, RoadMark]]:
    return [(origin + mark.s, mark) for mark in sorted(lane.road_marks, key=lambda m: m.s)]


def _marked_lanes(road: Road, index: int, rg: RoadGeometry) -> list[tuple[int, Lane, float]]:
    """(line index, lane, s its records are relative to) of every lane whose outer border is drawn as a line."""
    section = road.lane_sections[index]
    left, right = rg.side_lanes(index)
    out = [(1, lane, section.s) for lane in section.center[:1]]
    out += [(2 + k, lane, left.origin) for k, lane in enumerate(left.lanes)]
    out += [(2 + len(left.lanes) + k, lane, right.origin) for k, lane in enumerate(right.lanes)]
    return out


def _marks(marked: list[tuple[int, Lane, float]], s: np.ndarray, s1: float) -> list[Mark]:
    marks: list[Mark] = []
    for line, lane, origin in marked:
        starts = _mark_starts(lane, origin)
        for k, (start, mark) in enumerate(starts):
            stop = starts[k + 1][0] if k + 1 < len(starts) else s1
            kind = (mark.type or "none").strip()
            if kind == "none" or not stop > start:
                continue
            i0 = int(np.searchsorted(s, start - 1e-9))
            i1 = int(np.searchsorted(s, stop + 1e-9)) - 1
            if i1 > i0:
                marks.append(Mark(line, i0, i1, kind, (mark.color or "standard").strip(), mark.width or 0.0))
    return marks


def _section(road: Road, index: int, rg: RoadGeometry, chord: float, max_step: float) -> SectionShape | None:
    """The section's lines, or ``None`` when it has no length or no finite, near geometry."""
    s0, s1 = rg.section_range(index)
    if not s1 > s0:
        return None
    marked = _marked_lanes(road, index, rg)
    s = rg.sample_s(index, chord=chord, max_step=max_step)
    mark_s = [start for _, lane, origin in marked for start, _ in _mark_starts(lane, origin)]
    extra = np.array([v for v in mark_s if s0 < v < s1], dtype=float)
    s = np.unique(np.concatenate([s, extra]))
    if len(s) < 2:
        return None
    left, right = rg.side_lanes(index)
    curves = rg.border_curves(index, s)
    pose = rg.section_reference(index, s)
    order = [0, *(lane.id for lane in left.lanes), *(lane.id for lane in right.lanes)]
    lines = np.empty((1 + len(order), len(s), 2))
    lines[0, :, 0], lines[0, :, 1] = pose.x, pose.y
    for k, lane_id in enumerate(order, start=1):
        lines[k, :, 0], lines[k, :, 1] = curves[lane_id].x, curves[lane_id].y
    if not (np.abs(lines) <= MAX_EXTENT).all():  # also False for NaN
        raise ValueError("geometry not finite or too far away")
    return SectionShape(-1, index, s0, s, lines, _lane_list(left), _lane_list(right), tuple(_marks(marked, s, s1)))


def map_shapes(document: Document, chord: float = CHORD, max_step: float = MAX_STEP) -> MapShapes:
    """Sample every lane section of every road with a plan view (see the module docstring)."""
    shapes = MapShapes()
    geometries = geometry_of(document)
    with np.errstate(all="ignore"):  # damaged numbers give inf/nan, which leave the road out
        for road in document.roads:
            _add_road(shapes, road, geometries, chord, max_step)
    return shapes


def _add_road(shapes: MapShapes, road: Road, geometries: Mapping[str, RoadGeometry], chord: float, max_step: float):
    if not road.plan_view or not road.lane_sections:
        return
    rg = road_geometry(geometries, road)
    try:
        found = [_section(road, i, rg, chord, max_step) for i in range(len(road.lane_sections))]
    except Exception:
        shapes.skipped.append(road.id)
        return
    sections = [sec for sec in found if sec is not None]
    if sections:
        road_index = len(shapes.roads)
        shapes.roads.append((road.id, road.junction, road.name))
        shapes.sections.extend(replace(sec, road=road_index) for sec in sections)
