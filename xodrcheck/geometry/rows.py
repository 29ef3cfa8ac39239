"""Lane sections laid out as rows for the batched evaluation (:mod:`xodrcheck.geometry.batch`), and where each row's
values lie in a batch of sections.

Row 0 of a section is lane 0's line (the laneOffset), then come the left lanes inner to outer, then the right lanes;
a lane's depth is its place in its side (1 for the lanes beside lane 0). In a batch, row ``r`` of block ``k`` holds its
values at the block's samples as consecutive "pairs" (row, sample), the rows of a block one after the other and the
blocks end to end, so that one numpy call can update the rows of one depth across every block.
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from xodrcheck.geometry.planview import ReferenceLine
from xodrcheck.geometry.profile import Piecewise, Table
from xodrcheck.model import Cubic, Lane
from xodrcheck.support.arrays import ranges

#: Kinds of a row: no record (the outer border is the inner one), a width added or subtracted, a border record.
NONE, ADD, SUBTRACT, BORDER = 0, 1, -1, 2


class Side(Protocol):
    """The lanes of one side of a section, inner to outer, each with its profile (``None``: none) and whether it is a
    width (else a border) profile; ``origin``: the ``s`` their records are relative to."""

    @property
    def lanes(self) -> tuple[Lane, ...]: ...

    @property
    def origin(self) -> float: ...

    @property
    def laws(self) -> tuple[Piecewise | None, ...]: ...

    @property
    def is_width(self) -> tuple[bool, ...]: ...


@dataclass(frozen=True, eq=False)
class SectionRows:
    """A lane section laid out as rows (see the module docstring), with what evaluating it needs."""

    reference: ReferenceLine
    #: Lane id and lane of each row (row 0: lane 0, no lane).
    ids: tuple[int, ...]
    lanes: tuple[Lane | None, ...]
    #: Row 0's laneOffset and each lane's width or border profile.
    laws: Table
    #: Per row: its kind, the row before it in its side (0 for the first; row 0: 0), its depth, whether it is level.
    kind: np.ndarray
    prev: np.ndarray
    depth: np.ndarray
    level: np.ndarray
    #: Per row, the row whose border its id names (the last with that id); ``None`` when no lane id is given twice.
    view: np.ndarray | None
    #: Lane id -> first row with it (the lane its lines are of).
    first: dict[int, int]
    #: Rows of the border lines: lane 0, then the first row of every id, in order.
    lines: np.ndarray
    #: First row of a lane with ``<height>`` -> its inner and outer height profiles.
    heights: dict[int, tuple[Piecewise, Piecewise]]
    elevation: Table
    #: The superelevation, ``None`` on a road without (no roll anywhere).
    roll: Table | None


def lay_out(
    reference: ReferenceLine, sides: tuple[Side, Side], offset: Piecewise, elevation: Table, roll: Table | None
) -> SectionRows:
    """The :class:`SectionRows` of a section's ``(left, right)`` lanes on a road with this reference line, laneOffset,
    elevation and superelevation."""
    ids: list[int] = [0]
    lanes: list[Lane | None] = [None]
    rows = [(NONE, 0, 0, 0)]
    for sign, side in zip((+1, -1), sides):
        prev = 0
        for depth, (lane, law, is_width) in enumerate(zip(side.lanes, side.laws, side.is_width), start=1):
            kind = NONE if law is None else (ADD if sign > 0 else SUBTRACT) if is_width else BORDER
            rows.append((kind, prev, depth, int(bool(lane.level))))
            prev = len(ids)
            ids.append(lane.id)
            lanes.append(lane)
    table = np.array(rows, dtype=np.int64)
    first: dict[int, int] = {}
    last: dict[int, int] = {}
    for row, lane_id in enumerate(ids):
        first.setdefault(lane_id, row)
        last[lane_id] = row
    view = np.array([last[lane_id] for lane_id in ids], dtype=np.int64) if len(first) < len(ids) else None
    return SectionRows(
        reference,
        tuple(ids),
        tuple(lanes),
        Table((offset, *(law for side in sides for law in side.laws))),
        table[:, 0],
        table[:, 1],
        table[:, 2],
        table[:, 3].astype(bool),
        view,
        first,
        np.array(sorted(first.values()), dtype=np.int64),
        _heights(sides, lanes, first),
        elevation,
        roll,
    )


def _heights(sides: tuple[Side, Side], lanes: list[Lane | None], first: dict[int, int]) -> dict:
    """The inner and outer height profiles of every lane with ``<height>`` (the first lane with its id): each record
    is a constant, from its ``sOffset`` to the next (relative to the lanes' section start)."""
    out = {}
    for row, lane in enumerate(lanes):
        if lane is not None and lane.heights and first[lane.id] == row:
            origin = sides[0 if lane.id > 0 else 1].origin
            inner = tuple(Cubic(h.s, h.inner, 0.0, 0.0, 0.0, h.line) for h in lane.heights)
            outer = tuple(Cubic(h.s, h.outer, 0.0, 0.0, 0.0, h.line) for h in lane.heights)
            out[row] = (Piecewise(inner, origin), Piecewise(outer, origin))
    return out


@dataclass(frozen=True, eq=False)
class Step:
    """The rows of one depth across a batch: their pairs (``out``), their inner neighbours' (``inn``), their kind
    (``kind``, when they share one; ``subtract``: which pairs subtract where the rows add or subtract widths;
    ``groups``: the pairs of each kind otherwise), and which pairs are rolled by the superelevation (``None``:
    none)."""

    out: np.ndarray
    inn: np.ndarray
    kind: int | None
    subtract: np.ndarray | None
    groups: tuple[tuple[int, np.ndarray], ...]
    rolled: np.ndarray | None


#: Most samples of a block whose layout is kept (per-road queries at a few points repeat the same layouts).
_KEPT_SAMPLES = 64
#: Most layouts kept, least recently used dropped first (a few kB each).
_KEPT_LAYOUTS = 512
_KEPT: OrderedDict[tuple[int, int], tuple[SectionRows, Layout]] = OrderedDict()


def layout_of(sections: Sequence[SectionRows], counts: np.ndarray, offsets: np.ndarray) -> Layout:
    """The :class:`Layout` of a batch; those of one block of a few samples are kept for the next query."""
    if len(sections) != 1 or counts[0] > _KEPT_SAMPLES:
        return Layout(sections, counts, offsets)
    key = (id(sections[0]), int(counts[0]))
    found = _KEPT.get(key)
    if found is not None and found[0] is sections[0]:
        _KEPT.move_to_end(key)
        return found[1]
    layout = Layout(sections, counts, offsets)
    _KEPT[key] = (sections[0], layout)
    if len(_KEPT) > _KEPT_LAYOUTS:
        _KEPT.popitem(last=False)
    return layout


class Layout:
    """Where the rows of a batch of sections (with ``counts`` samples each) lie among its pairs."""

    __slots__ = (
        "base",
        "block_rows",
        "centre",
        "lines",
        "n",
        "prev",
        "rolled",
        "sample",
        "start",
        "starts",
        "steps",
        "views",
    )

    def __init__(self, sections: Sequence[SectionRows], counts: np.ndarray, offsets: np.ndarray):
        per_block = np.array([len(section.ids) for section in sections], dtype=np.int64)
        #: First pair of each block, and past the last.
        self.base = np.concatenate(([0], np.cumsum(per_block * counts))).astype(np.int64)
        #: First row of each block (rows numbered over the batch).
        self.block_rows = np.concatenate(([0], np.cumsum(per_block))).astype(np.int64)
        block = np.repeat(np.arange(len(sections)), per_block)
        local = np.arange(len(block)) - self.block_rows[block]
        #: Per row: how many pairs, where they start; where each row starts among the rows' pairs laid end to end.
        self.n = counts[block]
        self.start = self.base[block] + local * self.n
        self.starts = np.concatenate(([0], np.cumsum(self.n))).astype(np.int64)
        one = len(sections) == 1
        self.sample = self.pairs(np.repeat(offsets[:-1], per_block), one)
        kind, prev, depth, level = (
            getattr(sections[0], name) if one else np.concatenate([getattr(s, name) for s in sections] or [[]])
            for name in ("kind", "prev", "depth", "level")
        )
        kind, depth = kind.astype(np.int64, copy=False), depth.astype(np.int64, copy=False)
        prev, level = prev.astype(np.int64, copy=False), level.astype(bool, copy=False)
        #: Per row, the row before it in its side (row 0 for the first lanes, and for row 0).
        self.prev = prev = prev + self.block_rows[block]
        roll = np.array([section.roll is not None for section in sections], dtype=bool)
        rolled = roll[block] & ~level if roll.any() else None
        #: Per pair: whether its row is rolled by the superelevation (``None``: no block has superelevation).
        self.rolled = None if rolled is None else np.repeat(rolled, self.n)
        self.centre = self.pairs(self.start[local == 0], one, local == 0)
        self.steps = [self._step(d, depth, kind, prev, rolled, one) for d in range(1, int(depth.max(initial=0)) + 1)]
        #: Per pair, the pair whose border its lane id names (``None``: every id is its row's own).
        self.views = None
        #: The rows of the border lines (``None``: every row).
        self.lines = None
        if any(section.view is not None for section in sections):
            view = np.concatenate([s.view if s.view is not None else np.arange(len(s.ids)) for s in sections])
            self.views = ranges(self.start[view + self.block_rows[block]], self.n)
            self.lines = np.concatenate([s.lines + self.block_rows[k] for k, s in enumerate(sections)])

    def pairs(self, starts: np.ndarray, one: bool, rows: np.ndarray | slice = slice(None)) -> np.ndarray:
        """Pairs of rows starting at ``starts`` (``rows``: which rows; ``one``: a batch of one block, whose rows all
        have the same number of pairs)."""
        if one and len(self.n):
            return (starts[:, None] + np.arange(self.n[0])).ravel()
        return ranges(starts, self.n[rows])

    def _step(self, d: int, depth, kind, prev, rolled, one: bool) -> Step:
        rows = np.flatnonzero(depth == d)
        out = self.pairs(self.start[rows], one, rows)
        inn = self.pairs(self.start[prev[rows]], one, rows)
        kinds = kind[rows]
        present = set(kinds.tolist())
        per_pair = np.repeat(kinds, self.n[rows]) if len(present) > 1 else None
        widths = present == {ADD, SUBTRACT}
        return Step(
            out,
            inn,
            kinds[0].item() if len(present) == 1 else None,
            per_pair == SUBTRACT if widths and per_pair is not None else None,
            () if per_pair is None or widths else tuple((k, np.flatnonzero(per_pair == k)) for k in sorted(present)),
            None if rolled is None else np.repeat(rolled[rows], self.n[rows]),
        )

    def line_pairs(self) -> tuple[np.ndarray, np.ndarray]:
        """Pairs of every block's border lines, and where each line starts among them."""
        rows = self.lines if self.lines is not None else np.arange(len(self.n))
        n = self.n[rows]
        return ranges(self.start[rows], n), np.concatenate(([0], np.cumsum(n))).astype(np.int64)
