"""Stage 3: the overpasses of stage 1 on the laid roads (:mod:`junctionart.scenario.overpass`).

The two roads of an overpass may overlap in plan view (the deck's clearance separates them). Once the roads are laid,
each overpass is measured again: where the reference lines cross, whether the upper road has room for both ramps and
the lower road for its level stretch, and whether neither road already holds another overpass (two roads of one
chain of edges could). One that does not fit becomes a junction (the upper edge is split where it
crosses the lower one); the next pass lays the new intersection.
"""

from __future__ import annotations

from ..params import Params
from ..scenario.overpass import crossing, fits, half_width
from .roads import Road
from .survey import Survey


def _chains(view: Survey) -> list[tuple[tuple[int, int], int, int]]:
    """Each overpass whose two edges still exist: ((upper, lower) edges, upper chain, lower chain)."""
    chain_of = {e: c for c, ch in enumerate(view.chains) for e in ch.edges}
    pairs = sorted(view.state.overpasses)
    return [(p, chain_of[p[0]], chain_of[p[1]]) for p in pairs if p[0] in chain_of and p[1] in chain_of]


def separated(view: Survey) -> frozenset[frozenset[int]]:
    """The pairs of chains (roads) an overpass separates in height."""
    return frozenset(frozenset((up, low)) for _, up, low in _chains(view) if up != low)


def _half(road: Road, params: Params) -> float:
    spec = road.spec
    counts = (spec.lanes.forward, spec.lanes.backward, *spec.start, *spec.end)
    return half_width(counts, spec.lanes.median, params)


def fit_overpasses(view: Survey, roads: list[Road], params: Params) -> tuple[tuple[int, int], ...]:
    """(upper, lower) road indexes of the overpasses that fit; the others become junctions (``view.state`` dirty)."""
    st = view.state
    out = []
    used: set[int] = set()  # one overpass per road: its stretches then never overlap another's
    for pair, up, low in _chains(view):
        ru, rl = roads[up], roads[low]
        c = crossing(ru.geometry, rl.geometry) if up != low and not {up, low} & used else None
        length_up = ru.geometry[-1].s + ru.geometry[-1].length
        length_low = rl.geometry[-1].s + rl.geometry[-1].length
        if c is not None and fits(length_up, length_low, c, _half(ru, params), _half(rl, params), params):
            out.append((up, low))
            used.update((up, low))
        elif not st.touched(view.chains[up].nodes + view.chains[low].nodes):
            st.at_grade(
                pair,
                f"overpass between nodes {view.chains[up].start} and {view.chains[up].end}: no room for "
                "its ramps on the laid road, a junction instead",
            )
    return tuple(out)
