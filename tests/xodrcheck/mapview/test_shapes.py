"""The map's shapes: lines are the exact lane geometry, the encoding round-trips to the centimetre."""

from __future__ import annotations

import base64

import numpy as np
import pytest

from xodrcheck.geometry.lanes import geometry_of
from xodrcheck.mapview.encode import encode, zigzag_varints
from xodrcheck.mapview.shapes import map_shapes
from xodrcheck.reader import read

TOWN01 = "carla-towns/OpenDrive/Town01.xodr"


def decode_varints(data: bytes) -> list[int]:
    """Reference decoder, written plainly (the page's decoder is JavaScript)."""
    out, value, shift = [], 0, 0
    for byte in data:
        value |= (byte & 127) << shift
        shift += 7
        if not byte & 128:
            out.append(value >> 1 if value % 2 == 0 else -((value + 1) >> 1))
            value, shift = 0, 0
    return out


def decode_sections(data: dict) -> list[tuple[np.ndarray, np.ndarray]]:
    """(s, lines) of every section record, undoing encode's differences."""
    values = iter(decode_varints(base64.b64decode(data["stream"])))
    out = []
    for _road, _index, s0, n, left, right, _marks in data["sections"]:
        s = s0 + np.cumsum([next(values) for _ in range(n)]) / 100
        count = 2 + len(left) // 2 + len(right) // 2
        along = np.array([next(values) for _ in range(count * 2 * n)], dtype=float).reshape(count, 2, n)
        across = np.cumsum(along, axis=2)
        lines = np.cumsum(across, axis=0).transpose(0, 2, 1) / 100 + np.array(data["origin"])
        out.append((s, lines))
    return out


@pytest.mark.parametrize("values", [[0], [1, -1, 63, -64, 64, -65], [2**31, -(2**31) - 1, 2**40, -(2**45)]])
def test_zigzag_varints_round_trip(values):
    assert decode_varints(zigzag_varints(np.array(values))) == values


def test_varints_of_nothing():
    assert zigzag_varints(np.zeros(0, dtype=np.int64)) == b""


@pytest.fixture(scope="module")
def town01(corpus_dir):
    document = read(corpus_dir / TOWN01).document
    return document, map_shapes(document)


def test_lines_are_the_lane_borders(town01):
    """Line 0 is the reference line, line 1 lane 0's, then each lane's outer border (left, then right, inside out)."""
    document, shapes = town01
    geometries = geometry_of(document)
    assert len(shapes.sections) > 100 and not shapes.skipped
    for sec in shapes.sections[::7]:
        rg = geometries[shapes.roads[sec.road][0]]
        pose = rg.reference(sec.s)
        np.testing.assert_allclose(sec.lines[0], np.column_stack([pose.x, pose.y]), atol=1e-9)
        ids = [0, *(i for i, _ in sec.left), *(i for i, _ in sec.right)]
        for k, lane_id in enumerate(ids, start=1):
            p = rg.lane_points(sec.index, lane_id, sec.s, "outer")
            np.testing.assert_allclose(sec.lines[k], np.column_stack([p.x, p.y]), atol=1e-9)
        assert all(lane_id > 0 for lane_id, _ in sec.left) and all(lane_id < 0 for lane_id, _ in sec.right)


def test_marks_start_on_samples(town01):
    document, shapes = town01
    marked = [(sec, m) for sec in shapes.sections for m in sec.marks]
    assert len(marked) > 100
    types = {m.type for _, m in marked}
    assert types == {"broken", "curb"}  # what Town01 has besides "none" (not drawn)
    by_key = {(shapes.roads[sec.road][0], sec.index): sec for sec in shapes.sections}
    for road in document.roads[:20]:
        for index, section in enumerate(road.lane_sections):
            sec = by_key[(road.id, index)]
            for lane in section.center:
                for mark in lane.road_marks:
                    if mark.type != "none":
                        assert np.isclose(sec.s, section.s + mark.s, atol=1e-9).any()


def test_encoding_round_trips_to_the_centimetre(town01):
    _, shapes = town01
    data = encode(shapes)
    decoded = decode_sections(data)
    assert len(decoded) == len(shapes.sections)
    for (s, lines), sec in zip(decoded, shapes.sections):
        assert np.abs(s - sec.s).max() <= 0.005 + 1e-9
        assert np.abs(lines - sec.lines).max() <= 0.005 + 1e-6


def test_encoded_map_is_small(town01, corpus_dir):
    """Far below the 3x size budget of the page: the Town01 map is under a tenth of its file."""
    import json

    size = len(json.dumps(encode(town01[1])))
    assert size < (corpus_dir / TOWN01).stat().st_size / 10


def _huge_width() -> bytes:
    return b"""<?xml version="1.0"?><OpenDRIVE><header revMajor="1" revMinor="7"/>
<road id="1" length="100" junction="-1"><planView><geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry>
</planView><lanes><laneSection s="0"><center><lane id="0" type="none"/></center><right>
<lane id="-1" type="driving"><width sOffset="0" a="1e308" b="1e308" c="0" d="0"/></lane></right></laneSection>
</lanes></road>
<road id="2" length="50" junction="-1"><planView><geometry s="0" x="0" y="10" hdg="0" length="50"><line/></geometry>
</planView><lanes><laneSection s="0"><center><lane id="0" type="none"/></center><right>
<lane id="-1" type="driving"><width sOffset="0" a="3" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road>
</OpenDRIVE>"""


def test_a_road_of_infinite_width_is_named_not_drawn():
    shapes = map_shapes(read(_huge_width()).document)
    assert shapes.skipped == ["1"]
    assert [shapes.roads[sec.road][0] for sec in shapes.sections] == ["2"]
