"""Forks and ramps in generated maps (issue 28): where a control-line file asks for them and where the probabilities
draw them, they come out as asked, checked clean, and leave the paper profile's maps alone."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import junctionart as ja
from junctionart import cli, controllines
from junctionart.errors import InputError, ParamsError
from junctionart.params import Params
from xodrcheck.check import check
from xodrcheck.reader import read
from xodrcheck.structures import map_structures

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "forks_ramps.json"


def _errors(data: bytes) -> list[str]:
    return [f"{f.code} road {f.road}: {f.message}" for f in check(data).findings if f.severity.name != "INFO"]


def _special(data: bytes) -> list:
    return [s for s in map_structures(read(data).document) if s.kind != "junction"]


@pytest.mark.parametrize("direct", [True, False])
def test_the_example_file_gets_every_fork_and_ramp_it_asks_for(direct):
    lines = controllines.load(EXAMPLE)
    params = Params.create(randomize_lanes=True, direct_junctions=direct)
    result = ja.generate_layout(params, 0, lines)
    assert result.notes == ()
    data = ja.to_bytes(result.document)
    assert _errors(data) == []  # no error and no warning
    found = _special(data)
    forks = sorted(round(s.measures["split_angle"], 3) for s in found if s.kind == "fork")
    assert forks == [12.0, 12.0, 35.0, 35.0]  # each fork's split and merge, at the angles asked
    ramps = [s.measures for s in found if s.kind == "ramp"]
    assert sorted(m["exit"] for m in ramps) == [0, 0, 1, 1] and {round(m["ramp_angle"], 3) for m in ramps} >= {25.0}
    assert {s.measures["direct"] for s in found if s.kind == "fork"} == {float(direct)}
    assert all(m["taper_length"] > 25 and m["side_lane_length"] > 45 for m in ramps)


def test_a_request_that_does_not_fit_is_reported_and_the_map_stays_clean(tmp_path, capsys):
    raw = json.loads(EXAMPLE.read_text())
    raw["lines"][0]["forks"] = [{"at": 5}]  # on the bend where the generator joins the two roads
    path = tmp_path / "lines.json"
    path.write_text(json.dumps(raw))
    out = tmp_path / "m.xodr"
    assert cli.main(["generate", "--control-lines", str(path), "--randomize-lanes", "true", "-o", str(out), "-q"]) == 0
    err = capsys.readouterr().err
    assert "fork asked on line 'north' at 5 m:" in err
    assert _errors(out.read_bytes()) == []


@pytest.mark.parametrize(
    "entry, message",
    [
        ({"forks": {"at": 3}}, '"forks" must be a list'),
        ({"ramps": [{"at": -1}]}, "at=-1: must be a distance"),
        ({"ramps": [{"at": [1, "x"]}]}, "at=[1, 'x']: must be a distance along the line (m, >= 0) or a point [x, y]"),
        ({"ramps": [{"where": 4}]}, 'must be {"at"'),
        ({"forks": [{"at": 10, "angle": 120}]}, "angle=120: must be degrees in [2, 90]"),
        ({"forks": [{"at": 5000}]}, "asks for a fork at 5000 m; it is 1200 m long"),
    ],
)
def test_bad_requests_are_refused_with_one_line(entry, message):
    raw = json.loads(EXAMPLE.read_text())
    raw["lines"][0] = {k: v for k, v in raw["lines"][0].items() if k not in ("forks", "ramps")} | entry
    with pytest.raises(InputError) as err:
        controllines.parse(raw, "lines.json")
    assert message in str(err.value)


def test_geojson_features_ask_for_them_in_their_properties():
    raw = json.loads(EXAMPLE.read_text())
    raw["lines"][1]["ramps"] = [{"at": [800.0, -30.0], "angle": 25}]  # a point: its nearest point on the line
    features = [
        {
            "type": "Feature",
            "geometry": {"type": "LineString", "coordinates": ln["points"]},
            "properties": {k: v for k, v in ln.items() if k != "points"},
        }
        for ln in raw["lines"]
    ]
    lines = controllines.parse({"type": "FeatureCollection", "features": features}, "lines.geojson")
    assert [(r.kind, round(r.x), round(r.y), r.angle) for r in lines.requests] == [
        ("fork", 350, 300, 12.0),
        ("ramp", 850, 300, None),
        ("fork", 300, 0, 35.0),
        ("ramp", 800, 0, 25.0),
    ]


@pytest.mark.parametrize(
    "kwargs",
    [
        {"direct_junctions": True},
        {"direct_junctions": False, "traffic_rule": "LHT", "median_probability": 1.0},
        {"profile": "scenario", "terrain": "hilly"},
        {"profile": "scenario", "roadside": "rural", "curved_roads": True, "version": "1.7"},
    ],
)
def test_drawn_forks_and_ramps_check_clean(kwargs):
    params = Params.create(**{"width": 800, "height": 800, "randomize_lanes": True, **kwargs}).with_(
        fork_probability=0.6,
        ramp_probability=0.6,
        roundabout_probability=0.0,  # the counts are the network's as before
    )
    data = ja.to_bytes(ja.generate(params, 2), params.version)
    assert _errors(data) == []
    kinds = [s.kind for s in _special(data)]
    assert kinds.count("fork") >= 4 and kinds.count("ramp") >= 2


def test_the_draws_change_nothing_else_and_the_paper_profile_draws_none():
    base = Params(width=600, height=600, randomize_lanes=True)
    plain = ja.generate(base, 4)
    forked = ja.generate(base.with_(fork_probability=1.0), 4)
    assert len(forked.roads) > len(plain.roads)
    kept = {r.id for r in forked.roads} & {r.id for r in plain.roads}
    untouched = [r for r in plain.roads if r.id in kept and r in forked.roads]
    assert len(untouched) >= len(plain.roads) // 2  # roads without a structure (nor a renamed link) stay as they were
    assert Params().fork_probability == Params().ramp_probability == 0.0
    scenario = Params.create("scenario")
    assert 0 < scenario.fork_probability < 1 and 0 < scenario.ramp_probability < 1 and not scenario.direct_junctions


@pytest.mark.parametrize("name", ["fork_probability", "ramp_probability"])
def test_probabilities_are_validated(name, capsys):
    with pytest.raises(ParamsError, match=rf"{name}=1.5: must be in \[0, 1\]"):
        Params.create(**{name: 1.5})
    option = "--" + name.replace("_", "-")
    assert cli.main(["generate", option, "-0.1", "-o", "/nonexistent/x.xodr"]) == 2
    assert f"{name}=-0.1" in capsys.readouterr().err


def _z_and_grade(geometry, road, at_end: bool) -> tuple[float, float]:
    """Height and grade along s at one end of ``road`` (the grade by a 1 mm step inside the road)."""
    h = 1e-3
    s = np.array([road.length - h, road.length]) if at_end else np.array([0.0, h])
    z = geometry[road.id].elevation(s)
    return float(z[1] if at_end else z[0]), float((z[1] - z[0]) / h)


def test_on_hills_the_structures_follow_their_road_with_z_and_grade_continuous_at_every_link():
    """The branch's height is a cubic from the road's height and grade at the split to those at the merge, each piece
    keeps the road's profile, so at every link (a direct junction's joint, a connecting road's ends) height and grade
    run on (the generator's own junctions stay planar: tests/junctionart/test_terrain.py)."""
    from xodrcheck.geometry.lanes import geometry_of
    from xodrcheck.model import ContactPoint, ElementType, JunctionType

    for direct in (True, False):
        params = Params.create(
            "scenario", terrain="hilly", width=800, height=800, randomize_lanes=True, direct_junctions=direct
        ).with_(fork_probability=0.8, ramp_probability=0.8)
        data = ja.to_bytes(ja.generate(params, 3))
        assert _errors(data) == []
        doc = read(data).document
        geo = geometry_of(doc)
        assert len(_special(data)) >= 4
        links = 0
        for road in doc.roads:  # road-to-road links: connecting roads, every junction
            for link, at_end in ((road.predecessor, False), (road.successor, True)):
                if link is None or link.element_type is not ElementType.ROAD:
                    continue
                other = doc.road_by_id[link.element_id]
                z0, g0 = _z_and_grade(geo, road, at_end)
                z1, g1 = _z_and_grade(geo, other, link.contact_point is ContactPoint.END)
                assert abs(z0 - z1) < 1e-6 and abs(g0 - g1) < 1e-3, (road.id, other.id, z0, z1, g0, g1)
                links += 1
        for junction in doc.junctions:  # a direct junction's roads meet at one cross-section
            if junction.type is not JunctionType.DIRECT:
                continue
            ends = [
                _z_and_grade(geo, road, at_end)
                for road in doc.roads
                for link, at_end in ((road.predecessor, False), (road.successor, True))
                if link is not None and link.element_id == junction.id
            ]
            zs, grades = [z for z, _ in ends], [g for _, g in ends]
            assert len(ends) == 3 and np.ptp(zs) < 1e-6 and np.ptp(grades) < 1e-3, (junction.id, ends)
            links += 1
        hills = [float(np.ptp(geo[r.id].elevation(np.linspace(0, r.length, 20)))) for r in doc.roads]
        assert links >= 8 and max(hills) > 1.0  # on real slopes
