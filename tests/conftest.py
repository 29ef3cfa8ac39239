"""Shared fixtures. The third-party corpus comes from ``$XODR_CORPUS`` (default ``../shared/corpus``).

A missing corpus is a failure, not a skip: the corpus tests are acceptance tests.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from hypothesis import HealthCheck, settings

REPO = Path(__file__).resolve().parents[1]

#: The corpus as shipped in shared/ (see its MANIFEST.tsv): a copy with fewer files fails every corpus test.
CORPUS_SIZE = 128

# Tests never depend on timing: every Hypothesis test (the fuzz campaign's profiles do the same) runs without a
# deadline and without the too_slow health check, which a busy CI machine trips on strategies that are not slow.
settings.register_profile("tests", deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.load_profile("tests")


def corpus_root() -> Path:
    return Path(os.environ.get("XODR_CORPUS", REPO.parent / "shared" / "corpus")).resolve()


def corpus_files() -> list[Path]:
    root = corpus_root()
    return sorted(root.rglob("*.xodr")) if root.is_dir() else []


def lane_centres_root() -> Path:
    return corpus_root().parent / "lane-centres"


@pytest.fixture(scope="session")
def corpus_dir() -> Path:
    root = corpus_root()
    if not root.is_dir():
        pytest.fail(f"corpus not found at {root}: set XODR_CORPUS to the shared corpus folder")
    found = len(corpus_files())
    if found != CORPUS_SIZE:
        pytest.fail(f"the corpus at {root} has {found} .xodr files, not {CORPUS_SIZE}: an incomplete copy")
    return root


@pytest.fixture(scope="session")
def lane_centres_dir(corpus_dir: Path) -> Path:
    root = lane_centres_root()
    if not root.is_dir():
        pytest.fail(f"lane-centre reference points not found at {root} (expected beside the corpus)")
    return root
