"""Lane sections of the roads of a fork, merge or ramp: groups of lanes of one type, tapers, marks and links.

A road's cross-section is a list of :class:`Group` values on each side of its reference line, from the reference line
outward; a group's lanes are full width, or widen from zero (``grow``) or narrow to zero (``shrink``) over the
section. Marks: each lane's outer border is broken between lanes of one direction, solid at the side's edge and
wherever ``solid`` asks (before a split nobody may change between the lanes of the two branches); the centre line is
solid yellow on a two-way road, solid white on a one-way road; connecting roads carry no marks.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..opendrive import Cubic, Lane, LaneSection, RoadMark


@dataclass(frozen=True)
class Group:
    """``count`` lanes of one type on one side, full width unless they ``grow`` from or ``shrink`` to zero over the
    section; ``solid``: the border outside the group's last lane is solid (no lane change across it)."""

    count: int
    type: str = "driving"
    grow: bool = False
    shrink: bool = False
    solid: bool = False


def width(w: float, grow: bool, shrink: bool, length: float) -> Cubic:
    """A lane's width over a section: constant, or a smooth cubic from 0 to ``w`` (or ``w`` to 0) with zero slope at
    both ends."""
    if grow == shrink:
        return Cubic(0.0, w)
    a, d = (0.0, w) if grow else (w, -w)
    return Cubic(0.0, a, 0.0, 3 * d / length**2, -2 * d / length**3)


def _mark(kind: str, marks: bool, color: str = "standard") -> tuple[RoadMark, ...]:
    if not marks:
        return (RoadMark(0.0, "none"),)
    return (RoadMark(0.0, kind, color, lane_change="none" if kind == "solid" else "both"),)


@dataclass(frozen=True)
class Span:
    """A stretch of road ``length`` long and its groups: ``forward`` on the side whose lanes drive along ``s``,
    ``backward`` on the other."""

    length: float
    forward: tuple[Group, ...]
    backward: tuple[Group, ...] = ()


def _count(groups: tuple[Group, ...]) -> int:
    return sum(g.count for g in groups)


def _side(
    span: Span, groups: tuple[Group, ...], sign: int, w: float, marks: bool, before: int | None, after: int | None
) -> list[Lane]:
    """The lanes of one side (``sign`` +1 left, -1 right); ``before`` / ``after``: lanes of that side in the previous
    and next span (None where there is none), for the links."""
    out = []
    k = 0
    total = _count(groups)
    for g in groups:
        for i in range(g.count):
            k += 1
            edge = k == total or (i == g.count - 1 and g.solid)
            pred = sign * k if before is not None and k <= before and not g.grow else None
            succ = sign * k if after is not None and k <= after and not g.shrink else None
            out.append(
                Lane(
                    sign * k,
                    g.type,
                    (width(w, g.grow, g.shrink, span.length),),
                    _mark("solid" if edge else "broken", marks),
                    pred,
                    succ,
                )
            )
    return out


def sections(spans: list[Span], forward_side: int, w: float, marks: bool = True) -> tuple[LaneSection, ...]:
    """The lane sections of a road made of ``spans`` (in order along ``s``), linked lane to lane where a lane goes on
    at non-zero width."""
    out = []
    s = 0.0
    for k, span in enumerate(spans):
        prev = spans[k - 1] if k > 0 else None
        nxt = spans[k + 1] if k + 1 < len(spans) else None
        lanes: dict[int, list[Lane]] = {}
        for sign, groups, pick in ((forward_side, span.forward, "forward"), (-forward_side, span.backward, "backward")):
            before = _count(getattr(prev, pick)) if prev is not None else None
            after = _count(getattr(nxt, pick)) if nxt is not None else None
            lanes[sign] = _side(span, groups, sign, w, marks, before, after)
        two_way = bool(span.forward) and bool(span.backward)
        centre = Lane(0, "none", (), _mark("solid", marks, "yellow" if two_way else "standard"))
        left = tuple(sorted(lanes[1], key=lambda lane: lane.id))
        right = tuple(sorted(lanes[-1], key=lambda lane: -lane.id))
        out.append(LaneSection(s, left, centre, right))
        s += span.length
    return tuple(out)
