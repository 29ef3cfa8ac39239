"""SARIF 2.1.0: one run of the tool ``xodrcheck`` over all files.

``tool.driver.rules`` lists every rule applied or reported (id = code, name, short and full description, default
level, the UIDs of the standard's checker rules it enforces and a ``helpUri`` to the standard's annex of checker
rules); each result names its rule, level, message, ``physicalLocation`` (the file and, when known, the line) and, in
its properties, where on the map and the ``rule_uid`` it enforces.
"""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from pathlib import Path

from xodrcheck.findings import Finding, Severity
from xodrcheck.rules import load_rules
from xodrcheck.standard import ANNEX_URL

SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
LEVELS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}


def _uri(path: str | None) -> str:
    if path is None:
        return "-"
    p = Path(path)
    return p.as_uri() if p.is_absolute() else p.as_posix()


def _tool_version() -> str:
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("junctionart")
    except PackageNotFoundError:  # pragma: no cover - running from a source tree without metadata
        return "0"


def _result(f: Finding, uri: str, index: int) -> dict:
    physical: dict = {"artifactLocation": {"uri": uri}}
    if f.line:
        physical["region"] = {"startLine": f.line}
    result = {
        "ruleId": f.code,
        "ruleIndex": index,
        "level": LEVELS[f.severity],
        "message": {"text": f.message},
        "locations": [{"physicalLocation": physical}],
    }
    fields = (
        ("road", f.road),
        ("lane", f.lane),
        ("s", f.s),
        ("x", f.x),
        ("y", f.y),
        ("z", f.z),
        ("rule_uid", f.rule_uid),
    )
    where = {k: v for k, v in fields if v is not None and not (isinstance(v, float) and not math.isfinite(v))}
    if where:
        result["properties"] = where
    return result


def document(reports: Sequence) -> dict:
    rules = load_rules()
    codes: list[str] = []
    for report in reports:
        for code in (*report.rules_run, *(f.code for f in report.findings)):
            if code not in codes:
                codes.append(code)
    index = {code: i for i, code in enumerate(codes)}
    descriptors = []
    for code in codes:
        rule = rules.get(code)
        if rule is None:  # a finding of a rule that is not registered: describe it from the finding
            first = next(f for r in reports for f in r.findings if f.code == code)
            descriptors.append({"id": code, "name": first.name, "shortDescription": {"text": first.name}})
            continue
        descriptors.append(
            {
                "id": rule.code,
                "name": rule.name,
                "shortDescription": {"text": rule.summary},
                "fullDescription": {"text": rule.doc or rule.summary},
                "defaultConfiguration": {"level": LEVELS[rule.severity]},
                "properties": {"category": rule.category.value, "uids": list(rule.uids)},
                **({"helpUri": ANNEX_URL} if rule.uids else {}),
            }
        )
    results = [_result(f, _uri(r.path), index[f.code]) for r in reports for f in r.findings]
    return {
        "$schema": SCHEMA,
        "version": "2.1.0",
        "runs": [
            {
                "tool": {"driver": {"name": "xodrcheck", "version": _tool_version(), "rules": descriptors}},
                "artifacts": [{"location": {"uri": _uri(r.path)}} for r in reports],
                "results": results,
            }
        ],
    }


def render(reports: Sequence) -> str:
    return json.dumps(document(reports), indent=2) + "\n"
