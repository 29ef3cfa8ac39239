"""Reading and sampling speed on the CARLA towns, as ratios measured in one run.

For each town: a bare ``lxml.etree.parse`` of the file, ``xodrcheck.reader.read`` of the same file, their ratio, and the
time to sample every lane's inner and outer border every 0.5 m from the read document (road geometry built afresh).
Each figure is the median of ``--repeats`` runs (the ratio: the median of the ratios of parse and read timed one
after the other). Targets, printed beside: read within 2x of the bare parse on every town (issue 14); Town07's
borders in under 1 s.

The page faults of each call are shown beside its time, because they move the ratio as much as the reader's own
work does: on this VM a minor fault costs ~2.5 us, and a parse of Town01 needs ~1,000 fresh pages whenever glibc has
handed the memory of a tree freed before back to the system (it trims the top of its heap), which depends on what
else happens to lie at the top of the heap: from one process to the next, the bare parse faults on every call and
read() never, or the reverse, or neither (Town01 measured at 1.75 to 2.34 so). ``--no-trim`` runs the benchmark with
glibc told to keep freed memory (``MALLOC_TRIM_THRESHOLD_`` and ``MALLOC_MMAP_THRESHOLD_``): neither side faults,
and the ratio is that of the work done alone.

    python benchmarks/bench_read.py [--repeats 5] [--corpus DIR] [--no-trim]

The corpus folder defaults to ``$XODR_CORPUS``, else ``../shared/corpus`` beside the checkout.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path

from lxml import etree

from xodrcheck.analysis.sample import sample_lanes
from xodrcheck.geometry.lanes import RoadGeometry
from xodrcheck.reader import read

REPO = Path(__file__).resolve().parents[1]
STEP = 0.5
#: Issue 14: ``bench_read.py`` ratio to bare lxml <= 2 on every town.
READ_RATIO_TARGET = 2.0
TOWN07_BORDERS_TARGET_S = 1.0


def timed(fn: Callable[[], object]) -> tuple[float, object]:
    start = time.perf_counter()
    value = fn()
    return time.perf_counter() - start, value


def median_time(fn: Callable[[], object], repeats: int) -> tuple[float, object]:
    """Median wall time of ``repeats`` calls, and the last call's value."""
    runs = [timed(fn) for _ in range(repeats)]
    return statistics.median(t for t, _ in runs), runs[-1][1]


#: Environment under which glibc keeps the memory a program frees instead of returning it (``--no-trim``).
NO_TRIM = {"MALLOC_TRIM_THRESHOLD_": str(1 << 30), "MALLOC_MMAP_THRESHOLD_": str(1 << 30)}


def faults() -> int:
    """Minor page faults of this process so far."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_minflt


def parse_and_read(path: Path, parser: etree.XMLParser, repeats: int):
    """Bare parse and read() timed in alternation, so both see the same machine load; medians, the median of the
    per-repeat ratios, the median page faults of each, and the last read result."""
    bare, model, ratios, bare_faults, model_faults = [], [], [], [], []
    result = None
    for _ in range(repeats):
        before = faults()
        t_bare, _ = timed(lambda: etree.parse(str(path), parser))
        between = faults()
        t_model, result = timed(lambda: read(path))
        bare_faults.append(between - before)
        model_faults.append(faults() - between)
        bare.append(t_bare)
        model.append(t_model)
        ratios.append(t_model / t_bare)
    medians = (statistics.median(v) for v in (bare, model, ratios, bare_faults, model_faults))
    return (*medians, result)


def sample_borders(document) -> int:
    """Sample every lane border of the document at :data:`STEP`; returns the number of points."""
    geometry = {}
    for road in document.roads:
        geometry.setdefault(road.id, RoadGeometry(road))
    return sum(len(line) for line in sample_lanes(document, STEP, ("inner", "outer"), geometry))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    default_corpus = Path(os.environ.get("XODR_CORPUS", REPO.parent / "shared" / "corpus"))
    parser.add_argument("--corpus", type=Path, default=default_corpus)
    parser.add_argument("--no-trim", action="store_true", help="glibc keeps freed memory: no page faults either side")
    args = parser.parse_args()
    if args.no_trim and any(os.environ.get(k) != v for k, v in NO_TRIM.items()):
        # glibc reads these at start-up: run again under them
        os.execve(sys.executable, [sys.executable, *sys.argv], {**os.environ, **NO_TRIM})
    towns = sorted((args.corpus / "carla-towns").rglob("Town*.xodr"))
    if not towns:
        raise SystemExit(f"no CARLA towns under {args.corpus / 'carla-towns'}: set XODR_CORPUS or --corpus")

    lxml_parser = etree.XMLParser(resolve_entities=False, no_network=True)
    header = (
        f"{'map':<8} {'MB':>5} {'lxml ms':>8} {'faults':>7} {'read ms':>8} {'faults':>7} {'ratio':>6} {'<=':>4} "
        f"{'borders ms':>10} {'points':>8} {'target':>8}"
    )
    print(f"median of {args.repeats} runs; borders: inner and outer border of every lane every {STEP} m")
    trim = "glibc keeps freed memory (--no-trim)" if args.no_trim else "glibc as configured (it may trim its heap)"
    print(f"faults: minor page faults per call; {trim}")
    print(header)
    print("-" * len(header))
    worst_ratio = 0.0
    for path in towns:
        bare, model, ratio, bare_faults, model_faults, result = parse_and_read(path, lxml_parser, args.repeats)
        worst_ratio = max(worst_ratio, ratio)
        borders, points = median_time(lambda doc=result.document: sample_borders(doc), args.repeats)
        target = f"< {TOWN07_BORDERS_TARGET_S * 1000:.0f}" if path.stem == "Town07" else ""
        flag = "" if ratio <= READ_RATIO_TARGET else " !"
        if path.stem == "Town07" and borders >= TOWN07_BORDERS_TARGET_S:
            target += " !"
        print(
            f"{path.stem:<8} {path.stat().st_size / 1e6:>5.2f} {bare * 1e3:>8.1f} {bare_faults:>7.0f} "
            f"{model * 1e3:>8.1f} {model_faults:>7.0f} {ratio:>6.2f} "
            f"{READ_RATIO_TARGET:>4g}{flag:2} {borders * 1e3:>8.1f} {points:>8} {target:>8}"
        )
    print(f"worst read/lxml ratio {worst_ratio:.2f} (target <= {READ_RATIO_TARGET:g}); '!' marks a missed target")


if __name__ == "__main__":
    main()
