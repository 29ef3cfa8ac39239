"""Reading and sampling speed on the CARLA towns, as ratios measured in one run.

For each town: a bare ``lxml.etree.parse`` of the file, ``xodrcheck.reader.read`` of the same file, their ratio, and the
time to sample every lane's inner and outer border every 0.5 m from the read document (road geometry built afresh).
Each figure is the median of ``--repeats`` runs (the ratio: the median of the ratios of parse and read timed one
after the other). Targets, printed beside: read within 2x of the bare parse on every town (issue 14); Town07's
borders in under 1 s.

    python benchmarks/bench_read.py [--repeats 5] [--corpus DIR]

The corpus folder defaults to ``$XODR_CORPUS``, else ``../shared/corpus`` beside the checkout.
"""

from __future__ import annotations

import argparse
import os
import statistics
import time
from collections.abc import Callable
from pathlib import Path

from lxml import etree

from xodrcheck.lanes import RoadGeometry
from xodrcheck.reader import read
from xodrcheck.sample import sample_lanes

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


def parse_and_read(path: Path, parser: etree.XMLParser, repeats: int):
    """Bare parse and read() timed in alternation, so both see the same machine load; medians, the median of the
    per-repeat ratios, and the last read result."""
    bare, model, ratios = [], [], []
    result = None
    for _ in range(repeats):
        t_bare, _ = timed(lambda: etree.parse(str(path), parser))
        t_model, result = timed(lambda: read(path))
        bare.append(t_bare)
        model.append(t_model)
        ratios.append(t_model / t_bare)
    return statistics.median(bare), statistics.median(model), statistics.median(ratios), result


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
    args = parser.parse_args()
    towns = sorted((args.corpus / "carla-towns").rglob("Town*.xodr"))
    if not towns:
        raise SystemExit(f"no CARLA towns under {args.corpus / 'carla-towns'}: set XODR_CORPUS or --corpus")

    lxml_parser = etree.XMLParser(resolve_entities=False, no_network=True)
    header = (
        f"{'map':<8} {'MB':>5} {'lxml ms':>8} {'read ms':>8} {'ratio':>6} {'<=':>4} "
        f"{'borders ms':>10} {'points':>8} {'target':>8}"
    )
    print(f"median of {args.repeats} runs; borders: inner and outer border of every lane every {STEP} m")
    print(header)
    print("-" * len(header))
    worst_ratio = 0.0
    for path in towns:
        bare, model, ratio, result = parse_and_read(path, lxml_parser, args.repeats)
        worst_ratio = max(worst_ratio, ratio)
        borders, points = median_time(lambda doc=result.document: sample_borders(doc), args.repeats)
        target = f"< {TOWN07_BORDERS_TARGET_S * 1000:.0f}" if path.stem == "Town07" else ""
        flag = "" if ratio <= READ_RATIO_TARGET else " !"
        if path.stem == "Town07" and borders >= TOWN07_BORDERS_TARGET_S:
            target += " !"
        print(
            f"{path.stem:<8} {path.stat().st_size / 1e6:>5.2f} {bare * 1e3:>8.1f} {model * 1e3:>8.1f} {ratio:>6.2f} "
            f"{READ_RATIO_TARGET:>4g}{flag:2} {borders * 1e3:>8.1f} {points:>8} {target:>8}"
        )
    print(f"worst read/lxml ratio {worst_ratio:.2f} (target <= {READ_RATIO_TARGET:g}); '!' marks a missed target")


if __name__ == "__main__":
    main()
