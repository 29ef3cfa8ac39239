"""The lane graph against CARLA's own map API, on CARLA's towns (corpus copies).

* Between roads, the driving-lane successor pairs of :func:`xodrcheck.graph.lane_graph` are exactly those CARLA walks
  to with ``Waypoint.next`` from the end of each driving lane (each lane section, in its direction of travel).
* A long route's length agrees with a CARLA waypoint walk along the same lanes within 1 %.

CARLA runs in ``.venv-carla`` (created by ``.ci/run``), in a separate process; without it these tests fail.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tests.interop.carla_graph import carla_walk
from xodrcheck.graph import lane_graph
from xodrcheck.graph.lengths import node_lengths
from xodrcheck.graph.paths import shortest_from
from xodrcheck.graph.routes import Place, route
from xodrcheck.model import Document
from xodrcheck.reader import read

pytestmark = [pytest.mark.slow, pytest.mark.corpus]

TOWNS = [f"Town0{k}" for k in range(1, 8)]
#: How far past a lane's end CARLA is asked to step (m): less than the shortest lane section of the towns (4.5e-6 m
#: in Town03), far more than the rounding of CARLA's s.
PAST = 1e-7


def _town(corpus_dir: Path, name: str) -> Path:
    path = corpus_dir / "carla-towns" / "OpenDrive" / f"{name}.xodr"
    assert path.is_file(), f"corpus file missing: {path}"
    return path


def _section_holding(document: Document, road: str, s: float) -> int:
    starts = [section.s for section in document.road_by_id[road].lane_sections]
    return max(int(np.searchsorted(starts, s, side="right")) - 1, 0)


@pytest.mark.parametrize("town", TOWNS)
def test_successors_between_roads_are_carlas(corpus_dir, town):
    path = _town(corpus_dir, town)
    document = read(path).document
    graph = lane_graph(document, lane_changes=False)
    ours = set()
    for a, b, kind in zip(graph.source.tolist(), graph.target.tolist(), graph.kind.tolist()):
        na, nb = graph.nodes[a], graph.nodes[b]
        if kind == 0 and na.road != nb.road and na.type == nb.type == "driving":
            ours.add(((na.road, na.index, na.lane), (nb.road, nb.index, nb.lane)))
    ends, keys = [], []
    for node in graph.nodes:
        if node.type != "driving":
            continue
        road = document.road_by_id[node.road]
        s0, s1 = road.lane_sections[node.index].s, road.section_end(node.index)
        inset = min(1e-3, (s1 - s0) / 4)
        s, end = (s1 - inset, s1) if node.travel > 0 else (s0 + inset, s0)
        ends.append([node.road, node.lane, s, end, PAST])
        keys.append((node.road, node.index, node.lane))
    answers = carla_walk(path, {"ends": ends})["ends"]
    assert None not in answers, "CARLA has no waypoint on some driving lane"
    theirs = {
        (key, (road, _section_holding(document, road, s), lane))
        for key, answer in zip(keys, answers)
        for road, _, lane, s, lane_type in answer
        if road != key[0] and lane_type == "Driving"
    }
    assert len(ours) > 100
    assert sorted(ours - theirs) == [] and sorted(theirs - ours) == []


def _long_route(document: Document):
    """The route from the first driving lane of the first road to the lane farthest from it, from 1 cm after its
    start to 1 cm before its end (CARLA has no waypoint at a road's very end)."""
    graph = lane_graph(document, lane_changes=False)
    start = next(i for i, n in enumerate(graph.nodes) if n.type == "driving")
    dist, _ = shortest_from(graph, node_lengths(document, graph)[graph.source] + 1e-9, start)
    far = int(np.argmax(np.where(np.isfinite(dist), dist, -1)))
    whole = route(
        document, graph, Place(graph.nodes[start].road, graph.nodes[start].lane), _place(graph, far, document)
    )
    first, last = whole.steps[0], whole.steps[-1]
    origin = Place(first.node.road, first.node.lane, first.s_from + 0.01 * first.node.travel)
    destination = Place(last.node.road, last.node.lane, last.s_to - 0.01 * last.node.travel)
    return route(document, graph, origin, destination)


def _place(graph, node: int, document: Document) -> Place:
    n = graph.nodes[node]
    road = document.road_by_id[n.road]
    s0, s1 = road.lane_sections[n.index].s, road.section_end(n.index)
    return Place(n.road, n.lane, (s0 + s1) / 2)


@pytest.mark.parametrize("town", ["Town04", "Town07"])
def test_a_long_routes_length_is_carlas_walk(corpus_dir, town):
    path = _town(corpus_dir, town)
    document = read(path).document
    found = _long_route(document)
    assert found.found and found.length > 500
    steps = []
    for step in found.steps:
        here = [step.node.road, step.node.lane]
        if not steps or steps[-1] != here:
            steps.append(here)
    walk = {"steps": steps, "start": found.steps[0].s_from, "end": found.steps[-1].s_to, "step": 0.5}
    answer = carla_walk(path, {"walk": walk})["walk"]
    assert answer["error"] == ""
    passed = iter(steps)  # the lanes CARLA stepped on, in the route's order (a lane under a step long may be passed)
    assert all(lane in passed for lane in answer["passed"]) and answer["passed"][-1] == steps[-1]
    assert abs(found.length - answer["length"]) < 0.01 * answer["length"], (found.length, answer["length"])
