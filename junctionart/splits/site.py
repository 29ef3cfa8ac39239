"""Where a fork or ramp pair fits on a road of a generated map, and how it is shaped there.

In a map (``fork_probability``, ``ramp_probability``) a structure is a *loop* beside a straight stretch of a road:
on the side of the lanes that drive along ``s``, the road's outermost lanes split off (a fork), or an exit lane widens
beside them and leaves as an off-ramp (a ramp); the branch runs out at ``angle``, along the road ``clearance``
metres beside it, and back, where it joins the road again (a merge; an on-ramp whose lanes go on as an entry lane,
narrowing away). Both joints are junctions (direct, or default with connecting roads). A fork that leaves its road no
lane needs a lane first: the road gains one over a taper before the split and loses it after the merge.

The branch's reference line starts at the border between the lanes staying and those leaving, with the road's
heading (12.6), and is: ``lead`` m straight, an arc of ``angle`` at ``radius`` away from the road, a straight run, an
arc back to parallel, ``middle`` m along the road, and the same mirrored back to the road. A *site* is the stretch of
one road's reference line (a single line element inside the lane section where its lane counts are constant, away
from its ends, objects and signals) the whole structure lies beside; it fits when the branch and its lanes keep
clear of every other road.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from ..curves import wrap
from ..opendrive import Geometry, Line, Road
from .geometry import Path, path, reverse
from .pieces import constant
from .spec import MIN_RADIUS

#: Metres a structure keeps from its road's lane-count changes (and so from its junctions) and from its objects.
MARGIN = 15.0
#: Metres before a split (after a merge) in which no one may change between the lanes of the two branches.
SOLID = 20.0


@dataclass(frozen=True)
class Design:
    """The shape of one structure (module docstring); lengths in metres, ``angle`` in radians."""

    kind: str  #: "fork" or "ramp"
    far_lanes: int  #: lanes of the branch
    added: bool  #: the road gains the branch's lanes before the split (an exit lane, or a lane for a fork)
    taper: float  #: length over which an added lane widens (narrows)
    beside: float  #: length an added lane runs at full width before the split (after the merge)
    lead: float
    angle: float
    radius: float
    clearance: float
    middle: float

    @property
    def run(self) -> float:
        """Straight run between the arcs, out and back."""
        s, c = math.sin(self.angle), math.cos(self.angle)
        return max(0.0, (self.clearance - 2 * self.radius * (1 - c)) / s)

    @property
    def leg(self) -> float:
        """Length along the road of the way out (and of the way back)."""
        return self.lead + 2 * self.radius * math.sin(self.angle) + self.run * math.cos(self.angle)

    @property
    def loop(self) -> float:
        """Length along the road from the split to the merge."""
        return 2 * self.leg + self.middle

    @property
    def before(self) -> float:
        """Length along the road before the split that the structure uses (and after the merge)."""
        return self.taper + self.beside if self.added else SOLID

    @property
    def length(self) -> float:
        return 2 * self.before + self.loop


def design(kind: str, lanes_forward: int, angle_deg: float, lane_width: float, roadside: float) -> Design:
    """The structure of ``kind`` on a road with ``lanes_forward`` lanes driving along ``s``, turning out at
    ``angle_deg``; ``roadside``: width of the lanes beyond its outer driving lane (they go with the branch)."""
    angle = math.radians(angle_deg)
    if kind == "ramp":
        added, far, taper, beside, lead, clearance, middle = True, 1, 30.0, 20.0, 10.0, 12.0, 20.0
    else:
        added = lanes_forward < 2
        far, taper, beside, lead, clearance, middle = 1, 25.0, 10.0, 0.0, 8.0, 10.0
    width = far * lane_width + roadside
    clearance = max(clearance, roadside + 4.0)
    radius = max(MIN_RADIUS + width + 1.0, min(40.0, clearance / (2 * (1 - math.cos(angle)))))
    return Design(kind, far, added, taper, beside, lead, angle, radius, clearance, middle)


def loop_path(d: Design, x: float, y: float, hdg: float, away: int) -> Path:
    """The branch's reference line from (x, y) facing ``hdg`` (the split) to the merge; ``away``: -1 when the branch
    lies to the right of the road."""
    out = path(x, y, hdg, away * d.angle, d.radius, d.lead, d.lead + d.angle * d.radius + d.run)
    half = _extend(out, -away * d.angle, d.radius, d.middle / 2)
    # the way back is the way out mirrored: built from the merge backwards, then reversed and joined
    c, s = math.cos(hdg), math.sin(hdg)
    ex, ey = x + d.loop * c, y + d.loop * s
    back = path(ex, ey, hdg + math.pi, -away * d.angle, d.radius, d.lead, d.lead + d.angle * d.radius + d.run)
    back = _extend(back, away * d.angle, d.radius, d.middle / 2)
    return _join(half, reverse(back))


def _extend(p: Path, turn: float, radius: float, straight: float) -> Path:
    from ..curves import end_pose

    e = end_pose(p[-1])
    s = sum(g.length for g in p)
    more = path(e.x, e.y, e.hdg, turn, radius, 0.0, abs(turn) * radius + straight)
    return (*p, *(replace(g, s=g.s + s) for g in more))


def _join(a: Path, b: Path) -> Path:
    """``a`` then ``b``; where both meet with a straight line of one heading, one line."""
    s = sum(g.length for g in a)
    tail = [replace(g, s=g.s + s) for g in b]
    last, first = a[-1], tail[0]
    if isinstance(last, Line) and isinstance(first, Line) and abs(wrap(last.hdg - first.hdg)) < 1e-9:
        return (*a[:-1], replace(last, length=last.length + first.length), *tail[1:])
    return (*a, *tail)


@dataclass(frozen=True)
class Stretch:
    """Where a structure may lie on a road: road s from ``s0`` to ``s1`` on one line element, inside lane section
    ``section``."""

    road: Road
    line: Line
    section: int
    s0: float
    s1: float


def stretch(road: Road) -> Stretch | None:
    """The longest stretch of ``road`` (module docstring), or None when it has none."""
    if road.junction != "-1" or road.bridges or (road.predecessor is not None and road.predecessor == road.successor):
        return None  # a road whose both ends meet one junction: renaming its far end would be ambiguous
    best: Stretch | None = None
    for k, sec in enumerate(road.sections):
        a = sec.s + MARGIN if k > 0 else MARGIN
        b = (road.sections[k + 1].s if k + 1 < len(road.sections) else road.length) - MARGIN
        if b - a <= 0 or not constant(sec):
            continue
        for g in road.geometry:
            if not isinstance(g, Line):
                continue
            lo, hi = max(a, g.s), min(b, g.s + g.length)
            for at in [o.s for o in road.objects] + [x.s for x in road.signals]:  # keep clear of what stands there
                if lo - MARGIN < at < hi + MARGIN:
                    if at - lo > hi - at:
                        hi = min(hi, at - MARGIN)
                    else:
                        lo = max(lo, at + MARGIN)
            if hi - lo > (best.s1 - best.s0 if best else 0.0):
                best = Stretch(road, g, k, lo, hi)
    return best


def point_on(g: Geometry, s: float) -> tuple[float, float, float]:
    """(x, y, hdg) of road s ``s`` on line element ``g``."""
    assert isinstance(g, Line)
    d = s - g.s
    return g.x + d * math.cos(g.hdg), g.y + d * math.sin(g.hdg), g.hdg
