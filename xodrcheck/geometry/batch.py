"""One evaluation of lane lines over many blocks: each block is a lane section (:class:`~xodrcheck.geometry.rows.
SectionRows`) at an array of ``s``; the plan view, the profiles and the lane lines of every block are evaluated
together, on flat arrays of (row, sample) pairs (:mod:`xodrcheck.geometry.rows`), each step one numpy call over all
of them:

* profiles (laneOffset, elevation, superelevation, lane widths and borders), with
  :class:`~xodrcheck.geometry.profile.Laws`;
* the ``t`` of every lane's outer border, accumulated outward one lane depth at a time over every block and side
  (a width record added to or subtracted from the inner border, a border record taken as it is, no record: the inner
  border);
* the plan-view lateral offset and height of every border line, walking outward the same way: each lane's step in
  ``t`` is rolled by the superelevation (``t cos`` across, ``t sin`` up) unless the lane is level or the road has no
  superelevation (:mod:`xodrcheck.geometry.lanes` states these conventions);
* the reference poses (:func:`~xodrcheck.geometry.planview.poses`), and the lines placed on them
  (:class:`~xodrcheck.geometry.lines.Lines`).

Jets (a value and its first and second derivative) are the rows of ``(3, n)`` arrays. Every step is elementwise (or,
for spirals, poly3 and paramPoly3, one call per block), so a block's numbers are those of the block evaluated alone:
the per-road API (:class:`xodrcheck.geometry.lanes.RoadGeometry`) is a batch of one. A lane id given twice in a side
names the last such lane's border (as a mapping from ids would), and lines are asked for by id: the first lane with it.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence

import numpy as np

from xodrcheck.geometry.jet import Jet
from xodrcheck.geometry.lines import LanePoints, Lines, split
from xodrcheck.geometry.planview import poses
from xodrcheck.geometry.pose import Pose
from xodrcheck.geometry.profile import Laws
from xodrcheck.geometry.rows import ADD, BORDER, SUBTRACT, SectionRows, Step, layout_of
from xodrcheck.support import work
from xodrcheck.support.arrays import batches

#: Samples evaluated together by the checker's file-wide passes (sections' lane lines, road ends, the curvature and
#: junction rules): the temporaries of one pass scale with it (many times the results' size); batches keep them to
#: tens of MB at the speed of one pass.
BATCH_SAMPLES = 1 << 17

_WHERE = ("centre", "inner", "outer")
#: Codes of the lines asked for: a lane's outer border (or lane 0's line), its centre, its inner border.
_OUTER, _CENTRE, _INNER = 0, 1, 2


class Evaluation:
    """Blocks ``(rows, s)`` evaluated together: profiles and border ``t`` at once, the lateral walk and the reference
    poses on first use. Block ``k``'s samples are ``s[offsets[k]:offsets[k + 1]]``."""

    __slots__ = (
        "_heading",
        "_lateral",
        "_pose",
        "cos",
        "elevation",
        "elevation_jet",
        "layout",
        "offsets",
        "s",
        "sections",
        "sin",
        "t",
    )

    def __init__(self, sections: Sequence[SectionRows], samples: Sequence[np.ndarray]):
        self.sections = list(sections)
        counts = np.array([len(s) for s in samples], dtype=np.int64)
        self.offsets = np.concatenate(([0], np.cumsum(counts))).astype(np.int64)
        self.s = np.concatenate(samples).astype(float, copy=False) if len(samples) else np.zeros(0)
        #: Where each block's rows lie among the pairs.
        self.layout = layout_of(self.sections, counts, self.offsets)
        self._pose: Pose | None = None
        self._heading: tuple[np.ndarray, np.ndarray] | None = None
        self._lateral: tuple[np.ndarray, np.ndarray | None] | None = None
        #: Jets of the superelevation's cosine and sine per sample (``None``: no block's road has superelevation).
        self.cos: np.ndarray | None = None
        self.sin: np.ndarray | None = None
        own = self._profiles()
        #: ``t`` of every row's outer border per pair (row 0: the laneOffset line), a ``(3, pairs)`` jet.
        self.t = self._outer_borders(own)

    def _profiles(self) -> np.ndarray:
        """Every row's own profile per pair (returned), the elevation and the superelevation per sample."""
        pairs, size = int(self.layout.base[-1]), len(self.s)
        laws = Laws()
        rolled = False
        for k, section in enumerate(self.sections):
            lo, n = int(self.offsets[k]), int(self.offsets[k + 1] - self.offsets[k])
            laws.add(section.laws, int(self.layout.base[k]), lo, n)
            laws.add(section.elevation, pairs + lo, lo, n)
            if section.roll is not None:
                laws.add(section.roll, pairs + size + lo, lo, n)
                rolled = True
        found = laws.evaluate(self.s, pairs + (2 if rolled else 1) * size)
        self.elevation_jet = found[:, pairs : pairs + size]
        self.elevation = self.elevation_jet[0]
        if rolled:
            phi = Jet(*found[:, pairs + size :])
            self.cos, self.sin = _stack(phi.cos()), _stack(phi.sin())
        return found[:, :pairs]

    def _outer_borders(self, t: np.ndarray) -> np.ndarray:
        """``t`` of every row's outer border, accumulated outward depth by depth from the rows' own profiles (in
        place)."""
        with np.errstate(all="ignore"):  # damaged widths near the float limit overflow
            for step in self.layout.steps:
                t[:, step.out] = _accumulated(step, t[:, step.inn], t[:, step.out])
        if self.layout.views is not None:  # a lane id twice: each row's id names the last such row's border
            return t[:, self.layout.views]
        return t

    # ------------------------------------------------------------------------------------------------------ walk
    def _walk(self) -> tuple[np.ndarray, np.ndarray | None]:
        """Plan-view lateral offset (a jet) and height above the reference line (``None``: 0 everywhere) of every
        row's line: lane 0's, then each lane's outer border, continuing its inner neighbour's line."""
        if self._lateral is None:
            t = self.t
            lateral = t.copy()
            height = None
            with np.errstate(all="ignore"):
                if self.layout.rolled is not None:
                    height = np.zeros(t.shape[1])
                    at = self.layout.centre
                    at = at[self.layout.rolled[at]]
                    lateral[:, at], height[at] = self._rolled(at, t[:, at])
                for step in self.layout.steps:
                    self._step(lateral, height, step)
            self._lateral = (lateral, height)
            work.add("line points", t.shape[1])
        return self._lateral

    def _step(self, lateral: np.ndarray, height: np.ndarray | None, step: Step) -> None:
        """The lines of one depth: their inner neighbours' moved by the step in ``t`` between the two borders."""
        out, inn = step.out, step.inn
        moved = self.t[:, out] - self.t[:, inn]
        lateral[:, out] = lateral[:, inn] + moved
        if height is None or step.rolled is None:
            return
        height[out] = height[inn]
        at = np.flatnonzero(step.rolled)
        if len(at):
            across, up = self._rolled(out[at], moved[:, at])
            lateral[:, out[at]] = lateral[:, inn[at]] + across
            height[out[at]] = height[inn[at]] + up

    def _rolled(self, pairs: np.ndarray, step: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """A step in ``t`` (a jet) at ``pairs`` rolled by the superelevation: its plan-view part and its rise."""
        assert self.cos is not None and self.sin is not None
        at = self.layout.sample[pairs]
        return _stack(Jet(*step) * Jet(*self.cos[:, at])), step[0] * self.sin[0, at]

    # ------------------------------------------------------------------------------------------------------ results
    @property
    def pose(self) -> Pose:
        """The reference poses at every sample (evaluated on first use)."""
        if self._pose is None:
            self._pose = poses([section.reference for section in self.sections], self.s, self.offsets)
        return self._pose

    def heading(self) -> tuple[np.ndarray, np.ndarray]:
        """``sin`` and ``cos`` of the reference line's heading (computed once, shared by every line)."""
        if self._heading is None:
            self._heading = (np.sin(self.pose.hdg), np.cos(self.pose.hdg))
        return self._heading

    def block(self, k: int) -> slice:
        """Block ``k``'s samples."""
        return slice(int(self.offsets[k]), int(self.offsets[k + 1]))

    def row_pairs(self, k: int, row: int) -> slice:
        """Block ``k``'s row ``row``'s pairs."""
        n = int(self.offsets[k + 1] - self.offsets[k])
        base = int(self.layout.base[k])
        return slice(base + row * n, base + (row + 1) * n)

    def borders(self, k: int) -> dict[int, np.ndarray]:
        """Lateral ``t`` of each lane's outer border in block ``k`` (lane 0: the laneOffset line), by lane id."""
        section = self.sections[k]
        return {section.ids[r]: self.t[0, self.row_pairs(k, r)].copy() for r in section.lines.tolist()}

    def border_ids(self, k: int) -> list[int]:
        """Lane ids of block ``k``'s border lines, in :meth:`border_lines` order."""
        section = self.sections[k]
        return [section.ids[r] for r in section.lines.tolist()]

    def border_lines(self) -> Lines:
        """The border lines of every block (its :attr:`~xodrcheck.geometry.rows.SectionRows.lines`, block after
        block)."""
        lateral, height = self._walk()
        if self.layout.lines is None:  # every row is a border line
            return Lines(self, self.layout.sample, lateral, 0.0 if height is None else height, self.layout.starts)
        pairs, starts = self.layout.line_pairs()
        return Lines(
            self, self.layout.sample[pairs], lateral[:, pairs], 0.0 if height is None else height[pairs], starts
        )

    def border_points(self) -> list[dict[int, LanePoints]]:
        """Every block's border lines placed (:meth:`border_lines`), by lane id (views of the batch's arrays)."""
        lines = self.border_lines()
        parts = split(lines.points(), lines.starts)
        out, j = [], 0
        for k in range(len(self.sections)):
            ids = self.border_ids(k)
            out.append(dict(zip(ids, parts[j : j + len(ids)])))
            j += len(ids)
        return out

    def bending(self) -> np.ndarray:
        """At each sample, the largest of ``|curvature| * speed^2`` over its block's border lines and ``|curvature|``
        of the reference line: what the sampler bounds. NaN where every one is NaN."""
        lines = self.border_lines()
        _, speed, curvature = lines.bend()
        most = np.full(len(self.s), np.nan)
        np.fmax.at(most, lines.sample, np.abs(curvature) * speed**2)
        return np.fmax(np.abs(self.pose.curvature), most)

    def lines(self, wanted: Sequence[tuple[int, int, str, bool]]) -> Lines:
        """Lane lines ``(block, lane id, where, raised)``: a lane's ``"centre"``, ``"inner"`` or ``"outer"`` border
        (lane 0: its line, whatever ``where``), with ``raised`` lifted by the lane's height along the h-axis (normal
        to the lane's surface: rolled by the superelevation unless the lane is level). A lane id the block does not
        place raises ``KeyError``."""
        rows, codes = [], []
        for k, lane_id, where, _ in wanted:
            if where not in _WHERE:
                raise ValueError(f"where must be one of {_WHERE}, got {where!r}")
            row = self.sections[k].first.get(lane_id)
            if row is None:
                raise KeyError(f"no lane {lane_id} in the lane section")
            rows.append(int(self.layout.block_rows[k]) + row)
            codes.append(_OUTER if lane_id == 0 or where == "outer" else _CENTRE if where == "centre" else _INNER)
        layout = self.layout
        row_a = np.array(rows, dtype=np.int64)
        n = layout.n[row_a]
        out = layout.pairs(layout.start[row_a], False, row_a)
        lateral, height = self._walk()
        mine = lateral[:, out]
        lift = None if height is None else height[out]
        code = np.repeat(np.array(codes, dtype=np.int8), n)
        aside = np.flatnonzero(code != _OUTER)
        if len(aside):  # inner or centre: the inner border's line moved to the target
            prev = layout.pairs(layout.start[layout.prev[row_a]], False, row_a)[aside]
            lift = self._aside(mine, lift, out[aside], prev, code[aside] == _INNER, aside)
        starts = np.concatenate(([0], np.cumsum(n))).astype(np.int64)
        found = Lines(self, layout.sample[out], mine, 0.0 if lift is None else lift, starts)
        if any(raised for *_, raised in wanted):
            _raise(self, found, wanted)
        return found

    def _aside(self, mine: np.ndarray, lift, out: np.ndarray, inn: np.ndarray, inner: np.ndarray, at: np.ndarray):
        """Write into ``mine`` (and ``lift``) at ``at`` the lines at the inner border (where ``inner``) or the centre
        of the lanes whose outer border is at pairs ``out`` and inner border at ``inn``; returns ``lift``."""
        lateral, height = self._walk()
        with np.errstate(all="ignore"):
            low = self.t[:, inn]
            step = np.where(inner, low, 0.5 * (low + self.t[:, out])) - low
            mine[:, at] = lateral[:, inn] + step
            if height is None or self.layout.rolled is None:
                return lift
            lift[at] = height[inn]
            rolled = np.flatnonzero(self.layout.rolled[out])
            if len(rolled):
                across, up = self._rolled(out[rolled], step[:, rolled])
                mine[:, at[rolled]] = lateral[:, inn[rolled]] + across
                lift[at[rolled]] = height[inn[rolled]] + up
        return lift


def _accumulated(step: Step, inner: np.ndarray, own: np.ndarray) -> np.ndarray:
    """Outer borders of one depth's rows from their inner borders and their own profiles, by each row's kind."""
    if step.kind is not None:
        return _by_kind(step.kind, inner, own)
    if step.subtract is not None:
        return np.where(step.subtract, inner - own, inner + own)
    out = np.empty_like(own)
    for kind, at in step.groups:
        out[:, at] = _by_kind(kind, inner[:, at], own[:, at])
    return out


def _by_kind(kind: int, inner: np.ndarray, own: np.ndarray) -> np.ndarray:
    if kind == ADD:
        return inner + own
    if kind == SUBTRACT:
        return inner - own
    return own if kind == BORDER else inner


def _raise(evaluation: Evaluation, lines: Lines, wanted: Sequence[tuple[int, int, str, bool]]) -> None:
    """Lift the lines asked for ``raised`` by their lane's height (11.7.3) along the h-axis, in place."""
    for j, (k, lane_id, where, raised) in enumerate(wanted):
        section = evaluation.sections[k]
        row = section.first[lane_id]
        if not raised or lane_id == 0 or row not in section.heights:
            continue
        if not isinstance(lines.height, np.ndarray):
            lines.height = np.zeros(len(lines.sample))
        at = evaluation.block(k)
        inner, outer = (np.array(law.jet(evaluation.s[at])) for law in section.heights[row])
        lift = inner if where == "inner" else outer if where == "outer" else 0.5 * (inner + outer)
        pairs = slice(int(lines.starts[j]), int(lines.starts[j + 1]))
        lane = section.lanes[row]
        if (lane is not None and lane.level) or evaluation.cos is None or evaluation.sin is None:
            lines.height[pairs] = lines.height[pairs] + lift[0]
            continue
        lines.lateral[:, pairs] = lines.lateral[:, pairs] - _stack(Jet(*lift) * Jet(*evaluation.sin[:, at]))
        lines.height[pairs] = lines.height[pairs] + lift[0] * evaluation.cos[0, at]


def centre_lines(
    sections: Sequence[SectionRows], samples: Sequence[np.ndarray], wanted: Sequence[Sequence[int]], limit: int
) -> Iterator[tuple[int, int, Lines]]:
    """The centre lines of lanes ``wanted[k]`` (ids the section places) of every section at its samples, evaluated in
    batches of consecutive sections of at most ``limit`` (line, sample) pairs (a batch of one section may pass it):
    ``(lo, hi, lines)``, the lines of sections ``lo:hi`` in order, each section's in the order of ``wanted``."""
    for lo, hi in batches([len(s) * len(ids) for s, ids in zip(samples, wanted)], limit):
        evaluation = Evaluation(sections[lo:hi], samples[lo:hi])
        yield lo, hi, evaluation.lines([(k, i, "centre", False) for k in range(hi - lo) for i in wanted[lo + k]])


def _stack(jet: Jet) -> np.ndarray:
    return np.array((jet.v, jet.d1, jet.d2))
