"""A road of a generated map cut into pieces around a fork or ramp: its cross-section as lane templates, lane sections
built from them with lanes linked by name, and road marks and profiles clipped to a piece.

A *template* is one lane of the road's middle lane section (where its lane counts and widths are constant), named by
side and position (``F1``, ``F2``... on the side whose lanes drive along ``s``, ``B1``... on the other), or a lane the
structure adds (``X1``... its far lanes). A piece's lane sections list templates per side from the reference line
outward; lane ids follow from the positions, links from the names: a lane links to the lane of the same name in the
neighbouring section unless it widens from zero at their border (or narrows to zero).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from ..opendrive import Cubic, Lane, LaneHeight, LaneSection, RoadMark
from .lanes import width

#: Lane types of drivable lanes the generator writes.
DRIVABLE = frozenset({"driving", "exit", "entry", "offRamp", "onRamp"})


@dataclass(frozen=True)
class LaneT:
    """A lane as a template: its name, type, constant width, road marks (``sOffset`` from ``origin`` along the road)
    and heights."""

    key: str
    type: str
    width: float
    marks: tuple[RoadMark, ...] = ()
    heights: tuple[LaneHeight, ...] = ()
    origin: float = 0.0  #: road s the marks' sOffsets count from

    @property
    def drivable(self) -> bool:
        return self.type in DRIVABLE


@dataclass(frozen=True)
class Use:
    """A template in one section: full width, or widening from zero (``grow``) or narrowing to zero (``shrink``)
    over it; ``mark``: a road mark replacing the template's own (``"solid"``, ``"broken"``) in this section."""

    lane: LaneT
    grow: bool = False
    shrink: bool = False
    mark: str | None = None


@dataclass(frozen=True)
class Span:
    """One lane section of a piece: ``length`` m from road s ``at`` (for clipping the templates' marks), the lanes
    on the side driving along ``s`` and on the other, from the reference line outward, and the centre lane."""

    length: float
    at: float
    forward: tuple[Use, ...]
    backward: tuple[Use, ...]
    centre: Lane


def templates(section: LaneSection, forward_side: int, origin: float) -> tuple[list[LaneT], list[LaneT]]:
    """The lanes of ``section`` (starting at road s ``origin``) as templates, (forward side, other side), each from
    the reference line outward."""
    sides = []
    for sign, letter in ((forward_side, "F"), (-forward_side, "B")):
        lanes = sorted(section.left if sign > 0 else section.right, key=lambda lane: abs(lane.id))
        sides.append(
            [
                LaneT(f"{letter}{k}", lane.type, lane.widths[0].a, lane.marks, lane.heights, origin)
                for k, lane in enumerate(lanes, start=1)
            ]
        )
    return sides[0], sides[1]


def constant(section: LaneSection) -> bool:
    """Whether every lane of ``section`` has one constant width record."""
    lanes = (*section.left, *section.right)
    return all(
        len(lane.widths) == 1 and lane.widths[0].b == lane.widths[0].c == lane.widths[0].d == 0 for lane in lanes
    )


def clip_marks(marks: tuple[RoadMark, ...], origin: float, a: float, b: float) -> tuple[RoadMark, ...]:
    """Marks whose ``sOffset`` counts from road s ``origin``, clipped to road s [a, b) and counted from ``a``."""
    if not marks:
        return ()
    active = [m for m in marks if origin + m.s <= a + 1e-9]
    first = active[-1] if active else marks[0]
    out = [replace(first, s=0.0)]
    out += [replace(m, s=origin + m.s - a) for m in marks if a + 1e-9 < origin + m.s < b - 1e-9]
    return tuple(out)


def _simple(kind: str, color: str = "standard") -> tuple[RoadMark, ...]:
    return (RoadMark(0.0, kind, color, lane_change="none" if kind == "solid" else "both"),)


def _lane(use: Use, lane_id: int, span: Span, pred: int | None, succ: int | None) -> Lane:
    t = use.lane
    if use.mark is not None:
        marks = _simple(use.mark)
    else:
        marks = clip_marks(t.marks, t.origin, span.at, span.at + span.length) or _simple("solid")
    return Lane(lane_id, t.type, (width(t.width, use.grow, use.shrink, span.length),), marks, pred, succ, t.heights)


def sections(
    spans: list[Span],
    forward_side: int,
    first_links: dict[str, int] | None = None,
    last_links: dict[str, int] | None = None,
    s0: float = 0.0,
) -> list[LaneSection]:
    """Lane sections of ``spans`` from road s ``s0``, linked by name; ``first_links`` / ``last_links``: lane name ->
    the id its lane links to before the first span (after the last) in lane sections not built here."""
    out = []
    s = s0
    for k, span in enumerate(spans):
        prev = spans[k - 1] if k > 0 else None
        nxt = spans[k + 1] if k + 1 < len(spans) else None
        lanes: dict[int, list[Lane]] = {1: [], -1: []}
        for sign, uses, pick in ((forward_side, span.forward, "forward"), (-forward_side, span.backward, "backward")):
            before = (
                {u.lane.key: sign * i for i, u in enumerate(getattr(prev, pick), 1) if not u.shrink} if prev else None
            )
            after = {u.lane.key: sign * i for i, u in enumerate(getattr(nxt, pick), 1) if not u.grow} if nxt else None
            for i, use in enumerate(uses, start=1):
                key = use.lane.key
                pred = _neighbour(key, before, first_links, use.grow)
                succ = _neighbour(key, after, last_links, use.shrink)
                lanes[sign].append(_lane(use, sign * i, span, pred, succ))
        left = tuple(sorted(lanes[1], key=lambda lane: lane.id))
        right = tuple(sorted(lanes[-1], key=lambda lane: -lane.id))
        out.append(LaneSection(s, left, span.centre, right))
        s += span.length
    return out


def _neighbour(key: str, built: dict[str, int] | None, outside: dict[str, int] | None, zero: bool) -> int | None:
    """The id lane ``key`` links to: in the neighbouring built section (none where it is zero wide at the border),
    or outside the built sections."""
    if built is None:
        return (outside or {}).get(key)
    return None if zero else built.get(key)


def shift_sections(sections: tuple[LaneSection, ...], by: float) -> list[LaneSection]:
    """Lane sections moved ``by`` metres along ``s`` (their records count from their own start)."""
    return [replace(sec, s=sec.s + by) for sec in sections]


def clip_profile(profile: tuple[Cubic, ...], a: float, b: float) -> tuple[Cubic, ...]:
    """A road-level cubic profile (``s`` absolute) over [a, b), re-expressed from s = 0 at ``a``."""
    if not profile:
        return ()
    active = [c for c in profile if c.s <= a + 1e-9] or [profile[0]]
    c = active[-1]
    ds = a - c.s
    first = Cubic(
        0.0,
        c.a + ds * (c.b + ds * (c.c + ds * c.d)),
        c.b + ds * (2 * c.c + 3 * c.d * ds),
        c.c + 3 * c.d * ds,
        c.d,
    )
    return (first, *(replace(x, s=x.s - a) for x in profile if a + 1e-9 < x.s < b - 1e-9))


def profile_at(profile: tuple[Cubic, ...], s: float) -> tuple[float, float]:
    """(value, slope) of a road-level profile at road s ``s`` (0, 0 without one)."""
    if not profile:
        return 0.0, 0.0
    c = ([x for x in profile if x.s <= s + 1e-9] or [profile[0]])[-1]
    ds = s - c.s
    return c.a + ds * (c.b + ds * (c.c + ds * c.d)), c.b + ds * (2 * c.c + 3 * c.d * ds)


def hermite(z0: float, g0: float, z1: float, g1: float, length: float) -> tuple[Cubic, ...]:
    """The cubic from height ``z0`` and grade ``g0`` to ``z1`` and ``g1`` over ``length``; flat ground gives the
    generator's flat profile (none)."""
    if z0 == z1 == g0 == g1 == 0.0:
        return ()
    L = length
    c = (3 * (z1 - z0) - (2 * g0 + g1) * L) / L**2
    d = (2 * (z0 - z1) + (g0 + g1) * L) / L**3
    return (Cubic(0.0, z0, g0, c, d),)
