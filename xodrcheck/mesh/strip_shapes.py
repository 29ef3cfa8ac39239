"""Plan-view shapes of lane strips beyond their outline (:mod:`xodrcheck.mesh.footprint` builds on them): the pieces a
folded strip is united from, the full circles a strip turns through, and the lane sections whose strips are known not
to overlap at all.

The last rests on winding numbers. The triangles of a lane section (all its strips) form one surface whose boundary is
the section's outline: its outermost right border forward, its outermost left border back (the borders between
strips are shared, and the caps are straight cross-sections). Where every triangle lies the right way up, the outline
winds round a point once for every triangle that covers it; if the outline is a simple polygon, it winds round no
point more than once, so no two triangles of the section overlap: no pair of its strips needs intersecting, however
long they are (a 1e9 m road's two lanes that merely touch cost a second of GEOS overlay otherwise).
"""

from __future__ import annotations

import numpy as np
import shapely

from xodrcheck.mesh.surfaces import LaneSurfaces
from xodrcheck.support.arrays import ranges

__all__ = ["PIECE", "covers_twice", "pieces", "run_outlines", "strip_turns", "tiled_sections", "turns"]

#: Most quads of one piece of a folded strip (:func:`pieces`).
PIECE = 64


def run_outlines(inner: np.ndarray, outer: np.ndarray, runs: np.ndarray) -> np.ndarray:
    """Plan-view outline polygons of runs ``(a, b)`` of quads of one strip (its border rows ``inner`` and ``outer``,
    plan-view points): the inner row from ``a`` to ``b``, then the outer row back."""
    size = runs[:, 1] - runs[:, 0] + 1
    owner = np.repeat(np.arange(len(runs)), 2 * size)
    j = np.arange(owner.size) - np.repeat(np.concatenate([[0], np.cumsum(2 * size)[:-1]]), 2 * size)
    a, n = runs[owner, 0], size[owner]
    last = len(inner) - 1
    xy = np.where((j < n)[:, None], inner[np.clip(a + j, 0, last)], outer[np.clip(a + 2 * n - 1 - j, 0, last)])
    return shapely.polygons(shapely.linearrings(xy, indices=owner))


def turns(xy: np.ndarray) -> float:
    """Full circles the heading of a polyline sweeps: the range of its unwrapped heading over 2 pi (steps of no
    length, where a border passes a centre of curvature, are left out)."""
    steps = np.diff(xy, axis=0)
    steps = steps[(steps[:, 0] != 0) | (steps[:, 1] != 0)]
    if len(steps) < 2:
        return 0.0
    heading = np.unwrap(np.arctan2(steps[:, 1], steps[:, 0]))
    return float((heading.max() - heading.min()) / (2 * np.pi))


def strip_turns(surfaces: LaneSurfaces) -> np.ndarray:
    """:func:`turns` of every strip's inner border, for all strips at once."""
    count = len(surfaces)
    starts = surfaces.lane_vertices[:-1]
    half = np.diff(surfaces.lane_vertices) // 2
    if count == 0 or not half.any():
        return np.zeros(count)
    inner = ranges(starts, half)  # vertex index of every inner-row point, strip after strip
    owner = np.repeat(np.arange(count), half)
    xy = surfaces.vertices[inner, :2]
    step = np.diff(xy, axis=0)
    usable = ((step[:, 0] != 0) | (step[:, 1] != 0)) & (owner[1:] == owner[:-1])
    heading = np.arctan2(step[:, 1], step[:, 0])
    # heading change between usable steps of one strip, wrapped to (-pi, pi]: carried over the steps left out
    kept = np.flatnonzero(usable)
    change = np.zeros(len(step))
    same = owner[kept[1:] + 1] == owner[kept[:-1] + 1]
    turn = np.angle(np.exp(1j * (heading[kept[1:]] - heading[kept[:-1]])))
    change[kept[1:]] = np.where(same, turn, 0.0)
    profile = np.concatenate([[0.0], np.cumsum(change)])  # unwrapped heading (plus a constant) at each point
    low = np.minimum.reduceat(profile, np.concatenate([[0], np.cumsum(half)[:-1]]))
    high = np.maximum.reduceat(profile, np.concatenate([[0], np.cumsum(half)[:-1]]))
    return np.where(half > 0, (high - low) / (2 * np.pi), 0.0)


def covers_twice(surfaces: LaneSurfaces, lanes: np.ndarray) -> np.ndarray:
    """Whether each strip of ``lanes`` certainly covers some ground twice: its triangles' areas add up to more than
    the area of its bounding box. Cheap (a pass over its vertices) where testing the outline for simplicity is not:
    a strip wound thousands of times covers its box hundreds of times over."""
    out = np.zeros(len(lanes), dtype=bool)
    areas = np.concatenate([[0.0], np.cumsum(np.abs(surfaces.plan_areas))])
    for k, lane in enumerate(lanes.tolist()):
        xy = surfaces.vertices[surfaces.lane_vertices[lane] : surfaces.lane_vertices[lane + 1], :2]
        box = float(np.prod(xy.max(axis=0) - xy.min(axis=0))) if len(xy) else 0.0
        out[k] = areas[surfaces.lane_faces[lane + 1]] - areas[surfaces.lane_faces[lane]] > box
    return out


def pieces(surfaces: LaneSurfaces, lane: int) -> np.ndarray:
    """Polygons whose union is the union of a lane strip's triangles: runs of at most :data:`PIECE` quads whose
    outline is a simple polygon and whose triangles all lie one way up (such a run's outline is exactly the union of
    its triangles: they cover it once), other runs halved until they are, down to single triangles."""
    inner, outer = (row[:, :2] for row in surfaces.rows(lane))
    first, stop = surfaces.lane_faces[lane], surfaces.lane_faces[lane + 1]
    areas = surfaces.plan_areas[first:stop]
    down = np.concatenate([[0], np.cumsum(areas < 0)])  # faces upside down before each face
    up = np.concatenate([[0], np.cumsum(areas > 0)])
    quads = len(inner) - 1
    runs = np.array([(a, min(a + PIECE, quads)) for a in range(0, quads, PIECE)], dtype=np.int64).reshape(-1, 2)
    out, at = [], []  # pieces, and where along the strip each starts (quad index, then triangle)
    while len(runs):
        polys = run_outlines(inner, outer, runs)
        a, b = 2 * runs[:, 0], 2 * runs[:, 1]
        ok = shapely.is_valid(polys) & ((down[b] == down[a]) | (up[b] == up[a]))
        out.append(polys[ok])
        at.append(2 * runs[ok, 0])
        single = runs[~ok & (runs[:, 1] - runs[:, 0] == 1)]
        if len(single):
            faces = np.concatenate([2 * single[:, 0], 2 * single[:, 0] + 1])
            tris = surfaces.vertices[surfaces.faces[first + faces]][..., :2]
            polys = shapely.polygons(np.concatenate([tris, tris[:, :1]], axis=1))
            keep = shapely.area(polys) > 0
            out.append(polys[keep])
            at.append(faces[keep])
        split = runs[~ok & (runs[:, 1] - runs[:, 0] > 1)]
        middle = (split[:, 0] + split[:, 1]) // 2
        runs = np.concatenate([np.column_stack([split[:, 0], middle]), np.column_stack([middle, split[:, 1]])])
    if not out:
        return np.empty(0, dtype=object)
    # in order along the strip: the union is made of consecutive blocks, which stay compact that way
    return np.concatenate(out)[np.argsort(np.concatenate(at), kind="stable")]


def tiled_sections(surfaces: LaneSurfaces, overlapping: np.ndarray | None = None) -> np.ndarray:
    """For each strip, the index of its lane section's first strip when no two triangles of that section overlap
    (see the module docstring), else -1. ``surfaces`` must hold every lane
    (:func:`xodrcheck.mesh.surfaces.surfaces_of`). A section is the run of consecutive strips of one road id and section
    ``s``; a run that holds a lane id twice (two roads of one id) is not judged, nor one holding a strip of
    ``overlapping`` (indexes of strips known to cover themselves twice: a section that holds one is no tiling, and its
    outline may cross itself at every step)."""
    count = len(surfaces)
    out = np.full(count, -1, dtype=np.int64)
    if count == 0:
        return out
    keys = [(k.road, k.section_s) for k in surfaces.lanes]
    starts = [i for i in range(count) if i == 0 or keys[i] != keys[i - 1]]
    upright = np.bincount(surfaces.face_lane[surfaces.plan_areas < 0], minlength=count) == 0
    if overlapping is not None:
        upright[overlapping] = False
    rings, runs = [], []
    for first, stop in zip(starts, [*starts[1:], count]):
        ids = [surfaces.lanes[i].lane for i in range(first, stop)]
        if len(set(ids)) < len(ids) or not upright[first:stop].all():
            continue
        # the outermost right border (or the lane-0 line, without right lanes), then the outermost left border
        low, high = int(np.argmin(ids)), int(np.argmax(ids))
        bottom = surfaces.rows(first + low)[1 if ids[low] < 0 else 0]
        top = surfaces.rows(first + high)[1 if ids[high] > 0 else 0]
        rings.append(np.concatenate([bottom[:, :2], top[::-1, :2]]))
        runs.append((first, stop))
    if not rings:
        return out
    sizes = [len(r) for r in rings]
    owner = np.repeat(np.arange(len(rings)), sizes)
    outlines = shapely.polygons(shapely.linearrings(np.concatenate(rings), indices=owner))
    for (first, stop), simple in zip(runs, shapely.is_valid(outlines)):
        if simple:
            out[first:stop] = first
    return out
