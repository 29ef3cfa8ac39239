"""Profiles and lateral border lines for :mod:`xodrcheck.roadpass`: profile records evaluated for many (law,
samples) blocks at once (:class:`Laws`), and the lateral offset jets of every border line of many lane sections, lane
by lane outward over all sections and sides (:func:`lateral_lines`), with their plan-view speed and curvature
(:func:`bend`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from xodrcheck import work
from xodrcheck.arrays import ranges
from xodrcheck.geometry import profile
from xodrcheck.geometry.pose import Pose
from xodrcheck.roadpass_pose import Entry

#: Profiles with at most this many records find their record by counting (as ``profile.Batch``); longer ones search.
_COUNTED = 32


# ------------------------------------------------------------------------------------------------------ profiles
class Laws:
    """Profile evaluations to do: law ``i`` at samples ``s[sample:sample + n]``, written at ``dest:dest + n``."""

    def __init__(self) -> None:
        self.single: list[tuple[tuple, int, int, int]] = []
        self.multi: list[tuple[profile.Piecewise, int, int, int]] = []
        self.empty: list[tuple[int, int]] = []

    def add(self, law: profile.Piecewise, dest: int, sample: int, n: int) -> None:
        if law._single is not None:
            self.single.append((law._single, dest, sample, n))
        elif len(law.starts) == 0:
            self.empty.append((dest, n))
        else:
            self.multi.append((law, dest, sample, n))

    def evaluate(self, s: np.ndarray, size: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Value, first and second derivative arrays of ``size`` (zero where nothing was written)."""
        out = (np.zeros(size), np.zeros(size), np.zeros(size))
        if self.single:
            coef = np.array([c for c, _, _, _ in self.single], dtype=float)  # start, a, b, c, d
            sizes = np.array([n for _, _, _, n in self.single], dtype=np.int64)
            dests = ranges([d for _, d, _, _ in self.single], sizes)
            at = ranges([a for _, _, a, _ in self.single], sizes)
            per = np.repeat(coef, sizes, axis=0)
            jet = profile._cubic_jet(per[:, 1], per[:, 2], per[:, 3], per[:, 4], s[at] - per[:, 0], None)
            for o, j in zip(out, jet):
                o[dests] = j
        counted = [m for m in self.multi if len(m[0].starts) <= _COUNTED and not np.isnan(m[0].starts).any()]
        if counted:
            self._counted(counted, s, out)
        for law, dest, sample, n in self.multi:
            if len(law.starts) > _COUNTED or np.isnan(law.starts).any():
                for o, j in zip(out, law.jet(s[sample : sample + n])):
                    o[dest : dest + n] = j
        return out

    @staticmethod
    def _counted(laws: list, s: np.ndarray, out: tuple) -> None:
        """Profiles of a few records: each point's record by counting the starts at or before it."""
        width = max(len(law.starts) for law, _, _, _ in laws)
        starts = np.full((len(laws), width), np.inf)
        coef = np.zeros((len(laws), width, 4))
        for i, (law, _, _, _) in enumerate(laws):
            starts[i, : len(law.starts)] = law.starts
            coef[i, : len(law.starts)] = law.coefficients
        n = np.array([n for _, _, _, n in laws], dtype=np.int64)
        owner = np.repeat(np.arange(len(laws)), n)
        at = s[ranges([a for _, _, a, _ in laws], n)]
        count = np.zeros(len(at), dtype=np.int64)
        for j in range(width):  # one pass per record position: no (points x records) array
            count += at >= starts[owner, j]
        index = np.maximum(count - 1, 0)
        record_start = starts[owner, index]
        a, b, c, d = coef[owner, index].T
        jet = profile._cubic_jet(a, b, c, d, at - record_start, count > 0)
        dest = ranges([d for _, d, _, _ in laws], n)
        for o, j in zip(out, jet):
            o[dest] = j


# ------------------------------------------------------------------------------------------------------ lines
@dataclass
class Lines:
    """Border lines of the entries at their samples, as flat pair arrays (see :mod:`xodrcheck.roadpass`)."""

    #: Lane ids of each entry's lines (lane 0 first, then left lanes inner to outer, then right lanes).
    ids: list[list[int]]
    #: First pair of each entry's block (the lines of an entry are consecutive blocks of its sample count).
    base: np.ndarray
    #: Sample index of each pair (into the flat samples), and the per-pair lateral offset jet.
    sample: np.ndarray
    q: np.ndarray
    dq: np.ndarray
    ddq: np.ndarray
    #: Jet (``t``, its derivatives) of each pair's line before projection (lane 0: laneOffset; else outer border).
    outer: tuple[np.ndarray, np.ndarray, np.ndarray]


def lateral_lines(entries: Sequence[Entry], s: np.ndarray, offsets: np.ndarray) -> Lines:
    """Plan-view lateral offset jets of every border line (lane 0's line and each lane's outer border) of each entry
    at its samples: :func:`xodrcheck.lane_lines.border_lines` without superelevation, for all entries at once."""
    counts = np.diff(offsets)
    ids: list[list[int]] = []
    laws = Laws()
    steps: dict[int, list[tuple[int, int, int, int]]] = {}  # depth -> (out row, in row, count, kind)
    bases, rows_per_entry = [], []
    base = 0
    for k, (rg, index) in enumerate(entries):
        n, first = int(counts[k]), int(offsets[k])
        laws.add(rg._offset, base, first, n)  # row 0: the laneOffset line
        section_ids = [0]
        row = 1
        for sign, side in zip((1, -1), rg.side_lanes(index)):
            inner_row = 0
            for depth, (lane, law, is_width) in enumerate(zip(side.lanes, side.laws, side.is_width), start=1):
                kind = 0 if law is None else (sign if is_width else 2)  # none, +-width, border
                if law is not None:
                    laws.add(law, base + row * n, first, n)
                steps.setdefault(depth, []).append((base + row * n, base + inner_row * n, n, kind))
                section_ids.append(lane.id)
                inner_row = row
                row += 1
        ids.append(section_ids)
        bases.append(base)
        rows_per_entry.append(row)
        base += row * n
    rows_a = np.array(rows_per_entry, dtype=np.int64)
    row_sizes = np.repeat(counts, rows_a)
    sample = np.repeat(np.repeat(offsets[:-1], rows_a), row_sizes) + ranges(np.zeros(len(row_sizes)), row_sizes)
    law_jets = laws.evaluate(s, base)  # row 0 of each entry: the laneOffset jet; other rows: the lane's law
    outer = tuple(j.copy() for j in law_jets)  # outer border jets, filled outward below
    lateral = tuple(j.copy() for j in law_jets)  # lane 0's line is the laneOffset line itself
    for depth in sorted(steps):  # outward, one lane depth at a time over all entries and sides
        rows = np.array(steps[depth], dtype=np.int64).reshape(-1, 4)
        out = ranges(rows[:, 0], rows[:, 2])
        inn = ranges(rows[:, 1], rows[:, 2])
        kinds = np.repeat(rows[:, 3], rows[:, 2])
        for values, own_all, lat in zip(outer, law_jets, lateral):
            inner, own = values[inn], own_all[out]
            with np.errstate(all="ignore"):  # the branches not taken may overflow
                new = np.where(
                    kinds == 1, inner + own, np.where(kinds == -1, inner - own, np.where(kinds == 2, own, inner))
                )
                values[out] = new
                lat[out] = lat[inn] + (new - inner)
    q, dq, ddq = lateral
    work.add("line points", base)
    return Lines(ids, np.array(bases, dtype=np.int64), sample, q, dq, ddq, outer)


def bend(lines: Lines, pose: Pose) -> tuple[np.ndarray, np.ndarray]:
    """Plan-view speed and curvature of every pair's line (:func:`xodrcheck.lane_lines.bend`)."""
    at = lines.sample
    q, dq, ddq = lines.q, lines.dq, lines.ddq
    k, dk = pose.curvature[at], pose.dcurvature[at]
    a = 1.0 - q * k
    speed = np.hypot(a, dq)
    with np.errstate(divide="ignore", invalid="ignore"):
        return speed, (a * a * k + a * ddq + 2.0 * dq * dq * k + q * dq * dk) / speed**3
