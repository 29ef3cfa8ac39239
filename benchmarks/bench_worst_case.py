"""Worst-case cost of a check: CPU seconds per kB of the slowest documents the slow-input hunt finds (issue 31).

Runs the hunt (``python -m junctionart.fuzz --runs slow``, :mod:`junctionart.fuzz.hunt`) for ``--minutes`` and writes
its slowest documents to ``--out``, then checks every ``.xodr`` there and in the regression documents
(``tests/fuzz/slow`` and the winding fixtures of O002) again, one at a time in this process after a warm-up, and
prints the 20 slowest per kB (CPU seconds, size, seconds per kB, the work counted by :mod:`xodrcheck.support.work`) and
the maximum, against the bound: no document under 100 kB over 5 s of CPU. ``--minutes 0`` measures the documents only.

    python benchmarks/bench_worst_case.py [--minutes 10] [--out DIR] [DIR ...]
"""

from __future__ import annotations

import argparse
import tempfile
import time
import warnings
from pathlib import Path

from junctionart.fuzz import hunt
from xodrcheck.check import check
from xodrcheck.support import work

REPO = Path(__file__).resolve().parents[1]
REGRESSIONS = (REPO / "tests" / "fuzz" / "slow", REPO / "tests" / "xodrcheck" / "rules" / "fixtures" / "lane-fold")


def measure(path: Path) -> tuple[float, int, dict[str, int]]:
    """CPU seconds of checking ``path`` in this process, its size and the work counted."""
    data = path.read_bytes()
    with work.counting() as done:
        started = time.process_time()
        check(data)
        cpu = time.process_time() - started
    return cpu, len(data), dict(done)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="*", type=Path, help="more folders of .xodr documents to measure")
    parser.add_argument("--minutes", type=float, default=10.0, help="how long the hunt runs first (0: no hunt)")
    parser.add_argument("--out", type=Path, help="where the hunt writes its slowest documents (default: a temporary)")
    args = parser.parse_args()
    warnings.simplefilter("ignore", RuntimeWarning)  # damaged numbers overflow inside numpy on purpose
    folders = [*REGRESSIONS, *args.folders]
    if args.minutes > 0:
        from junctionart.fuzz.__main__ import main as fuzz

        out = args.out or Path(tempfile.mkdtemp(prefix="hunt-"))
        fuzz(["--runs", "slow", "--minutes", str(args.minutes), "--slowest", str(out)])
        folders.append(out)
    paths = sorted({p for folder in folders for p in folder.glob("*.xodr")})
    check(paths[0])  # imports and caches warm before timing
    rows = []
    for path in paths:
        cpu, size, done = measure(path)
        rows.append((cpu / max(size / 1024, 1e-3), cpu, size, done, path))
    rows.sort(key=lambda row: -row[0])
    print(f"{len(paths)} documents; the 20 slowest per kB (CPU s of one check in process):")
    print(f"{'s/kB':>8} {'CPU s':>8} {'bytes':>9}  work  document")
    for per_kb, cpu, size, done, path in rows[:20]:
        counted = ", ".join(f"{kind} {n:,}" for kind, n in sorted(done.items()))
        print(f"{per_kb:8.3f} {cpu:8.2f} {size:9,d}  {counted}  {path.name}")
    small = [row for row in rows if row[2] < hunt.LARGE]
    worst = max(small, key=lambda row: row[1])
    over = [row for row in small if row[1] > hunt.SLOW_SECONDS]
    print(
        f"maximum: {worst[1]:.2f} s of CPU ({worst[2]:,} bytes, {worst[4].name}); documents under "
        f"{hunt.LARGE // 1024} kB over {hunt.SLOW_SECONDS:g} s: {len(over)}"
    )


if __name__ == "__main__":
    main()
