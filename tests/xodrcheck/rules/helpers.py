"""Helpers for the per-rule tests: fixtures live in ``fixtures/<rule-name>/pass*.xodr`` and ``fail*.xodr``."""

from __future__ import annotations

from pathlib import Path

from xodrcheck.check import check
from xodrcheck.config import Config
from xodrcheck.findings import Finding
from xodrcheck.rules import load_rules

FIXTURES = Path(__file__).parent / "fixtures"


def fixture(rule_name: str, name: str) -> Path:
    path = FIXTURES / rule_name / name
    assert path.is_file(), f"missing fixture {path}"
    return path


def passing(rule_name: str) -> list[Path]:
    return sorted((FIXTURES / rule_name).glob("pass*.xodr"))


def failing(rule_name: str) -> list[Path]:
    return sorted((FIXTURES / rule_name).glob("fail*.xodr"))


def code_of(rule_name: str) -> str:
    (code,) = [r.code for r in load_rules().values() if r.name == rule_name]
    return code


def findings(path: Path, rule_name: str, profile: str = "default") -> list[Finding]:
    """The findings of one rule on one file (only that rule is run), judged by ``profile`` (``default``: the
    standard's verdicts; ``generator``: the rule's own severity)."""
    code = code_of(rule_name)
    report = check(path, Config(profile=profile), select=(code,))
    assert not [f for f in report.findings if f.code == "X900"], report.findings
    return [f for f in report.findings if f.code == code]


def line_of(path: Path, text: str, occurrence: int = 1) -> int:
    """1-based line of the ``occurrence``-th line containing ``text``."""
    hits = [i for i, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1) if text in line]
    assert len(hits) >= occurrence, f"{text!r} occurs {len(hits)} times in {path}"
    return hits[occurrence - 1]
