"""Overpasses (issue 16): a crossing of control lines kept as an overpass instead of a junction, measured from the
written file with xodrcheck's reader and geometry: clearance over the crossing, grades and vertical curves within the
terrain's limits, z continuous at every link, no finding; a deck lowered to 3 m is an O001 error."""

from __future__ import annotations

import itertools
from pathlib import Path

import numpy as np
import pytest
from lxml import etree

import junctionart as ja
from junctionart import controllines
from junctionart.params import Params, Terrain
from junctionart.scenario import terrain
from junctionart.scenario.overpass import RAMP_LIMITS, RISE
from xodrcheck.analysis.elevation import elevation_info
from xodrcheck.check import check
from xodrcheck.config import Config
from xodrcheck.mesh.footprint import overlap_index
from xodrcheck.reader import read

#: Generated maps are judged as junctionart guarantees them: every rule at its own severity.
GENERATOR = Config(profile="generator")

LINES = Path(__file__).resolve().parents[2] / "examples" / "overpass.json"
CASES = [("flat", 1), ("hilly", 1), ("rolling", 2), ("hilly", 2)]


def _generate(terrain_name: str, seed: int, **extra) -> ja.Result:
    # forks and ramps (issue 28) off: the junction counts here are the overpass's
    extra = {"fork_probability": 0.0, "ramp_probability": 0.0, **extra}
    p = Params.create("scenario", terrain=terrain_name, overpass_probability=1.0, **extra)
    return ja.generate_layout(p, seed, controllines.load(LINES))


@pytest.fixture(scope="module")
def maps(tmp_path_factory) -> list[tuple[str, Path, tuple[str, str]]]:
    """(terrain, written file, (upper road id, lower road id)) of each case."""
    folder = tmp_path_factory.mktemp("overpass")
    out = []
    for name, seed in CASES:
        r = _generate(name, seed)
        assert len(r.layout.overpasses) == 1, r.layout.repairs
        ((up, low),) = r.layout.overpasses
        path = ja.write(r.document, folder / f"{name}-{seed}.xodr")
        out.append((name, path, (str(up + 1), str(low + 1))))
    return out


def _limits(name: str) -> tuple[float, float]:
    return terrain.LIMITS.get(Terrain(name), RAMP_LIMITS)


def test_the_deck_clears_the_lower_road_by_the_rise_measured_from_the_file(maps):
    """Every plan-view overlap of the two roads' lane surfaces (xodrcheck's footprints, heights from the written
    elevation and lane heights) has at least 4.5 m between the surfaces; the shared area is the whole crossing."""
    for _, path, (up, low) in maps:
        index = overlap_index(read(path).document)
        lanes = index.surfaces.lanes
        found = [
            o
            for o in index.overlaps(0.5, 100.0)  # every overlap closer than 100 m in height: all of them
            if {lanes[o.lane_a].road, lanes[o.lane_b].road} == {up, low}
        ]
        area = sum(o.area for o in found)
        assert area > 100.0, path.name  # two roads >= 7 m wide and their sidewalks crossing at >= 40 degrees
        dz = min(o.dz for o in found)
        assert dz >= 4.5 and dz >= RISE - 0.2, (path.name, dz)  # 5.5 m less at most a 0.15 m kerb


def test_grades_curves_and_links_within_the_limits(maps):
    """``xodrcheck info``'s figures: max grade within the terrain's limit (the ramps' limit on flat ground), no z
    step at any link; the written records' vertical curves no sharper than the limit's radius."""
    for name, path, (up, _) in maps:
        doc = read(path).document
        grade, radius = _limits(name)
        e = elevation_info(doc)
        assert 0.01 < e.max_grade <= grade + 1e-9 and e.max_link_step < 1e-9 and e.links > 20
        assert e.max_z - e.min_z >= RISE - 1e-9
        for road in doc.roads:
            for rec in road.elevation:
                for u in np.linspace(0.0, road.length - rec.s, 50):  # curvature 2c + 6du, checked past each end
                    assert abs(2 * rec.c + 6 * rec.d * u) <= 1.0 / radius + 1e-9, (path.name, road.id)
        upper = next(r for r in doc.roads if r.id == up)
        assert len(upper.elevation) == 3  # ramp up, level deck, ramp down


def test_overpass_maps_have_no_finding_and_are_schema_valid(maps, schema18):
    for _, path, _ in maps:
        assert list(schema18.iter_errors(str(path))) == []
        report = check(path, GENERATOR)
        assert [(f.code, f.message) for f in report.findings if f.severity.name in ("ERROR", "WARNING")] == []


def test_a_bridge_record_spans_the_deck(maps):
    """The upper road carries one ``<bridge>`` over its level stretch, which holds the crossing: z is constant along
    it and at least the rise above the lower road's surface at the crossing."""
    for _, path, (up, low) in maps:
        root = etree.parse(str(path)).getroot()
        bridges = root.findall(".//road/objects/bridge")
        assert len(bridges) == 1 and bridges[0].getparent().getparent().get("id") == up
        b = bridges[0]
        assert b.get("type") == "concrete" and b.get("name") == f"overpass over road {low}"
        s0, length = float(b.get("s")), float(b.get("length"))
        road = next(r for r in read(path).document.roads if r.id == up)
        deck = [e for e in road.elevation if abs(e.s - s0) < 1e-9]
        assert len(deck) == 1 and (deck[0].b, deck[0].c, deck[0].d) == (0.0, 0.0, 0.0) and length > 10.0


@pytest.mark.parametrize("version", ["1.7", "1.9"])
def test_other_versions_are_schema_valid_with_the_bridge(version, schema17, schema19):
    r = _generate("hilly", 1, version=version)
    data = ja.to_bytes(r.document, version)
    assert b"<bridge " in data
    if version == "1.7":
        assert schema17.validate(etree.fromstring(data))
    else:
        assert list(schema19.iter_errors(etree.fromstring(data))) == []


def test_a_deck_only_3_m_above_is_an_o001_error(tmp_path, monkeypatch):
    monkeypatch.setattr(terrain, "RISE", 3.0)
    r = _generate("hilly", 1)
    ((up, low),) = r.layout.overpasses
    path = ja.write(r.document, tmp_path / "low.xodr")
    errors = [f for f in check(path, GENERATOR).findings if f.code == "O001"]
    assert errors and all(f.severity.name == "ERROR" for f in errors)
    assert {errors[0].road} <= {str(up + 1), str(low + 1)}
    assert (
        "3.00 m between their surfaces" in errors[0].message and "1.50 m short of it as a bridge" in errors[0].message
    )


def test_without_overpasses_the_crossing_is_a_junction():
    p = Params.create("scenario", terrain="hilly", overpass_probability=0.0)
    r = ja.generate_layout(p, 1, controllines.load(LINES))
    assert r.network.overpasses == () and r.layout.overpasses == ()
    at = (1225.0, 100.0)  # where the bypass crosses the approach road

    def near(result: ja.Result) -> list[int]:
        return [j.legs for j in result.layout.junctions if np.hypot(*np.subtract(j.position, at)) < 1.0]

    assert near(r) == [4] and near(_generate("hilly", 1)) == []


def test_an_overpass_without_room_for_its_ramps_becomes_a_junction(monkeypatch):
    """Stage 3 measures the laid roads again; an overpass that does not fit is split into a junction."""
    from junctionart.intersections import overpasses

    kept = len(_generate("hilly", 1).document.junctions)
    monkeypatch.setattr(overpasses, "fits", lambda *args: False)
    r = _generate("hilly", 1)
    assert r.network.overpasses and r.layout.overpasses == ()
    assert any("no room for its ramps" in why for why in r.layout.repairs)
    assert len(r.document.junctions) == kept + 1
    assert [f.code for f in check_document(r)] == []


def check_document(r: ja.Result) -> list:
    return [f for f in check(ja.to_bytes(r.document), GENERATOR).findings if f.severity.name == "ERROR"]


def test_short_roads_keep_their_junction():
    """A bypass too short for ramps or a level stretch under a deck crosses at a junction, whatever the probability."""
    data = controllines.load(LINES)
    short = ja.ControlLines(
        tuple(
            ln if ln.id != "bypass" else ln.__class__(ln.id, ((1200.0, 40.0), (1205.0, 160.0)), ln.group, ln.lanes)
            for ln in data.lines
        ),
        data.pairs,
    )
    r = ja.generate_layout(Params.create("scenario", terrain="hilly", overpass_probability=1.0), 1, short)
    assert r.network.overpasses == () and r.layout.overpasses == ()


def test_automatic_maps_have_no_crossing_so_the_option_changes_nothing():
    """Automatic control lines never cross: the scenario profile's overpasses leave those maps byte-identical, and
    the draw uses its own stream."""
    for seed in (3, 4):
        on = Params.create("scenario", width=600, height=600, randomize_lanes=True)
        off = on.with_(overpass_probability=0.0)
        assert on.overpass_probability == 0.5
        assert ja.to_bytes(ja.generate(on, seed)) == ja.to_bytes(ja.generate(off, seed))


def test_the_probability_is_validated():
    with pytest.raises(ja.ParamsError, match="overpass_probability"):
        Params.create(overpass_probability=1.5)
    assert Params().overpass_probability == 0.0 and not Params().scenario


def test_render_draws_pieces_by_height_only_where_heights_vary(maps, tmp_path):
    """A map whose heights vary is drawn in pieces, lowest first (the deck over the road below); a flat map whole,
    as before."""
    from junctionart.render import PIECE, _heights_vary, _pieces, render

    assert _pieces(200, False) == [(0, 200)]
    pieces = _pieces(200, True)
    assert pieces[0][0] == 0 and pieces[-1][1] == 200 and all(b[0] == a[1] - 1 for a, b in itertools.pairwise(pieces))
    assert max(hi - lo for lo, hi in pieces) == PIECE + 1
    flat = read(ja.to_bytes(ja.generate(Params(), 1))).document
    assert not _heights_vary(flat) and _heights_vary(read(maps[0][1]).document)  # maps[0]: flat ground, a deck
    out = render(maps[0][1], tmp_path / "overpass.png")
    assert out.roads > 10 and (tmp_path / "overpass.png").stat().st_size > 10_000


def test_xodrcheck_info_reports_the_grade_and_link_steps_within_the_limits(maps, capsys):
    """The acceptance figures as ``xodrcheck info`` prints them for the overpass maps."""
    import re

    from xodrcheck.cli import main

    for name, path, _ in maps:
        assert main(["info", str(path)]) == 0
        line = next(x for x in capsys.readouterr().out.splitlines() if x.strip().startswith("elevation"))
        grade, step = re.search(r"max grade ([\d.]+) %, largest z step at a road link ([\d.e+-]+) m", line).groups()
        assert 0.0 < float(grade) <= 100 * _limits(name)[0] + 1e-6 and float(step) < 1e-9, line


def test_heights_the_iterations_leave_are_scaled_until_every_piece_fits():
    """Fallback of the terrain step with overpasses: heights scaled toward their mean by the largest ratio at which
    every piece (a ramp climbing the rise included) fits its bound, keeping what relief it can."""
    z = {0: 0.0, 1: 40.0, 2: 12.0, -1: 20.0}
    pieces = [(0, 0.0, -1, RISE, 8.0), (-1, RISE, 1, 0.0, 8.0), (0, 0.0, 2, 0.0, 6.0), (2, 0.0, 1, 0.0, 30.0)]
    out = terrain._scaled(z, pieces)
    rises = [abs(out[b] + ob - out[a] - oa) for a, oa, b, ob, _ in pieces]
    assert all(r <= bound + 1e-9 for r, (*_, bound) in zip(rises, pieces))
    assert max(rises) > RISE and out[1] - out[0] > 1.0  # not flattened: the tightest piece binds
    assert any(abs(r - bound) < 1e-6 for r, (*_, bound) in zip(rises, pieces))
