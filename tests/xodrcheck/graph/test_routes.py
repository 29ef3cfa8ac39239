"""Routes: places, lengths on the lane centres, loops, and why there is none."""

from __future__ import annotations

import math

import pytest

from tests.xodrcheck.graph.maps import LOOP, T_JUNCTION, document
from xodrcheck.graph import lane_graph
from xodrcheck.graph.routes import Place, PlaceError, parse_place, route


@pytest.mark.parametrize(
    ("text", "place"),
    [
        ("1:-1", Place("1", -1)),
        ("12:2:30.5", Place("12", 2, 30.5)),
        ("a:b:-1", Place("a:b", -1)),  # road ids may hold colons
        ("road 7:1:0", Place("road 7", 1, 0.0)),
    ],
)
def test_places(text, place):
    assert parse_place(text) == place


@pytest.mark.parametrize("text", ["1", "1:x", ":-1", "1:-1:nan", "1:-1:inf", ""])
def test_bad_places(text):
    with pytest.raises(PlaceError):
        parse_place(text)


def test_a_right_turn_measures_the_lane_centre():
    """West road 1 (100 m) then connecting road 102 (a right turn of radius 10 m: lane -1's centre at 8.25 m) then the
    whole of south road 3 (100 m)."""
    doc = document(T_JUNCTION)
    found = route(doc, lane_graph(doc), Place("1", -1), Place("3", 1))
    assert found.found and found.why == ""
    assert [(s.node.road, s.node.lane, s.entered) for s in found.steps] == [
        ("1", -1, "start"),
        ("102", -1, "link"),
        ("3", 1, "link"),
    ]
    assert found.length == pytest.approx(200 + 8.25 * math.pi / 2, abs=0.01)
    assert (found.x[0], found.y[0]) == pytest.approx((-110.0, -1.75))
    assert (found.x[-1], found.y[-1]) == pytest.approx((-1.75, -110.0))  # lane 1 of road 3, west of its line


def test_places_with_s():
    doc = document(T_JUNCTION)
    found = route(doc, lane_graph(doc), Place("1", -1, 40.0), Place("2", -1, 25.0))
    assert found.length == pytest.approx(60 + 20 + 25)
    same = route(doc, lane_graph(doc), Place("1", -1, 10.0), Place("1", -1, 30.0))
    assert same.length == pytest.approx(20.0) and len(same.steps) == 1


def test_a_place_behind_the_start_is_reached_round_a_loop():
    """Road 2 of the loop fixture returns to its own start through connecting road 11."""
    doc = document(LOOP)
    graph = lane_graph(doc)
    found = route(doc, graph, Place("2", -1, 50.0), Place("2", -1, 10.0))
    assert found.found and [s.node.road for s in found.steps] == ["2", "11", "2"]
    loop = doc.road_by_id["2"].length
    assert found.length > loop - 40 and found.length < loop + 40


def test_no_route_says_where_it_stops_and_why():
    doc = document(T_JUNCTION)
    found = route(doc, lane_graph(doc), Place("1", -1), Place("1", 1))  # no U-turn
    assert not found.found
    assert "nearest the route gets is road 1 lane -1" in found.why and "3.5 m from the destination" in found.why
    assert [s.node.road for s in found.steps] == ["1"]


@pytest.mark.parametrize(
    ("place", "words"),
    [
        (Place("9", -1), "there is no road 9"),
        (Place("1", -3), "road 1 has no lane -3"),
        (Place("1", -1, 200.0), "s=200 is not on road 1"),
    ],
)
def test_places_that_name_no_lane(place, words):
    doc = document(T_JUNCTION)
    with pytest.raises(PlaceError, match=words):
        route(doc, lane_graph(doc), place, Place("2", -1))
