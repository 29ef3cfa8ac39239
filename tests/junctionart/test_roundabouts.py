"""Roundabouts (issue 28): ``roundabout_probability``, control-line requests and ``junctionart intersection
--roundabout`` build one-way rings with a junction per arm; every map checks clean and xodrcheck recognises each
roundabout from the written file alone, with the arms, radius and lanes the generator made."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

import junctionart as ja
from junctionart import cli, controllines
from junctionart.errors import InputError, ParamsError
from junctionart.intersection import IntersectionSpec, LegSpec, build, from_dict, to_dict
from junctionart.intersections.roundabout import splitter_width
from junctionart.intersections.roundabout_choice import SIZES, choose, drawn
from junctionart.params import Params, TrafficRule
from xodrcheck.check import check
from xodrcheck.config import load_config
from xodrcheck.model import Document, LaneType
from xodrcheck.reader import read
from xodrcheck.structures import map_structures

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _errors(data: bytes, strict: bool = False) -> list[str]:
    """Error- and warning-level findings of xodrcheck in its default (or strict) tolerance profile."""
    report = check(data, load_config(Path(__file__).parent, profile="strict" if strict else "default"))
    return [f"{f.code} road {f.road}: {f.message}" for f in report.findings if f.severity.name in ("ERROR", "WARNING")]


def _rings(document: Document) -> list[dict[str, float]]:
    return [s.measures for s in map_structures(document) if s.kind == "roundabout"]


def _legs(headings, lanes=(1, 1), median=False) -> tuple[LegSpec, ...]:
    return tuple(LegSpec(h, lanes[0], lanes[1], median) for h in headings)


# ------------------------------------------------------------------------------------------------------ parameters
def test_the_probability_is_validated_and_the_profiles_set_it():
    assert Params().roundabout_probability == 0.0 and not Params().scenario
    assert Params.create("scenario").roundabout_probability == 0.25
    assert Params(roundabout_probability=0.5).scenario
    for bad in (-0.1, 1.5, math.nan, "0.5"):
        with pytest.raises(ParamsError, match=r"roundabout_probability="):
            Params(roundabout_probability=bad)


def test_the_command_line_refuses_a_bad_probability_in_one_line(tmp_path, capsys):
    out = tmp_path / "m.xodr"
    assert cli.main(["generate", "--roundabout-probability", "2", "-o", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "roundabout_probability=2" in err[0] and not out.exists()


def test_nothing_is_drawn_at_probability_zero_and_sizes_come_from_the_classes():
    assert choose((10.0, 20.0), 4, Params(), None) is None
    assert choose((10.0, 20.0), 7, Params(roundabout_probability=1.0), None) is None  # 7 legs: no roundabout
    spec = choose((10.0, 20.0), 4, Params(roundabout_probability=1.0), None)
    assert spec is not None and spec == choose((10.0, 20.0), 4, Params(roundabout_probability=1.0), None)
    lo, hi = min(s[2] for s in SIZES), max(s[3] for s in SIZES)
    radii = [drawn(np.random.default_rng(k)) for k in range(300)]
    assert all(lo <= r.radius <= hi and r.lanes in (1, 2) for r in radii)
    assert all(r.lanes == 1 for r in radii if r.radius < 20.0) and any(r.lanes == 2 for r in radii)
    assert min(r.radius for r in radii) < 10.0 and max(r.radius for r in radii) > 30.0  # mini to large


# ------------------------------------------------------------------------------------------------- control lines
def test_control_line_files_ask_for_roundabouts_in_json_and_geojson():
    lines = [{"id": "a", "points": [[0, 0], [400, 0]]}, {"id": "b", "points": [[0, 200], [400, 200]]}]
    got = controllines.parse(
        {"lines": lines, "roundabouts": [{"at": [100, 0], "radius": 18, "lanes": 2}, {"at": [5, 6]}]}
    )
    assert [(r.at, r.radius, r.lanes) for r in got.roundabouts] == [((100.0, 0.0), 18.0, 2), ((5.0, 6.0), None, None)]
    features = [
        {
            "type": "Feature",
            "properties": {"id": ln["id"]},
            "geometry": {"type": "LineString", "coordinates": ln["points"]},
        }
        for ln in lines
    ]
    features.append(
        {
            "type": "Feature",
            "properties": {"roundabout": True, "radius": 12},
            "geometry": {"type": "Point", "coordinates": [1, 2]},
        }
    )
    got = controllines.parse({"type": "FeatureCollection", "features": features})
    assert [(r.at, r.radius, r.lanes) for r in got.roundabouts] == [((1.0, 2.0), 12.0, None)]


@pytest.mark.parametrize(
    "entry, message",
    [
        ({"at": [0, 0], "radius": 200}, "radius must be a number of metres in"),
        ({"at": [0, 0], "lanes": 3}, "lanes must be 1 or 2"),
        ({"at": [0, math.inf]}, "needs a point"),
        ({"at": [0, 0], "size": 3}, "unknown key 'size'"),
        ([0, 0], "a roundabout is an object"),
    ],
)
def test_bad_roundabout_requests_are_refused_naming_the_fault(entry, message):
    lines = [{"points": [[0, 0], [400, 0]]}, {"points": [[0, 200], [400, 200]]}]
    with pytest.raises(InputError, match=message):
        controllines.parse({"lines": lines, "roundabouts": [entry]}, "f.json")


# -------------------------------------------------------------------------------------------- one roundabout
ONE = [
    # headings, lanes (in, out), median, radius, ring lanes, traffic rule
    ((0, 120, 240), (1, 1), False, 9.5, 1, "RHT"),  # mini
    ((0, 90, 180, 270), (1, 1), False, 16.0, 1, "RHT"),  # compact
    ((0, 90, 180, 270), (2, 2), True, 30.0, 2, "RHT"),  # large, two lanes, medians
    ((0, 72, 144, 216, 288), (2, 1), False, 22.0, 1, "LHT"),
    ((10, 70, 130, 190, 250, 310), (1, 2), False, 32.0, 2, "LHT"),
    ((0, 35, 120, 240), (1, 1), False, 25.0, 1, "RHT"),  # two arms 35 deg apart
]


@pytest.fixture(scope="module")
def singles():
    out = []
    for headings, lanes, median, radius, ring, rule in ONE:
        spec = IntersectionSpec(
            _legs(headings, lanes, median),
            traffic_rule=TrafficRule(rule),
            roundabout_radius=radius,
            roundabout_lanes=ring,
        )
        built = build(spec)
        out.append((spec, built, ja.to_bytes(built.document, spec.version)))
    return out


def test_single_roundabouts_check_clean_in_the_default_and_strict_profiles(singles):
    for spec, built, data in singles:
        assert built.roundabout is not None, built.repairs
        assert _errors(data) == [] and _errors(data, strict=True) == [], spec


def test_single_roundabouts_are_recognised_with_their_arms_radius_and_lanes(singles):
    for spec, built, data in singles:
        (found,) = _rings(read(data).document)
        assert found["arms"] == len(spec.legs) == built.legs
        assert found["radius"] == pytest.approx(built.roundabout.radius, abs=0.01)
        assert built.roundabout.radius >= spec.roundabout_radius  # grown only where the arms need room
        assert found["ring_lanes"] == spec.roundabout_lanes
        headings = sorted(g.heading for g in spec.legs)
        tightest = min((b - a) % 360 for a, b in zip(headings, headings[1:] + headings[:1]))
        assert found["arm_angle"] == pytest.approx(tightest, abs=1.0)  # arms measured at their incident points


def test_traffic_circulates_counter_clockwise_on_the_right_and_clockwise_on_the_left(singles):
    for spec, built, data in singles:
        doc = read(data).document
        ring = [doc.road_by_id[str(k + 1)] for k in built.roundabout.ring_roads]
        for road in ring:  # one-way, driving along s, curving to the side traffic circulates round
            (arc,) = road.plan_view
            driving = [lane.id for sec in road.lane_sections for lane in sec.lanes if lane.type is LaneType.DRIVING]
            left = spec.traffic_rule.value == "LHT"
            assert all((lid > 0) == left for lid in driving) and len(set(driving)) == spec.roundabout_lanes
            assert (arc.curvature > 0) != left


def test_two_way_arms_end_in_a_splitter_island(singles):
    for spec, built, data in singles:
        doc = read(data).document
        width = splitter_width(built.roundabout.radius)
        for road_index, contact, _ in built.roundabout.arms:
            road = doc.road_by_id[str(road_index + 1)]
            section = road.lane_sections[-1 if contact == "end" else 0]
            (median,) = [lane for lane in section.lanes if lane.type is LaneType.MEDIAN]
            at = road.length - section.s if contact == "end" else 0.0
            a, b, c, d = (median.widths[0].a, median.widths[0].b, median.widths[0].c, median.widths[0].d)
            wanted = max(width, spec.median_width if spec.legs[0].median else 0.0)
            assert a + at * (b + at * (c + at * d)) == pytest.approx(wanted, abs=1e-3)  # written to the mm


def test_the_description_round_trips_and_a_junction_keeps_its_json():
    spec = IntersectionSpec(_legs((0, 90, 200)), roundabout_radius=14.0, roundabout_lanes=2)
    assert from_dict(json.loads(json.dumps(to_dict(spec)))) == spec
    assert "roundabout" not in to_dict(IntersectionSpec(_legs((0, 90, 200))))
    with pytest.raises(ParamsError, match="a roundabout has 3 to 6 arms"):
        IntersectionSpec(_legs((0, 50, 100, 150, 200, 250, 300)), roundabout_radius=20.0)
    with pytest.raises(ParamsError, match="roundabout lanes=3"):
        IntersectionSpec(_legs((0, 90, 200)), roundabout_radius=20.0, roundabout_lanes=3)


def test_the_intersection_command_builds_a_roundabout(tmp_path, capsys):
    out = tmp_path / "r.xodr"
    legs = ["--leg", "0:1:1", "--leg", "90:2:1", "--leg", "200:1:1:median"]
    assert cli.main(["intersection", *legs, "--roundabout", "15:1", "-o", str(out)]) == 0
    assert "one roundabout, 3 arms" in capsys.readouterr().out
    (found,) = _rings(read(out).document)
    assert found["arms"] == 3
    assert cli.main(["intersection", *legs, "--roundabout", "15:x", "-o", str(out)]) == 2
    assert "--roundabout '15:x': expected RADIUS[:LANES]" in capsys.readouterr().err


# ------------------------------------------------------------------------------------------- maps with roundabouts
MAPS = [
    ({"roundabout_probability": 1.0}, 901),
    ({"roundabout_probability": 1.0, "randomize_lanes": True, "width": 900, "height": 900}, 902),
    ({"roundabout_probability": 1.0, "traffic_rule": "LHT", "curved_roads": True, "randomize_lanes": True}, 903),
    ({"profile": "scenario", "roundabout_probability": 1.0, "randomize_lanes": True}, 904),
    ({"profile": "scenario", "terrain": "hilly", "roadside": "rural", "roundabout_probability": 0.6}, 905),
]


@pytest.fixture(scope="module")
def generated():
    out = []
    for kwargs, seed in MAPS:
        params = Params.create(**kwargs)
        result = ja.generate_layout(params, seed)
        out.append((params, result, ja.to_bytes(result.document, params.version)))
    return out


def test_generated_maps_with_roundabouts_check_clean(generated):
    assert sum(len(r.layout.roundabouts) for _, r, _ in generated) >= 10
    for params, _, data in generated:
        assert _errors(data) == [], params


def test_every_generated_roundabout_is_recognised_from_the_file_as_generated(generated):
    for _, result, data in generated:
        made = sorted((len(r.arms), r.lanes, r.radius) for r in result.layout.roundabouts)
        found = sorted((int(m["arms"]), int(m["ring_lanes"]), m["radius"]) for m in _rings(read(data).document))
        assert [m[:2] for m in found] == [m[:2] for m in made]
        assert [m[2] for m in found] == pytest.approx([m[2] for m in made], abs=0.02)


def test_roundabouts_are_reproducible_and_cost_the_paper_maps_nothing():
    p = Params.create(roundabout_probability=1.0)
    assert ja.to_bytes(ja.generate(p, 3)) == ja.to_bytes(ja.generate(p, 3))
    assert ja.to_bytes(ja.generate(Params(), 3)) == ja.to_bytes(ja.generate(Params(roundabout_probability=0.0), 3))


def test_every_entry_yields_in_the_scenario_profile(generated):
    """Each road meeting a roundabout's junction that is not a ring road (an arm: its approach, the piece next to the
    ring when a fork or ramp split the arm's road) carries the yield sign 205, the roundabout sign 215 and the yield
    line 341 at that end for its entry lanes; no ring road carries a signal."""
    for params, result, _ in generated:
        if params.junction_control.value == "none":
            continue
        doc = result.document
        for ring in result.layout.roundabouts:
            ring_ids = {str(k + 1) for k in ring.ring_roads}
            junction_ids = {doc.junctions[j].id for j in ring.junctions}
            assert all(doc.road(rid).signals == () for rid in ring_ids)
            arms = [
                (road, end)
                for road in doc.roads
                if road.junction == "-1" and road.id not in ring_ids
                for link, end in ((road.predecessor, "start"), (road.successor, "end"))
                if link is not None and link.element_type == "junction" and link.element_id in junction_ids
            ]
            assert len(arms) == len(ring.arms)
            for road, end in arms:
                near = [s for s in road.signals if (s.s < 5.0 if end == "start" else s.s > road.length - 5.0)]
                assert sorted(s.type for s in near) == ["205", "215", "341"], road.id
                assert {s.orientation for s in near} == {"-" if end == "start" else "+"}


def test_a_control_line_file_puts_roundabouts_where_it_asks(tmp_path):
    lines = controllines.load(EXAMPLES / "roundabouts.json")
    assert len(lines.roundabouts) == 2
    result = ja.generate_layout(Params(), 1, lines)
    centres = [ring.centre for ring in result.layout.roundabouts]
    assert len(centres) == 2, result.layout.repairs
    for asked in lines.roundabouts:
        assert min(math.dist(asked.at, c) for c in centres) < 60.0
    sizes = {(asked.radius, asked.lanes) for asked in lines.roundabouts}
    assert sizes == {(ring.radius, ring.lanes) for ring in result.layout.roundabouts}
    assert _errors(ja.to_bytes(result.document)) == []
