"""Lane centre lines evaluated together (xodrcheck.centres, used by C001 and J101) are the numbers of
RoadGeometry.lane_points(..., "centre") lane by lane, to the last bit, and the rules' findings do not change."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from xodrcheck import centres, roadpass
from xodrcheck.check import Selection, run_rules
from xodrcheck.config import Config
from xodrcheck.reader import read
from xodrcheck.rules import curvature, junction_geometry, sampled
from xodrcheck.rules.context import Context, placed_lane_ids

_FILES = [
    "carla-towns/OpenDrive/Town01.xodr",
    "carla-towns/OpenDrive/Town03.xodr",
    "esmini/resources/xodr/fabriksgatan.xodr",
    "esmini/EnvironmentSimulator/Unittest/xodr/multi_lane_3way_intersection.xodr",
    "esmini/EnvironmentSimulator/Unittest/xodr/two_pitched_and_rolled_roads.xodr",
]


def _context(path: Path) -> Context:
    return Context(read(path).document, Config(), path=str(path), data=None)


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    return a.shape == b.shape and a.tobytes() == b.tobytes()


@pytest.mark.corpus
@pytest.mark.parametrize("name", _FILES)
def test_centre_lines_together_are_each_lanes_own(corpus_dir: Path, name: str):
    ctx = _context(corpus_dir / name)
    entries, grids, wanted = [], [], []
    with np.errstate(all="ignore"):
        for road in ctx.document.roads:
            geometry = sampled.usable(ctx, road)
            for index in range(len(road.lane_sections)) if geometry is not None else ():
                s = sampled.section_samples(ctx, road, index)
                if roadpass.covered(geometry, index) and np.isfinite(s).all():
                    entries.append((geometry, index))
                    grids.append(s)
                    wanted.append(sorted(placed_lane_ids(geometry, index), reverse=True))
        found = centres.centre_lines(entries, grids, wanted)
        if not entries:
            assert found is None and "rolled" in name  # superelevation: no section covered
            return
        assert found is not None and len(found.lanes) == sum(len(w) for w in wanted)
        x, y = found.all_xy()
        for j, (k, lane_id) in enumerate(found.lanes):
            (geometry, index), lo, hi = entries[k], int(found.starts[j]), int(found.starts[j + 1])
            alone = geometry.lane_points(index, lane_id, grids[k], "centre")
            for got, want in (
                (found.curvature, alone.curvature),
                (found.speed, alone.speed),
                (x, alone.x),
                (y, alone.y),
            ):
                assert _same(got[lo:hi], want), (geometry.road.id, index, lane_id)
            assert found.xy([lo, hi - 1]) == [
                (float(alone.x[0]), float(alone.y[0])),
                (float(alone.x[-1]), float(alone.y[-1])),
            ]


@pytest.mark.corpus
@pytest.mark.parametrize("name", _FILES)
def test_c001_and_j101_find_the_same_with_lines_evaluated_lane_by_lane(
    corpus_dir: Path, name: str, monkeypatch: pytest.MonkeyPatch
):
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
    monkeypatch.setattr(curvature, "_centre_hits", lambda ctx, bound: {})
    monkeypatch.setattr(junction_geometry, "_known", lambda ctx, wanted: {})
    assert run() == together


def test_tightest_takes_the_first_largest_finite_curvature_where_the_line_moves():
    pose = None
    line = centres.Centres(
        [(0, 1), (0, 2), (1, -1)],
        np.array([0, 3, 6, 8]),
        np.arange(8),
        np.zeros(8),
        np.array([0.1, -0.5, 0.5, np.nan, np.inf, 0.3, 2.0, 0.9]),
        np.array([1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0, 1.0]),
        pose,  # type: ignore[arg-type]
    )
    assert centres.tightest(line, 0.2) == [(1, 1), (5, 2), (7, 1)]
    assert centres.tightest(line, 0.95) == [None, None, None]
