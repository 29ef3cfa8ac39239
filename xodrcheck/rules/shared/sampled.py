"""Geometry the geometric rules share, computed once per file.

Each lane section is sampled and evaluated once (:func:`section_lines`) and kept with the check's
:class:`~xodrcheck.rules.shared.context.Context`, so the link, curvature and junction rules share one evaluation. A road
without a plan view or without lane sections has no geometry here (``None``): the reader reports those.
"""

from __future__ import annotations

import math
import weakref
from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from xodrcheck.config import Tolerances
from xodrcheck.findings import Severity
from xodrcheck.geometry.batch import BATCH_SAMPLES, Evaluation
from xodrcheck.geometry.lanes import RoadGeometry
from xodrcheck.geometry.lines import LanePoints
from xodrcheck.model import Road
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.grids import section_grids
from xodrcheck.rules.shared.road_ends import END_CURVES as _END_CURVES
from xodrcheck.rules.shared.road_ends import ENDS as _ENDS
from xodrcheck.rules.shared.road_ends import REFERENCE as _REFERENCE
from xodrcheck.support.arrays import batches
from xodrcheck.support.budget import ByteBudget, array_bytes
from xodrcheck.support.quantities import metres


def section_samples(ctx: Context, road: Road, section_index: int) -> np.ndarray:
    """Sorted ``s`` covering lane section ``section_index`` (the ``s`` of :func:`section_lines`, without evaluating
    the lines).

    Every knot of the section (:meth:`~xodrcheck.geometry.lanes.RoadGeometry.knots`: record starts, plan-view joints,
    section ends) and even steps between them no longer than ``sqrt(8 * chord * min_radius)`` (and ``max_step``): a
    polyline through them strays at most ``chord`` from any line curving no tighter than the ``min_radius`` bound
    (tighter curves are reported by the curvature rules). The section's end is taken just before it (:func:`left_of`).
    """
    found = _lines_of(ctx).grid(road.id, section_index)
    return found if found is not None else _grid(ctx, ctx.road_geometry(road), section_index)


@dataclass(frozen=True)
class SectionLines:
    """A lane section evaluated once at its samples: ``t`` of every lane's outer border (lane 0: the lane-0 line),
    the reference line's curvature, and the border lines in plan view."""

    s: np.ndarray
    t: dict[int, np.ndarray]
    curvature: np.ndarray
    borders: dict[int, LanePoints]


#: Each file's :class:`SectionCache` (by its check's context), made on first use; :func:`release_lines` drops it.
LINES: weakref.WeakKeyDictionary[Context, SectionCache] = weakref.WeakKeyDictionary()

#: Bytes of :class:`SectionLines` kept per file (:class:`SectionCache`): a small map's lines are evaluated once for
#: all the rules (every corpus file fits, CARLA's Town05 included); of a big map's, each rule that reads them
#: evaluates again, batch by batch, those that do not fit (kept whole, a big map's lines grow with the map): the bound
#: trades evaluating again for a big map's peak memory (benchmarks/bench_memory.py measures it).
LINES_BUDGET = 64 << 20


def grid_step(tol: Tolerances) -> float:
    """The longest step of :func:`section_samples` (within the sample budget)."""
    return min(tol.max_step, math.sqrt(8.0 * tol.chord * max(tol.min_radius, tol.chord)))


def _grid(ctx: Context, geometry: RoadGeometry, section_index: int) -> np.ndarray:
    return section_grids(ctx.tolerances, [(geometry, section_index)], grid_step(ctx.tolerances))[0]


def section_lines(ctx: Context, road: Road, section_index: int) -> SectionLines:
    """The lane section's lines at its samples (one evaluation per section for all the geometric rules, while they
    fit in :data:`LINES_BUDGET`)."""
    return _lines_of(ctx).lines(ctx, road, section_index)


def lines_in_order(ctx: Context) -> Iterator[tuple[Road, int, RoadGeometry, SectionLines]]:
    """(road, section index, geometry, lines) of every usable road's lane sections, in document order: for a rule that
    reads each section once. The lines :func:`section_lines` keeps are read from its cache; the others are evaluated
    in batches of consecutive sections as the reading goes and not kept (the same numbers: a batch evaluates each
    section as alone), so a big file's lines that do not fit :data:`LINES_BUDGET` cost one evaluation per rule."""
    cache = _lines_of(ctx)
    pending: dict[tuple[str, int], SectionLines] = {}
    for road in ctx.document.roads:
        geometry = ctx.usable_geometry(road)
        if geometry is None:
            continue
        for index in range(len(road.lane_sections)):
            key = (road.id, index)
            found = cache.kept_lines(key)
            if found is None:
                found = pending.pop(key, None)
            if found is None and not cache.fits:
                position = cache.position(key)
                if position is not None:
                    pending = cache.passing(position)
                    found = pending.pop(key, None)
            if found is None:
                found = cache.lines(ctx, road, index)
            yield road, index, geometry, found


def release_lines(ctx: Context) -> None:
    """Drop the file's cached section lines (:func:`section_lines`), road ends (:func:`road_end`) and reference ends
    (:func:`reference_end`) once no rule to come reads them (the overlap rules, run last among the geometric rules,
    call it before building their meshes). A later call builds them again: the findings do not change."""
    for cache in (LINES, _ENDS, _END_CURVES, _REFERENCE):
        cache.pop(ctx, None)


def _lines_of(ctx: Context) -> SectionCache:
    found = LINES.get(ctx)
    return found if found is not None else LINES.setdefault(ctx, SectionCache(ctx))


def _lines_size(lines: SectionLines) -> int:
    """Bytes of a :class:`SectionLines`, about: ``s``, the curvature, and per lane ``t`` and six border arrays."""
    return array_bytes(2 + 7 * len(lines.t), lines.s.size)


class SectionCache:
    """The sampled lines of a file's lane sections, evaluated in batches of consecutive sections (document order)
    and kept within :data:`LINES_BUDGET`.

    The sections whose samples are finite are listed once with their samples (a few bytes per sample). A
    file whose lines fit the budget is evaluated in full batches, once, and kept whole. In a bigger file the lines
    first evaluated stay (three quarters of the budget: every rule that reads the file from its start finds them),
    and the rest pass through a window (the last quarter, least recently used dropped first): a section asked for and
    not kept is evaluated with the sections after it, in a batch that grows while the rule reads on in document order
    and starts small again where it jumps. Sections left out are evaluated one at a time.
    """

    __slots__ = (
        "_bytes",
        "_entries",
        "_first",
        "_grids",
        "_keys",
        "_next",
        "_position",
        "_resident",
        "_resident_bytes",
        "_resident_limit",
        "_size",
        "_window",
        "_window_budget",
    )

    def __init__(self, ctx: Context) -> None:
        self._entries: list[tuple[RoadGeometry, int]] = []
        self._keys: list[tuple[str, int]] = []
        self._grids: list[np.ndarray] = []
        self._bytes: list[int] = []
        candidates = [
            (road, geometry, index)
            for road in ctx.document.roads
            if (geometry := ctx.usable_geometry(road)) is not None
            for index in range(len(road.lane_sections))
        ]
        grids = section_grids(ctx.tolerances, [(g, i) for _, g, i in candidates], grid_step(ctx.tolerances))
        for (road, geometry, index), s in zip(candidates, grids):
            if np.isfinite(s).all():
                self._entries.append((geometry, index))
                self._keys.append((road.id, index))
                self._grids.append(s)
                lanes = 1 + sum(len(side.lanes) for side in geometry.side_lanes(index))
                self._bytes.append(array_bytes(2 + 7 * lanes, s.size))
        self._position = {key: i for i, key in enumerate(self._keys)}
        fits = sum(self._bytes) <= LINES_BUDGET
        self._resident: dict[tuple[str, int], SectionLines] = {}
        self._resident_bytes = 0
        self._resident_limit = LINES_BUDGET if fits else LINES_BUDGET - LINES_BUDGET // 4
        self._window: dict[tuple[str, int], SectionLines] = {}
        self._window_budget = ByteBudget(LINES_BUDGET - self._resident_limit)
        #: Samples of a batch started away from where the last one ended: all at once when everything fits.
        self._first = BATCH_SAMPLES if fits else _FIRST_BATCH_SAMPLES
        self._next = -1
        self._size = self._first

    @property
    def kept(self) -> int:
        """How many sections' lines are kept."""
        return len(self._resident) + len(self._window)

    @property
    def listed(self) -> int:
        """How many sections are listed: those whose samples are finite (evaluated in batches)."""
        return len(self._keys)

    def kept_sections(self) -> dict[tuple[str, int], SectionLines]:
        """The lines kept, by section: those first evaluated, then the window's."""
        return {**self._resident, **self._window}

    @property
    def fits(self) -> bool:
        """Whether every listed section's lines fit :data:`LINES_BUDGET` (then all are kept)."""
        return self._first == BATCH_SAMPLES

    def position(self, key: tuple[str, int]) -> int | None:
        """The place of a listed section in document order (``None`` for the others)."""
        return self._position.get(key)

    def kept_lines(self, key: tuple[str, int]) -> SectionLines | None:
        """A section's lines if they are kept (the window's not touched)."""
        found = self._resident.get(key)
        return found if found is not None else self._window.get(key)

    def passing(self, position: int) -> dict[tuple[str, int], SectionLines]:
        """The lines of the listed sections from ``position`` on, up to the next kept one, in one batch of at most
        :data:`PASSING_BYTES` (at least one section), evaluated and not kept."""
        end, weight = position, 0
        while end < len(self._grids) and (end == position or weight + self._bytes[end] <= PASSING_BYTES):
            if end > position and self.kept_lines(self._keys[end]) is not None:
                break
            weight += self._bytes[end]
            end += 1
        out: dict[tuple[str, int], SectionLines] = {}
        _evaluate_batch(self._entries[position:end], self._keys[position:end], self._grids[position:end], out)
        return out

    @property
    def kept_bytes(self) -> int:
        """Estimated bytes of the lines kept."""
        return self._resident_bytes + self._window_budget.total

    def grid(self, road_id: str, section_index: int) -> np.ndarray | None:
        """The samples of a listed section (``None`` for the others)."""
        position = self._position.get((road_id, section_index))
        return None if position is None else self._grids[position]

    def lines(self, ctx: Context, road: Road, section_index: int) -> SectionLines:
        key = (road.id, section_index)
        found = self._resident.get(key)
        if found is not None:
            return found
        found = self._window.get(key)
        if found is not None:
            self._window_budget.touch(self._window, key)
            return found
        position = self._position.get(key)
        if position is not None and self.fits and not self.kept:  # all is kept: the first batch from the first on
            found = self._evaluate_from(0).get(key)
        if found is None and position is not None:
            found = self._evaluate_from(position).get(key)
        if found is None:
            geometry = ctx.road_geometry(road)
            s = _grid(ctx, geometry, section_index)
            found = SectionLines(
                s,
                geometry.borders(section_index, s),
                geometry.reference(s).curvature,
                geometry.border_curves(section_index, s),
            )
            self._keep(key, found)
        return found

    def evaluate_all(self) -> dict[tuple[str, int], SectionLines]:
        """Every listed section's lines, evaluated in full batches of :data:`BATCH_SAMPLES` (not kept): the same
        numbers as one section at a time, with a fraction of the calls."""
        out: dict[tuple[str, int], SectionLines] = {}
        for lo, hi in batches([len(s) for s in self._grids], BATCH_SAMPLES):
            _evaluate_batch(self._entries[lo:hi], self._keys[lo:hi], self._grids[lo:hi], out)
        return out

    def _keep(self, key: tuple[str, int], lines: SectionLines) -> None:
        size = _lines_size(lines)
        if self._resident_bytes + size <= self._resident_limit:
            self._resident[key] = lines
            self._resident_bytes += size
        else:
            self._window[key] = lines
            self._window_budget.add(self._window, key, size)

    def _evaluate_from(self, position: int) -> dict[tuple[str, int], SectionLines]:
        """Evaluate the batch of listed sections starting at ``position`` and keep it (returned whole: the window
        may drop its first sections while keeping its last). In a file that does not fit, a batch takes at most a
        quarter of the window (the temporaries of its evaluation are several times its size); in one that fits (no
        window: all is kept), it is bounded by :data:`BATCH_SAMPLES` only."""
        size = min(2 * self._size, BATCH_SAMPLES) if position == self._next else self._first
        room = LINES_BUDGET if self.fits else max(self._window_budget.limit // 4, 1)
        end, total, weight = position, 0, 0
        while end < len(self._grids) and (
            end == position or (total + len(self._grids[end]) <= size and weight + self._bytes[end] <= room)
        ):
            total += len(self._grids[end])
            weight += self._bytes[end]
            end += 1
        out: dict[tuple[str, int], SectionLines] = {}
        _evaluate_batch(self._entries[position:end], self._keys[position:end], self._grids[position:end], out)
        if not self.fits:  # a big file: each section's own arrays, not views keeping the batch alive
            out = {key: _copied(lines) for key, lines in out.items()}
        for key, lines in out.items():
            self._keep(key, lines)
        self._next, self._size = end, size
        return out


def _copied(lines: SectionLines) -> SectionLines:
    """``lines`` with arrays of its own (a batch's sections are views of the batch's arrays)."""
    borders = {
        lane_id: LanePoints(*(np.array(getattr(p, name)) for name in ("x", "y", "z", "hdg", "curvature", "speed")))
        for lane_id, p in lines.borders.items()
    }
    t = {lane_id: np.array(v) for lane_id, v in lines.t.items()}
    return SectionLines(lines.s, t, np.array(lines.curvature), borders)


#: Estimated bytes of the lines :func:`lines_in_order` evaluates together and drops once read: it bounds a batch's
#: temporaries (a few times its size).
PASSING_BYTES = 12 << 20
#: Samples of the first batch a big file's sections are evaluated in where a rule starts reading (it doubles while
#: the rule reads on in document order).
_FIRST_BATCH_SAMPLES = 1 << 12


def _evaluate_batch(entries, keys, grids, out: dict[tuple[str, int], SectionLines]) -> None:
    """Evaluate one batch of sections together into ``out``."""
    evaluation = Evaluation([geometry.rows(index) for geometry, index in entries], grids)
    curvature = evaluation.pose.curvature
    for k, (key, s, borders) in enumerate(zip(keys, grids, evaluation.border_points())):
        out[key] = SectionLines(s, evaluation.borders(k), curvature[evaluation.block(k)], borders)


def warning_note(severity: Severity, tolerances: Tolerances, kind: str = "position") -> str:
    """What a message adds when :meth:`Tolerances.grade` made it a warning: the error threshold it stays under."""
    if severity is not Severity.WARNING:
        return ""
    if kind == "position":
        return (
            f" (a warning: over the {metres(tolerances.position)} m position tolerance, within the "
            f"{metres(tolerances.gap)} m gap)"
        )
    return (
        f" (a warning: over the {tolerances.heading:g} rad heading tolerance, within the {tolerances.kink:g} rad "
        f"({math.degrees(tolerances.kink):.2g} deg) kink)"
    )


def angle_between(a: float, b: float) -> float:
    """Absolute difference of two angles, wrapped to [0, pi]."""
    return abs(math.remainder(a - b, 2.0 * math.pi))
