"""Reference lines of forks and ramps: straight leads, one arc, straight tails; reversed, offset, cut in two.

Every path is made of :class:`~junctionart.opendrive.Line` and :class:`~junctionart.opendrive.Arc` elements only, so
cutting and reversing it is exact: the pieces meet with the same position and heading to the last bit the formulas
give.
"""

from __future__ import annotations

import math
from dataclasses import replace

from ..curves import end_pose, wrap
from ..opendrive import Arc, Geometry, Line

Path = tuple[Geometry, ...]


def offset(x: float, y: float, hdg: float, t: float) -> tuple[float, float]:
    """The point ``t`` metres left of (x, y) facing ``hdg``."""
    return x - t * math.sin(hdg), y + t * math.cos(hdg)


def path(x: float, y: float, hdg: float, turn: float, radius: float, lead: float, length: float) -> Path:
    """From (x, y) facing ``hdg``: ``lead`` m straight, an arc turning ``turn`` radians (positive: to the left) at
    ``radius``, then straight on to ``length`` m in all (``length`` must cover the lead and the arc)."""
    out: list[Geometry] = []
    s = 0.0
    if lead > 0:
        out.append(Line(0.0, x, y, hdg, lead))
        s = lead
    if turn != 0.0:
        arc = abs(turn) * radius
        p = end_pose(out[-1]) if out else None
        x0, y0, h0 = (p.x, p.y, p.hdg) if p is not None else (x, y, hdg)
        out.append(Arc(s, x0, y0, h0, arc, math.copysign(1.0 / radius, turn)))
        s += arc
    rest = length - s
    if rest > 1e-9 or not out:
        p = end_pose(out[-1]) if out else None
        x0, y0, h0 = (p.x, p.y, p.hdg) if p is not None else (x, y, hdg)
        out.append(Line(s, x0, y0, h0, max(rest, 0.0)))
    return tuple(out)


def length_of(p: Path) -> float:
    return sum(g.length for g in p)


def _restart(g: Geometry, s: float, x: float, y: float, hdg: float, length: float) -> Geometry:
    if isinstance(g, Line):
        return Line(s, x, y, hdg, length)
    assert isinstance(g, Arc)
    return Arc(s, x, y, hdg, length, g.curvature)


def reverse(p: Path) -> Path:
    """The same curve run the other way: it starts where ``p`` ends, facing back."""
    out: list[Geometry] = []
    s = 0.0
    for g in reversed(p):
        e = end_pose(g)
        if isinstance(g, Line):
            out.append(Line(s, e.x, e.y, wrap(e.hdg + math.pi), g.length))
        else:
            assert isinstance(g, Arc)
            out.append(Arc(s, e.x, e.y, wrap(e.hdg + math.pi), g.length, -g.curvature))
        s += g.length
    return tuple(out)


def cut(p: Path, at: float) -> tuple[Path, Path]:
    """``p`` cut at arc length ``at`` (0 < at < its length) into two paths, each starting at s = 0; the element cut
    must be a line or an arc (the others are only moved along s)."""
    head: list[Geometry] = []
    tail: list[Geometry] = []
    for g in p:
        if g.s + g.length <= at + 1e-9:
            head.append(g)
        elif g.s >= at - 1e-9:
            tail.append(g)
        else:  # the cut falls inside this element
            first = _restart(g, g.s, g.x, g.y, g.hdg, at - g.s)
            head.append(first)
            e = end_pose(first)
            tail.append(_restart(g, at, e.x, e.y, e.hdg, g.s + g.length - at))
    start = tail[0].s
    tail = [replace(g, s=g.s - start) for g in tail]
    return tuple(head), tuple(tail)
