"""Points along every lane at a fixed step: lane centre lines and, on request, lane borders.

This is what ``xodrcheck sample`` writes; it is also the plainest way to hand a map's lanes to another program.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from xodrcheck.config import Tolerances
from xodrcheck.geometry.lanes import RoadGeometry, geometry_of, road_geometry
from xodrcheck.model import Document, lane_type_name

__all__ = ["KINDS", "LaneLine", "sample_count", "sample_lanes", "section_s_values"]


#: The lines of a lane that can be sampled: its centre, its border towards lane 0 and its border away from it.
KINDS = ("centre", "inner", "outer")


@dataclass(frozen=True, eq=False)
class LaneLine:
    """One sampled line of one lane; the arrays all have one entry per sample."""

    road: str
    section_s: float
    lane: int
    lane_type: str
    kind: str
    s: np.ndarray
    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    hdg: np.ndarray

    def __len__(self) -> int:
        return len(self.s)


def section_s_values(start: float, end: float, step: float, budget: int | None = None) -> np.ndarray:
    """``start``, then every ``step``, then ``end`` (a grid point that only rounding separates from ``end`` is left
    out, so the last interval is never a sliver of a few ulps). With a ``budget``, a section needing more steps than
    that is stepped by ``length / budget`` instead (bounded output on absurdly long sections; the ``s`` column shows
    it)."""
    if not (math.isfinite(step) and step > 0):
        raise ValueError(f"step must be a finite number > 0, got {step!r}")
    length = end - start
    if budget is not None and length / step > budget:
        step = length / max(budget, 1)
    count = math.ceil(length / step) if length > 0 else 0
    grid = start + step * np.arange(count, dtype=float)
    grid = grid[grid < end - length * 1e-12]
    return np.concatenate([grid if count else [start], [end]])


def sample_count(document: Document, step: float, kinds: Sequence[str] = ("centre",)) -> float:
    """How many points :func:`sample_lanes` gives at ``step`` without a per-section bound (a float: absurd steps give
    counts past any integer type; lanes a ``singleSide`` section continues are not counted). Costs no geometry."""
    total = 0.0
    for road in document.roads:
        if not road.plan_view:
            continue
        for index, section in enumerate(road.lane_sections):
            length = road.section_end(index) - section.s
            if not length > 0:
                continue
            lanes = sum(1 for lane in (*section.left, *section.right) if lane.id != 0)
            total += lanes * len(kinds) * (math.ceil(length / step) + 1)
    return total


def sample_lanes(
    document: Document,
    step: float,
    kinds: Sequence[str] = ("centre",),
    geometry: Mapping[str, RoadGeometry] | None = None,
    budget: int | None = None,
) -> Iterator[LaneLine]:
    """Sample every lane (centre lanes excluded) of every road that has a plan view.

    Roads in file order, lane sections in order, lanes from the leftmost to the rightmost, ``kinds`` in the order given.
    A ``singleSide`` section also yields the lanes its other side continues from an earlier section. A lane section that
    does not end after it starts (the reader reports such sections) is skipped. A section that needs more than
    ``budget`` points per line (default ``Tolerances.max_samples_per_section``) is stepped more coarsely: the command
    line refuses such steps beforehand (:func:`sample_count`) and passes its own bound.
    """
    unknown = [k for k in kinds if k not in KINDS]
    if unknown:
        raise ValueError(f"unknown kind(s) {', '.join(unknown)}; known: {', '.join(KINDS)}")
    if not (math.isfinite(step) and step > 0):
        raise ValueError(f"step must be a finite number > 0, got {step!r}")
    geometry = geometry_of(document) if geometry is None else geometry
    budget = Tolerances().max_samples_per_section if budget is None else budget
    for road in document.roads:
        if not road.plan_view:
            continue
        rg = road_geometry(geometry, road)
        for index, section in enumerate(road.lane_sections):
            end = road.section_end(index)
            if not end > section.s:
                continue
            s = section_s_values(section.s, end, step, budget)
            left, right = rg.side_lanes(index)  # the lanes in effect (a singleSide section keeps the other side's)
            for lane in (*reversed(left.lanes), *right.lanes):
                for kind in kinds:
                    p = rg.lane_points(index, lane.id, s, where=kind)
                    yield LaneLine(road.id, section.s, lane.id, lane_type_name(lane), kind, s, p.x, p.y, p.z, p.hdg)
