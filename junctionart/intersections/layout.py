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
  dropped where every incoming lane keeps a link and every outgoing lane a feeder; after :data:`MAX_GROWTH` steps the
  leg that still fails is dropped;
* roads or junction areas that overlap where the map does not connect them lose a road.

Each repair removes an edge or a node or enlarges a bounded counter, so the loop ends. Repairs that touch different
parts of the network share one pass.
"""

from __future__ import annotations

import math
from collections import deque

import numpy as np

from ..curves import (
    HermiteFit,
    connection_geometry,
    end_pose,
    fit_connections,
    local_target,
    wrap,
)
from ..errors import GenerationError
from ..graph import Chain, chains
from ..lanegeom import (
    border_point,
    inner_offset,
    lane_id,
    taper_length,
)
from ..lanes import LaneConfig, LanedNetwork
from ..params import Params, TrafficRule
from . import links as linkplan
from . import uturn
from .crossing import LinkFit, crossing
from .legs import Leg, neighbour_gaps
from .model import ConnectionPlan, JunctionPlan, Layout, RoadPlan
from .overlap import overlaps
from .placement import incident_distances, road_geometry
from .state import NetworkState

MAX_LEGS = 7
MAX_GROWTH = 10
GROWTH = 1.15
MIN_ROAD = 5.0  #: shortest road written between two junctions
SCALES = np.linspace(0.2, 1.4, 17)  #: Hermite tangent lengths tried, in chords


class _Repair(Exception):
    """Raised inside one pass when the network was changed; the pass starts again."""


class Builder:
    def __init__(self, laned: LanedNetwork, params: Params, rng: np.random.Generator) -> None:
        net = laned.network
        self.p = params
        self.rng = rng
        self.w = params.lane_width
        self.mw = params.median_width
        self.st = NetworkState(list(net.nodes), {k: (e.u, e.v, laned.lanes[k]) for k, e in enumerate(net.edges)})
        self._fits: dict[tuple[float, float, float], HermiteFit | None] = {}
        self._crossings: dict[tuple, set[int]] = {}
        self._plans: dict[tuple[Leg, ...], linkplan.LinkPlan] = {}

    # ---------------------------------------------------------------------------------------------------------------
    # graph helpers
    # ---------------------------------------------------------------------------------------------------------------
    def _ids(self) -> list[int]:
        return sorted(self.st.edges)

    def _chains(self) -> list[Chain]:
        """Chains of the current network, naming edges by their ids."""
        ids = self._ids()
        ch = chains(len(self.st.nodes), [self.st.edges[k][:2] for k in ids])
        return [Chain(c.nodes, tuple(ids[e] for e in c.edges), c.forward) for c in ch]

    # ---------------------------------------------------------------------------------------------------------------
    # one pass
    # ---------------------------------------------------------------------------------------------------------------
    def _normalise(self, chs: list[Chain], deg: list[int]) -> None:
        """Give every chain one configuration (its first edge's); break pure cycles."""
        for ch in chs:
            if ch.start == ch.end and deg[ch.start] == 2:
                self.st.remove_edge(
                    ch.edges[0], f"removed a road forming a closed loop without junction at node {ch.start}"
                )
                continue
            first = self.st.edges[ch.edges[0]][2]
            cfg = first if ch.forward[0] else first.reversed()
            if deg[ch.start] == 1 or deg[ch.end] == 1:
                cfg = LaneConfig(max(cfg.forward, 1), max(cfg.backward, 1), cfg.median)
            if not (cfg.forward and cfg.backward):
                cfg = LaneConfig(cfg.forward, cfg.backward, False)
            for e, fw in zip(ch.edges, ch.forward):
                u, v, _ = self.st.edges[e]
                self.st.edges[e] = (u, v, cfg if fw else cfg.reversed())

    def _chain_cfg(self, ch: Chain) -> LaneConfig:
        cfg = self.st.edges[ch.edges[0]][2]
        return cfg if ch.forward[0] else cfg.reversed()

    def _set_chain_cfg(self, ch: Chain, cfg: LaneConfig) -> None:
        for e, fw in zip(ch.edges, ch.forward):
            u, v, _ = self.st.edges[e]
            self.st.edges[e] = (u, v, cfg if fw else cfg.reversed())

    def _legs(self, chs: list[Chain], deg: list[int]) -> dict[int, list[tuple[int, bool]]]:
        legs: dict[int, list[tuple[int, bool]]] = {}
        for c, ch in enumerate(chs):
            if deg[ch.start] >= 3:
                legs.setdefault(ch.start, []).append((c, True))
            if deg[ch.end] >= 3:
                legs.setdefault(ch.end, []).append((c, False))
        return legs

    def _leg(self, chs: list[Chain], key: tuple[int, bool]) -> Leg:
        c, at_start = key
        ch = chs[c]
        cfg = self._chain_cfg(ch)
        if at_start:
            a, b = self.st.nodes[ch.nodes[0]], self.st.nodes[ch.nodes[1]]
            n_in, n_out = cfg.backward, cfg.forward
        else:
            a, b = self.st.nodes[ch.nodes[-1]], self.st.nodes[ch.nodes[-2]]
            n_in, n_out = cfg.forward, cfg.backward
        node, edge = (ch.nodes[0], ch.edges[0]) if at_start else (ch.nodes[-1], ch.edges[-1])
        return Leg((node, edge), math.atan2(b[1] - a[1], b[0] - a[0]), n_in, n_out, cfg.median)

    def _acute_legs(self, chs: list[Chain], legs_at: dict[int, list[tuple[int, bool]]]) -> None:
        """Two legs closer than ``min_leg_angle`` need a junction several times larger than a square one (their
        stubs only part far from the control point): one of them is removed where the map stays connected without
        it, as engineers realign skewed approaches. Where both are needed, the junction is built as drawn."""
        limit = math.radians(self.p.min_leg_angle)
        for node in sorted(legs_at):
            keys = legs_at[node]
            if self.st.touched([node]) or limit <= 0:
                continue
            L = [self._leg(chs, k) for k in keys]
            for gap, a, b in sorted(neighbour_gaps(L)):
                if gap >= limit:
                    break
                # the leg with fewer lanes goes first; a leg whose road is needed for connectivity stays
                cands = sorted((a, b), key=lambda i: (L[i].n_in + L[i].n_out, i))
                edges = [chs[keys[i][0]].edges[0] if keys[i][1] else chs[keys[i][0]].edges[-1] for i in cands]
                edges = [e for e in edges if e in self.st.edges]
                # the whole road goes (no dead-end stub left by the junction), but only the leg's edge of a loop
                chain_of = {
                    e: {e} if chs[keys[i][0]].start == chs[keys[i][0]].end else set(chs[keys[i][0]].edges)
                    for i, e in zip(cands, edges)
                }
                for e in edges:
                    if self.st.connected_without(chain_of[e]):
                        for x in sorted(chain_of[e]):
                            if x in self.st.edges:
                                self.st.remove_edge(
                                    x,
                                    f"node {node}: removed a road whose leg was "
                                    f"{math.degrees(gap):.0f} deg from its neighbour",
                                )
                        break
                else:
                    continue
                break

    def _fix_exits(self, chs: list[Chain], legs: dict[int, list[tuple[int, bool]]]) -> None:
        """Every leg with lanes in has another leg with lanes out, and the other way round (opening one-way roads)."""
        for _ in range(10 * len(chs) + 10):
            changed = False
            for node in sorted(legs):
                keys = sorted(legs[node], key=lambda k: self._leg(chs, k).angle)
                L = [self._leg(chs, k) for k in keys]
                for i, leg in enumerate(L):
                    others = [L[j] for j in range(len(L)) if j != i]
                    need_out = leg.n_in > 0 and not any(o.n_out for o in others)
                    need_in = leg.n_out > 0 and not any(o.n_in for o in others)
                    if need_out or need_in:
                        key = keys[(i + 1) % len(keys)]
                        ch = chs[key[0]]
                        cfg = self._chain_cfg(ch)
                        # outgoing at a chain start is forward; incoming at a chain start is backward
                        f, b = cfg.forward, cfg.backward
                        if need_out:
                            f, b = (max(f, 1), b) if key[1] else (f, max(b, 1))
                        else:
                            f, b = (f, max(b, 1)) if key[1] else (max(f, 1), b)
                        self._set_chain_cfg(ch, LaneConfig(f, b, cfg.median))
                        changed = True
                        break
                if changed:
                    break
            if not changed:
                return

    def _plan(self, L: list[Leg]) -> linkplan.LinkPlan:
        """The lane links of a junction with legs ``L``. A plan that drew nothing new depends on the legs alone (what
        was drawn for a leg never changes), so it is kept for the next pass."""
        key = tuple(L)
        if key in self._plans:
            return self._plans[key]
        known = len(self.st.drawn)
        plan = linkplan.plan(L, self.p, self.rng, self.st.drawn)
        if len(self.st.drawn) == known:
            self._plans[key] = plan
        return plan

    def _incident(self, node: int, L: list[Leg], plan: linkplan.LinkPlan) -> list[float]:
        if node not in self.st.factor:
            self.st.factor[node] = float(self.rng.uniform(1.0, 1.2))
        return incident_distances(L, plan, self.p, self.st.factor[node] * self.st.scale.get(node, 1.0))

    def _road_geometry(
        self,
        ch: Chain,
        r0: float,
        r1: float,
        need: float,
        cfg: LaneConfig,
        ends: tuple[tuple[int, int], tuple[int, int]],
    ):
        return road_geometry([self.st.nodes[n] for n in ch.nodes], r0, r1, need, cfg, ends, self.p)

    def _merge_instead(self, ch: Chain, deg: list[int]) -> bool:
        """A road too short for its two junctions merges them into one when that has at most 7 legs (more varied
        intersections than removing the road); otherwise the road is removed if the map stays connected."""
        return ch.start != ch.end and deg[ch.start] + deg[ch.end] - 2 <= MAX_LEGS

    def _overlap_repair(self, chs: list[Chain], geoms: list, plans: dict, jplans: list[JunctionPlan]) -> None:
        """Roads and junction areas (with every connection lane) may only touch where the map connects them;
        otherwise a road is removed (one whose removal keeps the map connected when there is one)."""
        ends = {
            node: [(geoms[c][0], geoms[c][1], at_start) for c, at_start in keys]
            for node, (keys, *_rest) in plans.items()
        }
        lanes = {jp.node: [c.geometry for c in jp.connections] for jp in jplans}
        for cands in overlaps(chs, [(g[0], g[1]) for g in geoms], ends, lanes, self.p):
            if any(self.st.touched(chs[c].nodes) for c in cands):
                continue
            for c in cands:
                if self.st.connected_without(set(chs[c].edges)):
                    break
            else:
                c = cands[0]
            for e in chs[c].edges:
                del self.st.edges[e]
            self.st.dirty.update(chs[c].nodes)
            self.st.repairs.append(
                f"removed road between nodes {chs[c].start} and {chs[c].end}: it overlapped another road or junction"
            )

    def _drop_leg(self, node: int, keys: list[tuple[int, bool]], chs: list[Chain], prefer: list[int], why: str) -> None:
        """Remove the edge of one leg at ``node``: the first of ``prefer`` (leg indexes) that is not a bridge."""
        cands = []
        for i in prefer:
            c, at_start = keys[i]
            e = chs[c].edges[0] if at_start else chs[c].edges[-1]
            if e in self.st.edges:
                cands.append(e)
        if not cands:
            return
        for e in cands:
            if self.st.connected_without(e):
                self.st.remove_edge(e, why)
                return
        self.st.remove_edge(cands[0], why + " (the map loses the part behind it)")

    def _fit(self, node: int, plan: linkplan.LinkPlan, contact, median) -> tuple[list[LinkFit], bool]:
        """Connection geometry for every link (one vectorised fit for the links not seen before).

        Returns the links that fit and whether the junction must grow: a link that cannot meet the radius bound is
        dropped once the junction has grown at least once, provided its incoming lane keeps another link and its
        outgoing lane another feeder; otherwise the junction grows.
        """
        rule = self.p.traffic_rule
        sign = -1.0 if rule is TrafficRule.RHT else 1.0
        offsets = (sign * self.w / 2, sign * self.w)
        rows, keys = [], []
        for i, k, j, m in plan.links:
            xi, yi, hi, at_start_i = contact[i]
            xj, yj, hj, at_start_j = contact[j]
            lid_in = lane_id(not at_start_i, k, median[i], rule)
            lid_out = lane_id(at_start_j, m, median[j], rule)
            p0 = border_point(xi, yi, hi, inner_offset(lid_in, median[i], self.w, self.mw))
            p1 = border_point(xj, yj, hj, inner_offset(lid_out, median[j], self.w, self.mw))
            h0 = hi + (math.pi if at_start_i else 0.0)
            h1 = hj + (0.0 if at_start_j else math.pi)
            rows.append(LinkFit(i, k, j, m, lid_in, lid_out, p0, wrap(h0), None))
            keys.append(local_target(p0[0], p0[1], h0, p1[0], p1[1], h1))
        todo = sorted({key for key in keys if key not in self._fits})
        if todo:
            for key, fit in zip(todo, fit_connections(np.array(todo), offsets, self.p.min_turn_radius + 0.5, SCALES)):
                self._fits[key] = fit
        out = [r._replace(fit=self._fits[key]) for r, key in zip(rows, keys)]
        bad = {n for n, r in enumerate(out) if r.fit is None}
        signature = (tuple(rows), tuple(keys))
        if signature not in self._crossings:
            self._crossings[signature] = crossing(out, bad)
        bad |= self._crossings[signature]
        if not bad:
            return out, False
        marked = [r._replace(fit=None) if n in bad else r for n, r in enumerate(out)]
        if self.st.growth.get(node, 0) < 1:
            return marked, True
        good = [r for n, r in enumerate(out) if n not in bad]
        lanes_ok = {(r.leg_in, r.lane_in) for r in good}
        fed_ok = {(r.leg_out, r.lane_out) for r in good}
        for n in bad:
            if (out[n].leg_in, out[n].lane_in) not in lanes_ok or (out[n].leg_out, out[n].lane_out) not in fed_ok:
                return marked, True
        return good, False

    @staticmethod
    def _contacts(
        keys: list[tuple[int, bool]], geoms: list
    ) -> tuple[list[tuple[float, float, float, bool]], list[bool]]:
        """Per leg: the pose where its road meets the junction (and whether that is the road's start), and whether
        the road has a median."""
        contact, median = [], []
        for c, at_start in keys:
            g = geoms[c][0]
            if at_start:
                contact.append((g[0].x, g[0].y, g[0].hdg, True))
            else:
                e = end_pose(g[-1])
                contact.append((e.x, e.y, e.hdg, False))
            median.append(geoms[c][1].median)
        return contact, median

    def _u_turns(
        self, node: int, keys: list[tuple[int, bool]], plan: linkplan.LinkPlan, geoms: list, fits: list[LinkFit]
    ) -> list[ConnectionPlan]:
        """U-turn lanes of a finished junction: on legs where one meets the radius bound and crosses none of its
        road's other connection lanes, each with probability ``u_turn_probability``. Drawn last in stage 3, so the
        rest of the map does not depend on them."""
        if self.p.u_turn_probability <= 0.0:
            return []
        contact, median = self._contacts(keys, geoms)
        out = []
        for i, (c, at_start) in enumerate(keys):
            if plan.n_in_end[i] == 0:
                continue
            turn = uturn.candidate(i, contact[i], median[i], plan.n_out_end[i], self.p)
            if turn is None or uturn.crosses(turn, 1, fits, self.p):
                continue
            if self.rng.random() >= self.p.u_turn_probability:
                continue
            side = "start" if at_start else "end"
            out.append(ConnectionPlan(c, side, turn.id_in, c, side, turn.id_out, turn.geometry, turn.radius))
        return out

    def run_once(self) -> Layout:
        """One pass over the whole network. Repairs are applied as they are found; whatever they touched is left
        alone for the rest of the pass (so independent repairs share a pass), then the pass starts again."""
        self.st.dirty = set()
        chs = self._chains()
        deg = self.st.degree()
        self._normalise(chs, deg)
        if self.st.dirty:
            raise _Repair
        legs_at = self._legs(chs, deg)
        for node in sorted(legs_at):
            if len(legs_at[node]) > MAX_LEGS and not self.st.touched([node]):
                keys = legs_at[node]
                L = [self._leg(chs, k) for k in keys]
                prefer = [g.first for g in sorted(neighbour_gaps(L))]
                self._drop_leg(node, keys, chs, prefer, f"node {node}: dropped a leg ({len(keys)} legs, at most 7)")
        if self.st.dirty:
            raise _Repair
        self._acute_legs(chs, legs_at)
        if self.st.dirty:
            raise _Repair
        self._fix_exits(chs, legs_at)
        plans: dict[int, tuple[list[tuple[int, bool]], list[Leg], linkplan.LinkPlan, list[float]]] = {}
        r_at: dict[tuple[int, bool], float] = {}
        for node in sorted(legs_at):
            keys = sorted(legs_at[node])
            L = [self._leg(chs, k) for k in keys]
            plan = self._plan(L)
            r = self._incident(node, L, plan)
            plans[node] = (keys, L, plan, r)
            for k, x in zip(keys, r):
                r_at[k] = x
        # roads
        counts: dict[tuple[int, bool], tuple[int, int]] = {}
        for node, (keys, L, plan, _) in plans.items():
            for idx, k in enumerate(keys):
                counts[k] = (plan.n_in_end[idx], plan.n_out_end[idx])
        geoms = []
        need_of: dict[int, float] = {}
        for c, ch in enumerate(chs):
            if self.st.touched(ch.nodes):
                geoms.append(None)
                continue
            cfg = self._chain_cfg(ch)
            r0, r1 = r_at.get((c, True), 0.0), r_at.get((c, False), 0.0)
            fs, bs = (
                (counts[(c, True)][1], counts[(c, True)][0]) if (c, True) in counts else (cfg.forward, cfg.backward)
            )
            fe, be = (
                (counts[(c, False)][0], counts[(c, False)][1]) if (c, False) in counts else (cfg.forward, cfg.backward)
            )
            mid = (cfg.forward, cfg.backward)
            need = MIN_ROAD + taper_length(self.p, (fs, bs), mid) + taper_length(self.p, (fe, be), mid)
            need_of[c] = need
            status, g = self._road_geometry(ch, r0, r1, need, cfg, ((fs, bs), (fe, be)))
            if status == "vertex":
                self.st.smooth(ch, g, f"bend at node {ch.nodes[g]} too sharp for its lanes")
            elif status == "short":
                if len(ch.nodes) > 2:
                    P = [self.st.nodes[n] for n in ch.nodes]
                    turns = [
                        abs(
                            wrap(
                                math.atan2(P[i + 1][1] - P[i][1], P[i + 1][0] - P[i][0])
                                - math.atan2(P[i][1] - P[i - 1][1], P[i][0] - P[i - 1][0])
                            )
                        )
                        for i in range(1, len(P) - 1)
                    ]
                    self.st.smooth(
                        ch, 1 + int(np.argmax(turns)), f"bend on a road too short between nodes {ch.start} and {ch.end}"
                    )
                elif not self._merge_instead(ch, deg) and self.st.connected_without(ch.edges[0]):
                    self.st.remove_edge(
                        ch.edges[0],
                        f"removed road between nodes {ch.start} and {ch.end}: too short for its intersections",
                    )
                else:
                    self.st.contract(
                        ch.edges[0],
                        f"merged nodes {ch.start} and {ch.end} into one intersection: the "
                        f"road between them was too short",
                    )
            geoms.append((g, cfg, fs, bs, fe, be) if status == "ok" else None)
        if self.st.dirty:
            raise _Repair
        # junctions: a junction whose turns do not fit grows at once (its legs' roads are rebuilt, and a junction
        # at the other end of a rebuilt road is fitted again), until it fits or a repair is needed
        junction_of: dict[int, int] = {node: n for n, node in enumerate(sorted(plans))}
        done: dict[int, tuple] = {}
        queue = deque(sorted(plans))
        queued = set(queue)
        while queue:
            node = queue.popleft()
            queued.discard(node)
            if self.st.touched([node]):
                continue
            keys, L, plan, _ = plans[node]
            contact, median = self._contacts(keys, geoms)
            fits, grow = self._fit(node, plan, contact, median)
            if not grow:
                used = {r.leg_in for r in fits} | {r.leg_out for r in fits}
                lost = [i for i in range(len(keys)) if i not in used]
                if lost:  # a leg no lane enters or leaves the junction by: it cannot be linked, so it goes
                    self._drop_leg(node, keys, chs, lost, f"node {node}: dropped a leg without any lane link")
                    continue
                done[node] = (keys, fits)
                continue
            done.pop(node, None)
            self.st.growth[node] = self.st.growth.get(node, 0) + 1
            if self.st.growth[node] > MAX_GROWTH:
                failed = [r.leg_in for r in fits if r.fit is None]
                self.st.growth[node] = 0
                self.st.scale[node] = 1.0
                self._drop_leg(
                    node,
                    keys,
                    chs,
                    sorted(set(failed)),
                    f"node {node}: dropped a leg whose turns stay under the radius bound",
                )
                continue
            self.st.scale[node] = self.st.scale.get(node, 1.0) * GROWTH
            self.st.repairs.append(f"node {node}: moved incident points outward (turn radius)")
            for k, x in zip(keys, self._incident(node, L, plans[node][2])):
                r_at[k] = x
            rebuilt = []
            for c in sorted({k[0] for k in keys}):
                _, cfg, fs, bs, fe, be = geoms[c]
                status, g = self._road_geometry(
                    chs[c], r_at.get((c, True), 0.0), r_at.get((c, False), 0.0), need_of[c], cfg, ((fs, bs), (fe, be))
                )
                if status != "ok":
                    self.st.dirty.update(chs[c].nodes)  # the next pass repairs this road
                    break
                geoms[c] = (g, cfg, fs, bs, fe, be)
                rebuilt.append(c)
            else:
                for c in rebuilt:
                    for other in (chs[c].start, chs[c].end):
                        if other != node and other in plans and other not in queued:
                            done.pop(other, None)
                            queue.append(other)
                            queued.add(other)
                queue.appendleft(node)
                queued.add(node)
        if self.st.dirty:
            raise _Repair
        jplans = []
        for node in sorted(plans):
            keys, fits = done[node]
            conns = []
            for i, k, j, m, lid_in, lid_out, p0, h0, fit in fits:
                ci, si = keys[i]
                cj, sj = keys[j]
                conns.append(
                    ConnectionPlan(
                        ci,
                        "start" if si else "end",
                        lid_in,
                        cj,
                        "start" if sj else "end",
                        lid_out,
                        connection_geometry(p0[0], p0[1], h0, fit),
                        fit.min_radius,
                    )
                )
            conns.extend(self._u_turns(node, keys, plans[node][2], geoms, fits))
            jplans.append(JunctionPlan(node, self.st.nodes[node], len(keys), tuple(conns)))
        self._overlap_repair(chs, geoms, plans, jplans)
        if self.st.dirty:
            raise _Repair
        roads = []
        for c, ch in enumerate(chs):
            g, cfg, fs, bs, fe, be = geoms[c]
            roads.append(
                RoadPlan(
                    c,
                    ch.start,
                    ch.end,
                    junction_of.get(ch.start) if deg[ch.start] >= 3 else None,
                    junction_of.get(ch.end) if deg[ch.end] >= 3 else None,
                    g,
                    g[-1].s + g[-1].length,
                    cfg,
                    fs,
                    bs,
                    fe,
                    be,
                )
            )
        return Layout(tuple(roads), tuple(jplans), tuple(self.st.repairs))

    def run(self) -> Layout:
        limit = 20 * (len(self.st.edges) + len(self.st.nodes)) + 100
        for _ in range(limit):
            try:
                return self.run_once()
            except _Repair:
                continue
        # every repair shrinks the network or spends a bounded budget, so this is a guard, not an outcome
        raise GenerationError(f"stage 3 did not settle after {limit} passes; please report the seed and parameters")


def build(laned: LanedNetwork, params: Params, rng: np.random.Generator) -> Layout:
    """Stage 3 for a whole network."""
    return Builder(laned, params, rng).run()
