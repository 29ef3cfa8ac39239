"""Fixtures that say which rules of the standard they exercise.

A fixture under ``tests/xodrcheck/rules/fixtures/<rule-name>/`` names the Annex F UIDs it is a passing or failing
example of in a comment near its top::

    <!-- uids: asam.net:xodr:1.7.0:road.lane.link.zero_width_at_start -->

A ``fail*`` fixture must give a finding of its folder's rule with each UID it names; a ``pass*`` fixture none.
"""

from __future__ import annotations

import re
from pathlib import Path

FIXTURES = Path(__file__).resolve().parents[1] / "rules" / "fixtures"
_UIDS = re.compile(r"<!--\s*uids:\s*(.*?)-->", re.S)


def declared_uids(path: Path) -> tuple[str, ...]:
    """The UIDs a fixture names in its ``<!-- uids: ... -->`` comment (within its first 4 kB)."""
    head = path.read_bytes()[:4096].decode("utf-8", errors="replace")
    m = _UIDS.search(head)
    return tuple(m.group(1).split()) if m else ()


def uid_fixtures() -> dict[str, dict[str, list[Path]]]:
    """UID -> {"pass": [...], "fail": [...]} over every fixture that names UIDs."""
    out: dict[str, dict[str, list[Path]]] = {}
    for path in sorted(FIXTURES.glob("*/*.xodr")):
        kind = "pass" if path.name.startswith("pass") else "fail" if path.name.startswith("fail") else None
        if kind is None:
            continue
        for uid in declared_uids(path):
            out.setdefault(uid, {"pass": [], "fail": []})[kind].append(path)
    return out
