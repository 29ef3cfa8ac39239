"""Leg repairs made before any geometry: too many legs, legs too close together, legs nobody can enter or leave by.

These depend only on the graph and the lane counts, so they run first: a leg they remove would otherwise cost a
junction plan, road geometry and connection fits that are thrown away.
"""

from __future__ import annotations

import math

from ..lanes import LaneConfig, both_ways_where_needed
from ..params import Params
from .legs import MAX_LEGS, LegKey, neighbour_gaps
from .survey import Survey


def drop_excess_legs(view: Survey, legs_at: dict[int, list[LegKey]]) -> None:
    """A node with more than :data:`MAX_LEGS` legs loses the leg after its narrowest gap (the one most in the way)."""
    for node in sorted(legs_at):
        keys = legs_at[node]
        if len(keys) > MAX_LEGS and not view.state.touched([node]):
            prefer = [g.first for g in sorted(neighbour_gaps([view.leg(k) for k in keys]))]
            view.drop_leg(node, keys, prefer, f"node {node}: dropped a leg ({len(keys)} legs, at most 7)")


def drop_acute_legs(view: Survey, legs_at: dict[int, list[LegKey]], params: Params) -> None:
    """Two legs closer than ``min_leg_angle`` need a junction several times larger than a square one (their stubs
    only part far from the control point): one of them is removed where the map stays connected without it, as
    engineers realign skewed approaches. Where both are needed, the junction is built as drawn."""
    limit = math.radians(params.min_leg_angle)
    if limit <= 0:
        return
    for node in sorted(legs_at):
        if not view.state.touched([node]):
            _drop_acute_leg(view, node, legs_at[node], limit)


def _drop_acute_leg(view: Survey, node: int, keys: list[LegKey], limit: float) -> None:
    """At most one removal at ``node``: the narrowest gap under ``limit`` where either leg can go."""
    legs = [view.leg(k) for k in keys]
    for gap, a, b in sorted(neighbour_gaps(legs)):
        if gap >= limit:
            return
        # the leg with fewer lanes goes first; a leg whose road is needed for connectivity stays
        for i in sorted((a, b), key=lambda i: (legs[i].n_in + legs[i].n_out, i)):
            ch = view.chains[keys[i].chain]
            # the whole road goes (no dead-end stub left by the junction), but only the leg's edge of a loop
            road = {view.leg_edge(keys[i])} if ch.start == ch.end else set(ch.edges)
            if view.state.connected_without(road):
                why = f"node {node}: removed a road whose leg was {math.degrees(gap):.0f} deg from its neighbour"
                for e in sorted(road):
                    view.state.remove_edge(e, why)
                return


def open_exits(view: Survey, legs_at: dict[int, list[LegKey]]) -> None:
    """Every leg with lanes in gets another leg with lanes out, and the other way round: a one-way road next to it
    (counter-clockwise) is opened the other way. One change at a time, since it changes the legs of two nodes."""
    for _ in range(10 * len(view.chains) + 10):
        if not _open_one_exit(view, legs_at):
            return


def open_ways(view: Survey) -> None:
    """Stage 2 leaves every node reaching every other one through the roads' directions; a repair since (a road
    removed, two junctions merged) can break that, and leave a junction traffic never enters or never leaves (a loop
    road whose only other leg is a one-way road out of it). One-way roads are then made two-way again, as stage 2
    does (:func:`~junctionart.lanes.both_ways_where_needed`)."""
    drawn = [(ch, view.lanes(c)) for c, ch in enumerate(view.chains)]
    for c, ((ch, before), (_, after)) in enumerate(zip(drawn, both_ways_where_needed(drawn, view.degree))):
        if after != before:
            view.set_lanes(c, after)
            view.state.repairs.append(
                f"road from node {ch.start} to node {ch.end} made two-way: without it, part of the map could not be "
                "entered or left"
            )


def _open_one_exit(view: Survey, legs_at: dict[int, list[LegKey]]) -> bool:
    """Open the first missing exit or entry; whether there was one."""
    for node in sorted(legs_at):
        keys = legs_at[node]
        legs = [view.leg(k) for k in keys]
        order = sorted(range(len(keys)), key=lambda i: legs[i].angle)
        for n, i in enumerate(order):
            others = [legs[j] for j in order if j != i]
            need_out = legs[i].n_in > 0 and not any(o.n_out for o in others)
            need_in = legs[i].n_out > 0 and not any(o.n_in for o in others)
            if need_out or need_in:
                _open(view, keys[order[(n + 1) % len(order)]], need_out)
                return True
    return False


def _open(view: Survey, key: LegKey, outward: bool) -> None:
    """Give leg ``key`` a lane out of its junction (``outward``) or into it."""
    cfg = view.lanes(key.chain)
    # outgoing at a chain start is forward; incoming at a chain start is backward
    f, b = cfg.forward, cfg.backward
    if outward == key.at_start:
        f = max(f, 1)
    else:
        b = max(b, 1)
    view.set_lanes(key.chain, LaneConfig(f, b, cfg.median))
