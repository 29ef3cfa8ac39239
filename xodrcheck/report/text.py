"""Plain text: one line per finding, ``path:line: CODE severity message [road/lane/s x=X y=Y z=Z] (UID)``.

``line`` is 0 for a finding about the whole file. The bracket names where on the map: ``road/lane/s`` with ``-`` for a
part that does not apply (left out when the finding names no road), then the inertial coordinates in metres, ``z``
only where the place is not at height 0 (a flat map prints ``x`` and ``y`` alone); the bracket is left out when the
finding names no place. The UID in parentheses is the checker rule of the standard (ASAM OpenDRIVE Annex F) that the
finding enforces, where there is one.

Findings under the least severity shown (``--min-severity``; by default infos) are summarised after the finding lines,
one line per code: ``(not shown) G901 redundant-record: 9283 info finding(s) in 120 file(s); --min-severity info
lists them``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import TypeGuard

from xodrcheck.findings import Finding


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
    uid = f" ({f.rule_uid})" if f.rule_uid else ""
    return f"{path or '-'}:{f.line or 0}: {f.code} {f.severity} {message}{where(f)}{uid}"


def render(reports: Sequence) -> str:
    return "".join(line(r.path, f) + "\n" for r in reports for f in r.findings)


def not_shown(hidden: Mapping) -> str:
    """One line per code of the findings a report left out (:func:`xodrcheck.report.shown`)."""
    return "".join(
        f"(not shown) {code} {name}: {count} {severity} finding(s) in {files} file(s); --min-severity {severity} "
        "lists them\n"
        for (code, name, severity), (count, files) in hidden.items()
    )
