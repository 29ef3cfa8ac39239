"""Peak memory of ``xodrcheck check`` on generated maps of growing size (issue 18: a 10 km map within 1 GB).

    python benchmarks/bench_memory.py [--sizes 1000,2000,5000,10000] [--keep DIR]

Each map is generated once (``junctionart generate --size WxW``, seed 0) and checked by a whole ``xodrcheck check``
process writing a JSON report; the figure is that process's peak resident set size (``ru_maxrss`` of the child,
from ``os.wait4``), absolute MB on this machine, with the file's size, the ratio of the two, the wall time (noisy on
a shared machine) and whether the check was complete (no ``X901``/``X900``). ``--keep DIR`` keeps the maps there
(and reuses them on the next run: generating a 10 km map takes minutes).
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BIN = Path(sys.executable).parent
TARGET_MB = 1024


def generate(size: int, folder: Path) -> Path:
    path = folder / f"generated-{size}m.xodr"
    if not path.exists():
        command = [str(BIN / "junctionart"), "generate", "--size", f"{size}x{size}", "-o", str(path)]
        subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return path


def peak_of_check(path: Path, report: Path) -> tuple[float, float, int]:
    """(peak RSS in MB, wall seconds, exit code) of one ``xodrcheck check`` process."""
    command = [str(BIN / "xodrcheck"), "check", str(path), "--format", "json", "-o", str(report)]
    started = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(process.pid, 0)
    process.returncode = os.waitstatus_to_exitcode(status)
    return usage.ru_maxrss / 1024, time.perf_counter() - started, process.returncode


def incomplete(report: Path) -> int:
    """Number of X900/X901 findings (rules that crashed or did not run) in a JSON report."""
    data = json.loads(report.read_text())
    return sum(1 for f in data["files"] for x in f["findings"] if x["code"] in ("X900", "X901"))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="1000,2000,5000,10000", help="map widths in metres, comma-separated")
    parser.add_argument("--keep", type=Path, help="folder to keep (and reuse) the generated maps in")
    args = parser.parse_args()
    sizes = [int(s) for s in args.sizes.split(",")]
    print(f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}; peak RSS absolute (target {TARGET_MB} MB)")
    print(f"{'size':>8} {'file MB':>8} {'peak MB':>8} {'peak/file':>9} {'wall s':>7} {'exit':>4} {'X90x':>4}")
    with tempfile.TemporaryDirectory() as tmp:
        folder = args.keep or Path(tmp)
        folder.mkdir(parents=True, exist_ok=True)
        for size in sizes:
            path = generate(size, folder)
            report = Path(tmp) / f"report-{size}.json"
            peak, wall, code = peak_of_check(path, report)
            file_mb = path.stat().st_size / 2**20
            missing = incomplete(report) if report.exists() else -1
            print(
                f"{size:>7}m {file_mb:8.1f} {peak:8.0f} {peak / max(file_mb, 1e-9):9.1f} {wall:7.1f} {code:4d} "
                f"{missing:4d}",
                flush=True,
            )


if __name__ == "__main__":
    main()
