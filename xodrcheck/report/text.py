"""Plain text: the verdict, one line per finding, and what a user needs to act on many of them.

The report, top to bottom:

* the verdict (:mod:`xodrcheck.report.verdict`): ``FAIL: 3 errors of 2 rules in 1 of 4 files; 12 warnings``;
* one line per finding, ``path:line: CODE severity message [road/lane/s x=X y=Y z=Z] (basis)``. ``line`` is 0 for a
  finding about the whole file. The bracket names where on the map: ``road/lane/s`` with ``-`` for a part that does
  not apply (left out when the finding names no road), then the inertial coordinates in metres, ``z`` only where the
  place is not at height 0 (a flat map prints ``x`` and ``y`` alone); the bracket is left out when the finding names
  no place. The basis in parentheses is what the finding rests on: the UID of the standard's checker rule (ASAM
  OpenDRIVE Annex F) it enforces, or ``schema``, ``reading``, ``plausibility`` (the checker's own judgement);
* one line per code of the findings under the least severity shown (``--min-severity``; by default infos):
  ``(not shown) G901 redundant-record: 9283 info finding(s) in 120 file(s); --min-severity info lists them``;
* the tally per rule of the findings shown (count, files when there are several, code, severity, name, basis), like
  ruff's ``--statistics``: by default when more than :data:`STATISTICS_ABOVE` findings are shown;
* in a run over several files, the files that fail, with what fails them.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Mapping, Sequence
from typing import TypeGuard

from xodrcheck.findings import Finding, Severity
from xodrcheck.report import shown
from xodrcheck.report.verdict import count, failing, stopped, verdict

#: More findings shown than this, and the tally per rule is on unless ``--no-statistics``.
STATISTICS_ABOVE = 20


def _finite(v: float | None) -> TypeGuard[float]:
    return v is not None and math.isfinite(v)


def where(f: Finding) -> str:
    parts = []
    if f.road is not None:
        lane = "-" if f.lane is None else str(f.lane)
        s = "-" if f.s is None else f"{f.s:.3f}"
        parts.append(f"{f.road}/{lane}/{s}")
    if _finite(f.x) and _finite(f.y):
        parts.append(f"x={f.x:.3f} y={f.y:.3f}")
        if _finite(f.z) and abs(f.z) >= 0.0005:
            parts.append(f"z={f.z:.3f}")
    return f" [{' '.join(parts)}]" if parts else ""


def line(path: str | None, f: Finding) -> str:
    message = " ".join(f.message.split())  # one line, whatever the message holds
    return f"{path or '-'}:{f.line or 0}: {f.code} {f.severity} {message}{where(f)} ({f.basis})"


def render(
    reports: Sequence,
    *,
    least: Severity = Severity.INFO,
    statistics: bool | None = None,
    unreadable: Sequence[str] = (),
) -> str:
    """The whole text report of ``reports`` (see the module docstring), showing findings of ``least`` severity and
    up; ``statistics`` forces the tally on or off; ``unreadable`` names the files that could not be checked."""
    visible, hidden = shown(reports, least)
    out = [verdict(reports, len(unreadable)) + "\n"]
    out += [line(r.path, f) + "\n" for r in visible for f in r.findings]
    out.append(not_shown(hidden))
    if statistics or (statistics is None and sum(len(r.findings) for r in visible) > STATISTICS_ABOVE):
        out.append(tally(visible))
    out.append(failing_files(reports, unreadable))
    return "".join(out)


def not_shown(hidden: Mapping) -> str:
    """One line per code of the findings a report left out (:func:`xodrcheck.report.shown`)."""
    return "".join(
        f"(not shown) {code} {name}: {count} {severity} finding(s) in {files} file(s); --min-severity {severity} "
        "lists them\n"
        for (code, name, severity), (count, files) in hidden.items()
    )


def tally(reports: Sequence) -> str:
    """The findings of ``reports`` counted per rule and severity, the worst and the most first, in aligned columns
    under a header; the basis column names the most frequent basis first."""
    counts: Counter[tuple[str, Severity]] = Counter()
    files: Counter[tuple[str, Severity]] = Counter()
    names: dict[str, str] = {}
    bases: dict[tuple[str, Severity], Counter[str]] = {}
    for report in reports:
        here: set[tuple[str, Severity]] = set()
        for f in report.findings:
            key = (f.code, f.severity)
            counts[key] += 1
            here.add(key)
            names.setdefault(f.code, f.name)
            bases.setdefault(key, Counter())[f.basis] += 1
        files.update(here)
    if not counts:
        return ""
    several = len(reports) > 1
    head = ["count", *(["files"] if several else []), "code", "severity", "name", "basis"]
    rows = [head]
    for key in sorted(counts, key=lambda k: (-k[1], -counts[k], k[0])):
        code, severity = key
        by = [b for b, _ in bases[key].most_common()]
        text = ", ".join(by[:2]) + (f" (+{len(by) - 2} more)" if len(by) > 2 else "")
        rows.append([str(counts[key]), *([str(files[key])] if several else []), code, str(severity), names[code], text])
    widths = [max(len(row[i]) for row in rows) for i in range(len(head) - 1)]
    numeric = 2 if several else 1  # right-aligned count (and files) columns
    lines = [
        "  ".join([cell.rjust(w) if i < numeric else cell.ljust(w) for i, (cell, w) in enumerate(zip(row, widths))])
        + "  "
        + row[-1]
        for row in rows
    ]
    return "\nfindings shown, per rule:\n" + "".join(f"  {text}\n" for text in lines)


def failing_files(reports: Sequence, unreadable: Sequence[str] = ()) -> str:
    """In a run over several files: each file that fails (in the order given) with what fails it, then those that
    could not be checked; empty for one file, or when none fails."""
    if len(reports) + len(unreadable) < 2:
        return ""
    rows = []
    for report in reports:
        if report.ok:
            continue
        bad = failing(report)
        errors = sum(1 for f in bad if f.severity is Severity.ERROR)
        parts = [count(errors, "error")] + ([count(len(bad) - errors, "warning")] if report.strict else [])
        if not report.complete:
            codes = sorted({f.code for f in stopped(report)})
            parts.append(f"incomplete ({', '.join(codes)})")
        rows.append(f"  {report.path or '-'}: {', '.join(parts)}\n")
    rows += [f"  {path}: could not be checked\n" for path in unreadable]
    if not rows:
        return ""
    total = len(reports) + len(unreadable)
    return f"\nfailing files ({len(rows)} of {total}):\n" + "".join(rows)
