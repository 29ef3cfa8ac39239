"""``junctionart`` follows the same rules as ``xodrcheck`` (the README's table): ``-o`` errors name the user's path
and the cause, files are written whole or not at all (also on SIGTERM), maps too large to finish in reasonable time
are refused with the bound, an input that cannot be read whole is exit 2 with no output."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from junctionart import controllines
from junctionart.cli import main
from junctionart.errors import InputError, ParamsError
from junctionart.params import MAX_AREA, Params

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "t-junction.xodr"


def test_generate_into_proc_names_the_users_path_and_the_cause(capsys):
    """Was: "/proc/.x.xodr.xjuyv1bv.tmp: No such file or directory"."""
    assert main(["generate", "-q", "-o", "/proc/x.xodr"]) == 2
    err = capsys.readouterr().err
    assert err == (
        "junctionart: error: cannot write /proc/x.xodr: cannot create a file in folder /proc (No such file or "
        "directory)\n"
    )


def test_generate_onto_a_directory_is_refused_before_generating(tmp_path, capsys, monkeypatch):
    """Was: ".bad.gx7mwf9_.tmp: Is a directory", after the map had been generated."""
    import junctionart

    target = tmp_path / "bad"
    target.mkdir()
    monkeypatch.setattr(junctionart, "generate_layout", lambda *a, **k: pytest.fail("generated before checking -o"))
    assert main(["generate", "-q", "-o", str(target)]) == 2
    assert capsys.readouterr().err == f"junctionart: error: cannot write {target}: it is a directory\n"


def test_render_onto_a_directory_and_into_a_missing_folder(tmp_path, capsys):
    target = tmp_path / "map.png"
    target.mkdir()
    assert main(["render", str(EXAMPLE), "-o", str(target)]) == 2
    assert capsys.readouterr().err == f"junctionart: error: cannot write {target}: it is a directory\n"
    missing = tmp_path / "nowhere" / "map.png"
    assert main(["render", str(EXAMPLE), "-o", str(missing)]) == 2
    assert capsys.readouterr().err == (
        f"junctionart: error: cannot write {missing}: folder {missing.parent} does not exist\n"
    )


@pytest.mark.parametrize(
    ("suffix", "magic"),
    [
        (".png", b"\x89PNG"),
        (".jpg", b"\xff\xd8\xff"),
        (".jpeg", b"\xff\xd8\xff"),
        (".svg", b"<?xml"),
        (".pdf", b"%PDF"),
    ],
)
def test_render_writes_the_format_its_suffix_names_and_says_so(tmp_path, capsys, suffix, magic):
    """Was: ``-o map.jpg`` wrote PNG bytes, and nothing was printed."""
    out = tmp_path / f"map{suffix}"
    assert main(["render", str(EXAMPLE), "-o", str(out), "--dpi", "30"]) == 0
    assert out.read_bytes().startswith(magic)
    printed = capsys.readouterr().out
    assert printed.startswith(f"{out}: ") and "plan view of" in printed and "junctions" in printed


def test_render_refuses_an_unknown_suffix(tmp_path, capsys):
    out = tmp_path / "map.bmp"
    assert main(["render", str(EXAMPLE), "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "unknown image format '.bmp'" in err and ".png" in err
    assert not out.exists()


def test_render_refuses_a_file_it_cannot_read_whole(tmp_path, capsys):
    truncated = tmp_path / "t.xodr"
    truncated.write_bytes(EXAMPLE.read_bytes()[:4000])
    out = tmp_path / "t.png"
    assert main(["render", str(truncated), "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"cannot read {truncated} whole" in err and "X101" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["t.xodr"]


@pytest.mark.parametrize(
    ("size", "words"),
    [
        ("0x0", "--size 0x0: the width must be in [50, 100000] m, got 0"),
        ("600x20", "--size 600x20: the height must be in [50, 100000] m, got 20"),
        ("100000x100000", "--size 100000x100000: the map would cover 1e+10 m^2, more than the bound of 1e+08 m^2"),
        ("20000x20000", "more than the bound of 1e+08 m^2"),
    ],
)
def test_size_outside_the_bounds_is_one_line_naming_what_was_typed(tmp_path, capsys, size, words):
    """Was: "width=0.0"; and 100000x100000 sat at "network 20 %" for more than 400 s."""
    started = time.monotonic()
    assert main(["generate", "--size", size, "-o", str(tmp_path / "m.xodr")]) == 2
    assert time.monotonic() - started < 10
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and words in err
    assert list(tmp_path.iterdir()) == []


def test_the_area_bound_holds_for_library_callers_too():
    with pytest.raises(ParamsError, match="more than the bound of 1e\\+08 m\\^2"):
        Params(width=20_000.0, height=20_000.0)
    assert Params(width=10_000.0, height=10_000.0).width * 10_000.0 == MAX_AREA  # the largest square map is allowed


def _pair(length: float, offset: float = 0.0) -> dict:
    return {
        "lines": [
            {"id": "a", "points": [[offset, 0], [offset + length, 0]]},
            {"id": "b", "points": [[offset, 150], [offset + length, 150]]},
        ]
    }


@pytest.mark.parametrize(
    ("data", "words"),
    [
        (_pair(300_000.0), "span 300000 m x 150 m; at most 100000 m each way"),
        (_pair(1e12), "a coordinate is 1e+12 m from the origin; at most 1e+07 m"),
        (
            {"lines": [{"id": str(k), "points": [[0, 100 * k], [90_000, 100 * k]]} for k in range(8)]},
            "the control lines are 720 km long in total; at most 600 km",
        ),
    ],
)
def test_control_lines_outside_the_bounds_are_refused_at_once(tmp_path, capsys, data, words):
    """Was: lines 300 km (or 1e12 m) long ran silently past 60 s."""
    path = tmp_path / "lines.json"
    path.write_text(json.dumps(data))
    started = time.monotonic()
    assert main(["generate", "--control-lines", str(path), "-o", str(tmp_path / "m.xodr")]) == 2
    assert time.monotonic() - started < 10
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and words in err, err
    with pytest.raises(InputError, match="at most"):
        controllines.parse(data)


def test_control_lines_in_projected_coordinates_are_accepted():
    lines = controllines.parse(_pair(2_000.0, offset=5_400_000.0))  # a UTM northing-sized offset
    assert lines.lines[0].points[0][0] == 5_400_000.0


def test_generate_help_shows_the_defaults(capsys):
    """Was: no default in ``generate --help``."""
    with pytest.raises(SystemExit):
        main(["generate", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    for words in (
        "(default: 3.5)",  # --lane-width
        "(default: 80,200)",  # --line-spacing
        "(default: RHT)",
        "(default: false)",  # --randomize-lanes
        "(default: map.xodr)",
        "(default: 500x500;",
        "(default: 1.8)",
        "repairs",
    ):
        assert words in text, words


def test_summary_explains_repairs_and_verbose_lists_them(tmp_path, capsys):
    """Was: "1 repairs" and nothing anywhere saying what a repair is."""
    out = tmp_path / "m.xodr"
    assert main(["generate", "--seed", "3", "--size", "1000x1000", "--randomize-lanes", "true", "-o", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "repairs (changes made so every junction fits; --verbose lists them)" in printed
    assert (
        main(["generate", "-v", "--seed", "3", "--size", "1000x1000", "--randomize-lanes", "true", "-o", str(out)]) == 0
    )
    captured = capsys.readouterr()
    listed = [line for line in captured.err.splitlines() if line.startswith("junctionart: seed 3: repair: ")]
    count = int(captured.out.split(" repairs")[0].rsplit(", ", 1)[1])
    assert count > 0 and len(listed) == count


def test_sigterm_while_writing_leaves_no_temporary_file(tmp_path, capsys, monkeypatch):
    """A real SIGTERM to this process while the map's temporary file is open: it is removed, exit 143."""
    import xodrcheck.support.atomic

    fsync = os.fsync

    def fsync_then_sigterm(fd: int) -> None:
        fsync(fd)
        os.kill(os.getpid(), signal.SIGTERM)
        time.sleep(5)  # the handler raises before this ends

    monkeypatch.setattr(xodrcheck.support.atomic.os, "fsync", fsync_then_sigterm)
    out = tmp_path / "m.xodr"
    out.write_text("old")
    assert main(["generate", "-q", "-o", str(out)]) == 143
    assert capsys.readouterr().err == "junctionart: terminated\n"
    assert out.read_text() == "old" and sorted(p.name for p in tmp_path.iterdir()) == ["m.xodr"]


def test_sigterm_from_outside_ends_generate_with_143(tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    log = tmp_path / "stderr.txt"
    with open(log, "w") as stderr:
        proc = subprocess.Popen(
            [sys.executable, "-m", "junctionart", "generate", "--size", "5000x5000", "-o", str(out / "m.xodr")],
            stdout=subprocess.DEVNULL,
            stderr=stderr,
        )
        try:
            deadline = time.monotonic() + 120
            while "network" not in log.read_text() and time.monotonic() < deadline:  # generating (the stage bar)
                time.sleep(0.05)
            proc.send_signal(signal.SIGTERM)
            proc.wait(timeout=60)
        finally:
            proc.kill()
    err = log.read_text()
    assert proc.returncode == 143 and "junctionart: terminated" in err and "Traceback" not in err
    assert list(out.iterdir()) == []


def test_render_without_matplotlib_names_the_extra_and_writes_nothing(tmp_path):
    """matplotlib is the extra ``figures``: without it, render says what to install in one line, exit 2, no file."""
    out = tmp_path / "map.png"
    probe = (
        "import sys; sys.modules['matplotlib'] = None\n"  # import matplotlib now raises ImportError
        "from junctionart.cli import main\n"
        f"sys.exit(main(['render', {str(EXAMPLE)!r}, '-o', {str(out)!r}]))\n"
    )
    proc = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=False)
    assert proc.returncode == 2, proc.stderr
    assert proc.stderr.count("\n") == 1 and "pip install 'junctionart[figures]'" in proc.stderr
    assert "Traceback" not in proc.stderr and not out.exists()


@pytest.mark.parametrize("command", ["generate", "render", "era", "intersection", "search"])
def test_every_subcommand_help_prints_and_exits_0(command, capsys):
    """Was: ``generate --help`` raised ValueError (a bare '%' in an option's help, which argparse formats)."""
    with pytest.raises(SystemExit) as exit_info:
        main([command, "--help"])
    assert exit_info.value.code == 0
    assert capsys.readouterr().out.startswith(f"usage: junctionart {command}")


def test_the_help_tests_cover_every_subcommand(capsys):
    with pytest.raises(SystemExit):
        main(["--help"])
    listed = capsys.readouterr().out.split("{", 1)[1].split("}", 1)[0].split(",")
    assert listed == ["generate", "render", "era", "intersection", "search"]
