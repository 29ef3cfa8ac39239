"""U-turn connection lanes: only where the radius bound is met (measured with xodrcheck's geometry), at the configured
probability, drawn last so the rest of the map does not change."""

import numpy as np
import pytest

import junctionart as ja
from junctionart.params import Params, TrafficRule
from xodrcheck.check import check
from xodrcheck.geometry.lanes import geometry_of
from xodrcheck.reader import read

WIDE = {
    "randomize_lanes": True,
    "median_width": 4.0,
    "median_probability": 1.0,
    "width": 800.0,
    "height": 800.0,
    "lane_distribution_side": (0.0, 0.2, 0.3, 0.5),
}


def _same_end(road) -> bool:
    """A U-turn: the connecting road leaves and enters the same end of one road."""
    a, b = road.predecessor, road.successor
    return a.element_id == b.element_id and a.contact_point == b.contact_point


def _u_turn_radii(path) -> list[tuple[float, float, float]]:
    """Per U-turn connecting road (one that leads back to the road end it comes from): the smallest radius of its
    reference line, lane centre and outer border, and its signed curvature at the middle."""
    doc = read(path).document
    geos = geometry_of(doc)
    out = []
    for road in doc.roads:
        if road.junction is None or not _same_end(road):
            continue
        geo = geos[road.id]
        (lane,) = (*road.lane_sections[0].left, *road.lane_sections[0].right)
        s = np.linspace(0.0, road.length, 200)
        radii = [1.0 / float(np.abs(geo.reference(s).curvature).max())]
        for where in ("centre", "outer"):
            radii.append(1.0 / float(np.abs(geo.lane_points(0, lane.id, s, where=where).curvature).max()))
        out.append((min(radii), radii[1], float(geo.reference(np.array([road.length / 2])).curvature[0])))
    return out


@pytest.mark.parametrize("rule", [TrafficRule.RHT, TrafficRule.LHT])
def test_u_turns_where_wide_enough_meet_the_bound_and_turn_towards_the_centre(rule, tmp_path):
    params = Params(u_turn_probability=1.0, traffic_rule=rule, **WIDE)
    found = 0
    for seed in range(3):
        path = ja.write(ja.generate(params, seed), tmp_path / f"{seed}.xodr")
        radii = _u_turn_radii(path)
        found += len(radii)
        for smallest, centre, curvature in radii:
            assert smallest >= params.min_turn_radius - 1e-9
            assert centre >= params.min_turn_radius + params.lane_width / 2 - 1e-9
            assert (curvature > 0) == (rule is TrafficRule.RHT)  # RHT turns back to the left
        assert check(path).findings == ()
    assert found >= 5


def test_default_widths_leave_no_room_for_a_u_turn(tmp_path):
    """3.5 m lanes and a 2 m median: the inner borders of the innermost lane in and the outermost lane out are at most
    9 m apart, a 4.5 m radius, under the 5 m bound: no U-turn, however likely."""
    params = Params(
        randomize_lanes=True,
        u_turn_probability=1.0,
        median_probability=1.0,
        lane_distribution_side=(0.0, 0.0, 0.0, 1.0),
        width=600.0,
        height=600.0,
    )
    path = ja.write(ja.generate(params, 1), tmp_path / "m.xodr")
    assert _u_turn_radii(path) == []


def test_probability_zero_gives_none_and_u_turns_change_nothing_else():
    with_all = ja.generate_layout(Params(u_turn_probability=1.0, **WIDE), 4).layout
    without = ja.generate_layout(Params(u_turn_probability=0.0, **WIDE), 4).layout
    assert with_all.roads == without.roads
    turns = [
        c for j in with_all.junctions for c in j.connections if (c.in_road, c.in_contact) == (c.out_road, c.out_contact)
    ]
    assert turns
    assert not [
        c for j in without.junctions for c in j.connections if (c.in_road, c.in_contact) == (c.out_road, c.out_contact)
    ]
    rest = [
        [c for c in j.connections if (c.in_road, c.in_contact) != (c.out_road, c.out_contact)]
        for j in with_all.junctions
    ]
    assert rest == [list(j.connections) for j in without.junctions]


def test_probability_is_honoured_roughly():
    counts = []
    for p in (0.0, 0.5, 1.0):
        lay = ja.generate_layout(Params(u_turn_probability=p, **WIDE), 5).layout
        counts.append(
            sum((c.in_road, c.in_contact) == (c.out_road, c.out_contact) for j in lay.junctions for c in j.connections)
        )
    assert counts[0] == 0 < counts[1] < counts[2]


def test_u_turn_probability_is_validated():
    with pytest.raises(ja.ParamsError, match=r"u_turn_probability=1.5: must be in \[0, 1\]"):
        Params(u_turn_probability=1.5)
