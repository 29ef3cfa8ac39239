"""Whole-process times of the short commands a user types, beside a bare Python start in the same run.

    python benchmarks/bench_startup.py [--repeats 7]

Times ``xodrcheck --help``, ``xodrcheck check`` of a 2 kB file without spirals, ``junctionart --help``, ``junctionart
generate`` of a 1 km map and ``python -c pass``, each as a new process (minimum and median of the repeats, wall clock,
and the median CPU of the child). Target (issue 27): a check of a small file under 0.6 s. On a busy machine wall
times grow with the load; the minimum, the child CPU time and the ratio to the bare interpreter, measured in the same
run, say more. Byte code is compiled first (``compileall``), as an installed package has it.
"""

from __future__ import annotations

import argparse
import compileall
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent
TARGETS = {"xodrcheck check (2 kB)": 0.6}

PLAIN = """<?xml version="1.0" encoding="UTF-8"?>
<OpenDRIVE>
  <header revMajor="1" revMinor="6" name="plain"/>
  <road id="1" length="30" junction="-1">
    <link/>
    <planView>
      <geometry s="0" x="0" y="0" hdg="0" length="20"><line/></geometry>
      <geometry s="20" x="20" y="0" hdg="0" length="10"><arc curvature="0.01"/></geometry>
    </planView>
    <lanes>
      <laneSection s="0">
        <left><lane id="1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left>
        <center><lane id="0" type="none" level="false"/></center>
        <right><lane id="-1" type="driving" level="false"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
      </laneSection>
    </lanes>
  </road>
</OpenDRIVE>
"""


def timed(command: list[str], cwd: Path, env: dict[str, str]) -> tuple[float, float]:
    """Wall and CPU (user + system) seconds of one run of ``command``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    started = time.perf_counter()
    subprocess.run(command, cwd=cwd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    wall = time.perf_counter() - started
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()
    for package in ("xodrcheck", "junctionart"):
        compileall.compile_dir(REPO / package, quiet=1)
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        plain = folder / "plain.xodr"
        plain.write_text(PLAIN)
        env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        commands = {
            "python -c pass": [sys.executable, "-c", "pass"],
            "xodrcheck --help": [str(BIN / "xodrcheck"), "--help"],
            "xodrcheck check (2 kB)": [str(BIN / "xodrcheck"), "check", str(plain)],
            "junctionart --help": [str(BIN / "junctionart"), "--help"],
            "junctionart generate 1 km": [
                str(BIN / "junctionart"),
                "generate",
                "--size",
                "1000x1000",
                "--seed",
                "1",
                "-q",
                "-o",
                str(folder / "map.xodr"),
            ],
        }
        for command in commands.values():  # warm the file cache
            timed(command, folder, env)
        runs: dict[str, list[tuple[float, float]]] = {name: [] for name in commands}
        for _ in range(args.repeats):  # interleaved, so that a burst of load hits every command alike
            for name, command in commands.items():
                runs[name].append(timed(command, folder, env))
    bare = statistics.median(cpu for _, cpu in runs["python -c pass"])
    load = " ".join(f"{x:.1f}" for x in os.getloadavg())
    print(f"{os.cpu_count()} cores, load average {load} (1, 5, 15 min); {args.repeats} runs each")
    print(f"{'command':<40}{'min s':>8}{'median s':>10}{'CPU s':>8}{'CPU/python':>12}{'target s':>10}")
    for name, values in runs.items():
        low = min(w for w, _ in values)
        wall = statistics.median(w for w, _ in values)
        cpu = statistics.median(c for _, c in values)
        target = TARGETS.get(name)
        mark = "" if target is None else f"{target:>10.2f}" + ("" if cpu <= target else " (CPU over)")
        print(f"{name:<40}{low:>8.3f}{wall:>10.3f}{cpu:>8.3f}{cpu / max(bare, 1e-9):>12.1f}{mark}")


if __name__ == "__main__":
    main()
