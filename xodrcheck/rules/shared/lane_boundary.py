"""Lanes linked across a lane-section boundary inside a road, for ``lane-border-discontinuous`` (``L101``,
:mod:`xodrcheck.rules.link`): the lane links across the boundary, which lanes must meet (a lane and the lane it
continues as, or the band of lanes side by side it splits into or merges from), the band a lane should have been
linked to all of, the heights of their edges, and how the finding words lanes and changes.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator

from xodrcheck.geometry.lanes import RoadGeometry
from xodrcheck.model import LaneSection
from xodrcheck.rules.shared.sampled import SectionLines


def boundary_links(before: LaneSection, after: LaneSection) -> dict[tuple[int, int], int]:
    """The lane links across the boundary between two consecutive sections, ``(lane before, lane after) -> line``: the
    earlier lanes' ``<successor>`` records, then the later lanes' ``<predecessor>`` records (a link given both ways
    keeps the first one's line)."""
    pairs: dict[tuple[int, int], int] = {}
    for lane in before.lanes:
        for nxt in lane.successors:
            pairs.setdefault((lane.id, nxt), lane.line)
    for lane in after.lanes:
        for prev in lane.predecessors:
            pairs.setdefault((prev, lane.id), lane.line)
    return pairs


def inner_pairs(side):
    """(id of the lane whose outer border is the inner border, lane) for the lanes of one side, inner to outer."""
    inner = 0
    for lane in side.lanes:
        yield inner, lane
        inner = lane.id


def unlinked_band(lane_id, want, lines, inner_of, linked, k, tol) -> tuple[int, int] | None:
    """Lanes side by side around ``lane_id`` whose others have no link across the boundary and whose band's inner
    and outer border at sample ``k`` are ``want`` (within ``tol``): what a lane split into (or merged from) when it
    should have linked them all. ``None`` when there is no such band."""
    sign = 1 if lane_id > 0 else -1
    inward, outward = [lane_id], [lane_id]
    while (nxt := inward[-1] - sign) * sign > 0 and nxt in lines.t and nxt not in linked:
        inward.append(nxt)
    while (nxt := outward[-1] + sign) in lines.t and nxt not in linked:
        outward.append(nxt)
    for inner in inward:
        for outer in outward:
            if inner == outer == lane_id:
                continue
            band = (float(lines.t[inner_of[inner]][k]), float(lines.t[outer][k]))
            if max(abs(p - q) for p, q in zip(band, want)) <= tol:
                return inner, outer
    return None


def link_groups(pairs: dict[tuple[int, int], int]) -> Iterator[tuple[tuple[int, int, int, int], int]]:
    """What must meet across a lane-section boundary, from the lane links ``(before, after) -> line``.

    A lane linked to one lane: the two lanes. A lane split into several lanes side by side (several successors), or
    several lanes side by side merged into one (``road.lane.link.multiple_connections``): the lane and the band the
    others cover together. Yields ``(innermost before, outermost before, innermost after, outermost after)`` with the
    line of the first link; a band that is not side by side on one side (reported by ``lane-links-ambiguous`` and
    ``lane-link-direction``) falls back to its single links.
    """
    after_of: dict[int, list[int]] = {}
    before_of: dict[int, list[int]] = {}
    for a, b in sorted(pairs):
        after_of.setdefault(a, []).append(b)
        before_of.setdefault(b, []).append(a)
    done: set[tuple[int, int]] = set()
    for a, targets in sorted(after_of.items()):
        band = _band(targets) if len(targets) > 1 and all(len(before_of[b]) == 1 for b in targets) else None
        if band is not None:
            inner, outer = band
            done.update((a, b) for b in targets)
            yield (a, a, inner, outer), pairs[(a, targets[0])]
    for b, sources in sorted(before_of.items()):
        band = _band(sources) if len(sources) > 1 and all(len(after_of[a]) == 1 for a in sources) else None
        if band is not None:
            inner, outer = band
            done.update((a, b) for a in sources)
            yield (inner, outer, b, b), pairs[(sources[0], b)]
    for (a, b), line in sorted(pairs.items()):
        if (a, b) not in done:
            yield (a, a, b, b), line


def _band(ids: list[int]) -> tuple[int, int] | None:
    """(innermost, outermost) of lane ids side by side on one side of the centre, else ``None``."""
    ordered = sorted(ids, key=abs)
    sign = 1 if ordered[0] > 0 else -1
    if any(i * sign <= 0 for i in ordered) or any(abs(q) - abs(p) != 1 for p, q in itertools.pairwise(ordered)):
        return None
    return ordered[0], ordered[-1]


def lanes_text(inner: int, outer: int) -> str:
    """A lane, or a band of lanes, in words."""
    return f"lane {inner}" if inner == outer else f"lanes {inner} to {outer}"


def group_heights(
    geometry: RoadGeometry, lines: SectionLines, index: int, inner: int, outer: int, inner_of: dict, k: int
) -> tuple[float, float]:
    """z of the inner edge of lane ``inner`` and of the outer edge of lane ``outer`` (the same lane, or a band)."""
    z_inner = _edge_heights(geometry, lines, index, inner, inner_of[inner], k)[0]
    z_outer = _edge_heights(geometry, lines, index, outer, inner_of[outer], k)[1]
    return z_inner, z_outer


def change_text(before: tuple[float, float], after: tuple[float, float]) -> str:
    """How an (inner, outer) pair of values changes across the boundary, in words."""
    return f"inner {before[0]:.3f} -> {after[0]:.3f}, outer {before[1]:.3f} -> {after[1]:.3f}"


def _edge_heights(
    geometry: RoadGeometry, lines: SectionLines, index: int, lane_id: int, inner_id: int, k: int
) -> tuple[float, float]:
    """z of a lane's inner and outer edge at sample ``k`` of its section's lines, lane height included."""
    if geometry.has_height(index, lane_id):
        s = lines.s[k:][:1]
        edges = (geometry.lane_points(index, lane_id, s, where, raised=True) for where in ("inner", "outer"))
        inner, outer = (float(points.z[0]) for points in edges)
        return inner, outer
    return float(lines.borders[inner_id].z[k]), float(lines.borders[lane_id].z[k])
