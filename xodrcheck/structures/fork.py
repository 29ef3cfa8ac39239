"""The ``fork`` kind: one road splitting into two (a fork) or two joining into one (a merge), read from the file.

A junction is fork-shaped when it has three legs and one of them, the *stem*, is the only road that traffic comes
from (a split: the stem feeds both other legs, the *branches*) or goes to (a merge: both branches feed the stem):
every flow through the junction (:mod:`.flows`) joins the stem and a branch, none goes from one branch to the other,
and both branches leave within 90 degrees of straight on. A direct junction (12.6) is the standard's model of one;
a common junction with connecting roads qualifies too. Directions are the legs'
(:func:`xodrcheck.analysis.metrics.make_leg`: from the incident point to the point 50 m back along the road), so they
compare with the junction kind's angles.

Measures: ``split_angle``, the largest angle between the two branches' headings (away from the junction) at equal
distances along their roads up to :data:`REACH` metres (or the shorter road's end): the angle the branches part by,
whatever kind of junction carries them and whether they run on apart or come back beside each other; ``lanes_in``, lanes
of the stem that split (merge: that the branches fill); ``lanes_left`` and ``lanes_right``, lanes of each branch joined
to the stem in the fork's direction, left and right as a driver sees them (a split: looking from the stem into the
branches; a merge: driving towards the stem); ``merge`` (1 for a merge, 0 for a split); ``direct`` (1 for a direct
junction). A ramp (:mod:`.ramp`) is fork-shaped too and is recognised first."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from xodrcheck.analysis.metrics import Leg, leg_ends, make_leg
from xodrcheck.geometry.lanes import geometry_of
from xodrcheck.model import ContactPoint, Document, Junction, JunctionType, Road

from . import Kind, Measure, Structure
from .flows import Flow, flows

KIND = Kind(
    "fork",
    "one road splitting into two or two joining into one, lanes continuing on both",
    (
        Measure("split_angle", "deg", 0.0, 90.0, 18, "angle between the two branches"),
        Measure("lanes_in", "", 0.5, 6.5, 6, "lanes of the stem that split (or that the branches fill)"),
        Measure("lanes_left", "", 0.5, 3.5, 3, "lanes of the left branch"),
        Measure("lanes_right", "", 0.5, 3.5, 3, "lanes of the right branch"),
        Measure("merge", "", -0.5, 1.5, 2, "1 for a merge, 0 for a split"),
        Measure("direct", "", -0.5, 1.5, 2, "1 for a direct junction (12.6), 0 for a common one"),
    ),
)

End = tuple[str, ContactPoint]
#: Distance (m) along the branches within which their headings are compared for the split angle, every STEP m.
REACH = 100.0
STEP = 1.0


@dataclass(frozen=True)
class ForkShape:
    """A fork-shaped junction: its stem and branches (legs), whether it merges, its flows and the split angle."""

    junction: Junction
    stem: Leg
    left: Leg
    right: Leg
    merge: bool
    flows: tuple[Flow, ...]
    split_angle: float

    def branch_flows(self, leg: Leg) -> list[Flow]:
        """The flows between the stem and ``leg`` in the fork's direction (into a branch for a split, out of it for
        a merge)."""
        key = (leg.road, leg.end)
        end = (lambda f: f.source) if self.merge else (lambda f: f.target)
        return [f for f in self.flows if (end(f).road, end(f).end) == key]

    def branch_lanes(self, leg: Leg) -> int:
        """Distinct lanes of ``leg`` joined to the stem in the fork's direction."""
        key = (leg.road, leg.end)
        lanes = {x.lane for f in self.branch_flows(leg) for x in (f.source, f.target) if (x.road, x.end) == key}
        return len(lanes)

    @property
    def stem_lanes(self) -> int:
        """Distinct lanes of the stem joined to a branch in the fork's direction."""
        key = (self.stem.road, self.stem.end)
        lanes = set()
        for leg in (self.left, self.right):
            lanes |= {x.lane for f in self.branch_flows(leg) for x in (f.source, f.target) if (x.road, x.end) == key}
        return len(lanes)


def _direction(leg: Leg) -> np.ndarray:
    """The leg's direction out of the junction (unit vector, from the incident point back along the road)."""
    d = np.subtract(leg.p0, leg.p1)
    n = float(np.hypot(*d))
    return d / n if n > 0 else d


def _angle(a: np.ndarray, b: np.ndarray) -> float:
    return math.degrees(abs(math.atan2(a[0] * b[1] - a[1] * b[0], float(a @ b))))


def fork_shape(document: Document, junction: Junction) -> ForkShape | None:
    """The fork shape of ``junction`` (module docstring), or None when it has none."""
    ends = leg_ends(document, junction)
    if len(ends) != 3:
        return None
    through = flows(document, junction)
    pairs = {((f.source.road, f.source.end), (f.target.road, f.target.end)) for f in through}
    if not pairs:
        return None
    for stem in ends:
        branches = [e for e in ends if e != stem]
        if any((a, b) in pairs for a in branches for b in branches):
            continue  # traffic from one branch into the other: not with this stem
        split = all((stem, b) in pairs for b in branches)
        merge = all((b, stem) in pairs for b in branches)
        if split or merge:
            return _shape(document, junction, stem, branches, merge and not split, tuple(through))
    return None


def _shape(
    document: Document, junction: Junction, stem: End, branches: list[End], merge: bool, through: tuple[Flow, ...]
) -> ForkShape | None:
    geometries = geometry_of(document)
    if any(road not in geometries for road, _ in (stem, *branches)):
        return None
    legs = [make_leg(geometries[road], end) for road, end in (stem, *branches)]
    ahead = -_direction(legs[0])  # straight on through the junction from the stem
    out = [_direction(leg) for leg in legs[1:]]
    if any(_angle(ahead, d) >= 90.0 for d in out):
        return None
    # left and right as the driver sees them: the branch lying further left of the stem's line, looking from the
    # stem into the branches (a split), or from the branches towards the stem (a merge: the other way round)
    p1 = np.asarray(legs[0].p1)

    def lateral(leg: Leg) -> float:
        v = np.asarray(leg.p0) - p1
        return float(ahead[0] * v[1] - ahead[1] * v[0])

    a, b = legs[1], legs[2]
    left, right = (a, b) if (lateral(a) >= lateral(b)) != merge else (b, a)
    return ForkShape(junction, legs[0], left, right, merge, through, parting_angle(document, a, b))


def _distances(road: Road, end: ContactPoint, reach: float) -> np.ndarray:
    """Distances from the road's ``end`` to its plan-view elements' ends (where a heading made of lines and arcs
    turns back), within ``reach``."""
    ends = np.array([g.s for g in road.plan_view] + [road.length])
    d = ends if end is ContactPoint.START else road.length - ends
    return d[(d >= 0) & (d <= reach)]


def headings_out(document: Document, leg: Leg, at: np.ndarray) -> np.ndarray:
    """Headings (radians) of the leg's road at distances ``at`` from the junction, pointing away from it."""
    road = document.road_by_id[leg.road]
    at = np.clip(at, 0.0, road.length)
    s = at if leg.end is ContactPoint.START else road.length - at
    hdg = geometry_of(document)[road.id].reference(s).hdg
    return hdg + (math.pi if leg.end is ContactPoint.END else 0.0)


def parting_angle(document: Document, a: Leg, b: Leg, reach: float = REACH) -> float:
    """The largest angle (degrees) between the headings of the roads of legs ``a`` and ``b`` at equal distances
    from the junction, up to ``reach`` metres (or the shorter road's end): every :data:`STEP` metres and at each
    element end of either road."""
    ra, rb = document.road_by_id[a.road], document.road_by_id[b.road]
    top = min(reach, ra.length, rb.length)
    at = np.unique(
        np.concatenate([np.arange(0.0, top, STEP), [top], _distances(ra, a.end, top), _distances(rb, b.end, top)])
    )
    diff = np.abs((headings_out(document, a, at) - headings_out(document, b, at) + np.pi) % (2 * np.pi) - np.pi)
    return float(np.degrees(diff.max()))


def values(shape: ForkShape) -> tuple[tuple[str, float], ...]:
    return (
        ("split_angle", shape.split_angle),
        ("lanes_in", float(shape.stem_lanes)),
        ("lanes_left", float(shape.branch_lanes(shape.left))),
        ("lanes_right", float(shape.branch_lanes(shape.right))),
        ("merge", 1.0 if shape.merge else 0.0),
        ("direct", 1.0 if shape.junction.type is JunctionType.DIRECT else 0.0),
    )


def recognise(document: Document, free: Sequence[Junction]) -> list[Structure]:
    out = []
    for junction in free:
        shape = fork_shape(document, junction)
        if shape is not None:
            out.append(Structure(KIND.name, (junction.id,), values(shape)))
    return out
