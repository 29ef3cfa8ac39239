"""The README's first screen: its two commands are the ones that work (the main job and the test command CI runs)."""

from __future__ import annotations

import re
import shlex
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text(encoding="utf-8")
BLOCKS = re.findall(r"```sh\n(.*?)\n```", README, re.DOTALL)


def test_first_screen_has_the_main_job_then_the_test_command():
    first_screen = README[: README.index("\n---\n")]
    assert first_screen.count("```sh") == 2
    main_job, tests = BLOCKS[0].strip(), BLOCKS[1].strip()
    assert main_job.startswith("scripts/setup && ")
    assert tests == ".venv/bin/python -m pytest"
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8").strip().splitlines()
    assert ci[-1] == tests  # CI calls exactly the README's test command


def test_main_job_generates_checks_and_draws_a_map(tmp_path):
    """Everything after ``scripts/setup`` (which CI runs itself), in an empty folder, with this environment's
    commands."""
    steps = BLOCKS[0].strip().split(" && ")[1:]
    bin_dir = Path(sys.executable).parent
    for step in steps:
        argv = shlex.split(step)
        assert argv[0].startswith(".venv/bin/"), step
        argv[0] = str(bin_dir / argv[0].removeprefix(".venv/bin/"))
        done = subprocess.run(argv, cwd=tmp_path, capture_output=True, text=True, check=False, timeout=300)
        assert done.returncode == 0, (step, done.stdout[-2000:], done.stderr[-2000:])
        assert "Traceback" not in done.stderr
    xodr, png = tmp_path / "map.xodr", tmp_path / "map.png"
    assert xodr.read_bytes().startswith(b"<?xml")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 10_000


def test_first_screen_counts_are_the_checkers():
    """The rule count and the Annex F coverage the README states are the ones ``xodrcheck rules`` reports."""
    from xodrcheck.rules import load_rules
    from xodrcheck.standard.status import ENFORCED, MISSING, PARTIAL, statuses

    rules = load_rules()
    table = statuses(rules)
    counts = {s: sum(1 for row in table if row.status == s) for s in (ENFORCED, PARTIAL, MISSING)}
    first_screen = " ".join(README[: README.index("\n---\n")].split())
    assert f"checks it against {len(rules)} rules" in first_screen
    assert (
        f"Of the {len(table)} checker rules of OpenDRIVE 1.9.0 (Annex F) it enforces {counts[ENFORCED]} in full and "
        f"{counts[PARTIAL]} in part; the other {counts[MISSING]} are" in first_screen
    )
