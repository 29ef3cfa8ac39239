"""A fork or ramp pair put into a generated map's document: the road cut into its pieces, the branch added, the
joints made junctions (direct, or default with connecting roads), every reference to the road's far end renamed.

The road keeps its id for the piece before the split (*A*); the piece between the joints (*B*), the branch and the
piece after the merge (*C*) get new ids. Everything on the road (objects, signals, elevation, speed) goes with the
piece it lies on. Both joints are built by :func:`_joint` from the three pieces meeting there; a default junction
carries the branches' first (split) or last (merge) :data:`~.spec.JUNCTION_LENGTH` metres on connecting roads, one
for each side's lanes.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from ..opendrive import Connection, Corner, Cubic, Document, Junction, Lane, LaneLink, LaneSection, Link, Road
from ..params import Params, TrafficRule
from ..scenario.ids import Ids
from .geometry import Path, cut, length_of, offset
from .pieces import LaneT, Span, Use, clip_profile, hermite, profile_at, sections, shift_sections, templates
from .site import SOLID, Design, Stretch, loop_path, point_on
from .spec import JUNCTION_LENGTH

JUNCTION_SPEED = 30.0


@dataclass(frozen=True)
class Piece:
    """A road being made: id, reference line, the lane sections kept as they were before (``head``) and after
    (``tail``, already at their new ``s``) those built from ``spans`` (which start at road s ``start``), the links of
    the built sections' lanes to ``head`` and ``tail`` (name -> id), elevation, speed and what stands on it."""

    id: str
    geometry: Path
    spans: tuple[Span, ...]
    forward_side: int
    start: float = 0.0
    elevation: tuple[Cubic, ...] = ()
    head: tuple[LaneSection, ...] = ()
    tail: tuple[LaneSection, ...] = ()
    first_links: tuple[tuple[str, int], ...] = ()
    last_links: tuple[tuple[str, int], ...] = ()
    speed: float | None = None
    road_type: str = "town"

    @property
    def length(self) -> float:
        return length_of(self.geometry)

    def lane_sections(self) -> tuple[LaneSection, ...]:
        built = sections(list(self.spans), self.forward_side, dict(self.first_links), dict(self.last_links), self.start)
        return (*self.head, *built, *self.tail)

    def end_ids(self, at_start: bool) -> dict[str, int]:
        """Lane name -> id in the built lane section at the piece's start (or end)."""
        span = self.spans[0] if at_start else self.spans[-1]
        fs = self.forward_side
        return {
            **{u.lane.key: fs * i for i, u in enumerate(span.forward, 1)},
            **{u.lane.key: -fs * i for i, u in enumerate(span.backward, 1)},
        }

    def side_keys(self, at_start: bool, forward: bool) -> list[str]:
        span = self.spans[0] if at_start else self.spans[-1]
        return [u.lane.key for u in (span.forward if forward else span.backward)]

    def drivable(self, at_start: bool) -> set[str]:
        span = self.spans[0] if at_start else self.spans[-1]
        return {u.lane.key for u in (*span.forward, *span.backward) if u.lane.drivable}

    def carve(self, at_start: bool, length: float) -> tuple[Piece, Path, tuple[Span, ...], tuple[Cubic, ...]]:
        """The piece without its first (last) ``length`` metres, and that stretch's geometry, spans and elevation
        (the piece has no ``head``/``tail`` there)."""
        total = self.length
        at = length if at_start else total - length
        first, second = cut(self.geometry, at)
        a_spans, b_spans = _split_spans(self.spans, at)
        a_elev, b_elev = clip_profile(self.elevation, 0.0, at), clip_profile(self.elevation, at, total)
        if at_start:
            return replace(self, geometry=second, spans=b_spans, elevation=b_elev), first, a_spans, a_elev
        return replace(self, geometry=first, spans=a_spans, elevation=a_elev), second, b_spans, b_elev


def _split_spans(spans: tuple[Span, ...], at: float) -> tuple[tuple[Span, ...], tuple[Span, ...]]:
    head, tail = [], []
    s = 0.0
    for sp in spans:
        if s + sp.length <= at + 1e-9:
            head.append(sp)
        elif s >= at - 1e-9:
            tail.append(sp)
        else:
            head.append(replace(sp, length=at - s))
            tail.append(replace(sp, length=s + sp.length - at, at=sp.at + at - s))
        s += sp.length
    return tuple(head), tuple(tail)


def _road(p: Piece, rule: str, junction: str, pred: Link | None, succ: Link | None, name: str) -> Road:
    return Road(
        p.id,
        p.length,
        junction,
        p.geometry,
        p.lane_sections(),
        rule,
        pred,
        succ,
        name=name,
        speed_kmh=p.speed,
        road_type=p.road_type,
        elevation=p.elevation,
    )


@dataclass(frozen=True)
class Built:
    """What a joint adds: connecting roads (default junction), the junction, and the branch pieces as they remain."""

    roads: tuple[Road, ...]
    junction: Junction
    branches: tuple[Piece, ...]


def _links(pairs: list[tuple[int, int]]) -> tuple[LaneLink, ...]:
    return tuple(LaneLink(a, b) for a, b in pairs)


def _joint(jid: str, one: Piece, others: tuple[Piece, ...], split: bool, kind: str, rule: str, ids: Ids) -> Built:
    """The junction where ``one`` (ending there for a split, starting there for a merge) meets ``others`` (starting
    there for a split, ending there for a merge)."""
    one_ids = one.end_ids(at_start=not split)
    if kind == "direct":
        conns = []
        for k, other in enumerate(others):
            other_ids = other.end_ids(at_start=split)
            keys = [key for key in other_ids if key in one_ids]
            if split:
                conns.append(
                    Connection(str(k), one.id, other.id, "start", _links([(one_ids[x], other_ids[x]) for x in keys]))
                )
            else:
                conns.append(
                    Connection(str(k), other.id, one.id, "start", _links([(other_ids[x], one_ids[x]) for x in keys]))
                )
        return Built((), Junction(jid, f"{'split' if split else 'merge'} {jid}", tuple(conns), type="direct"), others)
    roads: list[Road] = []
    conns_d: list[Connection] = []
    remaining = []
    fs = one.forward_side
    for other in others:
        rest, geo, spans, elev = other.carve(at_start=split, length=JUNCTION_LENGTH)
        remaining.append(rest)
        rest_ids = rest.end_ids(at_start=split)
        for forward in (True, False):
            keys = other.side_keys(at_start=split, forward=forward)
            if not keys:
                continue
            side_spans = tuple(
                replace(sp, forward=sp.forward if forward else (), backward=() if forward else sp.backward)
                for sp in spans
            )
            cid = ids.next()
            up, down = (one_ids, rest_ids) if split else (rest_ids, one_ids)
            conn = Piece(cid, geo, side_spans, fs, elevation=elev, speed=JUNCTION_SPEED)
            own = conn.end_ids(at_start=True)
            first = tuple((key, up[key]) for key in keys if key in up)
            last = tuple((key, down[key]) for key in keys if key in down)
            conn = replace(conn, first_links=first, last_links=last)
            before = Link("road", one.id if split else rest.id, "end")
            after = Link("road", rest.id if split else one.id, "start")
            roads.append(
                _road(conn, rule, jid, before, after, f"{'split' if split else 'merge'} {jid} connection {cid}")
            )
            drivable = [key for key in keys if key in other.drivable(at_start=split) and key in up and key in down]
            if forward:  # along s: from the road at the connecting road's start
                incoming = one.id if split else rest.id
                conns_d.append(
                    Connection(str(len(conns_d)), incoming, cid, "start", _links([(up[x], own[x]) for x in drivable]))
                )
            else:  # against s: from the road at its end
                incoming = rest.id if split else one.id
                conns_d.append(
                    Connection(str(len(conns_d)), incoming, cid, "end", _links([(down[x], own[x]) for x in drivable]))
                )
    junction = Junction(jid, f"{'split' if split else 'merge'} {jid}", tuple(conns_d))
    return Built(tuple(roads), junction, tuple(remaining))


@dataclass(frozen=True)
class Lanes:
    """The road's middle cross-section split into groups (templates): on the side driving along ``s``, what lies
    inside the driving lanes (a median), the lanes staying on the road (near), those leaving (far), the roadside
    beyond; and the other side."""

    inner: tuple[LaneT, ...]
    near: tuple[LaneT, ...]
    far: tuple[LaneT, ...]
    roadside: tuple[LaneT, ...]
    backward: tuple[LaneT, ...]
    added: bool  #: the far lanes are new (an exit or entry lane, or a lane gained for a fork)


def lane_groups(section: LaneSection, origin: float, fs: int, d: Design, width: float) -> Lanes | None:
    """The groups of the road's middle section for ``d`` (None when it has no driving lane on its forward side)."""
    forward, backward = templates(section, fs, origin)
    driving = [k for k, t in enumerate(forward) if t.type == "driving"]
    if not driving or driving != list(range(driving[0], driving[-1] + 1)):
        return None
    inner, drv, roadside = forward[: driving[0]], forward[driving[0] : driving[-1] + 1], forward[driving[-1] + 1 :]
    if d.added:
        far_type = "exit" if d.kind == "ramp" else "driving"
        far = tuple(LaneT(f"X{k}", far_type, width) for k in range(1, d.far_lanes + 1))
        return Lanes(tuple(inner), tuple(drv), far, tuple(roadside), tuple(backward), True)
    if len(drv) <= d.far_lanes:
        return None
    return Lanes(
        tuple(inner), tuple(drv[: -d.far_lanes]), tuple(drv[-d.far_lanes :]), tuple(roadside), tuple(backward), False
    )


def _uses(*groups: tuple[LaneT, ...], **marks: str) -> tuple[Use, ...]:
    return tuple(Use(t, mark=marks.get(t.key)) for g in groups for t in g)


def _approach(g: Lanes, d: Design, s_end: float, merge: bool) -> list[tuple[float, tuple[Use, ...]]]:
    """(length, forward uses) of the stretches before a split ending at road s ``s_end`` (a merge: after it,
    starting there), in order along ``s``."""
    last = g.near[-1].key
    if g.added:
        entry = tuple(replace(t, type="entry") for t in g.far) if merge and d.kind == "ramp" else g.far
        full = (
            d.beside,
            (*_uses(g.inner, g.near, **{last: "broken"}), *(Use(t, mark="solid") for t in entry), *_uses(g.roadside)),
        )
        taper = (
            d.taper,
            (
                *_uses(g.inner, g.near, **{last: "broken"}),
                *(Use(t, grow=not merge, shrink=merge, mark="solid") for t in entry),
                *_uses(g.roadside),
            ),
        )
        spans = [taper, full]
    else:
        spans = [(SOLID, _uses(g.inner, g.near, g.far, g.roadside, **{last: "solid"}))]
    return spans[::-1] if merge else spans


@dataclass(frozen=True)
class _Cut:
    """Where the road is cut: its middle lane section and where that ends, the split and merge s, its lane groups
    and side of the lanes driving along ``s``."""

    road: Road
    st: Stretch
    sec: LaneSection
    sec_end: float
    s1: float
    s2: float
    g: Lanes
    fs: int

    def span(self, length: float, at: float, forward: tuple[Use, ...]) -> Span:
        return Span(length, at, forward, _uses(self.g.backward), self.sec.center)

    @property
    def whole(self) -> tuple[Use, ...]:
        """The road's lanes along ``s`` as they are away from the structure."""
        g = self.g
        return _uses(g.inner, g.near, g.roadside) if g.added else _uses(g.inner, g.near, g.far, g.roadside)


def _before(c: _Cut, d: Design) -> Piece:
    """A: the road up to the split (its id, links, head sections)."""
    pre = _approach(c.g, d, c.s1, merge=False)
    at = c.s1 - sum(x for x, _ in pre)
    spans = [c.span(at - c.sec.s, c.sec.s, c.whole)]
    for length, uses in pre:
        spans.append(c.span(length, at, uses))
        at += length
    return Piece(
        c.road.id,
        cut(c.road.geometry, c.s1)[0],
        tuple(spans),
        c.fs,
        start=c.sec.s,
        elevation=clip_profile(c.road.elevation, 0.0, c.s1),
        head=c.road.sections[: c.st.section],
        first_links=tuple(_original_links(c.sec, c.fs, "predecessor")),
        speed=c.road.speed_kmh,
        road_type=c.road.road_type,
    )


def _between(c: _Cut, ids: Ids) -> Piece:
    """B: the road between the joints, without the lanes that leave and the roadside beyond them."""
    last = c.g.near[-1].key
    geometry = cut(cut(c.road.geometry, c.s1)[1], c.s2 - c.s1)[0]
    forward = _uses(c.g.inner, c.g.near, **{last: "solid"})
    return Piece(
        ids.next(),
        geometry,
        (c.span(c.s2 - c.s1, c.s1, forward),),
        c.fs,
        elevation=clip_profile(c.road.elevation, c.s1, c.s2),
        speed=c.road.speed_kmh,
        road_type=c.road.road_type,
    )


def _branch(c: _Cut, d: Design, ids: Ids) -> Piece:
    """The branch: the far lanes and the roadside, beside the road from the split to the merge; its height a cubic
    from the road's height and grade at one joint to those at the other."""
    x, y, hdg = point_on(c.st.line, c.s1)
    fx, fy = offset(x, y, hdg, c.fs * sum(lane.width for lane in (*c.g.inner, *c.g.near)))
    geometry = loop_path(d, fx, fy, hdg, c.fs)
    length = length_of(geometry)
    z1, g1 = profile_at(c.road.elevation, c.s1)
    z2, g2 = profile_at(c.road.elevation, c.s2)
    types = ("offRamp", "onRamp") if d.kind == "ramp" else ("driving",)  # a ramp's lanes change type halfway
    spans = []
    for k, kind in enumerate(types):
        uses = (*(Use(replace(t, type=kind), mark="solid") for t in c.g.far), *_uses(c.g.roadside))
        spans.append(Span(length / len(types), k * length / len(types), uses, (), _one_way_centre()))
    elevation = hermite(z1, g1, z2, g2, length)
    return Piece(ids.next(), geometry, tuple(spans), c.fs, elevation=elevation, speed=c.road.speed_kmh)


def _after(c: _Cut, d: Design, ids: Ids) -> Piece:
    """C: the road after the merge (a new id; its tail sections and links)."""
    spans = []
    at = c.s2
    for length, uses in _approach(c.g, d, c.s2, merge=True):
        spans.append(c.span(length, at, uses))
        at += length
    spans.append(c.span(c.sec_end - at, at, c.whole))
    return Piece(
        ids.next(),
        cut(c.road.geometry, c.s2)[1],
        tuple(spans),
        c.fs,
        elevation=clip_profile(c.road.elevation, c.s2, c.road.length),
        tail=tuple(shift_sections(c.road.sections[c.st.section + 1 :], -c.s2)),
        last_links=tuple(_original_links(c.sec, c.fs, "successor")),
        speed=c.road.speed_kmh,
        road_type=c.road.road_type,
    )


def place(doc: Document, st: Stretch, d: Design, centre: float, params: Params, ids: Ids, kind: str) -> Document | None:
    """``doc`` with the structure ``d`` beside stretch ``st`` around road s ``centre``, its joints ``kind``
    ("direct" or "default") junctions (None when the road's lanes do not allow it)."""
    road = st.road
    fs = -1 if params.traffic_rule is TrafficRule.RHT else 1
    sec = road.sections[st.section]
    g = lane_groups(sec, sec.s, fs, d, params.lane_width)
    if g is None:
        return None
    sec_end = road.sections[st.section + 1].s if st.section + 1 < len(road.sections) else road.length
    c = _Cut(road, st, sec, sec_end, centre - d.loop / 2, centre + d.loop / 2, g, fs)
    a, b, loop, after = _before(c, d), _between(c, ids), _branch(c, d, ids), _after(c, d, ids)
    rule = params.traffic_rule.value
    j1, j2 = ids.next(), ids.next()
    split = _joint(j1, a, (b, loop), True, kind, rule, ids)
    merge = _joint(j2, after, split.branches, False, kind, rule, ids)
    b, loop = merge.branches
    label = "ramp" if d.kind == "ramp" else "fork"
    at1, at2 = Link("junction", j1), Link("junction", j2)
    new_roads = [
        _keep(_road(a, rule, "-1", road.predecessor, at1, road.name), road, lambda s: s < c.s1, 0.0),
        _road(b, rule, "-1", at1, at2, f"road {b.id} ({label} main)"),
        _road(loop, rule, "-1", at1, at2, f"road {loop.id} ({label} branch)"),
        _keep(_road(after, rule, "-1", at2, road.successor, f"road {after.id}"), road, lambda s: s > c.s2, c.s2),
    ]
    roads = [_renamed(old, road.id, after.id) for old in doc.roads if old.id != road.id]
    at = next(k for k, old in enumerate(doc.roads) if old.id == road.id)
    roads[at:at] = [*new_roads, *split.roads, *merge.roads]
    junctions = [_renamed_junction(j, road, after.id) for j in doc.junctions] + [split.junction, merge.junction]
    return replace(doc, roads=tuple(roads), junctions=tuple(junctions))


def _one_way_centre() -> Lane:
    from ..opendrive import RoadMark

    return Lane(0, "none", (), (RoadMark(0.0, "solid", "standard", lane_change="none"),))


def _original_links(sec: LaneSection, fs: int, which: str):
    """(name, id) of the lanes of ``sec`` that link ``which`` way (``predecessor`` / ``successor``) outside it."""
    for sign, letter in ((fs, "F"), (-fs, "B")):
        lanes = sorted(sec.left if sign > 0 else sec.right, key=lambda lane: abs(lane.id))
        for k, lane in enumerate(lanes, start=1):
            target = getattr(lane, which)
            if target is not None:
                yield f"{letter}{k}", target


def _keep(new: Road, old: Road, where, shift: float) -> Road:
    """``new`` with the objects and signals of ``old`` that stand where ``where(s)`` holds, moved back by ``shift``."""
    objects = tuple(
        replace(o, s=o.s - shift, outline=tuple(Corner(c.s - shift, c.t) for c in o.outline))
        for o in old.objects
        if where(o.s)
    )
    signals = tuple(replace(x, s=x.s - shift) for x in old.signals if where(x.s))
    return replace(new, objects=objects, signals=signals)


def _renamed(road: Road, old: str, new: str) -> Road:
    """``road`` with links to the far end of road ``old`` naming road ``new`` instead."""

    def fix(link: Link | None) -> Link | None:
        if link is not None and link.element_type == "road" and link.element_id == old and link.contact_point == "end":
            return replace(link, element_id=new)
        return link

    return replace(road, predecessor=fix(road.predecessor), successor=fix(road.successor))


def _renamed_junction(j: Junction, road: Road, new: str) -> Junction:
    """``j`` with ``road`` as an incoming road at its far end renamed ``new``."""
    if road.successor is None or road.successor.element_type != "junction" or road.successor.element_id != j.id:
        return j
    conns = tuple(replace(c, incoming_road=new) if c.incoming_road == road.id else c for c in j.connections)
    return replace(j, connections=conns)
