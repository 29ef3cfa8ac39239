"""The values stage 3 hands to stage 4, from a pass that needed no repair: junction plans and road plans.

Kept apart from the pass so that what stage 4 receives (:mod:`.model`) is built in one place, from the pass's typed
results, and only once every junction fits.
"""

from __future__ import annotations

import numpy as np

from ..curves import connection_geometry
from ..errors import GenerationError
from ..params import Params
from . import uturn
from .crossing import LinkFit
from .legs import LegKey
from .model import ConnectionPlan, JunctionPlan, RoadPlan, contact_point
from .planning import Junction
from .roads import Road, leg_ends
from .survey import Survey


def junction_plans(
    view: Survey,
    junctions: dict[int, Junction],
    fitted: dict[int, list[LinkFit]],
    roads: list[Road],
    params: Params,
    rng: np.random.Generator,
) -> list[JunctionPlan]:
    """Every junction with its connection lanes (the fitted links, then any U-turns), in node order."""
    out = []
    for node in sorted(junctions):
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


def road_plans(view: Survey, roads: list[Road], junctions: dict[int, Junction]) -> list[RoadPlan]:
    """Every road with the junctions at its ends (None for a dead end) and its lane counts there."""
    junction_of = {node: n for n, node in enumerate(sorted(junctions))}
    out = []
    for c, ch in enumerate(view.chains):
        spec, g = roads[c].spec, roads[c].geometry
        out.append(
            RoadPlan(
                c,
                ch.start,
                ch.end,
                junction_of.get(ch.start) if view.is_junction(ch.start) else None,
                junction_of.get(ch.end) if view.is_junction(ch.end) else None,
                g,
                g[-1].s + g[-1].length,
                spec.lanes,
                spec.start.forward,
                spec.start.backward,
                spec.end.forward,
                spec.end.backward,
            )
        )
    return out
