"""Which parts of the repository may import which: the tests never import ``benchmarks/``.

The benchmarks import the tests' helpers (e.g. ``tests/interop/asam_harness.py``), not the other way round: a test
must run from the package and its own tree, whatever the benchmarks do.
"""

from __future__ import annotations

import ast
from pathlib import Path

TESTS = Path(__file__).resolve().parent


def _imported_modules(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            names.add(node.module)
    return names


def test_no_test_imports_benchmarks() -> None:
    files = sorted(TESTS.rglob("*.py"))
    assert len(files) > 100, "the tests tree should hold its modules"
    offenders = {
        p.relative_to(TESTS).as_posix(): sorted(m for m in _imported_modules(p) if m.split(".")[0] == "benchmarks")
        for p in files
    }
    assert {k: v for k, v in offenders.items() if v} == {}
