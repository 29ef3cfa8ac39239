"""JUnit XML: one ``<testsuite>`` per file, one ``<testcase>`` per rule applied to it.

A rule's test case fails (``<failure>``) when it gave a finding that fails the check (an error; a warning too in
strict mode); its other findings are listed in the case's ``<system-out>``, one text line each (ending with its basis).
A case with findings has the property ``basis``: what they rest on (Annex F UIDs, ``schema``, ``reading``,
``plausibility``). CI systems show the result as a test view.
"""

from __future__ import annotations

from collections.abc import Sequence

from lxml import etree

from xodrcheck.findings import Severity
from xodrcheck.report.text import line
from xodrcheck.rules import load_rules


def render(reports: Sequence) -> str:
    rules = load_rules()
    root = etree.Element("testsuites", name="xodrcheck")
    total = failed = 0
    for report in reports:
        worst = Severity.WARNING if report.strict else Severity.ERROR
        by_code: dict[str, list] = {}
        for f in report.findings:
            by_code.setdefault(f.code, []).append(f)
        codes = list(report.rules_run) + [c for c in by_code if c not in report.rules_run]
        suite = etree.SubElement(root, "testsuite", name=report.path or "-")
        suite_failures = 0
        for code in codes:
            rule = rules.get(code)
            name = rule.name if rule else by_code[code][0].name
            case = etree.SubElement(suite, "testcase", classname=report.path or "-", name=f"{code} {name}")
            found = by_code.get(code, [])
            if found:
                properties = etree.SubElement(case, "properties")
                etree.SubElement(
                    properties, "property", name="basis", value=" ".join(dict.fromkeys(f.basis for f in found))
                )
            failing = [f for f in found if f.severity >= worst]
            if failing:
                suite_failures += 1
                failure = etree.SubElement(
                    case, "failure", message=failing[0].message, type=str(max(f.severity for f in failing))
                )
                failure.text = "".join(line(report.path, f) + "\n" for f in failing)
            others = [f for f in found if f.severity < worst]
            if others:
                etree.SubElement(case, "system-out").text = "".join(line(report.path, f) + "\n" for f in others)
        suite.set("tests", str(len(codes)))
        suite.set("failures", str(suite_failures))
        suite.set("errors", "0")
        total += len(codes)
        failed += suite_failures
    root.set("tests", str(total))
    root.set("failures", str(failed))
    root.set("errors", "0")
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True).decode("utf-8")
