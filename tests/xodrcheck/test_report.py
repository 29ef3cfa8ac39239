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

BROKEN = fixture("road-link-target-missing", "fail.xodr")
CLEAN = fixture("link-not-reciprocal", "pass.xodr")
TEXT_LINE = re.compile(
    r"^(?P<path>[^:]+):(?P<line>\d+): (?P<code>[A-Z]\d{3}) (?P<severity>error|warning|info) (?P<message>.+?)"
    r"(?: \[(?P<road>[^/\]]+)/(?P<lane>-?\d+|-)/(?P<s>-?\d+\.\d{3}|-)"
    r"(?: x=(?P<x>-?\d+\.\d{3}) y=(?P<y>-?\d+\.\d{3})(?: z=(?P<z>-?\d+\.\d{3}))?)?\])?"
    r"(?: \((?P<uid>asam\.net:xodr:[^)]+)\))?$"
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


def test_text_one_line_per_finding(reports):
    lines = render("text", reports).splitlines()
    assert len(lines) == sum(len(r.findings) for r in reports) > 0
    for line, f in zip(lines, reports[0].findings):
        m = TEXT_LINE.match(line)
        assert m, line
        assert (m["path"], int(m["line"]), m["code"], m["severity"]) == (str(BROKEN), f.line, f.code, str(f.severity))
        assert m["road"] == f.road
        assert m["uid"] == f.rule_uid  # the Annex F rule the finding enforces, where it has one
        assert (float(m["x"]), float(m["y"])) == pytest.approx((f.x, f.y), abs=5e-4)  # every place has coordinates


def test_text_location_bracket_and_single_line_message():
    lines = render("text", [odd_report()]).splitlines()
    assert len(lines) == 2
    assert lines[0] == "dir/a,b:c.xodr:12: R010 error 100% wrong: a, b and more [7/-2/1.500]"
    assert lines[1] == "dir/a,b:c.xodr:0: X203 info whole file"


def test_text_prints_coordinates_and_height_where_it_is_not_zero():
    """x, y of every place (issue 18: the text report gave ``[13/-3/1.383]`` only), z where the place is not at 0."""
    base = Finding("K104", "link-step", Category.LINK, Severity.ERROR, "steps", road="1", lane=-3, s=1.3832)
    placed = render("text", [Report("m.xodr", "1.7", (replace(base, x=12.3456, y=-7.0, z=5.0),), ())])
    flat = render("text", [Report("m.xodr", "1.7", (replace(base, x=12.3456, y=-7.0, z=0.0001),), ())])
    assert placed == "m.xodr:0: K104 error steps [1/-3/1.383 x=12.346 y=-7.000 z=5.000]\n"
    assert flat == "m.xodr:0: K104 error steps [1/-3/1.383 x=12.346 y=-7.000]\n"
    off_road = Finding("O001", "road-overlap", Category.OVERLAP, Severity.ERROR, "here", x=1.0, y=2.0)
    assert render("text", [Report("m.xodr", "1.7", (off_road,), ())]) == "m.xodr:0: O001 error here [x=1.000 y=2.000]\n"


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
    assert run["results"][0]["properties"] == {"road": "7", "lane": -2, "s": 1.5}


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
        "100%25 wrong: a, b%0Aand more [7/-2/1.500]"
    )
    assert lines[1] == "::notice file=dir/a%2Cb%3Ac.xodr,title=X203 missing-element::whole file"


def test_github_annotations_for_a_checked_file(reports):
    lines = render("github", reports).splitlines()
    assert len(lines) == 2 and all(line.startswith(f"::error file={BROKEN},line=") for line in lines)
