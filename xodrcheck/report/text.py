"""Plain text: one line per finding, ``path:line: CODE severity message [road/lane/s] (UID)``.

``line`` is 0 for a finding about the whole file. The bracket names where on the map, as ``road/lane/s`` with ``-``
for a part that does not apply; it is left out when the finding names no road. The UID in parentheses is the checker
rule of the standard (ASAM OpenDRIVE Annex F) that the finding enforces, where there is one.
"""

from __future__ import annotations

from collections.abc import Sequence

from xodrcheck.findings import Finding


def where(f: Finding) -> str:
    if f.road is None:
        return ""
    lane = "-" if f.lane is None else str(f.lane)
    s = "-" if f.s is None else f"{f.s:.3f}"
    return f" [{f.road}/{lane}/{s}]"


def line(path: str | None, f: Finding) -> str:
    message = " ".join(f.message.split())  # one line, whatever the message holds
    uid = f" ({f.rule_uid})" if f.rule_uid else ""
    return f"{path or '-'}:{f.line or 0}: {f.code} {f.severity} {message}{where(f)}{uid}"


def render(reports: Sequence) -> str:
    return "".join(line(r.path, f) + "\n" for r in reports for f in r.findings)
