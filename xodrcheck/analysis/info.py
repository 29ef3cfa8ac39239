"""A summary of an OpenDRIVE file: what ``xodrcheck info`` prints.

:func:`map_info` computes it from a :class:`~xodrcheck.reader.ReadResult`; the command line only formats it.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from xodrcheck.config import Tolerances
from xodrcheck.findings import Finding, Severity
from xodrcheck.geometry.lanes import RoadGeometry, geometry_of, road_geometry
from xodrcheck.geometry.sampling import step_counts
from xodrcheck.model import (
    Arc,
    Document,
    ElementType,
    Junction,
    JunctionType,
    Line,
    ParamPoly3,
    Poly3,
    Spiral,
    lane_type_name,
)
from xodrcheck.reader import ReadResult

if TYPE_CHECKING:
    from xodrcheck.analysis.elevation import ElevationInfo

#: OpenDRIVE element names of the plan-view geometry kinds.
GEOMETRY_NAMES = {Line: "line", Arc: "arc", Spiral: "spiral", Poly3: "poly3", ParamPoly3: "paramPoly3"}

#: What the bounding box was computed from.
BASIS_LANES = "lane borders"
BASIS_REFERENCE = "reference line"
BASIS_MIXED = "lane borders and reference line"


@dataclass(frozen=True)
class BoundingBox:
    """The plan-view extent of a map, and what it was measured on (lanes or reference lines)."""

    min_x: float
    min_y: float
    max_x: float
    max_y: float
    #: :data:`BASIS_LANES` when every placed road had lanes, :data:`BASIS_REFERENCE` when none had,
    #: :data:`BASIS_MIXED` otherwise.
    basis: str


@dataclass(frozen=True)
class MapInfo:
    """Counts and extents of one file. Mappings are sorted by key and are not to be mutated."""

    path: str | None
    #: ``"major.minor"`` from the header, ``None`` without a header or revision.
    version: str | None
    roads: int
    #: Roads that belong to a junction (connecting roads).
    junction_roads: int
    junctions: int
    #: Junction type (``default``, ``direct``, ``virtual``, ``crossing``) -> count.
    junctions_by_type: Mapping[str, int]
    #: Number of legs -> count; see :func:`junction_legs`.
    junctions_by_legs: Mapping[int, int]
    lane_sections: int
    #: Lanes counted once per lane section they appear in; the centre lane (id 0) is not counted.
    lanes: int
    #: Lane type (the standard's spelling; an unknown type as the file spelled it) -> count, counted like ``lanes``.
    lanes_by_type: Mapping[str, int]
    #: Sum of the roads' declared lengths (m).
    reference_length: float
    #: Plan-view geometry kind (OpenDRIVE element name) -> count.
    geometries: Mapping[str, int]
    #: Extent in the file's inertial frame (the header's offset is not applied); ``None`` when nothing could be placed.
    bbox: BoundingBox | None
    #: Reader findings by severity name (``error``, ``warning``, ``info``; all three always present).
    findings: Mapping[str, int]
    #: Height range, steepest grade and largest z step at a road link (:mod:`xodrcheck.analysis.elevation`).
    elevation: ElevationInfo | None = None


def junction_legs(junction: Junction, document: Document) -> int:
    """Legs of a junction: the distinct roads outside it that its connections join.

    That is every incoming road, plus, for a direct junction, every linked road and, for the other types, the road at
    the far end of every connecting road. Counting incoming roads alone undercounts: many tools (CARLA's towns among
    them) list connections only from the roads that lead *into* the junction, so one-way exits never appear as
    incoming roads.
    """
    roads: set[str] = set()
    for c in junction.connections:
        if c.incoming_road is not None:
            roads.add(c.incoming_road)
        if junction.type is JunctionType.DIRECT:
            if c.linked_road is not None:
                roads.add(c.linked_road)
            continue
        connecting = document.road_by_id.get(c.connecting_road) if c.connecting_road is not None else None
        if connecting is None:
            continue
        for link in (connecting.predecessor, connecting.successor):
            if link is None or link.element_type is not ElementType.ROAD:
                continue
            other = document.road_by_id.get(link.element_id)
            if other is None or other.junction != junction.id:  # a road chained inside the junction is no leg
                roads.add(link.element_id)
    return len(roads)


def _sorted(counter: Counter) -> dict:
    return dict(sorted(counter.items()))


def _road_points(rg: RoadGeometry, tolerances: Tolerances) -> tuple[list[np.ndarray], list[np.ndarray], bool]:
    """Points outlining one road: the outer borders of its outermost lanes (the laneOffset line on a side without
    lanes), or its reference line where a section has no lanes at all. Returns xs, ys and whether lanes were used."""
    road = rg.road
    xs: list[np.ndarray] = []
    ys: list[np.ndarray] = []
    used_lanes = False
    if not road.lane_sections:
        pose = rg.reference(_reference_s(rg, tolerances))
        return [pose.x], [pose.y], False
    for index, section in enumerate(road.lane_sections):
        if road.section_end(index) < section.s:
            continue  # sections out of order: the reader reports them; nothing to place
        s = rg.sample_s(
            index, chord=tolerances.chord, max_step=tolerances.max_step, budget=tolerances.max_samples_per_section
        )
        left, right = (tuple(lane.id for lane in side.lanes) for side in rg.side_lanes(index))
        if not left and not right:
            pose = rg.reference(s)
            xs.append(pose.x)
            ys.append(pose.y)
            continue
        used_lanes = True
        # Each side's edge: its outermost lane's outer border, or the laneOffset line (inner border of the other side).
        edges = (
            (left[-1], "outer") if left else (right[0], "inner"),
            (right[-1], "outer") if right else (left[0], "inner"),
        )
        for lane_id, where in edges:
            points = rg.lane_points(index, lane_id, s, where=where)
            xs.append(points.x)
            ys.append(points.y)
    return xs, ys, used_lanes


def _reference_s(rg: RoadGeometry, tolerances: Tolerances) -> np.ndarray:
    """Samples of a road without lane sections: element starts, the road end, and steps of at most ``max_step``."""
    length = max(rg.road.length, 0.0)
    count = int(step_counts(np.array([length]), tolerances.max_step, tolerances.max_samples_per_section)[0]) + 1
    return np.unique(np.concatenate([np.linspace(0.0, length, count), rg.reference_line.breakpoints]))


def bounding_box(document: Document, tolerances: Tolerances | None = None) -> BoundingBox | None:
    """Extent of the lane borders of every road with a plan view (the reference line where a road has no lanes)."""
    tolerances = tolerances or Tolerances()
    geometry = geometry_of(document)
    xs: list[np.ndarray] = []
    ys: list[np.ndarray] = []
    bases: set[bool] = set()
    for road in document.roads:
        if not road.plan_view:
            continue
        rg = road_geometry(geometry, road)
        rx, ry, used_lanes = _road_points(rg, tolerances)
        xs.extend(rx)
        ys.extend(ry)
        bases.add(used_lanes)
    if not xs:
        return None
    x = np.concatenate(xs)
    y = np.concatenate(ys)
    finite = np.isfinite(x) & np.isfinite(y)
    if not finite.any():
        return None
    basis = BASIS_MIXED if len(bases) > 1 else BASIS_LANES if True in bases else BASIS_REFERENCE
    x, y = x[finite], y[finite]
    return BoundingBox(float(x.min()), float(y.min()), float(x.max()), float(y.max()), basis)


def _finding_counts(findings: Iterable[Finding]) -> dict[str, int]:
    counts = Counter(str(f.severity) for f in findings)
    return {str(sev): counts.get(str(sev), 0) for sev in sorted(Severity, reverse=True)}


def map_counts(doc: Document) -> dict[str, Any]:
    """The counts of roads, junctions, lane sections and lanes that :class:`MapInfo` holds (by its field names) and
    :class:`~xodrcheck.analysis.snapshot.Snapshot` keeps; mappings sorted by key."""
    lanes = Counter(
        lane_type_name(lane)
        for road in doc.roads
        for section in road.lane_sections
        for lane in (*section.left, *section.right)
        if lane.id != 0
    )
    return {
        "roads": len(doc.roads),
        "junction_roads": sum(1 for road in doc.roads if road.junction is not None),
        "junctions": len(doc.junctions),
        "junctions_by_type": _sorted(Counter(j.type.value for j in doc.junctions)),
        "junctions_by_legs": _sorted(Counter(junction_legs(j, doc) for j in doc.junctions)),
        "lane_sections": sum(len(road.lane_sections) for road in doc.roads),
        "lanes": sum(lanes.values()),
        "lanes_by_type": _sorted(lanes),
    }


def map_info(result: ReadResult, tolerances: Tolerances | None = None) -> MapInfo:
    """Summarise a read file."""
    from xodrcheck.analysis.elevation import elevation_info  # here: the meshes' lane_type_name loads no elevation

    doc = result.document
    findings = _finding_counts(result.findings)
    if doc is None:
        return MapInfo(result.path, None, 0, 0, 0, {}, {}, 0, 0, {}, 0.0, {}, None, findings)
    version = None if doc.version is None else "{}.{}".format(*doc.version)
    geometries = Counter(GEOMETRY_NAMES[type(g)] for road in doc.roads for g in road.plan_view)
    return MapInfo(
        path=result.path,
        version=version,
        **map_counts(doc),
        reference_length=float(sum(road.length for road in doc.roads)),
        geometries=_sorted(geometries),
        bbox=bounding_box(doc, tolerances),
        findings=findings,
        elevation=elevation_info(doc),
    )
