"""The engine: reading, selecting rules, crash containment, the time budget, and the Report."""

from __future__ import annotations

import dataclasses
import gzip

import pytest

import xodrcheck
from tests.xodrcheck.rules.helpers import fixture
from xodrcheck.check import Report, check, is_valid, is_valid_reason
from xodrcheck.config import Config, ConfigError, Tolerances
from xodrcheck.findings import Category, Finding, Severity
from xodrcheck.rules import load_rules
from xodrcheck.rules.registry import RULES

CLEAN = fixture("link-not-reciprocal", "pass_junction.xodr")
BROKEN = fixture("road-link-target-missing", "fail.xodr")  # R010 error plus K001 (1.9 rule, 1.7 file: plausibility)
WARNING_ONLY = fixture("short-lane-section", "fail.xodr")  # one G012 warning


def codes(report: Report) -> set[str]:
    return {f.code for f in report.findings}


def test_library_names_are_exported():
    assert xodrcheck.check is check and xodrcheck.is_valid is is_valid and xodrcheck.Report is Report


def test_clean_map_report():
    report = check(CLEAN)
    assert report.ok and report.findings == ()
    assert report.path == str(CLEAN) and report.version == "1.7"
    run = set(report.rules_run)
    assert {"S001", "R010", "K001", "L010", "J005"} <= run  # check rules
    assert "X101" in run  # reader rules count as run
    assert "X900" not in run


def test_findings_are_sorted_by_line_then_code():
    report = check(BROKEN)
    keys = [(f.line or 0, f.code) for f in report.findings]
    assert keys == sorted(keys) and len(keys) >= 2
    assert not report.ok and report.errors == 1 and report.warnings == 1
    assert check(BROKEN, Config(profile="generator")).errors == len(report.findings)  # no bound: both errors


def test_strict_fails_on_warnings():
    assert check(WARNING_ONLY).ok
    report = check(WARNING_ONLY, Config(strict=True))
    assert not report.ok and report.warnings == 1


@pytest.mark.parametrize(
    ("select", "expected"),
    [
        (("R010",), {"R010"}),
        (("R",), {"R010"}),
        (("R01",), {"R010"}),
        (("link",), {"K001"}),
        (("road-link-target-missing",), {"R010"}),
        (("K001", "reference"), {"R010", "K001"}),
    ],
)
def test_select_by_code_prefix_name_or_category(select, expected):
    report = check(BROKEN, select=select)
    assert codes(report) == expected
    assert all(r in set(report.rules_run) for r in expected)


def test_ignore_removes_rules_and_overrides_config():
    assert codes(check(BROKEN, ignore=("K",))) == {"R010"}
    config = Config(ignore=("R010",))
    assert codes(check(BROKEN, config)) == {"K001"}
    assert codes(check(BROKEN, config, ignore=("K001",))) == {"R010"}  # the argument replaces the configured list


def test_select_and_ignore_apply_to_reader_findings():
    data = b"<!-- a comment first -->\n" + CLEAN.read_bytes()
    assert codes(check(data)) == {"X103"}
    assert codes(check(data, ignore=("X103",))) == set()
    assert codes(check(data, select=("reference",))) == set()


def test_unknown_selector_is_a_config_error():
    with pytest.raises(ConfigError, match="Z123"):
        check(CLEAN, select=("Z123",))
    with pytest.raises(ConfigError, match="no-such-rule"):
        check(CLEAN, ignore=("no-such-rule",))


def test_bytes_and_gzip_input():
    report = check(BROKEN.read_bytes())
    assert report.path is None and "R010" in codes(report)
    schema_fail = fixture("schema-invalid", "fail.xodr")
    assert "S001" in codes(check(gzip.compress(schema_fail.read_bytes())))


def test_a_rule_that_raises_becomes_an_x900_finding(monkeypatch):
    load_rules()
    original = RULES["R001"]

    def boom(ctx):
        yield original.finding("kept before the crash")
        raise ZeroDivisionError("division by zero in a rule")

    monkeypatch.setitem(RULES, "R001", dataclasses.replace(original, check=boom))
    report = check(CLEAN)
    crashed = [f for f in report.findings if f.code == "X900"]
    assert len(crashed) == 1
    assert "R001" in crashed[0].message and "ZeroDivisionError" in crashed[0].message
    assert crashed[0].severity is Severity.ERROR and not report.ok  # the default profile never lowers it
    assert crashed[0].basis == "incomplete"
    assert [f.message for f in report.findings if f.code == "R001"] == ["kept before the crash"]
    assert "J005" in report.rules_run  # the other rules still ran


def test_crash_is_reported_even_when_its_rule_family_is_selected_away(monkeypatch):
    load_rules()
    original = RULES["R001"]
    monkeypatch.setitem(RULES, "R001", dataclasses.replace(original, check=lambda ctx: 1 / 0))
    assert "X900" in codes(check(CLEAN, select=("R001",)))


def test_a_time_budget_set_and_spent_makes_the_check_incomplete_and_failed():
    """A bound the user sets trades completeness for time: the rules it skips are X901 errors, so the file is not
    valid (it used to be a warning: "0 error(s)" and exit 0 for a check that did not run)."""
    config = Config(tolerances=Tolerances(time_budget=1e-9))
    report = check(CLEAN, config)
    skipped = [f for f in report.findings if f.code == "X901"]
    assert skipped and all(f.severity is Severity.ERROR for f in skipped)
    assert "the check is incomplete" in skipped[0].message
    assert not [c for c in report.rules_run if c.startswith("R")]
    assert not report.complete and not report.ok
    assert not is_valid(CLEAN, config) and is_valid_reason(CLEAN, config).startswith("X901 rule-out-of-time")


def test_no_time_budget_by_default_so_the_verdict_does_not_depend_on_speed(monkeypatch):
    """A machine so slow that every rule starts hours after the file was read still runs every rule."""
    from xodrcheck.rules.shared import context

    clock = iter(range(0, 10**9, 3600))
    monkeypatch.setattr(context.time, "monotonic", lambda: float(next(clock)))
    assert Tolerances().time_budget == 0
    report = check(CLEAN)
    assert report.complete and report.ok and "X901" not in codes(report)
    assert {"R010", "K001", "O001"} <= set(report.rules_run)


def test_is_valid_of_a_missing_file_names_the_path(tmp_path):
    missing = tmp_path / "nowhere" / "map.xodr"
    with pytest.raises(xodrcheck.ReadError, match=f"cannot read {missing}: no such file"):
        is_valid(missing)


def test_not_well_formed_file_is_checked_as_far_as_it_was_read():
    report = check(b"<OpenDRIVE><header revMajor='1' revMinor='7'/><road")
    assert "X101" in codes(report) and not report.ok
    assert "X900" not in codes(report)
    assert "S001" in report.rules_run and "S001" not in codes(report)  # no schema errors on top of X101


def test_is_valid_and_reason():
    assert is_valid(CLEAN) and is_valid_reason(CLEAN) == "Valid OpenDRIVE"
    assert not is_valid(BROKEN)
    reason = is_valid_reason(BROKEN)
    assert reason.startswith("R010 road-link-target-missing:") and "line" in reason


def test_finding_fields_follow_the_rule():
    (f,) = [f for f in check(BROKEN).findings if f.code == "R010"]
    rule = load_rules()["R010"]
    assert isinstance(f, Finding)
    assert (f.name, f.category, f.severity) == (rule.name, Category.REFERENCE, rule.severity)


def test_footprint_union_stops_when_out_of_time():
    """A lane strip that folds over itself is united triangle block by triangle block; the time check between GEOS
    calls stops it (what makes a damaged 1e9 m spiral end near the budget instead of minutes past it)."""
    from xodrcheck.findings import OutOfTime
    from xodrcheck.mesh.footprint import OverlapIndex
    from xodrcheck.reader import read

    document = read(fixture("lane-fold", "fail.xodr")).document
    assert len(OverlapIndex(document).footprints.invalid) > 0  # the fold is united from triangles
    with pytest.raises(OutOfTime, match="footprints"):
        OverlapIndex(document, out_of_time=lambda: True)


def test_rule_stopped_by_the_budget_keeps_an_x901_error_not_a_crash(monkeypatch):
    """A rule interrupted part way (here: the overlap index while it unites a folded strip) reports X901 'stopped'."""
    from xodrcheck.rules.shared import context

    calls = {"n": 0}

    def out_of_time(self):
        calls["n"] += 1
        return calls["n"] > 1  # in time for the engine's check before O001, spent inside it

    monkeypatch.setattr(context.Context, "out_of_time", out_of_time)
    report = check(fixture("lane-fold", "fail.xodr"), select=("O001",))
    (stopped,) = [f for f in report.findings if f.code == "X901"]
    assert "O001 road-overlap stopped (building lane footprints)" in stopped.message
    assert stopped.severity is Severity.ERROR and not report.complete and not report.ok
    assert "X900" not in codes(report)


def test_library_check_of_damaged_numbers_gives_findings_not_numpy_warnings():
    """Library users (not only the command line) get findings for widths near the float limit, and no numpy
    RuntimeWarning (made errors here, so a warning fails the test)."""
    import warnings

    text = (
        '<?xml version="1.0" encoding="UTF-8"?>\n<OpenDRIVE><header revMajor="1" revMinor="7"/>'
        '<road id="1" length="50" junction="-1"><planView><geometry s="0" x="0" y="0" hdg="0" length="50">'
        '<arc curvature="0.05"/></geometry></planView><lanes><laneSection s="0"><center><lane id="0" type="none"/>'
        '</center><right><lane id="-1" type="driving"><width sOffset="0" a="-1e308" b="0" c="0" d="0"/></lane>'
        "</right></laneSection></lanes></road></OpenDRIVE>\n"
    )
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        report = check(text.encode())
    assert "G010" in {f.code for f in report.findings}
    assert not any(f.code.startswith("X90") for f in report.findings)
