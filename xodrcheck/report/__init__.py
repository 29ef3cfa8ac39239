"""Reporters: a list of :class:`~xodrcheck.check.Report` in, one text out.

Each format module has ``render(reports) -> str``; :func:`render` picks one by name. Formats: ``text`` (one line per
finding), ``json``, ``junit`` (XML for CI test views), ``sarif`` (2.1.0, for code-scanning tools) and ``github``
(workflow commands that annotate a pull request), ``xqar`` (the ASAM Quality Checker Framework's result file)
and ``html`` (a self-contained page with a map of each file).
"""

from __future__ import annotations

import importlib
from collections.abc import Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # pragma: no cover
    from xodrcheck.check import Report

FORMATS = ("text", "json", "junit", "sarif", "github", "xqar", "html")


def render(name: str, reports: Sequence[Report]) -> str:
    """Render reports in the format ``name`` (one of :data:`FORMATS`)."""
    if name not in FORMATS:
        raise ValueError(f"unknown format {name!r}; choose one of {', '.join(FORMATS)}")
    module = importlib.import_module(f"{__name__}.{name}")
    return module.render(reports)


def summary(reports: Sequence[Report]) -> dict:
    """Counts over all reports: files, findings by severity and by code, and whether all are ok."""
    from xodrcheck.findings import Severity

    by_code: dict[str, int] = {}
    for report in reports:
        for f in report.findings:
            by_code[f.code] = by_code.get(f.code, 0) + 1
    counts = {str(sev): sum(r.count(sev) for r in reports) for sev in (Severity.ERROR, Severity.WARNING, Severity.INFO)}
    return {
        "files": len(reports),
        "files_failed": sum(1 for r in reports if not r.ok),
        "files_incomplete": sum(1 for r in reports if not r.complete),
        "findings": sum(len(r.findings) for r in reports),
        "errors": counts["error"],
        "warnings": counts["warning"],
        "infos": counts["info"],
        "by_code": dict(sorted(by_code.items())),
        "ok": all(r.ok for r in reports),
    }
