"""Many lane sections evaluated together (:mod:`xodrcheck.geometry.batch`, :mod:`xodrcheck.geometry.sampling`) give
each section's own numbers (the per-road API, a batch of one) to the last bit: samples, border lines, lane lines and
meshes, on corpus maps (superelevation and a duplicated lane id included) and on generated and damaged documents."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings

from junctionart.fuzz.documents import opendrive_documents
from junctionart.fuzz.mutations import damaged_documents
from tests.conftest import corpus_root
from xodrcheck.check import Selection, run_rules
from xodrcheck.config import Config
from xodrcheck.geometry.batch import Evaluation, centre_lines
from xodrcheck.geometry.lanes import RoadGeometry, geometry_of, road_geometry
from xodrcheck.geometry.lines import tightest
from xodrcheck.geometry.sampling import sample_sections
from xodrcheck.mesh.surfaces import MAX_COORDINATE, build_surfaces
from xodrcheck.model import LaneKey
from xodrcheck.reader import read
from xodrcheck.rules import curvature, junction_geometry
from xodrcheck.rules.shared import sampled
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.grids import section_grids
from xodrcheck.support import arrays

CHORD, MAX_STEP, BUDGET = 0.01, 5.0, 200_000
#: Corpus maps with many sections, lane offsets, multi-record widths, border records, spirals and paramPoly3.
CORPUS = (
    "carla-towns/OpenDrive/Town07.xodr",
    "carla-towns/OpenDrive/Town03.xodr",
    "esmini/resources/xodr/fabriksgatan.xodr",
    "esmini/resources/xodr/multi_intersections.xodr",
    "esmini/EnvironmentSimulator/Unittest/xodr/lane_width_and_offset.xodr",
    "ika-roadgeneration/test/gt/junction_m2a.xodr",
    "scenariogeneration-examples/road_with_multiple_lane_widths0.xodr",
)
_POINTS = ("x", "y", "z", "hdg", "curvature", "speed")


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    return a.shape == b.shape and a.tobytes() == b.tobytes()


def _sections(document) -> list[tuple[RoadGeometry, int]]:
    geometries = geometry_of(document)
    out = []
    for road in document.roads:
        rg = geometries[road.id]
        if road.plan_view and rg.road is road:
            out.extend((rg, i) for i in range(len(road.lane_sections)))
    return out


def _assert_samples_and_lines(document) -> int:
    entries = _sections(document)
    samples = sample_sections([(rg.rows(i), rg.knots(i)) for rg, i in entries], CHORD, MAX_STEP, BUDGET)
    for (rg, i), s in zip(entries, samples):
        assert _same(s, rg.sample_s(i, chord=CHORD, max_step=MAX_STEP, budget=BUDGET)), (rg.road.id, i)
    evaluation = Evaluation([rg.rows(i) for rg, i in entries], samples)
    for k, ((rg, i), s, lines) in enumerate(zip(entries, samples, evaluation.border_points())):
        curves = rg.border_curves(i, s)
        assert list(lines) == list(curves)
        for lane_id, p in curves.items():
            assert all(_same(getattr(lines[lane_id], n), getattr(p, n)) for n in _POINTS), (rg.road.id, i, lane_id)
        alone = rg.borders(i, s)
        together = evaluation.borders(k)
        assert list(together) == list(alone) and all(_same(together[j], alone[j]) for j in alone)
        assert _same(evaluation.pose.curvature[evaluation.block(k)], rg.reference(s).curvature)
    _assert_lane_lines(entries, samples, evaluation)
    return len(entries)


def _assert_lane_lines(entries, samples, evaluation: Evaluation) -> None:
    """Every lane's centre, inner and outer line, raised or not, asked for together: lane_points lane by lane."""
    wanted = [(k, lane_id) for k, (rg, i) in enumerate(entries) for lane_id in rg.rows(i).first]
    for where in ("centre", "inner", "outer"):
        for raised in (False, True):
            lines = evaluation.lines([(k, lane_id, where, raised) for k, lane_id in wanted])
            together = lines.points()
            for j, (k, lane_id) in enumerate(wanted):
                rg, i = entries[k]
                alone = rg.lane_points(i, lane_id, samples[k], where, raised)
                part = together.part(int(lines.starts[j]), int(lines.starts[j + 1]))
                assert all(_same(getattr(part, n), getattr(alone, n)) for n in _POINTS), (rg.road.id, i, lane_id)


def _assert_mesh_is_each_sections_own(document, chord: float) -> None:
    """The mesh's strips are the border rows of each section sampled and evaluated alone, in document order; a section
    whose rows are not finite or lie beyond MAX_COORDINATE has none."""
    surfaces = build_surfaces(document, chord=chord)
    geometries = geometry_of(document)
    keys, rows = [], []
    for road in document.roads:
        if not road.plan_view:
            continue
        rg = road_geometry(geometries, road)
        for i, section in enumerate(road.lane_sections):
            if not road.section_end(i) > section.s:
                continue
            s = rg.sample_s(i, chord=chord, max_step=MAX_STEP)
            if len(s) < 2:
                continue
            curves = rg.border_curves(i, s)
            xyz = {k: np.column_stack([p.x, p.y, p.z]) for k, p in curves.items()}
            if not all((np.abs(v) <= MAX_COORDINATE).all() for v in xyz.values()):
                continue
            for side in rg.side_lanes(i):
                inner = 0
                for lane in side.lanes:
                    keys.append(LaneKey(road.id, section.s, lane.id))
                    rows.append((xyz[inner], xyz[lane.id], s))
                    inner = lane.id
    assert surfaces.lanes == tuple(keys)
    for k, (inner, outer, s) in enumerate(rows):
        got_inner, got_outer = surfaces.rows(k)
        assert _same(got_inner, inner) and _same(got_outer, outer), surfaces.lanes[k]
        faces = slice(int(surfaces.lane_faces[k]), int(surfaces.lane_faces[k + 1]))
        assert _same(surfaces.face_s[faces], np.repeat(s[:-1], 2))


@pytest.mark.corpus
@pytest.mark.parametrize("name", CORPUS)
def test_corpus_sections_in_one_batch_are_each_sections_own_numbers(corpus_dir: Path, name: str):
    document = read(corpus_dir / name).document
    assert _assert_samples_and_lines(document) > 0
    _assert_mesh_is_each_sections_own(document, 0.1)


def test_superelevation_duplicate_lane_ids_and_lane_heights_in_one_batch():
    """Rolled roads, a lane id given twice and lanes with <height> are evaluated in the same batch as plain roads."""
    from tests.xodrcheck.rules.helpers import fixture

    for path in (
        fixture("duplicate-lane-id", "fail.xodr"),
        corpus_root() / "esmini/EnvironmentSimulator/Unittest/xodr/tilted_crest.xodr",
        corpus_root() / "esmini/EnvironmentSimulator/Unittest/xodr/two_pitched_and_rolled_roads.xodr",
    ):
        document = read(path).document
        rows = [rg.rows(i) for rg, i in _sections(document)]
        assert any(r.roll is not None or r.view is not None for r in rows), path
        with np.errstate(all="ignore"):
            assert _assert_samples_and_lines(document) > 0
            _assert_mesh_is_each_sections_own(document, 0.05)


@pytest.mark.corpus
def test_checker_grid_lines_in_one_pass(corpus_dir: Path):
    path = corpus_dir / "carla-towns/OpenDrive/Town07.xodr"
    document = read(path).document
    ctx = Context(document, Config(), path=str(path), data=None, deadline=time.monotonic() + 1e9)
    together = sampled.SectionCache(ctx).evaluate_all()
    assert len(together) > 700
    for (road_id, i), got in list(together.items())[::7]:
        rg = ctx.geometry(road_id)
        s = section_grids(ctx.tolerances, [(rg, i)], sampled.grid_step(ctx.tolerances))[0]
        assert _same(got.s, s) and _same(got.curvature, rg.reference(s).curvature)
        curves = rg.border_curves(i, s)
        for lane_id, p in curves.items():
            assert all(_same(getattr(got.borders[lane_id], n), getattr(p, n)) for n in ("x", "y", "z", "hdg"))


@pytest.mark.corpus
def test_checker_grid_lines_in_batches_are_the_one_pass_numbers(corpus_dir: Path, monkeypatch: pytest.MonkeyPatch):
    """Bounded memory: the sections are evaluated in batches of samples; any batch size gives the same numbers."""
    path = corpus_dir / "carla-towns/OpenDrive/Town07.xodr"
    document = read(path).document

    def lines(batch: int) -> dict:
        monkeypatch.setattr(sampled, "BATCH_SAMPLES", batch)
        return sampled.SectionCache(Context(document, Config(), path=str(path), data=None)).evaluate_all()

    whole, batched = lines(1 << 40), lines(1000)
    assert len(arrays.batches([len(v.s) for v in whole.values()], 1000)) > 5
    assert whole.keys() == batched.keys() and len(whole) > 700
    for key, one in whole.items():
        other = batched[key]
        assert np.array_equal(one.s, other.s) and one.t.keys() == other.t.keys()
        for lane_id, p in one.borders.items():
            q = other.borders[lane_id]
            assert np.array_equal(one.t[lane_id], other.t[lane_id])
            assert all(np.array_equal(getattr(p, n), getattr(q, n)) for n in ("x", "y", "z", "hdg", "curvature"))


def test_batches_cover_every_count_once_within_the_limit():
    counts = [5, 3, 9, 1, 1, 12, 2]
    ranges = arrays.batches(counts, 8)
    assert [i for lo, hi in ranges for i in range(lo, hi)] == list(range(len(counts)))
    assert all(sum(counts[lo:hi]) <= 8 or hi - lo == 1 for lo, hi in ranges)
    assert ranges == [(0, 2), (2, 3), (3, 5), (5, 6), (6, 7)]
    assert arrays.batches([], 8) == []


_CENTRE_FILES = [
    "carla-towns/OpenDrive/Town01.xodr",
    "carla-towns/OpenDrive/Town03.xodr",
    "esmini/resources/xodr/fabriksgatan.xodr",
    "esmini/EnvironmentSimulator/Unittest/xodr/multi_lane_3way_intersection.xodr",
    "esmini/EnvironmentSimulator/Unittest/xodr/two_pitched_and_rolled_roads.xodr",
]


def _context(path: Path) -> Context:
    return Context(read(path).document, Config(), path=str(path), data=None)


@pytest.mark.corpus
@pytest.mark.parametrize("name", _CENTRE_FILES)
def test_centre_lines_in_batches_are_each_lanes_own(corpus_dir: Path, name: str):
    """The centre lines C001 and J101 evaluate together (centre_lines, in batches of pairs) are lane_points lane by
    lane: curvature, speed and plan-view points."""
    ctx = _context(corpus_dir / name)
    entries, grids, wanted = [], [], []
    with np.errstate(all="ignore"):
        for road in ctx.document.roads:
            geometry = ctx.usable_geometry(road)
            for index in range(len(road.lane_sections)) if geometry is not None else ():
                entries.append((geometry, index))
                grids.append(sampled.section_samples(ctx, road, index))
                wanted.append(sorted(geometry.placed_lane_ids(index), reverse=True))
        limit = sum(len(s) * len(w) for s, w in zip(grids, wanted)) // 3  # three batches or more
        batches = list(centre_lines([g.rows(i) for g, i in entries], grids, wanted, limit))
        assert len(batches) > 1 and batches[-1][1] == len(entries)
        for lo, hi, found in batches:
            _, speed, bent = found.bend()
            x, y = found.xy()
            line = 0
            for k in range(lo, hi):
                geometry, index = entries[k]
                for lane_id in wanted[k]:
                    a, b = int(found.starts[line]), int(found.starts[line + 1])
                    alone = geometry.lane_points(index, lane_id, grids[k], "centre")
                    for got, want in ((bent, alone.curvature), (speed, alone.speed), (x, alone.x), (y, alone.y)):
                        assert _same(got[a:b], want), (geometry.road.id, index, lane_id)
                    line += 1
            assert line == len(found)


@pytest.mark.corpus
@pytest.mark.parametrize("name", _CENTRE_FILES)
def test_c001_and_j101_find_the_same_in_small_batches(corpus_dir: Path, name: str, monkeypatch: pytest.MonkeyPatch):
    def run() -> list:
        with np.errstate(all="ignore"):
            findings, ran = run_rules(_context(corpus_dir / name), Selection(select=("C001", "J101")))
        assert {"C001", "J101"} <= set(ran)
        return [repr(f) for f in findings]

    together = run()
    assert together or "fabriksgatan" in name or "rolled" in name  # Town01, Town03, the 3-way junction find some
    for module in (curvature, junction_geometry):  # many small batches (a big map's): the same findings
        monkeypatch.setattr(module, "BATCH_SAMPLES", 64)
    assert run() == together


def test_tightest_takes_the_first_largest_finite_curvature_where_the_line_moves():
    curvature = np.array([0.1, -0.5, 0.5, np.nan, np.inf, 0.3, 2.0, 0.9])
    speed = np.array([1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 1.0])
    starts = np.array([0, 3, 6, 6, 8])  # the third line has no pairs
    assert tightest(curvature, speed, starts, 0.2) == [(1, 1), (5, 2), None, (7, 1)]
    assert tightest(curvature, speed, starts, 0.95) == [None, None, None, None]


_DOCS = opendrive_documents(max_roads_per_chain=2, max_elements=3, max_lanes=3)


@settings(max_examples=40, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(_DOCS)
def test_generated_documents(data: bytes):
    document = read(data).document
    with np.errstate(all="ignore"):  # tiny elements: 8 chord / bending overflows to inf, alone and together alike
        _assert_samples_and_lines(document)
        _assert_mesh_is_each_sections_own(document, 0.05)


@settings(max_examples=60, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(damaged_documents(base=_DOCS, min_mutations=1, max_mutations=3))
def test_damaged_documents_mesh_as_each_section_alone(data: bytes):
    result = read(data)
    if result.document is None:
        return
    with np.errstate(all="ignore"):
        _assert_samples_and_lines(result.document)
        _assert_mesh_is_each_sections_own(result.document, 0.05)
