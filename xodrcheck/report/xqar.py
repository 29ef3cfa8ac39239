"""ASAM Quality Checker Framework results (``.xqar``): xodrcheck as a checker bundle beside ASAM's own.

The layout is the framework's report format (``CheckerResults`` > ``CheckerBundle`` > ``Checker`` > ``Issue`` >
``Locations``), as ``qc_baselib.Result`` reads it:

* one checker bundle per file, named ``xodrcheck`` (``xodrcheck: PATH`` when several files are reported), with the
  ``InputFile`` parameter;
* one checker per xodrcheck rule that ran or reported (``checkerId`` ``xodrcheck_<code>_<name>``, status
  ``completed``), addressing the UIDs its issues carry;
* one issue per finding: level 1 error, 2 warning, 3 information; ``ruleUID`` the Annex F UID the finding enforces,
  else the framework's own UID where xodrcheck's rule is the same check as ASAM's (``xml.valid_schema``, ...), else
  a UID of xodrcheck's own (``xodrcheck.local:xodr:1.4.0:<category>.<rule_name>``); locations: the file row, the
  XPath of the element that starts on that row, and the inertial x, y, z where the finding has a place;
* the basis, in the two places the format leaves to a checker: each issue's ``DomainSpecificInfo name="xodrcheck"``
  holds ``<Basis value="..."/>`` (the Annex F UID the finding enforces, or ``schema``, ``reading``,
  ``plausibility``: the framework's ``ruleUID`` cannot say that a check is the checker's own judgement), and each
  checker with issues a ``Metadata key="basis"`` listing what they rest on.

Two UIDs of the annex are not in the form the framework's schema accepts (``1.x.0`` is no version, and
``s-value_sum`` has a hyphen); they are written as ``1.9.0`` and ``s_value_sum``.

The file is written with lxml: ``asam-qc-baselib`` pins lxml < 6, which clashes with this project's lxml; the tests
load what is written here with ``qc_baselib.Result`` in ASAM's own environment.
"""

from __future__ import annotations

import datetime
import math
import re
from collections.abc import Sequence
from pathlib import Path

from lxml import etree

from xodrcheck.findings import Finding, Severity
from xodrcheck.rules import load_rules
from xodrcheck.rules.registry import Rule

REPORT_VERSION = "1.0.0"
LEVELS = {Severity.ERROR: "1", Severity.WARNING: "2", Severity.INFO: "3"}
#: xodrcheck rules that are the very check of ASAM's framework UIDs (``asam.net:xodr:1.0.0:xml.*``).
FRAMEWORK_UIDS = {
    "X101": "asam.net:xodr:1.0.0:xml.valid_xml_document",
    "X201": "asam.net:xodr:1.0.0:xml.root_tag_is_opendrive",
    "S001": "asam.net:xodr:1.0.0:xml.valid_schema",
}
OWN_ENTITY = "xodrcheck.local"
_UID_NAME = re.compile(r"[^\w.]")


def conform_uid(uid: str) -> str:
    """A UID in the form the framework's schema accepts (see the module's note on two annex UIDs)."""
    entity, standard, version, name = uid.split(":")
    if not re.fullmatch(r"[0-9]+(\.[0-9]+)+", version):
        version = "1.9.0"
    return f"{entity}:{standard}:{version}:{_UID_NAME.sub('_', name)}"


def own_uid(name: str, category: str) -> str:
    """The UID of one of xodrcheck's own rules (the standard has none for it)."""
    return f"{OWN_ENTITY}:xodr:1.4.0:{category.replace('-', '_')}.{name.replace('-', '_')}"


def issue_uid(f: Finding) -> str:
    if f.rule_uid is not None:
        return conform_uid(f.rule_uid)
    return FRAMEWORK_UIDS.get(f.code) or own_uid(f.name, f.category.value)


def _xpaths(path: str | None) -> dict[int, str]:
    """Row -> XPath of the first element that starts on it (empty when the file cannot be parsed)."""
    from xodrcheck.reader.xmlsafe import parse

    if path is None:
        return {}
    try:
        root, _ = parse(Path(path).read_bytes())
    except OSError:
        return {}
    if root is None:
        return {}
    tree = root.getroottree()
    out: dict[int, str] = {}
    for element in root.iter(etree.Element):
        if element.sourceline is not None and element.sourceline not in out:
            out[element.sourceline] = tree.getpath(element)
    return out


def _number(value: float | None) -> str | None:
    return None if value is None or not math.isfinite(value) else repr(float(value))


def _issue(checker: etree._Element, f: Finding, issue_id: int, xpaths: dict[int, str]) -> None:
    issue = etree.SubElement(
        checker,
        "Issue",
        issueId=str(issue_id),
        description=f"{f.code} {f.name}: {f.message}",
        level=LEVELS[f.severity],
        ruleUID=issue_uid(f),
    )
    where = []
    if f.line:
        where.append(("FileLocation", {"column": "0", "row": str(f.line)}))
        if f.line in xpaths:
            where.append(("XMLLocation", {"xpath": xpaths[f.line]}))
    x, y, z = _number(f.x), _number(f.y), _number(getattr(f, "z", None))
    if x is not None and y is not None:
        where.append(("InertialLocation", {"x": x, "y": y, "z": z or "0.0"}))
    if where:
        locations = etree.SubElement(issue, "Locations", description=f.message)
        for tag, attributes in where:
            etree.SubElement(locations, tag, attributes)
    info = etree.SubElement(issue, "DomainSpecificInfo", name="xodrcheck")
    etree.SubElement(info, "Basis", value=f.basis)


def _checker(bundle: etree._Element, code: str, rule: Rule | None, found: list[Finding]) -> etree._Element:
    name = rule.name if rule else found[0].name
    summary = rule.summary if rule else name
    checker = etree.SubElement(
        bundle,
        "Checker",
        status="completed",
        checkerId=f"xodrcheck_{code}_{name.replace('-', '_')}",
        description=summary.replace("``", ""),
        summary=f"{len(found)} issue(s) found.",
    )
    addressed = [conform_uid(uid) for uid in rule.uids] if rule else []
    for f in found:
        uid = issue_uid(f)
        if uid not in addressed:
            addressed.append(uid)
    if not addressed:  # a rule that found nothing and enforces no Annex F rule: its own UID
        addressed.append(FRAMEWORK_UIDS.get(code) or own_uid(name, rule.category.value if rule else "xml"))
    for uid in addressed:
        etree.SubElement(checker, "AddressedRule", ruleUID=uid)
    return checker


def _metadata(checker: etree._Element, found: list[Finding]) -> None:
    """What the issues of a checker with issues rest on, after them (as the framework's library writes it)."""
    if found:
        value = " ".join(dict.fromkeys(f.basis for f in found))
        etree.SubElement(checker, "Metadata", key="basis", value=value, description="what the issues rest on")


def document(reports: Sequence) -> etree._Element:
    from xodrcheck.report import tool_version

    rules = load_rules()
    root = etree.Element("CheckerResults", version=REPORT_VERSION)
    today = datetime.date.today().isoformat()
    for report in reports:
        by_code: dict[str, list[Finding]] = {}
        for f in report.findings:
            by_code.setdefault(f.code, []).append(f)
        codes = list(dict.fromkeys((*report.rules_run, *by_code)))
        name = "xodrcheck" if len(reports) == 1 else f"xodrcheck: {report.path or '-'}"
        bundle = etree.SubElement(
            root,
            "CheckerBundle",
            build_date=today,
            description="xodrcheck: OpenDRIVE conformance checks, the standard's Annex F checker rules among them",
            name=name,
            version=tool_version(),
            summary=f"{len(codes)} checker(s) completed; {len(report.findings)} issue(s) found.",
        )
        etree.SubElement(bundle, "Param", name="InputFile", value=report.path or "-")
        xpaths = _xpaths(report.path) if report.findings else {}
        issue_id = 0
        for code in codes:
            found = by_code.get(code, [])
            checker = _checker(bundle, code, rules.get(code), found)
            for f in found:
                _issue(checker, f, issue_id, xpaths)
                issue_id += 1
            _metadata(checker, found)
    return root


def render(reports: Sequence) -> str:
    root = document(reports)
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True).decode("utf-8")
