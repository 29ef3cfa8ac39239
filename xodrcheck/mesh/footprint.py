"""Plan-view footprints of lanes (shapely 2) and the spatial questions the overlap rules and the metrics ask.

The footprint of a lane strip is the polygon its mesh covers in plan view (:mod:`xodrcheck.mesh.surfaces`): its inner
border followed by its outer border reversed, from the same samples as the mesh. A strip whose outline is not a valid
polygon (zero width over a stretch, a fold) is the union of its mesh triangles instead. Candidate pairs come from a
:class:`shapely.STRtree` over all footprints, so the work grows with the number of lanes that are near each other, not
with the square of the number of lanes.

Heights at a plan-view point are read from the mesh (barycentric interpolation in the lane's triangle that contains
the point, or the nearest one for points on a border).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import shapely

from xodrcheck.config import Tolerances
from xodrcheck.findings import OutOfTime
from xodrcheck.mesh import strip_shapes
from xodrcheck.mesh.surfaces import LaneSurfaces, cached_per_chord, surfaces_of
from xodrcheck.model import DRIVABLE_LANE_TYPES, Document, ElementType, JunctionType, LaneKey
from xodrcheck.support import work

DRIVABLE_TYPE_NAMES = frozenset(t.value for t in DRIVABLE_LANE_TYPES)
#: Pieces united in one GEOS call when a lane strip's outline is not a simple polygon.
_UNION_BLOCK = 256
#: Most points of an overlap polygon's outline sampled for heights (plus its representative point).
_HEIGHT_POINTS = 24
#: Lane-strip pairs intersected at a time by :meth:`OverlapIndex.overlaps`: it bounds a block's temporary geometries.
PAIR_BLOCK = 4096


#: Mesh vertices whose lane outlines are made polygons at a time (the temporaries scale with it, a few times the
#: vertices' own size).
OUTLINE_BLOCK = 1 << 18


def outlines(surfaces: LaneSurfaces) -> np.ndarray:
    """One plan-view polygon per lane strip (its outline; possibly not valid), built in blocks of lanes."""
    polygons = np.empty(len(surfaces), dtype=object)
    xy = surfaces.vertices[:, :2]
    starts = surfaces.lane_vertices
    first = 0
    while first < len(surfaces):
        last = int(np.searchsorted(starts, starts[first] + OUTLINE_BLOCK, side="right")) - 1
        last = min(max(last, first + 1), len(surfaces))
        order, owner = surfaces.outline_order(first, last)
        polygons[first:last] = shapely.polygons(shapely.linearrings(xy[order], indices=owner))
        first = last
    return polygons


class Footprints:
    """Lane footprints of one document with a spatial index (build with :func:`footprints_of`).

    A strip whose outline is not a simple polygon and whose border turns through more than ``max_turns`` full circles
    (:attr:`winding`) winds round itself: its footprint is left empty instead of united (the union's cost grows with
    every turn, and a road wound round a 0.5 m circle a thousand times is no road), and ``lane-fold`` says so."""

    def __init__(
        self, surfaces: LaneSurfaces, out_of_time: Callable[[], bool] | None = None, max_turns: float | None = None
    ):
        self.surfaces = surfaces
        self._out_of_time = out_of_time
        self._near: np.ndarray | None = None
        most = Tolerances().max_turns if max_turns is None else max_turns
        polygons = outlines(surfaces)
        turns = strip_shapes.strip_turns(surfaces)
        # a strip turning that much whose triangles outweigh its box winds round itself: testing its outline for
        # simplicity would cost the square of its size (a 1e9 m spiral: minutes)
        many = np.flatnonzero(turns > most)
        wound = many[strip_shapes.covers_twice(surfaces, many)]
        judged = np.ones(len(polygons), dtype=bool)
        judged[wound] = False
        invalid = np.union1d(wound, np.flatnonzero(judged)[~shapely.is_valid(polygons[judged])]).astype(np.int64)
        #: Strips that wind round themselves -> the full turns their inner border sweeps (see the class docstring).
        self.winding: dict[int, float] = {}
        for i in map(int, invalid):
            if turns[i] > most:
                self.winding[i] = float(turns[i])
                polygons[i] = shapely.Polygon()
            else:
                polygons[i] = self._union(i)
        #: One (multi)polygon per lane strip of :attr:`surfaces` (empty for a strip that winds round itself).
        self.polygons = polygons
        #: Lane strips whose outline is not a simple polygon (their footprint is the union of their triangles).
        self.invalid = invalid
        self.tree = shapely.STRtree(polygons)

    def triangles(self, lane: int) -> np.ndarray:
        """Plan-view triangles ``(T, 3, 2)`` of a lane strip."""
        s = self.surfaces
        faces = s.faces[s.lane_faces[lane] : s.lane_faces[lane + 1]]
        return s.vertices[faces][..., :2]

    def _union(self, lane: int):
        """Union of a lane strip's triangles, made from its pieces (:func:`xodrcheck.mesh.strip_shapes.pieces`) in
        blocks of :data:`_UNION_BLOCK` merged pairwise, so that the time budget can stop it between two GEOS calls
        (:class:`OutOfTime`)."""
        polys = strip_shapes.pieces(self.surfaces, lane)
        work.add("union coordinates", int(shapely.get_num_coordinates(polys).sum()))
        parts = []
        for k in range(0, len(polys), _UNION_BLOCK):
            self._check_time()
            parts.append(shapely.union_all(polys[k : k + _UNION_BLOCK]))
        while len(parts) > 1:
            self._check_time()
            parts = [shapely.union_all(parts[k : k + 2]) for k in range(0, len(parts), 2)]
        return parts[0] if parts else shapely.Polygon()

    def _check_time(self) -> None:
        if self._out_of_time is not None and self._out_of_time():
            raise OutOfTime("building lane footprints")

    def self_overlap(self, lane: int) -> float:
        """Plan-view area a lane strip covers more than once (its triangles' areas minus the area of their union)."""
        tris = self.triangles(lane)
        u, v = tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0]
        total = 0.5 * np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]).sum()
        return float(total - shapely.area(self.polygons[lane]))

    @cached_property
    def tiled(self) -> np.ndarray:
        """Per strip, its lane section's first strip when the section's strips overlap nowhere, else -1
        (:func:`xodrcheck.mesh.strip_shapes.tiled_sections`)."""
        return strip_shapes.tiled_sections(self.surfaces, self.invalid)

    def near_pairs(self) -> np.ndarray:
        """``(2, P)`` lane-strip index pairs ``i < j`` whose footprints intersect, but for two strips of one lane
        section known to overlap nowhere (:attr:`tiled`: they touch along their shared borders, and testing that on
        two long strips costs much). Queried once: the overlap rules between roads and within a road share it."""
        if self._near is None:
            pairs = self.tree.query(self.polygons)  # bounding boxes that meet
            tiled = self.tiled
            pairs = pairs[:, (pairs[0] < pairs[1]) & ((tiled[pairs[0]] < 0) | (tiled[pairs[0]] != tiled[pairs[1]]))]
            polys = self.polygons
            self._near = pairs[:, shapely.intersects(polys[pairs[0]], polys[pairs[1]])]
        return self._near

    def heights(self, lane: int, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Surface height of a lane strip at plan-view ``points`` ``(P, 2)``, and the face index (in the whole mesh)
        each was read from."""
        s = self.surfaces
        first = s.lane_faces[lane]
        faces = s.faces[first : s.lane_faces[lane + 1]]
        tri = s.vertices[faces]  # (T, 3, 3)
        lo, hi = points.min(axis=0), points.max(axis=0)
        near = np.flatnonzero(
            (tri[:, :, 0].max(axis=1) >= lo[0])
            & (tri[:, :, 0].min(axis=1) <= hi[0])
            & (tri[:, :, 1].max(axis=1) >= lo[1])
            & (tri[:, :, 1].min(axis=1) <= hi[1])
        )
        if near.size == 0:  # the points lie outside every triangle's box: use the nearest triangles
            near = np.arange(len(tri))
        t = tri[near]
        a, b, c = t[:, 0, :2], t[:, 1, :2], t[:, 2, :2]
        det = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
        usable = np.abs(det) > 1e-12
        with np.errstate(divide="ignore", invalid="ignore"):
            px = points[:, None, 0] - a[None, :, 0]
            py = points[:, None, 1] - a[None, :, 1]
            l1 = (px * (c[:, 1] - a[:, 1]) - py * (c[:, 0] - a[:, 0])) / det
            l2 = ((b[:, 0] - a[:, 0]) * py - (b[:, 1] - a[:, 1]) * px) / det
        l0 = 1.0 - l1 - l2
        inside = np.minimum(np.minimum(l0, l1), l2)
        inside = np.where(usable[None, :], np.nan_to_num(inside, nan=-np.inf), -np.inf)
        best = inside.argmax(axis=1)
        rows = np.arange(len(points))
        w = np.clip(np.stack([l0[rows, best], l1[rows, best], l2[rows, best]], axis=1), 0.0, 1.0)
        w /= np.maximum(w.sum(axis=1, keepdims=True), 1e-300)
        z = (w * t[best][:, :, 2]).sum(axis=1)
        return z, first + near[best]


def sample_points(geometry) -> np.ndarray:
    """Plan-view points of a (multi)polygon for height comparisons: a representative point of each part and up to
    :data:`_HEIGHT_POINTS` points of its outline."""
    points = [np.asarray(shapely.get_coordinates(shapely.point_on_surface(geometry)))]
    outline = shapely.get_coordinates(shapely.boundary(geometry))
    if len(outline):
        step = max(1, len(outline) // _HEIGHT_POINTS)
        points.append(outline[::step])
    return np.concatenate(points)


@dataclass(frozen=True, slots=True)
class Overlap:
    """Two lane strips of different roads overlapping in plan view where their surfaces are within the clearance."""

    lane_a: int
    lane_b: int
    #: Plan-view area of the intersection (m^2) times the share of its sampled points within the clearance.
    area: float
    #: A point of the overlap (x, y), and the height difference there.
    x: float
    y: float
    dz: float
    #: Reference-line ``s`` of each lane at that point.
    s_a: float
    s_b: float


class Relations:
    """Which roads may overlap, and which roads share a junction.

    Roads *related* here may overlap: a road with itself (its own overlaps are :attr:`OverlapIndex.self_pairs`),
    consecutive roads (a road link either way: ASAM OpenDRIVE 10.3 allows overlaps of roads whose reference lines are
    linked), members of one junction (Annex F ``road.overlap_inside_junction``: only roads with the same junction id
    may overlap), the roads of one direct junction (the incoming and linked roads that split or merge there), the roads
    of a crossing (they cross there, 12.8; that they overlap only within its road sections is
    ``crossing-range-short``'s) and a virtual junction's roads with its main road (12.7).

    Roads that only share a junction otherwise (two of its legs, or a connecting road and a leg it does not join) are
    not related, but :meth:`shared_junction` names the junction: their sidewalks and shoulders commonly meet at the
    junction's corners, so the overlap rules report only drivable lanes among them."""

    def __init__(self, document: Document):
        links: dict[str, set[str]] = {}
        groups: dict[str, set[str]] = {}
        for road in document.roads:
            mine = groups.setdefault(road.id, set())
            if road.junction is not None:
                mine.add(road.junction)
            for link in (road.predecessor, road.successor):
                if link is None:
                    continue
                if link.element_type is ElementType.JUNCTION:
                    mine.add(link.element_id)
                else:
                    links.setdefault(road.id, set()).add(link.element_id)
                    links.setdefault(link.element_id, set()).add(road.id)
        for junction in document.junctions:
            for c in junction.connections:
                for road_id in (c.incoming_road, c.connecting_road, c.linked_road):
                    if road_id is not None:
                        groups.setdefault(road_id, set()).add(junction.id)
            main_road = junction.main_road if junction.type is JunctionType.VIRTUAL else None
            for road_id in (*junction.crossing_roads, main_road):
                if road_id is not None:
                    groups.setdefault(road_id, set()).add(junction.id)
        self._links = links
        self._groups = groups
        #: Junctions whose roads may all overlap: direct junctions (their roads split or merge) and crossings (their
        #: roads cross, 12.8).
        self._direct = frozenset(
            j.id for j in document.junctions if j.type in (JunctionType.DIRECT, JunctionType.CROSSING)
        )
        #: Virtual junction id -> its main road, on which the junction's own roads (cross paths too) lie (12.7).
        self._main_road = {
            j.id: j.main_road for j in document.junctions if j.type is JunctionType.VIRTUAL and j.main_road is not None
        }
        self.junction_of = {road.id: road.junction for road in document.roads}

    def related(self, a: str, b: str) -> bool:
        if a == b or b in self._links.get(a, ()):
            return True
        junction = self.junction_of.get(a)
        if junction is not None and junction == self.junction_of.get(b):
            return True
        if b == self._main_road.get(junction or "") or a == self._main_road.get(self.junction_of.get(b) or ""):
            return True
        return bool(self._groups.get(a, set()) & self._groups.get(b, set()) & self._direct)

    def shared_junction(self, a: str, b: str) -> str | None:
        """A junction both roads belong to, link to or are named by (the smallest id), else ``None``."""
        shared = self._groups.get(a, set()) & self._groups.get(b, set())
        return min(shared) if shared else None


class OverlapIndex:
    """Footprints plus the road relations of one document."""

    def __init__(
        self,
        document: Document,
        chord: float | None = None,
        out_of_time: Callable[[], bool] | None = None,
        max_turns: float | None = None,
    ):
        self.document = document
        self.footprints = Footprints(surfaces_of(document, chord), out_of_time, max_turns)
        self.relations = Relations(document)

    @property
    def surfaces(self) -> LaneSurfaces:
        return self.footprints.surfaces

    @cached_property
    def strip_of(self) -> dict[LaneKey, int]:
        """Lane key -> index of its lane strip (the first road's, when road ids repeat)."""
        out: dict[LaneKey, int] = {}
        for i, key in enumerate(self.surfaces.lanes):
            out.setdefault(key, i)
        return out

    @cached_property
    def unrelated_pairs(self) -> np.ndarray:
        """``(2, P)`` near lane-strip pairs of roads that are not related (see :class:`Relations`)."""
        pairs = self.footprints.near_pairs()
        lanes = self.surfaces.lanes
        keep = [not self.relations.related(lanes[i].road, lanes[j].road) for i, j in pairs.T]
        return pairs[:, np.array(keep, dtype=bool)] if pairs.size else pairs

    @cached_property
    def self_pairs(self) -> np.ndarray:
        """``(2, P)`` near lane-strip pairs of one road (:meth:`Footprints.near_pairs`: not two strips of a lane section
        known to overlap nowhere), neither of them a strip that folds over itself (whose own overlap
        :attr:`Footprints.invalid` marks)."""
        pairs = self.footprints.near_pairs()
        if not pairs.size:
            return pairs
        lanes = self.surfaces.lanes
        folded = np.zeros(len(lanes), dtype=bool)
        folded[self.footprints.invalid] = True
        keep = [lanes[i].road == lanes[j].road and not folded[i] and not folded[j] for i, j in pairs.T]
        return pairs[:, np.array(keep, dtype=bool)]

    def overlaps(
        self, min_area: float, clearance: float, deadline_check=None, pairs: np.ndarray | None = None
    ) -> list[Overlap]:
        """Overlaps of lane strips of unrelated roads (or of the given ``pairs``) whose surfaces come closer than
        ``clearance`` in height.

        Intersections smaller than a thousandth of ``min_area`` are ignored (borders that merely touch); callers sum
        the rest per road pair and compare the sum with ``min_area``."""
        if pairs is None:
            pairs = self.unrelated_pairs
        out: list[Overlap] = []
        if pairs.size == 0:
            return out
        for lo in range(0, pairs.shape[1], PAIR_BLOCK):  # blocks: the intersections of a whole map at once took GBs
            if self._block_overlaps(pairs[:, lo : lo + PAIR_BLOCK], min_area, clearance, deadline_check, out):
                break
        return out

    def _block_overlaps(
        self, pairs: np.ndarray, min_area: float, clearance: float, deadline_check, out: list[Overlap]
    ) -> bool:
        """:meth:`overlaps` of one block of pairs, appended to ``out``; ``True`` when the deadline stopped it."""
        polys = self.footprints.polygons
        work.add("overlay coordinates", int(shapely.get_num_coordinates(polys[pairs]).sum()))
        shared = shapely.intersection(polys[pairs[0]], polys[pairs[1]])
        areas = shapely.area(shared)
        for k in np.flatnonzero(areas > min_area * 1e-3):
            if deadline_check is not None and deadline_check():
                return True
            i, j = int(pairs[0, k]), int(pairs[1, k])
            points = sample_points(shared[k])
            z_a, face_a = self.footprints.heights(i, points)
            z_b, face_b = self.footprints.heights(j, points)
            dz = np.abs(z_a - z_b)
            close = dz < clearance
            if not close.any():
                continue
            at = int(np.flatnonzero(close)[0])
            out.append(
                Overlap(
                    i,
                    j,
                    float(areas[k]) * float(close.mean()),
                    float(points[at, 0]),
                    float(points[at, 1]),
                    float(dz[at]),
                    float(self.surfaces.face_s[face_a[at]]),
                    float(self.surfaces.face_s[face_b[at]]),
                )
            )
        return False


def overlap_index(
    document: Document,
    chord: float | None = None,
    out_of_time: Callable[[], bool] | None = None,
    max_turns: float | None = None,
) -> OverlapIndex:
    """:class:`OverlapIndex` of a document, cached for its lifetime (per chord and ``max_turns``). ``out_of_time`` is
    polled while the footprints are built; when it says so, :class:`OutOfTime` is raised and nothing is cached."""
    most = Tolerances().max_turns if max_turns is None else float(max_turns)
    return cached_per_chord(
        f"overlap index within {most!r} turns", document, chord, lambda d, c: OverlapIndex(d, c, out_of_time, most)
    )


# ------------------------------------------------------------------------------------------------------ metrics
def _junction_lanes(index: OverlapIndex, drivable_only: bool) -> dict[str, np.ndarray]:
    """Junction id -> lane strips of its connecting roads (default and other non-direct junctions)."""
    out: dict[str, list[int]] = {}
    junction_of = index.relations.junction_of
    for i, (key, lane_type) in enumerate(zip(index.surfaces.lanes, index.surfaces.lane_types)):
        junction = junction_of.get(key.road)
        if junction is not None and (not drivable_only or lane_type in DRIVABLE_TYPE_NAMES):
            out.setdefault(junction, []).append(i)
    return {j: np.array(v) for j, v in out.items()}


def area_and_conflict(
    footprints: np.ndarray | Sequence[object], road_ids: Sequence[str], min_overlap: float = 0.0
) -> tuple[float, float]:
    """(area of the union, area of the union of the pairwise overlaps) of lane footprints (shapely geometries), each
    tagged with its road id: pairs on the same road (lanes side by side) and overlaps smaller than ``min_overlap`` are
    not conflicts."""
    if len(footprints) == 0:
        return 0.0, 0.0
    polygons = np.asarray(footprints, dtype=object)
    roads = np.asarray(road_ids, dtype=object)
    area = float(shapely.area(shapely.union_all(polygons)))
    left, right = shapely.STRtree(polygons).query(polygons, predicate="intersects")
    keep = (left < right) & (roads[left] != roads[right])
    if not keep.any():
        return area, 0.0
    overlaps = shapely.intersection(polygons[left[keep]], polygons[right[keep]])
    overlaps = overlaps[shapely.area(overlaps) >= min_overlap]
    conflict = float(shapely.area(shapely.union_all(overlaps))) if len(overlaps) else 0.0
    return area, conflict


def _junction_areas(document: Document, chord: float | None) -> dict[str, tuple[float, float]]:
    """Junction id -> :func:`area_and_conflict` of its drivable connection lanes (U-turns included)."""
    index = overlap_index(document, chord)
    polys = index.footprints.polygons
    lanes = index.surfaces.lanes
    return {
        junction: area_and_conflict(polys[members], [lanes[i].road for i in members])
        for junction, members in _junction_lanes(index, drivable_only=True).items()
    }


def conflict_areas(document: Document, chord: float | None = None) -> dict[str, float]:
    """Junction id -> plan-view area (m^2) where connection lanes of different connecting roads overlap: the union of
    the pairwise intersections of the junction's drivable connection lanes (U-turns included: a U-turn lane crossing
    another path is a conflict like any other). Lanes of one connecting road lie side by side and do not count.
    Junctions without connecting roads with lanes are absent; junctions whose paths never cross give 0."""
    return {junction: conflict for junction, (_, conflict) in _junction_areas(document, chord).items()}


def junction_area(document: Document, chord: float | None = None) -> dict[str, float]:
    """Junction id -> plan-view area (m^2) of the union of its drivable connection lanes (the surface vehicles use
    inside the junction; with :func:`conflict_areas`, the share of it where paths conflict)."""
    return {junction: area for junction, (area, _) in _junction_areas(document, chord).items()}
