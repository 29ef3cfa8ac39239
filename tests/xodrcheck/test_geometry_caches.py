"""The geometric rules' shared caches stay within their byte budgets on a map bigger than them, and the findings are
those of an unbounded run (xodrcheck.support.budget, xodrcheck.geometry.lanes.EVALUATION_BUDGET,
xodrcheck.rules.shared.sampled)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from xodrcheck.check import Selection, run_rules
from xodrcheck.config import Config
from xodrcheck.geometry import lanes
from xodrcheck.model import ContactPoint
from xodrcheck.reader import read
from xodrcheck.rules.shared import road_ends, sampled
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.budget import ByteBudget

#: The modules whose rules read the shared section lines, road ends and lane evaluations.
_MODULES = ("curvature", "link", "road_attributes", "junction_shapes", "junction_geometry", "junction_direct")


def _codes() -> tuple[str, ...]:
    rules = Selection().rules.values()
    return tuple(r.code for r in rules if r.check is not None and r.check.__module__.rsplit(".", 1)[-1] in _MODULES)


def _check(path: Path) -> tuple[list, Context]:
    document = read(path).document
    ctx = Context(document, Config(), path=str(path), data=None)
    with np.errstate(all="ignore"):
        findings, run = run_rules(ctx, Selection(select=_codes()))
    assert len(run) > 8
    return findings, ctx


def _largest_total(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """Record the largest total of every :class:`ByteBudget` after each entry it counts."""
    seen = [0]
    add = ByteBudget.add

    def counted(self: ByteBudget, cache, key, size: int) -> None:
        add(self, cache, key, size)
        if self.limit < 1 << 30:
            seen[0] = max(seen[0], self.total)

    monkeypatch.setattr(ByteBudget, "add", counted)
    return seen


@pytest.mark.corpus
def test_section_lines_stay_within_their_budget_with_unchanged_findings(
    corpus_dir: Path, monkeypatch: pytest.MonkeyPatch
):
    path = corpus_dir / "carla-towns/OpenDrive/Town07.xodr"
    monkeypatch.setattr(sampled, "LINES_BUDGET", 1 << 40)
    whole, ctx = _check(path)
    assert sampled.LINES[ctx].kept > 700  # the budget holds every section: evaluated once

    small = 1 << 20
    monkeypatch.setattr(sampled, "LINES_BUDGET", small)
    largest = _largest_total(monkeypatch)
    bounded, ctx = _check(path)
    assert bounded == whole and len(whole) > 0
    cache = sampled.LINES[ctx]
    assert 0 < cache.kept < 700 and cache.kept_bytes <= small
    kept = cache.kept_sections().values()
    # each kept section owns its arrays: a view would keep its whole batch alive, past the budget's count
    assert all(p.x.base is None and p.speed.base is None for lines in kept for p in lines.borders.values())
    assert 0 < largest[0] <= small + (1 << 19)  # a newest entry may pass the budget by its own size


@pytest.mark.corpus
def test_road_evaluations_stay_within_their_budget_with_unchanged_numbers(
    corpus_dir: Path, monkeypatch: pytest.MonkeyPatch
):
    """The per-road evaluations (RoadGeometry's recent queries) of a document share EVALUATION_BUDGET: lane by lane
    over a whole town they stay within it, and a dropped evaluation gives the same numbers when asked again."""
    document = read(corpus_dir / "carla-towns/OpenDrive/Town07.xodr").document
    small = 1 << 20
    monkeypatch.setattr(lanes, "EVALUATION_BUDGET", small)
    largest = _largest_total(monkeypatch)
    geometries = lanes.geometry_of(document)
    first: dict[tuple[str, int, int], np.ndarray] = {}
    for _ in range(2):  # the second round finds most evaluations dropped
        for road in document.roads:
            geometry = geometries[road.id]
            for index in range(len(road.lane_sections)):
                s = np.linspace(*geometry.section_range(index), 200)
                for lane_id in geometry.rows(index).first:
                    x = geometry.lane_points(index, lane_id, s, "centre").x
                    assert np.array_equal(first.setdefault((road.id, index, lane_id), x), x, equal_nan=True)
    budget = geometries.budget
    kept = sum(geometries[road].cached_evaluations() for road in geometries.built())
    assert kept == len(budget) > 0 and budget.total <= small
    assert 0 < largest[0] <= small + (1 << 19)  # a newest entry may pass the budget by its own size


def test_a_budget_drops_the_least_recently_used_entries_of_every_cache():
    budget = ByteBudget(100)
    a: dict[str, int] = {}
    b: dict[str, int] = {}
    for key, cache in (("1", a), ("2", b), ("3", a)):
        cache[key] = 0
        budget.add(cache, key, 40)
    assert a == {"3": 0} and b == {"2": 0} and budget.total == 80
    budget.touch(b, "2")
    a["4"] = 0
    budget.add(a, "4", 40)
    assert b == {"2": 0} and a == {"4": 0} and budget.total == 80
    budget.discard(a, "4")
    del a["4"]
    assert len(budget) == 1 and budget.total == 40
    big: dict[str, int] = {"x": 0}
    budget.add(big, "x", 500)  # the newest entry stays, alone, even over the limit
    assert big == {"x": 0} and b == {} and len(budget) == 1


@pytest.mark.corpus
@pytest.mark.parametrize(
    "name", ["carla-towns/OpenDrive/Town07.xodr", "esmini/resources/xodr/multi_intersections.xodr"]
)
def test_lane_meshes_built_in_batches_are_the_one_pass_mesh(
    corpus_dir: Path, monkeypatch: pytest.MonkeyPatch, name: str
):
    """The lane meshes of a big map are built in batches of border points (the temporaries scale with a batch, not
    the map), its sections sampled in batches of sections."""
    from xodrcheck.mesh import surfaces as mesh

    document = read(corpus_dir / name).document
    monkeypatch.setattr(mesh, "MESH_BATCH", 1 << 40)
    whole = mesh.build_surfaces(document)
    calls: list[tuple[int, int]] = []
    evaluation = mesh.Evaluation

    def counted(sections, samples):
        calls.append((sum(len(s) * len(rows.ids) for rows, s in zip(sections, samples)), len(sections)))
        return evaluation(sections, samples)

    sampled_sections: list[int] = []
    sample_sections = mesh.sample_sections

    def sampling(blocks, *args):
        sampled_sections.append(len(blocks))
        return sample_sections(blocks, *args)

    monkeypatch.setattr(mesh, "Evaluation", counted)
    monkeypatch.setattr(mesh, "sample_sections", sampling)
    monkeypatch.setattr(mesh, "MESH_BATCH", 2000)
    monkeypatch.setattr(mesh, "SAMPLE_SECTIONS", 5)
    batched = mesh.build_surfaces(document)
    assert len(calls) > 3 and all(points <= 2000 or sections == 1 for points, sections in calls)
    assert len(sampled_sections) > 3 and max(sampled_sections) <= 5
    assert whole.lanes == batched.lanes and whole.lane_types == batched.lane_types and len(whole.lanes) > 20
    for field in ("vertices", "faces", "face_lane", "face_s", "lane_vertices", "lane_faces"):
        assert np.array_equal(getattr(whole, field), getattr(batched, field), equal_nan=True), field


@pytest.mark.corpus
def test_lane_outlines_made_in_blocks_are_the_outlines_made_at_once(corpus_dir: Path, monkeypatch: pytest.MonkeyPatch):
    """The footprints' polygons of a big map are made a block of lanes at a time (bounded temporaries)."""
    import shapely

    from xodrcheck.mesh import footprint
    from xodrcheck.mesh import surfaces as mesh

    surfaces = mesh.surfaces_of(read(corpus_dir / "carla-towns/OpenDrive/Town07.xodr").document)
    order, owner = surfaces.outline_order()
    whole = shapely.polygons(shapely.linearrings(surfaces.vertices[order, :2], indices=owner))
    blocks: list[int] = []
    polygons = shapely.polygons

    def counted(rings):
        blocks.append(int(shapely.get_num_coordinates(rings).sum()))
        return polygons(rings)

    monkeypatch.setattr(footprint, "OUTLINE_BLOCK", 1000)
    monkeypatch.setattr(shapely, "polygons", counted)
    made = footprint.outlines(surfaces)
    assert len(blocks) > 10 and max(blocks) <= 1000 + max(np.diff(surfaces.lane_vertices)) + len(surfaces)
    assert len(made) == len(whole) > 700
    assert all(np.array_equal(shapely.get_coordinates(a), shapely.get_coordinates(b)) for a, b in zip(made, whole))


@pytest.mark.corpus
def test_lines_read_in_order_are_those_of_the_cache_and_released_before_the_meshes(
    corpus_dir: Path, monkeypatch: pytest.MonkeyPatch
):
    path = corpus_dir / "carla-towns/OpenDrive/Town01.xodr"
    ctx = Context(read(path).document, Config(), path=str(path), data=None)
    monkeypatch.setattr(sampled, "LINES_BUDGET", 1 << 18)  # most sections do not fit: they pass in batches
    monkeypatch.setattr(sampled, "PASSING_BYTES", 1 << 16)
    with np.errstate(all="ignore"):
        first = ctx.document.roads[0]
        kept = sampled.section_lines(ctx, first, 0)  # a rule before kept some lines; the rest pass in batches
        streamed = [(road.id, index, lines) for road, index, _, lines in sampled.lines_in_order(ctx)]
        cache = sampled.LINES[ctx]
        assert not cache.fits and 0 < cache.kept < len(streamed) and cache.kept_bytes <= sampled.LINES_BUDGET
        assert any(lines is kept for _, _, lines in streamed)
        assert len(streamed) == sum(len(r.lane_sections) for r in ctx.document.roads if ctx.usable_geometry(r))
        for road_id, index, lines in streamed:
            alone = sampled.section_lines(ctx, ctx.document.road_by_id[road_id], index)
            assert np.array_equal(lines.s, alone.s) and lines.t.keys() == alone.t.keys()
            assert np.array_equal(lines.curvature, alone.curvature, equal_nan=True)
            for lane_id, p in lines.borders.items():
                assert np.array_equal(p.x, alone.borders[lane_id].x, equal_nan=True)
                assert np.array_equal(p.hdg, alone.borders[lane_id].hdg, equal_nan=True)
        road_ends.road_end(ctx, first, ContactPoint.START)
        sampled.release_lines(ctx)
    assert ctx not in sampled.LINES and ctx not in road_ends.ENDS and ctx not in road_ends.END_CURVES


@pytest.mark.corpus
def test_a_file_that_fits_has_its_lines_evaluated_in_one_batch(corpus_dir: Path, monkeypatch: pytest.MonkeyPatch):
    path = corpus_dir / "carla-towns/OpenDrive/Town01.xodr"
    ctx = Context(read(path).document, Config(), path=str(path), data=None)
    sizes: list[int] = []
    evaluation = sampled.Evaluation

    def counted(sections, samples):
        sizes.append(len(sections))
        return evaluation(sections, samples)

    monkeypatch.setattr(sampled, "Evaluation", counted)  # one call per batch of sections
    roads = ctx.document.roads
    with np.errstate(all="ignore"):
        sampled.section_lines(ctx, roads[len(roads) // 2], 0)  # asked first in the middle: all from the first on
        sampled.section_lines(ctx, roads[0], 0)
        for _ in sampled.lines_in_order(ctx):
            pass
    cache = sampled.LINES[ctx]
    assert cache.position((roads[len(roads) // 2].id, 0)) > 0
    assert cache.fits and sizes == [cache.listed] and cache.kept == cache.listed > 100


#: Files evaluated in batches: a town, a small esmini map, and one with superelevation.
_PASS_FILES = [
    "carla-towns/OpenDrive/Town01.xodr",
    "esmini/resources/xodr/fabriksgatan.xodr",
    "esmini/EnvironmentSimulator/Unittest/xodr/two_pitched_and_rolled_roads.xodr",
]


@pytest.mark.corpus
@pytest.mark.parametrize("name", _PASS_FILES)
def test_road_ends_evaluated_together_are_each_roads_own_border_curves(corpus_dir: Path, name: str):
    """road_ends.road_end takes the border curves of every road end from one batched evaluation: each section's
    RoadGeometry.border_curves to the last bit."""
    path = corpus_dir / name
    ctx = Context(read(path).document, Config(), path=str(path), data=None)
    with np.errstate(all="ignore"):
        together = road_ends.end_curves(ctx)
        compared = 0
        for road in ctx.document.roads:
            geometry = ctx.usable_geometry(road)
            for end in (ContactPoint.START, ContactPoint.END) if geometry is not None else ():
                index, _, s = road_ends.end_samples(road, end)
                alone = geometry.border_curves(index, s)
                if (road.id, index) in together:
                    got = together[(road.id, index)]
                    assert list(got) == list(alone)
                    for lane_id, p in alone.items():
                        for field in ("x", "y", "z", "hdg", "curvature", "speed"):
                            a, b = getattr(got[lane_id], field), getattr(p, field)
                            assert a.shape == b.shape and a.tobytes() == b.tobytes(), (road.id, end, lane_id, field)
                    compared += 1
                end_point = road_ends.road_end(ctx, road, end).border(0, "outer")
                assert end_point is None or end_point.x == float(
                    alone[0].x[0 if len(s) == 1 or end is ContactPoint.START else 1]
                )
    assert compared > 0


@pytest.mark.corpus
@pytest.mark.parametrize("name", _PASS_FILES)
def test_lane_width_pieces_evaluated_together_are_each_sections_own(corpus_dir: Path, name: str):
    """lane_shape's pieces (G010, G011, G015) take every section's borders from one batched evaluation: the same
    numbers as RoadGeometry.borders section by section."""
    from xodrcheck.rules import lane_shape

    path = corpus_dir / name
    ctx = Context(read(path).document, Config(), path=str(path), data=None)
    compared = 0
    with np.errstate(all="ignore"):
        for road in ctx.document.roads:
            for index in range(len(road.lane_sections)) if ctx.usable_geometry(road) is not None else ():
                together = lane_shape.lane_pieces(ctx, road, index)
                alone = lane_shape.section_pieces(ctx, road, index, lane_shape.piece_nodes(ctx, road, index))
                assert (together is None) == (alone is None)
                if together is not None:
                    assert together[0] == alone[0]
                    assert all(
                        x.shape == y.shape and x.tobytes() == y.tobytes() for x, y in zip(together[1:], alone[1:])
                    )
                    compared += 1
    assert compared > 0
