"""The places of many findings evaluated together (xodrcheck.rules.shared.places.locate_all) are those of evaluating
each alone (Context.locate), to the last bit, on roads of lines and arcs and of spirals."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from xodrcheck.check import Selection, run_rules
from xodrcheck.config import Config
from xodrcheck.reader import read_keeping_tree
from xodrcheck.rules.shared import places
from xodrcheck.rules.shared.context import Context


def _findings(path: Path) -> tuple[list, Context]:
    result, tree = read_keeping_tree(path)
    with np.errstate(all="ignore"):
        ctx = Context(result.document, Config(), path=str(path), tree=tree)
        more, _ = run_rules(ctx, Selection())
    return [*result.findings, *more], ctx


def _places(findings) -> list[tuple]:
    return [
        (f.code, f.road, f.s, f.lane, f.x, f.y, None if f.z is None else np.float64(f.z).tobytes()) for f in findings
    ]


@pytest.mark.corpus
@pytest.mark.parametrize(
    "name", ["carla-towns/OpenDrive/Town01.xodr", "esmini/EnvironmentSimulator/Unittest/xodr/highway_merge.xodr"]
)
def test_findings_located_together_are_located_as_one_by_one(corpus_dir: Path, name: str, monkeypatch):
    findings, ctx = _findings(corpus_dir / name)
    alone = [ctx.locate(f) for f in findings]
    findings, ctx = _findings(corpus_dir / name)
    alone_calls: list[int] = []
    points_at = places.points_at

    def counted(geometry, at, placed):
        alone_calls.append(len(at))
        return points_at(geometry, at, placed)

    monkeypatch.setattr(places, "points_at", counted)
    monkeypatch.setattr(places, "PLACES_TOGETHER", 7)  # several batches
    together = ctx.locate_all(findings)
    assert _places(together) == _places(alone)
    assert sum(f.x is not None for f in together) > 5
    assert not alone_calls  # every place evaluated together
