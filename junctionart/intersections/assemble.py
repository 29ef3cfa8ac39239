"""The values stage 3 hands to stage 4, from a pass that needed no repair: junction plans and road plans.

Kept apart from the pass so that what stage 4 receives (:mod:`.model`) is built in one place, from the pass's typed
results, and only once every junction fits. Junction plans come in node order; a roundabout's node gives one plan per
arm (in driving order round its ring), and its ring roads follow the roads of the network's chains.
"""

from __future__ import annotations

import numpy as np

from ..curves import connection_geometry
from ..errors import GenerationError
from ..lanes import LaneConfig
from ..params import Params
from . import uturn
from .crossing import LinkFit
from .legs import LegKey
from .model import ConnectionPlan, JunctionPlan, RoadPlan, RoundaboutPlan, contact_point
from .planning import Junction
from .roads import Road, leg_ends
from .roundabout import RoadRole
from .survey import Survey


def _slots(junctions: dict[int, Junction]) -> list[tuple[int, int | None]]:
    """Every junction plan as (node, the roundabout's junction in driving order, or None for an ordinary junction),
    in plan order."""
    out: list[tuple[int, int | None]] = []
    for node in sorted(junctions):
        ring = junctions[node].ring
        out.extend([(node, None)] if ring is None else [(node, k) for k in range(len(ring.junctions))])
    return out


def _ring_bases(view: Survey, junctions: dict[int, Junction]) -> dict[int, int]:
    """Index of each roundabout's first ring road among the layout's roads (after the chains' roads)."""
    out, base = {}, len(view.chains)
    for node in sorted(junctions):
        ring = junctions[node].ring
        if ring is not None:
            out[node] = base
            base += len(ring.ring)
    return out


def junction_plans(
    view: Survey,
    junctions: dict[int, Junction],
    fitted: dict[int, list[LinkFit]],
    roads: list[Road],
    params: Params,
    rng: np.random.Generator,
) -> list[JunctionPlan]:
    """Every junction with its connection lanes (the fitted links, then any U-turns), in node order; a roundabout's
    arm junctions with theirs."""
    out = []
    bases = _ring_bases(view, junctions)
    for node, arm in _slots(junctions):
        if arm is not None:
            out.append(_arm_plan(junctions[node], arm, bases[node]))
            continue
        j, fits = junctions[node], fitted[node]
        conns = [_connection(j.keys, r) for r in fits]
        contacts, medians = leg_ends(roads, j.keys)
        conns.extend(uturn.u_turns(j.keys, j.links, contacts, medians, fits, params, rng))
        out.append(JunctionPlan(node, view.state.nodes[node], len(j.keys), tuple(conns)))
    return out


def _connection(keys: list[LegKey], r: LinkFit) -> ConnectionPlan:
    a, b = keys[r.leg_in], keys[r.leg_out]
    if r.fit is None:  # a guard: the links of a junction that fits all have a curve
        raise GenerationError(f"link from leg {r.leg_in} to leg {r.leg_out} has no curve; please report the seed")
    return ConnectionPlan(
        a.chain,
        contact_point(a.at_start),
        r.id_in,
        b.chain,
        contact_point(b.at_start),
        r.id_out,
        connection_geometry(r.start[0], r.start[1], r.hdg, r.fit),
        r.fit.min_radius,
    )


def _arm_plan(j: Junction, k: int, base: int) -> JunctionPlan:
    """A roundabout's ``k``-th junction (in driving order): the ring's lanes past it, its arms' entries and exits."""
    assert j.ring is not None  # only roundabouts have ring junctions
    junction, n = j.ring.junctions[k], len(j.ring.junctions)

    def road(role: RoadRole, incoming: bool) -> tuple[int, str]:
        kind, i = role
        if kind == "arm":
            key = j.keys[i]
            return key.chain, contact_point(key.at_start)
        return base + i % n, "end" if incoming else "start"

    conns = []
    for link in junction.links:
        (a, ca), (b, cb) = road(link.road_in, True), road(link.road_out, False)
        conns.append(ConnectionPlan(a, ca, link.lane_in, b, cb, link.lane_out, link.geometry, link.min_radius))
    return JunctionPlan(j.node, junction.position, 2 + len(junction.arms), tuple(conns))


def road_plans(view: Survey, roads: list[Road], junctions: dict[int, Junction]) -> list[RoadPlan]:
    """Every road with the junctions at its ends (None for a dead end) and its lane counts there; then the ring
    roads of the roundabouts."""
    slots = _slots(junctions)
    index = {slot: n for n, slot in enumerate(slots)}
    arm_of = {
        j.keys[arm.leg]: k
        for j in junctions.values()
        if j.ring is not None
        for k, ring_junction in enumerate(j.ring.junctions)
        for arm in ring_junction.arms
    }

    def junction_at(node: int, key: LegKey) -> int | None:
        if not view.is_junction(node):
            return None
        return index.get((node, arm_of.get(key)))

    out = []
    for c, ch in enumerate(view.chains):
        spec, g = roads[c].spec, roads[c].geometry
        out.append(
            RoadPlan(
                c,
                ch.start,
                ch.end,
                junction_at(ch.start, LegKey(c, True)),
                junction_at(ch.end, LegKey(c, False)),
                g,
                g[-1].s + g[-1].length,
                spec.lanes,
                spec.start.forward,
                spec.start.backward,
                spec.end.forward,
                spec.end.backward,
                spec.splitter_start,
                spec.splitter_end,
            )
        )
    for node in sorted(junctions):
        ring = junctions[node].ring
        if ring is None:
            continue
        n, lanes = len(ring.ring), ring.lanes
        for k, arc in enumerate(ring.ring):
            start, end = index[(node, k)], index[(node, (k + 1) % n)]
            cfg = LaneConfig(lanes, 0)
            out.append(
                RoadPlan(len(out), node, node, start, end, (arc,), arc.length, cfg, lanes, 0, lanes, 0, ring=True)
            )
    return out


def roundabout_plans(view: Survey, junctions: dict[int, Junction]) -> list[RoundaboutPlan]:
    """Every roundabout: its ring, its arm junctions and ring roads (indexes into the layout's junctions and roads)."""
    slots = _slots(junctions)
    index = {slot: n for n, slot in enumerate(slots)}
    bases = _ring_bases(view, junctions)
    out = []
    for node in sorted(bases):
        j = junctions[node]
        assert j.ring is not None  # bases holds roundabouts only
        n = len(j.ring.junctions)
        arms = tuple(
            (j.keys[a.leg].chain, contact_point(j.keys[a.leg].at_start), index[(node, k)])
            for k, ring_junction in enumerate(j.ring.junctions)
            for a in ring_junction.arms
        )
        out.append(
            RoundaboutPlan(
                node,
                j.ring.centre,
                j.ring.radius,
                j.ring.lanes,
                tuple(index[(node, k)] for k in range(n)),
                tuple(bases[node] + k for k in range(n)),
                arms,
            )
        )
    return out
