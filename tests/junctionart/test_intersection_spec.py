"""``junctionart intersection``: an explicit description becomes a valid one-junction map with the legs asked for."""

from __future__ import annotations

import json

import pytest

from junctionart.cli import main
from junctionart.intersection import IntersectionSpec, LegSpec, build, from_dict, to_dict
from xodrcheck.analysis.metrics import junction_legs, map_metrics, smallest_leg_angle
from xodrcheck.check import check
from xodrcheck.config import Config
from xodrcheck.findings import Severity
from xodrcheck.reader import read

#: Generated maps are judged as junctionart guarantees them: every rule at its own severity.
GENERATOR = Config(profile="generator")


def _measure(path):
    document = read(path).document
    assert document is not None and len(document.junctions) == 1
    metrics = map_metrics(document)[0]
    return metrics, smallest_leg_angle(junction_legs(document, document.junctions[0]))


def _errors(path) -> list[str]:
    return [f"{f.code} {f.message}" for f in check(path, GENERATOR).findings if f.severity >= Severity.ERROR]


@pytest.mark.parametrize(
    "legs, smallest",
    [
        (["0:2:2", "90:1:1:median", "180:2:2", "270:1:1"], 90.0),
        (["10:1:1", "100:2:1", "235:1:2"], 90.0),
        (["0:1:1", "40:1:1", "95:1:1", "150:1:1", "205:1:1", "260:1:1", "310:1:1"], 40.0),
    ],
)
def test_written_map_is_valid_reproducible_and_has_the_legs_asked_for(tmp_path, capsys, legs, smallest):
    a, b = tmp_path / "a.xodr", tmp_path / "b.xodr"
    argv = ["intersection", *(x for leg in legs for x in ("--leg", leg)), "--turn-lanes", "--seed", "3"]
    assert main([*argv, "-o", str(a)]) == 0
    assert f"{len(legs)} legs" in capsys.readouterr().out
    assert main([*argv, "-o", str(b), "-q"]) == 0
    assert a.read_bytes() == b.read_bytes()
    assert _errors(a) == []
    metrics, angle = _measure(a)
    assert metrics.legs == len(legs)
    # straight approach roads: the measured directions are the headings given
    assert angle == pytest.approx(smallest, abs=0.5)


def test_bends_medians_u_turns_and_left_hand_traffic(tmp_path):
    spec = {
        "legs": [
            {"heading": 0, "in": 2, "out": 2, "median": True, "bend": 25},
            {"heading": 120, "in": 3, "out": 1, "bend": -30},
            {"heading": 250, "in": 1, "out": 3, "median": True},
        ],
        "u_turns": True,
        "traffic_rule": "LHT",
        "median_width": 6.0,
    }
    out = tmp_path / "m.xodr"
    assert main(["intersection", "--spec", json.dumps(spec), "-o", str(out), "-q"]) == 0
    assert _errors(out) == []
    metrics, _ = _measure(out)
    assert metrics.legs == 3 and metrics.n_u_turn_lanes > 0


def test_description_round_trips_and_fixes_the_document():
    spec = IntersectionSpec((LegSpec(0, 2, 1), LegSpec(130, 1, 1, median=True), LegSpec(260, 1, 2, bend=10)))
    assert from_dict(json.loads(json.dumps(to_dict(spec)))) == spec
    assert build(spec, 5).document == build(spec, 5).document
    assert build(spec).legs == 3 and build(spec).repairs == ()


@pytest.mark.parametrize(
    "args, message",
    [
        (["--leg", "0:1:1", "--leg", "90:1:1"], "2 given, an intersection has 3 to 7"),
        (["--leg", "0:1:1", "--leg", "90:1:x", "--leg", "180:1:1"], "'90:1:x'"),
        (["--leg", "0:1:1", "--leg", "90:4:1", "--leg", "180:1:1"], "leg 1 in=4"),
        (["--leg", "0:1:1", "--leg", "0.5:1:1", "--leg", "180:1:1"], "1 deg between them"),
        (["--leg", "0:1:1", "--leg", "90:1:1:bend=80", "--leg", "180:1:1"], "leg 1 bend=80"),
        (
            ["--spec", '{"legs": [{"heading": 0}, {"heading": 90}, {"heading": 180, "lanes": 2}]}'],
            "unknown key 'lanes'",
        ),
        (["--spec", "{not json"], "not JSON"),
        (["--spec", '{"legs": [{"heading": 0}, {"heading": 90}, {"heading": 180}]}', "--traffic-rule", "X"], "RHT"),
        ([], "no legs"),
    ],
)
def test_bad_descriptions_give_one_line_and_exit_2(tmp_path, capsys, args, message):
    out = tmp_path / "m.xodr"
    assert main(["intersection", *args, "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and message in err and "Traceback" not in err
    assert not out.exists()
