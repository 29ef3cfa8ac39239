"""A fork, merge or ramp as an OpenDRIVE document: the stem, the near and far branch roads and their junction.

Road ids: 1 the stem, 2 the near branch, 3 the far branch, then the connecting roads of a default junction; the
junction comes last. Every road is flat and ends in open space (the map is the structure alone, like ``junctionart
intersection``'s). A direct junction names the branches (or, for a merge, the stem) as linked roads (12.6); a default
one carries each branch's first :data:`~.spec.JUNCTION_LENGTH` metres (a merge: last) on connecting roads, one for the
lanes of each direction, linked lane by lane.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..cleanup import _three_points
from ..opendrive import Connection, Document, Header, Junction, LaneLink, LaneSection, Line, Link, Road
from .geometry import Path, cut, length_of, offset, path, reverse
from .lanes import Group, Span, sections
from .plan import Plan, of_spec
from .spec import JUNCTION_LENGTH, ForkSpec, RampSpec

ROAD_SPEED = 50.0
JUNCTION_SPEED = 30.0
#: Metres of the stem before a split (after a merge) where no one may change between the two branches' lanes.
SOLID_BEFORE_SPLIT = 30.0


@dataclass(frozen=True)
class Paths:
    """The reference lines: the stem, and each branch road as a whole (from or to the junction)."""

    stem: Path
    near: Path
    far: Path


def lay_out(plan: Plan, x: float = 0.0, y: float = 0.0, hdg: float = 0.0) -> Paths:
    """Reference lines with the junction at (x, y), the stem heading ``hdg`` there."""
    fs, L, Lb = plan.forward_side, plan.stem_length, plan.branch_length
    far_x, far_y = offset(x, y, hdg, fs * plan.n_near * plan.lane_width)
    c, s = math.cos(hdg), math.sin(hdg)
    if not plan.merge:
        stem = (Line(0.0, x - L * c, y - L * s, hdg, L),)
        near = path(x, y, hdg, plan.near_turn, plan.near_radius, plan.near_lead, Lb)
        far = path(far_x, far_y, hdg, plan.far_turn, plan.far_radius, plan.far_lead, Lb)
        return Paths(stem, near, far)
    # a merge: each branch traced back from the junction (the side it lies on seen facing the other way), reversed
    back = hdg + math.pi
    near = reverse(path(x, y, back, -plan.near_turn, plan.near_radius, plan.near_lead, Lb))
    far = reverse(path(far_x, far_y, back, -plan.far_turn, plan.far_radius, plan.far_lead, Lb))
    return Paths((Line(0.0, x, y, hdg, L),), near, far)


def _stem_spans(plan: Plan) -> list[Span]:
    """The stem's spans, from its start: the far lanes all along (a fork) or only near the junction (a ramp)."""
    near = Group(plan.n_near, solid=True)
    back = (Group(plan.oncoming),) if plan.oncoming else ()
    L = plan.stem_length
    if plan.added is None:
        split = Span(min(SOLID_BEFORE_SPLIT, L / 2), (near, Group(plan.n_far)), back)
        open_ = Span(L - split.length, (Group(plan.n_near), Group(plan.n_far)), back)
        return [split, open_] if plan.merge else [open_, split]
    taper, full = plan.added
    kind = plan.stem_far_type
    widening = Span(taper, (Group(plan.n_near), Group(plan.n_far, kind, grow=not plan.merge, shrink=plan.merge)), back)
    beside = Span(full, (Group(plan.n_near), Group(plan.n_far, kind)), back) if full > 0 else None
    plain = Span(L - taper - full, (Group(plan.n_near),), back)
    spans = [plain, widening, *([beside] if beside else [])]
    return spans[::-1] if plan.merge else spans


def _spans(length: float, forward: int, backward: int, kind: str = "driving") -> list[Span]:
    return [Span(length, (Group(forward, kind),), (Group(backward),) if backward else ())]


@dataclass(frozen=True)
class _Roads:
    """Ids of the structure's roads."""

    stem: str = "1"
    near: str = "2"
    far: str = "3"


def _road(
    rid: str,
    geometry: Path,
    secs: tuple[LaneSection, ...],
    plan: Plan,
    junction: str = "-1",
    predecessor: Link | None = None,
    successor: Link | None = None,
) -> Road:
    speed = JUNCTION_SPEED if junction != "-1" else ROAD_SPEED
    name = f"{plan.name} road {rid}" if junction == "-1" else f"{plan.name} junction {junction} connection {rid}"
    return Road(
        rid,
        length_of(geometry),
        junction,
        geometry,
        secs,
        plan.rule.value,
        predecessor,
        successor,
        name=name,
        speed_kmh=speed,
    )


def build(spec: ForkSpec | RampSpec) -> Document:
    """The map of ``spec``: the junction at the origin, the stem arriving from the west (a merge: leaving east)."""
    plan = of_spec(spec)
    return document(plan, lay_out(plan))


def document(plan: Plan, paths: Paths) -> Document:
    """The roads and the junction of ``plan`` laid out along ``paths``."""
    fs, w = plan.forward_side, plan.lane_width
    ids = _Roads()
    direct = plan.junction == "direct"
    jid = "4" if direct else str(4 + 2 + (1 if plan.oncoming else 0))  # after the roads and connecting roads
    at_junction = Link("junction", jid)
    stem_secs = sections(_stem_spans(plan), fs, w)
    # the branch roads: whole (direct junction) or without the stretch the connecting roads carry
    near_geo, far_geo = paths.near, paths.far
    near_conn = far_conn = None
    if not direct:
        if plan.merge:
            near_geo, near_conn = cut(paths.near, length_of(paths.near) - JUNCTION_LENGTH)
            far_geo, far_conn = cut(paths.far, length_of(paths.far) - JUNCTION_LENGTH)
        else:
            near_conn, near_geo = cut(paths.near, JUNCTION_LENGTH)
            far_conn, far_geo = cut(paths.far, JUNCTION_LENGTH)
    near_secs = sections(_spans(length_of(near_geo), plan.n_near, plan.oncoming), fs, w)
    far_secs = sections(_spans(length_of(far_geo), plan.n_far, 0, plan.far_type), fs, w)
    stem_link = (at_junction, None) if plan.merge else (None, at_junction)
    branch_link = (None, at_junction) if plan.merge else (at_junction, None)
    roads = [
        _road(ids.stem, paths.stem, stem_secs, plan, "-1", *stem_link),
        _road(ids.near, near_geo, near_secs, plan, "-1", *branch_link),
        _road(ids.far, far_geo, far_secs, plan, "-1", *branch_link),
    ]
    if direct:
        junction = _direct(plan, jid, ids)
    else:
        assert near_conn is not None and far_conn is not None
        conns, junction = _default(plan, jid, ids, near_conn, far_conn)
        roads += conns
    return Document(_header(plan, roads), tuple(roads), (junction,))


def _lane_links(pairs) -> tuple[LaneLink, ...]:
    return tuple(LaneLink(a, b) for a, b in pairs)


def _direct(plan: Plan, jid: str, ids: _Roads) -> Junction:
    """12.6: the stem linked to both branches; lanes of the stem's far group continue on the far branch."""
    fs = plan.forward_side
    near = [(fs * k, fs * k) for k in range(1, plan.n_near + 1)] + [
        (-fs * k, -fs * k) for k in range(1, plan.oncoming + 1)
    ]
    far = [(fs * (plan.n_near + k), fs * k) for k in range(1, plan.n_far + 1)]
    if not plan.merge:  # one incoming road (the stem), two linked roads starting at the junction
        conns = (
            Connection("0", ids.stem, ids.near, "start", _lane_links(near)),
            Connection("1", ids.stem, ids.far, "start", _lane_links(far)),
        )
    else:  # two incoming roads (the branches) ending at the junction, one linked road (the stem) starting there
        conns = (
            Connection("0", ids.near, ids.stem, "start", _lane_links((b, a) for a, b in near)),
            Connection("1", ids.far, ids.stem, "start", _lane_links((b, a) for a, b in far)),
        )
    return Junction(jid, f"{plan.name} {jid}", conns, type="direct")


def _default(plan: Plan, jid: str, ids: _Roads, near_conn: Path, far_conn: Path) -> tuple[list[Road], Junction]:
    """A common junction: one connecting road per branch for the lanes driving along ``s``, and one beside the near
    one for the lanes of the other direction (sharing its reference line)."""
    fs, w = plan.forward_side, plan.lane_width
    roads: list[Road] = []
    conns: list[Connection] = []
    next_id = 4
    for branch, geo, lanes, first, kind in (
        (ids.near, near_conn, plan.n_near, 1, "driving"),
        (ids.far, far_conn, plan.n_far, plan.n_near + 1, plan.far_type),
    ):
        rid = str(next_id)
        next_id += 1
        stem_ids = [fs * (first + k) for k in range(lanes)]
        own = [fs * (k + 1) for k in range(lanes)]
        upstream, downstream = (own, stem_ids) if plan.merge else (stem_ids, own)
        secs = sections([Span(length_of(geo), (Group(lanes, kind),))], fs, w, marks=False)
        sec = _with_links(secs[0], dict(zip(own, upstream)), dict(zip(own, downstream)))
        before = Link("road", branch if plan.merge else ids.stem, "end")
        after = Link("road", ids.stem if plan.merge else branch, "start")
        roads.append(_road(rid, geo, (sec,), plan, jid, before, after))
        incoming = branch if plan.merge else ids.stem
        conns.append(Connection(str(len(conns)), incoming, rid, "start", _lane_links(zip(upstream, own))))
        if branch == ids.near and plan.oncoming:  # the other direction, against s: from the s-end road back
            rid = str(next_id)
            next_id += 1
            back = [-fs * (k + 1) for k in range(plan.oncoming)]
            secs = sections([Span(length_of(geo), (), (Group(plan.oncoming),))], fs, w, marks=False)
            sec = _with_links(secs[0], {b: b for b in back}, {b: b for b in back})
            roads.append(_road(rid, geo, (sec,), plan, jid, before, after))
            source = ids.stem if plan.merge else branch  # where this traffic comes from: the road at the s-end
            conns.append(Connection(str(len(conns)), source, rid, "end", _lane_links((b, b) for b in back)))
    return roads, Junction(jid, f"{plan.name} {jid}", tuple(conns))


def _with_links(sec: LaneSection, pred: dict[int, int], succ: dict[int, int]) -> LaneSection:
    from dataclasses import replace

    def linked(lane):
        return replace(lane, predecessor=pred.get(lane.id), successor=succ.get(lane.id))

    return replace(sec, left=tuple(map(linked, sec.left)), right=tuple(map(linked, sec.right)))


def _header(plan: Plan, roads: list[Road]) -> Header:
    points = [xy for r in roads for g in r.geometry for xy in _three_points(g)]
    xs, ys = [x for x, _ in points], [y for _, y in points]
    return Header(name=f"junctionart {plan.name}", north=max(ys), south=min(ys), east=max(xs), west=min(xs))
