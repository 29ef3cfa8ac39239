"""A road's reference line: its plan-view elements evaluated at absolute ``s``, vectorised.

Each ``s`` is assigned to the last element whose start ``s`` is at or before it (a binary search over the element
starts, so a point exactly on a joint belongs to the element that starts there), then every element evaluates its
own points in one call. ``s`` outside ``[first start, last end]`` is clamped to that range, and ``ds`` is clamped to
the element's ``[0, length]``: gaps and overlaps between elements are the geometry rules' business, not a reason for
extrapolated points.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from xodrcheck.geometry import arc, line, parampoly3, poly3, spiral
from xodrcheck.geometry.pose import Pose, as_array
from xodrcheck.model import Arc, Geometry, Line, ParamPoly3, Poly3, Spiral

_EVALUATORS: dict[type, Callable[..., Pose]] = {
    Line: line.evaluate,
    Arc: arc.evaluate,
    Spiral: spiral.evaluate,
    Poly3: poly3.evaluate,
    ParamPoly3: parampoly3.evaluate,
}


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
        self._lengths = np.array([max(g.length, 0.0) for g in self.elements], dtype=float)

    @property
    def start(self) -> float:
        return float(self.breakpoints[0]) if self.elements else 0.0

    @property
    def end(self) -> float:
        return float(self.breakpoints[-1] + self._lengths[-1]) if self.elements else 0.0

    def element_index(self, s) -> np.ndarray:
        """Index of the element each ``s`` falls on (clamped to the first and last element)."""
        s = as_array(s)
        return _clamp(np.searchsorted(self.breakpoints, s, side="right") - 1, 0, len(self.elements) - 1)

    def evaluate(self, s) -> Pose:
        """Poses at absolute ``s`` (NaN everywhere when the plan view is empty)."""
        s = as_array(s)
        if not self.elements or len(s) == 0:
            return Pose.empty(len(s))
        if len(self.elements) == 1:
            return evaluate_element(self.elements[0], _clamp(s - self.breakpoints[0], 0.0, self._lengths[0]))
        index = self.element_index(_clamp(s, self.start, self.end))
        ds = _clamp(s - self.breakpoints[index], 0.0, self._lengths[index])
        changes = np.flatnonzero(index[1:] != index[:-1]) + 1
        if len(changes) == 0:
            return evaluate_element(self.elements[index[0]], ds)
        pose = Pose.empty(len(s))
        if len(changes) < len(self.elements) and (index[changes] > index[changes - 1]).all():
            # Sorted s (the usual case): each element owns one contiguous run.
            bounds = np.concatenate(([0], changes, [len(s)]))
            for lo, hi in zip(bounds[:-1].tolist(), bounds[1:].tolist()):
                pose.assign(slice(lo, hi), evaluate_element(self.elements[index[lo]], ds[lo:hi]))
            return pose
        for i in np.unique(index):
            mask = index == i
            pose.assign(mask, evaluate_element(self.elements[i], ds[mask]))
        return pose
