"""``junctionart search``: the command line of the quality-diversity search."""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import ParamsError
from .measure import DEFAULT_DESCRIPTORS, METRICS, NAMES

if TYPE_CHECKING:
    from .engine import State
    from .predicate import Predicate


def add_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "-o",
        "--output",
        type=Path,
        default=Path("search"),
        help="folder of the results (default: ./search); reused to resume",
    )
    p.add_argument(
        "--kind",
        default="junction",
        help="what to search (default: junction, an intersection of 3 to 7 legs); each kind has its own genome and "
        "metrics (junctionart.search.kinds)",
    )
    p.add_argument(
        "--descriptors",
        default=None,
        metavar="NAME[:CELLS],...",
        help=f"two or three metrics spanning the archive; for junctions from {', '.join(NAMES)} "
        f"(default: {','.join(DEFAULT_DESCRIPTORS)}; each kind has its own; cells per metric: its default, or "
        "NAME:CELLS)",
    )
    p.add_argument("--where", default=None, help='stop when -n elites meet this, e.g. "legs >= 6 and min_angle < 30"')
    p.add_argument(
        "-n", "--elites", type=int, default=None, help="how many distinct elites must meet --where (default 50)"
    )
    p.add_argument(
        "--evaluations", type=int, default=5000, help="budget: stop after this many evaluated maps (default 5000)"
    )
    p.add_argument("--seed", type=int, default=0, help="random seed of the search (default 0)")
    p.add_argument(
        "--batch", type=int, default=16, help="candidates per emitter per iteration (default 16, 2 emitters)"
    )
    p.add_argument("-j", "--jobs", type=int, default=None, help="worker processes (default: all cores)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS", help="run on this Dask scheduler instead")
    p.add_argument("--no-maps", action="store_true", help="do not write the elites' .xodr files")
    p.add_argument(
        "--network",
        action="store_true",
        help="also place each elite meeting --where (every elite without it) into an ordinary generated map: "
        "network/*.xodr, listed in network.csv (each map checked and re-measured: it holds a junction meeting the "
        "target)",
    )
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")


def descriptors(text: str, metrics: dict[str, tuple[float, float, int]] = METRICS) -> tuple[tuple[str, int], ...]:
    """``legs,min_angle:24`` -> ((legs, 5), (min_angle, 24)), the names among ``metrics`` (a kind's)."""
    out = []
    for item in (part.strip() for part in text.split(",")):
        name, _, cells = item.partition(":")
        if name not in metrics:
            raise ParamsError(f"--descriptors: unknown metric {name!r}; choose from {', '.join(metrics)}")
        try:
            n = int(cells) if cells else metrics[name][2]
        except ValueError:
            raise ParamsError(f"--descriptors: {item!r}: CELLS must be an integer") from None
        if not 1 <= n <= 200:
            raise ParamsError(f"--descriptors: {item!r}: CELLS must be in [1, 200]")
        out.append((name, n))
    if not 2 <= len(out) <= 3 or len({n for n, _ in out}) != len(out):
        raise ParamsError(f"--descriptors {text!r}: give two or three different metrics")
    return tuple(out)


def run(args: argparse.Namespace) -> int:
    try:
        import ribs  # noqa: F401
    except ImportError:
        raise ParamsError("junctionart search needs pyribs: pip install 'junctionart[search]'") from None
    from . import kinds
    from .engine import Settings
    from .outputs import write_all
    from .predicate import Predicate
    from .run import search

    kind = kinds.get(args.kind)
    metrics = kind.METRICS
    where = Predicate.parse(args.where, tuple(metrics)) if args.where is not None else None
    wanted = args.elites if args.elites is not None else (50 if where is not None else None)
    if wanted is not None and wanted < 1:
        raise ParamsError(f"-n {wanted}: must be at least 1")
    if args.seed < 0 or not 1 <= args.batch <= 10_000:
        raise ParamsError("--seed must be >= 0 and --batch in [1, 10000]")
    if args.network and args.kind != "junction":
        raise ParamsError(f"--network places junctions into generated maps; it does not take --kind {args.kind}")
    text = args.descriptors if args.descriptors is not None else ",".join(kind.DEFAULT_DESCRIPTORS)
    settings = Settings(descriptors(text, metrics), args.seed, args.batch, args.kind)
    t0 = time.perf_counter()
    state = search(args.output, settings, args.evaluations, where, wanted, args.jobs, args.scheduler, not args.quiet)
    report = write_all(args.output, state, where, maps=not args.no_maps)
    stats = state.scheduler.archive.stats
    found = "" if where is None else f", {sum(1 for _ in _meeting(state, where))} meet --where"
    print(
        f"{report}: {state.evaluated} maps evaluated, {int(stats.num_elites)} elites ({float(stats.coverage):.1%} "
        f"coverage, QD-score {float(stats.qd_score):.2f}){found}, {time.perf_counter() - t0:.0f} s"
    )
    if args.network:
        _network(args, where)
    if where is not None and wanted is not None and sum(1 for _ in _meeting(state, where)) < wanted:
        print(
            f"junctionart: warning: the budget of {args.evaluations} maps ran out before {wanted} elites met "
            f"--where; rerun with a larger --evaluations to resume",
            file=sys.stderr,
        )
    return 0


def _network(args: argparse.Namespace, where: Predicate | None) -> None:
    import csv
    import os

    from .place import place_all

    with open(args.output / "archive.csv", newline="", encoding="utf-8") as stream:
        rows = list(csv.DictReader(stream))
    jobs = args.jobs or os.cpu_count() or 1
    listing = place_all(args.output, rows, None if where is None else where.text, jobs, not args.quiet)
    with open(listing, newline="", encoding="utf-8") as stream:
        placed = list(csv.DictReader(stream))
    done = sum(1 for r in placed if r["map"])
    print(f"{listing}: {done} of {len(placed)} elites placed into generated maps under {args.output / 'network'}")
    if done < len(placed):
        print(
            f"junctionart: warning: {len(placed) - done} elites could not be placed so that the map keeps a junction "
            "meeting the target (network.csv lists them without a map)",
            file=sys.stderr,
        )


def _meeting(state: State, where: Predicate) -> Iterator[int]:
    from .engine import elites

    data = elites(state)
    for row in range(len(data["index"])):
        if where({n: float(data[n][row]) for n in state.settings.metrics}):
            yield row
