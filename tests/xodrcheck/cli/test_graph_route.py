"""``xodrcheck graph`` and ``xodrcheck route`` on the README's T junction: formats, exit codes, one-line errors."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from xodrcheck.cli import main

REPO = Path(__file__).resolve().parents[3]
T_JUNCTION = str(REPO / "examples" / "t-junction.xodr")


def _run(capsys, *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_graph_json_names_each_edges_lanes(capsys):
    code, out, err = _run(capsys, "graph", T_JUNCTION)
    assert (code, err) == (0, "")
    data = json.loads(out)
    assert data["summary"] == {
        "nodes": 12,
        "links": 12,
        "lane_changes": 0,
        "strong_components": 12,
        "entries": 3,
        "exits": 3,
    }
    edge = next(e for e in data["edges"] if e["from"]["road"] == "1" and e["to"]["road"] == "102")
    assert edge["from"] == {"road": "1", "section_s": 0.0, "lane": -1, "type": "driving", "travel": "forward"}
    assert edge["to"] == {"road": "102", "section_s": 0.0, "lane": -1, "type": "driving", "travel": "forward"}
    assert edge["kind"] == "link" and edge["length"] == pytest.approx(100.0)
    west_out = next(n for n in data["nodes"] if (n["road"], n["lane"]) == ("1", 1))
    assert west_out["stop"]["kind"] == "open" and west_out["travel"] == "backward"


def test_graph_dot_and_geojson(capsys, tmp_path):
    code, out, _ = _run(capsys, "graph", T_JUNCTION, "--format", "dot")
    assert code == 0 and out.startswith("digraph lanes {") and out.count(" -> ") == 12
    assert '"1/0/-1" -> "102/0/-1";' in out and '"1/0/1<"' in out
    target = tmp_path / "g.geojson"
    assert _run(capsys, "graph", T_JUNCTION, "--format", "geojson", "-o", str(target))[0] == 0
    features = json.loads(target.read_text(encoding="utf-8"))["features"]
    lanes = [f for f in features if f["properties"]["element"] == "lane"]
    edges = [f for f in features if f["properties"]["element"] == "edge"]
    assert (len(lanes), len(edges)) == (12, 12)
    west = next(f for f in lanes if (f["properties"]["road"], f["properties"]["lane"]) == ("1", 1))
    assert west["geometry"]["coordinates"][0][:2] == [-10.0, 1.75]  # driven west: from the junction outwards


def test_route_text_json_geojson(capsys):
    code, out, err = _run(capsys, "route", T_JUNCTION, "--from", "1:-1", "--to", "3:1")
    assert (code, err) == (0, "")
    assert out.splitlines()[0] == "route from 1:-1 to 3:1: 212.957 m, 3 lane(s)"
    code, out, _ = _run(capsys, "route", T_JUNCTION, "--from", "1:-1:50", "--to", "2:-1:50", "--format", "json")
    data = json.loads(out)
    assert code == 0 and data["found"] and data["length"] == pytest.approx(120.0)
    assert [s["road"] for s in data["steps"]] == ["1", "101", "2"] and data["polyline"][0][:2] == [-60.0, -1.75]
    code, out, _ = _run(capsys, "route", T_JUNCTION, "--from", "1:-1", "--to", "3:1", "--format", "geojson")
    (feature,) = json.loads(out)["features"]
    assert feature["properties"]["length"] == pytest.approx(200 + 8.25 * math.pi / 2, abs=0.01)


def test_no_route_is_exit_1_with_the_partial_route_and_why(capsys):
    code, out, err = _run(capsys, "route", T_JUNCTION, "--from", "1:-1", "--to", "1:1")
    assert code == 1
    assert out.startswith("no route from 1:-1 to 1:1: ") and "road 1 lane -1" in out
    assert err.count("\n") == 1 and err.startswith("xodrcheck: no route from 1:-1 to 1:1: ")


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (["--from", "9:-1", "--to", "1:1"], "there is no road 9"),
        (["--from", "1:-4", "--to", "1:1"], "road 1 has no lane -4"),
        (["--from", "1:-1:500", "--to", "1:1"], "s=500 is not on road 1"),
    ],
)
def test_places_that_name_no_lane_are_one_line_and_exit_2(capsys, argv, words):
    code, out, err = _run(capsys, "route", T_JUNCTION, *argv)
    assert (code, out) == (2, "") and err.count("\n") == 1 and words in err


def test_a_malformed_place_is_a_usage_error(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["route", T_JUNCTION, "--from", "1:x", "--to", "1:1"])
    assert stop.value.code == 2
    assert "'1:x' is not ROAD:LANE or ROAD:LANE:S" in capsys.readouterr().err
