"""The reader's compiled fast path (``xodrcheck_speedups``, through :mod:`xodrcheck.reader.fast`) builds the same model
as the pure-Python reader: on every corpus file, on damaged documents, and on each unusual case it hands back to the
Python reader (which it must, since only that reports findings)."""

from __future__ import annotations

import contextlib
import os
import struct
import subprocess
import sys
import tracemalloc
import types
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from lxml import etree

import junctionart as ja
from junctionart.fuzz.documents import opendrive_documents
from junctionart.fuzz.mutations import damaged_documents
from junctionart.params import Params
from junctionart.writer import to_bytes
from tests.conftest import corpus_files
from xodrcheck.reader import fast, read
from xodrcheck.reader.context import REMEMBER, Numbers

FAST = (fast.plan_view, fast.profile, fast.lanes)


def test_the_compiled_path_is_on():
    """scripts/setup builds it; without it every other test here would compare the Python reader with itself."""
    assert fast.UNAVAILABLE == "", fast.UNAVAILABLE
    assert all(f is not None for f in FAST)


@contextlib.contextmanager
def pure_reader():
    saved = (fast.plan_view, fast.profile, fast.lanes)
    fast.plan_view = fast.profile = fast.lanes = None
    try:
        yield
    finally:
        fast.plan_view, fast.profile, fast.lanes = saved


def both(source):
    """read() with the compiled path, then without it."""
    compiled = read(source)
    with pure_reader():
        pure = read(source)
    return compiled, pure


def assert_same(source) -> None:
    compiled, pure = both(source)
    assert compiled.document == pure.document
    assert compiled.findings == pure.findings


@pytest.mark.parametrize("path", corpus_files(), ids=lambda p: p.name)
def test_corpus_files_read_the_same(path: Path, corpus_dir):
    assert_same(path)


def test_the_corpus_takes_the_fast_path(corpus_dir):
    """The point of it: a clean CARLA town is built by the compiled path, every road of it."""
    root = etree.parse(str(corpus_dir / "carla-towns" / "OpenDrive" / "Town01.xodr")).getroot()
    numbers = Numbers()
    roads = root.findall("road")
    assert len(roads) == 98
    for road in roads:
        assert fast.plan_view(road.find("planView"), numbers) is not None
        assert fast.profile(road.find("elevationProfile"), numbers, "elevation") is not None
        assert fast.lanes(road.find("lanes"), numbers, False) is not None


# ------------------------------------------------------------------------------------------------ unusual cases

ROAD = """<?xml version="1.0" encoding="UTF-8"?>
<OpenDRIVE>
  <header revMajor="1" revMinor="{minor}" name="fast" north="0" south="0" east="0" west="0"/>
  <road id="1" length="60" junction="-1">
    <planView>
      <geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry>
      <geometry s="10" x="10" y="0" hdg="0" length="10"><arc curvature="0.01"/></geometry>
      <geometry s="20" x="20" y="0.5" hdg="0.1" length="10"><spiral curvStart="0.01" curvEnd="-0.01"/></geometry>
      <geometry s="30" x="30" y="1" hdg="0.1" length="10"><poly3 a="0" b="0" c="0.001" d="0"/></geometry>
      <geometry s="40" x="40" y="1" hdg="0.1" length="20">
        <paramPoly3 aU="0" bU="20" cU="0" dU="0" aV="0" bV="0" cV="0.1" dV="0" pRange="arcLength"/>
      </geometry>
    </planView>
    <elevationProfile>
      <elevation s="0" a="1" b="0" c="0" d="0"/>
      <elevation s="30" a="1" b="0.01" c="0" d="0"/>
    </elevationProfile>
    <lateralProfile><superelevation s="0" a="0" b="0" c="0" d="0"/></lateralProfile>
    <lanes>
      <laneOffset s="0" a="0" b="0" c="0" d="0"/>
      <laneOffset s="20" a="0.1" b="0" c="0" d="0"/>
      <laneSection s="0">
        <left>
          <lane id="1" type="driving" level="false">
            <link><successor id="1"/></link>
            <width sOffset="0" a="3.5" b="0" c="0" d="0"/>
            <roadMark sOffset="0" type="solid" weight="standard" color="white" width="0.15" laneChange="none"/>
            <speed sOffset="0" max="13.9" unit="m/s"/>
          </lane>
        </left>
        <center><lane id="0" type="none"><roadMark sOffset="0" type="broken"/></lane></center>
        <right>
          <lane id="-1" type="driving" level="true">
            <link><predecessor id="-1"/><successor id="-1"/></link>
            <width sOffset="0" a="3.5" b="0" c="0" d="0"/>
            <width sOffset="10" a="3.5" b="0.01" c="0" d="0"/>
            <roadMark sOffset="0" type="solid"/>
            <height sOffset="0" inner="0.1" outer="0.1"/>
          </lane>
          <lane id="-2" type="sidewalk">
            <border sOffset="0" a="5" b="0" c="0" d="0"/>
            <userData><vectorLane/></userData>
          </lane>
        </right>
      </laneSection>
      <laneSection s="30" singleSide="false">
        <center><lane id="0" type="none"/></center>
        <right><lane id="-1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane></right>
      </laneSection>
    </lanes>
  </road>
</OpenDRIVE>
"""


def document(minor: int = 8, old: str = "", new: str = "", count: int = 1) -> bytes:
    text = ROAD.format(minor=minor)
    if old:
        assert old in text, old
        text = text.replace(old, new, count)
    return text.encode()


def fast_results(data: bytes, layered: bool = False) -> tuple:
    """What each compiled function makes of the road's parts (None: handed to the Python reader)."""
    road = etree.fromstring(data).find("road")
    numbers = Numbers()
    return (
        fast.plan_view(road.find("planView"), numbers),
        fast.profile(road.find("elevationProfile"), numbers, "elevation"),
        fast.lanes(road.find("lanes"), numbers, layered),
    )


def test_the_example_road_takes_the_fast_path_and_reads_the_same():
    data = document()
    plan_view, elevation, lanes = fast_results(data)
    assert [type(g).__name__ for g in plan_view] == ["Line", "Arc", "Spiral", "Poly3", "ParamPoly3"]
    assert [e.s for e in elevation] == [0.0, 30.0]
    offsets, sections = lanes
    assert [o.line for o in offsets] == [20, 21]
    assert [len(s.left) + len(s.center) + len(s.right) for s in sections] == [4, 2]
    result = read(data)
    assert result.findings == ()
    assert_same(data)


# (what to change in the example road, which part of it the compiled path hands back: 0 plan view, 1 elevation,
# 2 lanes)
HANDED_BACK = {
    "negative width sOffset": ('<width sOffset="0" a="3.5"', '<width sOffset="-1" a="3.5"', 2),
    "width not a number": ('a="3.5" b="0.01"', 'a="x3" b="0.01"', 2),
    "width NaN": ('a="3.5" b="0.01"', 'a="NaN" b="0.01"', 2),
    "width infinite": ('a="3.5" b="0.01"', 'a="1e999" b="0.01"', 2),
    "width missing a": ('<width sOffset="10" a="3.5" ', '<width sOffset="10" ', 2),
    "widths out of order": (
        '<width sOffset="10"',
        '<width sOffset="12" a="3" b="0" c="0" d="0"/><width sOffset="10"',
        2,
    ),
    "road mark without type": ('<roadMark sOffset="0" type="broken"/>', '<roadMark sOffset="0"/>', 2),
    "negative road mark width": ('width="0.15"', 'width="-0.15"', 2),
    "lane id with a plus": ('<lane id="1" type', '<lane id="+1" type', 2),
    "lane id not an integer": ('<lane id="-2"', '<lane id="-2.0"', 2),
    "lane id with spaces": ('<lane id="-2"', '<lane id=" -2 "', 2),
    "lane id of ten digits": ('<lane id="-2"', '<lane id="-1000000002"', 2),
    "lane type in capitals": ('<lane id="-2" type="sidewalk"', '<lane id="-2" type="Sidewalk"', 2),
    "unknown lane type": ('<lane id="-2" type="sidewalk"', '<lane id="-2" type="footpath"', 2),
    "lane without type": ('<lane id="-2" type="sidewalk"', '<lane id="-2"', 2),
    "level in capitals": ('level="true"', 'level="TRUE"', 2),
    "repeated lane link": ('<link><successor id="1"/></link>', '<link/><link><successor id="1"/></link>', 2),
    "lane link id not an integer": ('<successor id="1"/>', '<successor id="one"/>', 2),
    "singleSide in capitals": ('singleSide="false"', 'singleSide="False"', 2),
    "no centre lane 0": ('<center><lane id="0" type="none"/></center>', "<center/>", 2),
    "no centre": ('<center><lane id="0" type="none"/></center>', "", 2),
    "repeated side": (
        '<right><lane id="-1" type="driving"><width',
        '<right/><right><lane id="-1" type="driving"><width',
        2,
    ),
    "lane sections out of order": ('<laneSection s="30"', '<laneSection s="-30"', 2),
    "lane offsets out of order": ('<laneOffset s="20"', '<laneOffset s="-20"', 2),
    "geometry with two shapes": ("<line/>", "<line/><arc curvature='0.1'/>", 0),
    "geometry without shape": ("<line/>", "", 0),
    "geometry of negative length": ('hdg="0" length="10"><line/>', 'hdg="0" length="-10"><line/>', 0),
    "geometry without s": ('<geometry s="0" x="0"', '<geometry x="0"', 0),
    "arc without curvature": ('<arc curvature="0.01"/>', "<arc/>", 0),
    "spiral curvature not a number": ('curvEnd="-0.01"', 'curvEnd="-"', 0),
    "paramPoly3 without pRange": (' pRange="arcLength"', "", 0),
    "pRange in capitals": ('pRange="arcLength"', 'pRange="ArcLength"', 0),
    "unknown pRange": ('pRange="arcLength"', 'pRange="meters"', 0),
    "geometries out of order": ('<geometry s="40"', '<geometry s="5"', 0),
    "elevations out of order": ('<elevation s="30"', '<elevation s="-30"', 1),
    "attribute value with a character reference": ('<elevation s="30"', '<elevation s="3&#48;"', None),
}

#: Cases the Python reader reads without a finding (int() takes " -2 ", a name is matched without regard to case):
#: the compiled path leaves them to it all the same, being strict about what it reads itself.
READ_WITHOUT_FINDING = {
    "lane id with a plus",
    "lane id with spaces",
    "lane id of ten digits",
    "lane type in capitals",
    "level in capitals",
    "singleSide in capitals",
    "pRange in capitals",
    "attribute value with a character reference",
}


@pytest.mark.parametrize("case", sorted(HANDED_BACK))
def test_unusual_parts_are_handed_to_the_python_reader(case):
    old, new, part = HANDED_BACK[case]
    data = document(8, old, new)
    results = fast_results(data)
    for i, result in enumerate(results):
        if i == part:
            assert result is None, f"{case}: part {i} should go to the Python reader"
        elif part is not None:
            assert result is not None, f"{case}: part {i} should still take the fast path"
    assert_same(data)
    assert bool(read(data).findings) == (case not in READ_WITHOUT_FINDING), case


def test_a_road_without_lane_sections_is_the_python_readers():
    data = ROAD.format(minor=8)
    start, end = data.index("<laneSection"), data.index("</lanes>")
    data = (data[:start] + data[end:]).encode()
    assert fast_results(data)[2] is None
    assert_same(data)


def test_lane_layers_of_19_are_the_python_readers():
    """In a 1.9 file a lane link's ``layer`` and a section's ``length`` are read; a layer goes to Python."""
    data = document(9, '<successor id="1"/>', '<successor id="1" layer="temporary"/>')
    assert fast_results(data, layered=True)[2] is None
    assert fast_results(data, layered=False)[2] is not None  # before 1.9 the attribute is not read
    assert_same(data)
    with_length = document(9, 'singleSide="false"', 'singleSide="false" length="30"')
    sections = fast_results(with_length, layered=True)[2][1]
    assert sections[1].length == 30.0
    assert fast_results(with_length, layered=False)[2][1][1].length is None
    assert_same(with_length)


@pytest.mark.parametrize(
    "old, new",
    [
        ('<width sOffset="10"', '<!-- a comment --><width sOffset="10"'),
        ('<width sOffset="10"', '<x:width xmlns:x="urn:x" sOffset="0" a="9" b="0" c="0" d="0"/><width sOffset="10"'),
        ('<width sOffset="10" a="3.5"', '<width xmlns:x="urn:x" x:a="9" sOffset="10" a="3.5"'),
        ('<roadMark sOffset="0" type="solid"/>', '<roadMark sOffset="0" type="solid" color=""/>'),
        (
            '<width sOffset="10" a="3.5" b="0.01" c="0" d="0"/>',
            '<width d="0" c="0" b="0.01" a="3.5" sOffset="10" extra="1"/>',
        ),
    ],
    ids=["comment", "namespaced element", "namespaced attribute", "empty attribute", "attributes in another order"],
)
def test_what_both_readers_ignore_is_ignored_alike(old, new):
    data = document(8, old, new)
    assert all(result is not None for result in fast_results(data))
    assert_same(data)


def test_lines_past_65534_are_the_python_readers():
    """libxml2 keeps a line in 16 bits; past it lxml guesses from neighbours, so the compiled path hands it back."""
    padding = "\n" * 70000
    data = document(8, "<lanes>", "<lanes>" + padding)
    assert fast_results(data)[2] is None
    assert fast_results(data)[0] is not None
    assert_same(data)
    assert read(data).document.roads[0].lane_sections[0].line > 70000


def test_arguments_that_are_not_elements_are_the_python_readers():
    numbers = Numbers()
    assert fast.lanes(object(), numbers, False) is None
    assert fast.plan_view(etree.Comment("x"), numbers) is None
    with pytest.raises(TypeError):
        fast.profile(etree.Element("a"), numbers, 5)
    with pytest.raises(TypeError):
        fast.lanes(etree.Element("lanes"), [], False)


class _Forgetful(Numbers):
    """A number cache that could change the tree or the cache under the compiled walk: refused."""

    __slots__ = ()


@pytest.mark.parametrize("numbers", [{}, _Forgetful()], ids=["dict", "Numbers subclass"])
def test_numbers_must_be_the_readers_own_cache(numbers):
    lanes = etree.fromstring(document()).find("road/lanes")
    with pytest.raises(TypeError, match="Numbers"):
        fast.lanes(lanes, numbers, False)


def test_profile_tags_with_a_namespace_or_a_nul_are_the_python_readers():
    profile = etree.fromstring(
        b'<elevationProfile xmlns:x="urn:x"><x:elevation s="0" a="1" b="0" c="0" d="0"/>'
        b'<elev s="0" a="1" b="0" c="0" d="0"/></elevationProfile>'
    )
    assert fast.profile(profile, Numbers(), "{urn:x}elevation") is None
    assert fast.profile(profile, Numbers(), "elev\0ation") is None
    assert len(fast.profile(profile, Numbers(), "elev")) == 1


def test_configure_refuses_what_is_not_lxmls_element():
    import xodrcheck_speedups

    with pytest.raises(TypeError, match="_Element"):
        xodrcheck_speedups.configure(dict, Numbers, 10, make_cubic=None)
    assert fast.lanes(etree.fromstring(document()).find("road/lanes"), Numbers(), False) is not None  # unchanged


@pytest.mark.parametrize("spelling", ["offRamp", "HOV", "connectingRamp", "offramp"])
def test_lane_types_spelled_as_the_standard_does_take_the_fast_path(spelling):
    """The standard writes some types in camel case; the Python reader matches them without regard to case."""
    data = document(8, '<lane id="-2" type="sidewalk"', f'<lane id="-2" type="{spelling}"')
    sections = fast_results(data)[2][1]
    lane = sections[0].right[1]
    assert lane.type_name == spelling and lane.type.value.lower() == spelling.lower()
    assert_same(data)
    assert read(data).findings == ()


def test_no_memory_is_kept_by_the_compiled_path():
    """Each call's records (built or abandoned on the way to a hand-back) are freed with the result."""
    good = etree.fromstring(document()).find("road")
    bad = etree.fromstring(document(8, '<width sOffset="10"', '<width sOffset="-1"')).find("road")

    def calls():
        numbers = Numbers()
        for road in (good, bad):
            fast.plan_view(road.find("planView"), numbers)
            fast.lanes(road.find("lanes"), numbers, False)

    calls()
    tracemalloc.start()
    try:
        calls()
        before = tracemalloc.get_traced_memory()[0]
        for _ in range(300):
            calls()
        grown = tracemalloc.get_traced_memory()[0] - before
    finally:
        tracemalloc.stop()
    assert grown < 20_000, f"{grown} bytes kept after 300 calls"


def test_the_pure_reader_can_be_asked_for():
    code = "from xodrcheck.reader import fast; print(fast.lanes is None, fast.UNAVAILABLE)"
    env = {**os.environ, "XODRCHECK_PURE_READER": "1"}
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True).stdout
    assert out.strip() == "True XODRCHECK_PURE_READER=1 is set"


@settings(max_examples=150, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(damaged_documents(min_mutations=1, max_mutations=4))
def test_damaged_documents_read_the_same(data):
    assert_same(data)


def every_part_is_fast(data: bytes) -> None:
    """Every road's plan view and ``<lanes>`` of a valid document are built by the compiled path."""
    root = etree.fromstring(data)
    layered = root.find("header").get("revMinor") == "9"
    roads = root.findall("road")
    assert roads
    for road in roads:
        numbers = Numbers()
        assert fast.plan_view(road.find("planView"), numbers) is not None, road.get("id")
        assert fast.lanes(road.find("lanes"), numbers, layered) is not None, road.get("id")


@pytest.mark.parametrize("version", ["1.7", "1.8", "1.9"])
@pytest.mark.parametrize("seed", [1, 2])
def test_generated_maps_take_the_fast_path_and_read_the_same(seed, version):
    data = to_bytes(ja.generate(Params(), seed), version)
    every_part_is_fast(data)
    assert_same(data)


@settings(max_examples=60, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(opendrive_documents(versions=((1, 4), (1, 6), (1, 7), (1, 8), (1, 9))))
def test_valid_documents_take_the_fast_path_and_read_the_same(data):
    every_part_is_fast(data)
    assert_same(data)


_V19 = opendrive_documents(versions=((1, 9),), max_roads_per_chain=2, max_elements=2, max_lanes=2)


@settings(max_examples=100, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(damaged_documents(base=_V19, min_mutations=1, max_mutations=4))
def test_damaged_19_documents_read_the_same(data):
    """1.9 files have lane layers, which the compiled path leaves to Python."""
    assert_same(data)


NUMBER_TEXTS = [
    "3.5",
    "+3.5",
    "-0",
    "-0.0",
    ".5",
    "5.",
    "1E5",
    "1e-400",
    "4.9406564584124654e-324",
    "1.7976931348623157e308",
    "1.7976931348623159e308",
    "3.5000000000000000e+0",
    "0.1",
    "1_0",
    " 3.5",
    "3.5 ",
    "0x10",
    "inf",
    "-Infinity",
    "nan",
    "1e",
    "",
    "٣",
]


@pytest.mark.parametrize("raw", NUMBER_TEXTS)
def test_numbers_are_the_floats_python_reads(raw):
    """The compiled path parses a plain float itself (PyOS_string_to_double, as float() does) and leaves anything
    else (whitespace, underscores, non-finite, not a number) to the cache's own __missing__."""
    data = document(8, '<width sOffset="10" a="3.5"', f'<width sOffset="10" a="{raw}"')
    lanes = fast_results(data)[2]
    try:
        expected = float(raw)
    except ValueError:
        expected = None
    if expected is None or expected - expected != 0.0:
        assert lanes is None  # a finding: the Python reader's
    else:
        width = lanes[1][0].right[0].widths[1]
        assert struct.pack("<d", width.a) == struct.pack("<d", expected)
    assert_same(data)


def test_a_full_number_cache_is_not_grown():
    numbers = Numbers({str(i): float(i) for i in range(REMEMBER)})
    road = etree.fromstring(document()).find("road")
    assert fast.lanes(road.find("lanes"), numbers, False) is not None
    assert fast.plan_view(road.find("planView"), numbers) is not None
    assert len(numbers) == REMEMBER
    smaller = Numbers()
    fast.lanes(road.find("lanes"), smaller, False)
    assert "3.5" in smaller and 0 < len(smaller) < 20


class _Misfit:
    """A compiled module built for another lxml: configure refuses, or its nodes are not where it looks."""

    CONTRACT = fast.CONTRACT

    def __init__(self, refuses: bool) -> None:
        self.refuses = refuses

    def configure(self, *args, **parts):
        if self.refuses:
            raise TypeError("configure(): element_type is not lxml.etree._Element")

    def node_line(self, el):
        return ("b", 2)


@pytest.mark.parametrize(
    "refuses, reason", [(True, "does not fit this installation"), (False, "built for another lxml")]
)
def test_a_module_that_does_not_fit_is_left_off(monkeypatch, refuses, reason):
    monkeypatch.setitem(sys.modules, "xodrcheck_speedups", _Misfit(refuses))
    before = (fast.plan_view, fast.profile, fast.lanes)
    assert reason in fast._load()
    assert (fast.plan_view, fast.profile, fast.lanes) == before  # the working module stays in use


@pytest.mark.parametrize("contract", [None, fast.CONTRACT + 1])
def test_a_module_of_another_contract_is_left_off(monkeypatch, contract):
    """A module built from other sources (an older checkout) is not trusted, even if it would configure."""
    module = types.SimpleNamespace(configure=lambda *args, **parts: None, node_line=lambda el: ("a", 1))
    if contract is not None:
        module.CONTRACT = contract
    monkeypatch.setitem(sys.modules, "xodrcheck_speedups", module)
    assert f"contract {contract if contract is not None else 'none'}, this reader needs" in fast._load()


def test_the_installed_module_is_of_this_readers_contract():
    import xodrcheck_speedups

    assert xodrcheck_speedups.CONTRACT == fast.CONTRACT
