"""Where a junction's incident points go: each leg's distance from the control point.

The junction area ends at the incident points, so they decide how large a junction is: far enough out for the legs'
lanes to part and for the linked turns to meet the radius bound, and no further (an oversized junction means long
connecting roads). A junction whose turns still do not fit moves them outward step by step (:mod:`.growth`).
"""

from __future__ import annotations

import math

from ..lanegeom import side_width
from ..params import Params
from ..scenario.roadside import roadside_width
from . import links as linkplan
from .legs import Leg, neighbour_gaps

MARGIN = 1.0  #: clearance between the stubs of neighbouring legs


def incident_distances(L: list[Leg], plan: linkplan.LinkPlan, params: Params, scale: float) -> list[float]:
    """Distance of each leg's incident point from the control point: the paper's W / sin(d) rule with the legs'
    actual widths, room for a turn between neighbouring legs that ``plan`` links, times ``scale`` (the node's
    random factor and growth). Neighbours at a sharp angle that no lane links need only keep their stubs apart."""
    # lanes at the junction: a turn lane added before it widens the incoming side
    # (the roadside lanes, when the map has them, widen every leg alike)
    half = [
        max(
            side_width(max(leg.n_in, plan.n_in_end[i]), leg.median, params.lane_width, params.median_width),
            side_width(leg.n_out, leg.median, params.lane_width, params.median_width),
        )
        + roadside_width(params)
        for i, leg in enumerate(L)
    ]
    r = [h + params.min_turn_radius + 2.0 for h in half]
    turn_r = params.min_turn_radius + 1.0 + params.lane_width / 2
    linked = {frozenset((i, j)) for i, _, j, _ in plan.links}
    for d, a, b in neighbour_gaps(L):
        W = half[a] + half[b] + MARGIN
        need = W / max(math.sin(d), 1e-3) if d < math.pi / 2 else W
        if d < math.pi and frozenset((a, b)) in linked:
            # a kerb-side turn through the wedge: tangent points of a circle of radius turn_r fitted between
            # the two legs' outer lanes lie (offset + radius) / tan(d / 2) from the control point
            need = max(need, (max(half[a], half[b]) + turn_r) / max(math.tan(d / 2), 1e-3))
        r[a], r[b] = max(r[a], need), max(r[b], need)
    return [x * scale for x in r]
