"""Connection lanes of one junction: a Hermite cubic for every lane link, and the verdict whether the junction fits.

A junction is fitted again and again as it grows and as repairs elsewhere restart the pass, mostly with links it has
seen before: each link's fit is kept by its target (end pose in the frame of its start), and each junction's crossing
test by its links and targets, so only what is new is computed (in one vectorised call).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple

import numpy as np

from ..curves import HermiteFit, fit_connections, local_target, wrap
from ..params import Params, TrafficRule
from .crossing import LinkFit, crossing
from .links import LinkPlan
from .roadshape import Contact

SCALES = np.linspace(0.2, 1.4, 17)  #: Hermite tangent lengths tried, in chords

#: A link's end point and heading change in the frame of its start: what its Hermite fit depends on.
Target = tuple[float, float, float]


class JunctionFit(NamedTuple):
    """The links of a junction and whether it must grow. When it must, every link is returned, those that failed
    with ``fit`` None; otherwise the links to build (every one fits)."""

    links: list[LinkFit]
    grow: bool


class LinkFitter:
    """Fits links, remembering fits and crossing tests across passes (see the module's docstring)."""

    def __init__(self, params: Params) -> None:
        self.p = params
        sign = -1.0 if params.traffic_rule is TrafficRule.RHT else 1.0
        #: the lane centre and outer border, from the reference line (the lane's inner border)
        self.offsets = (sign * params.lane_width / 2, sign * params.lane_width)
        self._fits: dict[Target, HermiteFit | None] = {}
        self._crossings: dict[tuple[tuple[LinkFit, ...], tuple[Target, ...]], set[int]] = {}

    def fit(
        self,
        plan: LinkPlan,
        contacts: list[Contact],
        medians: list[bool],
        may_drop: bool,
        roads: Sequence[int] = (),
    ) -> JunctionFit:
        """Connection geometry for every link of ``plan`` between legs meeting the junction at ``contacts``.

        A link that cannot meet the radius bound, or crosses another link from its road, makes the junction grow,
        unless ``may_drop`` (the junction has grown once already) and the links left keep what it gave
        (:func:`_droppable`): it is then left out. ``roads`` names each leg's road (two legs of one road: a loop)."""
        rows, targets = self._rows(plan, contacts, medians)
        out = self._fitted(rows, targets)
        bad = {n for n, r in enumerate(out) if r.fit is None}
        signature = (tuple(rows), tuple(targets))
        if signature not in self._crossings:
            self._crossings[signature] = crossing(out, bad)
        bad |= self._crossings[signature]
        if not bad:
            return JunctionFit(out, False)
        marked = JunctionFit([r._replace(fit=None) if n in bad else r for n, r in enumerate(out)], True)
        if not may_drop:
            return marked
        good = [r for n, r in enumerate(out) if n not in bad]
        if not _droppable([out[n] for n in sorted(bad)], good, roads):
            return marked
        return JunctionFit(good, False)

    def _rows(self, plan: LinkPlan, contacts: list[Contact], medians: list[bool]) -> tuple[list[LinkFit], list[Target]]:
        """Each link from the inner border of its incoming lane to that of its outgoing lane (not fitted yet)."""
        rows, targets = [], []
        for i, k, j, m in plan.links:
            lid_in, p0 = contacts[i].entering(k, medians[i], self.p)
            lid_out, p1 = contacts[j].leaving(m, medians[j], self.p)
            h0, h1 = contacts[i].inward, contacts[j].outward
            rows.append(LinkFit(i, k, j, m, lid_in, lid_out, p0, wrap(h0), None))
            targets.append(local_target(p0[0], p0[1], h0, p1[0], p1[1], h1))
        return rows, targets

    def _fitted(self, rows: list[LinkFit], targets: list[Target]) -> list[LinkFit]:
        """``rows`` with their fits, fitting the targets not seen before in one call."""
        todo = sorted({t for t in targets if t not in self._fits})
        if todo:
            fits = fit_connections(np.array(todo), self.offsets, self.p.min_turn_radius + 0.5, SCALES)
            self._fits.update(zip(todo, fits))
        return [r._replace(fit=self._fits[t]) for r, t in zip(rows, targets)]


def _droppable(bad: list[LinkFit], good: list[LinkFit], roads: Sequence[int]) -> bool:
    """Whether the ``bad`` links may be left out, the ``good`` ones kept: each bad link's incoming lane keeps another
    link and its outgoing lane another feeder. At a road looping back to the junction, a link between it and another
    road must also leave its loop lane another link with another road: a loop lane fed, or left, only through the
    loop's other end could never be entered from the rest of the map, or never be left."""
    exits = {(r.leg_in, r.lane_in) for r in good}
    feeds = {(r.leg_out, r.lane_out) for r in good}
    if any((r.leg_in, r.lane_in) not in exits or (r.leg_out, r.lane_out) not in feeds for r in bad):
        return False
    loops = {r for r in roads if list(roads).count(r) > 1}
    if not loops:
        return True
    across = [r for r in good if roads[r.leg_in] != roads[r.leg_out]]
    exits, feeds = {(r.leg_in, r.lane_in) for r in across}, {(r.leg_out, r.lane_out) for r in across}
    for r in bad:
        if roads[r.leg_in] == roads[r.leg_out]:
            continue
        if roads[r.leg_in] in loops and (r.leg_in, r.lane_in) not in exits:
            return False
        if roads[r.leg_out] in loops and (r.leg_out, r.lane_out) not in feeds:
            return False
    return True
