"""Acceptance: ``xodrcheck sample --borders`` writes finite points for every lane of every corpus file."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from tests.conftest import corpus_files, corpus_root
from xodrcheck.cli import main

pytestmark = [pytest.mark.corpus, pytest.mark.slow]


@pytest.mark.parametrize("path", corpus_files(), ids=lambda p: p.relative_to(corpus_root()).as_posix())
def test_sample_borders_as_geojson(path: Path, corpus_dir: Path, tmp_path: Path, capsys):
    out = tmp_path / "lanes.geojson"
    code = main(["sample", str(path), "--step", "5", "--borders", "--format", "geojson", "-o", str(out)])
    err = capsys.readouterr().err
    assert code == 0, f"xodrcheck sample {path.relative_to(corpus_dir)} exited {code}: {err.strip()}"
    features = json.loads(out.read_text(encoding="utf-8"))["features"]
    assert features, "no lane was sampled"
    assert {f["properties"]["kind"] for f in features} == {"centre", "inner", "outer"}
    for f in features:
        coords = f["geometry"]["coordinates"]
        assert len(coords) >= 2
        assert all(math.isfinite(v) for c in coords for v in c), f"non-finite point on {f['properties']}"
