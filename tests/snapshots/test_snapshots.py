"""Map invariants: ``xodrcheck snapshot``/``diff``, the pytest plugin, and golden snapshots.

Golden snapshots of corpus maps live in ``tests/snapshots/corpus/`` (refresh them with
``pytest tests/snapshots --xodr-snapshot-update`` after a deliberate change of the reader or the rules, and read the
diff in review). Golden snapshots of generator seeds live in ``tests/snapshots/generator/``: any change in the
generator's output shows up there as a readable diff (refresh them the same way after a deliberate change, and say in
the commit what changed). Seeds are also checked for determinism (the same seed gives the same bytes and snapshot).
"""

from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path

import pytest

import junctionart as ja
from tests.conftest import corpus_root
from xodrcheck.analysis.snapshot import (
    Snapshot,
    SnapshotError,
    differences,
    lane_links,
    snapshot_of,
    topology_hash,
)
from xodrcheck.cli import main
from xodrcheck.reader import read

pytest_plugins = ("pytester",)

HERE = Path(__file__).parent
FIXTURES = HERE.parent / "xodrcheck" / "rules" / "fixtures"
JUNCTION = FIXTURES / "link-not-reciprocal" / "pass_junction.xodr"
DROPPED = FIXTURES / "lane-not-continued" / "fail_junction.xodr"  # the same map without one lane predecessor
GOLDEN = {
    "connected_junctions_simple": "esmini/EnvironmentSimulator/Unittest/xodr/connected_junctions_simple.xodr",
    "direct_junction_simple": "esmini/EnvironmentSimulator/Unittest/xodr/direct_junction_simple.xodr",
    "highway_exit": "esmini/EnvironmentSimulator/Unittest/xodr/highway_exit.xodr",
    "junction_ma": "ika-roadgeneration/test/gt/junction_ma.xodr",
    "road_straight_curve_junction": "esmini/EnvironmentSimulator/Unittest/xodr/road_straight_curve_junction.xodr",
}


# ------------------------------------------------------------------------------------------------------ snapshot
def test_snapshot_counts_a_small_junction():
    snap = snapshot_of(JUNCTION)  # a T junction: roads 1, 2, 3 (two lanes each), connecting roads 10, 11, 16, 17
    assert (snap.roads, snap.junction_roads, snap.junctions, snap.lane_sections, snap.lanes) == (7, 4, 1, 7, 10)
    assert snap.legs == {"3": 1} and snap.junctions_by_type == {"default": 1}
    assert snap.lanes_by_type == {"driving": 10}
    # six 50 m lanes, two 20 m straight connections, two quarter circles (lane centres at radius 8.25 and 11.75 m)
    assert snap.lane_length == pytest.approx(6 * 50.0 + 2 * 20.0 + (8.25 + 11.75) * math.pi / 2, abs=0.01)
    # 4 connecting lanes x (predecessor + successor) + 4 junction laneLinks
    assert snap.lane_links == 12
    assert snap.bbox == pytest.approx((0.0, -3.5, 120.0, 60.0))
    assert snap.findings == {}


def test_snapshot_round_trips_through_json():
    snap = snapshot_of(JUNCTION)
    assert Snapshot.from_json(json.loads(json.dumps(snap.to_json()))) == snap


def test_topology_hash_ignores_file_order_but_not_links():
    doc = read(JUNCTION).document
    edges = lane_links(doc)
    shuffled = dataclasses.replace(doc, roads=tuple(reversed(doc.roads)))
    assert topology_hash(lane_links(shuffled)) == topology_hash(edges)
    assert topology_hash(lane_links(read(DROPPED).document)) != topology_hash(edges)


def test_differences_are_readable_and_tolerant():
    old = snapshot_of(JUNCTION)
    assert list(differences(old, old)) == []
    noise = dataclasses.replace(old, lane_length=old.lane_length + 4e-4, bbox=tuple(v + 4e-4 for v in old.bbox))
    assert list(differences(old, noise)) == []
    lines = list(differences(old, snapshot_of(DROPPED)))
    assert "lane links: 12 -> 11 (-1)" in lines
    assert "findings L010: 0 -> 1" in lines
    assert any(line.startswith("lane graph topology changed") for line in lines)
    moved = dataclasses.replace(old, bbox=(old.bbox[0] - 1.0, *old.bbox[1:]), roads=8, legs={"4": 1})
    lines = list(differences(old, moved))
    assert "roads: 7 -> 8 (+1)" in lines
    assert "junctions with 3 legs: 1 -> 0" in lines and "junctions with 4 legs: 0 -> 1" in lines
    assert any(line.startswith("bounding box: x 0.000..120.000") for line in lines)


T_JUNCTION = Path(__file__).resolve().parents[2] / "examples" / "t-junction.xodr"


def test_snapshots_keep_where_traffic_enters_and_leaves_and_which_routes_there_are():
    """The README's T junction: every road's outer end is open; all nine entry-exit pairs route but the three
    U-turns (no connection turns back)."""
    snap = snapshot_of(T_JUNCTION)
    assert snap.entries == ("1:-1:start", "2:1:end", "3:-1:start")
    assert snap.exits == ("1:1:start", "2:-1:end", "3:1:start")
    assert snap.unroutable == (("1:-1:start", "1:1:start"), ("2:1:end", "2:-1:end"), ("3:-1:start", "3:1:start"))
    assert snap.strong_components == 12


def test_diff_names_a_route_that_vanished(tmp_path):
    """Without connection 2 (west to south) and connecting lane 102/-1's predecessor, no route leads from road 1's
    start to road 3's start any more (either alone still does: the graph follows a link either side states)."""
    text = T_JUNCTION.read_text(encoding="utf-8")
    start = text.index('<connection id="2"')
    end = text.index("</connection>", start) + len("</connection>")
    text = text[:start] + text[end:]
    road = text.index('<road id="102"')
    text = text[:road] + text[road:].replace('<predecessor id="-1"/><successor id="1"/>', '<successor id="1"/>', 1)
    cut = tmp_path / "no-turn.xodr"
    cut.write_text(text, encoding="utf-8")
    lines = list(differences(snapshot_of(T_JUNCTION), snapshot_of(cut)))
    assert "route from 1:-1:start to 3:1:start vanished" in lines
    assert not [line for line in lines if "appeared" in line or " is gone" in line]


def test_a_snapshot_without_reachability_still_compares():
    """Snapshots written before issue 30 have no reachability keys: they load, and compare on the rest."""
    data = snapshot_of(JUNCTION).to_json()
    for key in ("strong_components", "entries", "exits", "unroutable"):
        del data[key]
    old = Snapshot.from_json(data)
    assert old.entries is None and list(differences(old, snapshot_of(JUNCTION))) == []


@pytest.mark.parametrize("data", [[], {"format": 99}, {"format": 1, "roads": 1}, {"format": 1, "roads": "x"}])
def test_malformed_snapshots_are_refused(data):
    with pytest.raises(SnapshotError):
        Snapshot.from_json(data)


# ------------------------------------------------------------------------------------------------------ command line
def test_snapshot_then_diff_on_the_command_line(tmp_path, capsys):
    out = tmp_path / "snap.json"
    assert main(["snapshot", str(JUNCTION), "-o", str(out)]) == 0
    assert json.loads(out.read_text())["roads"] == 7
    capsys.readouterr()
    assert main(["diff", str(out), str(JUNCTION)]) == 0
    assert "no change" in capsys.readouterr().out
    assert main(["diff", str(out), str(DROPPED)]) == 1
    printed = capsys.readouterr().out.splitlines()
    assert f"{DROPPED}: findings L010: 0 -> 1" in printed


def test_snapshot_to_standard_output(capsys):
    assert main(["snapshot", str(JUNCTION)]) == 0
    assert json.loads(capsys.readouterr().out)["lane_links"] == 12


@pytest.mark.parametrize("case", ["missing-map", "not-xml", "missing-snapshot", "bad-snapshot"])
def test_command_line_errors_exit_2_with_one_line(case, tmp_path, capsys):
    snap = tmp_path / "snap.json"
    snap.write_text(json.dumps(snapshot_of(JUNCTION).to_json()))
    junk = tmp_path / "junk.xodr"
    junk.write_text("this is not XML")
    args = {
        "missing-map": ["diff", str(snap), str(tmp_path / "none.xodr")],
        "not-xml": ["snapshot", str(junk)],
        "missing-snapshot": ["diff", str(tmp_path / "none.json"), str(JUNCTION)],
        "bad-snapshot": ["diff", str(junk), str(JUNCTION)],
    }[case]
    assert main(args) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("xodrcheck: ")


# ------------------------------------------------------------------------------------------------------ golden
@pytest.mark.corpus
@pytest.mark.parametrize("name", sorted(GOLDEN))
def test_corpus_maps_match_their_golden_snapshots(name, xodr_snapshot):
    path = corpus_root() / GOLDEN[name]
    if not path.is_file():
        pytest.skip(f"corpus not available at {corpus_root()}")
    xodr_snapshot(path, snapshot=HERE / "corpus" / f"{name}.json")


#: name -> (Params keywords, seed) of the generator's golden maps: small and large, both lane modes, LHT, 1.7, curves
GENERATOR_GOLDEN = {
    "two_lane_500m_seed1": ({"width": 500, "height": 500}, 1),
    "two_lane_500m_seed7": ({"width": 500, "height": 500}, 7),
    "two_lane_500m_seed42": ({"width": 500, "height": 500}, 42),
    "random_lane_1km_seed3": ({"width": 1000, "height": 1000, "randomize_lanes": True}, 3),
    "random_lane_lht_curved_seed5": (
        {"width": 700, "height": 700, "randomize_lanes": True, "traffic_rule": "LHT", "curved_roads": True},
        5,
    ),
    "two_lane_v17_seed11": ({"width": 500, "height": 500, "version": "1.7"}, 11),
    # issue 16: sidewalks and corners, traffic lights / signs / crosswalks, hilly elevation (the scenario profile
    # before roundabouts, issue 28: its roundabouts have golden maps of their own)
    "scenario_hilly_random_lane_seed9": (
        {
            "profile": "scenario",
            "terrain": "hilly",
            "width": 700,
            "height": 700,
            "randomize_lanes": True,
            "roundabout_probability": 0.0,
        },
        9,
    ),
}


@pytest.mark.parametrize("name", sorted(GENERATOR_GOLDEN))
def test_generator_seeds_match_their_golden_snapshots(name, xodr_snapshot):
    kwargs, seed = GENERATOR_GOLDEN[name]
    params = ja.Params.create(**kwargs)
    data = ja.to_bytes(ja.generate(params, seed), params.version)
    xodr_snapshot(data, snapshot=HERE / "generator" / f"{name}.json")


#: name -> (Params keywords, seed, control-line file in examples/) of golden maps drawn from control lines
GENERATOR_GOLDEN_LINES = {
    # issue 16: the bypass passes over the approach road (an overpass, no junction), hilly, signals and sidewalks
    "scenario_overpass_hilly_seed1": (
        {"profile": "scenario", "terrain": "hilly", "overpass_probability": 1.0, "roundabout_probability": 0.0},
        1,
        "overpass.json",
    ),
}


@pytest.mark.parametrize("name", sorted(GENERATOR_GOLDEN_LINES))
def test_generator_control_line_maps_match_their_golden_snapshots(name, xodr_snapshot):
    kwargs, seed, lines = GENERATOR_GOLDEN_LINES[name]
    params = ja.Params.create(**kwargs)
    result = ja.generate_layout(params, seed, ja.controllines.load(HERE.parent.parent / "examples" / lines))
    assert len(result.layout.overpasses) == 1  # the case is there for its overpass
    data = ja.to_bytes(result.document, params.version)
    xodr_snapshot(data, snapshot=HERE / "generator" / f"{name}.json")


@pytest.mark.parametrize("seed", [1, 7, 42])
def test_generator_seeds_give_the_same_snapshot_twice(seed):
    params = ja.Params.create(width=250, height=250)
    first = ja.to_bytes(ja.generate(params, seed), params.version)
    again = ja.to_bytes(ja.generate(params, seed), params.version)
    assert first == again
    snap = snapshot_of(first)
    assert snap.roads > 0 and snap.lane_links > 0
    assert list(differences(snap, snapshot_of(again))) == []


# ------------------------------------------------------------------------------------------------------ plugin
def test_the_plugin_is_declared_as_a_pytest11_entry_point():
    text = (HERE.parent.parent / "pyproject.toml").read_text(encoding="utf-8")
    assert '[project.entry-points.pytest11]\nxodrcheck = "xodrcheck.pytest_plugin"' in text


#: The plugin is loaded explicitly in the inner runs, whether or not the package's entry points are installed.
PLUGIN = ("-p", "xodrcheck.pytest_plugin")


@pytest.fixture
def pytester(pytester, monkeypatch):
    monkeypatch.setenv("PYTEST_DISABLE_PLUGIN_AUTOLOAD", "1")
    return pytester


def test_plugin_fixture_writes_compares_and_reports(pytester):
    pytester.makepyfile(
        test_map=f"""
        from pathlib import Path

        def test_map(xodr_snapshot):
            xodr_snapshot(Path({str(JUNCTION)!r}), snapshot=Path("snaps") / "map.json")
        """
    )
    result = pytester.runpytest_subprocess(*PLUGIN)
    result.assert_outcomes(failed=1)
    result.stdout.fnmatch_lines(["*no snapshot*--xodr-snapshot-update*"])

    result = pytester.runpytest_subprocess(*PLUGIN, "--xodr-snapshot-update")
    result.assert_outcomes(passed=1)
    written = pytester.path / "snaps" / "map.json"
    assert json.loads(written.read_text())["roads"] == 7

    result = pytester.runpytest_subprocess(*PLUGIN)
    result.assert_outcomes(passed=1)

    data = json.loads(written.read_text())
    data["findings"] = {"L010": 1}
    data["roads"] = 6
    written.write_text(json.dumps(data))
    result = pytester.runpytest_subprocess(*PLUGIN)
    result.assert_outcomes(failed=1)
    result.stdout.fnmatch_lines(["*differs from*", "*roads: 6 -> 7 (+1)*", "*findings L010: 1 -> 0*"])


def test_plugin_default_snapshot_path_is_beside_the_test(pytester):
    pytester.makepyfile(
        test_default=f"""
        def test_map(xodr_snapshot):
            xodr_snapshot({str(JUNCTION)!r})
        """
    )
    pytester.runpytest_subprocess(*PLUGIN, "--xodr-snapshot-update").assert_outcomes(passed=1)
    assert (pytester.path / "snapshots" / "pass_junction.json").is_file()
    pytester.runpytest_subprocess(*PLUGIN).assert_outcomes(passed=1)
