"""JSON: ``{"files": [{"path", "version", "ok", "complete", "findings": [...]}], "summary": {...}}``.

``complete`` is false when a rule did not run to its end (X900, X901): such a file is never ``ok``.

Every finding has the keys ``code name category severity message road lane s x y z line rule_uid basis`` (``null``
where a key does not apply), so consumers can rely on the shape. ``rule_uid`` names the checker rule of the standard
(ASAM OpenDRIVE Annex F) that the finding enforces; ``basis`` what the finding rests on: that UID, or ``schema``,
``reading``, ``plausibility`` or ``incomplete`` (:class:`~xodrcheck.findings.Basis`), never ``null``.
"""

from __future__ import annotations

import json
import math
from collections.abc import Sequence

from xodrcheck.findings import Finding
from xodrcheck.report import summary


def _number(v):
    return None if v is None or (isinstance(v, float) and not math.isfinite(v)) else v


def finding_dict(f: Finding) -> dict:
    return {
        "code": f.code,
        "name": f.name,
        "category": f.category.value,
        "severity": str(f.severity),
        "message": f.message,
        "road": f.road,
        "lane": f.lane,
        "s": _number(f.s),
        "x": _number(f.x),
        "y": _number(f.y),
        "z": _number(f.z),
        "line": f.line,
        "rule_uid": f.rule_uid,
        "basis": f.basis,
    }


def document(reports: Sequence) -> dict:
    return {
        "files": [
            {
                "path": r.path,
                "version": r.version,
                "ok": r.ok,
                "complete": r.complete,
                "findings": [finding_dict(f) for f in r.findings],
            }
            for r in reports
        ],
        "summary": summary(reports),
    }


def render(reports: Sequence) -> str:
    return json.dumps(document(reports), indent=2, allow_nan=False) + "\n"
