"""``xodrcheck fix``: a dry run prints the diff and writes nothing; ``-o``/``--in-place`` write atomically; the summary
says per rule what was fixed and what is left; exit codes as ``check``'s for the fixed file. ``xodrcheck rules`` marks
the rules that have fixes, and the HTML report marks their findings."""

from __future__ import annotations

import json

from tests.xodrcheck.fix.test_fixes import ROAD1_LANE1, T_JUNCTION, damaged
from xodrcheck.cli import main

BROKEN = damaged(T_JUNCTION, ROAD1_LANE1, ROAD1_LANE1.replace(b"\n", b"\n            <link/>\n", 1))
GAP = damaged(
    BROKEN,
    b'<geometry s="0" x="-110" y="0" hdg="0" length="100"><line/></geometry>',
    b'<geometry s="0" x="-110" y="0" hdg="0" length="50"><line/></geometry>\n'
    b'      <geometry s="50" x="-59.996" y="0" hdg="0" length="50"><line/></geometry>',
)


def _file(tmp_path, data=BROKEN, name="map.xodr"):
    path = tmp_path / name
    path.write_bytes(data)
    return path


def test_a_dry_run_prints_the_diff_and_writes_nothing(tmp_path, capsys):
    path = _file(tmp_path)
    assert main(["fix", str(path)]) == 0  # the fixed file would have no error
    out, err = capsys.readouterr()
    assert out.startswith(f"--- {path}\n+++ {path}\n@@") and "-            <link/>\n" in out
    assert path.read_bytes() == BROKEN and sorted(p.name for p in tmp_path.iterdir()) == ["map.xodr"]
    assert "1 finding(s) fixed" in err and "fixed  L024 lane-link-not-omitted" in err and "nothing written" in err


def test_output_file_then_the_check_of_it(tmp_path, capsys):
    path, out_path = _file(tmp_path), tmp_path / "fixed.xodr"
    assert main(["fix", str(path), "-o", str(out_path)]) == 0
    out, err = capsys.readouterr()
    assert out_path.read_bytes() == T_JUNCTION and path.read_bytes() == BROKEN
    assert "---" not in out and f"wrote {out_path}" in err
    assert main(["fix", str(out_path), "-o", str(tmp_path / "again.xodr")]) == 0  # nothing to fix: the same bytes
    assert (tmp_path / "again.xodr").read_bytes() == T_JUNCTION and "unchanged" in capsys.readouterr().err


def test_in_place_on_several_files_and_the_exit_code_of_what_is_left(tmp_path, capsys):
    a, b = _file(tmp_path, BROKEN, "a.xodr"), _file(tmp_path, GAP, "b.xodr")
    strict = ["--profile", "strict"]  # a 4 mm gap is an error: b keeps it without --unsafe
    assert main(["fix", str(a), str(b), "--in-place", *strict]) == 1
    out, err = capsys.readouterr()
    assert a.read_bytes() == T_JUNCTION and b"<link/>" not in b.read_bytes() and b"-59.996" in b.read_bytes()
    assert "G001 error" in out and "left   G001 plan-view-gap" in err and "--unsafe applies it" in err
    assert main(["fix", str(b), "--in-place", "--unsafe", *strict]) == 0
    err = capsys.readouterr().err
    assert (
        b'x="-60.0"' in b.read_bytes()
        and "moved  road 1: moved the elements from s=50 on" in err
        and "by 0.004 m" in err
    )


def test_diff_select_ignore_and_json(tmp_path, capsys):
    path = _file(tmp_path, GAP)
    assert main(["fix", str(path), "--unsafe", "--select", "G001", "--diff", "-o", str(tmp_path / "o.xodr")]) == 0
    out = capsys.readouterr().out
    assert '+      <geometry s="50" x="-60.0" y="0.0"' in out and "<link/>" not in out
    assert b"<link/>" in (tmp_path / "o.xodr").read_bytes()
    assert main(["fix", str(path), "--ignore", "G001", "--format", "json", "-o", str(tmp_path / "p.xodr")]) == 0
    (entry,) = json.loads(capsys.readouterr().out)["files"]
    assert "G001" not in {f["code"] for f in entry["findings"]}  # ignored: neither fixed nor reported
    assert not [f for f in entry["findings"] if f["severity"] == "error"]
    assert entry["path"] == str(tmp_path / "p.xodr") and b"<link/>" not in (tmp_path / "p.xodr").read_bytes()


def test_usage_and_unreadable_files_exit_2_and_write_nothing(tmp_path, capsys):
    path = _file(tmp_path)
    assert main(["fix", str(path), str(path), "-o", str(tmp_path / "o.xodr")]) == 2
    assert "-o takes one FILE" in capsys.readouterr().err
    assert main(["fix", str(tmp_path / "missing.xodr"), "--in-place"]) == 2
    assert "cannot read" in capsys.readouterr().err
    assert main(["fix", str(path), "-o", str(tmp_path / "no" / "dir.xodr")]) == 2
    assert main(["fix", str(path), "--select", "Q999"]) == 2
    assert sorted(p.name for p in tmp_path.iterdir()) == ["map.xodr"] and path.read_bytes() == BROKEN


def test_rules_mark_the_fixable_and_describe_their_fixes(capsys):
    assert main(["rules"]) == 0
    lines = {line.split()[0]: line for line in capsys.readouterr().out.splitlines()}
    assert "fix:safe " in lines["L024"] and "fix:unsafe " in lines["G001"] and "fix:" not in lines["C001"]
    assert "fix:safe+unsafe" in lines["R012"]
    assert main(["rules", "G001"]) == 0
    out = capsys.readouterr().out
    assert "xodrcheck fix repairs its findings:" in out and "snap-plan-view-gap (unsafe;" in out and "--unsafe" in out
    assert main(["rules", "L024", "--format", "json"]) == 0
    item = json.loads(capsys.readouterr().out)
    assert item["fix"] == "safe" and [f["name"] for f in item["fixes"]] == [
        "remove-empty-lane-link",
        "remove-lane-link-into-junction",
    ]


def test_the_html_report_marks_fixable_findings(tmp_path, capsys):
    path = _file(tmp_path, GAP)
    assert main(["check", str(path), "-j", "1", "--format", "html", "-o", str(tmp_path / "r.html")]) == 1
    page = (tmp_path / "r.html").read_text(encoding="utf-8")
    assert 'data-code="L024"' in page and 'data-fixable="safe"' in page and 'data-fixable="unsafe"' in page
    assert 'class="xc-fix" title="xodrcheck fix has a safe fix for this rule"' in page
