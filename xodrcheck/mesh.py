"""Lane surface meshes: every lane of every lane section as a triangle strip in 3D, built with numpy index arithmetic.

Each lane section is sampled once (:meth:`RoadGeometry.sample_s`, adaptive under a chord tolerance) and all its lane
borders are evaluated at those ``s`` in one call, elevation and superelevation applied as :mod:`xodrcheck.lanes` does.
Every lane then gets two vertex rows of its own, its inner and its outer border (vertices are not shared between
lanes, so a lane can be coloured or cut out alone), and ``2 (n - 1)`` triangles between them, wound counter-clockwise
seen from above (normals point up where the lane does not fold).

Faces know their lane: ``face_lane[f]`` indexes :attr:`LaneSurfaces.lanes` (a :class:`~xodrcheck.model.LaneKey` per
lane), and ``face_s[f]`` is the reference-line ``s`` where the face's quad starts. The vertices and faces of one lane
are contiguous (``lane_vertices``/``lane_faces`` give the ranges), so a lane's plan-view outline is its inner row
followed by its outer row reversed.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Collection, Mapping
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from xodrcheck.config import Tolerances
from xodrcheck.info import lane_type_name
from xodrcheck.lanes import RoadGeometry, geometry_of
from xodrcheck.model import Document, LaneKey, Road, document_cache

#: Largest coordinate (m) a meshed vertex may have: 25 times the Earth's circumference. Beyond it a lane is damaged
#: input (a width of 1e308, say), and polygon operations (GEOS) fail on such numbers instead of giving an area.
MAX_COORDINATE = 1e9


@dataclass(frozen=True, eq=False)
class LaneSurfaces:
    """The lane surfaces of a map as one indexed triangle mesh (see the module docstring)."""

    #: One key per lane strip (a lane of one lane section), in build order.
    lanes: tuple[LaneKey, ...]
    #: The lane type of each strip, as the standard spells it (``lane_type_name``).
    lane_types: tuple[str, ...]
    #: ``(V, 3)`` vertex positions (x, y, z) in the file's inertial frame.
    vertices: np.ndarray
    #: ``(F, 3)`` vertex indices, counter-clockwise seen from above.
    faces: np.ndarray
    #: ``(F,)`` index into :attr:`lanes` of each face.
    face_lane: np.ndarray
    #: ``(F,)`` reference-line ``s`` at the start of each face's quad.
    face_s: np.ndarray
    #: ``(L + 1,)`` vertex offsets: lane ``i`` owns vertices ``lane_vertices[i]:lane_vertices[i + 1]`` (inner row, then
    #: outer row, each of the same length).
    lane_vertices: np.ndarray
    #: ``(L + 1,)`` face offsets, as ``lane_vertices``.
    lane_faces: np.ndarray

    def __len__(self) -> int:
        return len(self.lanes)

    @property
    def lane_index(self) -> dict[LaneKey, int]:
        return {key: i for i, key in enumerate(self.lanes)}

    @cached_property
    def face_areas(self) -> np.ndarray:
        """Area of each face in 3D."""
        a, b, c = (self.vertices[self.faces[:, k]] for k in range(3))
        return 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)

    @cached_property
    def plan_areas(self) -> np.ndarray:
        """Signed plan-view area of each face: positive where the lane surface lies the right way up, negative where it
        folds back over itself."""
        a, b, c = (self.vertices[self.faces[:, k], :2] for k in range(3))
        u, v = b - a, c - a
        return 0.5 * (u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])

    def lane_areas(self) -> np.ndarray:
        """3D surface area of each lane strip."""
        return np.bincount(self.face_lane, weights=self.face_areas, minlength=len(self.lanes))

    def area(self) -> float:
        return float(self.face_areas.sum())

    def rows(self, lane: int) -> tuple[np.ndarray, np.ndarray]:
        """Inner and outer border vertices ``(n, 3)`` of one lane strip."""
        start, stop = self.lane_vertices[lane], self.lane_vertices[lane + 1]
        half = (stop - start) // 2
        return self.vertices[start : start + half], self.vertices[start + half : stop]

    def outline_order(self) -> tuple[np.ndarray, np.ndarray]:
        """Vertex indices of every lane's plan-view outline (inner row forward, outer row backward), concatenated,
        and the lane index of each: ready for ``shapely.linearrings(xy[order], indices=owner)``."""
        counts = np.diff(self.lane_vertices)
        owner = np.repeat(np.arange(len(self.lanes)), counts)
        j = np.arange(owner.size) - np.repeat(self.lane_vertices[:-1], counts)
        half = np.repeat(counts // 2, counts)
        base = np.repeat(self.lane_vertices[:-1], counts)
        order = np.where(j < half, base + j, base + 3 * half - 1 - j)
        return order, owner

    def select(self, keep: np.ndarray) -> LaneSurfaces:
        """The surfaces of the lanes where the boolean array ``keep`` (one entry per lane) is true."""
        keep = np.asarray(keep, dtype=bool)
        chosen = np.flatnonzero(keep)
        v_counts = np.diff(self.lane_vertices)[chosen]
        f_counts = np.diff(self.lane_faces)[chosen]
        v_take = _ranges(self.lane_vertices[chosen], v_counts)
        f_take = _ranges(self.lane_faces[chosen], f_counts)
        new_vertex = np.full(len(self.vertices), -1, dtype=np.int64)
        new_vertex[v_take] = np.arange(v_take.size)
        new_lane = np.full(len(self.lanes), -1, dtype=np.int64)
        new_lane[chosen] = np.arange(chosen.size)
        return LaneSurfaces(
            lanes=tuple(self.lanes[i] for i in chosen),
            lane_types=tuple(self.lane_types[i] for i in chosen),
            vertices=self.vertices[v_take],
            faces=new_vertex[self.faces[f_take]],
            face_lane=new_lane[self.face_lane[f_take]],
            face_s=self.face_s[f_take],
            lane_vertices=np.concatenate([[0], np.cumsum(v_counts)]).astype(np.int64),
            lane_faces=np.concatenate([[0], np.cumsum(f_counts)]).astype(np.int64),
        )

    def to_trimesh(self):
        """One :class:`trimesh.Trimesh` (not processed, so faces keep their order and ``face_lane`` stays valid)."""
        import trimesh

        return trimesh.Trimesh(vertices=self.vertices, faces=self.faces, process=False, validate=False)


def _ranges(starts: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """Concatenated ``arange(start, start + count)`` for each pair."""
    counts = np.asarray(counts, dtype=np.int64)
    offsets = np.repeat(np.asarray(starts, dtype=np.int64) - np.cumsum(counts) + counts, counts)
    return offsets + np.arange(counts.sum(), dtype=np.int64)


def _strip_faces(lane_count: int, n: int, left: np.ndarray) -> np.ndarray:
    """Faces of ``lane_count`` strips of ``n`` samples whose vertices are laid out lane after lane (inner row, outer
    row); ``left[i]`` flips the winding of strip ``i`` (a left lane's outer border lies to the left of its inner)."""
    j = np.arange(n - 1)
    base = (2 * n * np.arange(lane_count))[:, None]
    inner, inner_next = base + j, base + j + 1
    outer, outer_next = inner + n, inner_next + n
    right_tris = np.stack(
        [np.stack([inner, outer, outer_next], -1), np.stack([inner, outer_next, inner_next], -1)], axis=2
    )
    left_tris = right_tris[..., [0, 2, 1]]
    tris = np.where(left[:, None, None, None], left_tris, right_tris)  # (lanes, n - 1, 2, 3)
    return tris.reshape(lane_count, -1, 3)


class MeshTooLarge(ValueError):
    """The mesh would have more vertices than the bound it was built with."""


def _road_geometry(document: Document, road: Road, geometries: Mapping[str, RoadGeometry]) -> RoadGeometry:
    rg = geometries[road.id]
    return rg if rg.road is road else RoadGeometry(road)  # a duplicated id: the mapping holds the first road


def build_surfaces(
    document: Document,
    chord: float | None = None,
    lane_types: Collection[str] | None = None,
    max_step: float | None = None,
    max_vertices: int | None = None,
) -> LaneSurfaces:
    """Mesh every lane of every road with a plan view (centre lanes have no surface).

    ``lane_types`` keeps only lanes of those types (names as the standard spells them; ``None``: all). Lane sections
    that do not end after they start, and sections whose geometry does not evaluate to finite numbers or lies beyond
    :data:`MAX_COORDINATE` (a damaged width or position: other rules report it), are skipped. With ``max_vertices``,
    a mesh that would have more vertices raises :class:`MeshTooLarge` as soon as it passes the bound.
    """
    defaults = Tolerances()
    chord = defaults.chord if chord is None else chord
    max_step = defaults.max_step if max_step is None else max_step
    if not (math.isfinite(chord) and chord > 0):
        raise ValueError(f"chord must be a finite number > 0, got {chord!r}")
    wanted = None if lane_types is None else frozenset(lane_types)
    geometries = geometry_of(document)
    keys: list[LaneKey] = []
    types: list[str] = []
    vertex_blocks: list[np.ndarray] = []
    face_blocks: list[np.ndarray] = []
    s_blocks: list[np.ndarray] = []
    lane_sizes: list[np.ndarray] = []
    vertex_total = 0
    for road in document.roads:
        if not road.plan_view:
            continue
        rg = _road_geometry(document, road, geometries)
        for index, section in enumerate(road.lane_sections):
            if not road.section_end(index) > section.s:
                continue
            left, right = rg.side_lanes(index)
            pairs = [  # (lane, id of the lane whose outer border is its inner border)
                (lane, inner.id if k else 0)
                for side in (left, right)
                for k, (lane, inner) in enumerate(zip(side.lanes, (None, *side.lanes[:-1])))
            ]
            pairs = [(lane, inner) for lane, inner in pairs if wanted is None or lane_type_name(lane) in wanted]
            if not pairs:
                continue
            s = rg.sample_s(index, chord=chord, max_step=max_step)
            n = len(s)
            if n < 2:
                continue
            curves = rg.border_curves(index, s)
            ids = list(curves)
            rows = np.stack([np.column_stack([curves[i].x, curves[i].y, curves[i].z]) for i in ids])
            if not (np.abs(rows) <= MAX_COORDINATE).all():  # also False for NaN
                continue
            row_of = {lane_id: k for k, lane_id in enumerate(ids)}
            inner = np.array([row_of[i] for _, i in pairs])
            outer = np.array([row_of[lane.id] for lane, _ in pairs])
            block = np.stack([rows[inner], rows[outer]], axis=1).reshape(-1, 3)  # lane after lane: inner, outer rows
            faces = _strip_faces(len(pairs), n, np.array([lane.id > 0 for lane, _ in pairs]))
            vertex_blocks.append(block)
            face_blocks.append(faces.reshape(-1, 3) + vertex_total)
            s_blocks.append(np.tile(np.repeat(s[:-1], 2), len(pairs)))
            lane_sizes.append(np.full(len(pairs), n))
            vertex_total += len(block)
            if max_vertices is not None and vertex_total > max_vertices:
                raise MeshTooLarge(f"the mesh has more than {max_vertices:,} vertices (tolerance max_output_points)")
            keys.extend(LaneKey(road.id, section.s, lane.id) for lane, _ in pairs)
            types.extend(lane_type_name(lane) for lane, _ in pairs)
    sizes = np.concatenate(lane_sizes) if lane_sizes else np.zeros(0, dtype=np.int64)
    lane_vertices = np.concatenate([[0], np.cumsum(2 * sizes)]).astype(np.int64)
    lane_faces = np.concatenate([[0], np.cumsum(2 * (sizes - 1))]).astype(np.int64)
    return LaneSurfaces(
        lanes=tuple(keys),
        lane_types=tuple(types),
        vertices=np.concatenate(vertex_blocks) if vertex_blocks else np.zeros((0, 3)),
        faces=np.concatenate(face_blocks).astype(np.int64) if face_blocks else np.zeros((0, 3), dtype=np.int64),
        face_lane=np.repeat(np.arange(len(keys)), 2 * (sizes - 1)),
        face_s=np.concatenate(s_blocks) if s_blocks else np.zeros(0),
        lane_vertices=lane_vertices,
        lane_faces=lane_faces,
    )


def cached_per_chord(name: str, document: Document, chord: float | None, build: Callable):
    """``build(document, chord)`` (chord defaulting to the configured tolerance), kept as ``name`` with the document
    (:func:`xodrcheck.model.document_cache`) for its lifetime, per chord."""
    chord = Tolerances().chord if chord is None else float(chord)
    cache = document_cache(document)
    key = (name, chord)
    found = cache.get(key)
    if found is None:
        found = cache[key] = build(document, chord)
    return found


def surfaces_of(document: Document, chord: float | None = None) -> LaneSurfaces:
    """:func:`build_surfaces` of every lane, cached per document and chord for the document's lifetime (the overlap
    rules and the metrics share one mesh)."""
    return cached_per_chord("surfaces", document, chord, build_surfaces)
