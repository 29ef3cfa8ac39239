"""Reporters: a list of :class:`~xodrcheck.check.Report` in, one text out.

Each format module has ``render(reports) -> str``; :func:`render` picks one by name. Formats: ``text`` (one line per
finding), ``json``, ``junit`` (XML for CI test views), ``sarif`` (2.1.0, for code-scanning tools) and ``github``
(workflow commands that annotate a pull request), ``xqar`` (the ASAM Quality Checker Framework's result file)
and ``html`` (a self-contained page with a map of each file).

What a report shows can be limited to a least severity (:func:`shown`): people read ``text`` and ``github`` output,
which show warnings and errors by default; the others (machine formats, and ``html``, which filters on the page) show
everything. Findings that fail the check (errors; warnings too in strict mode) are always shown, and the text report
ends with one line per code of what it did not show.
"""

from __future__ import annotations

import dataclasses
import importlib
from collections import Counter
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING

from xodrcheck.findings import Finding, Severity

if TYPE_CHECKING:  # pragma: no cover
    from xodrcheck.check import Report
    from xodrcheck.rules.registry import Rule

__all__ = [
    "DEFAULT_MIN_SEVERITY",
    "FORMATS",
    "Hidden",
    "least_severity",
    "render",
    "rule_bases",
    "shown",
    "summary",
    "tool_version",
]


FORMATS = ("text", "json", "junit", "sarif", "github", "xqar", "html")

#: The least severity each format shows unless told otherwise (``--min-severity``, key ``min_severity``).
DEFAULT_MIN_SEVERITY = {name: Severity.WARNING if name in ("text", "github") else Severity.INFO for name in FORMATS}


def least_severity(name: str | None, fmt: str) -> Severity:
    """The least severity to show: ``name`` (``info``, ``warning``, ``error``) or the format's default."""
    return DEFAULT_MIN_SEVERITY.get(fmt, Severity.INFO) if name is None else Severity[name.upper()]


#: What a report did not show: (code, name, severity) -> (findings, files).
Hidden = dict[tuple[str, str, Severity], tuple[int, int]]


def shown(reports: Sequence[Report], least: Severity) -> tuple[list[Report], Hidden]:
    """The reports keeping their findings of at least ``least`` severity (and every finding that fails the check),
    and what was left out, counted per code."""
    findings: Counter[tuple[str, str, Severity]] = Counter()
    files: Counter[tuple[str, str, Severity]] = Counter()
    out = []
    for report in reports:
        floor = min(least, Severity.WARNING if report.strict else Severity.ERROR)
        kept = tuple(f for f in report.findings if f.severity >= floor)
        left = Counter((f.code, f.name, f.severity) for f in report.findings if f.severity < floor)
        findings.update(left)
        files.update(left.keys())
        out.append(report if len(kept) == len(report.findings) else dataclasses.replace(report, findings=kept))
    return out, {key: (findings[key], files[key]) for key in sorted(findings)}


def render(name: str, reports: Sequence[Report], **options: object) -> str:
    """Render reports in the format ``name`` (one of :data:`FORMATS`); ``options`` go to that format's ``render``
    (``text`` takes ``least``, ``statistics`` and ``unreadable``)."""
    if name not in FORMATS:
        raise ValueError(f"unknown format {name!r}; choose one of {', '.join(FORMATS)}")
    module = importlib.import_module(f"{__name__}.{name}")
    return module.render(reports, **options)


def rule_bases(rule: Rule | None, findings: Iterable[Finding] = ()) -> list[str]:
    """What a rule's findings rest on: the UIDs it enforces, then what its findings without one rest on (declared
    by the rule), then any other basis of ``findings``; each once, in that order."""
    out = list(rule.uids) if rule is not None else []
    if rule is not None and rule.basis is not None:
        out.append(rule.basis)
    for f in findings:
        if f.basis not in out:
            out.append(f.basis)
    return out


def summary(reports: Sequence[Report]) -> dict:
    """Counts over all reports: files, findings by severity and by code, and whether all are ok."""
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


def tool_version() -> str:
    """The installed package's version, as every report names the tool ("unknown" from a source tree without
    package metadata)."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("junctionart")
    except PackageNotFoundError:  # pragma: no cover - running from a source tree without metadata
        return "unknown"
