"""SARIF 2.1.0: one run of the tool ``xodrcheck`` over all files.

``tool.driver.rules`` lists every rule applied or reported (id = code, name, short and full description, ``help``
as text and Markdown ending with the rule's basis, default level, and in its properties the UIDs of the standard's
checker rules it enforces, its ``basis`` (those UIDs, and ``schema``, ``reading`` or ``plausibility`` for findings
without one) and ``tags`` (``annex-f``, ``schema``, ``reading``, ``plausibility``: code-scanning tools filter on
them), and a ``helpUri`` to the standard's annex of checker rules); each result names its rule, level, message,
``physicalLocation`` (the file and, when known, the line) and, in its properties, where on the map, the ``rule_uid``
it enforces and its ``basis``.
"""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from pathlib import Path

from xodrcheck.findings import Finding, Severity
from xodrcheck.report import rule_bases, tool_version
from xodrcheck.rules import load_rules
from xodrcheck.rules.registry import Rule
from xodrcheck.rules.shared.docformat import markdown
from xodrcheck.rules.shared.plaintext import plain
from xodrcheck.standard import ANNEX_URL

SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"
LEVELS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}


def _uri(path: str | None) -> str:
    if path is None:
        return "-"
    p = Path(path)
    return p.as_uri() if p.is_absolute() else p.as_posix()


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
        ("basis", f.basis),
    )
    where = {k: v for k, v in fields if v is not None and not (isinstance(v, float) and not math.isfinite(v))}
    if where:
        result["properties"] = where
    return result


def _tag(basis: str) -> str:
    return "annex-f" if basis.count(":") == 3 else basis


def _descriptor(code: str, rule: Rule | None, found: list[Finding]) -> dict:
    bases = rule_bases(rule, found)
    said = f"Basis: {', '.join(bases)}." if bases else ""
    properties = {"basis": bases, "tags": list(dict.fromkeys(_tag(b) for b in bases))}
    if rule is None:  # a finding of a rule that is not registered: describe it from the finding
        name = found[0].name
        return {"id": code, "name": name, "shortDescription": {"text": name}, "properties": properties}
    return {
        "id": rule.code,
        "name": rule.name,
        "shortDescription": {"text": rule.summary},
        "fullDescription": {"text": rule.doc or rule.summary},
        "help": {"text": f"{plain(rule.doc)}\n\n{said}".strip(), "markdown": f"{markdown(rule.doc)}\n{said}".strip()},
        "defaultConfiguration": {"level": LEVELS[rule.severity]},
        "properties": {"category": rule.category.value, "uids": list(rule.uids), **properties},
        **({"helpUri": ANNEX_URL} if rule.uids else {}),
    }


def document(reports: Sequence) -> dict:
    rules = load_rules()
    found: dict[str, list[Finding]] = {}
    for report in reports:
        for code in report.rules_run:
            found.setdefault(code, [])
        for f in report.findings:
            found.setdefault(f.code, []).append(f)
    index = {code: i for i, code in enumerate(found)}
    descriptors = [_descriptor(code, rules.get(code), items) for code, items in found.items()]
    results = [_result(f, _uri(r.path), index[f.code]) for r in reports for f in r.findings]
    return {
        "$schema": SCHEMA,
        "version": "2.1.0",
        "runs": [
            {
                "tool": {"driver": {"name": "xodrcheck", "version": tool_version(), "rules": descriptors}},
                "artifacts": [{"location": {"uri": _uri(r.path)}} for r in reports],
                "results": results,
            }
        ],
    }


def render(reports: Sequence) -> str:
    return json.dumps(document(reports), indent=2) + "\n"
