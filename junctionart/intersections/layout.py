"""Stage 3: incident points, road geometry and connection lanes, repairing until every intersection fits.

The loop never discards a map. When something does not fit it changes the network, always towards a state that
fits, and records what it did (``Layout.repairs``):

* a node with more than 7 legs loses a leg;
* a bend (2-leg node) too sharp for its roads' lanes is cut open when the map stays connected (one side becomes a dead
  end), otherwise straightened (split into a new intersection where the straight road crosses another);
* a road too short for its two incident points and lane tapers merges its two junctions into one when that has at
  most 7 legs, otherwise it is removed when the map stays connected without it, otherwise merged anyway;
* an intersection whose turns do not meet the radius bound, or whose connection lanes from one road would cross,
  gets its incident points moved outward (its roads are rebuilt at once); after one step, links that still fail are
  dropped where every incoming lane keeps a link and every outgoing lane a feeder; after ``MAX_GROWTH`` steps the
  leg that still fails is dropped;
* roads or junction areas that overlap where the map does not connect them lose a road (an overpass's two roads are
  connected by its deck's clearance);
* a one-way road is made two-way where repairs left part of the map that traffic cannot enter or leave;
* an overpass whose laid roads leave no room for its ramps becomes a junction (:mod:`.overpasses`).

Each repair removes an edge or a node or enlarges a bounded counter, so the loop ends. Repairs that touch different
parts of the network share one pass: a repair marks the nodes it touched, later repairs in the pass leave them alone,
and the pass starts again after the phase that made any repair.

A pass runs these phases, each in its own module:

1. :mod:`.survey`: chains, degrees and legs of the current network;
2. :mod:`.prune`: too many legs, legs too close together, legs without an exit or entry;
3. :mod:`.planning`: each junction's lane links and incident distances;
4. :mod:`.roads`: each road's geometry between its incident points (:mod:`.roadshape`);
5. :mod:`.growth`: each junction's connection lanes (:mod:`.fitting`), growing junctions whose turns do not fit;
6. :mod:`.assemble` and :mod:`.overlap`: the junction plans, then the overlap test, then the road plans.
"""

from __future__ import annotations

import numpy as np

from ..errors import GenerationError
from ..lanes import LanedNetwork
from ..params import Params
from .assemble import junction_plans, road_plans, roundabout_plans
from .fitting import SCALES, LinkFitter
from .growth import Growth
from .model import Layout
from .overlap import remove_overlaps
from .overpasses import fit_overpasses
from .planning import Planner
from .prune import drop_acute_legs, drop_excess_legs, open_exits, open_ways
from .roads import lay_roads
from .state import NetworkState
from .survey import Survey

__all__ = ["SCALES", "Builder", "build"]  # SCALES: the fit's tangent lengths, which tests sweep


class Builder:
    """Stage 3 for one network: the state that repairs edit, and what is kept from pass to pass (random choices,
    link plans, fits)."""

    def __init__(self, laned: LanedNetwork, params: Params, rng: np.random.Generator) -> None:
        net = laned.network
        self.p = params
        self.rng = rng
        self.st = NetworkState(list(net.nodes), {k: (e.u, e.v, laned.lanes[k]) for k, e in enumerate(net.edges)})
        self.st.overpasses = set(net.overpasses)
        self.planner = Planner(self.st, params, rng, net.roundabouts)
        self.fitter = LinkFitter(params)

    def run(self) -> Layout:
        limit = 20 * (len(self.st.edges) + len(self.st.nodes)) + 100
        for _ in range(limit):
            layout = self.run_once()
            if layout is not None:
                return layout
        # every repair shrinks the network or spends a bounded budget, so this is a guard, not an outcome
        raise GenerationError(f"stage 3 did not settle after {limit} passes; please report the seed and parameters")

    def run_once(self) -> Layout | None:
        """One pass over the whole network: the layout, or None when a repair changed the network (the next pass
        starts from the changed network)."""
        st = self.st
        st.dirty = set()
        view = Survey.take(st)
        if st.dirty:
            return None
        legs_at = view.legs_at()
        drop_excess_legs(view, legs_at)
        if st.dirty:
            return None
        drop_acute_legs(view, legs_at, self.p)
        if st.dirty:
            return None
        open_exits(view, legs_at)
        open_ways(view)
        junctions, reach = self.planner.plan_all(view, legs_at)
        roads = lay_roads(view, junctions, reach, self.p)
        if roads is None:
            return None
        fitted = Growth(view, self.planner, self.fitter, junctions, reach, roads, self.p).run()
        if fitted is None:
            return None
        plans = junction_plans(view, junctions, fitted, roads, self.p, self.rng)
        remove_overlaps(view, roads, junctions, plans, self.p)
        if st.dirty:
            return None
        decks = fit_overpasses(view, roads, self.p)
        if st.dirty:
            return None
        rings = tuple(roundabout_plans(view, junctions))
        repairs = (*st.repairs, *(self.planner.notes[n] for n in sorted(self.planner.notes)))
        return Layout(tuple(road_plans(view, roads, junctions)), tuple(plans), repairs, decks, rings)


def build(laned: LanedNetwork, params: Params, rng: np.random.Generator) -> Layout:
    """Stage 3 for a whole network."""
    return Builder(laned, params, rng).run()
