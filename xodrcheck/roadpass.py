"""All lane sections of a file in one pass: adaptive sampling (:func:`xodrcheck.sampling.sample_section`) and lane
border lines (:meth:`xodrcheck.lanes.RoadGeometry.border_curves`) for every section at once, on flat arrays.

The per-section code pays numpy's call overhead once per section and stage (a few hundred calls); here the samples of
all sections lie end to end in one array, each border line of a section is a block of "pairs" (line, sample), and
each step is one numpy call over all of them (the reference line: one call per road). The arithmetic per element is
the per-section code's, operation for operation, so the results are the same to the last bit:

* knots, step counts and the final sorted samples are the per-section ones (sums of whole numbers are exact; sorting
  by section then value and dropping repeats is ``np.unique`` per section);
* profiles (laneOffset, elevation, lane widths and borders) are evaluated elementwise with the same formulas, the
  record in force found by counting starts at or before ``s``, as :class:`~xodrcheck.geometry.profile.Batch`;
* border jets accumulate outward lane by lane (one array step per lane depth over all sections and sides), and the
  plan-view lateral offset of each line as ``inner line + (outer - inner)``, as
  :func:`xodrcheck.lane_lines.border_lines`;
* the reference line is evaluated element run by element run; elements whose evaluation depends on the whole batch
  of points (spirals, poly3, paramPoly3: series lengths and Newton iterations are chosen per call) are evaluated once
  per section, with exactly the points the per-section code gives them;
* reductions are exact (``fmax``, ``max``).

Sections this pass does not cover exactly are left to the per-section code (:func:`covered` says which): roads with
superelevation, sections with a duplicated lane id; a pass whose samples are not finite or not sorted (damaged input)
returns ``None``.

The reference-line poses are :mod:`xodrcheck.roadpass_pose`'s, the profiles and the border lines' lateral jets
:mod:`xodrcheck.roadpass_lines`'s; this module samples the sections and places their lines.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from xodrcheck.geometry import profile
from xodrcheck.lanes import RoadGeometry
from xodrcheck.roadpass_lines import Laws, bend, lateral_lines
from xodrcheck.roadpass_pose import Entry, poses
from xodrcheck.sampling import _MAX_COUNT, _PROBE_INSET, knots


def covered(rg: RoadGeometry, index: int) -> bool:
    """Whether this pass evaluates the section exactly: no superelevation on its road (no roll anywhere) and no lane
    id twice."""
    if len(rg._roll.starts):
        return False
    left, right = rg.side_lanes(index)
    ids = [0, *(lane.id for lane in left.lanes), *(lane.id for lane in right.lanes)]
    return len(set(ids)) == len(ids)


def _by_section_then_value(values: np.ndarray, owner: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Sorted unique values per owner (``np.unique`` of each owner's values), as flat values and owners."""
    order = np.lexsort((values, owner))
    values, owner = values[order], owner[order]
    keep = np.ones(len(values), dtype=bool)
    keep[1:] = (values[1:] != values[:-1]) | (owner[1:] != owner[:-1])
    return values[keep], owner[keep]


# ------------------------------------------------------------------------------------------------------ sampling
def _counts(lengths: np.ndarray, step, owner: np.ndarray, sections: int, budget: int | None) -> np.ndarray | None:
    """:func:`xodrcheck.sampling.step_counts` for the pieces of several sections (``owner``: section of each piece),
    the budget applied per section. ``None`` when a section's total is too large to sum exactly."""
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        counts = np.ceil(lengths / step)
    counts = np.where((counts >= 1) & (counts <= _MAX_COUNT), counts, 1)
    if budget is not None:
        totals = np.bincount(owner, weights=counts, minlength=sections)
        if (totals > 2.0**52).any():
            return None
        over = totals > budget
        if over.any():
            factor = np.ones(sections)
            factor[over] = max(budget, 1) / totals[over]
            counts = np.where(over[owner], np.maximum(np.floor(counts * factor[owner]), 1), counts)
    return counts.astype(np.int64)


def _subdivide(starts: np.ndarray, lengths: np.ndarray, counts: np.ndarray) -> np.ndarray:
    owner = np.repeat(np.arange(len(starts)), counts)
    index = np.arange(owner.size) - np.repeat(np.cumsum(counts) - counts, counts)
    return starts[owner] + lengths[owner] * index / counts[owner]


def _knots(entries: Sequence[Entry]) -> tuple[np.ndarray, np.ndarray]:
    """:func:`xodrcheck.sampling.knots` of every entry, as flat values and the entry of each."""
    parts, owners = [], []
    road_level: dict[int, np.ndarray] = {}
    for rg, index in entries:
        shared = road_level.get(id(rg))
        if shared is None:
            road = rg.road
            shared = road_level[id(rg)] = np.concatenate(
                [
                    rg.reference_line.breakpoints,
                    profile.breakpoints(road.lane_offset),
                    profile.breakpoints(road.elevation),
                    profile.breakpoints(road.superelevation),
                ]
            )
        own = [law.starts for side in rg.side_lanes(index) for law in side.laws if law is not None]
        s0, s1 = rg.section_range(index)
        part = np.concatenate([np.array([s0, s1]), shared, *own])
        parts.append(part)
        owners.append(len(part))
    values = np.concatenate(parts)
    owner = np.repeat(np.arange(len(entries)), owners)
    section_ranges = np.array([rg.section_range(index) for rg, index in entries], dtype=float).reshape(-1, 2)
    inside = (values >= section_ranges[owner, 0]) & (values <= section_ranges[owner, 1])
    values, owner = _by_section_then_value(values[inside], owner[inside])
    zero = (values == 0) & np.signbit(values)
    if zero.any():  # -0.0 beside 0.0: np.unique's choice between them is the per-section code's; ask it
        bad = set(owner[zero].tolist())
        keep = ~np.isin(owner, list(bad))
        extra = [(knots(*entries[k]), k) for k in sorted(bad)]
        values = np.concatenate([values[keep], *(v for v, _ in extra)])
        owner = np.concatenate([owner[keep], *(np.full(len(v), k) for v, k in extra)])
        order = np.argsort(owner, kind="stable")
        values, owner = values[order], owner[order]
    return values, owner


def sample_sections(
    entries: Sequence[Entry], chord: float, max_step: float, budget: int | None
) -> list[np.ndarray] | None:
    """``sample_section(rg, k, chord, max_step, budget)`` of every entry (each :func:`covered`), computed together;
    ``None`` when some samples are not finite or not sorted (see the module docstring). A section with fewer than
    two knots gets its knots, as ``sample_section`` gives them."""
    if not chord > 0 or not max_step > 0:
        raise ValueError(f"chord and max_step must be > 0, got {chord} and {max_step}")
    if not entries:
        return []
    flat, cut_owner = _knots(entries)
    cut_counts = np.bincount(cut_owner, minlength=len(entries))
    short = cut_counts < 2
    if not short.any():
        return _sample(entries, flat, cut_owner, cut_counts, chord, max_step, budget)
    out: list[np.ndarray] = np.split(flat, np.cumsum(cut_counts)[:-1])
    keep = np.flatnonzero(~short)
    renumber = np.cumsum(~short) - 1
    inside = ~short[cut_owner]
    found = _sample(
        [entries[k] for k in keep.tolist()],
        flat[inside],
        renumber[cut_owner[inside]],
        cut_counts[keep],
        chord,
        max_step,
        budget,
    )
    if found is None:
        return None
    for k, s in zip(keep.tolist(), found):
        out[k] = s
    return out


def _sample(
    entries: Sequence[Entry],
    flat: np.ndarray,
    cut_owner: np.ndarray,
    cut_counts: np.ndarray,
    chord: float,
    max_step: float,
    budget: int | None,
) -> list[np.ndarray] | None:
    """:func:`sample_sections` of entries with at least two knots each (``flat``: their knots, entry by entry)."""
    m = len(entries)
    if m == 0:
        return []
    last = np.cumsum(cut_counts) - 1
    is_left = np.ones(len(flat), dtype=bool)
    is_left[last] = False
    piece = np.flatnonzero(is_left)  # the left cut of each piece
    piece_owner = cut_owner[piece]
    lengths = flat[piece + 1] - flat[piece]
    counts = _counts(lengths, max_step, piece_owner, m, budget)
    if counts is None:
        return None
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
    probes = columns.ravel()
    if not np.isfinite(probes).all():
        return None
    offsets = np.concatenate(([0], np.cumsum(3 * per_section)))
    bending = _bending(entries, probes, offsets)
    if bending is None:
        return None
    bending = np.nan_to_num(bending.reshape(-1, 3).max(axis=1), nan=0.0, posinf=np.inf)
    ratio = np.divide(8.0 * chord, bending, out=np.full_like(bending, np.inf), where=bending != 0)
    allowed = np.maximum(np.sqrt(ratio), 2.0 * chord)
    counts = _counts(steps, allowed, coarse_owner, m, budget)
    if counts is None:
        return None
    fine = np.concatenate([_subdivide(coarse, steps, counts), flat[last]])
    fine_owner = np.concatenate([np.repeat(coarse_owner, counts), np.arange(m)])
    values, owner = _by_section_then_value(fine, fine_owner)
    return np.split(values, np.cumsum(np.bincount(owner, minlength=m))[:-1])


def _bending(entries: Sequence[Entry], s: np.ndarray, offsets: np.ndarray) -> np.ndarray | None:
    """:meth:`RoadGeometry.border_bending` of each entry at its probes, then the elevation's second derivative
    (``sample_section``'s bound before the per-step maximum)."""
    pose = poses(entries, s, offsets)
    if pose is None:
        return None
    lines = lateral_lines(entries, s, offsets)
    speed, curvature = bend(lines, pose)
    most = np.full(len(s), np.nan)
    np.fmax.at(most, lines.sample, np.abs(curvature) * speed**2)
    bending = np.fmax(np.abs(pose.curvature), most)
    elevation = Laws()
    counts = np.diff(offsets)
    for k, (rg, _) in enumerate(entries):
        elevation.add(profile.compiled(rg.road.elevation), int(offsets[k]), int(offsets[k]), int(counts[k]))
    return np.fmax(bending, np.abs(elevation.evaluate(s, len(s))[2]))


# ------------------------------------------------------------------------------------------------------ border lines
@dataclass
class Borders:
    """Every border line of every entry at its samples (positions of :meth:`RoadGeometry.border_curves`): entry
    ``k`` has lines ``ids[k]``, its pairs ``base[k]:base[k] + len(ids[k]) * n_k`` (line after line) in ``x``, ``y``,
    ``z``."""

    ids: list[list[int]]
    base: np.ndarray
    offsets: np.ndarray
    s: np.ndarray
    x: np.ndarray
    y: np.ndarray
    z: np.ndarray


def border_lines(entries: Sequence[Entry], samples: Sequence[np.ndarray]) -> Borders | None:
    """The border lines of each entry at its samples (sorted and finite); ``None`` when not covered exactly."""
    if not entries:
        empty = np.zeros(0)
        return Borders([], np.zeros(0, dtype=np.int64), np.zeros(1, dtype=np.int64), empty, empty, empty, empty)
    counts = np.array([len(s) for s in samples], dtype=np.int64)
    offsets = np.concatenate(([0], np.cumsum(counts)))
    s = np.concatenate(samples) if len(samples) else np.zeros(0)
    pose = poses(entries, s, offsets)
    if pose is None:
        return None
    lines = lateral_lines(entries, s, offsets)
    elevation = Laws()
    for k, (rg, _) in enumerate(entries):
        elevation.add(rg._elevation, int(offsets[k]), int(offsets[k]), int(counts[k]))
    z = elevation.evaluate(s, len(s))[0] + 0.0  # the height above the elevation is 0.0 without superelevation
    at, q = lines.sample, lines.q
    x = pose.x[at] - q * np.sin(pose.hdg)[at]
    y = pose.y[at] + q * np.cos(pose.hdg)[at]
    return Borders(lines.ids, lines.base, offsets, s, x, y, z[at])


# ------------------------------------------------------------------------------------------------------ lane points
def section_borders(entries: Sequence[Entry], samples: Sequence[np.ndarray]) -> list[dict[int, np.ndarray]]:
    """:meth:`RoadGeometry.borders` of every entry (each :func:`covered`) at its samples (finite, in any order): ``t``
    of each lane's outer border and of lane 0's line, without the reference line."""
    counts = [len(s) for s in samples]
    offsets = np.concatenate(([0], np.cumsum(counts))).astype(np.int64)
    lines = lateral_lines(entries, np.concatenate(samples) if samples else np.zeros(0), offsets)
    out = []
    for k, ids in enumerate(lines.ids):
        lo, n = int(lines.base[k]), counts[k]
        rows = lines.outer[0][lo : lo + len(ids) * n].reshape(len(ids), n)
        out.append({lane_id: rows[j].copy() for j, lane_id in enumerate(ids)})
    return out


@dataclass
class SectionPoints:
    """One section's lines at its samples, as the per-section code gives them: ``t`` of each line
    (:meth:`RoadGeometry.borders`), the reference line's curvature, and the plan-view points of each line
    (:meth:`RoadGeometry.border_curves`: rows of ``x``, ``y``, ``z``, ``hdg``, ``curvature``, ``speed`` per lane id)."""

    ids: list[int]
    t: np.ndarray
    reference_curvature: np.ndarray
    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    hdg: np.ndarray
    curvature: np.ndarray
    speed: np.ndarray


def section_points(entries: Sequence[Entry], samples: Sequence[np.ndarray]) -> list[SectionPoints] | None:
    """:class:`SectionPoints` of every entry (each :func:`covered`) at its samples (sorted, finite); ``None`` when
    not covered exactly."""
    if not entries:
        return []
    counts = np.array([len(s) for s in samples], dtype=np.int64)
    offsets = np.concatenate(([0], np.cumsum(counts)))
    s = np.concatenate(samples)
    pose = poses(entries, s, offsets)
    if pose is None:
        return None
    lines = lateral_lines(entries, s, offsets)
    elevation = Laws()
    for k, (rg, _) in enumerate(entries):
        elevation.add(rg._elevation, int(offsets[k]), int(offsets[k]), int(counts[k]))
    z = (elevation.evaluate(s, len(s))[0] + 0.0)[lines.sample]
    at, q, dq = lines.sample, lines.q, lines.dq
    x = pose.x[at] - q * np.sin(pose.hdg)[at]
    y = pose.y[at] + q * np.cos(pose.hdg)[at]
    speed, curvature = bend(lines, pose)
    a = 1.0 - q * pose.curvature[at]
    hdg = pose.hdg[at] + np.arctan2(dq, a)
    out = []
    for k, ids in enumerate(lines.ids):
        n = int(counts[k])
        lo = int(lines.base[k])
        hi, shape = lo + len(ids) * n, (len(ids), n)
        rows = [v[lo:hi].reshape(shape) for v in (lines.outer[0], x, y, z, hdg, curvature, speed)]
        out.append(SectionPoints(ids, rows[0], pose.curvature[offsets[k] : offsets[k + 1]], *rows[1:]))
    return out
