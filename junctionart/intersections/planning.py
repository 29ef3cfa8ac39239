"""Junction plans: each junction's legs, lane links and incident distances.

Plans are made afresh every pass (a repair elsewhere can change a junction's legs), but what was drawn at random
stays drawn: a leg's turn-lane and split choices live in the network state, a node's random size factor too, and a
plan that drew nothing new is kept for the next pass with the same legs. So a junction keeps its random choices while
repairs elsewhere make the pass start again.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..controllines import RoundaboutRequest
from ..params import Params
from . import links as linkplan
from .legs import Leg, LegKey
from .placement import incident_distances
from .roundabout import ArmLeg, Design, design
from .roundabout_choice import choose, nearest_requests
from .state import NetworkState
from .survey import Survey


class Junction(NamedTuple):
    node: int
    keys: list[LegKey]  #: the legs, sorted
    legs: list[Leg]  #: heading and lane counts of each of ``keys``
    links: linkplan.LinkPlan
    ring: Design | None = None  #: the roundabout this junction is built as (its links are then empty)


#: Distance of each leg's incident point from its control point (where its road ends and the junction begins).
Reach = dict[LegKey, float]


class Planner:
    """Plans junctions, keeping link plans across passes (see the module's docstring)."""

    def __init__(
        self,
        st: NetworkState,
        params: Params,
        rng: np.random.Generator,
        requests: tuple[RoundaboutRequest, ...] = (),
    ) -> None:
        self.st = st
        self.p = params
        self.rng = rng
        self.requests = requests
        self._plans: dict[tuple[Leg, ...], linkplan.LinkPlan] = {}
        self._rings: dict[tuple, Design | None] = {}
        #: what became of each roundabout asked for in the last plan (grown, or an ordinary junction), by node
        self.notes: dict[int, str] = {}

    def plan_all(self, view: Survey, legs_at: dict[int, list[LegKey]]) -> tuple[dict[int, Junction], Reach]:
        """Every junction's plan (by node, in node order) and the incident distance of every leg."""
        junctions: dict[int, Junction] = {}
        reach: Reach = {}
        asked = nearest_requests(self.requests, {n: self.st.nodes[n] for n in legs_at}) if self.requests else {}
        self.notes = {}
        for node in sorted(legs_at):
            keys = sorted(legs_at[node])
            legs = [view.leg(k) for k in keys]
            ring = self._roundabout(node, keys, legs, asked.get(node))
            if ring is not None:
                junction = Junction(node, keys, legs, _ring_links(ring, len(keys)), ring)
                junctions[node] = junction
                reach.update((keys[arm.leg], arm.reach) for arm in ring.arms)
                continue
            junction = Junction(node, keys, legs, self._links(legs))
            junctions[node] = junction
            reach.update(zip(keys, self.incident(junction)))
        return junctions, reach

    def _roundabout(
        self, node: int, keys: list[LegKey], legs: list[Leg], request: RoundaboutRequest | None
    ) -> Design | None:
        """The roundabout junction ``node`` becomes, or None. Designs are kept by what they depend on, so a repair
        elsewhere costs no new design; one that had to grow, or could not fit, leaves a note (:attr:`notes`)."""
        xy = self.st.nodes[node]
        spec = choose(xy, len(legs), self.p, request)
        if spec is None:
            return None
        arms = [ArmLeg(i, g.angle, g.n_in, g.n_out, g.median, k.at_start) for i, (k, g) in enumerate(zip(keys, legs))]
        key = (xy, tuple(arms), spec)
        if key not in self._rings:
            self._rings[key] = design(xy, arms, spec, self.p)
        found = self._rings[key]
        if found is None:
            self.notes[node] = (
                f"node {node}: no roundabout of outer radius {spec.radius:g} to {spec.largest:g} m "
                f"fits its {len(legs)} arms; an ordinary junction instead"
            )
        elif found.radius > spec.radius:
            self.notes[node] = (
                f"node {node}: roundabout grown from outer radius {spec.radius:g} m to {found.radius:g} m to fit its "
                f"{len(legs)} arms and {spec.lanes} lane(s)"
            )
        return found

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


def _ring_links(ring: Design, n: int) -> linkplan.LinkPlan:
    """A roundabout's lanes at each arm's end (its lane links are the arm junctions' own, :class:`Design`)."""
    n_in, n_out = [0] * n, [0] * n
    for arm in ring.arms:
        n_in[arm.leg], n_out[arm.leg] = arm.n_in, arm.n_out
    return linkplan.LinkPlan(tuple(n_in), tuple(n_out), ())
