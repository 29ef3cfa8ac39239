"""Reference-line poses for :mod:`xodrcheck.roadpass`: the plan-view pose at every sample of many lane sections at
once, lines and arcs of all roads gathered into one elementwise call each, the other elements (spirals, poly3,
paramPoly3, whose evaluation depends on the batch of points) per section and element run, with exactly the points the
per-section code gives them.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from xodrcheck.arrays import ranges
from xodrcheck.geometry import parampoly3
from xodrcheck.geometry.planview import ReferenceLine, evaluate_element
from xodrcheck.geometry.pose import Pose
from xodrcheck.lanes import RoadGeometry
from xodrcheck.model import Arc, Line, ParamPoly3, Poly3, Spiral

#: A lane section of a road: (its road's geometry, the section's index).
Entry = tuple[RoadGeometry, int]

#: Plan-view elements whose evaluation depends on the batch of points it is given (evaluated per section).
_PER_CALL = (ParamPoly3, Poly3, Spiral)


def poses(entries: Sequence[Entry], s: np.ndarray, offsets: np.ndarray) -> Pose | None:
    """Reference poses of every entry's samples (entries grouped by road): ``_reference`` of each road, with the
    lines and arcs of all roads evaluated in one gathered call each (their formulas are elementwise)."""
    n = len(s)
    counts = np.diff(offsets)
    roads: list[ReferenceLine] = []
    road_of_entry = np.empty(len(entries), dtype=np.int64)
    for k, (rg, _) in enumerate(entries):
        if not roads or roads[-1] is not rg.reference_line:
            roads.append(rg.reference_line)
        road_of_entry[k] = len(roads) - 1
    road = np.repeat(road_of_entry, counts)
    first = np.concatenate(([0], np.cumsum([len(line.elements) for line in roads])))
    elements = [g for line in roads for g in line.elements]
    if any(not line.elements for line in roads):
        return None  # no plan view: left to the per-section code
    breakpoints = np.concatenate([line.breakpoints for line in roads])
    lengths = np.concatenate([line._lengths for line in roads])
    index = np.empty(n, dtype=np.int64)
    bounds = np.concatenate(([0], np.cumsum(np.bincount(road, minlength=len(roads)))))
    for r, line in enumerate(roads):  # the element of each point, as ReferenceLine.evaluate finds it
        lo, hi = int(bounds[r]), int(bounds[r + 1])
        if len(line.elements) == 1:
            index[lo:hi] = first[r]
        else:
            index[lo:hi] = first[r] + line.element_index(np.minimum(np.maximum(s[lo:hi], line.start), line.end))
    ds = np.minimum(np.maximum(s - breakpoints[index], 0.0), lengths[index])
    inside = np.ones(max(n - 1, 0), dtype=bool)
    inside[offsets[1:-1] - 1] = False  # k and k + 1 belong to different sections
    step = np.diff(index)
    if (step[inside] < 0).any():
        return None  # unsorted samples: the per-section code groups them otherwise
    kind = np.array([0 if type(g) is Line else 1 if type(g) is Arc else 2 for g in elements], dtype=np.int8)
    pose = Pose.empty(n)
    own = kind[index]
    for code, evaluate in ((0, _lines_at), (1, _arcs_at)):
        at = np.flatnonzero(own == code)
        if len(at):
            pose.assign(at, evaluate(elements, index[at], ds[at], kind, code))
    other = own == 2
    if other.any():  # per section and element run, with exactly the per-section code's points
        cut = (step != 0) | ~inside
        edges = np.concatenate(([0], np.flatnonzero(cut) + 1, [n]))
        curves: list[tuple[int, int]] = []  # paramPoly3 runs: evaluated together, each as its own call
        for lo, hi in zip(edges[:-1].tolist(), edges[1:].tolist()):
            if other[lo]:
                if type(elements[index[lo]]) is ParamPoly3:
                    curves.append((lo, hi))
                else:
                    pose.assign(slice(lo, hi), evaluate_element(elements[index[lo]], ds[lo:hi]))
        if curves:
            at = ranges([lo for lo, _ in curves], [hi - lo for lo, hi in curves])
            counts = np.array([hi - lo for lo, hi in curves], dtype=np.int64)
            pose.assign(at, parampoly3.evaluate_runs([elements[index[lo]] for lo, _ in curves], ds[at], counts))
    return pose


def _lines_at(elements: list, index: np.ndarray, ds: np.ndarray, kind: np.ndarray, code: int) -> Pose:
    """``line.evaluate`` at points of many lines: ``x0 + ds cos(hdg)``, ``y0 + ds sin(hdg)``."""
    chosen = np.flatnonzero(kind == code)
    x0, y0, hdg = np.zeros(len(kind)), np.zeros(len(kind)), np.zeros(len(kind))
    x0[chosen] = [elements[i].x for i in chosen]
    y0[chosen] = [elements[i].y for i in chosen]
    hdg[chosen] = [elements[i].hdg for i in chosen]
    zero = np.zeros_like(ds)
    return Pose(x0[index] + ds * np.cos(hdg)[index], y0[index] + ds * np.sin(hdg)[index], hdg[index], zero, zero.copy())


def _arcs_at(elements: list, index: np.ndarray, ds: np.ndarray, kind: np.ndarray, code: int) -> Pose:
    """``arc.evaluate`` at points of many arcs (the same operations, with each point's arc's numbers)."""
    chosen = np.flatnonzero(kind == code)
    x0, y0, hdg, k = (np.zeros(len(kind)) for _ in range(4))
    x0[chosen] = [elements[i].x for i in chosen]
    y0[chosen] = [elements[i].y for i in chosen]
    hdg[chosen] = [elements[i].hdg for i in chosen]
    k[chosen] = [elements[i].curvature for i in chosen]
    k_at, hdg_at = k[index], hdg[index]
    half_turn = (0.5 * k)[index] * ds
    chord = ds * np.sinc(half_turn / np.pi)
    direction = hdg_at + half_turn
    return Pose(
        x0[index] + chord * np.cos(direction),
        y0[index] + chord * np.sin(direction),
        hdg_at + k_at * ds,
        k_at.copy(),
        np.zeros_like(ds),
    )
