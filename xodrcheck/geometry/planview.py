"""Reference lines: plan-view elements evaluated at absolute ``s``, vectorised, for one road or many together.

Each ``s`` is assigned to the last element whose start ``s`` is at or before it (a binary search over the element
starts, so a point exactly on a joint belongs to the element that starts there), then the elements evaluate their
points. ``s`` outside ``[first start, last end]`` is clamped to that range, and ``ds`` is clamped to the element's
``[0, length]``: gaps and overlaps between elements are the geometry rules' business, not a reason for extrapolated
points.

:func:`poses` evaluates many blocks of ``s`` (each on its own road) at once; :meth:`ReferenceLine.evaluate` is one
block. Lines and arcs are evaluated elementwise, the points of every block together; an element whose evaluation
depends on the batch of points it is given (spiral, poly3, paramPoly3: series lengths and Newton iterations are chosen
per call) gets one call per block with that block's points on it, in their order, so a block's numbers never depend
on the other blocks.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence

import numpy as np

from xodrcheck.geometry import arc, line, parampoly3, poly3, spiral
from xodrcheck.geometry.pose import Pose, as_array
from xodrcheck.model import Arc, Geometry, Line, ParamPoly3, Poly3, Spiral
from xodrcheck.support.arrays import ranges

_EVALUATORS: dict[type, Callable[..., Pose]] = {
    Line: line.evaluate,
    Arc: arc.evaluate,
    Spiral: spiral.evaluate,
    Poly3: poly3.evaluate,
    ParamPoly3: parampoly3.evaluate,
}

#: Elements whose calls are evaluated together, each call with its own numbers.
_RUNS: dict[type, Callable[..., Pose]] = {ParamPoly3: parampoly3.evaluate_runs, Poly3: poly3.evaluate_runs}

#: Element kinds in :attr:`ReferenceLine.kinds`: evaluated elementwise (lines, arcs), or one call per block.
_LINE, _ARC, _PER_CALL = 0, 1, 2


def _clamp(values: np.ndarray, low, high) -> np.ndarray:
    """``np.clip`` (NaN stays NaN) without its per-call overhead."""
    return np.minimum(np.maximum(values, low), high)


def evaluate_element(g: Geometry, ds) -> Pose:
    """Evaluate one plan-view element at distances ``ds`` from its start."""
    return _EVALUATORS[type(g)](g, ds)


class ReferenceLine:
    """The plan view of one road. ``elements`` are sorted by start ``s`` (stable: a file whose elements are out of
    order still gets a defined answer; the geometry rules report the order), ``breakpoints`` are their starts."""

    def __init__(self, plan_view: Sequence[Geometry]):
        self.elements: tuple[Geometry, ...] = tuple(sorted(plan_view, key=lambda g: g.s))
        self.breakpoints = np.array([g.s for g in self.elements], dtype=float)
        self.lengths = np.array([max(g.length, 0.0) for g in self.elements], dtype=float)
        self.kinds = np.array(
            [_LINE if type(g) is Line else _ARC if type(g) is Arc else _PER_CALL for g in self.elements], dtype=np.int8
        )
        #: x, y, hdg and curvature (0 but for arcs) of each element's start
        self.starts = np.array(
            [(g.x, g.y, g.hdg, g.curvature if type(g) is Arc else 0.0) for g in self.elements], dtype=float
        ).reshape(-1, 4)

    @property
    def start(self) -> float:
        return float(self.breakpoints[0]) if self.elements else 0.0

    @property
    def end(self) -> float:
        return float(self.breakpoints[-1] + self.lengths[-1]) if self.elements else 0.0

    def element_index(self, s) -> np.ndarray:
        """Index of the element each ``s`` falls on (clamped to the first and last element)."""
        s = as_array(s)
        return _clamp(np.searchsorted(self.breakpoints, s, side="right") - 1, 0, len(self.elements) - 1)

    def evaluate(self, s) -> Pose:
        """Poses at absolute ``s`` (NaN everywhere when the plan view is empty)."""
        s = as_array(s)
        return poses([self], s, np.array([0, len(s)]))


def poses(lines: Sequence[ReferenceLine], s: np.ndarray, offsets: np.ndarray) -> Pose:
    """Poses of many blocks of ``s``: block ``k`` is ``s[offsets[k]:offsets[k + 1]]`` on ``lines[k]`` (NaN for a
    line without elements). Each block's numbers are :meth:`ReferenceLine.evaluate`'s of that block alone."""
    pose = Pose.empty(len(s))
    element, ds, table, elements = _locate(lines, s, offsets)
    if not len(table):
        return pose
    kinds = np.where(element >= 0, table[np.maximum(element, 0), 4], -1)
    starts = table[:, :4]
    at = np.flatnonzero(kinds == _LINE)
    if len(at):
        x0, y0, hdg, _ = starts[element[at]].T
        pose.assign(at, line.at(x0, y0, hdg, ds[at]))
    at = np.flatnonzero(kinds == _ARC)
    if len(at):
        x0, y0, hdg, k = starts[element[at]].T
        pose.assign(at, arc.at(x0, y0, hdg, k, ds[at]))
    at = np.flatnonzero(kinds == _PER_CALL)
    if len(at):
        _per_call(pose, elements, np.repeat(np.arange(len(lines)), np.diff(offsets))[at], element, ds, at)
    return pose


def _locate(
    lines: Sequence[ReferenceLine], s: np.ndarray, offsets: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[Geometry]]:
    """The element of each ``s`` (numbered over the distinct lines, in order of first use; -1 on a line without
    elements), its ``ds``, a table of every element's start x, y, hdg, curvature and kind, and the elements.
    Consecutive blocks on the same line are searched together (the search is elementwise)."""
    element = np.full(len(s), -1, dtype=np.int64)
    ds = np.full(len(s), np.nan)
    first: dict[int, int] = {}
    tables = []
    elements: list[Geometry] = []
    k = 0
    while k < len(lines):
        reference = lines[k]
        end = k + 1
        while end < len(lines) and lines[end] is reference:
            end += 1
        lo, hi = int(offsets[k]), int(offsets[end])
        k = end
        if not reference.elements or hi == lo:
            continue
        base = first.get(id(reference))
        if base is None:
            base = first[id(reference)] = len(elements)
            elements.extend(reference.elements)
            tables.append(np.column_stack((reference.starts, reference.kinds)))
        here = s[lo:hi]
        if len(reference.elements) == 1:
            index = np.zeros(hi - lo, dtype=np.int64)
        else:
            index = reference.element_index(_clamp(here, reference.start, reference.end))
        ds[lo:hi] = _clamp(here - reference.breakpoints[index], 0.0, reference.lengths[index])
        element[lo:hi] = base + index
    table = np.concatenate(tables) if tables else np.zeros((0, 5))
    return element, ds, table, elements


def _per_call(
    pose: Pose,
    elements: list[Geometry],
    block: np.ndarray,
    element: np.ndarray,
    ds: np.ndarray,
    at: np.ndarray,
) -> None:
    """Evaluate the points ``at`` (on spirals, poly3 and paramPoly3; ``block``: the block of each) one call per block
    and element, each call with its points in their order; the poly3 and paramPoly3 calls together (their
    ``evaluate_runs``)."""
    order = np.lexsort((element[at], block))  # stable: a call's points keep their order
    at, block = at[order], block[order]
    owner = element[at]
    cuts = np.flatnonzero((owner[1:] != owner[:-1]) | (block[1:] != block[:-1])) + 1
    bounds = np.concatenate(([0], cuts, [len(at)])).tolist()
    runs: dict[type, tuple[list, list[tuple[int, int]]]] = {ParamPoly3: ([], []), Poly3: ([], [])}
    for lo, hi in itertools.pairwise(bounds):
        g = elements[int(owner[lo])]
        if type(g) in runs:
            runs[type(g)][0].append(g)
            runs[type(g)][1].append((lo, hi))
        else:
            pose.assign(at[lo:hi], evaluate_element(g, ds[at[lo:hi]]))
    for kind, (curves, spans) in runs.items():
        if curves:
            inside = at[ranges([lo for lo, _ in spans], [hi - lo for lo, hi in spans])]
            counts = np.array([hi - lo for lo, hi in spans], dtype=np.int64)
            pose.assign(inside, _RUNS[kind](curves, ds[inside], counts))
