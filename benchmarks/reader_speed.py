"""Reader speed: ``xodrcheck.reader.read`` against a bare ``lxml.etree.parse`` of the same file, as a ratio.

    python benchmarks/reader_speed.py [--repeat 15] [files...]

Default files: the CARLA towns of the corpus (``$XODR_CORPUS``, else ``../shared/corpus``). The two are timed in
alternation, in CPU time, and each keeps its best of ``--repeat`` runs, so that other work on the machine disturbs both
alike; the ratio (read / bare parse) is the figure of merit, with a target of at most 3.
"""

from __future__ import annotations

import argparse
import gc
import os
import sys
import time
from pathlib import Path

from lxml import etree

from xodrcheck.reader import read

REPO = Path(__file__).resolve().parents[1]
TARGET = 3.0


def _cpu(fn) -> float:
    gc.collect()
    start = time.process_time()
    fn()
    return time.process_time() - start


def ratio(path: Path, repeat: int) -> tuple[float, float]:
    """Best CPU times (s) of a bare parse and of :func:`read` on ``path``, timed alternately."""
    bare = full = float("inf")
    for _ in range(repeat):
        bare = min(bare, _cpu(lambda: etree.parse(str(path))))
        full = min(full, _cpu(lambda: read(path)))
    return bare, full


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", type=Path)
    parser.add_argument("--repeat", type=int, default=15)
    args = parser.parse_args(argv)
    corpus = Path(os.environ.get("XODR_CORPUS", REPO.parent / "shared" / "corpus"))
    files = args.files or sorted((corpus / "carla-towns" / "OpenDrive").glob("Town0*.xodr"))
    if not files:
        print(f"no files given and no CARLA towns under {corpus}", file=sys.stderr)
        return 2
    print(f"{'file':<14}{'MB':>6}{'parse ms':>10}{'read ms':>10}{'ratio':>7}")
    worst = 0.0
    for path in files:
        bare, full = ratio(path, args.repeat)
        worst = max(worst, full / bare)
        size = path.stat().st_size / 1e6
        print(f"{path.name:<14}{size:>6.2f}{bare * 1e3:>10.1f}{full * 1e3:>10.1f}{full / bare:>7.2f}")
    print(f"worst ratio {worst:.2f} (target <= {TARGET:g})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
