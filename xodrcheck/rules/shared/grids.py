"""The sampling grids of many lane sections at once (:func:`.sampled.section_samples`): every section's
knots end to end in one array, the even steps between them in a few numpy calls over all sections.

The arithmetic per element is :func:`xodrcheck.rules.shared.sampled._grid`'s, so the grids are the same to the last bit:
step counts are ``ceil(length / step)`` elementwise (a section whose counts pass the sample budget is counted alone,
:func:`xodrcheck.geometry.sampling.step_counts`); the samples are ``cut + length * offset / count`` elementwise; each
grid ends with ``left_of(end)``, and a grid that is not already non-decreasing is made so by
``np.maximum.accumulate`` alone.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from xodrcheck.config import Tolerances
from xodrcheck.geometry.lanes import RoadGeometry
from xodrcheck.geometry.sampling import raw_counts, step_counts
from xodrcheck.rules.shared.road_ends import left_of

#: Knot intervals counted together: it bounds a batch's temporaries (they scale with its samples, a few arrays of
#: them).
BATCH_INTERVALS = 1 << 14


def section_grids(tol: Tolerances, entries: Sequence[tuple[RoadGeometry, int]], step: float) -> list[np.ndarray]:
    """``_grid`` of each (geometry, section index) with the longest step ``step`` (``sampled.grid_step``)."""
    out: list[np.ndarray] = []
    cuts: list[np.ndarray] = []
    ends: list[float] = []
    pending = 0
    for geometry, index in entries:
        start, end = geometry.section_range(index)
        if not end > start:
            out.extend(knot_grids(cuts, ends, step, tol.max_samples_per_section))
            cuts, ends, pending = [], [], 0
            out.append(np.array([start], dtype=float))
            continue
        cuts.append(geometry.knots(index))
        ends.append(left_of(end))
        pending += len(cuts[-1])
        if pending >= BATCH_INTERVALS:
            out.extend(knot_grids(cuts, ends, step, tol.max_samples_per_section))
            cuts, ends, pending = [], [], 0
    out.extend(knot_grids(cuts, ends, step, tol.max_samples_per_section))
    return out


def knot_grids(cuts: list[np.ndarray], ends: list[float], step: float, budget: int | None) -> list[np.ndarray]:
    """The grids of sections with knots ``cuts`` (two or more each) and last samples ``ends``, each section's steps
    within ``budget`` (``None``: unbounded): the kernel of :func:`section_grids`, all sections in a few numpy calls.
    It takes any knots, so its repairs (a falling grid made non-decreasing, a NaN spreading) can be tested alone."""
    if not cuts:
        return []
    sizes = np.array([len(c) for c in cuts], dtype=np.int64)
    flat = np.concatenate(cuts)
    lengths_all = np.diff(flat)
    last = np.cumsum(sizes) - 1  # each section's last knot: its interval to the next section's first is dropped
    keep = np.ones(len(lengths_all), dtype=bool)
    keep[last[:-1]] = False
    lengths, starts = lengths_all[keep], flat[:-1][keep]
    intervals = sizes - 1
    counts = raw_counts(lengths, step)
    first = np.cumsum(intervals) - intervals
    if budget is not None:
        for over in np.flatnonzero(np.add.reduceat(counts, first) > budget):  # rare: counted alone, scaled down
            lo, hi = int(first[over]), int(first[over] + intervals[over])
            counts[lo:hi] = step_counts(lengths[lo:hi], step, budget)
    counts = counts.astype(np.int64)
    owner = np.repeat(np.arange(len(counts)), counts)
    offset = np.arange(owner.size) - np.repeat(np.cumsum(counts) - counts, counts)
    inner = starts[owner] + lengths[owner] * offset / counts[owner]
    per_section = np.add.reduceat(counts, first)
    # each section's samples then its end: the end of section k goes after its own samples
    total = per_section + 1
    s = np.empty(int(total.sum()))
    tail = np.cumsum(total) - 1
    body = np.ones(len(s), dtype=bool)
    body[tail] = False
    s[body] = inner
    s[tail] = np.asarray(ends, dtype=float)
    bounds = np.concatenate(([0], np.cumsum(total)))
    falls = np.flatnonzero(s[1:] < s[:-1]) + 1  # a sample below the one before it, within a section or across
    section = np.searchsorted(bounds, falls, side="right") - 1
    fix = set(section[bounds[section] != falls].tolist())  # falls within a section
    fix.update((np.searchsorted(bounds, np.flatnonzero(~np.isfinite(s)), side="right") - 1).tolist())  # NaN spreads
    out = []
    for k in range(len(cuts)):
        grid = s[bounds[k] : bounds[k + 1]]
        out.append(np.maximum.accumulate(grid) if k in fix else grid.copy())
    return out
