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
  plan-view lateral offset of each line as ``inner line + (outer - inner)``, as :meth:`RoadGeometry._border_lines`;
* the reference line is evaluated element run by element run; elements whose evaluation depends on the whole batch
  of points (spirals, poly3, paramPoly3: series lengths and Newton iterations are chosen per call) are evaluated once
  per section, with exactly the points the per-section code gives them;
* reductions are exact (``fmax``, ``max``).

Sections this pass does not cover exactly are left to the per-section code (:func:`covered` says which): roads with
superelevation, sections with a duplicated lane id; a pass whose samples are not finite or not sorted (damaged input)
returns ``None``.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from xodrcheck.arrays import ranges
from xodrcheck.classcache import dataclass
from xodrcheck.geometry import parampoly3, profile
from xodrcheck.geometry.planview import ReferenceLine, evaluate_element
from xodrcheck.geometry.pose import Pose
from xodrcheck.lanes import RoadGeometry
from xodrcheck.model import Arc, Line, ParamPoly3, Poly3, Spiral
from xodrcheck.sampling import _MAX_COUNT, _PROBE_INSET, knots

#: Plan-view elements whose evaluation depends on the batch of points it is given (evaluated per section).
_PER_CALL = (ParamPoly3, Poly3, Spiral)
#: Profiles with at most this many records find their record by counting (as ``profile.Batch``); longer ones search.
_COUNTED = 32

#: A lane section of a road: (its road's geometry, the section's index).
Entry = tuple[RoadGeometry, int]


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


# ------------------------------------------------------------------------------------------------------ reference line
def _pose(entries: Sequence[Entry], s: np.ndarray, offsets: np.ndarray) -> Pose | None:
    """Reference poses of every entry's samples (entries grouped by road): ``_reference`` of each road, with the
    lines and arcs of all roads evaluated in one gathered call each (their formulas are elementwise)."""
    n = len(s)
    counts = np.diff(offsets)
    roads: list[ReferenceLine] = []
    road_of_entry = np.empty(len(entries), dtype=np.int64)
    for k, (rg, _) in enumerate(entries):
        if not roads or roads[-1] is not rg.reference_line:
            roads.append(rg.reference_line)
        road_of_entry[k] = len(roads) - 1
    road = np.repeat(road_of_entry, counts)
    first = np.concatenate(([0], np.cumsum([len(line.elements) for line in roads])))
    elements = [g for line in roads for g in line.elements]
    if any(not line.elements for line in roads):
        return None  # no plan view: left to the per-section code
    breakpoints = np.concatenate([line.breakpoints for line in roads])
    lengths = np.concatenate([line._lengths for line in roads])
    index = np.empty(n, dtype=np.int64)
    bounds = np.concatenate(([0], np.cumsum(np.bincount(road, minlength=len(roads)))))
    for r, line in enumerate(roads):  # the element of each point, as ReferenceLine.evaluate finds it
        lo, hi = int(bounds[r]), int(bounds[r + 1])
        if len(line.elements) == 1:
            index[lo:hi] = first[r]
        else:
            index[lo:hi] = first[r] + line.element_index(np.minimum(np.maximum(s[lo:hi], line.start), line.end))
    ds = np.minimum(np.maximum(s - breakpoints[index], 0.0), lengths[index])
    inside = np.ones(max(n - 1, 0), dtype=bool)
    inside[offsets[1:-1] - 1] = False  # k and k + 1 belong to different sections
    step = np.diff(index)
    if (step[inside] < 0).any():
        return None  # unsorted samples: the per-section code groups them otherwise
    kind = np.array([0 if type(g) is Line else 1 if type(g) is Arc else 2 for g in elements], dtype=np.int8)
    pose = Pose.empty(n)
    own = kind[index]
    for code, evaluate in ((0, _lines_at), (1, _arcs_at)):
        at = np.flatnonzero(own == code)
        if len(at):
            pose.assign(at, evaluate(elements, index[at], ds[at], kind, code))
    other = own == 2
    if other.any():  # per section and element run, with exactly the per-section code's points
        cut = (step != 0) | ~inside
        edges = np.concatenate(([0], np.flatnonzero(cut) + 1, [n]))
        curves: list[tuple[int, int]] = []  # paramPoly3 runs: evaluated together, each as its own call
        for lo, hi in zip(edges[:-1].tolist(), edges[1:].tolist()):
            if other[lo]:
                if type(elements[index[lo]]) is ParamPoly3:
                    curves.append((lo, hi))
                else:
                    pose.assign(slice(lo, hi), evaluate_element(elements[index[lo]], ds[lo:hi]))
        if curves:
            at = ranges([lo for lo, _ in curves], [hi - lo for lo, hi in curves])
            counts = np.array([hi - lo for lo, hi in curves], dtype=np.int64)
            pose.assign(at, parampoly3.evaluate_runs([elements[index[lo]] for lo, _ in curves], ds[at], counts))
    return pose


def _lines_at(elements: list, index: np.ndarray, ds: np.ndarray, kind: np.ndarray, code: int) -> Pose:
    """``line.evaluate`` at points of many lines: ``x0 + ds cos(hdg)``, ``y0 + ds sin(hdg)``."""
    chosen = np.flatnonzero(kind == code)
    x0, y0, hdg = np.zeros(len(kind)), np.zeros(len(kind)), np.zeros(len(kind))
    x0[chosen] = [elements[i].x for i in chosen]
    y0[chosen] = [elements[i].y for i in chosen]
    hdg[chosen] = [elements[i].hdg for i in chosen]
    zero = np.zeros_like(ds)
    return Pose(x0[index] + ds * np.cos(hdg)[index], y0[index] + ds * np.sin(hdg)[index], hdg[index], zero, zero.copy())


def _arcs_at(elements: list, index: np.ndarray, ds: np.ndarray, kind: np.ndarray, code: int) -> Pose:
    """``arc.evaluate`` at points of many arcs (the same operations, with each point's arc's numbers)."""
    chosen = np.flatnonzero(kind == code)
    x0, y0, hdg, k = (np.zeros(len(kind)) for _ in range(4))
    x0[chosen] = [elements[i].x for i in chosen]
    y0[chosen] = [elements[i].y for i in chosen]
    hdg[chosen] = [elements[i].hdg for i in chosen]
    k[chosen] = [elements[i].curvature for i in chosen]
    k_at, hdg_at = k[index], hdg[index]
    half_turn = (0.5 * k)[index] * ds
    chord = ds * np.sinc(half_turn / np.pi)
    direction = hdg_at + half_turn
    return Pose(
        x0[index] + chord * np.cos(direction),
        y0[index] + chord * np.sin(direction),
        hdg_at + k_at * ds,
        k_at.copy(),
        np.zeros_like(ds),
    )


# ------------------------------------------------------------------------------------------------------ profiles
class _Laws:
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
class _Lines:
    """Border lines of the entries at their samples, as flat pair arrays (see the module docstring)."""

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


def _lines(entries: Sequence[Entry], s: np.ndarray, offsets: np.ndarray) -> _Lines:
    """Plan-view lateral offset jets of every border line (lane 0's line and each lane's outer border) of each entry
    at its samples: :meth:`RoadGeometry._border_lines` without superelevation, for all entries at once."""
    counts = np.diff(offsets)
    ids: list[list[int]] = []
    laws = _Laws()
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
    return _Lines(ids, np.array(bases, dtype=np.int64), sample, q, dq, ddq, outer)


def _bend(lines: _Lines, pose: Pose) -> tuple[np.ndarray, np.ndarray]:
    """Plan-view speed and curvature of every pair's line (:meth:`RoadGeometry._bend`)."""
    at = lines.sample
    q, dq, ddq = lines.q, lines.dq, lines.ddq
    k, dk = pose.curvature[at], pose.dcurvature[at]
    a = 1.0 - q * k
    speed = np.hypot(a, dq)
    with np.errstate(divide="ignore", invalid="ignore"):
        return speed, (a * a * k + a * ddq + 2.0 * dq * dq * k + q * dq * dk) / speed**3


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
    pose = _pose(entries, s, offsets)
    if pose is None:
        return None
    lines = _lines(entries, s, offsets)
    speed, curvature = _bend(lines, pose)
    most = np.full(len(s), np.nan)
    np.fmax.at(most, lines.sample, np.abs(curvature) * speed**2)
    bending = np.fmax(np.abs(pose.curvature), most)
    elevation = _Laws()
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
    pose = _pose(entries, s, offsets)
    if pose is None:
        return None
    lines = _lines(entries, s, offsets)
    elevation = _Laws()
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
    lines = _lines(entries, np.concatenate(samples) if samples else np.zeros(0), offsets)
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
    pose = _pose(entries, s, offsets)
    if pose is None:
        return None
    lines = _lines(entries, s, offsets)
    elevation = _Laws()
    for k, (rg, _) in enumerate(entries):
        elevation.add(rg._elevation, int(offsets[k]), int(offsets[k]), int(counts[k]))
    z = (elevation.evaluate(s, len(s))[0] + 0.0)[lines.sample]
    at, q, dq = lines.sample, lines.q, lines.dq
    x = pose.x[at] - q * np.sin(pose.hdg)[at]
    y = pose.y[at] + q * np.cos(pose.hdg)[at]
    speed, curvature = _bend(lines, pose)
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
