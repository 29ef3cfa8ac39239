"""The rules every ``xodrcheck`` command follows (the README's table): an input that cannot be read whole is exit 2
with one line and no output; ``-o`` errors name the user's path and the cause; output files are written whole or not
at all, also on SIGTERM; output sizes are bounded."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests.xodrcheck.cli import maps
from xodrcheck.analysis.sample import sample_count
from xodrcheck.cli import main
from xodrcheck.reader import read
from xodrcheck.support.atomic import EXIT_TERMINATED, OutputError, Terminated, atomic_file, signals_raise

REPO = Path(__file__).resolve().parents[3]
T_JUNCTION = (REPO / "examples" / "t-junction.xodr").read_bytes()

#: Inputs that cannot be read whole, and the reader finding that says why.
UNREADABLE = {
    "empty": (b"", "X101"),
    "binary": (bytes(range(256)) * 8, "X101"),
    "truncated": (T_JUNCTION[: len(T_JUNCTION) // 2], "X101"),
    "not-opendrive": (b'<?xml version="1.0"?>\n<svg><road/></svg>\n', "X201"),
    "entity-references": (
        T_JUNCTION.replace(b"<OpenDRIVE", b'<!DOCTYPE OpenDRIVE [<!ENTITY n "x">]>\n<OpenDRIVE', 1).replace(
            b'name="', b'name="&n;', 1
        ),
        "X102",
    ),
}


def _snapshot(tmp_path: Path) -> Path:
    good = tmp_path / "good.xodr"
    good.write_bytes(T_JUNCTION)
    snap = tmp_path / "good.json"
    assert main(["snapshot", str(good), "-o", str(snap)]) == 0
    good.unlink()
    return snap


#: Every command that turns a map into data: its arguments for input SRC and output OUT (folder TMP).
DATA_COMMANDS = {
    "info": lambda src, out, tmp: ["info", src],
    "info-json": lambda src, out, tmp: ["info", "--format", "json", src],
    "sample": lambda src, out, tmp: ["sample", src, "--step", "5", "-o", out + ".csv"],
    "sample-stdout": lambda src, out, tmp: ["sample", src, "--step", "5"],
    "mesh": lambda src, out, tmp: ["mesh", src, "-o", out + ".glb"],
    "view": lambda src, out, tmp: ["view", src, "-o", out + ".html"],
    "metrics": lambda src, out, tmp: ["metrics", src, "-o", out + ".csv"],
    "metrics-stdout": lambda src, out, tmp: ["metrics", src],
    "snapshot": lambda src, out, tmp: ["snapshot", src, "-o", out + ".json"],
    "diff": lambda src, out, tmp: ["diff", str(_snapshot(tmp)), src],
    "graph": lambda src, out, tmp: ["graph", src, "-o", out + ".json"],
    "graph-stdout": lambda src, out, tmp: ["graph", src, "--format", "dot"],
    "route": lambda src, out, tmp: ["route", src, "--from", "1:-1", "--to", "2:-1", "-o", out + ".txt"],
}


@pytest.mark.parametrize("command", sorted(DATA_COMMANDS))
@pytest.mark.parametrize("kind", sorted(UNREADABLE))
def test_an_input_that_cannot_be_read_whole_is_exit_2_one_line_and_no_output(tmp_path, capsys, command, kind):
    """Was: an empty file exit 1 from info/sample/mesh but 2 from metrics/snapshot, a CSV header printed before exit 2,
    a partial .glb from a truncated file."""
    data, code = UNREADABLE[kind]
    src = tmp_path / f"{kind}.xodr"
    src.write_bytes(data)
    argv = DATA_COMMANDS[command](str(src), str(tmp_path / "out"), tmp_path)
    before = sorted(p.name for p in tmp_path.iterdir())
    capsys.readouterr()
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.count("\n") == 1 and f"cannot read {src} whole" in err and code in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == before  # no output file, no temporary file


@pytest.mark.parametrize("kind", sorted(UNREADABLE))
def test_check_reports_such_an_input_as_a_finding(tmp_path, capsys, kind):
    """``check`` judges the file: what the data commands refuse is a finding there (exit 1), not an I/O error."""
    data, code = UNREADABLE[kind]
    src = tmp_path / "x.xodr"
    src.write_bytes(data)
    assert main(["check", str(src)]) == 1
    assert code in capsys.readouterr().out


#: Every command with ``-o``: its arguments for output OUT, on the readable example map SRC.
WRITERS = {
    "check": lambda src, out: ["check", src, "-o", out],
    "sample": lambda src, out: ["sample", src, "--step", "5", "-o", out],
    "mesh": lambda src, out: ["mesh", src, "-o", out],
    "view": lambda src, out: ["view", src, "-o", out],
    "metrics": lambda src, out: ["metrics", src, "-o", out],
    "snapshot": lambda src, out: ["snapshot", src, "-o", out],
    "graph": lambda src, out: ["graph", src, "-o", out],
    "route": lambda src, out: ["route", src, "--from", "1:-1", "--to", "2:-1", "-o", out],
}
SUFFIX = {"mesh": ".glb"}


def _good(tmp_path: Path) -> str:
    src = tmp_path / "map.xodr"
    src.write_bytes(T_JUNCTION)
    return str(src)


@pytest.mark.parametrize("command", sorted(WRITERS))
def test_output_in_a_folder_where_no_file_can_be_created_names_the_users_path(tmp_path, capsys, command):
    """Was: "/proc/.x.xodr.xjuyv1bv.tmp: No such file or directory" (the temporary file, not the user's path)."""
    target = "/proc/out" + SUFFIX.get(command, ".txt")
    assert main(WRITERS[command](_good(tmp_path), target)) == 2
    err = capsys.readouterr().err
    assert (
        err == f"xodrcheck: cannot write {target}: cannot create a file in folder /proc (No such file or directory)\n"
    )


@pytest.mark.parametrize("command", sorted(WRITERS))
def test_output_that_is_a_directory_is_refused_before_any_work(tmp_path, capsys, command):
    """Was: ".bad.gx7mwf9_.tmp: Is a directory"."""
    target = tmp_path / ("out" + SUFFIX.get(command, ".txt"))
    target.mkdir()
    assert main(WRITERS[command](_good(tmp_path), str(target))) == 2
    err = capsys.readouterr().err
    assert err == f"xodrcheck: cannot write {target}: it is a directory\n"
    assert ".tmp" not in err and list(target.iterdir()) == []


@pytest.mark.parametrize("command", sorted(WRITERS))
def test_output_in_a_missing_folder(tmp_path, capsys, command):
    target = tmp_path / "nowhere" / ("out" + SUFFIX.get(command, ".txt"))
    assert main(WRITERS[command](_good(tmp_path), str(target))) == 2
    err = capsys.readouterr().err
    assert err == f"xodrcheck: cannot write {target}: folder {target.parent} does not exist\n"


@pytest.mark.parametrize("command", ["check", "metrics"])
def test_a_file_that_cannot_be_opened_among_several_writes_no_output(tmp_path, capsys, command):
    """Exit 2 never leaves an output file, also when other files of the run could be read."""
    out = tmp_path / "out.txt"
    argv = [command, str(tmp_path / "missing.xodr"), _good(tmp_path), "-o", str(out)]
    assert main(argv) == 2
    assert not out.exists()
    assert f"nothing written to {out}" in capsys.readouterr().err


def test_sample_step_needing_too_many_points_is_refused_with_the_step_that_fits(tmp_path, capsys):
    """Was: ``--step 1e-9`` ran until the disk filled (a 397 MB temporary file after a few seconds)."""
    src = tmp_path / "map.xodr"
    src.write_text(maps.STRAIGHT)  # 100 m, two lanes
    out = tmp_path / "s.csv"
    started = time.monotonic()
    assert main(["sample", str(src), "--step", "1e-9", "-o", str(out)]) == 2
    assert time.monotonic() - started < 10
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "would give 2e+11 points, more than the bound of 10,000,000" in err
    assert "max_output_points" in err and "use a step of at least 2.01e-05 m" in err
    assert list(tmp_path.iterdir()) == [src]
    document = read(src).document
    assert sample_count(document, 2.01e-5) <= 10_000_000 < sample_count(document, 2.0e-5)  # it fits, just


def test_sample_bound_is_a_configurable_tolerance(tmp_path, capsys, monkeypatch):
    src = tmp_path / "map.xodr"
    src.write_text(maps.STRAIGHT)
    (tmp_path / "xodrcheck.toml").write_text("[tolerances]\nmax_output_points = 100\n")
    monkeypatch.chdir(tmp_path)
    assert main(["sample", str(src), "--step", "1"]) == 2  # 2 lanes x 101 points
    assert "more than the bound of 100" in capsys.readouterr().err
    assert main(["sample", str(src), "--step", "5"]) == 0  # 2 x 21


def test_mesh_with_too_many_vertices_is_refused_and_writes_nothing(tmp_path, capsys, monkeypatch):
    src = tmp_path / "map.xodr"
    src.write_bytes(T_JUNCTION)
    (tmp_path / "xodrcheck.toml").write_text("[tolerances]\nmax_output_points = 500\n")
    monkeypatch.chdir(tmp_path)
    assert main(["mesh", str(src), "-o", "m.glb", "--chord", "1e-9"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "more than 500 vertices" in err and "use a larger chord" in err
    assert not (tmp_path / "m.glb").exists()


def test_mesh_says_what_it_wrote(tmp_path, capsys):
    out = tmp_path / "m.glb"
    assert main(["mesh", _good(tmp_path), "-o", str(out)]) == 0
    printed = capsys.readouterr().out
    assert printed.startswith(f"{out}: ") and "vertices" in printed and "triangles" in printed


def test_atomic_file_removes_its_temporary_file_on_a_real_sigterm(tmp_path):
    target = tmp_path / "out.txt"
    target.write_text("old")
    previous = signal.getsignal(signal.SIGTERM)
    with pytest.raises(Terminated), signals_raise(), atomic_file(target) as stream:
        stream.write("new, half written")
        os.kill(os.getpid(), signal.SIGTERM)
        time.sleep(5)  # the handler raises before this ends
    assert target.read_text() == "old" and sorted(p.name for p in tmp_path.iterdir()) == ["out.txt"]
    assert signal.getsignal(signal.SIGTERM) is previous  # the handler is put back


def test_output_error_names_the_path_as_given():
    with (
        pytest.raises(OutputError, match=r"^cannot write /proc/x\.csv: cannot create a file in folder /proc"),
        atomic_file("/proc/x.csv"),
    ):
        pass


def _wait_for(predicate, seconds: float = 60.0) -> bool:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if predicate():
            return True
        time.sleep(0.05)
    return False


def test_sigterm_while_sampling_leaves_no_temporary_file(tmp_path):
    """Was: a SIGTERM (``timeout``, a CI runner stopping a job) left the temporary file behind; Ctrl-C did not."""
    src = tmp_path / "map.xodr"
    src.write_text(maps.STRAIGHT)
    out = tmp_path / "s.csv"
    proc = subprocess.Popen(
        [sys.executable, "-m", "xodrcheck", "sample", str(src), "--step", "4e-5", "-o", str(out)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        assert _wait_for(lambda: any(p.name.endswith(".tmp") for p in tmp_path.iterdir())), "no temporary file"
        temporary = next(p for p in tmp_path.iterdir() if p.name.endswith(".tmp"))
        assert _wait_for(lambda: temporary.exists() and temporary.stat().st_size > 0)
        proc.send_signal(signal.SIGTERM)
        _, err = proc.communicate(timeout=60)
    finally:
        proc.kill()
    assert proc.returncode == EXIT_TERMINATED == 143
    assert err.strip().splitlines()[-1] == "xodrcheck: terminated" and "Traceback" not in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["map.xodr"]


def test_the_readme_table_covers_every_command_of_both_tools():
    from xodrcheck.cli import SUBCOMMANDS

    readme = (REPO / "README.md").read_text(encoding="utf-8")
    section = readme.split("## Exit codes, output files and interruptions", 1)[1].split("\n## ", 1)[0]
    rows = [line for line in section.splitlines() if line.startswith("| `")]
    named = " ".join(row.split("|")[1] for row in rows)
    missing = [c for c in SUBCOMMANDS if f"`{c}`" not in named and f"`xodrcheck {c}`" not in named]
    missing += [c for c in ("generate", "render", "era") if c not in named]
    assert not missing, missing
    assert "130 after Ctrl-C, 143 after SIGTERM" in section and str(EXIT_TERMINATED) == "143"


def test_check_exits_3_when_incomplete_and_says_so(tmp_path, capsys):
    """A time bound the user sets and the check does not meet: exit 3 and an INCOMPLETE summary, not "0 error(s)"
    and exit 0 (what a 120 s default budget gave a 10 km map)."""
    import json

    src = _good(tmp_path)
    assert main(["check", src, "-j", "1", "--tolerance", "time_budget=1e-9"]) == 3
    captured = capsys.readouterr()
    assert "X901 error" in captured.out and "INCOMPLETE" in captured.err and "the verdict is not known" in captured.err
    assert main(["check", src, "-j", "1", "--tolerance", "time_budget=1e-9", "--format", "json"]) == 3
    (entry,) = json.loads(capsys.readouterr().out)["files"]
    assert entry["complete"] is False and entry["ok"] is False
    assert main(["check", src, "-j", "1"]) == 0  # no bound by default: complete
