"""Acceptance: ``xodrcheck info`` reads every third-party corpus file without an error-level finding."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.conftest import corpus_files, corpus_root
from xodrcheck.cli import main

pytestmark = [pytest.mark.corpus, pytest.mark.slow]


@pytest.mark.parametrize("path", corpus_files(), ids=lambda p: p.relative_to(corpus_root()).as_posix())
def test_info_exits_0(path: Path, corpus_dir: Path, capsys):
    code = main(["info", "--format", "json", str(path)])
    captured = capsys.readouterr()
    assert code == 0, f"xodrcheck info {path.relative_to(corpus_dir)} exited {code}: {captured.err.strip()}"
    assert captured.err == ""
    assert '"roads": 0' not in captured.out
