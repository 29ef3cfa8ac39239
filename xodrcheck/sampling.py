"""Adaptive ``s`` sampling of a lane section under a chord tolerance.

The section is first cut at every point where some curve may change its law: the section ends, plan-view element
joints, laneOffset, elevation and superelevation record starts, and the width/border record starts of the lanes in
effect. Each piece is split into steps of at most ``max_step``; on each step the largest absolute curvature of the
reference line, of every lane border in plan view (offset curves, width change included; scaled by the square of the
border's length per metre of ``s``, since an outer border is longer than the reference line) and of the elevation is
probed just inside both ends and in the middle, and the step is divided evenly so that the sagitta
``curvature * h^2 / 8`` of every border polyline stays under ``chord``. (Where a profile jumps, as a laneOffset
record that does not continue its predecessor, the polyline has a knot at the jump but cannot follow it.) A step never
needs to be shorter than
``2 * chord`` (no arc strays further than half its length from its chord), which also bounds the work near cusps.

Each stage keeps at most about ``budget`` samples per section (``Tolerances.max_samples_per_section``): past it the
steps of the stage grow in proportion so that an absurdly long section (a road of 1e12 m) or an absurd bend (a lane
1e9 m wide on a curve) costs bounded time and memory. Below the budget nothing changes; rule ``G013``
(``sampling-capped``) reports the sections whose checker grid is capped.
"""

from __future__ import annotations

import weakref
from typing import TYPE_CHECKING

import numpy as np

from xodrcheck.geometry import profile

if TYPE_CHECKING:
    from xodrcheck.lanes import RoadGeometry

_PROBE_INSET = 1e-7  # relative inset of the end probes, so each probes the piece it belongs to
_MAX_COUNT = 2.0**53  # more steps than this over one piece cannot be told apart in s


_KNOTS: weakref.WeakKeyDictionary[RoadGeometry, dict[int, np.ndarray]] = weakref.WeakKeyDictionary()


def knots(geometry: RoadGeometry, section_index: int) -> np.ndarray:
    """Sorted unique ``s`` where the section's curves may change their law (including the section ends)."""
    per_section = _KNOTS.get(geometry)
    if per_section is None:
        per_section = _KNOTS[geometry] = {}
    found = per_section.get(section_index)
    if found is None:
        found = per_section[section_index] = _knots(geometry, section_index)
    return found.copy()  # callers own their array


def _knots(geometry: RoadGeometry, section_index: int) -> np.ndarray:
    road = geometry.road
    s0, s1 = geometry.section_range(section_index)
    candidates = [
        np.array([s0, s1]),
        geometry.reference_line.breakpoints,
        profile.breakpoints(road.lane_offset),
        profile.breakpoints(road.elevation),
        profile.breakpoints(road.superelevation),
    ]
    for side in geometry.side_lanes(section_index):
        candidates.extend(law.starts for law in side.laws if law is not None)
    points = np.concatenate(candidates)
    return np.unique(points[(points >= s0) & (points <= s1)])


def _subdivide(starts: np.ndarray, lengths: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """Left ends of ``counts[i]`` equal steps over each ``[starts[i], starts[i] + lengths[i]]``."""
    owner = np.repeat(np.arange(len(starts)), counts)
    index = np.arange(owner.size) - np.repeat(np.cumsum(counts) - counts, counts)
    return starts[owner] + lengths[owner] * index / counts[owner]


def step_counts(lengths: np.ndarray, step, budget: int | None = None) -> np.ndarray:
    """Number of equal steps of at most ``step`` covering each length (at least 1). A count beyond ``2**53`` (a damaged
    section, astronomically long: its steps would be below the resolution of its ``s``) or not a number gives 1.

    With a ``budget``, counts whose total exceeds it are scaled down together (each kept at least 1), so the total stays
    within ``budget`` plus the number of lengths: the steps then exceed ``step``."""
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        counts = np.ceil(lengths / step)
    counts = np.where((counts >= 1) & (counts <= _MAX_COUNT), counts, 1)
    if budget is not None and counts.sum() > budget:
        counts = np.maximum(np.floor(counts * (max(budget, 1) / counts.sum())), 1)
    return counts.astype(np.int64)


def capped(lengths: np.ndarray, step, budget: int) -> bool:
    """Whether :func:`step_counts` of ``lengths`` at ``step`` goes over ``budget`` (and so takes longer steps)."""
    return bool(step_counts(lengths, step).sum() > budget)


def sample_section(
    geometry: RoadGeometry, section_index: int, chord: float, max_step: float, budget: int | None = None
) -> np.ndarray:
    """Sorted ``s`` covering the section (ends and every knot included) with border chord error below ``chord``, at
    most about ``2 * budget`` of them plus the knots (each stage within ``budget``; ``None``: no bound)."""
    if not chord > 0 or not max_step > 0:
        raise ValueError(f"chord and max_step must be > 0, got {chord} and {max_step}")
    cuts = knots(geometry, section_index)
    if len(cuts) < 2:
        return cuts
    lengths = np.diff(cuts)
    coarse = _subdivide(cuts[:-1], lengths, step_counts(lengths, max_step, budget))
    coarse_ends = np.append(coarse[1:], cuts[-1])
    steps = coarse_ends - coarse
    inset = _PROBE_INSET * steps
    columns = np.empty((len(coarse), 3))
    columns[:, 0] = coarse + inset
    columns[:, 1] = coarse + 0.5 * steps
    columns[:, 2] = coarse_ends - inset
    probes = columns.ravel()

    bending = geometry.border_bending(section_index, probes)
    bending = np.fmax(bending, np.abs(profile.second_derivative(geometry.road.elevation, probes)))
    bending = np.nan_to_num(bending.reshape(-1, 3).max(axis=1), nan=0.0, posinf=np.inf)

    # 8 chord / bending, infinite where nothing bends.
    ratio = np.divide(8.0 * chord, bending, out=np.full_like(bending, np.inf), where=bending != 0)
    allowed = np.maximum(np.sqrt(ratio), 2.0 * chord)
    fine = _subdivide(coarse, steps, step_counts(steps, allowed, budget))
    return np.unique(np.append(fine, cuts[-1]))
