"""Roadside lanes (issue 16): kerbs and sidewalks (urban) or shoulders and borders (rural) on every road, continued
round every junction corner by a connecting road whose lanes meet the legs' roadside lanes without a gap."""

from __future__ import annotations

import math

import pytest
from lxml import etree

import junctionart as ja
from junctionart.params import Params, Roadside
from junctionart.writer import to_bytes, write
from xodrcheck.analysis.sample import sample_lanes
from xodrcheck.check import check
from xodrcheck.config import Config
from xodrcheck.reader import read

#: Generated maps are judged as junctionart guarantees them: every rule at its own severity.
GENERATOR = Config(profile="generator")

ROADSIDE = {"curb", "sidewalk", "shoulder", "border"}
#: (type, width m, height m) from the driving lanes outward
URBAN = (("curb", 0.2, 0.15), ("sidewalk", 2.0, 0.15))
RURAL = (("shoulder", 1.5, 0.0), ("border", 0.5, 0.0))


@pytest.fixture(scope="module")
def urban():
    """Five urban maps, random lanes and curved roads, right- and left-hand traffic."""
    out = []
    for seed, rule in [(0, "RHT"), (1, "RHT"), (2, "LHT"), (3, "RHT"), (4, "LHT")]:
        # forks and ramps off: their branch takes the roadside on its outer side, the island inside has none
        p = Params.create("scenario", randomize_lanes=True, curved_roads=True, traffic_rule=rule)
        out.append(ja.generate_layout(p.with_(fork_probability=0.0, ramp_probability=0.0), seed))
    return out


def _outer(lanes, side: int) -> list:
    return sorted(lanes, key=lambda ln: side * ln.id)


def test_every_road_ends_in_kerb_and_sidewalk_of_the_documented_sizes(urban):
    checked = 0
    for result in urban:
        for road in result.document.roads:
            if road.junction != "-1":
                continue
            for sec in road.sections:
                for side, lanes in ((1, sec.left), (-1, sec.right)):
                    ordered = _outer(lanes, side)
                    tail = ordered[-2:]
                    assert [(ln.type, ln.widths[0].a, ln.heights[0].inner) for ln in tail] == list(URBAN)
                    assert all(ln.widths[0].b == ln.widths[0].c == ln.widths[0].d == 0.0 for ln in tail)
                    # ids consecutive from the centre: the kerb borders the outermost carriageway lane
                    assert [abs(ln.id) for ln in ordered] == list(range(1, len(ordered) + 1))
                    assert all(ln.type not in ROADSIDE for ln in ordered[:-2])
                    checked += 1
    assert checked > 100


def test_roadside_lanes_are_linked_through_lane_sections(urban):
    links = 0
    for result in urban:
        for road in result.document.roads:
            if road.junction != "-1":
                continue
            for a, b in zip(road.sections, road.sections[1:]):
                for side in ("left", "right"):
                    types_b = {ln.id: ln.type for ln in getattr(b, side)}
                    for ln in getattr(a, side):
                        if ln.type in ROADSIDE:
                            assert types_b[ln.successor] == ln.type
                            links += 1
    assert links > 50


def _corners(result):
    doc = result.document
    return [r for r in doc.roads if r.junction != "-1" and "corner" in r.name]


def test_each_corner_carries_the_roadside_lanes_from_leg_to_leg(urban):
    """Corner roads hold only roadside lanes, linked to lanes of the same type on the legs, and their junction has a
    connection for each; almost every corner of every junction with 3+ legs has one."""
    legs = corners = 0
    for result in urban:
        doc = result.document
        roads = {r.id: r for r in doc.roads}
        for k, j in enumerate(doc.junctions):
            n = sum((rp.start_junction == k) + (rp.end_junction == k) for rp in result.layout.roads)
            mine = [c for c in j.connections if "corner" in roads[c.connecting_road].name]
            if n > 2:
                legs, corners = legs + n, corners + len(mine)
            for c in mine:
                road = roads[c.connecting_road]
                (sec,) = road.sections
                lanes = sec.left + sec.right
                assert [ln.type for ln in sorted(lanes, key=lambda ln: abs(ln.id))] == ["curb", "sidewalk"]
                pred, succ = roads[road.predecessor.element_id], roads[road.successor.element_id]
                p_sec = pred.sections[0] if road.predecessor.contact_point == "start" else pred.sections[-1]
                s_sec = succ.sections[0] if road.successor.contact_point == "start" else succ.sections[-1]
                for ln in lanes:
                    assert _lane(p_sec, ln.predecessor).type == ln.type
                    assert _lane(s_sec, ln.successor).type == ln.type
                assert {(ll.from_lane, ll.to_lane) for ll in c.lane_links} == {(ln.predecessor, ln.id) for ln in lanes}
    assert corners >= 0.95 * legs > 0


def _lane(sec, lane_id):
    (lane,) = [ln for ln in sec.left + sec.right if ln.id == lane_id]
    return lane


def _ends(doc_path):
    """(road, lane) -> {"inner"/"outer": ((x, y) at s start, (x, y) at s end)} of every lane, read back by xodrcheck."""
    doc = read(doc_path).document
    out: dict = {}
    for line in sample_lanes(doc, 1.0, ("inner", "outer")):
        key = (line.road, line.section_s, line.lane)
        out.setdefault(key, {})[line.kind] = ((line.x[0], line.y[0]), (line.x[-1], line.y[-1]))
    return doc, out


def test_corner_borders_meet_the_legs_borders(urban, tmp_path):
    """Read back from the written file: at both ends of each corner lane, its inner and outer borders lie on those of
    the leg lane it links to (within 1 mm), so the sidewalk runs round the corner without a gap or a step."""
    met = 0
    for i, result in enumerate(urban[:3]):
        path = write(result.document, tmp_path / f"m{i}.xodr")
        doc, ends = _ends(path)
        roads = {r.id: r for r in doc.roads}
        for road in _corners(result):
            for end, link, lane_attr in ((0, road.predecessor, "predecessor"), (1, road.successor, "successor")):
                leg = roads[link.element_id]
                sec = leg.lane_sections[0] if link.contact_point == "start" else leg.lane_sections[-1]
                at = 0 if link.contact_point == "start" else 1
                for ln in road.sections[0].left + road.sections[0].right:
                    mine = ends[(road.id, 0.0, ln.id)]
                    theirs = ends[(leg.id, sec.s, getattr(ln, lane_attr))]
                    for kind in ("inner", "outer"):
                        assert math.dist(mine[kind][end], theirs[kind][at]) < 1e-3
                        met += 1
    assert met > 200


def test_maps_are_clean_and_valid_for_every_version(urban, schema18, schema19, schema17, tmp_path):
    for i, result in enumerate(urban):
        p18 = write(result.document, tmp_path / f"a{i}.xodr", "1.8")
        assert list(schema18.iter_errors(str(p18))) == []
        report = check(p18, GENERATOR)
        assert [f.code for f in report.findings if f.severity.name in ("ERROR", "WARNING")] == []
        if i < 2:
            assert list(schema19.iter_errors(str(write(result.document, tmp_path / f"b{i}.xodr", "1.9")))) == []
            tree = etree.parse(str(write(result.document, tmp_path / f"c{i}.xodr", "1.7")))
            assert schema17.validate(tree), schema17.error_log
        types = {el.get("type") for el in etree.parse(str(p18)).iter("lane")}
        assert {"curb", "sidewalk", "driving"} <= types
        heights = etree.parse(str(p18)).findall(".//lane[@type='sidewalk']/height")
        assert heights and all(h.get("inner") == h.get("outer") == "0.15" for h in heights)


def test_rural_roadside_has_shoulders_and_borders_at_road_level(tmp_path):
    result = ja.generate_layout(Params.create(roadside="rural", randomize_lanes=True), 5)
    widths = {}
    for road in result.document.roads:
        for sec in road.sections:
            for ln in sec.left + sec.right:
                if ln.type in ROADSIDE:
                    widths[ln.type] = ln.widths[0].a
                    assert ln.heights == ()
    assert widths == {t: w for t, w, _ in RURAL}
    report = check(write(result.document, tmp_path / "r.xodr"), GENERATOR)
    assert [f.code for f in report.findings if f.severity.name == "ERROR"] == []


def test_roadside_keeps_the_paper_layout_but_widens_junctions():
    """The roadside draws no random number of its own: the network is the paper's, only the junctions are pushed
    outward by the roadside width, and the default parameters are the paper's (no roadside)."""
    assert Params().roadside is Roadside.NONE and Params.create().roadside is Roadside.NONE
    assert Params.create("paper") == Params()
    plain = ja.generate_layout(Params(), 1)
    side = ja.generate_layout(Params.create("scenario"), 1)
    assert plain.network == side.network
    assert len(plain.layout.junctions) == len(side.layout.junctions)
    assert to_bytes(plain.document) == to_bytes(ja.generate(Params.create("paper"), 1))
    assert to_bytes(plain.document) != to_bytes(side.document)


def test_profile_and_roadside_are_validated():
    with pytest.raises(ja.ParamsError, match="profile"):
        Params.create("city")
    with pytest.raises(ja.ParamsError, match="roadside"):
        Params.create(roadside="grass")
    assert Params.create("scenario", roadside="none").roadside is Roadside.NONE


def test_command_line_profile_and_roadside(tmp_path, capsys):
    from junctionart.cli import main

    paths = {name: tmp_path / f"{name}.xodr" for name in ("plain", "paper", "scenario", "rural", "bad")}
    base = ["generate", "--seed", "3", "--size", "500x500", "-q", "-o"]
    assert main([*base, str(paths["plain"])]) == 0
    assert main([*base, str(paths["paper"]), "--profile", "paper"]) == 0
    assert main([*base, str(paths["scenario"]), "--profile", "scenario"]) == 0
    assert main([*base, str(paths["rural"]), "--profile", "scenario", "--roadside", "rural"]) == 0
    assert paths["plain"].read_bytes() == paths["paper"].read_bytes()
    assert (
        b'type="sidewalk"' in paths["scenario"].read_bytes() and b'type="sidewalk"' not in paths["plain"].read_bytes()
    )
    assert b'type="shoulder"' in paths["rural"].read_bytes() and b'type="sidewalk"' not in paths["rural"].read_bytes()
    assert main([*base, str(paths["bad"]), "--roadside", "grass"]) == 2
    assert "roadside" in capsys.readouterr().err and not paths["bad"].exists()
