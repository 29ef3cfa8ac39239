"""Lane surface meshes: every lane of every lane section as a triangle strip in 3D, built with numpy index arithmetic.

Each lane section is sampled once (:meth:`RoadGeometry.sample_s`, adaptive under a chord tolerance) and all its lane
borders are evaluated at those ``s`` (:mod:`xodrcheck.geometry.batch`, many sections at once), elevation and
superelevation applied as :mod:`xodrcheck.geometry.lanes` describes.
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
from collections.abc import Callable, Collection, Iterator
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from xodrcheck.config import Tolerances
from xodrcheck.findings import XodrError
from xodrcheck.geometry.batch import Evaluation
from xodrcheck.geometry.lanes import RoadGeometry, road_geometry
from xodrcheck.geometry.sampling import sample_sections
from xodrcheck.model import Document, Lane, LaneKey, document_cache, lane_type_name
from xodrcheck.support import work
from xodrcheck.support.arrays import batches, ranges

__all__ = [
    "FACE_BLOCK",
    "MAX_COORDINATE",
    "MESH_BATCH",
    "SAMPLE_SECTIONS",
    "LaneSurfaces",
    "MeshTooLarge",
    "build_surfaces",
    "cached_per_chord",
    "surfaces_of",
]


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

    @cached_property
    def face_areas(self) -> np.ndarray:
        """Area of each face in 3D."""
        return self._per_face(_face_area)

    @cached_property
    def plan_areas(self) -> np.ndarray:
        """Signed plan-view area of each face: positive where the lane surface lies the right way up, negative where it
        folds back over itself."""
        return self._per_face(_plan_area)

    def _per_face(self, measure: Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray]) -> np.ndarray:
        """``measure(a, b, c)`` of every face's corners, in blocks of :data:`FACE_BLOCK` faces (the corners of a big
        map's faces at once are hundreds of MB of temporaries)."""
        out = np.empty(len(self.faces))
        for lo in range(0, len(self.faces), FACE_BLOCK):
            faces = self.faces[lo : lo + FACE_BLOCK]
            out[lo : lo + len(faces)] = measure(*(self.vertices[faces[:, k]] for k in range(3)))
        return out

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

    def outline_order(self, first: int = 0, last: int | None = None) -> tuple[np.ndarray, np.ndarray]:
        """Vertex indices of the plan-view outline of every lane from ``first`` to before ``last`` (default: all;
        inner row forward, outer row backward), concatenated, and the lane index of each counted from ``first``:
        ready for ``shapely.linearrings(xy[order], indices=owner)``."""
        starts = self.lane_vertices[first : (len(self.lanes) if last is None else last) + 1]
        counts = np.diff(starts)
        owner = np.repeat(np.arange(len(counts)), counts)
        j = np.arange(owner.size) - np.repeat(starts[:-1] - starts[0], counts)
        half = np.repeat(counts // 2, counts)
        base = np.repeat(starts[:-1], counts)
        order = np.where(j < half, base + j, base + 3 * half - 1 - j)
        return order, owner

    def select(self, keep: np.ndarray) -> LaneSurfaces:
        """The surfaces of the lanes where the boolean array ``keep`` (one entry per lane) is true."""
        keep = np.asarray(keep, dtype=bool)
        chosen = np.flatnonzero(keep)
        v_counts = np.diff(self.lane_vertices)[chosen]
        f_counts = np.diff(self.lane_faces)[chosen]
        v_take = ranges(self.lane_vertices[chosen], v_counts)
        f_take = ranges(self.lane_faces[chosen], f_counts)
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


#: Faces measured at a time (:meth:`LaneSurfaces.face_areas`, :meth:`LaneSurfaces.plan_areas`).
FACE_BLOCK = 1 << 16


def _face_area(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    return 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)


def _plan_area(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    u, v = b[:, :2] - a[:, :2], c[:, :2] - a[:, :2]
    return 0.5 * (u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])


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


class MeshTooLarge(XodrError, ValueError):
    """The mesh would have more vertices than the bound it was built with."""


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
    a mesh that would have more vertices raises :class:`MeshTooLarge` before its vertex arrays are built. All sections
    are sampled and evaluated together, in batches (:mod:`xodrcheck.geometry.sampling`,
    :mod:`xodrcheck.geometry.batch`: the numbers of each section alone).
    """
    defaults = Tolerances()
    chord = defaults.chord if chord is None else chord
    max_step = defaults.max_step if max_step is None else max_step
    if not (math.isfinite(chord) and chord > 0):
        raise ValueError(f"chord must be a finite number > 0, got {chord!r}")
    wanted = None if lane_types is None else frozenset(lane_types)
    bound = _Bound(max_vertices)
    part = _Part.concat([p for todo in _sections(document, wanted) for p in _together(todo, chord, max_step, bound)])
    work.add("mesh vertices", len(part.vertices))
    return part.surfaces()


def _sections(document: Document, wanted: frozenset | None) -> Iterator[list[_Section]]:
    """The lane sections to mesh, road after road, in runs of about :data:`SAMPLE_SECTIONS` sections. Their roads'
    geometry is the document's cached one where the rules built it (``geometry_of``), else each run's own, dropped
    with the run: the mesh of a big map (whose check drops the cache first) holds the geometry of one run at a time
    and leaves none in the document's cache."""
    cached = document_cache(document).get("geometry")
    todo: list[_Section] = []
    for road in document.roads:
        if not road.plan_view:
            continue
        rg = RoadGeometry(road) if cached is None else road_geometry(cached, road)
        for index, section in enumerate(road.lane_sections):
            if road.section_end(index) > section.s:
                pairs = _lane_pairs(rg, index, wanted)
                if pairs:
                    todo.append(_Section(rg, index, pairs))
        if len(todo) >= SAMPLE_SECTIONS:
            yield todo
            todo = []
    if todo:
        yield todo


class _Bound:
    """Counts the vertices of the mesh being built against ``max_vertices`` (``None``: no bound)."""

    def __init__(self, most: int | None) -> None:
        self.most = most
        self.total = 0

    def add(self, vertices: int) -> None:
        self.total += vertices
        if self.most is not None and self.total > self.most:
            raise MeshTooLarge(f"the mesh has more than {self.most:,} vertices (tolerance max_output_points)")


@dataclass
class _Section:
    """A lane section to mesh: its road geometry, index and the lanes with their inner neighbours."""

    rg: RoadGeometry
    index: int
    #: (lane, id of the lane whose outer border is its inner border) of every meshed lane.
    pairs: list[tuple[Lane, int]]


def _lane_pairs(rg: RoadGeometry, index: int, wanted: frozenset | None) -> list[tuple[Lane, int]]:
    left, right = rg.side_lanes(index)
    pairs = [(lane, side.lanes[k - 1].id if k else 0) for side in (left, right) for k, lane in enumerate(side.lanes)]
    return [(lane, inner) for lane, inner in pairs if wanted is None or lane_type_name(lane) in wanted]


@dataclass
class _Part:
    """Mesh arrays of consecutive lane strips, faces numbered from the part's first vertex."""

    vertices: np.ndarray
    faces: np.ndarray
    face_s: np.ndarray
    sizes: np.ndarray  # samples per strip
    keys: list[LaneKey]
    types: list[str]

    @staticmethod
    def concat(parts: list[_Part]) -> _Part:
        """The parts one after the other; the parts' arrays are dropped as they are copied, so the copy costs one
        array's size at a time."""
        if len(parts) == 1:
            return parts[0]
        empty = np.zeros((0, 3))
        shift = np.cumsum([0] + [len(p.vertices) for p in parts])
        out = _Part(
            np.concatenate([p.vertices for p in parts] or [empty]),
            empty.astype(np.int64),
            np.zeros(0),
            np.concatenate([p.sizes for p in parts] or [np.zeros(0)]).astype(np.int64),
            [k for p in parts for k in p.keys],
            [t for p in parts for t in p.types],
        )
        for p in parts:
            p.vertices = empty
        out.faces = np.concatenate([p.faces + shift[i] for i, p in enumerate(parts)] or [out.faces]).astype(np.int64)
        for p in parts:
            p.faces = empty
        out.face_s = np.concatenate([p.face_s for p in parts] or [out.face_s])
        return out

    def surfaces(self) -> LaneSurfaces:
        sizes = self.sizes
        return LaneSurfaces(
            lanes=tuple(self.keys),
            lane_types=tuple(self.types),
            vertices=self.vertices,
            faces=self.faces,
            face_lane=np.repeat(np.arange(len(self.keys)), 2 * (sizes - 1)),
            face_s=self.face_s,
            lane_vertices=np.concatenate([[0], np.cumsum(2 * sizes)]).astype(np.int64),
            lane_faces=np.concatenate([[0], np.cumsum(2 * (sizes - 1))]).astype(np.int64),
        )


#: Border-line points (samples times lines) of the sections meshed in one evaluation: the temporaries of a call scale
#: with it, so a big map is meshed in batches, not all at once.
MESH_BATCH = 1 << 18
#: Sections sampled in one :func:`~xodrcheck.geometry.sampling.sample_sections` call (its temporaries scale with them,
#: many times the samples' own size); also about the sections whose road geometry the mesh holds at once.
SAMPLE_SECTIONS = 1 << 10


def _together(todo: list[_Section], chord: float, max_step: float, bound: _Bound | None = None) -> list[_Part]:
    """The sections of ``todo`` sampled and meshed in batches of consecutive sections (the same numbers: a batch
    evaluates each section as alone)."""
    blocks = [(t.rg.rows(t.index), t.rg.knots(t.index)) for t in todo]
    budget = Tolerances().max_samples_per_section
    samples: list[np.ndarray] = []
    for lo in range(0, len(blocks), SAMPLE_SECTIONS):
        samples.extend(sample_sections(blocks[lo : lo + SAMPLE_SECTIONS], chord, max_step, budget))
    return [
        _batch(todo[lo:hi], samples[lo:hi], bound)
        for lo, hi in batches([len(s) * (len(t.pairs) + 1) for t, s in zip(todo, samples)], MESH_BATCH)
    ]


def _batch(todo: list[_Section], samples: list[np.ndarray], bound: _Bound | None) -> _Part:
    """One batch of :func:`_together` (its sections sampled), meshed from one evaluation of their border lines; a
    section whose lines are not finite or lie beyond :data:`MAX_COORDINATE` is left out."""
    keep = [k for k, s in enumerate(samples) if len(s) > 1]  # fewer than two knots: nothing to mesh
    evaluation = Evaluation([todo[k].rg.rows(todo[k].index) for k in keep], [samples[k] for k in keep])
    lines = evaluation.border_lines()
    x, y = lines.xy()
    xyz = np.column_stack([x, y, lines.z()])
    del x, y, lines
    ok = (np.abs(xyz) <= MAX_COORDINATE).all(axis=1)  # also False for NaN
    line_counts = [len(section.lines) * len(samples[k]) for section, k in zip(evaluation.sections, keep)]
    first = np.concatenate(([0], np.cumsum(line_counts)[:-1])).astype(np.int64)
    usable = np.zeros(len(todo), dtype=bool)
    if len(ok):
        usable[keep] = np.logical_and.reduceat(ok, first)
    ids: list[list[int]] = [[] for _ in todo]
    base = np.zeros(len(todo), dtype=np.int64)
    for kept, k in enumerate(keep):
        ids[k], base[k] = evaluation.border_ids(kept), first[kept]
    del evaluation
    if bound is not None:
        bound.add(sum(2 * len(s) * len(t.pairs) for t, s, fine in zip(todo, samples, usable) if fine))
    offsets = np.concatenate(([0], np.cumsum([len(s) for s in samples]))).astype(np.int64)
    return _strips(todo, ids, xyz, base, samples, offsets, usable)


def _strips(
    todo: list[_Section],
    ids: list[list[int]],
    xyz: np.ndarray,
    base: np.ndarray,
    samples: list[np.ndarray],
    offsets: np.ndarray,
    usable: np.ndarray | None = None,
) -> _Part:
    """Vertices (inner row then outer row of each lane, lane after lane), faces and face ``s`` of the sections'
    strips, from their border rows (section ``k``: row ``r`` at ``base[k] + r * n_k`` of ``xyz``)."""
    inner_at, outer_at, sizes, left, keys, types, strips = [], [], [], [], [], [], [0]
    for k, t in enumerate(todo):
        if usable is not None and not usable[k]:
            strips.append(strips[-1])
            continue
        n = len(samples[k])
        row_of = {lane_id: r for r, lane_id in enumerate(ids[k])}
        first = int(base[k])
        section_s = t.rg.road.lane_sections[t.index].s
        for lane, inner in t.pairs:
            inner_at.append(first + row_of[inner] * n)
            outer_at.append(first + row_of[lane.id] * n)
            sizes.append(n)
            left.append(lane.id > 0)
            keys.append(LaneKey(t.rg.road.id, section_s, lane.id))
            types.append(lane_type_name(lane))
        strips.append(len(sizes))
    counts = np.array(sizes, dtype=np.int64)
    rows = np.empty(2 * len(counts), dtype=np.int64)
    rows[0::2], rows[1::2] = inner_at, outer_at
    vertices = xyz[ranges(rows, np.repeat(counts, 2))]
    first_vertex = np.concatenate([[0], np.cumsum(2 * counts)[:-1]]).astype(np.int64)
    steps = counts - 1
    j = ranges(np.zeros(len(counts)), steps)
    owner = np.repeat(np.arange(len(counts)), steps)
    inner = first_vertex[owner] + j
    inner_next, outer = inner + 1, inner + counts[owner]
    outer_next = outer + 1
    flip = np.array(left, dtype=bool)[owner]
    tris = np.empty((len(j), 2, 3), dtype=np.int64)
    tris[:, 0, 0], tris[:, 1, 0] = inner, inner
    tris[:, 0, 1] = np.where(flip, outer_next, outer)
    tris[:, 0, 2] = np.where(flip, outer, outer_next)
    tris[:, 1, 1] = np.where(flip, inner_next, outer_next)
    tris[:, 1, 2] = np.where(flip, outer_next, inner_next)
    entry = np.repeat(np.arange(len(todo)), np.diff(strips))  # section of each strip
    s_flat = np.concatenate(samples) if samples else np.zeros(0)
    sample_at = np.asarray(offsets, dtype=np.int64)[entry][owner] + j if len(j) else j
    return _Part(vertices, tris.reshape(-1, 3), np.repeat(s_flat[sample_at], 2), counts, keys, types)


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
