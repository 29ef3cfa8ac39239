"""Generated maps are strongly connected at lane level through their open edges (issue 30): every lane is reached
from where traffic enters the map and leads to where it leaves. The fuzz campaign's maps property asserts it on every
map it draws (:func:`junctionart.fuzz.properties.generated_map_is_connected`); here it runs on a few seeds of each
profile. That every entry reaches every exit is not promised: a junction need not offer every turn (on
``examples/overpass.json``, seed 1, no connection turns left from road 6 into road 14, so three of the 25 entry-exit
pairs have no route); the snapshots of the golden maps keep the pairs that route (``xodrcheck diff`` says when one
vanishes)."""

from __future__ import annotations

from pathlib import Path

import pytest

import junctionart as ja
from junctionart.controllines import load
from junctionart.fuzz.properties import generated_map_is_connected
from junctionart.params import Params
from xodrcheck.graph import lane_graph
from xodrcheck.graph.reach import entries, exits, reached
from xodrcheck.reader import read

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

CASES = {
    "paper": Params.create(),
    "scenario": Params.create("scenario"),
    "random-lanes": Params.create(randomize_lanes=True),
    "random-lanes-lht": Params.create(randomize_lanes=True, traffic_rule="LHT"),
}


@pytest.mark.parametrize("seed", [0, 3])
@pytest.mark.parametrize("case", sorted(CASES))
def test_generated_maps_are_connected(case, seed):
    params = CASES[case]
    data = ja.to_bytes(ja.generate(params, seed), params.version)
    generated_map_is_connected(data, seed=seed)
    assert len(entries(lane_graph(read(data).document))) >= 1


def test_a_map_from_control_lines_with_an_overpass_is_connected():
    params = Params.create("scenario")
    lines = load(EXAMPLES / "overpass.json")
    data = ja.to_bytes(ja.generate(params, 1, lines), params.version)
    generated_map_is_connected(data)
    graph = lane_graph(read(data).document)
    routed = sum(int(reached(graph, [i])[exits(graph)].sum()) for i in entries(graph).tolist())
    assert (len(entries(graph)), len(exits(graph)), routed) == (5, 5, 22)


def test_a_lane_opening_behind_a_solid_line_breaks_the_property(monkeypatch):
    """The generator marks the line beside a lane that opens or closes broken; drawn solid (as it was before issue
    30), the turn lanes opening before junctions are reached by no route, and the property says so."""
    from junctionart import cleanup

    original = cleanup._marks

    def solid_beside_tapers(kind, color, s0, s1, rp, taper=False):
        return original(kind, color, s0, s1, rp, False)

    monkeypatch.setattr(cleanup, "_marks", solid_beside_tapers)
    params = CASES["paper"]
    data = ja.to_bytes(ja.generate(params, 1), params.version)
    with pytest.raises(AssertionError, match="L041 lane-unreachable"):
        generated_map_is_connected(data, seed=1)
