"""``xodrcheck check``'s text report as a user reads it (issue 26): the verdict first, the tally per rule, the failing
files of a run over several, and what ``-o`` says on stderr."""

from __future__ import annotations

import os
import re
import shutil
import sys

import pytest

from tests.xodrcheck.cli.maps import TWO_LANES, document, line, road
from tests.xodrcheck.rules.helpers import fixture
from xodrcheck.cli import main

CLEAN = fixture("link-not-reciprocal", "pass.xodr")
BROKEN = fixture("road-link-target-missing", "fail.xodr")  # an R010 error; K001, a plausibility warning by default
WARNING_ONLY = fixture("short-lane-section", "fail.xodr")  # one G012 warning, one G901 info
MISSING = "a successor that does not exist"


def run(capsys, *args) -> tuple[int, str, str]:
    code = main(["check", *map(str, args)])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture(autouse=True)
def _no_project_config(tmp_path, monkeypatch):
    home = tmp_path / "cwd"
    home.mkdir()
    monkeypatch.chdir(home)


@pytest.fixture
def many(tmp_path):
    """23 roads whose successor does not exist: 23 R010 errors (``--select R010``), over the tally's threshold."""
    link = '<successor elementType="road" elementId="99" contactPoint="start"/>'
    roads = [road(str(i), 10, line(0, 20 * i, 0, 10), TWO_LANES, link=link) for i in range(1, 24)]
    path = tmp_path / "many.xodr"
    path.write_text(document(*roads), encoding="utf-8")
    return path


# ----------------------------------------------------------------------------------------------------- the verdict
@pytest.mark.parametrize(
    ("files", "flags", "first", "exit_code"),
    [
        ([CLEAN], [], "PASS: 0 errors", 0),
        ([WARNING_ONLY], [], "PASS: 0 errors; 1 warning, 1 info", 0),
        ([BROKEN], [], "FAIL: 1 error of 1 rule; 1 warning", 1),
        ([CLEAN, WARNING_ONLY], [], "PASS: 0 errors in 2 files; 1 warning, 1 info", 0),
        ([BROKEN, CLEAN, WARNING_ONLY, CLEAN], [], "FAIL: 1 error of 1 rule in 1 of 4 files; 2 warnings, 1 info", 1),
        ([BROKEN, WARNING_ONLY], ["--select", "R010"], "FAIL: 1 error of 1 rule in 1 of 2 files", 1),
        ([WARNING_ONLY], ["--strict"], "FAIL: 1 warning of 1 rule (strict); 1 info", 1),
        ([CLEAN], ["--strict"], "PASS: 0 errors, 0 warnings (strict)", 0),
    ],
)
def test_the_first_line_is_the_verdict(capsys, files, flags, first, exit_code):
    code, out, err = run(capsys, *files, *flags)
    assert out.splitlines()[0] == first and code == exit_code
    assert err.splitlines() == [first]  # stdout is not a terminal here: stderr says it too


def test_a_file_that_cannot_be_read_fails_the_verdict(capsys, tmp_path):
    missing = tmp_path / "nope.xodr"
    code, out, _ = run(capsys, missing, CLEAN)
    assert code == 2 and out.splitlines()[0] == "FAIL: 1 of 2 files could not be checked; 0 errors in 1 file"
    code, out, _ = run(capsys, missing)
    assert code == 2 and out.splitlines()[0] == "FAIL: 1 file could not be checked"


def test_an_incomplete_check_says_so_first(capsys):
    code, out, _ = run(capsys, CLEAN, "--tolerance", "time_budget=1e-9", "-j", "1")
    assert code == 3
    assert re.fullmatch(
        r"INCOMPLETE: \d+ rules? did not run to (its|their) end \(X900/X901\), so the verdict is not known; "
        r"no other error",
        out.splitlines()[0],
    )


def test_the_verdict_stays_off_stderr_when_the_terminal_shows_the_whole_report(capsys, monkeypatch, many):
    """On a 24-line terminal a 3-line report keeps its verdict in sight; a longer one has it repeated last."""
    monkeypatch.setattr(sys.stdout, "isatty", lambda: True)
    monkeypatch.setattr(shutil, "get_terminal_size", lambda *a, **k: os.terminal_size((80, 24)))
    code, out, err = run(capsys, BROKEN)
    assert code == 1 and out.startswith("FAIL: 1 error of 1 rule; 1 warning\n") and err == ""
    code, out, err = run(capsys, many, "--select", "R010")
    assert out.count("\n") > 24 and err == out.splitlines()[0] + "\n" == "FAIL: 23 errors of 1 rule\n"


@pytest.mark.parametrize("fmt", ["json", "sarif", "github"])
def test_machine_formats_keep_stdout_and_give_the_verdict_on_stderr(capsys, fmt):
    code, out, err = run(capsys, BROKEN, "--format", fmt)
    assert code == 1 and not out.startswith("FAIL") and err == "FAIL: 1 error of 1 rule; 1 warning\n"


# ------------------------------------------------------------------------------------------------------ statistics
def tally(out: str) -> list[list[str]]:
    """The rows of the tally (header first), split on runs of spaces; empty when there is none."""
    if "\nfindings shown, per rule:\n" not in out:
        return []
    block = out.split("\nfindings shown, per rule:\n", 1)[1].split("\n\n", 1)[0]
    return [row.split() for row in block.splitlines()]


def test_statistics_are_on_by_default_above_20_findings_shown(capsys, many):
    code, out, _ = run(capsys, many, "--select", "R010")
    assert code == 1
    assert tally(out) == [
        ["count", "code", "severity", "name", "basis"],
        ["23", "R010", "error", "road-link-target-missing", "asam.net:xodr:1.4.0:ids.only_ref_defined_ids"],
    ]
    assert tally(run(capsys, many, "--select", "R010", "--no-statistics")[1]) == []


def test_statistics_are_off_by_default_for_few_findings_and_can_be_forced(capsys):
    assert tally(run(capsys, BROKEN)[1]) == []
    rows = tally(run(capsys, BROKEN, CLEAN, "--statistics")[1])
    assert rows[0] == ["count", "files", "code", "severity", "name", "basis"]
    assert sorted(row[2] for row in rows[1:]) == ["K001", "R010"]
    assert all(row[:2] == ["1", "1"] for row in rows[1:])
    assert sorted((row[2], row[3]) for row in rows[1:]) == [("K001", "warning"), ("R010", "error")]


def test_statistics_count_what_is_shown_and_the_worst_first(capsys):
    rows = tally(run(capsys, WARNING_ONLY, BROKEN, "--statistics")[1])
    assert [row[3] for row in rows[1:]] == ["error", "warning", "warning"]  # the info is not shown: not counted
    rows = tally(run(capsys, WARNING_ONLY, "--statistics", "--min-severity", "info")[1])
    assert [(row[1], row[2]) for row in rows[1:]] == [("G012", "warning"), ("G901", "info")]


# --------------------------------------------------------------------------------------------------- failing files
def failing(out: str) -> tuple[str, list[str]]:
    head, _, rows = out.rpartition("\nfailing files ")[2].partition(":\n")
    return head, rows.splitlines()


def test_a_run_over_several_files_ends_with_the_failing_ones(capsys, tmp_path):
    missing = tmp_path / "nope.xodr"
    code, out, _ = run(capsys, CLEAN, BROKEN, WARNING_ONLY, missing)
    assert code == 2
    assert failing(out) == ("(2 of 4)", [f"  {BROKEN}: 1 error", f"  {missing}: could not be checked"])
    code, out, _ = run(capsys, CLEAN, WARNING_ONLY, BROKEN, "--strict")
    assert failing(out) == ("(2 of 3)", [f"  {WARNING_ONLY}: 0 errors, 1 warning", f"  {BROKEN}: 1 error, 1 warning"])


def test_no_failing_files_list_for_one_file_or_when_all_pass(capsys):
    assert "failing files" not in run(capsys, BROKEN)[1]
    assert "failing files" not in run(capsys, CLEAN, WARNING_ONLY)[1]


# --------------------------------------------------------------------------------------------------------------- -o
@pytest.mark.parametrize(("fmt", "suffix"), [("text", "txt"), ("html", "html"), ("xqar", "xqar"), ("junit", "xml")])
def test_output_file_is_named_on_stderr_and_stdout_stays_empty(capsys, tmp_path, fmt, suffix):
    target = tmp_path / f"report.{suffix}"
    code, out, err = run(capsys, BROKEN, WARNING_ONLY, "--format", fmt, "-o", target)
    assert code == 1 and out == ""
    verdict, wrote = err.splitlines()
    assert verdict == "FAIL: 1 error of 1 rule in 1 of 2 files; 2 warnings, 1 info"
    shown = 3 if fmt == "text" else 4  # text leaves the info out by default
    assert re.fullmatch(rf"wrote {re.escape(str(target))} \({shown} findings, \d+(\.\d)? (B|KiB|MiB)\)", wrote), wrote
    if fmt == "text":
        assert target.read_text(encoding="utf-8").splitlines()[0] == verdict
