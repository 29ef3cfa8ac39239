"""``xodrcheck sample``: where the points are, the CSV and GeoJSON shapes, and atomic output."""

from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path

import numpy as np
import pytest

import xodrcheck.cli.sample as sample_cli
from tests.xodrcheck.cli import maps
from xodrcheck.analysis.sample import section_s_values
from xodrcheck.cli import main


def write(tmp_path: Path, text: str, name: str = "map.xodr") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def sample_csv(capsys, path: Path, *flags: str) -> list[dict]:
    assert main(["sample", str(path), *flags]) == 0
    out = capsys.readouterr().out
    rows = list(csv.DictReader(io.StringIO(out)))
    assert out.splitlines()[0] == "road,section_s,lane,type,kind,s,x,y,z,hdg"
    return rows


def column(rows: list[dict], name: str, **where) -> np.ndarray:
    chosen = [r for r in rows if all(r[k] == str(v) for k, v in where.items())]
    return np.array([float(r[name]) for r in chosen])


@pytest.mark.parametrize(
    ("start", "end", "step", "expected"),
    [
        (0, 100, 10, [0, 10, 20, 30, 40, 50, 60, 70, 80, 90, 100]),
        (0, 100, 30, [0, 30, 60, 90, 100]),
        (40, 100, 25, [40, 65, 90, 100]),
        (0, 0.3, 0.1, [0, 0.1, 0.2, 0.3]),  # 0.3 / 0.1 is 2.9999999999999996 in floating point
        (5, 7, 10, [5, 7]),
    ],
)
def test_section_s_values(start, end, step, expected):
    np.testing.assert_allclose(section_s_values(start, end, step), expected, atol=1e-12)


def test_straight_road_centres(tmp_path, capsys):
    rows = sample_csv(capsys, write(tmp_path, maps.STRAIGHT), "--step", "10")
    assert {r["kind"] for r in rows} == {"centre"}
    assert [r["lane"] for r in rows[:1]] == ["1"]  # leftmost lane first
    for lane, y in ((1, 1.75), (-1, -1.75)):
        s = column(rows, "s", lane=lane)
        np.testing.assert_allclose(s, np.arange(0, 101, 10))
        np.testing.assert_allclose(column(rows, "x", lane=lane), s, atol=1e-6)
        np.testing.assert_allclose(column(rows, "y", lane=lane), y, atol=1e-6)
        np.testing.assert_allclose(column(rows, "z", lane=lane), 0, atol=1e-6)
        np.testing.assert_allclose(column(rows, "hdg", lane=lane), 0, atol=1e-9)
    assert {r["road"] for r in rows} == {"1"} and {r["type"] for r in rows} == {"driving"}
    assert {r["section_s"] for r in rows} == {"0.000000"}


def test_borders_and_elevation(tmp_path, capsys):
    rows = sample_csv(capsys, write(tmp_path, maps.STRAIGHT_RISING), "--step", "30", "--borders")
    assert len(rows) == 2 * 3 * 5  # two lanes, three lines each, s = 0, 30, 60, 90, 100
    expected_t = {
        (1, "inner"): 0,
        (1, "centre"): 1.75,
        (1, "outer"): 3.5,
        (-1, "inner"): 0,
        (-1, "centre"): -1.75,
        (-1, "outer"): -3.5,
    }
    for (lane, kind), t in expected_t.items():
        s = column(rows, "s", lane=lane, kind=kind)
        np.testing.assert_allclose(s, [0, 30, 60, 90, 100])
        np.testing.assert_allclose(column(rows, "y", lane=lane, kind=kind), t, atol=1e-6)
        np.testing.assert_allclose(column(rows, "z", lane=lane, kind=kind), 1 + 0.02 * s, atol=1e-6)


def test_arc_centres(tmp_path, capsys):
    # Left arc of radius R around (0, R); a point at lateral offset t lies on the circle of radius R - t.
    rows = sample_csv(capsys, write(tmp_path, maps.ARC), "--step", "20")
    R = maps.ARC_RADIUS
    for lane, t in ((1, 1.75), (-1, -1.75)):
        s = column(rows, "s", lane=lane)
        assert s[-1] == pytest.approx(maps.ARC_LENGTH, abs=1e-6) and s[1] == pytest.approx(20)
        theta = s / R
        np.testing.assert_allclose(column(rows, "x", lane=lane), (R - t) * np.sin(theta), atol=2e-6)
        np.testing.assert_allclose(column(rows, "y", lane=lane), R - (R - t) * np.cos(theta), atol=2e-6)
        np.testing.assert_allclose(column(rows, "hdg", lane=lane), theta, atol=1e-8)


def test_lane_sections_each_start_and_end(tmp_path, capsys):
    rows = sample_csv(capsys, write(tmp_path, maps.TWO_SECTIONS), "--step", "25")
    np.testing.assert_allclose(column(rows, "s", section_s="0.000000", lane=-1), [0, 25, 40])
    np.testing.assert_allclose(column(rows, "s", section_s="40.000000", lane=-1), [40, 65, 90, 100])
    np.testing.assert_allclose(column(rows, "y", section_s="0.000000", lane=-2), -3.5 - 1.0, atol=1e-6)
    np.testing.assert_allclose(column(rows, "y", section_s="40.000000", lane=-1), -1.5, atol=1e-6)
    assert {r["type"] for r in rows if r["lane"] == "-2"} == {"sidewalk"}


def test_geojson(tmp_path, capsys):
    path = write(tmp_path, maps.TWO_SECTIONS)
    assert main(["sample", str(path), "--step", "25", "--borders", "--format", "geojson"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["type"] == "FeatureCollection"
    features = data["features"]
    # section 0: lanes -1 and -2, section 40: lane -1; three lines each.
    assert len(features) == 3 * 3
    props = [(f["properties"]["section_s"], f["properties"]["lane"], f["properties"]["kind"]) for f in features]
    assert props[:3] == [(0, -1, "centre"), (0, -1, "inner"), (0, -1, "outer")]
    for f in features:
        assert f["type"] == "Feature" and f["geometry"]["type"] == "LineString"
        assert set(f["properties"]) == {"road", "section_s", "lane", "kind", "type"}
        assert f["properties"]["road"] == "7"
        assert all(len(c) == 3 for c in f["geometry"]["coordinates"])
    outer = next(f for f in features if f["properties"]["lane"] == -2 and f["properties"]["kind"] == "outer")
    assert outer["properties"]["type"] == "sidewalk"
    assert outer["geometry"]["coordinates"] == [[0, -5.5, 0], [25, -5.5, 0], [40, -5.5, 0]]


def test_output_file_is_written(tmp_path, capsys):
    out = tmp_path / "centres.geojson"
    assert (
        main(["sample", str(write(tmp_path, maps.STRAIGHT)), "--step", "50", "--format", "geojson", "-o", str(out)])
        == 0
    )
    assert capsys.readouterr().out == ""
    assert len(json.loads(out.read_text())["features"]) == 2
    assert sorted(p.name for p in tmp_path.iterdir()) == ["centres.geojson", "map.xodr"]


def test_failure_while_writing_leaves_no_partial_file(tmp_path, capsys, monkeypatch):
    out = tmp_path / "out.csv"
    out.write_text("previous content")

    def broken(lines, stream):
        stream.write("road,section_s\n" * 1000)
        raise RuntimeError("disk on fire")

    monkeypatch.setattr(sample_cli, "write_csv", broken)
    code = main(["sample", str(write(tmp_path, maps.STRAIGHT)), "--step", "10", "-o", str(out)])
    assert code == 2
    err = capsys.readouterr().err
    assert "internal error" in err and "disk on fire" in err and "Traceback" not in err
    assert out.read_text() == "previous content"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["map.xodr", "out.csv"]


def test_unwritable_output_exits_2(tmp_path, capsys):
    out = tmp_path / "no" / "such" / "dir" / "out.csv"
    assert main(["sample", str(write(tmp_path, maps.STRAIGHT)), "--step", "10", "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "cannot write" in err


@pytest.mark.parametrize("step", ["0", "-1", "nan", "inf", "ten"])
def test_bad_step_is_a_usage_error(tmp_path, step):
    with pytest.raises(SystemExit) as exc:
        main(["sample", str(write(tmp_path, maps.STRAIGHT)), "--step", step])
    assert exc.value.code == 2


def test_missing_file_exits_2(tmp_path, capsys):
    assert main(["sample", str(tmp_path / "nope.xodr"), "--step", "1"]) == 2
    assert "Traceback" not in capsys.readouterr().err


def test_heading_is_continuous_on_a_circle(tmp_path, capsys):
    rows = sample_csv(capsys, write(tmp_path, maps.HALF_CIRCLE), "--step", "5")
    hdg = column(rows, "hdg", lane=-1)
    assert hdg[-1] == pytest.approx(math.pi, abs=1e-8)
    assert np.all(np.diff(hdg) > 0)


def test_single_side_section_keeps_the_other_sides_lanes(tmp_path, capsys):
    # [0, 50): lanes 1 (3 m) and -1; [50, 100) is singleSide and only redefines the right side (lane -1 now 2 m wide),
    # so lane 1 continues there with its 3 m width.
    sections = maps.section(0, left=[(1, 3.0, "sidewalk")], right=[(-1, 3.5, "driving")]) + maps.section(
        50, right=[(-1, 2.0, "driving")]
    ).replace('<laneSection s="50">', '<laneSection s="50" singleSide="true">')
    text = maps.document(maps.road("1", 100, maps.line(0, 0, 0, 100), sections))
    rows = sample_csv(capsys, write(tmp_path, text), "--step", "25")
    np.testing.assert_allclose(column(rows, "s", section_s="50.000000", lane=1), [50, 75, 100])
    np.testing.assert_allclose(column(rows, "y", section_s="50.000000", lane=1), 1.5, atol=1e-6)
    np.testing.assert_allclose(column(rows, "y", section_s="50.000000", lane=-1), -1.0, atol=1e-6)
    assert {r["type"] for r in rows if r["lane"] == "1"} == {"sidewalk"}
