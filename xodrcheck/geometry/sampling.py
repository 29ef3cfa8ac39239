"""Adaptive ``s`` sampling of lane sections under a chord tolerance, many sections at once.

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

:func:`sample_sections` samples many sections together: their knots, steps and probes lie end to end in flat arrays,
the probes are evaluated in one batch (:class:`~xodrcheck.geometry.batch.Evaluation`), and every step is elementwise
or per section (step counts, sorting), so each section's samples are those it gets alone.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from xodrcheck.geometry.batch import Evaluation, SectionRows

_PROBE_INSET = 1e-7  # relative inset of the end probes, so each probes the piece it belongs to
_MAX_COUNT = 2.0**53  # more steps than this over one piece cannot be told apart in s


def _subdivide(starts: np.ndarray, lengths: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """Left ends of ``counts[i]`` equal steps over each ``[starts[i], starts[i] + lengths[i]]``."""
    owner = np.repeat(np.arange(len(starts)), counts)
    index = np.arange(owner.size) - np.repeat(np.cumsum(counts) - counts, counts)
    return starts[owner] + lengths[owner] * index / counts[owner]


def raw_counts(lengths: np.ndarray, step) -> np.ndarray:
    """``ceil(length / step)``, 1 where that is below 1, beyond ``2**53`` (a damaged section, astronomically long: its
    steps would be below the resolution of its ``s``) or not a number."""
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        counts = np.ceil(lengths / step)
    return np.where((counts >= 1) & (counts <= _MAX_COUNT), counts, 1)


def step_counts(lengths: np.ndarray, step, budget: int | None = None) -> np.ndarray:
    """Number of equal steps of at most ``step`` covering each length (at least 1; see :func:`raw_counts`).

    With a ``budget``, counts whose total exceeds it are scaled down together (each kept at least 1), so the total stays
    within ``budget`` plus the number of lengths: the steps then exceed ``step``."""
    counts = raw_counts(lengths, step)
    if budget is not None and counts.sum() > budget:
        counts = np.maximum(np.floor(counts * (max(budget, 1) / counts.sum())), 1)
    return counts.astype(np.int64)


def capped(lengths: np.ndarray, step, budget: int) -> bool:
    """Whether :func:`step_counts` of ``lengths`` at ``step`` goes over ``budget`` (and so takes longer steps)."""
    return bool(step_counts(lengths, step).sum() > budget)


def _counts(lengths: np.ndarray, step, owner: np.ndarray, sections: int, budget: int | None) -> np.ndarray:
    """:func:`step_counts` of the pieces of several sections (``owner``: the section of each piece), the budget
    applied per section; a section whose total is too large to sum exactly is counted alone."""
    counts = raw_counts(lengths, step)
    if budget is None:
        return counts.astype(np.int64)
    totals = np.bincount(owner, weights=counts, minlength=sections)
    over = totals > budget
    if over.any():
        factor = np.ones(sections)
        factor[over] = max(budget, 1) / totals[over]
        counts = np.where(over[owner], np.maximum(np.floor(counts * factor[owner]), 1), counts)
    for k in np.flatnonzero(totals > 2.0**52):  # beyond exact sums: the section's own count
        mine = owner == k
        counts[mine] = step_counts(lengths[mine], step if np.ndim(step) == 0 else step[mine], budget)
    return counts.astype(np.int64)


def _unique_per_section(values: np.ndarray, owner: np.ndarray, sections: int) -> list[np.ndarray]:
    """``np.unique`` of each section's values (``owner``: the section of each)."""
    order = np.lexsort((values, owner))
    ordered, owners = values[order], owner[order]
    keep = np.ones(len(ordered), dtype=bool)
    keep[1:] = (ordered[1:] != ordered[:-1]) | (owners[1:] != owners[:-1])
    out = np.split(ordered[keep], np.cumsum(np.bincount(owners[keep], minlength=sections))[:-1])
    # np.unique's own choice between -0.0 and 0.0 (which depends on the values' order) and its one NaN: asked of it
    odd = ~np.isfinite(values) | ((values == 0) & np.signbit(values))
    for k in set(owner[odd].tolist()):
        out[k] = np.unique(values[owner == k])
    return out


def sample_sections(
    blocks: Sequence[tuple[SectionRows, np.ndarray]], chord: float, max_step: float, budget: int | None
) -> list[np.ndarray]:
    """Sorted ``s`` covering each section (given with its knots: ends and every knot included) with border chord
    error below ``chord``, at most about ``2 * budget`` of them plus the knots (each stage within ``budget``;
    ``None``: no bound). A section with fewer than two knots gets its knots."""
    if not chord > 0 or not max_step > 0:
        raise ValueError(f"chord and max_step must be > 0, got {chord} and {max_step}")
    out = [cuts for _, cuts in blocks]
    full = [k for k, (_, cuts) in enumerate(blocks) if len(cuts) >= 2]
    if full:
        found = _sample([blocks[k] for k in full], chord, max_step, budget)
        for k, s in zip(full, found):
            out[k] = s
    return out


def _sample(
    blocks: Sequence[tuple[SectionRows, np.ndarray]], chord: float, max_step: float, budget: int | None
) -> list[np.ndarray]:
    """:func:`sample_sections` of sections with at least two knots each."""
    m = len(blocks)
    flat = np.concatenate([cuts for _, cuts in blocks])
    sizes = np.array([len(cuts) for _, cuts in blocks], dtype=np.int64)
    last = np.cumsum(sizes) - 1
    is_left = np.ones(len(flat), dtype=bool)
    is_left[last] = False
    piece = np.flatnonzero(is_left)  # the left cut of each piece
    piece_owner = np.repeat(np.arange(m), sizes - 1)
    lengths = flat[piece + 1] - flat[piece]
    counts = _counts(lengths, max_step, piece_owner, m, budget)
    coarse = _subdivide(flat[piece], lengths, counts)
    coarse_owner = np.repeat(piece_owner, counts)
    per_section = np.bincount(coarse_owner, minlength=m)
    coarse_ends = np.empty_like(coarse)
    coarse_ends[:-1] = coarse[1:]
    coarse_ends[np.cumsum(per_section) - 1] = flat[last]
    steps = coarse_ends - coarse
    inset = _PROBE_INSET * steps
    columns = np.empty((len(coarse), 3))
    columns[:, 0] = coarse + inset
    columns[:, 1] = coarse + 0.5 * steps
    columns[:, 2] = coarse_ends - inset
    probes = np.split(columns.ravel(), np.cumsum(3 * per_section)[:-1])

    evaluation = Evaluation([rows for rows, _ in blocks], probes)
    bending = np.fmax(evaluation.bending(), np.abs(evaluation.elevation_jet[2]))
    bending = np.nan_to_num(bending.reshape(-1, 3).max(axis=1), nan=0.0, posinf=np.inf)

    # 8 chord / bending, infinite where nothing bends.
    ratio = np.divide(8.0 * chord, bending, out=np.full_like(bending, np.inf), where=bending != 0)
    allowed = np.maximum(np.sqrt(ratio), 2.0 * chord)
    counts = _counts(steps, allowed, coarse_owner, m, budget)
    fine = np.concatenate([_subdivide(coarse, steps, counts), flat[last]])
    fine_owner = np.concatenate([np.repeat(coarse_owner, counts), np.arange(m)])
    return _unique_per_section(fine, fine_owner, m)
