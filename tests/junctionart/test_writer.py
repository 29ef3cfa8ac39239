import math
import os
import stat

import pytest
from lxml import etree

import junctionart as ja
from junctionart.errors import JunctionArtError
from junctionart.opendrive import Cubic, Document, Header, Lane, LaneSection, Line, Road
from junctionart.params import Params, TrafficRule
from junctionart.writer import fmt, to_bytes, write
from xodrcheck.config import Config

#: Generated maps are judged as junctionart guarantees them: every rule at its own severity.
GENERATOR = Config(profile="generator")


def _tiny(x0: float = 0.1) -> Document:
    lane = Lane(-1, "driving", (Cubic(0.0, 3.5),))
    sec = LaneSection(0.0, (), Lane(0, "none"), (lane,))
    road = Road("1", 10.0, "-1", (Line(0.0, x0, 0.2, 0.3, 10.0),), (sec,))
    return Document(Header(), (road,), ())


@pytest.mark.parametrize("x", [0.1, 1 / 3, 1e-300, 123456.789012345678, -2.5e-7, math.pi])
def test_floats_round_trip_exactly(x):
    assert float(fmt(x)) == x


def test_non_finite_numbers_are_refused(tmp_path):
    with pytest.raises(JunctionArtError, match="non-finite"):
        write(_tiny(float("nan")), tmp_path / "a.xodr")
    assert list(tmp_path.iterdir()) == []  # atomic: nothing written, no temporary left


def test_declaration_first_and_deterministic():
    data = to_bytes(_tiny())
    assert data.startswith(b'<?xml version="1.0" encoding="UTF-8"?>\n<OpenDRIVE>')
    assert data == to_bytes(_tiny())


def test_atomic_write_replaces_whole_file(tmp_path):
    target = tmp_path / "m.xodr"
    target.write_text("old")
    write(_tiny(), target)
    assert target.read_bytes() == to_bytes(_tiny())
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.xodr"]
    with pytest.raises(JunctionArtError, match="does not exist"):
        write(_tiny(), tmp_path / "missing" / "m.xodr")


@pytest.mark.parametrize("mask", [0o022, 0o027, 0o002])
def test_written_file_gets_the_mode_of_a_new_file_under_the_umask(tmp_path, mask):
    old = os.umask(mask)
    try:
        write(_tiny(), tmp_path / "m.xodr")
        (tmp_path / "plain.txt").write_text("x")  # what any new file gets
    finally:
        os.umask(old)
    mode = stat.S_IMODE((tmp_path / "m.xodr").stat().st_mode)
    assert mode == 0o666 & ~mask
    assert mode == stat.S_IMODE((tmp_path / "plain.txt").stat().st_mode)


@pytest.mark.parametrize("seed", [0, 1, 2])
@pytest.mark.parametrize("rule", [TrafficRule.RHT, TrafficRule.LHT])
def test_generated_maps_valid_against_both_schemas(seed, rule, schema18, schema17, tmp_path):
    doc = ja.generate(Params(randomize_lanes=True, curved_roads=True, traffic_rule=rule), seed)
    p18 = write(doc, tmp_path / "a.xodr", "1.8")
    errors = list(schema18.iter_errors(str(p18)))
    assert errors == [], errors[:3]
    p17 = write(doc, tmp_path / "b.xodr", "1.7")
    tree = etree.parse(str(p17))
    assert schema17.validate(tree), schema17.error_log
    assert tree.getroot().find("header").get("revMinor") == "7"
    assert etree.parse(str(p18)).getroot().find("header").get("revMinor") == "8"


@pytest.mark.parametrize("seed", [0, 1])
@pytest.mark.parametrize("rule", [TrafficRule.RHT, TrafficRule.LHT])
def test_generated_19_maps_valid_against_the_official_19_schema_and_clean(seed, rule, schema19, tmp_path):
    """--version 1.9: xmlschema (the slow, reference validator) on the official 1.9.0 XSD finds no error, xodrcheck
    no error or warning; the bytes are the 1.8 file's but for revMinor."""
    import xodrcheck

    doc = ja.generate(Params(randomize_lanes=True, curved_roads=True, traffic_rule=rule), seed)
    p19 = write(doc, tmp_path / "a.xodr", "1.9")
    errors = list(schema19.iter_errors(str(p19)))
    assert errors == [], errors[:3]
    assert etree.parse(str(p19)).getroot().find("header").get("revMinor") == "9"
    report = xodrcheck.check(p19, GENERATOR)
    assert [f for f in report.findings if f.severity.name in ("ERROR", "WARNING")] == []
    b18 = to_bytes(doc, "1.8")
    assert p19.read_bytes() == b18.replace(b'revMinor="8"', b'revMinor="9"', 1) != b18


def test_same_seed_same_bytes_other_seed_other_bytes(tmp_path):
    p = Params(randomize_lanes=True, curved_roads=True)
    a = write(ja.generate(p, 7), tmp_path / "a.xodr").read_bytes()
    b = write(ja.generate(p, 7), tmp_path / "b.xodr").read_bytes()
    c = write(ja.generate(p, 8), tmp_path / "c.xodr").read_bytes()
    assert a == b
    assert a != c


def test_written_numbers_read_back_to_the_model(tmp_path):
    doc = ja.generate(Params(randomize_lanes=True, curved_roads=True), 3)
    root = etree.fromstring(to_bytes(doc))
    for road, el in zip(doc.roads, root.iter("road")):
        assert float(el.get("length")) == road.length
        for g, ge in zip(road.geometry, el.find("planView")):
            assert (float(ge.get("x")), float(ge.get("y")), float(ge.get("hdg"))) == (g.x, g.y, g.hdg)


def test_text_is_escaped_and_reads_back():
    name = 'A & B <"quoted"> \ttab\nline é'
    doc = Document(Header(name=name, vendor="x>y"), _tiny().roads, ())
    root = etree.fromstring(to_bytes(doc), etree.XMLParser(resolve_entities=False, no_network=True))
    header = root.find("header")
    assert header.get("name") == name
    assert header.get("vendor") == "x>y"


def test_text_xml_cannot_hold_is_refused(tmp_path):
    doc = Document(Header(name="bell\x07"), _tiny().roads, ())
    with pytest.raises(JunctionArtError, match="XML does not allow"):
        write(doc, tmp_path / "a.xodr")
    assert list(tmp_path.iterdir()) == []


def test_text_layout_is_lxmls_pretty_print():
    """The directly built text is what lxml writes for the same tree (so any XML tool reads the same document)."""
    data = ja.to_bytes(ja.generate(Params(width=300.0, height=300.0, randomize_lanes=True), 2))
    tree = etree.fromstring(data, etree.XMLParser(resolve_entities=False, no_network=True, remove_blank_text=True))
    again = b'<?xml version="1.0" encoding="UTF-8"?>\n' + etree.tostring(tree, encoding="UTF-8", pretty_print=True)
    assert data == again


def test_a_direct_junction_names_its_type_and_linked_roads_and_a_default_one_neither():
    from junctionart.opendrive import Connection, Junction, LaneLink

    link = (LaneLink(-1, -1),)
    direct = Junction("9", "fork", (Connection("0", "1", "2", "start", link),), type="direct")
    default = Junction("8", "plain", (Connection("0", "1", "3", "start", link),))
    root = etree.fromstring(to_bytes(Document(Header(), _tiny().roads, (direct, default))))
    first, second = root.findall("junction")
    assert first.get("type") == "direct" and second.get("type") is None
    a, b = first.find("connection"), second.find("connection")
    assert a.get("linkedRoad") == "2" and a.get("connectingRoad") is None
    assert b.get("connectingRoad") == "3" and b.get("linkedRoad") is None
