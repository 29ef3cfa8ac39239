"""Junction plans: each junction's legs, lane links and incident distances.

Plans are made afresh every pass (a repair elsewhere can change a junction's legs), but what was drawn at random
stays drawn: a leg's turn-lane and split choices live in the network state, a node's random size factor too, and a
plan that drew nothing new is kept for the next pass with the same legs. So a junction keeps its random choices while
repairs elsewhere make the pass start again.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..params import Params
from . import links as linkplan
from .legs import Leg, LegKey
from .placement import incident_distances
from .state import NetworkState
from .survey import Survey


class Junction(NamedTuple):
    node: int
    keys: list[LegKey]  #: the legs, sorted
    legs: list[Leg]  #: heading and lane counts of each of ``keys``
    links: linkplan.LinkPlan


#: Distance of each leg's incident point from its control point (where its road ends and the junction begins).
Reach = dict[LegKey, float]


class Planner:
    """Plans junctions, keeping link plans across passes (see the module's docstring)."""

    def __init__(self, st: NetworkState, params: Params, rng: np.random.Generator) -> None:
        self.st = st
        self.p = params
        self.rng = rng
        self._plans: dict[tuple[Leg, ...], linkplan.LinkPlan] = {}

    def plan_all(self, view: Survey, legs_at: dict[int, list[LegKey]]) -> tuple[dict[int, Junction], Reach]:
        """Every junction's plan (by node, in node order) and the incident distance of every leg."""
        junctions: dict[int, Junction] = {}
        reach: Reach = {}
        for node in sorted(legs_at):
            keys = sorted(legs_at[node])
            legs = [view.leg(k) for k in keys]
            junction = Junction(node, keys, legs, self._links(legs))
            junctions[node] = junction
            reach.update(zip(keys, self.incident(junction)))
        return junctions, reach

    def _links(self, legs: list[Leg]) -> linkplan.LinkPlan:
        """The lane links of a junction with these legs. A plan that drew nothing new depends on the legs alone (what
        was drawn for a leg never changes), so it is kept for the next pass."""
        key = tuple(legs)
        if key in self._plans:
            return self._plans[key]
        known = len(self.st.drawn)
        plan = linkplan.plan(legs, self.p, self.rng, self.st.drawn)
        if len(self.st.drawn) == known:
            self._plans[key] = plan
        return plan

    def incident(self, junction: Junction) -> list[float]:
        """Incident distances of the junction's legs, times its node's random factor (drawn once) and growth."""
        node = junction.node
        if node not in self.st.factor:
            self.st.factor[node] = float(self.rng.uniform(1.0, 1.2))
        return incident_distances(
            junction.legs, junction.links, self.p, self.st.factor[node] * self.st.scale.get(node, 1.0)
        )
