"""Lane centre lines of many lane sections in one pass (:mod:`xodrcheck.roadpass`): the plan-view curvature and speed
of chosen lanes' centre lines, the numbers :meth:`RoadGeometry.lane_points` gives with ``where="centre"``, to the last
bit.

The border jets and the lateral offset of every border line come from
:func:`xodrcheck.roadpass_lines.lateral_lines` (lane by lane outward, as :func:`xodrcheck.lane_lines.border_lines`); a
lane's centre line is then, as :func:`xodrcheck.lane_lines.projected` computes it, the lateral offset of its inner
border line plus ``0.5 * (inner + outer) - inner`` (jets of ``t``), and its curvature and speed are
:func:`xodrcheck.lane_lines.bend`'s formulas, elementwise on flat arrays of (line, sample) pairs. Only sections
:func:`xodrcheck.roadpass.covered` covers (no superelevation, no lane id twice) are evaluated here.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass

import numpy as np

from xodrcheck import roadpass
from xodrcheck.arrays import batches, ranges
from xodrcheck.geometry.pose import Pose
from xodrcheck.roadpass_lines import lateral_lines
from xodrcheck.roadpass_pose import poses


@dataclass
class Centres:
    """Centre lines of the chosen lanes: line ``j`` is lane ``lanes[j][1]`` of entry ``lanes[j][0]``, its samples the
    pairs ``starts[j]:starts[j + 1]`` of the flat arrays (``sample``: index into the pass's samples)."""

    lanes: list[tuple[int, int]]
    starts: np.ndarray
    sample: np.ndarray
    q: np.ndarray
    curvature: np.ndarray
    speed: np.ndarray
    pose: Pose

    def xy(self, pairs: Sequence[int]) -> list[tuple[float, float]]:
        """Plan-view ``x``, ``y`` of some pairs (as :meth:`all_xy`)."""
        if not pairs:
            return []
        x, y = self._place(self.sample[list(pairs)], self.q[list(pairs)])
        return [(float(a), float(b)) for a, b in zip(x, y)]

    def all_xy(self) -> tuple[np.ndarray, np.ndarray]:
        """Plan-view ``x``, ``y`` of every pair."""
        return self._place(self.sample, self.q)

    def _place(self, at: np.ndarray, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """:func:`xodrcheck.lane_lines.place`'s formulas at samples ``at`` and lateral offsets ``q`` (the heading's
        sine and cosine of all the pass's samples at once, as :func:`xodrcheck.roadpass.border_lines`)."""
        return self.pose.x[at] - q * np.sin(self.pose.hdg)[at], self.pose.y[at] + q * np.cos(self.pose.hdg)[at]


def centre_lines(
    entries: Sequence[roadpass.Entry], samples: Sequence[np.ndarray], wanted: Sequence[Sequence[int]]
) -> Centres | None:
    """The centre lines of lanes ``wanted[k]`` (ids the section places) of each entry (each :func:`roadpass.covered`)
    at its samples (sorted, finite); ``None`` when the pass does not cover them exactly."""
    counts = np.array([len(s) for s in samples], dtype=np.int64)
    offsets = np.concatenate(([0], np.cumsum(counts)))
    s = np.concatenate(samples) if len(samples) else np.zeros(0)
    pose = poses(entries, s, offsets) if entries else None
    if pose is None:
        return None
    lines = lateral_lines(entries, s, offsets)
    lanes, outer_rows, inner_rows, sizes = [], [], [], []
    for k, ((rg, index), ids) in enumerate(zip(entries, lines.ids)):
        n, base = int(counts[k]), int(lines.base[k])
        first_right = 1 + len(rg.side_lanes(index)[0].lanes)
        row_of = {lane_id: row for row, lane_id in enumerate(ids)}
        for lane_id in wanted[k]:
            row = row_of[lane_id]
            lanes.append((k, lane_id))
            outer_rows.append(base + row * n)
            inner_rows.append(base + (0 if row in (1, first_right) else row - 1) * n)
            sizes.append(n)
    out, inn = ranges(outer_rows, sizes), ranges(inner_rows, sizes)
    lateral = []
    for border, line in zip(lines.outer, (lines.q, lines.dq, lines.ddq)):
        inner = border[inn]
        lateral.append(line[inn] + (0.5 * (inner + border[out]) - inner))
    q, dq, ddq = lateral
    at = lines.sample[out]
    k_, dk = pose.curvature[at], pose.dcurvature[at]
    a = 1.0 - q * k_
    speed = np.hypot(a, dq)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        curvature = (a * a * k_ + a * ddq + 2.0 * dq * dq * k_ + q * dq * dk) / speed**3
    starts = np.concatenate(([0], np.cumsum(np.array(sizes, dtype=np.int64))))
    return Centres(lanes, starts, at, q, curvature, speed, pose)


def centre_batches(
    entries: Sequence[roadpass.Entry], samples: Sequence[np.ndarray], wanted: Sequence[Sequence[int]], limit: int
) -> Iterator[tuple[int, int, Centres | None]]:
    """:func:`centre_lines` of consecutive runs ``lo:hi`` of the entries, each run's (line, sample) pairs within
    ``limit`` (a run of one entry may exceed it): ``(lo, hi, centres)``, ``centres`` ``None`` for a run the pass
    does not cover exactly."""
    for lo, hi in batches([len(s) * len(ids) for s, ids in zip(samples, wanted)], limit):
        yield lo, hi, centre_lines(entries[lo:hi], samples[lo:hi], wanted[lo:hi])


def tightest(centres: Centres, bound: float) -> list[tuple[int, int] | None]:
    """For each line, ``(pair, sample)`` of its largest ``|curvature|`` where ``speed > 0`` (NaN and infinities taken
    as 0, the first of equal ones) when that is above ``bound``, else ``None``: ``curvature._tightest`` of each line."""
    if not centres.lanes:
        return []
    k = np.abs(np.nan_to_num(np.where(centres.speed > 0, centres.curvature, 0.0), nan=0.0, posinf=0.0, neginf=0.0))
    most = np.maximum.reduceat(k, centres.starts[:-1])
    out: list[tuple[int, int] | None] = [None] * len(centres.lanes)
    for j in np.flatnonzero(most > bound):
        lo, hi = int(centres.starts[j]), int(centres.starts[j + 1])
        i = int(np.argmax(k[lo:hi]))
        out[int(j)] = (lo + i, i)
    return out
