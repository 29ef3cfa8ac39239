"""Signal control (``V0xx``): what the signals of one controller release together in a junction.

A ``<controller>`` (14.6) maps dynamic signals to one signal group: they always show the same aspect, so everything
they control goes (or stops) together. A junction's ``<controller>`` references (12.14) gather those groups into one
synchronisation group. This module finds the movements a traffic light releases and compares those of one group.

Which connection lanes a signal controls (the interpretation; the standard says where a signal stands and which lanes
it is valid for, 14.2, not which junction movements it governs):

* a *vehicle traffic light* is a signal with ``dynamic="yes"`` that is not one of the signal reference's pedestrian
  or bicycle lights (:data:`NOT_FOR_VEHICLES`); each ``<signal>`` and each ``<signalReference>`` to it (14.5) is a
  placement of the light on its road;
* the lanes of a placement are its ``<validity>`` lanes, or without one every drivable lane of the road whose traffic
  runs in the ``@orientation`` direction (14.2) at the placement's ``s``; each is followed by its lane links to the
  road's end its traffic drives towards;
* when that end links to a junction, the placement controls the connection lanes the junction's ``<laneLink>`` s
  enter from those lanes (12.3): the light stands on the incoming road before the junction.

Limits: placements on a junction's connecting roads, and lights whose lanes end at a road link (the junction being
further on), control nothing here; a lane with several lane links across a lane section is not followed; the meaning of
``<control type>`` is the application's (14.6) and is not read.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.model import ContactPoint, ElementType, Junction, JunctionType, Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared.context import Context, travel_direction
from xodrcheck.rules.shared.lane_paths import centre_path, parted

if TYPE_CHECKING:  # pragma: no cover - the model's signal module loads for a file with signals
    from xodrcheck.model import Controller, LaneValidity

#: Dynamic signals of the OpenDRIVE signal reference that are not for vehicles on the lanes they stand beside:
#: pedestrian light (1000002, the spec's own example of 14.4), pedestrian and bicycle light (1000007), bicycle light
#: (1000013).
NOT_FOR_VEHICLES = frozenset({"1000002", "1000007", "1000013"})


@dataclass(frozen=True)
class Placement:
    """One vehicle traffic light on one road: a ``<signal>`` or a ``<signalReference>`` to it."""

    signal: str
    road: str
    s: float | None
    line: int
    orientation: str | None
    validities: tuple[LaneValidity, ...]
    reference: bool = False  #: placed by a ``<signalReference>``

    def describe(self) -> str:
        where = f"s={self.s:.3f}" if self.s is not None else "s unknown"
        what = "signalReference to signal" if self.reference else "signal"
        return f"{what} {self.signal} (road {self.road}, {where}, line {self.line})"


@dataclass(frozen=True)
class Movement:
    """A connection lane released by a placement: from ``lane`` of road ``incoming`` into ``road`` lane ``to_lane``."""

    junction: Junction
    incoming: str
    lane: int
    road: Road
    to_lane: int
    xy: np.ndarray  # (n, 2) centre line from the contact point on

    def describe(self) -> str:
        return f"road {self.incoming} lane {self.lane} -> connecting road {self.road.id} lane {self.to_lane}"


def is_vehicle_light(dynamic: str | None, kind: str | None) -> bool:
    return (dynamic or "").strip().lower() in ("yes", "true") and (kind or "").strip() not in NOT_FOR_VEHICLES


def _written(record: Any, name: str) -> str | None:
    """An enumerated attribute as the file wrote it (``None``: absent); a yes/no one as ``yes`` or ``no``."""
    value = getattr(record, name)
    if value is None:
        return record.xml.text(name)
    if isinstance(value, bool):
        return "yes" if value else "no"
    return value.value


def placements(ctx: Context) -> dict[str, list[Placement]]:
    """Signal id -> the placements of that vehicle traffic light (its signal first, then its references)."""
    out: dict[str, list[Placement]] = {}
    roads = ctx.document.roads
    for sig in (signal for road in roads for signal in road.signals):
        if sig.id is not None and is_vehicle_light(_written(sig, "dynamic"), sig.type) and sig.id not in out:
            where = (sig.road, sig.s, sig.line, _written(sig, "orientation"), sig.validities)
            out[sig.id] = [Placement(sig.id, *where)]
    for ref in (ref for road in roads for ref in road.signal_references):
        if ref.id is not None and ref.id in out:
            where = (ref.road, ref.s, ref.line, _written(ref, "orientation"), ref.validities)
            out[ref.id].append(Placement(ref.id, *where, True))
    return out


def _lanes(road: Road, p: Placement) -> list[tuple[int, int]]:
    """(section index, lane id) of the lanes the placement is valid for, at its ``s``."""
    sections = road.lane_sections
    s = p.s if p.s is not None else 0.0
    index = max((k for k, sec in enumerate(sections) if sec.s <= s + 1e-9), default=0)
    section = sections[index]
    if p.validities:
        ids = {
            k
            for v in p.validities
            if v.from_lane is not None and v.to_lane is not None
            for k in range(v.from_lane, v.to_lane + 1)
        }
        return [(index, k) for k in sorted(ids) if k != 0 and section.lane(k) is not None]
    want = {"+": (1,), "-": (-1,)}.get((p.orientation or "").strip(), (1, -1))
    return [(index, lane.id) for lane in section.lanes if lane.drivable and travel_direction(road, lane) in want]


def _to_end(road: Road, index: int, lane_id: int) -> tuple[ContactPoint, int] | None:
    """The road end the lane's traffic drives towards and the lane's id in the section there."""
    start = road.lane_sections[index].lane(lane_id)
    direction = None if start is None else travel_direction(road, start)
    if direction is None:
        return None
    step = direction
    current: int | None = lane_id
    k = index
    while 0 <= k + step < len(road.lane_sections):
        lane = road.lane_sections[k].lane(current) if current is not None else None
        links = (lane.successors if step > 0 else lane.predecessors) if lane is not None else ()
        if len(links) != 1:
            return None
        current, k = links[0], k + step
    if current is None or road.lane_sections[k].lane(current) is None:
        return None
    return (ContactPoint.END if step > 0 else ContactPoint.START), current


def movements(ctx: Context, p: Placement, cache: dict) -> list[Movement]:
    """The connection lanes the placement releases (see the module's interpretation)."""
    road = ctx.road(p.road)
    if road is None or not road.lane_sections or ctx.usable_geometry(road) is None:
        return []
    out: list[Movement] = []
    for index, lane_id in _lanes(road, p):
        reached = _to_end(road, index, lane_id)
        if reached is None:
            continue
        end, end_lane = reached
        link = road.link_at(end)
        if link is None or link.element_type is not ElementType.JUNCTION:
            continue
        junction = ctx.junction(link.element_id)
        if junction is None or junction.type is JunctionType.DIRECT:
            continue
        for c in ctx.connections_by_incoming.get((junction.id, road.id), ()):
            if ctx.incoming_contact(junction, c) is not end or c.contact_point is None:
                continue
            connecting = ctx.road(c.connecting_road)
            if connecting is None or ctx.usable_geometry(connecting) is None:
                continue
            for ll in c.lane_links:
                if ll.from_lane != end_lane:
                    continue
                key = (connecting.id, ll.to_lane, c.contact_point)
                if key not in cache:
                    cache[key] = centre_path(ctx, connecting, ll.to_lane, c.contact_point)
                xy = cache[key]
                if xy is not None:
                    out.append(Movement(junction, road.id, end_lane, connecting, ll.to_lane, xy))
    return out


def crossing(a: Movement, b: Movement, tol: float) -> np.ndarray | None:
    """Where two connection lanes cross, leaving out a shared start (a diverge: both leave the same incoming lane)
    and a shared end (a merge into the same lane); ``None`` when they do not meet otherwise."""
    import shapely  # here: shapely loads only for controllers whose lights release something

    if a.road.id == b.road.id and a.to_lane == b.to_lane:
        return None
    pa, pb = a.xy, b.xy
    if a.incoming == b.incoming and a.lane == b.lane:
        ta, tb = parted(pa, shapely.LineString(pb), tol), parted(pb, shapely.LineString(pa), tol)
        if ta is None or tb is None:
            return None
        pa, pb = ta, tb
    if float(np.hypot(*(pa[-1] - pb[-1]))) <= tol:
        ra, rb = parted(pa[::-1], shapely.LineString(pb), tol), parted(pb[::-1], shapely.LineString(pa), tol)
        if ra is None or rb is None:
            return None
        pa, pb = ra[::-1], rb[::-1]
    meet = shapely.intersection(shapely.LineString(pa), shapely.LineString(pb))
    if meet.is_empty:
        return None
    return shapely.get_coordinates(meet)[0]


def _released(
    ctx: Context, controller: Controller, lights: dict[str, list[Placement]], cache: dict
) -> list[tuple[list[Placement], list[Movement]]]:
    """The controller's placements that release something, those releasing the same connection lanes together (the
    near-side and far-side heads of one approach): (placements, movements), in control order."""
    groups: dict[frozenset, tuple[list[Placement], list[Movement]]] = {}
    seen: set[str] = set()
    for control in controller.controls:
        if control.signal_id not in lights or control.signal_id in seen:
            continue
        seen.add(control.signal_id)
        for p in lights[control.signal_id]:
            moves = movements(ctx, p, cache)
            key = frozenset((m.junction.id, m.road.id, m.to_lane) for m in moves)
            if key:
                groups.setdefault(key, ([], moves))[0].append(p)
    return list(groups.values())


def _conflicts(
    ctx: Context, controller: Controller, lights: dict[str, list[Placement]], cache: dict
) -> Iterator[tuple[list[Placement], list[Placement], Movement, Movement, np.ndarray, int]]:
    """(placements, placements, movement, movement, crossing point, crossing pairs) per two sets of the controller's
    placements whose movements cross in one junction (the first crossing pair, and how many there are)."""
    tol = ctx.tolerances.junction_start
    released = _released(ctx, controller, lights, cache)
    for i, (p, moves_p) in enumerate(released):
        for q, moves_q in released[i + 1 :]:
            first = None
            count = 0
            for a in moves_p:
                for b in moves_q:
                    if a.junction.id != b.junction.id:
                        continue
                    point = crossing(a, b, tol)
                    if point is not None:
                        count += 1
                        first = first or (a, b, point)
            if first is not None:
                yield p, q, first[0], first[1], first[2], count


def _lights(placed: list[Placement]) -> str:
    """The placements releasing the same lanes, with the verb."""
    others = [f"signal {p.signal} (line {p.line})" for p in placed[1:]]
    return " and ".join([placed[0].describe(), *others]) + (" release" if others else " releases")


@rule(
    "V001",
    "conflicting-signals-same-controller",
    Category.SIGNAL_CONTROL,
    Severity.WARNING,
    basis=Basis.PLAUSIBILITY,
)
def conflicting_signals_same_controller(ctx: Context):
    """Two traffic lights of one controller release junction movements that cross: they always show green together.

    The signals of a ``<controller>`` form one signal group (14.6) and show the same aspect; a junction's
    ``<controller>`` references gather groups that take turns (12.14). A light on an incoming road releases the
    connection lanes entered from the lanes it is valid for (14.2; the module docstring says exactly how). When two
    lights of one group release connection lanes that cross inside the same junction (other than a diverge from
    one lane or a merge into one lane), crossing movements get green together: put the lights in different
    controllers, or give the conflicting turn its own light. A permissive left turn (green together with the
    oncoming traffic it yields to) is reported too: where that is intended, deselect the rule.

    Plausibility: the standard states no rule on which movements a controller may release together; a warning
    whatever the profile.

    Passes (the two opposite straight-on approaches in one group, the crossing left turn in another)::

        <controller id="1"><control signalId="11"/><control signalId="12"/></controller>
        <controller id="2"><control signalId="13"/></controller>

    Fails (the left turn from road 3 crosses the straight-on lane from road 2, in the same group)::

        <controller id="1"><control signalId="12"/><control signalId="13"/></controller>
    """
    controllers = ctx.document.controllers
    if not controllers:
        return
    lights = placements(ctx)
    cache: dict = {}
    for controller in controllers:
        for p, q, a, b, point, count in _conflicts(ctx, controller, lights, cache):
            more = f" ({count - 1} more crossing pair{'s' if count > 2 else ''} of these lights)" if count > 1 else ""
            yield conflicting_signals_same_controller.finding(
                f"junction {a.junction.id}, controller {controller.id}: crossing movements are released together: "
                f"{_lights(p)} {a.describe()}, {_lights(q)} {b.describe()}; they cross at "
                f"({point[0]:.3f}, {point[1]:.3f}){more}. Put the two lights in different controllers (signal "
                f"groups) or give the conflicting movement its own light",
                road=p[0].road,
                s=p[0].s,
                x=float(point[0]),
                y=float(point[1]),
                line=controller.line or None,
            )
