"""Shapes of lane strips: turns, pieces and lane sections known to overlap nowhere (xodrcheck.mesh.strip_shapes)."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from tests.xodrcheck.rules.helpers import fixture
from xodrcheck.mesh import strip_shapes
from xodrcheck.mesh.surfaces import surfaces_of
from xodrcheck.reader import read


def _document(element: str, lanes: str, length: float = 100.0):
    text = f"""<?xml version="1.0" encoding="UTF-8"?>
<OpenDRIVE><header revMajor="1" revMinor="7"/>
<road id="1" length="{length}" junction="-1"><planView>
<geometry s="0" x="0" y="0" hdg="0" length="{length}">{element}</geometry></planView>
<lanes><laneSection s="0">{lanes}</laneSection></lanes></road></OpenDRIVE>"""
    return read(text.encode()).document


def _lane(lane_id: int, width: str = "3.5") -> str:
    return f'<lane id="{lane_id}" type="driving"><width sOffset="0" a="{width}" b="0" c="0" d="0"/></lane>'


_BOTH = f"<left>{_lane(2)}{_lane(1)}</left><center><lane id='0' type='none'/></center><right>{_lane(-1)}</right>"


def test_turns_of_a_circle_and_a_line():
    angle = np.linspace(0.0, 6 * np.pi, 600)
    assert strip_shapes.turns(np.column_stack([np.cos(angle), np.sin(angle)])) == pytest.approx(3.0, abs=0.01)
    assert strip_shapes.turns(np.column_stack([np.arange(5.0), np.zeros(5)])) == 0.0


def test_the_strips_of_a_plain_section_overlap_nowhere():
    surfaces = surfaces_of(_document('<arc curvature="0.01"/>', _BOTH))
    assert strip_shapes.tiled_sections(surfaces).tolist() == [0, 0, 0]


@pytest.mark.parametrize(
    ("element", "lanes"),
    [
        ('<arc curvature="0.07"/>', _BOTH),  # 1.1 turns of radius 14 m: the road runs over its start
        ('<arc curvature="0.5"/>', _BOTH),  # the left lanes lie past the centre of curvature: they fold
        ("<line/>", f"<center><lane id='0' type='none'/></center><right>{_lane(-1)}{_lane(-2, '-1')}</right>"),
    ],
    ids=["loop", "fold", "negative-width"],
)
def test_a_section_that_may_overlap_itself_is_not_judged(element, lanes):
    surfaces = surfaces_of(_document(element, lanes))
    assert (strip_shapes.tiled_sections(surfaces) == -1).all()


def test_two_sections_are_judged_apart():
    surfaces = surfaces_of(read(fixture("road-self-overlap", "fail.xodr")).document)
    tiled = strip_shapes.tiled_sections(surfaces)
    sections = [k.section_s for k in surfaces.lanes]
    assert sections == [0.0, 0.0, 70.0, 70.0] and tiled.tolist() == [0, 0, 2, 2]


def test_pieces_unite_to_the_triangles_union():
    """A lane folded on the inside of a tight curve: its pieces' union is its triangles' union, from far fewer
    polygons."""
    surfaces = surfaces_of(_document('<arc curvature="0.5"/>', _BOTH, length=40.0))
    lane = [k.lane for k in surfaces.lanes].index(2)
    first, stop = surfaces.lane_faces[lane], surfaces.lane_faces[lane + 1]
    tris = surfaces.vertices[surfaces.faces[first:stop]][..., :2]
    triangles = shapely.polygons(np.concatenate([tris, tris[:, :1]], axis=1))
    expected = shapely.union_all(triangles[shapely.area(triangles) > 0])
    pieces = strip_shapes.pieces(surfaces, lane)
    assert len(pieces) < len(triangles) / 4
    assert shapely.is_valid(pieces).all()
    united = shapely.union_all(pieces)
    assert shapely.area(shapely.symmetric_difference(united, expected)) < 1e-6 * shapely.area(expected)


def test_strip_turns_are_each_strips_turns():
    surfaces = surfaces_of(read(fixture("lane-fold", "fail-winding-generated.xodr")).document)
    expected = [strip_shapes.turns(surfaces.rows(i)[0][:, :2]) for i in range(len(surfaces))]
    assert strip_shapes.strip_turns(surfaces) == pytest.approx(expected, abs=1e-9)
    assert max(expected) > 35


def test_covers_twice():
    wound = surfaces_of(_document('<arc curvature="1.0"/>', _BOTH, length=100.0))
    plain = surfaces_of(_document('<arc curvature="0.01"/>', _BOTH))
    lanes = np.arange(3)
    assert strip_shapes.covers_twice(wound, lanes).all() and not strip_shapes.covers_twice(plain, lanes).any()
