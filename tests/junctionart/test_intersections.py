import dataclasses
import math
from collections import defaultdict

import numpy as np
import pytest
import shapely
from shapely import LineString

import junctionart as ja
from junctionart.curves import end_pose, sample
from junctionart.lanegeom import lane_id
from junctionart.params import Params, SplitStrategy, TrafficRule


def _check_links(layout, params):
    rule = params.traffic_rule
    roads = layout.roads
    for jp in layout.junctions:
        assert 3 <= jp.legs <= 7
        by_in = defaultdict(list)
        for c in jp.connections:
            by_in[(c.in_road, c.in_contact)].append(c)
        for (r, contact), conns in by_in.items():
            rp = roads[r]
            n_in = rp.bwd_start if contact == "start" else rp.fwd_end
            median = rp.lanes.median
            expect = {lane_id(contact == "end", k, median, rule) for k in range(1, n_in + 1)}
            assert {c.in_lane for c in conns} == expect, "every incoming lane reaches an outgoing lane"
            targets = [(c.out_road, c.out_contact, c.out_lane) for c in conns]
            assert len(targets) == len(set(targets)), "two lanes of one road merge into one lane"
            back = [c for c in conns if (c.out_road, c.out_contact) == (r, contact)]
            assert len(back) <= 1 and all(c.in_lane == lane_id(contact == "end", 1, median, rule) for c in back), (
                "U-turns only from the innermost lane"
            )
        for c in jp.connections:
            assert c.min_radius >= params.min_turn_radius
        # every leg is linked: some lane enters or leaves the junction by it
        linked = {(c.in_road, c.in_contact) for c in jp.connections} | {
            (c.out_road, c.out_contact) for c in jp.connections
        }
        for rp in roads:
            for contact, j in (("start", rp.start_junction), ("end", rp.end_junction)):
                if j is not None and layout.junctions[j] is jp:
                    assert (rp.index, contact) in linked
        # every outgoing lane is fed
        fed = {(c.out_road, c.out_contact, c.out_lane) for c in jp.connections}
        for rp in roads:
            for contact, j, n_out in (("start", rp.start_junction, rp.fwd_start), ("end", rp.end_junction, rp.bwd_end)):
                if j is not None and layout.junctions[j] is jp:
                    for m in range(1, n_out + 1):
                        assert (rp.index, contact, lane_id(contact == "start", m, rp.lanes.median, rule)) in fed


def _parted(xy, other, tol=0.05):
    far = np.flatnonzero(shapely.distance(shapely.points(xy), other) > tol)
    return LineString(xy[far[0] :]) if len(far) and len(xy) - far[0] >= 2 else None


def _no_crossing(layout):
    """Centre lines of the connection lanes leaving one road meet only where they start."""
    bad = 0
    for jp in layout.junctions:
        by_in = defaultdict(list)
        for c in jp.connections:
            by_in[(c.in_road, c.in_contact)].append(c)
        for conns in by_in.values():
            pts = [sample(c.geometry, 200) for c in conns]
            lines = [LineString(p) for p in pts]
            for a in range(len(conns)):
                for b in range(a + 1, len(conns)):
                    if conns[a].in_lane == conns[b].in_lane:
                        # same start point: they part there (5 cm apart, as xodrcheck's J101) and never meet again
                        tail_a, tail_b = _parted(pts[a], lines[b]), _parted(pts[b], lines[a])
                        bad += tail_a is not None and tail_b is not None and tail_a.intersects(tail_b)
                    elif lines[a].intersects(lines[b]):
                        bad += 1
    return bad


@pytest.mark.parametrize("idx", range(5))
def test_stage3_invariants_random_lanes(random_500, idx):
    result = random_500[idx]
    params = Params(randomize_lanes=True, curved_roads=True)
    _check_links(result.layout, params)
    assert _no_crossing(result.layout) == 0


@pytest.mark.parametrize("rule", [TrafficRule.RHT, TrafficRule.LHT])
@pytest.mark.parametrize("strategy", list(SplitStrategy))
def test_rules_and_strategies(rule, strategy):
    params = Params(randomize_lanes=True, traffic_rule=rule, split_strategy=strategy, width=800, height=800)
    for seed in range(2):
        layout = ja.generate_layout(params, seed).layout
        _check_links(layout, params)
        assert _no_crossing(layout) == 0
        lanes_used = {c.in_lane for j in layout.junctions for c in j.connections}
        # right-hand traffic drives on the right: forward lanes are negative, and vice versa
        for j in layout.junctions:
            for c in j.connections:
                if c.in_contact == "end":
                    assert (c.in_lane < 0) == (rule is TrafficRule.RHT)
        assert lanes_used


def test_split_first_and_split_last_differ():
    """With more outgoing lanes than incoming ones, split-first feeds the extras from the centre lane, split-last from
    the kerb lane."""

    def extras(strategy):
        params = Params(randomize_lanes=True, split_strategy=strategy, width=800, height=800, turn_lane_probability=0.0)
        layout = ja.generate_layout(params, 2).layout
        counts = defaultdict(lambda: defaultdict(int))
        for j in layout.junctions:
            for c in j.connections:
                counts[(j.node, c.in_road, c.in_contact)][abs(c.in_lane)] += 1
        centre = kerb = 0
        for per_lane in counts.values():
            if len(per_lane) >= 2:
                ids = sorted(per_lane)
                centre += per_lane[ids[0]] > 1
                kerb += per_lane[ids[-1]] > 1
        return centre, kerb

    c_first, k_first = extras(SplitStrategy.SPLIT_FIRST)
    c_last, k_last = extras(SplitStrategy.SPLIT_LAST)
    assert c_first > 0 and k_last > 0
    assert c_first > c_last and k_last > k_first


def test_bends_are_roads_not_junctions(random_500):
    for result in random_500:
        deg = result.network.degree()
        for jp in result.layout.junctions:
            assert deg[jp.node] >= 3 or jp.legs >= 3
        arcs = [g for r in result.layout.roads for g in r.geometry if type(g).__name__ == "Arc"]
        for a in arcs:
            assert 1 / abs(a.curvature) >= 5.0


def test_roads_start_at_their_incident_points(random_500):
    """Every road end at a junction lies outside the junction's centre and joins its chain seamlessly."""
    for result in random_500:
        lay = result.layout
        for rp in lay.roads:
            for g, h in zip(rp.geometry, rp.geometry[1:]):
                e = end_pose(g)
                assert math.hypot(e.x - h.x, e.y - h.y) < 1e-9 and abs(e.hdg - h.hdg) < 1e-12
            if rp.start_junction is not None:
                cx, cy = lay.junctions[rp.start_junction].position
                assert math.hypot(rp.geometry[0].x - cx, rp.geometry[0].y - cy) > 3.0


def test_repairs_never_discard_a_map():
    """Dense networks (tiny gaps, wide roads) need repairs; every seed still yields a map."""
    params = Params(
        randomize_lanes=True,
        min_distance=30.0,
        max_distance=40.0,
        snap_distance=20.0,
        lane_distribution_side=(0.0, 0.0, 0.0, 1.0),
        lane_distribution_control_lines=(0.0, 0.0, 0.0, 1.0),
        width=600,
        height=600,
        curved_roads=True,
    )
    repairs = 0
    for seed in range(4):
        result = ja.generate_layout(params, seed)
        assert result.layout.roads and result.layout.junctions
        _check_links(result.layout, params)
        repairs += len(result.layout.repairs)
    assert repairs > 0


def test_link_plan_feeds_a_leg_reachable_only_by_a_sharp_turn():
    """An outgoing-only leg at a sharp angle to the only incoming leg is still fed (no unlinked leg)."""
    from junctionart.intersections.links import Leg, plan

    legs = [
        Leg((0, 0), 0.0, 1, 1, False),  # two-way leg to the east
        Leg((0, 1), math.radians(10.0), 0, 1, False),  # one-way out, 10 degrees from the first
        Leg((0, 2), math.pi, 0, 1, False),
    ]  # one-way out to the west
    p = plan(legs, Params(turn_lane_probability=0.0), np.random.default_rng(0), {})
    assert {j for _, _, j, _ in p.links} == {1, 2}
    assert p.n_out_end == (0, 1, 1)
    assert p.n_in_end == (1, 0, 0)


def test_link_plan_feeds_both_ends_of_a_loop_from_the_other_road():
    """A road looping back to its junction (legs 1 and 2, one road): each of its ends is fed from the other road
    (leg 0), even where that turn is sharper than SHARPEST_TURN, so traffic from elsewhere can enter both directions of
    the loop (fuzz regression loop-road-direction-without-a-way-in: leg 0's 156 deg turn into leg 1 was left out and
    leg 1 was fed only by the loop's own other end)."""
    from junctionart.intersections.links import Leg, plan

    legs = [
        Leg((0, 17), -0.0976, 1, 1, True, road=0),
        Leg((0, 23), 0.3194, 1, 1, True, road=1),  # 156 deg right turn from leg 0
        Leg((0, 21), 2.0652, 1, 1, True, road=1),  # 56 deg right turn from leg 0
    ]
    p = plan(legs, Params(turn_lane_probability=0.0), np.random.default_rng(0), {})
    assert {j for i, _, j, _ in p.links if i == 0} == {1, 2}
    assert {i for i, _, j, _ in p.links if j == 1} == {0, 2}
    one_road = [dataclasses.replace(g, road=-1) for g in legs]  # three roads: the sharp turn stays out
    q = plan(one_road, Params(turn_lane_probability=0.0), np.random.default_rng(0), {})
    assert {j for i, _, j, _ in q.links if i == 0} == {2}


def test_a_failing_link_into_a_loop_is_kept_while_it_is_the_loops_only_way_in():
    """After a growth step the fitter may leave out a failing link whose lanes keep other links; into a road looping
    back to the junction (legs 1 and 2), a link from another road stays while the loop's own other end is the only
    other feeder (fuzz regression loop-link-dropped-at-a-growing-junction)."""
    from junctionart.intersections.crossing import LinkFit
    from junctionart.intersections.fitting import _droppable

    def link(i, j):
        return LinkFit(i, 1, j, 1, 0, 0, (0.0, 0.0), 0.0, None)

    bad, good = [link(0, 1)], [link(2, 1), link(0, 2), link(1, 0)]
    assert not _droppable(bad, good, [0, 1, 1])  # leg 1 would be fed only by its own road's other end
    assert _droppable(bad, good, [0, 1, 2])  # three roads: leg 2 is a feeder like any other
    assert _droppable(bad, [*good, link(3, 1)], [0, 1, 1, 3])  # road 3 still feeds the loop


def test_repairs_that_strand_a_junction_make_a_one_way_road_two_way():
    """Node 0 has a loop (0-1-2-0) and a one-way road out to node 3 (a junction of two dead ends): nothing enters
    node 0 until that road gets a lane back (fuzz regression repairs-leaving-a-loop-junction-without-a-way-in)."""
    from junctionart.intersections.prune import open_ways
    from junctionart.intersections.state import NetworkState
    from junctionart.intersections.survey import Survey
    from junctionart.lanes import LaneConfig

    two, one = LaneConfig(1, 1), LaneConfig(1, 0)
    nodes = [(0.0, 0.0), (-100.0, 100.0), (-100.0, -100.0), (200.0, 0.0), (300.0, 100.0), (300.0, -100.0)]
    edges = {0: (0, 1, two), 1: (1, 2, two), 2: (2, 0, two), 3: (0, 3, one), 4: (3, 4, two), 5: (3, 5, two)}
    st = NetworkState(nodes, edges)
    view = Survey.take(st)
    open_ways(view)
    assert st.edges[3][2] == LaneConfig(1, 1)
    assert st.edges[0][2] == two and st.edges[4][2] == two
    assert len(st.repairs) == 1 and "made two-way" in st.repairs[0]
    open_ways(Survey.take(st))  # connected now: nothing changes
    assert len(st.repairs) == 1
