"""Fitting every junction's connection lanes, moving a junction's incident points outward until its turns fit.

A junction whose turns do not meet the radius bound (or whose lanes from one road would cross) grows at once: its
incident distances are scaled by :data:`GROWTH`, its legs' roads are rebuilt, and the junction at the other end of
each rebuilt road is fitted again (its links start where the road now ends). A junction that has grown
:data:`MAX_GROWTH` times drops the leg that still fails instead, so the queue empties.
"""

from __future__ import annotations

from collections import deque

from ..params import Params
from .crossing import LinkFit
from .fitting import LinkFitter
from .planning import Junction, Planner, Reach
from .roads import Road, build_road, leg_ends
from .survey import Survey

MAX_GROWTH = 10  #: growth steps of one junction before it drops a leg instead
GROWTH = 1.15  #: factor on a junction's incident distances per growth step


class Growth:
    """One pass's fitting queue; :meth:`run` gives the links of every junction."""

    def __init__(
        self,
        view: Survey,
        planner: Planner,
        fitter: LinkFitter,
        junctions: dict[int, Junction],
        reach: Reach,
        roads: list[Road],
        params: Params,
    ) -> None:
        self.view, self.st = view, view.state
        self.planner, self.fitter, self.p = planner, fitter, params
        self.junctions, self.reach, self.roads = junctions, reach, roads
        self.done: dict[int, list[LinkFit]] = {}
        # a roundabout's connection lanes were fitted with its design (:mod:`.roundabout`): it never grows
        self.queue = deque(n for n in sorted(junctions) if junctions[n].ring is None)
        self.queued = set(self.queue)
        self.ordinary = frozenset(self.queue)

    def run(self) -> dict[int, list[LinkFit]] | None:
        """The links to build at every junction (``roads`` then hold the roads they start from), or None when the
        network had to change (a leg dropped or a rebuilt road no longer fits): the pass starts again."""
        while self.queue:
            node = self.queue.popleft()
            self.queued.discard(node)
            if not self.st.touched([node]):
                self._visit(self.junctions[node])
        return None if self.st.dirty else self.done

    def _visit(self, j: Junction) -> None:
        contacts, medians = leg_ends(self.roads, j.keys)
        may_drop = self.st.growth.get(j.node, 0) >= 1
        fit = self.fitter.fit(j.links, contacts, medians, may_drop, [leg.road for leg in j.legs])
        if not fit.grow:
            self._accept(j, fit.links)
            return
        self.done.pop(j.node, None)
        if self._grow(j, fit.links):
            self._rebuild(j)

    def _accept(self, j: Junction, links: list[LinkFit]) -> None:
        """Keep the links, unless a leg has none left: no lane could enter or leave by it, so the leg goes."""
        used = {r.leg_in for r in links} | {r.leg_out for r in links}
        lost = [i for i in range(len(j.keys)) if i not in used]
        if lost:
            self.view.drop_leg(j.node, j.keys, lost, f"node {j.node}: dropped a leg without any lane link")
        else:
            self.done[j.node] = links

    def _grow(self, j: Junction, links: list[LinkFit]) -> bool:
        """One growth step, moving the incident points (whether it was taken: after :data:`MAX_GROWTH` steps a leg
        whose turns fail is dropped instead, and the node starts again at its first size)."""
        node = j.node
        self.st.growth[node] = self.st.growth.get(node, 0) + 1
        if self.st.growth[node] > MAX_GROWTH:
            failed = sorted({r.leg_in for r in links if r.fit is None})
            self.st.growth[node] = 0
            self.st.scale[node] = 1.0
            self.view.drop_leg(
                node, j.keys, failed, f"node {node}: dropped a leg whose turns stay under the radius bound"
            )
            return False
        self.st.scale[node] = self.st.scale.get(node, 1.0) * GROWTH
        self.st.repairs.append(f"node {node}: moved incident points outward (turn radius)")
        self.reach.update(zip(j.keys, self.planner.incident(j)))
        return True

    def _rebuild(self, j: Junction) -> None:
        """Rebuild the roads of the junction's legs; fit it again first, then the junctions at their other ends.
        A road that no longer fits is left to the next pass (its nodes are marked)."""
        rebuilt = []
        for c in sorted({k.chain for k in j.keys}):
            shape = build_road(self.view, self.roads[c].spec, self.reach, self.p)
            if shape.misfit is not None:
                self.st.dirty.update(self.view.chains[c].nodes)
                return
            self.roads[c] = self.roads[c]._replace(geometry=shape.geometry)
            rebuilt.append(c)
        for c in rebuilt:
            for other in (self.view.chains[c].start, self.view.chains[c].end):
                if other != j.node and other in self.ordinary and other not in self.queued:
                    self.done.pop(other, None)
                    self.queue.append(other)
                    self.queued.add(other)
        self.queue.appendleft(j.node)
        self.queued.add(j.node)
