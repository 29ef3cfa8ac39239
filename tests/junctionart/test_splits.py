"""Forks, merges and ramps (issue 28): ``junctionart intersection --preset`` and kind descriptions build maps with
no xodrcheck error, which xodrcheck recognises as what was asked and measures as described."""

from __future__ import annotations

import math

import numpy as np
import pytest

from junctionart import cli, to_bytes
from junctionart.errors import ParamsError
from junctionart.splits.build import build
from junctionart.splits.spec import PRESETS, Branch, ForkSpec, RampSpec, from_dict, to_dict
from xodrcheck.check import check
from xodrcheck.geometry.lanes import geometry_of
from xodrcheck.model import JunctionType
from xodrcheck.reader import read
from xodrcheck.structures import map_structures


def _document(spec):
    return read(to_bytes(build(spec), spec.version)).document


def _errors(spec) -> list[str]:
    return [
        f"{f.code} {f.message}"
        for f in check(to_bytes(build(spec), spec.version)).findings
        if f.severity.name == "ERROR"
    ]


CASES = [
    *[(name, junction) for name in PRESETS for junction in ("direct", "default")],
]


@pytest.mark.parametrize("name, junction", CASES)
def test_every_preset_checks_clean_and_is_recognised_as_its_kind(name, junction):
    spec = from_dict({**PRESETS[name], "junction": junction})
    assert _errors(spec) == []
    (found,) = map_structures(_document(spec))
    assert found.kind == PRESETS[name]["kind"]
    assert found.measures["direct" if found.kind == "fork" else "exit"] in (0.0, 1.0)
    if found.kind == "fork":
        assert found.measures["direct"] == (junction == "direct")
        assert found.measures["merge"] == bool(PRESETS[name].get("merge", False))
    else:
        assert found.measures["exit"] == (not PRESETS[name].get("entry", False))


@pytest.mark.parametrize("rule", ["RHT", "LHT"])
@pytest.mark.parametrize("merge", [False, True])
@pytest.mark.parametrize("junction", ["direct", "default"])
def test_forks_measure_as_described(rule, merge, junction):
    spec = ForkSpec(
        left=Branch(2, 12.0, 150.0),
        right=Branch(1, -3.0, 300.0),
        oncoming=1,
        merge=merge,
        junction=junction,
        traffic_rule=from_dict({"kind": "fork", "traffic_rule": rule}).traffic_rule,
    )
    assert _errors(spec) == []
    (found,) = map_structures(_document(spec))
    m = found.measures
    assert found.kind == "fork" and m["split_angle"] == pytest.approx(15.0, abs=1e-6)
    assert (m["lanes_left"], m["lanes_right"], m["lanes_in"], m["merge"]) == (2, 1, 3, merge)


@pytest.mark.parametrize("entry", [False, True])
@pytest.mark.parametrize("junction", ["direct", "default"])
def test_ramps_measure_as_described(entry, junction):
    spec = RampSpec(
        entry=entry,
        lanes=3,
        oncoming=0,
        ramp_lanes=2,
        taper_length=80.0,
        lane_length=50.0,
        angle=45.0,
        radius=60.0,
        junction=junction,
    )
    assert _errors(spec) == []
    document = _document(spec)
    (found,) = map_structures(document)
    m = found.measures
    assert found.kind == "ramp" and m["ramp_angle"] == pytest.approx(45.0, abs=1e-6)
    assert m["ramp_lanes"] == 2 and m["exit"] == (not entry)
    # the cubic taper is within 1 mm of full width for about 0.8 m at each end of an 80 m taper
    assert 78.0 < m["taper_length"] <= 80.0 and 128.0 < m["side_lane_length"] <= 130.0
    types = {lane.type.value for road in document.roads for sec in road.lane_sections for lane in sec.lanes}
    assert types >= ({"entry", "onRamp"} if entry else {"exit", "offRamp"})


def test_the_yosemite_preset_leads_from_the_approach_into_both_branches(tmp_path):
    """The paper's case from one command: a one-way, two-lane road; lane links, read back by xodrcheck, lead its
    left lane onto a branch curving off to the left and its right lane onto one going straight on."""
    out = tmp_path / "yosemite.xodr"
    assert cli.main(["intersection", "--preset", "yosemite", "-o", str(out), "-q"]) == 0
    assert [f for f in check(out).findings if f.severity.name == "ERROR"] == []
    doc = read(out).document
    (junction,) = doc.junctions
    assert junction.type is JunctionType.DIRECT
    roads = doc.road_by_id
    approach = next(r for r in doc.roads if r.successor is not None and r.successor.element_id == junction.id)
    last = approach.lane_sections[-1]
    assert [lane.id for lane in last.lanes if lane.id != 0] == [-1, -2] and not last.left  # one-way, two lanes
    reached = {}
    for lane in (-1, -2):  # follow each approach lane through the junction's lane links
        (step,) = [
            (c.linked_road, ll.to_lane)
            for c in junction.connections
            if c.incoming_road == approach.id
            for ll in c.lane_links
            if ll.from_lane == lane
        ]
        road = roads[step[0]]
        assert road.predecessor.element_id == junction.id and road.lane_sections[0].lane(step[1]) is not None
        reached[lane] = road
    left, right = reached[-1], reached[-2]
    assert left.id != right.id
    geometry = geometry_of(doc)
    turn = {}
    for name, road in (("left", left), ("right", right)):
        hdg = geometry[road.id].reference(np.array([0.0, road.length])).hdg
        turn[name] = math.degrees(hdg[1] - hdg[0])
    assert turn["left"] == pytest.approx(40.0) and turn["right"] == pytest.approx(0.0)


def test_descriptions_round_trip_and_bad_ones_are_refused():
    for raw in PRESETS.values():
        spec = from_dict(raw)
        assert from_dict(to_dict(spec)) == spec
    with pytest.raises(ParamsError, match="must part by at least"):
        ForkSpec(left=Branch(1, 1.0), right=Branch(1, 0.0))
    with pytest.raises(ParamsError, match=r"right.turn=5.0: must be in \[-90, 0\]"):
        ForkSpec(left=Branch(1, 30.0), right=Branch(1, 5.0))
    with pytest.raises(ParamsError, match="radius=8: the lanes on the inside"):
        ForkSpec(left=Branch(1, 30.0), right=Branch(3, -30.0, 8.0))
    with pytest.raises(ParamsError, match="taper_length=12"):
        RampSpec(ramp_lanes=2, taper_length=12.0)
    with pytest.raises(ParamsError, match="unknown key 'lanez'"):
        from_dict({"kind": "ramp", "lanez": 2})


def test_the_cli_refuses_options_that_do_not_apply(tmp_path, capsys):
    out = tmp_path / "x.xodr"
    assert cli.main(["intersection", "--preset", "exit", "--u-turns", "-o", str(out)]) == 2
    assert cli.main(["intersection", "--preset", "nowhere", "-o", str(out)]) == 2
    assert cli.main(["intersection", "--leg", "0:1:1", "--junction", "direct", "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert "--u-turns does not apply to a ramp" in err and "choose from yosemite" in err and not out.exists()
    assert (
        cli.main(
            ["intersection", "--preset", "merge", "--junction", "default", "--version", "1.7", "-o", str(out), "-q"]
        )
        == 0
    )
    root = read(out).document
    assert root.version == (1, 7) and root.junctions[0].type is JunctionType.DEFAULT
