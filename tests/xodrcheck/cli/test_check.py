"""``xodrcheck check``: exit codes, rule selection, strictness, output files, tolerances and configuration."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from tests.xodrcheck.rules.helpers import fixture
from xodrcheck.cli import main

CLEAN = fixture("link-not-reciprocal", "pass.xodr")
BROKEN = fixture("road-link-target-missing", "fail.xodr")  # an R010 error + K001 (plausibility on 1.7: a warning)
WARNING_ONLY = fixture("short-lane-section", "fail.xodr")  # one G012 warning


def run(capsys, *args) -> tuple[int, str, str]:
    code = main(["check", *map(str, args)])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture(autouse=True)
def _no_project_config(tmp_path, monkeypatch):
    """Run from an empty folder so the repository's own pyproject does not configure the checks."""
    home = tmp_path / "cwd"
    home.mkdir()
    monkeypatch.chdir(home)


def test_exit_0_on_a_clean_map(capsys):
    """The report of a clean map is its verdict alone (issue 26: it was empty); stderr repeats it when stdout is not
    the terminal."""
    code, out, err = run(capsys, CLEAN)
    assert code == 0 and out == "PASS: 0 errors\n"
    assert err == "PASS: 0 errors\n"


def test_exit_1_on_an_error_and_one_line_per_finding(capsys):
    code, out, err = run(capsys, BROKEN)
    assert code == 1
    verdict, *lines = out.splitlines()
    assert verdict == "FAIL: 1 error of 1 rule; 1 warning"
    assert [line.split()[1] for line in lines] == ["R010", "K001"]  # by line
    assert all(line.startswith(f"{BROKEN}:") for line in lines)
    assert "Traceback" not in err


def test_exit_2_on_a_missing_file_and_the_others_are_still_checked(capsys, tmp_path):
    code, out, err = run(capsys, tmp_path / "nope.xodr", BROKEN)
    assert code == 2
    assert "cannot read" in err and "nope.xodr" in err and "Traceback" not in err
    assert "R010" in out


def test_exit_2_on_a_folder_without_maps(capsys, tmp_path):
    empty = tmp_path / "empty"
    empty.mkdir()
    code, _, err = run(capsys, empty)
    assert code == 2 and "without .xodr files" in err


def test_a_folder_stands_for_its_maps(capsys, tmp_path):
    folder = tmp_path / "maps"
    (folder / "sub").mkdir(parents=True)
    shutil.copy(CLEAN, folder / "a.xodr")
    shutil.copy(BROKEN, folder / "sub" / "b.xodr")
    code, out, _ = run(capsys, folder, "--format", "json")
    assert code == 1
    assert [Path(f["path"]).name for f in json.loads(out)["files"]] == ["a.xodr", "b.xodr"]


@pytest.mark.parametrize(
    ("flags", "expected_codes", "exit_code"),
    [
        (["--select", "R010"], {"R010"}, 1),
        (["--select", "reference"], {"R010"}, 1),
        (["--select", "link,R"], {"R010", "K001"}, 1),
        (["--select", "link", "--select", "R010"], {"R010", "K001"}, 1),
        (["--ignore", "R010,K001"], set(), 0),
        (["--ignore", "reference", "--ignore", "link"], set(), 0),
        (["--select", "R", "--ignore", "R010"], set(), 0),
    ],
)
def test_select_and_ignore(capsys, flags, expected_codes, exit_code):
    code, out, _ = run(capsys, BROKEN, "--format", "json", *flags)
    found = {f["code"] for f in json.loads(out)["files"][0]["findings"]}
    assert (found, code) == (expected_codes, exit_code)


@pytest.mark.parametrize("flags", [["--select", "Q999"], ["--ignore", "no-such-rule"], ["--select", ""]])
def test_unknown_selector_is_a_usage_error(capsys, flags):
    code, out, err = run(capsys, CLEAN, *flags)
    assert code == 2 and out == ""
    assert err.startswith("xodrcheck: check:") and "Traceback" not in err


def test_strict_makes_warnings_fail(capsys):
    assert run(capsys, WARNING_ONLY)[0] == 0
    assert run(capsys, WARNING_ONLY, "--strict")[0] == 1


@pytest.mark.parametrize(
    ("value", "message"),
    [
        ("position", "NAME=VALUE"),
        ("=1", "NAME=VALUE"),
        ("position=", "NAME=VALUE"),
        ("nonsense=1", "unknown tolerance 'nonsense'"),
        ("position=abc", "must be a number"),
        ("position=-1", ">= 0"),
        ("position=nan", ">= 0"),
    ],
)
def test_bad_tolerance_is_a_usage_error(capsys, value, message):
    code, out, err = run(capsys, CLEAN, "--tolerance", value)
    assert code == 2 and out == ""
    assert message in err and "Traceback" not in err


def test_good_tolerance_is_used(capsys):
    """A zero-width threshold of 5 m makes every lane "zero width", so the appearing full-width lane is accepted (L010
    is plausibility: the generator profile makes it an error)."""
    path = fixture("lane-not-continued", "fail.xodr")
    assert run(capsys, path, "--select", "L010", "--profile", "generator")[0] == 1
    widened = ("--tolerance", "zero_width=5", "--tolerance", "position=0.01")
    assert run(capsys, path, "--select", "L010", "--profile", "generator", *widened)[0] == 0


def test_output_file_is_written_whole_and_atomically(capsys, tmp_path):
    target = tmp_path / "out" / "report.json"
    target.parent.mkdir()
    target.write_text("old content", encoding="utf-8")
    code, out, err = run(capsys, BROKEN, "--format", "json", "-o", target)
    assert code == 1 and out == ""
    assert json.loads(target.read_text(encoding="utf-8"))["summary"]["errors"] == 1
    assert err.splitlines()[-1].startswith(f"wrote {target} (2 findings, ")
    assert sorted(p.name for p in target.parent.iterdir()) == ["report.json"]  # no temporary file left


def test_output_into_a_missing_folder_is_an_io_error(capsys, tmp_path):
    code, _, err = run(capsys, CLEAN, "-o", tmp_path / "missing" / "report.txt")
    assert code == 2 and "cannot write" in err and "Traceback" not in err


@pytest.mark.parametrize("fmt", ["text", "json", "junit", "sarif", "github"])
def test_every_format_keeps_the_exit_code(capsys, fmt):
    code, out, _ = run(capsys, BROKEN, "--format", fmt)
    assert code == 1 and out


def test_configuration_file_selects_and_flags_override(capsys):
    Path("xodrcheck.toml").write_text('ignore = ["K001"]\nstrict = true\n', encoding="utf-8")
    code, out, _ = run(capsys, BROKEN, "--format", "json")
    assert {f["code"] for f in json.loads(out)["files"][0]["findings"]} == {"R010"} and code == 1
    code, out, _ = run(capsys, BROKEN, "--format", "json", "--ignore", "R010")
    assert {f["code"] for f in json.loads(out)["files"][0]["findings"]} == {"K001"}
    assert run(capsys, WARNING_ONLY)[0] == 1  # strict from the file


def test_pyproject_tool_table_and_its_tolerances(capsys):
    Path("pyproject.toml").write_text(
        '[tool.xodrcheck]\nselect = ["L010"]\n[tool.xodrcheck.tolerances]\nzero_width = 5\n', encoding="utf-8"
    )
    assert run(capsys, fixture("lane-not-continued", "fail.xodr"))[0] == 0


@pytest.mark.parametrize("text", ["select = [\n", "select = [1]\n", "[tolerances]\nposition = -2\n"])
def test_bad_configuration_file_is_a_usage_error(capsys, text):
    Path("xodrcheck.toml").write_text(text, encoding="utf-8")
    code, out, err = run(capsys, CLEAN)
    assert code == 2 and out == "" and err.startswith("xodrcheck: check:") and "Traceback" not in err


def test_damaged_numbers_give_findings_not_numpy_warnings(tmp_path):
    """Widths near the float limit overflow inside the geometry; the user sees findings, not RuntimeWarnings."""
    import subprocess
    import sys

    path = tmp_path / "huge.xodr"
    path.write_text(
        '<?xml version="1.0" encoding="UTF-8"?>\n<OpenDRIVE><header revMajor="1" revMinor="7"/>'
        '<road id="1" length="50" junction="-1"><planView><geometry s="0" x="0" y="0" hdg="0" length="50">'
        '<arc curvature="0.05"/></geometry></planView><lanes><laneSection s="0"><center><lane id="0" type="none"/>'
        '</center><right><lane id="-1" type="driving"><width sOffset="0" a="-1e308" b="0" c="0" d="0"/></lane>'
        "</right></laneSection></lanes></road></OpenDRIVE>\n"
    )
    done = subprocess.run(
        [sys.executable, "-m", "xodrcheck", "check", str(path)], check=False, capture_output=True, text=True
    )
    assert done.returncode == 1
    assert "G010" in done.stdout
    assert "Warning" not in done.stderr and "Traceback" not in done.stderr


INFOS = fixture("redundant-record", "fail.xodr")  # infos only (G901)


def test_text_and_github_hide_infos_by_default_with_one_line_per_code(capsys):
    """Issue 18: the infos drowned the errors (463 ::notice lines for Town01). Text shows warnings and up and says in
    one line per code what it left out; github emits no notice; machine formats keep everything."""
    code, out, _ = run(capsys, INFOS)
    hidden = [line for line in out.splitlines() if line.startswith("(not shown)")]
    assert code == 0 and hidden and len(hidden) == len(out.splitlines()) - 1  # all but the verdict
    assert out.startswith("PASS: 0 errors; ") and " info\n" in out.splitlines(keepends=True)[0]
    assert hidden[0].startswith("(not shown) G901 redundant-record: ") and "--min-severity info lists them" in hidden[0]
    assert "::notice" not in run(capsys, INFOS, "--format", "github")[1]
    shown_all = run(capsys, INFOS, "--min-severity", "info")[1]
    assert "(not shown)" not in shown_all and " G901 info " in shown_all
    assert json.loads(run(capsys, INFOS, "--format", "json")[1])["files"][0]["findings"]
    assert "::notice" in run(capsys, INFOS, "--format", "github", "--min-severity", "info")[1]


def test_min_severity_error_keeps_what_fails_and_the_exit_code(capsys):
    code, out, _ = run(capsys, WARNING_ONLY, "--min-severity", "error")
    assert code == 0 and out.splitlines()[1].startswith("(not shown) G012 short-lane-section: 1 warning finding(s)")
    code, out, _ = run(capsys, WARNING_ONLY, "--min-severity", "error", "--strict")
    assert code == 1 and " G012 warning " in out  # a finding that fails the check is always shown
    doc = json.loads(run(capsys, BROKEN, "--format", "json", "--min-severity", "error")[1])
    assert {f["code"] for f in doc["files"][0]["findings"]} == {"R010"}


def test_min_severity_from_the_configuration_and_bad_values(capsys):
    Path("xodrcheck.toml").write_text('min_severity = "info"\n', encoding="utf-8")
    assert " G901 info " in run(capsys, INFOS)[1]
    Path("xodrcheck.toml").write_text('min_severity = "loud"\n', encoding="utf-8")
    code, _, err = run(capsys, INFOS)
    assert code == 2 and "min_severity must be one of info, warning, error" in err
    with pytest.raises(SystemExit):
        main(["check", str(INFOS), "--min-severity", "loud"])


@pytest.mark.parametrize(
    ("flags", "expected"),
    [
        (["--select", "info"], {("G901", "info")}),
        (["--select", "error"], set()),
        (["--ignore", "info"], set()),
        (["--select", "G9,info"], {("G901", "info")}),
        (["--select", "K,info"], set()),
    ],
)
def test_severities_are_selectors(capsys, flags, expected):
    """Issue 18: `--select info` was an unknown selector. A severity filters findings; with codes, both must match."""
    code, out, _ = run(capsys, INFOS, "--format", "json", *flags)
    found = {(f["code"], f["severity"]) for f in json.loads(out)["files"][0]["findings"]}
    assert code == 0 and found == expected


def test_profile_strict_is_one_option_away(capsys, tmp_path):
    """A 5 mm gap at a road link is a warning by default (under the 1 cm `gap`) and an error with --profile strict."""
    path = tmp_path / "gap.xodr"
    path.write_text(fixture("link-gap", "fail.xodr").read_text(encoding="utf-8").replace("100.05", "100.005"))
    code, out, _ = run(capsys, path, "--select", "K101")
    assert code == 0 and " K101 warning gap of 0.005 m" in out
    code, out, _ = run(capsys, path, "--select", "K101", "--profile", "strict")
    assert code == 1 and " K101 error gap of 0.005 m" in out
    assert run(capsys, path, "--select", "K101", "--tolerance", "gap=0.001")[0] == 1
    with pytest.raises(SystemExit):
        main(["check", str(path), "--profile", "lax"])
