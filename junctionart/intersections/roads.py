"""The roads of one pass: what each must carry, its geometry between its incident points, and the repair of a road
that has none.

A road's end lane counts come from its junctions' link plans (a turn lane appears before a junction, an unfed lane
tapers out), so roads are laid after the junctions are planned and before their connection lanes are fitted, which
start where the roads end.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..curves import wrap
from ..graph import Chain
from ..lanegeom import taper_length
from ..opendrive import Geometry
from ..params import Params
from .legs import MAX_LEGS, LegKey
from .planning import Junction, Reach
from .roadshape import Contact, EndLanes, Misfit, RoadShape, RoadSpec, contact, shape_road
from .roundabout import SPLITTER_CLEAR, splitter_spans
from .survey import Survey

MIN_ROAD = 5.0  #: shortest road written between two junctions (beyond its lane tapers)


class Road(NamedTuple):
    spec: RoadSpec
    geometry: tuple[Geometry, ...]


def lay_roads(view: Survey, junctions: dict[int, Junction], reach: Reach, params: Params) -> list[Road] | None:
    """The road of every chain (indexed like the chains), or None when one did not fit. Each misfit is repaired at
    once, so that roads laid later in the pass see what was changed; the pass then starts again."""
    ends = _end_lanes(junctions)
    splitters = _splitters(junctions)
    roads: list[Road] = []
    for c, ch in enumerate(view.chains):
        if view.state.touched(ch.nodes):
            continue
        spec = _spec(view, c, ends, params, splitters)
        shape = build_road(view, spec, reach, params)
        if shape.misfit is None:
            roads.append(Road(spec, shape.geometry))
        else:
            _repair(view, c, shape)
    return None if view.state.dirty else roads


def build_road(view: Survey, spec: RoadSpec, reach: Reach, params: Params) -> RoadShape:
    """The geometry of ``spec``'s chain between the incident points in ``reach`` (a dead end runs to its node)."""
    c = spec.chain
    return shape_road(view.points(c), reach.get(LegKey(c, True), 0.0), reach.get(LegKey(c, False), 0.0), spec, params)


def leg_ends(roads: list[Road], keys: list[LegKey]) -> tuple[list[Contact], list[bool]]:
    """Per leg: the pose where its road meets the junction, and whether the road has a median."""
    return (
        [contact(roads[k.chain].geometry, k.at_start) for k in keys],
        [roads[k.chain].spec.lanes.median for k in keys],
    )


def _end_lanes(junctions: dict[int, Junction]) -> dict[LegKey, EndLanes]:
    """Lane counts where each leg's road meets its junction, along the road: forward lanes leave a junction at the
    road's start and enter the one at its end."""
    out: dict[LegKey, EndLanes] = {}
    for j in junctions.values():
        for idx, key in enumerate(j.keys):
            n_in, n_out = j.links.n_in_end[idx], j.links.n_out_end[idx]
            out[key] = EndLanes(n_out, n_in) if key.at_start else EndLanes(n_in, n_out)
    return out


def _splitters(junctions: dict[int, Junction]) -> dict[LegKey, float]:
    """The splitter island's width at the end of each roundabout arm that has one."""
    return {
        j.keys[arm.leg]: arm.splitter
        for j in junctions.values()
        if j.ring is not None
        for arm in j.ring.arms
        if arm.splitter > 0.0
    }


def _spec(
    view: Survey, c: int, ends: dict[LegKey, EndLanes], params: Params, splitters: dict[LegKey, float] | None = None
) -> RoadSpec:
    """Chain ``c``'s lanes; a dead end keeps the middle's counts. It needs room for both tapers and a piece between,
    and for the splitter island at a roundabout's end and :data:`SPLITTER_CLEAR` beside it."""
    cfg = view.lanes(c)
    mid = EndLanes(cfg.forward, cfg.backward)
    start, end = ends.get(LegKey(c, True), mid), ends.get(LegKey(c, False), mid)
    need = MIN_ROAD + taper_length(params, start, mid) + taper_length(params, end, mid)
    if not splitters:
        return RoadSpec(c, cfg, start, end, need)
    first, last = splitters.get(LegKey(c, True), 0.0), splitters.get(LegKey(c, False), 0.0)
    median = params.median_width if cfg.median else 0.0
    island = sum(length for w in (first, last) for length, _ in splitter_spans(w, median, params))
    need += island + (SPLITTER_CLEAR if island > 0.0 else 0.0)
    return RoadSpec(c, cfg, start, end, need, first, last)


def _repair(view: Survey, c: int, shape: RoadShape) -> None:
    """A bend too sharp is cut open or straightened. A road too short loses its sharpest bend when it has one;
    otherwise its two junctions merge when the merged one has at most :data:`MAX_LEGS` legs (more varied
    intersections than removing the road), else the road goes where the map stays connected without it."""
    ch, st = view.chains[c], view.state
    if shape.misfit is Misfit.SHARP_BEND:
        st.smooth(ch, shape.bend, f"bend at node {ch.nodes[shape.bend]} too sharp for its lanes")
    elif len(ch.nodes) > 2:
        st.smooth(ch, _sharpest_bend(view.points(c)), f"bend on a road too short between nodes {ch.start} and {ch.end}")
    elif not _merge_instead(view, ch) and st.connected_without(ch.edges[0]):
        st.remove_edge(
            ch.edges[0], f"removed road between nodes {ch.start} and {ch.end}: too short for its intersections"
        )
    else:
        st.contract(
            ch.edges[0],
            f"merged nodes {ch.start} and {ch.end} into one intersection: the road between them was too short",
        )


def _merge_instead(view: Survey, ch: Chain) -> bool:
    return ch.start != ch.end and view.degree[ch.start] + view.degree[ch.end] - 2 <= MAX_LEGS


def _sharpest_bend(P: list[tuple[float, float]]) -> int:
    """Index of the interior point of polyline ``P`` where it turns most."""
    turns = [
        abs(
            wrap(
                math.atan2(P[i + 1][1] - P[i][1], P[i + 1][0] - P[i][0])
                - math.atan2(P[i][1] - P[i - 1][1], P[i][0] - P[i - 1][0])
            )
        )
        for i in range(1, len(P) - 1)
    ]
    return 1 + int(np.argmax(turns))
