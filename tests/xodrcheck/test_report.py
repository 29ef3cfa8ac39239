"""Reporters: text line shape, JSON shape, SARIF structure, JUnit XML, GitHub workflow commands."""

from __future__ import annotations

import json
import re
from dataclasses import replace

import pytest
from lxml import etree

from tests.xodrcheck.rules.helpers import fixture
from xodrcheck.check import Report, check
from xodrcheck.config import Config
from xodrcheck.findings import Category, Finding, Severity
from xodrcheck.report import FORMATS, render
from xodrcheck.report.text import line

BROKEN = fixture("road-link-target-missing", "fail.xodr")
CLEAN = fixture("link-not-reciprocal", "pass.xodr")
TEXT_LINE = re.compile(
    r"^(?P<path>[^:]+):(?P<line>\d+): (?P<code>[A-Z]\d{3}) (?P<severity>error|warning|info) (?P<message>.+?)"
    r"(?: \[(?P<road>[^/\]]+)/(?P<lane>-?\d+|-)/(?P<s>-?\d+\.\d{3}|-)"
    r"(?: x=(?P<x>-?\d+\.\d{3}) y=(?P<y>-?\d+\.\d{3})(?: z=(?P<z>-?\d+\.\d{3}))?)?\])?"
    r" \((?P<basis>asam\.net:xodr:[^)]+|schema|reading|plausibility|incomplete)\)$"
)


@pytest.fixture(scope="module")
def reports() -> list[Report]:
    # the generator profile keeps K001 (a 1.9 rule on this 1.7 file: plausibility) an error beside R010
    return [check(BROKEN, Config(profile="generator")), check(CLEAN)]


def odd_report() -> Report:
    """Hand-made findings with characters the formats must escape, and no line."""
    f1 = Finding(
        "R010",
        "road-link-target-missing",
        Category.REFERENCE,
        Severity.ERROR,
        "100% wrong: a, b\nand more",
        road="7",
        lane=-2,
        s=1.5,
        line=12,
    )
    f2 = Finding("X203", "missing-element", Category.SCHEMA, Severity.INFO, "whole file")
    return Report(path="dir/a,b:c.xodr", version=None, findings=(f1, f2), rules_run=("R010",))


def test_every_format_renders(reports):
    for name in FORMATS:
        assert render(name, reports).endswith("\n")
    with pytest.raises(ValueError):
        render("xml", reports)


def finding_lines(text: str) -> list[str]:
    """The finding lines of a text report: after the verdict, before the first blank line (tally, failing files)."""
    return text.split("\n\n", 1)[0].splitlines()[1:]


def test_text_one_line_per_finding(reports):
    text = render("text", reports)
    assert text.startswith("FAIL: 2 errors of 2 rules in 1 of 2 files\n")  # the verdict first (issue 26)
    lines = finding_lines(text)
    assert len(lines) == sum(len(r.findings) for r in reports) > 0
    for text_line, f in zip(lines, reports[0].findings):
        m = TEXT_LINE.match(text_line)
        assert m, text_line
        assert (m["path"], int(m["line"]), m["code"], m["severity"]) == (str(BROKEN), f.line, f.code, str(f.severity))
        assert m["road"] == f.road
        assert m["basis"] == f.basis == (f.rule_uid or m["basis"])  # the Annex F rule it enforces, where it has one
        assert (float(m["x"]), float(m["y"])) == pytest.approx((f.x, f.y), abs=5e-4)  # every place has coordinates


def test_text_location_bracket_and_single_line_message():
    lines = render("text", [odd_report()]).splitlines()
    assert lines == [
        "FAIL: 1 error of 1 rule; 1 info",
        "dir/a,b:c.xodr:12: R010 error 100% wrong: a, b and more [7/-2/1.500] (plausibility)",
        "dir/a,b:c.xodr:0: X203 info whole file (plausibility)",
    ]


def test_text_prints_coordinates_and_height_where_it_is_not_zero():
    """x, y of every place (issue 18: the text report gave ``[13/-3/1.383]`` only), z where the place is not at 0."""
    base = Finding("K104", "link-step", Category.LINK, Severity.ERROR, "steps", road="1", lane=-3, s=1.3832)
    placed = line("m.xodr", replace(base, x=12.3456, y=-7.0, z=5.0))
    flat = line("m.xodr", replace(base, x=12.3456, y=-7.0, z=0.0001))
    assert placed == "m.xodr:0: K104 error steps [1/-3/1.383 x=12.346 y=-7.000 z=5.000] (plausibility)"
    assert flat == "m.xodr:0: K104 error steps [1/-3/1.383 x=12.346 y=-7.000] (plausibility)"
    off_road = Finding("O001", "road-overlap", Category.OVERLAP, Severity.ERROR, "here", x=1.0, y=2.0)
    assert line("m.xodr", off_road) == "m.xodr:0: O001 error here [x=1.000 y=2.000] (plausibility)"


def test_json_shape(reports):
    doc = json.loads(render("json", reports))
    assert set(doc) == {"files", "summary"}
    assert [f["path"] for f in doc["files"]] == [str(BROKEN), str(CLEAN)]
    first = doc["files"][0]
    assert first["version"] == "1.7" and first["ok"] is False
    for finding in first["findings"]:
        assert list(finding) == [
            "code",
            "name",
            "category",
            "severity",
            "message",
            "road",
            "lane",
            "s",
            "x",
            "y",
            "z",
            "line",
            "rule_uid",
            "basis",
        ]
        assert finding["basis"] == (finding["rule_uid"] or "plausibility"), finding
    assert doc["files"][1]["findings"] == []
    summary = doc["summary"]
    assert summary["files"] == 2 and summary["errors"] == len(first["findings"]) and summary["ok"] is False
    assert summary["by_code"] == {"K001": 1, "R010": 1}


def test_sarif_structure(reports):
    doc = json.loads(render("sarif", reports))
    assert doc["version"] == "2.1.0" and "sarif-2.1.0" in doc["$schema"]
    (run,) = doc["runs"]
    rules = run["tool"]["driver"]["rules"]
    ids = [r["id"] for r in rules]
    assert run["tool"]["driver"]["name"] == "xodrcheck" and len(ids) == len(set(ids))
    assert {"R010", "K001", "S001"} <= set(ids)
    for r in rules:
        assert r["shortDescription"]["text"] and r["defaultConfiguration"]["level"] in {"error", "warning", "note"}
    assert len(run["results"]) == 2
    for result in run["results"]:
        assert rules[result["ruleIndex"]]["id"] == result["ruleId"]
        assert result["level"] == "error" and result["message"]["text"]
        (location,) = result["locations"]
        physical = location["physicalLocation"]
        assert physical["artifactLocation"]["uri"] == BROKEN.as_uri()
        assert physical["region"]["startLine"] >= 1


def test_sarif_without_line_has_no_region_and_info_is_note():
    (run,) = json.loads(render("sarif", [odd_report()]))["runs"]
    info = run["results"][1]
    assert info["level"] == "note" and "region" not in info["locations"][0]["physicalLocation"]
    assert run["results"][0]["properties"] == {"road": "7", "lane": -2, "s": 1.5, "basis": "plausibility"}


def test_junit_parses_one_suite_per_file_one_case_per_rule(reports):
    root = etree.fromstring(render("junit", reports).encode("utf-8"))
    suites = root.findall("testsuite")
    assert [s.get("name") for s in suites] == [str(BROKEN), str(CLEAN)]
    broken, clean = suites
    assert len(broken.findall("testcase")) == len(reports[0].rules_run)
    failed = [c.get("name") for c in broken.findall("testcase") if c.find("failure") is not None]
    assert sorted(failed) == ["K001 link-not-reciprocal", "R010 road-link-target-missing"]
    assert broken.get("failures") == "2" and clean.get("failures") == "0"
    assert root.get("tests") == str(len(reports[0].rules_run) + len(reports[1].rules_run))


def test_junit_warnings_fail_only_in_strict_mode():
    path = fixture("short-lane-section", "fail.xodr")  # one warning
    for strict, failures in ((False, "0"), (True, "1")):
        root = etree.fromstring(render("junit", [check(path, Config(strict=strict))]).encode("utf-8"))
        assert root.find("testsuite").get("failures") == failures


def test_github_annotations_are_escaped():
    lines = render("github", [odd_report()]).splitlines()
    assert lines[0] == (
        "::error file=dir/a%2Cb%3Ac.xodr,line=12,title=R010 road-link-target-missing::"
        "100%25 wrong: a, b%0Aand more [7/-2/1.500] (plausibility)"
    )
    assert lines[1] == "::notice file=dir/a%2Cb%3Ac.xodr,title=X203 missing-element::whole file (plausibility)"


def test_github_annotations_for_a_checked_file(reports):
    lines = render("github", reports).splitlines()
    assert len(lines) == 2 and all(line.startswith(f"::error file={BROKEN},line=") for line in lines)


# ------------------------------------------------------------------------------------ issue 26: verdict and basis
def made(path: str, *findings: Finding, strict: bool = False) -> Report:
    return Report(path, "1.7", tuple(findings), tuple(dict.fromkeys(f.code for f in findings)), strict)


def finding(code: str, severity: Severity, uid: str | None = None) -> Finding:
    return Finding(code, f"rule-{code.lower()}", Category.LANE, severity, "m", rule_uid=uid)


UID = "asam.net:xodr:1.4.0:road.lane.link.no_link"


@pytest.mark.parametrize(
    ("reports", "unreadable", "expected"),
    [
        ([], 1, "FAIL: 1 file could not be checked"),
        ([made("a")], 0, "PASS: 0 errors"),
        ([made("a", finding("L001", Severity.INFO))], 0, "PASS: 0 errors; 1 info"),
        ([made("a", *[finding("L001", Severity.WARNING)] * 2)], 0, "PASS: 0 errors; 2 warnings"),
        (
            [made("a", finding("L001", Severity.ERROR)), made("b")],
            1,
            "FAIL: 1 of 3 files could not be checked; 1 error of 1 rule in 1 of 2 files",
        ),
        (
            [made("a", finding("X900", Severity.ERROR))],
            0,
            "INCOMPLETE: 1 rule did not run to its end (X900/X901), so the verdict is not known; no other error",
        ),
        (
            [made("a", finding("X901", Severity.ERROR), finding("L001", Severity.ERROR)), made("b")],
            0,
            "FAIL: 1 error of 1 rule in 1 of 2 files; incomplete: 1 rule did not run to its end in 1 of 2 files "
            "(X900/X901)",
        ),
        (
            [made("a", finding("L001", Severity.ERROR), finding("L002", Severity.WARNING), strict=True)],
            0,
            "FAIL: 1 error and 1 warning of 2 rules (strict)",
        ),
    ],
)
def test_verdict_lines(reports, unreadable, expected):
    from xodrcheck.report.verdict import verdict

    assert verdict(reports, unreadable) == expected


def test_tally_names_the_bases_of_a_rule_most_frequent_first():
    from xodrcheck.report.text import tally

    uids = [f"asam.net:xodr:1.4.0:road.x{k}" for k in range(4)]
    report = made("a", *(finding("L013", Severity.ERROR, uid) for uid in (uids[0], uids[1], uids[1], uids[2], uids[3])))
    rows = [row.split() for row in tally([report]).strip().splitlines()[1:]]
    assert rows[1][:4] == ["5", "L013", "error", "rule-l013"]
    assert " ".join(rows[1][4:]) == f"{uids[1]}, {uids[0]} (+2 more)"


def test_sarif_rules_say_their_basis_and_render_their_help(reports):
    (run,) = json.loads(render("sarif", reports))["runs"]
    rules = {r["id"]: r for r in run["tool"]["driver"]["rules"]}
    r010 = rules["R010"]
    assert r010["properties"]["basis"][0] == "asam.net:xodr:1.4.0:ids.only_ref_defined_ids"
    assert "annex-f" in r010["properties"]["tags"]
    assert r010["help"]["text"].endswith(f"Basis: {', '.join(r010['properties']['basis'])}.")
    markdown = r010["help"]["markdown"]
    assert "```xml\n<" in markdown and "::" not in markdown.replace("```", "")  # literal blocks fenced, not ``::``
    for result in run["results"]:
        assert result["properties"]["basis"] in rules[result["ruleId"]]["properties"]["basis"]


def test_xqar_issues_carry_their_basis_as_domain_specific_info(reports):
    root = etree.fromstring(render("xqar", reports).encode("utf-8"))
    issues = root.findall(".//Issue")
    assert len(issues) == sum(len(r.findings) for r in reports)
    for issue, f in zip(issues, [f for r in reports for f in r.findings]):
        (info,) = issue.findall("DomainSpecificInfo")
        assert info.get("name") == "xodrcheck" and info.find("Basis").get("value") == f.basis
        assert list(issue)[-1] is info  # after the locations, as the framework's schema orders them
        checker = issue.getparent()
        (meta,) = checker.findall("Metadata")
        assert meta.get("key") == "basis" and f.basis in meta.get("value").split()
        assert list(checker)[-1] is meta
    assert all(not c.findall("Metadata") for c in root.iter("Checker") if not c.findall("Issue"))


def test_junit_cases_with_findings_carry_their_basis(reports):
    root = etree.fromstring(render("junit", reports).encode("utf-8"))
    for case in root.iter("testcase"):
        props = case.findall("properties/property")
        if case.find("failure") is None and case.find("system-out") is None:
            assert props == []
            continue
        (prop,) = props
        assert prop.get("name") == "basis" and prop.get("value")
        assert f"({prop.get('value').split()[0]})" in case.find("failure").text
