"""``xodrcheck info``: the numbers it prints, its JSON shape, and its exit codes."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from tests.xodrcheck.cli import maps
from xodrcheck.cli import main

REPO = Path(__file__).resolve().parents[3]
EXAMPLE = REPO / "examples" / "t-junction.xodr"

JSON_KEYS = {
    "file",
    "findings_counted",
    "opendrive_version",
    "roads",
    "junction_roads",
    "junctions",
    "lane_sections",
    "lanes",
    "reference_line_length_m",
    "geometry",
    "bounding_box",
    "findings",
    "elevation",
}


def write(tmp_path: Path, text: str, name: str = "map.xodr") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def info_json(capsys, *paths: Path) -> tuple[int, list[dict], str]:
    """Exit code, the JSON objects printed and what went to stderr."""
    code = main(["info", "--format", "json", *map(str, paths)])
    out, err = capsys.readouterr()
    return code, [json.loads(line) for line in out.splitlines()], err


def test_straight_road_numbers(tmp_path, capsys):
    code, (info,), err = info_json(capsys, write(tmp_path, maps.STRAIGHT))
    assert code == 0 and err == ""
    assert set(info) == JSON_KEYS
    assert info["opendrive_version"] == "1.8"
    assert info["roads"] == 1 and info["junction_roads"] == 0
    assert info["junctions"] == {"total": 0, "by_type": {}, "by_legs": {}}
    assert info["lane_sections"] == 1
    assert info["lanes"]["total"] == 2 and info["lanes"]["by_type"] == {"driving": 2}
    assert "per lane section" in info["lanes"]["counted"]
    assert info["reference_line_length_m"] == pytest.approx(100.0)
    assert info["geometry"] == {"line": 1}
    box = info["bounding_box"]
    assert box["basis"] == "lane borders"
    assert (box["min_x"], box["min_y"], box["max_x"], box["max_y"]) == pytest.approx((0, -3.5, 100, 3.5), abs=1e-9)
    assert info["findings"]["error"] == 0


def test_arc_bounding_box_follows_the_outer_lane_border(tmp_path, capsys):
    # Quarter circle around (0, 100): the right border (t = -3.5) has radius 103.5 and runs from (0, -3.5) to
    # (103.5, 100); the left border (radius 96.5) stays inside it.
    _, (info,), _ = info_json(capsys, write(tmp_path, maps.ARC))
    box = info["bounding_box"]
    assert box["min_x"] == pytest.approx(0.0, abs=1e-9)
    assert box["max_x"] == pytest.approx(maps.ARC_RADIUS + 3.5, abs=1e-6)
    assert box["min_y"] == pytest.approx(-3.5, abs=1e-9)
    assert box["max_y"] == pytest.approx(maps.ARC_RADIUS, abs=1e-6)
    assert info["geometry"] == {"arc": 1}
    assert info["reference_line_length_m"] == pytest.approx(math.pi / 2 * maps.ARC_RADIUS)


def test_bounding_box_finds_an_extreme_inside_a_road(tmp_path, capsys):
    # Half circle around (0, 100): the right border's rightmost point (103.5, 100) lies half way along the road.
    # Sampled under the chord tolerance (1 cm), the box may fall short of it by at most that much, never exceed it.
    _, (info,), _ = info_json(capsys, write(tmp_path, maps.HALF_CIRCLE))
    box = info["bounding_box"]
    r_out = maps.ARC_RADIUS + 3.5
    assert r_out - 0.01 <= box["max_x"] <= r_out + 1e-9
    assert box["min_y"] == pytest.approx(-3.5, abs=1e-9)
    assert box["max_y"] == pytest.approx(200 + 3.5, abs=1e-6)
    assert box["min_x"] == pytest.approx(0.0, abs=1e-6)


def test_lanes_are_counted_per_lane_section(tmp_path, capsys):
    _, (info,), _ = info_json(capsys, write(tmp_path, maps.TWO_SECTIONS))
    assert info["lane_sections"] == 2
    assert info["lanes"]["total"] == 3
    assert info["lanes"]["by_type"] == {"driving": 2, "sidewalk": 1}
    # The sidewalk only exists on [0, 40): there the right edge is at -5.5, later at -3.0.
    assert info["bounding_box"]["min_y"] == pytest.approx(-5.5)
    assert info["bounding_box"]["max_y"] == pytest.approx(0.0, abs=1e-12)


def test_junction_types_and_legs(tmp_path, capsys):
    _, (info,), _ = info_json(capsys, write(tmp_path, maps.JUNCTIONS))
    assert info["junctions"]["total"] == 2
    assert info["junctions"]["by_type"] == {"default": 1, "direct": 1}
    # direct: roads 1, 2, 3 joined -> 3 legs; default: incoming 4 and 5, plus 9 and 10 reached by connecting roads.
    assert info["junctions"]["by_legs"] == {"3": 1, "4": 1}
    assert info["roads"] == 10 and info["junction_roads"] == 3


def test_example_map(capsys):
    code, (info,), err = info_json(capsys, EXAMPLE)
    assert code == 0 and err == ""
    assert info["roads"] == 6 and info["junction_roads"] == 3
    assert info["junctions"] == {"total": 1, "by_type": {"default": 1}, "by_legs": {"3": 1}}
    assert info["lanes"]["by_type"] == {"driving": 12}
    assert info["geometry"] == {"arc": 2, "line": 4}
    assert info["reference_line_length_m"] == pytest.approx(300 + 20 + 2 * math.pi / 2 * 10)
    box = info["bounding_box"]
    assert (box["min_x"], box["min_y"], box["max_x"], box["max_y"]) == pytest.approx((-110, -110, 110, 3.5))
    assert info["findings"] == {"error": 0, "warning": 0, "info": 0}


def test_text_output(tmp_path, capsys):
    path = write(tmp_path, maps.TWO_SECTIONS)
    assert main(["info", str(path)]) == 0
    out = capsys.readouterr().out
    lines = out.splitlines()
    assert lines[0] == str(path)
    fields = {line.split()[0] for line in lines[1:]}
    assert {"OpenDRIVE", "roads", "junctions", "lanes", "length", "geometry", "bounding", "findings"} <= fields
    assert "3 (per lane section, centre lanes excluded): driving 2, sidewalk 1" in out
    assert "100.000 m of reference line" in out
    assert "x 0.000 .. 100.000, y -5.500 .. 0.000" in out
    # info reads, it does not check: its counts must not read as the check's verdict
    assert "0 error, 0 warning, 0 info found while reading (the rules are not run" in out


def test_several_files_print_one_object_each(tmp_path, capsys):
    a = write(tmp_path, maps.STRAIGHT, "a.xodr")
    b = write(tmp_path, maps.ARC, "b.xodr")
    code, infos, _ = info_json(capsys, a, b)
    assert code == 0
    assert [i["file"] for i in infos] == [str(a), str(b)]
    assert [i["geometry"] for i in infos] == [{"line": 1}, {"arc": 1}]


def test_missing_file_exits_2_with_one_line(tmp_path, capsys):
    missing = tmp_path / "nope.xodr"
    assert main(["info", str(missing)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and str(missing) in err and "Traceback" not in err


def test_directory_exits_2(tmp_path, capsys):
    assert main(["info", str(tmp_path)]) == 2
    assert "Traceback" not in capsys.readouterr().err


def test_worst_exit_code_wins_and_good_files_are_still_reported(tmp_path, capsys):
    good = write(tmp_path, maps.STRAIGHT)
    code, infos, err = info_json(capsys, tmp_path / "missing.xodr", good)
    assert code == 2
    assert err.count("\n") == 1 and "missing.xodr" in err
    assert [i["file"] for i in infos] == [str(good)]


def test_not_xml_cannot_be_read_whole_exit_2_and_nothing_printed(tmp_path, capsys):
    path = write(tmp_path, "this is not < xml")
    code, infos, err = info_json(capsys, path)
    assert code == 2 and infos == []
    assert err.count("\n") == 1 and f"cannot read {path} whole" in err and "X101" in err


def test_reader_errors_in_a_file_read_whole_exit_1_with_the_summary(tmp_path, capsys):
    path = write(tmp_path, maps.STRAIGHT.replace('length="100"', 'length="seven"', 1))
    code, (info,), err = info_json(capsys, path)
    assert code == 1 and info["findings"]["error"] >= 1
    assert err.count("\n") == 1 and "X206" in err


def test_usage_error_exits_2(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["info"])
    assert exc.value.code == 2
    with pytest.raises(SystemExit) as exc:
        main(["info", "--format", "yaml", "x.xodr"])
    assert exc.value.code == 2


def test_an_internal_error_is_one_line_and_exit_2(tmp_path, capsys, monkeypatch):
    import xodrcheck.cli.info as info_cli

    real = info_cli.map_info
    calls = []

    def flaky(result):
        calls.append(result.path)
        if len(calls) == 1:
            raise ZeroDivisionError("boom")
        return real(result)

    monkeypatch.setattr(info_cli, "map_info", flaky)
    a = write(tmp_path, maps.STRAIGHT, "a.xodr")
    b = write(tmp_path, maps.ARC, "b.xodr")
    code, infos, err = info_json(capsys, a, b)
    assert code == 2
    assert err == f"xodrcheck: internal error on {a}: ZeroDivisionError: boom\n"
    assert [i["file"] for i in infos] == [str(b)]
