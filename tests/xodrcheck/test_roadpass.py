"""The one-pass evaluation of all lane sections (:mod:`xodrcheck.roadpass`) gives the per-section code's numbers to
the last bit: samples, border lines, lane points and meshes, on corpus maps and on generated documents."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings

from junctionart.fuzz.documents import opendrive_documents
from junctionart.fuzz.mutations import damaged_documents
from tests.conftest import corpus_root
from xodrcheck import arrays, roadpass
from xodrcheck.config import Config
from xodrcheck.lanes import RoadGeometry, geometry_of
from xodrcheck.mesh import _lane_pairs, _one, _Part, _Section, build_surfaces
from xodrcheck.reader import read
from xodrcheck.rules import sampled
from xodrcheck.rules.context import Context

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


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    return a.shape == b.shape and a.tobytes() == b.tobytes()


def _entries(document) -> list[tuple[RoadGeometry, int]]:
    geometries = geometry_of(document)
    out = []
    for road in document.roads:
        rg = geometries[road.id]
        if road.plan_view and rg.road is road:
            out.extend((rg, i) for i in range(len(road.lane_sections)) if roadpass.covered(rg, i))
    return out


def _assert_samples_and_lines(document) -> int:
    entries = _entries(document)
    samples = roadpass.sample_sections(entries, CHORD, MAX_STEP, BUDGET)
    assert samples is not None
    for (rg, i), s in zip(entries, samples):
        assert _same(s, rg.sample_s(i, chord=CHORD, max_step=MAX_STEP, budget=BUDGET)), (rg.road.id, i)
    points = roadpass.section_points(entries, samples)
    assert points is not None
    for (rg, i), s, p in zip(entries, samples, points):
        curves = rg.border_curves(i, s)
        assert p.ids == list(curves)
        for k, lane_id in enumerate(p.ids):
            for name in ("x", "y", "z", "hdg", "curvature", "speed"):
                assert _same(getattr(p, name)[k], getattr(curves[lane_id], name)), (rg.road.id, i, lane_id, name)
            assert _same(p.t[k], rg.borders(i, s)[lane_id])
        assert _same(p.reference_curvature, rg.reference(s).curvature)
    return len(entries)


def _per_section_mesh(document, chord: float):
    geometries = geometry_of(document)
    parts = []
    for road in document.roads:
        if not road.plan_view:
            continue
        rg = geometries[road.id] if geometries[road.id].road is road else RoadGeometry(road)
        for i, section in enumerate(road.lane_sections):
            if road.section_end(i) > section.s and (pairs := _lane_pairs(rg, i, None)):
                parts.append(_one(_Section(rg, i, pairs), chord, MAX_STEP))
    return _Part.join(parts).surfaces()


def _assert_same_mesh(document, chord: float) -> None:
    fast, slow = build_surfaces(document, chord=chord), _per_section_mesh(document, chord)
    assert fast.lanes == slow.lanes and fast.lane_types == slow.lane_types
    for name in ("vertices", "faces", "face_lane", "face_s", "lane_vertices", "lane_faces"):
        assert _same(getattr(fast, name), getattr(slow, name)), name


@pytest.mark.corpus
@pytest.mark.parametrize("name", CORPUS)
def test_corpus_sections_in_one_pass_are_the_per_section_numbers(corpus_dir: Path, name: str):
    document = read(corpus_dir / name).document
    assert _assert_samples_and_lines(document) > 0
    _assert_same_mesh(document, 0.1)


@pytest.mark.corpus
def test_checker_grid_lines_in_one_pass(corpus_dir: Path):
    path = corpus_dir / "carla-towns/OpenDrive/Town07.xodr"
    document = read(path).document
    ctx = Context(document, Config(), path=str(path), data=None, deadline=time.monotonic() + 1e9)
    together = sampled._all_sections(ctx)
    assert len(together) > 700
    for (road_id, i), got in list(together.items())[::7]:
        rg = ctx.geometry(road_id)
        s = sampled._grid(ctx, rg, i)
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
        return sampled._all_sections(Context(document, Config(), path=str(path), data=None))

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


def test_superelevation_and_duplicate_lane_ids_are_left_to_the_per_section_code(corpus_dir: Path):
    from tests.xodrcheck.rules.helpers import fixture

    document = read(fixture("duplicate-lane-id", "fail.xodr")).document
    geometries = geometry_of(document)
    covered = [roadpass.covered(geometries[r.id], i) for r in document.roads for i in range(len(r.lane_sections))]
    assert not all(covered)  # the section with a lane id twice
    _assert_same_mesh(document, 0.05)
    tilted = (corpus_root() / "esmini/EnvironmentSimulator/Unittest/xodr/tilted_crest.xodr").read_bytes()
    document = read(tilted).document
    assert document.roads[0].superelevation
    assert not roadpass.covered(geometry_of(document)[document.roads[0].id], 0)
    _assert_same_mesh(document, 0.05)


_DOCS = opendrive_documents(max_roads_per_chain=2, max_elements=3, max_lanes=3)


@settings(max_examples=40, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(_DOCS)
def test_generated_documents(data: bytes):
    document = read(data).document
    with np.errstate(all="ignore"):  # tiny elements: 8 chord / bending overflows to inf, in both codes alike
        _assert_samples_and_lines(document)
        _assert_same_mesh(document, 0.05)


@settings(max_examples=60, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(damaged_documents(base=_DOCS, min_mutations=1, max_mutations=3))
def test_damaged_documents_mesh_as_before(data: bytes):
    result = read(data)
    if result.document is None:
        return
    with np.errstate(all="ignore"):
        _assert_same_mesh(result.document, 0.05)
