"""Junction control (issue 16): traffic lights with signal groups, or stop / yield signs on the minor legs.

Control type per junction (``junction_control="auto"``), drawn from the junction's own random stream:

=========================================  ==============  ====  =====  ====
junction                                   traffic lights  stop  yield  none
=========================================  ==============  ====  =====  ====
4+ legs and a major leg                    0.8             0.1   0.08   0.02
4+ legs, or 3 legs and a major leg         0.5             0.25  0.2    0.05
3 legs, no major leg                       0.2             0.4   0.3    0.1
=========================================  ==============  ====  =====  ====

A *major* leg has 3 or more driving lanes or a median at the junction (an arterial); junctions of fewer than 3 legs
(a road joining another at a bend) get no control. ``traffic-lights``, ``stop``, ``yield`` and ``none`` impose one
type on every junction of 3+ legs. A roundabout's arm junctions are controlled as roundabouts whatever the setting
(other than ``none``): traffic on the ring has priority, every entry yields (the yield sign 205 over the roundabout
sign 215 at the outer edge, and the yield line 341 across the entry lanes 1 m before the junction).

Traffic lights: one signal per incoming lane (the signal reference's vehicle light, hung over its lane at 5 m on a
mast arm), its ``<validity>`` that lane, referring to the approach's stop line; one ``<controller>`` per signal group
(:mod:`.phases`), referenced by the junction with ``sequence`` = the group's turn in the cycle. Stop line: a sign-294
road marking across the incoming lanes, valid for them, 1 m before the junction, or 1 m before the leg's crosswalk
(:mod:`.crosswalks`) at a signalised junction. Stop and yield: the two legs with the
most lanes keep priority (sign 306 on their approaches); every other approach gets the stop sign 206 and a stop line,
or the yield sign 205, at the outer edge of the road (on the sidewalk or border when the road has them).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from ..opendrive import (
    Controller,
    Document,
    Junction,
    JunctionController,
    Road,
    RoadObject,
    Signal,
    SignalLink,
    Validity,
)
from ..params import JunctionControl, Params
from .catalogue import COUNTRIES, Catalogue, SignType
from .crosswalks import STOP_BACK_WITH_WALK, crosswalk, fits
from .ids import Ids
from .phases import LaneKey, signal_groups

#: (traffic lights, stop, yield, none) by junction kind, as in the module's table.
CONTROL_PROBABILITIES = {
    "big": (0.8, 0.1, 0.08, 0.02),
    "medium": (0.5, 0.25, 0.2, 0.05),
    "small": (0.2, 0.4, 0.3, 0.1),
}
CONTROLS = (JunctionControl.TRAFFIC_LIGHTS, JunctionControl.STOP, JunctionControl.YIELD, JunctionControl.NONE)
STOP_BACK = 1.0  #: m between the stop line and the junction
LIGHT_HEIGHT = 5.0  #: m, bottom of an overhead traffic light above the road
SIGN_GAP = 0.05  #: m between two signs on one post


@dataclass(frozen=True)
class Approach:
    """The incoming lanes of one leg: road ``road`` meets the junction with its ``contact`` end."""

    road: Road
    contact: str
    lanes: tuple[int, ...]  #: incoming lane ids with a connection, by distance from the reference line
    back: float = STOP_BACK  #: m from the junction to the stop line

    @property
    def s(self) -> float:
        return max(0.0, self.road.length - self.back) if self.contact == "end" else min(self.back, self.road.length)

    @property
    def orientation(self) -> str:
        return "+" if self.contact == "end" else "-"


def add_signals(
    doc: Document, params: Params, seed: int, ids: Ids, entries: dict[str, list[tuple[str, str]]] | None = None
) -> Document:
    """``doc`` with the control of every junction of 3+ legs: signals on the incoming roads, controllers.
    ``entries``: the arms (road id, contact point) of each junction of a roundabout, by junction id."""
    entries = entries or {}
    rng = np.random.default_rng([seed, 16])
    roads = {r.id: r for r in doc.roads}
    added: dict[str, list[Signal]] = {}
    objects: dict[str, list[RoadObject]] = {}
    controllers: list[Controller] = []
    junctions = []
    for j in doc.junctions:
        movements, legs = _movements(j, roads)
        control = _control(params, rng, legs, roads)
        if j.id in entries and params.junction_control is not JunctionControl.NONE:
            made = _roundabout_signals(entries[j.id], movements, roads, params, ids)
        else:
            made = _junction_signals(j, control, movements, legs, roads, params, ids)
        for sig_road, sig in made.signals:
            added.setdefault(sig_road, []).append(sig)
        for obj_road, obj in made.objects:
            objects.setdefault(obj_road, []).append(obj)
        controllers.extend(made.controllers)
        junctions.append(dataclasses.replace(j, controllers=made.refs))
    new_roads = tuple(
        dataclasses.replace(
            r, signals=r.signals + tuple(added.get(r.id, ())), objects=r.objects + tuple(objects.get(r.id, ()))
        )
        for r in doc.roads
    )
    return dataclasses.replace(
        doc, roads=new_roads, junctions=tuple(junctions), controllers=doc.controllers + tuple(controllers)
    )


def _movements(j: Junction, roads: dict[str, Road]) -> tuple[dict[LaneKey, list[Road]], dict[tuple[str, str], int]]:
    """The driving connection lanes of ``j`` by incoming lane, and the legs (road, contact) with their driving lane
    count at the junction."""
    movements: dict[LaneKey, list[Road]] = {}
    legs: dict[tuple[str, str], int] = {}
    for c in j.connections:
        road = roads[c.connecting_road]
        if not any(ln.type == "driving" for ln in road.sections[0].left + road.sections[0].right):
            continue
        for link in (road.predecessor, road.successor):
            if link is not None and link.contact_point is not None:
                legs[(link.element_id, link.contact_point)] = _driving_lanes(roads[link.element_id], link.contact_point)
        for ll in c.lane_links:
            movements.setdefault((c.incoming_road, ll.from_lane), []).append(road)
    return movements, legs


def _driving_lanes(road: Road, contact: str) -> int:
    sec = road.sections[0] if contact == "start" else road.sections[-1]
    lanes = sec.left + sec.right
    median = any(ln.type == "median" for ln in lanes)
    return sum(ln.type == "driving" for ln in lanes) + (10 if median else 0)


def _control(params: Params, rng: np.random.Generator, legs: dict, roads: dict) -> JunctionControl:
    """The junction's control type (one draw from the junction's row of :data:`CONTROL_PROBABILITIES`)."""
    draw = rng.random()  # drawn for every junction, so one junction's kind never shifts another's draw
    if len(legs) < 3:
        return JunctionControl.NONE
    if params.junction_control is not JunctionControl.AUTO:
        return params.junction_control
    major = any(n >= 3 for n in legs.values())
    kind = "big" if len(legs) >= 4 and major else "medium" if len(legs) >= 4 or major else "small"
    edges = np.cumsum(CONTROL_PROBABILITIES[kind])
    return CONTROLS[min(int(np.searchsorted(edges, draw, side="right")), len(CONTROLS) - 1)]


@dataclass
class _Made:
    """What dressing the junctions made: signals, objects, controllers and the junctions' controller references."""

    signals: list[tuple[str, Signal]] = dataclasses.field(default_factory=list)
    objects: list[tuple[str, RoadObject]] = dataclasses.field(default_factory=list)
    controllers: list[Controller] = dataclasses.field(default_factory=list)
    refs: tuple[JunctionController, ...] = ()


def _approaches(movements: dict[LaneKey, list[Road]], roads: dict[str, Road]) -> list[Approach]:
    by_leg: dict[tuple[str, str], list[int]] = {}
    for (road_id, lane), conns in movements.items():
        contact = conns[0].predecessor.contact_point if conns[0].predecessor is not None else None
        by_leg.setdefault((road_id, contact or "end"), []).append(lane)
    return [Approach(roads[r], c, tuple(sorted(ls, key=abs))) for (r, c), ls in sorted(by_leg.items())]


def _junction_signals(
    j: Junction,
    control: JunctionControl,
    movements: dict[LaneKey, list[Road]],
    legs: dict[tuple[str, str], int],
    roads: dict[str, Road],
    params: Params,
    ids: Ids,
) -> _Made:
    made = _Made()
    if control is JunctionControl.NONE or not movements:
        return made
    cat = COUNTRIES[params.country]
    approaches = _approaches(movements, roads)
    if control is JunctionControl.TRAFFIC_LIGHTS:
        _lit(j, approaches, movements, legs, roads, cat, ids, made)
        return made
    priority = sorted(legs, key=lambda leg: (-legs[leg], leg))[:2]
    for a in approaches:
        if (a.road.id, a.contact) in priority:
            made.signals.append((a.road.id, _sign(a, cat.priority_road, ids.next)))
            continue
        sign = cat.stop if control is JunctionControl.STOP else cat.yield_
        made.signals.append((a.road.id, _sign(a, sign, ids.next)))
        if control is JunctionControl.STOP:
            made.signals.append((a.road.id, _stop_line(a, cat.stop_line, ids.next)))
    return made


def _roundabout_signals(
    arms: list[tuple[str, str]], movements: dict[LaneKey, list[Road]], roads: dict[str, Road], params: Params, ids: Ids
) -> _Made:
    """A roundabout's junction: on each arm's entry the yield sign over the roundabout sign, and the yield line."""
    made = _Made()
    cat = COUNTRIES[params.country]
    for a in _approaches(movements, roads):
        if (a.road.id, a.contact) not in arms:
            continue  # the ring: circulating traffic has priority
        low = _sign(a, cat.roundabout, ids.next)
        made.signals.append((a.road.id, low))
        high = low.z_offset + cat.roundabout.height + SIGN_GAP
        made.signals.append((a.road.id, dataclasses.replace(_sign(a, cat.yield_, ids.next), z_offset=high)))
        made.signals.append((a.road.id, _stop_line(a, cat.yield_line, ids.next)))
    return made


def _lit(
    j: Junction,
    approaches: list[Approach],
    movements: dict[LaneKey, list[Road]],
    legs: dict[tuple[str, str], int],
    roads: dict[str, Road],
    cat: Catalogue,
    ids: Ids,
    made: _Made,
) -> None:
    """Traffic lights, stop lines, signal groups and crosswalks of a signalised junction into ``made``."""
    for road_id, contact in sorted(legs):
        if fits(roads[road_id]):
            made.objects.append((road_id, crosswalk(roads[road_id], contact, ids.next)))
    lights: dict[LaneKey, str] = {}
    for a in approaches:
        if fits(a.road):
            a = dataclasses.replace(a, back=STOP_BACK_WITH_WALK)
        line = _stop_line(a, cat.stop_line, ids.next)
        made.signals.append((a.road.id, line))
        for lane in a.lanes:
            sig = _light(a, lane, cat.traffic_light, line.id, ids.next)
            made.signals.append((a.road.id, sig))
            lights[(a.road.id, lane)] = sig.id
    for k, group in enumerate(signal_groups(movements)):
        name = f"junction {j.id} signal group {k + 1}"
        made.controllers.append(Controller(ids.next(), name, tuple(lights[key] for key in group)))
    made.refs = tuple(JunctionController(c.id, k) for k, c in enumerate(made.controllers))


def _lane_span(road: Road, s: float, lane: int) -> tuple[float, float]:
    """t of the inner and outer border of ``lane`` at ``s`` (the generator's roads have no lane offset)."""
    sec = [x for x in road.sections if x.s <= s + 1e-9][-1]
    side = 1 if lane > 0 else -1
    lanes = {ln.id: ln for ln in (sec.left if side > 0 else sec.right)}
    ds = s - sec.s
    t = 0.0
    for k in range(1, abs(lane)):
        t += _width(lanes[side * k], ds)
    return side * t, side * (t + _width(lanes[lane], ds))


def _width(lane, ds: float) -> float:
    w = lane.widths[0]
    return w.a + ds * (w.b + ds * (w.c + ds * w.d))


def _signal(a: Approach, kind: SignType, sid: str, t: float, lanes: tuple[int, int], **extra) -> Signal:
    return Signal(
        sid,
        kind.name,
        a.s,
        t,
        a.orientation,
        kind.dynamic,
        kind.country,
        kind.type,
        kind.subtype,
        extra.pop("z_offset", kind.z_offset),
        extra.pop("width", kind.width),
        kind.height,
        validity=(Validity(min(lanes), max(lanes)),),
        **extra,
    )


def _stop_line(a: Approach, kind: SignType, new_id: Callable[[], str]) -> Signal:
    t0 = _lane_span(a.road, a.s, a.lanes[0])[0]
    t1 = _lane_span(a.road, a.s, a.lanes[-1])[1]
    return _signal(a, kind, new_id(), (t0 + t1) / 2.0, (a.lanes[0], a.lanes[-1]), width=abs(t1 - t0))


def _light(a: Approach, lane: int, kind: SignType, line_id: str, new_id: Callable[[], str]) -> Signal:
    t0, t1 = _lane_span(a.road, a.s, lane)
    ref = (SignalLink(line_id, "stopLine", "signal"),)
    return _signal(a, kind, new_id(), (t0 + t1) / 2.0, (lane, lane), z_offset=LIGHT_HEIGHT, references=ref)


def _sign(a: Approach, kind: SignType, new_id: Callable[[], str]) -> Signal:
    """A sign at the outer edge of the approach's side: the middle of the outermost lane when that is a sidewalk or
    border, else the road's edge."""
    side = 1 if a.lanes[0] > 0 else -1
    sec = [x for x in a.road.sections if x.s <= a.s + 1e-9][-1]
    outer = max((ln.id for ln in (sec.left if side > 0 else sec.right)), key=abs)
    t0, t1 = _lane_span(a.road, a.s, outer)
    kept = next(ln for ln in sec.left + sec.right if ln.id == outer).type in ("sidewalk", "border")
    return _signal(a, kind, new_id(), (t0 + t1) / 2.0 if kept else t1, (a.lanes[0], a.lanes[-1]))
