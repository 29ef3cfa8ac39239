import subprocess
import sys
from pathlib import Path

import pytest

from junctionart.cli import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_generate_writes_a_map_and_is_reproducible(tmp_path, capsys):
    a, b = tmp_path / "a.xodr", tmp_path / "b.xodr"
    assert main(["generate", "--seed", "4", "--size", "600x400", "--randomize-lanes", "true", "-o", str(a)]) == 0
    assert (
        main(["generate", "--seed", "4", "--size", "600x400", "--randomize-lanes", "true", "-o", str(b), "--quiet"])
        == 0
    )
    assert a.read_bytes() == b.read_bytes()
    out = capsys.readouterr().out
    assert "junctions" in out and str(a) in out


def test_generate_from_control_lines_version_17(tmp_path):
    out = tmp_path / "a.xodr"
    assert (
        main(["generate", "--control-lines", str(EXAMPLES / "a_shape.json"), "--version", "1.7", "-o", str(out), "-q"])
        == 0
    )
    assert b'revMinor="7"' in out.read_bytes()[:300]


def test_generate_version_19_and_18_stays_the_default(tmp_path):
    a, b = tmp_path / "a.xodr", tmp_path / "b.xodr"
    assert main(["generate", "--seed", "2", "--size", "500x500", "--version", "1.9", "-o", str(a), "-q"]) == 0
    assert main(["generate", "--seed", "2", "--size", "500x500", "-o", str(b), "-q"]) == 0
    assert b'revMinor="9"' in a.read_bytes()[:300] and b'revMinor="8"' in b.read_bytes()[:300]


def test_count_with_seed_pattern(tmp_path):
    assert main(["generate", "--count", "3", "--seed", "10", "-o", str(tmp_path / "m{seed}.xodr"), "-q"]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m10.xodr", "m11.xodr", "m12.xodr"]


@pytest.mark.parametrize(
    "args, words",
    [
        (["--lane-width", "9"], "lane_width=9.0: must be in [2, 6]"),
        (["--split-strategy", "middle"], "split_strategy='middle'"),
        (["--control-lines", "/nonexistent/lines.json"], "cannot read"),
        (["--count", "2"], "{seed}"),
        (["--seed", "-1"], "--seed=-1"),
        (["--transitions", "{bad"], "--transitions"),
    ],
)
def test_bad_input_one_line_exit_2_no_file(tmp_path, capsys, args, words):
    out = tmp_path / "x.xodr"
    assert main(["generate", *args, "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert words in err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_render(tmp_path):
    xodr = tmp_path / "a.xodr"
    png = tmp_path / "a.png"
    assert main(["generate", "--seed", "1", "-o", str(xodr), "-q"]) == 0
    assert main(["render", str(xodr), "-o", str(png)]) == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert png.stat().st_size > 10_000


def test_render_bad_file(tmp_path, capsys):
    bad = tmp_path / "bad.xodr"
    bad.write_text("<OpenDRIVE><header revMajor='1' revMinor='8'/></OpenDRIVE>")
    assert main(["render", str(bad), "-o", str(tmp_path / "x.png")]) == 2
    assert "no road" in capsys.readouterr().err
    assert main(["render", str(tmp_path / "none.xodr"), "-o", str(tmp_path / "x.png")]) == 2
    assert not (tmp_path / "x.png").exists()


def test_console_script_entry_point(tmp_path):
    proc = subprocess.run(
        [sys.executable, "-m", "junctionart", "generate", "--size", "10x10", "-o", str(tmp_path / "a.xodr")],
        capture_output=True,
        text=True,
        check=False,
    )
    assert proc.returncode == 2
    # the value as the user typed it, not the parameter it fills ("width=10.0")
    assert "--size 10x10: the width must be in [50, 100000] m, got 10" in proc.stderr
    assert "Traceback" not in proc.stderr


def test_stages_are_reported_in_order():
    import junctionart as ja

    seen = []
    ja.generate_layout(ja.Params(), 0, on_stage=seen.append)
    assert tuple(seen) == ja.STAGES


def test_usage_errors_are_one_line(capsys):
    with pytest.raises(SystemExit) as ex:
        main(["generate", "--size", "10x"])
    assert ex.value.code == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--size '10x'" in err
