"""``xodrcheck.structures``: every junction of a map is in exactly one structure, of a registered kind, measured from
the file."""

from __future__ import annotations

import math

import pytest

import junctionart
from junctionart.params import Params
from xodrcheck import structures
from xodrcheck.analysis.metrics import junction_legs, smallest_leg_angle
from xodrcheck.reader import read


@pytest.fixture(scope="module")
def paper_map(tmp_path_factory):
    path = tmp_path_factory.mktemp("structures") / "m.xodr"
    junctionart.write(junctionart.generate(Params(width=500.0, height=500.0, randomize_lanes=True), 4), path)
    return read(path).document


def test_every_junction_is_in_exactly_one_structure_of_a_known_kind(paper_map):
    found = structures.map_structures(paper_map)
    ids = [j for s in found for j in s.junctions]
    assert sorted(ids) == sorted(j.id for j in paper_map.junctions) and len(ids) == len(set(ids)) > 3
    known = {k.name for k in structures.KINDS}
    assert all(s.kind in known for s in found)
    for s in found:  # each structure carries exactly its kind's measures, in its order
        assert tuple(n for n, _ in s.values) == structures.kind(s.kind).names


def test_a_paper_map_holds_ordinary_junctions_measured_by_their_legs(paper_map):
    found = structures.map_structures(paper_map)
    assert {s.kind for s in found} == {"junction"}
    by_id = paper_map.junction_by_id
    for s in found:
        legs = junction_legs(paper_map, by_id[s.junctions[0]])
        assert s.measures["legs"] == len(legs)
        angle = smallest_leg_angle(legs)
        assert (
            s.measures["min_angle"] == pytest.approx(angle)
            if angle is not None
            else math.isnan(s.measures["min_angle"])
        )


def test_kinds_are_listed_with_unique_measure_names():
    names = structures.measure_names()
    assert len(names) == len(set(names)) and "legs" in names
    assert structures.KINDS[-1].name == "junction"  # what no other recogniser claims
    with pytest.raises(KeyError, match=r"unknown kind 'tunnel'; kinds: .*junction"):
        structures.kind("tunnel")


_ROAD = """<road name="{name}" length="{length}" id="{id}" junction="-1" rule="RHT">
    <link><{link} elementType="junction" elementId="100"/></link>
    <planView><geometry s="0.0" x="{x}" y="{y}" hdg="0.0" length="{length}">{shape}</geometry></planView>
    <lanes><laneSection s="0.0"><center><lane id="0" type="none" level="false"/></center><right>{lanes}</right>
    </laneSection></lanes>
  </road>"""
_LANE = '<lane id="{id}" type="{type}" level="false"><width sOffset="0.0" a="3.5" b="0.0" c="0.0" d="0.0"/></lane>'


def _direct_junction(branch_type: str) -> bytes:
    """A hand-written file of another tool's kind: a one-way, two-lane road whose lanes continue on a straight road
    and on one curving off to the left by 0.8 rad, joined by a direct junction (12.6)."""
    two = _LANE.format(id=-1, type="driving") + _LANE.format(id=-2, type="driving")
    roads = [
        _ROAD.format(name="a", length=100.0, id=1, link="successor", x=0.0, y=0.0, shape="<line/>", lanes=two),
        _ROAD.format(
            name="l",
            length=80.0,
            id=2,
            link="predecessor",
            x=100.0,
            y=0.0,
            shape='<arc curvature="0.01"/>',
            lanes=_LANE.format(id=-1, type="driving"),
        ),
        _ROAD.format(
            name="r",
            length=100.0,
            id=3,
            link="predecessor",
            x=100.0,
            y=-3.5,
            shape="<line/>",
            lanes=_LANE.format(id=-1, type=branch_type),
        ),
    ]
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<OpenDRIVE>
  <header revMajor="1" revMinor="8" name="t" version="1.00" vendor="other"/>
  {"".join(roads)}
  <junction name="split" id="100" type="direct">
    <connection id="0" incomingRoad="1" linkedRoad="2" contactPoint="start"><laneLink from="-1" to="-1"/></connection>
    <connection id="1" incomingRoad="1" linkedRoad="3" contactPoint="start"><laneLink from="-2" to="-1"/></connection>
  </junction>
</OpenDRIVE>""".encode()


def test_a_direct_junction_from_another_tool_is_a_fork_with_its_split_angle():
    doc = read(_direct_junction("driving")).document
    (found,) = structures.map_structures(doc)
    assert found.kind == "fork"
    m = found.measures
    assert m["split_angle"] == pytest.approx(math.degrees(0.8))  # the arc's heading at its end (80 m < 100 m)
    assert (m["lanes_in"], m["lanes_left"], m["lanes_right"], m["merge"], m["direct"]) == (2, 1, 1, 0, 1)


def test_the_same_junction_with_an_off_ramp_lane_is_a_ramp_without_a_taper():
    doc = read(_direct_junction("offRamp")).document
    (found,) = structures.map_structures(doc)
    assert found.kind == "ramp"
    m = found.measures
    assert m["ramp_angle"] == pytest.approx(math.degrees(0.8)) and m["ramp_lanes"] == 1 and m["exit"] == 1
    # the stem's lane joined to the ramp is full width all along the stem: no taper, as long as the stem
    assert m["taper_length"] == 0.0 and m["side_lane_length"] == pytest.approx(100.0)


# --------------------------------------------------------------------------------------------------- roundabouts
def _corpus_map(name: str):
    from tests.conftest import corpus_root

    return read(corpus_root() / name).document


def test_carla_town03s_roundabout_is_recognised_with_its_split_arms():
    """Town03's ring: one-way two-lane ring roads round a 20 m island through six junctions; its four arms split
    into one-way entry and exit roads that meet beyond the ring (each counted once)."""
    doc = _corpus_map("carla-towns/OpenDrive/Town03.xodr")
    (ring,) = [s for s in structures.map_structures(doc) if s.kind == "roundabout"]
    m = ring.measures
    assert len(ring.junctions) == 6 and m["arms"] == 4 and m["ring_lanes"] == 2
    assert 24.0 < m["radius"] < 26.5 and 80.0 < m["arm_angle"] < 90.0


def test_a_stadium_shaped_turnaround_loop_and_town_blocks_are_not_roundabouts():
    """Town06's U-turn loops between two one-way carriageways form a closed one-way loop through four junctions, but
    it is a stadium (reference lines 37 % off a circle), not a ring; no other corpus map but ika's roundabout has
    one."""
    for name in ("carla-towns/OpenDrive/Town06.xodr", "carla-towns/OpenDrive/Town01.xodr"):
        assert not [s for s in structures.map_structures(_corpus_map(name)) if s.kind == "roundabout"], name
    (ring,) = [
        s
        for s in structures.map_structures(_corpus_map("ika-roadgeneration/test/gt/junction_m2a.xodr"))
        if s.kind == "roundabout"
    ]
    assert ring.measures["arms"] == 4 and ring.measures["ring_lanes"] == 4


def test_a_generated_roundabout_is_recognised_as_generated():
    from junctionart.intersection import IntersectionSpec, LegSpec, build

    legs = (LegSpec(0, 1, 1), LegSpec(90, 2, 1, True), LegSpec(150, 1, 1), LegSpec(260, 1, 2))
    built = build(IntersectionSpec(legs, roundabout_radius=24.0, roundabout_lanes=2))
    doc = read(junctionart.to_bytes(built.document)).document
    (found,) = structures.map_structures(doc)
    assert found.kind == "roundabout" and len(found.junctions) == len(built.roundabout.junctions) >= 3
    assert found.measures == pytest.approx(
        {"arms": 4, "radius": built.roundabout.radius, "ring_lanes": 2, "arm_angle": 60.0}, abs=0.05
    )
