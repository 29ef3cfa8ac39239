"""Lane meshes: areas against closed forms, faces knowing their lanes, and ``xodrcheck mesh`` output."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import shapely
import trimesh
from scipy.integrate import quad

from tests.xodrcheck.roadbuild import lane, section, width
from xodrcheck.cli import main
from xodrcheck.mesh.export import COLOURS, vertex_colours
from xodrcheck.mesh.surfaces import build_surfaces
from xodrcheck.model import (
    Arc,
    Cubic,
    Document,
    Header,
    LaneKey,
    Line,
    ParamPoly3,
    PRange,
    Road,
    Spiral,
)

#: Relative area error allowed by the acceptance criterion.
AREA_REL = 1e-3
W_LEFT, W_RIGHT = 3.5, 3.0


def document(geometry, length, lanes=None, **road) -> Document:
    lanes = lanes or section(0.0, left=[lane(1, width(W_LEFT))], right=[lane(-1, width(W_RIGHT))])
    return Document(
        Header(1, 7), roads=(Road(id="r", length=length, plan_view=(geometry,), lane_sections=(lanes,), **road),)
    )


def strip_area(width_: float, t_inner: float, t_outer: float, length: float, turn: float) -> float:
    """Plan-view area between two offset curves at lateral ``t_inner``/``t_outer`` of a curve of ``length`` whose
    heading turns by ``turn``: the integral of ``(t2 - t1)(1 - k (t1 + t2)/2) ds`` (no fold)."""
    t1, t2 = sorted((t_inner, t_outer))
    assert t2 - t1 == pytest.approx(width_)
    return (t2 - t1) * length - (t2**2 - t1**2) / 2 * turn


def expected(length: float, turn: float) -> dict[int, float]:
    return {1: strip_area(W_LEFT, 0, W_LEFT, length, turn), -1: strip_area(W_RIGHT, 0, -W_RIGHT, length, turn)}


def lane_areas(doc: Document, chord: float = 0.01) -> dict[int, float]:
    surfaces = build_surfaces(doc, chord=chord)
    return {key.lane: float(a) for key, a in zip(surfaces.lanes, surfaces.lane_areas())}


def assert_areas(doc: Document, want: dict[int, float]) -> None:
    got = lane_areas(doc)
    assert set(got) == set(want)
    for lane_id, area in want.items():
        assert got[lane_id] == pytest.approx(area, rel=AREA_REL), lane_id


def _param_poly3() -> tuple[ParamPoly3, float, float]:
    """A paramPoly3 (normalised p) with its arc length and heading change, computed here independently."""
    u, v = np.array([0.0, 60.0, 0.0, 0.0]), np.array([0.0, 0.0, 40.0, -12.0])
    du, dv = np.polynomial.polynomial.polyder(u), np.polynomial.polynomial.polyder(v)

    def speed(p):
        return math.hypot(np.polynomial.polynomial.polyval(p, du), np.polynomial.polynomial.polyval(p, dv))

    length = quad(speed, 0.0, 1.0, epsabs=1e-12, epsrel=1e-12)[0]

    def heading(p):
        return math.atan2(np.polynomial.polynomial.polyval(p, dv), np.polynomial.polynomial.polyval(p, du))

    g = ParamPoly3(0.0, 5.0, -3.0, 0.4, length, *u, *v, p_range=PRange.NORMALIZED)
    return g, length, heading(1.0) - heading(0.0)


def test_straight_road_area():
    assert_areas(document(Line(0.0, 0.0, 0.0, 0.3, 120.0), 120.0), expected(120.0, 0.0))


def test_arc_road_area():
    assert_areas(document(Arc(0.0, 0.0, 0.0, 0.0, 100.0, 0.02), 100.0), expected(100.0, 0.02 * 100.0))


def test_tight_arc_area_is_still_within_tolerance():
    assert_areas(document(Arc(0.0, 0.0, 0.0, 0.0, 30.0, -0.1), 30.0), expected(30.0, -0.1 * 30.0))


def test_spiral_road_area():
    g = Spiral(0.0, 1.0, 2.0, -0.5, 80.0, 0.0, 0.05)
    assert_areas(document(g, 80.0), expected(80.0, (0.0 + 0.05) / 2 * 80.0))


def test_param_poly3_road_area():
    g, length, turn = _param_poly3()
    assert abs(turn) > 0.5  # a real bend, not a straight line in disguise
    assert_areas(document(g, length), expected(length, turn))


def test_widening_lane_area():
    lanes = section(0.0, right=[lane(-1, width(0.0, 4.0 / 100.0))])  # 0 m to 4 m over 100 m
    assert lane_areas(document(Line(0.0, 0.0, 0.0, 0.0, 100.0), 100.0, lanes))[-1] == pytest.approx(200.0, rel=1e-9)


def test_slope_and_superelevation_are_applied():
    line = Line(0.0, 0.0, 0.0, 0.0, 100.0)
    sloped = document(line, 100.0, elevation=(Cubic(0.0, 2.0, 0.1, 0.0, 0.0),))
    assert_areas(sloped, {k: a * math.sqrt(1.01) for k, a in expected(100.0, 0.0).items()})
    rolled = document(line, 100.0, superelevation=(Cubic(0.0, 0.2, 0.0, 0.0, 0.0),))
    assert_areas(rolled, expected(100.0, 0.0))  # widths are measured in the rolled plane
    surfaces = build_surfaces(rolled)
    plan = np.abs(surfaces.plan_areas).sum()
    assert plan == pytest.approx((W_LEFT + W_RIGHT) * 100.0 * math.cos(0.2), rel=1e-9)
    inner, outer = surfaces.rows(surfaces.lanes.index(LaneKey("r", 0.0, 1)))
    assert outer[:, 2] == pytest.approx(W_LEFT * math.sin(0.2))  # the left side is lifted
    assert inner[:, 2] == pytest.approx(0.0, abs=1e-12)


def test_faces_know_their_lane_and_face_up():
    g, length, _ = _param_poly3()
    surfaces = build_surfaces(document(g, length), chord=0.05)
    assert surfaces.lanes == (LaneKey("r", 0.0, 1), LaneKey("r", 0.0, -1))
    assert surfaces.lane_types == ("driving", "driving")
    assert len(surfaces.face_lane) == len(surfaces.faces) == surfaces.lane_faces[-1]
    assert (surfaces.plan_areas > 0).all()  # counter-clockwise seen from above, both sides
    for index in range(2):
        faces = surfaces.faces[surfaces.face_lane == index]
        lo, hi = surfaces.lane_vertices[index], surfaces.lane_vertices[index + 1]
        assert faces.min() >= lo and faces.max() < hi  # every face of a lane uses that lane's vertices only
    assert np.all(np.diff(surfaces.face_s[surfaces.face_lane == 0][::2]) > 0)  # faces follow s
    # the lane's plan-view outline (inner row, outer row reversed) encloses exactly the faces' plan area
    order, owner = surfaces.outline_order()
    polygons = shapely.polygons(shapely.linearrings(surfaces.vertices[order, :2], indices=owner))
    for index, polygon in enumerate(polygons):
        assert polygon.is_valid
        assert polygon.area == pytest.approx(surfaces.plan_areas[surfaces.face_lane == index].sum(), rel=1e-9)


def test_adaptive_sampling_follows_the_chord():
    doc = document(Arc(0.0, 0.0, 0.0, 0.0, 100.0, 0.05), 100.0)
    coarse, fine = build_surfaces(doc, chord=0.1), build_surfaces(doc, chord=0.001)
    assert len(fine.faces) > 5 * len(coarse.faces)
    exact = sum(expected(100.0, 5.0).values())
    assert abs(fine.area() - exact) < abs(coarse.area() - exact)


def test_lane_type_filter_and_select():
    lanes = section(0.0, left=[lane(1, width(3.0))], right=[lane(-1, width(3.0))])
    doc = document(Line(0.0, 0.0, 0.0, 0.0, 50.0), 50.0, lanes)
    assert len(build_surfaces(doc, lane_types=("sidewalk",)).faces) == 0
    both = build_surfaces(doc)
    right = both.select(np.array([k.lane < 0 for k in both.lanes]))
    assert right.lanes == (LaneKey("r", 0.0, -1),)
    assert right.area() == pytest.approx(150.0)
    assert right.faces.max() < len(right.vertices) and (right.face_lane == 0).all()


def test_mesh_is_a_trimesh_with_the_same_faces():
    surfaces = build_surfaces(document(Arc(0.0, 0.0, 0.0, 0.0, 60.0, 0.03), 60.0))
    mesh = surfaces.to_trimesh()
    assert len(mesh.faces) == len(surfaces.faces)
    assert mesh.area == pytest.approx(surfaces.area())
    assert (mesh.face_normals[:, 2] > 0.99).all()
    colours = vertex_colours(surfaces)
    assert (colours == COLOURS["driving"]).all()


# ---------------------------------------------------------------------------------------------------------- CLI
MAP = Path(__file__).parents[1] / "rules" / "fixtures" / "connection-overlap" / "pass.xodr"


@pytest.fixture(scope="module")
def map_area() -> float:
    from xodrcheck.reader import read

    return build_surfaces(read(MAP).document, chord=0.05).area()


def test_cli_writes_glb_with_one_named_mesh_per_lane_type(tmp_path, map_area):
    out = tmp_path / "map.glb"
    assert main(["mesh", str(MAP), "-o", str(out), "--chord", "0.05"]) == 0
    scene = trimesh.load(out)
    assert list(scene.geometry) == ["driving"]
    mesh = scene.geometry["driving"]
    assert mesh.area == pytest.approx(map_area, rel=1e-5)  # float32 in the file
    assert np.ptp(mesh.vertices[:, 1]) < 1e-3 < np.ptp(mesh.vertices[:, 2])  # y-up: the flat map lies in x-z


@pytest.mark.parametrize("suffix", [".obj", ".ply"])
def test_cli_writes_obj_and_ply(tmp_path, suffix, map_area):
    out = tmp_path / f"map{suffix}"
    assert main(["mesh", str(MAP), "-o", str(out), "--chord", "0.05"]) == 0
    mesh = trimesh.load(out, process=False)
    assert mesh.area == pytest.approx(map_area, rel=1e-5)
    assert mesh.visual.kind == "vertex"


def test_cli_lane_types(tmp_path):
    out = tmp_path / "none.ply"
    assert main(["mesh", str(MAP), "-o", str(out), "--lane-types", "sidewalk"]) == 1  # nothing to mesh
    assert not out.exists()
    with pytest.raises(SystemExit) as exit_:
        main(["mesh", str(MAP), "-o", str(out), "--lane-types", "drivng"])
    assert exit_.value.code == 2


def test_cli_unknown_extension_and_unwritable_output(tmp_path, capsys):
    out = tmp_path / "map.stl"
    assert main(["mesh", str(MAP), "-o", str(out)]) == 2
    assert "unknown mesh format '.stl'" in capsys.readouterr().err
    assert not out.exists()
    assert main(["mesh", str(MAP), "-o", str(tmp_path / "missing" / "map.glb")]) == 2
    assert "cannot write" in capsys.readouterr().err
    assert main(["mesh", str(tmp_path / "absent.xodr"), "-o", str(tmp_path / "map.glb")]) == 2
    assert list(tmp_path.iterdir()) == []  # no partial or temporary file left


def test_derived_caches_die_with_their_document():
    """Geometry, mesh and overlap index are cached with the document, not in module dicts keyed by id(document):
    the overlap index refers back to its document, and the module cache kept every measured map alive (the ERA run
    grew by ~55 MB a map, 4 GB over 10,000 intersections)."""
    import gc
    import weakref

    from tests.xodrcheck.rules.helpers import fixture
    from xodrcheck.geometry.lanes import geometry_of
    from xodrcheck.mesh.footprint import overlap_index
    from xodrcheck.mesh.surfaces import surfaces_of
    from xodrcheck.reader import read

    document = read(fixture("road-overlap", "fail.xodr")).document
    index = overlap_index(document)
    assert overlap_index(document) is index and surfaces_of(document) is index.surfaces
    assert geometry_of(document) is geometry_of(document)
    assert len(index.surfaces) > 0
    alive = weakref.ref(document)
    del document, index
    gc.collect()
    assert alive() is None


def test_meshing_leaves_no_road_geometry_cached_with_the_document():
    """The mesh evaluates its roads with geometry of its own, dropped run by run: a big map's mesh does not keep every
    road's evaluated geometry alive beside it (nor is a geometry the rules cached replaced)."""
    from xodrcheck.geometry.lanes import geometry_of
    from xodrcheck.model import document_cache

    doc = document(Line(0.0, 0.0, 0.0, 0.0, 50.0), 50.0)
    assert len(build_surfaces(doc, chord=0.05).lanes) == 2
    assert "geometry" not in document_cache(doc)
    cached = geometry_of(doc)
    cached["r"]  # a rule evaluated the road
    build_surfaces(doc, chord=0.05)
    assert document_cache(doc)["geometry"] is cached and cached.built() == ["r"]
