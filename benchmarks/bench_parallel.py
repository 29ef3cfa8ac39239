"""``xodrcheck check DIR -j N`` against ``-j 1`` on the corpus: throughput ratio and whether the reports are identical.

    python benchmarks/bench_parallel.py [--corpus DIR] [--jobs 2]

Both runs are whole processes writing a JSON report; the ratio of their wall times is measured in one run (target on
2 cores: >= 1.7). On a machine shared with other work the wall times depend on the load; the CPU time of each run
(children included) shows what the workers' start-up costs.
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
TARGET = 1.7


def run(corpus: Path, jobs: int, out: Path) -> tuple[float, float]:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    started = time.perf_counter()
    command = [str(Path(sys.executable).parent / "xodrcheck"), "check", str(corpus), "-j", str(jobs)]
    subprocess.run([*command, "--format", "json", "-o", str(out)], stderr=subprocess.DEVNULL, check=False)
    wall = time.perf_counter() - started
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--corpus", type=Path, default=Path(os.environ.get("XODR_CORPUS", REPO.parent / "shared/corpus"))
    )
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    files = len(list(args.corpus.rglob("*.xodr")))
    with tempfile.TemporaryDirectory() as tmp:
        serial, parallel = Path(tmp) / "serial.json", Path(tmp) / "parallel.json"
        wall_1, cpu_1 = run(args.corpus, 1, serial)
        wall_n, cpu_n = run(args.corpus, args.jobs, parallel)
        same = serial.read_bytes() == parallel.read_bytes()
    ratio = wall_1 / max(wall_n, 1e-9)
    print(f"{files} files, {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    print(f"-j 1:  {wall_1:7.1f} s wall, {cpu_1:7.1f} s CPU")
    print(f"-j {args.jobs}:  {wall_n:7.1f} s wall, {cpu_n:7.1f} s CPU")
    print(f"throughput ratio {ratio:.2f} (target >= {TARGET}); reports identical: {'yes' if same else 'NO'}")


if __name__ == "__main__":
    main()
