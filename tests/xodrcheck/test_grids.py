"""The sampling grids of many sections at once (xodrcheck.rules.shared.grids) are those the section-by-section
formula gives (the former sampled._grid, kept here as the reference), to the last bit."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

from xodrcheck.config import Config, Tolerances
from xodrcheck.geometry.lanes import RoadGeometry
from xodrcheck.geometry.sampling import step_counts
from xodrcheck.reader import read
from xodrcheck.rules.shared import grids, road_ends, sampled
from xodrcheck.rules.shared.context import Context


def _reference(tol: Tolerances, geometry: RoadGeometry, section_index: int) -> np.ndarray:
    start, end = geometry.section_range(section_index)
    if not end > start:
        return np.array([start], dtype=float)
    step = sampled.grid_step(tol)
    cuts = geometry.knots(section_index)
    lengths = np.diff(cuts)
    counts = step_counts(lengths, step, tol.max_samples_per_section)
    owner = np.repeat(np.arange(len(lengths)), counts)
    offset = np.arange(owner.size) - np.repeat(np.cumsum(counts) - counts, counts)
    s = np.append(cuts[owner] + lengths[owner] * offset / counts[owner], road_ends.left_of(end))
    return np.maximum.accumulate(s)


@pytest.mark.corpus
@pytest.mark.parametrize(
    "name",
    [
        "carla-towns/OpenDrive/Town01.xodr",
        "carla-towns/OpenDrive/Town04.xodr",
        "esmini/resources/xodr/fabriksgatan.xodr",
        "esmini/EnvironmentSimulator/Unittest/xodr/two_pitched_and_rolled_roads.xodr",
    ],
)
@pytest.mark.parametrize("budget", [None, 40])
def test_grids_together_are_each_sections_own(
    corpus_dir: Path, name: str, budget: int | None, monkeypatch: pytest.MonkeyPatch
):
    tol = Tolerances() if budget is None else dataclasses.replace(Tolerances(), max_samples_per_section=budget)
    ctx = Context(read(corpus_dir / name).document, Config(tolerances=tol), path=name, data=None)
    entries = [
        (geometry, index)
        for road in ctx.document.roads
        if (geometry := ctx.usable_geometry(road)) is not None
        for index in range(len(road.lane_sections))
    ]
    monkeypatch.setattr(grids, "BATCH_INTERVALS", 50)  # several batches
    with np.errstate(all="ignore"):
        together = grids.section_grids(tol, entries, sampled.grid_step(tol))
        alone = [_reference(tol, geometry, index) for geometry, index in entries]
    assert len(together) == len(alone) > 1
    assert all(a.shape == b.shape and a.tobytes() == b.tobytes() for a, b in zip(together, alone))
    if budget is not None and "Town" in name:  # the budget took longer steps somewhere
        assert any(len(s) <= budget + 60 < len(_reference(Tolerances(), *e)) for s, e in zip(together, entries))


def test_a_grid_that_falls_is_made_non_decreasing_and_nan_spreads():
    # two sections: the second's cut values fall below the end of its first step (damaged knots), a NaN end
    out = grids.knot_grids([np.array([0.0, 1.0]), np.array([5.0, 4.0, 6.0])], [0.9, float("nan")], 0.5, None)
    assert out[0].tolist() == [0.0, 0.5, 0.9]
    assert np.isnan(out[1][-1]) and out[1][:2].tolist() == [5.0, 5.0]
