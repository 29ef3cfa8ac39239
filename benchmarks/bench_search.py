"""Quality-diversity search against random sampling, at the same number of evaluated maps, in one run (issue 13).

    python benchmarks/bench_search.py --evaluations 5000 -j 2 -o /tmp/bench_search     # the issue's budget
    python benchmarks/bench_search.py --evaluations 300 --era-maps 12 --target 50      # what fits a busy hour

Three samplers fill the same archive (``junctionart search``'s default grid, legs x min_angle, 60 cells; feasible =
0 error-level xodrcheck findings; objective = compactness):

1. ``junctionart search`` (MAP-Elites, pyribs), ``--evaluations`` maps;
2. random genomes: the same number of maps, each a uniformly random vector of the same genome;
3. random generation the way ``junctionart era`` samples: ``--era-maps`` 1 km x 1 km maps with random seeds, two-lane
   and random-lane in turn, each checked as a whole (a map with an error contributes nothing) and every intersection
   (3+ legs) measured into the archive; the number of maps is smaller (each holds about 30 intersections and costs
   about 10 maps of the search), so its figures are given per map and per second.

Then the time to ``--target`` distinct valid 7-leg intersections: a search with ``--where "legs >= 7"`` on a finer
grid (legs x min_angle:36 x area:20) is timed; random generation's time is its measured seconds per intersection times
the intersections it needs per 7-leg one: its own sample's rate when it found any, else the rate of ``docs/era``'s
10,000 + 10,000 intersections (9 7-leg ones). Times are wall clock on this machine (absolute, noisy when it is shared);
coverage and QD-score are exact counts of one run.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from junctionart.search.engine import Settings  # noqa: E402
from junctionart.search.measure import METRICS, NAMES, evaluate, objective  # noqa: E402

GRID = (("legs", 5), ("min_angle", 12))
FINE = (("legs", 5), ("min_angle", 36), ("area", 20))
#: docs/era/report.md: 7-leg intersections among the 20,198 of both runs (2 two-lane + 7 random-lane).
ERA_SEVEN, ERA_TOTAL = 9, 20198


def _archive(grid: tuple[tuple[str, int], ...]):
    from ribs.archives import GridArchive

    return GridArchive(
        solution_dim=1,
        dims=[c for _, c in grid],
        ranges=[METRICS[n][:2] for n, _ in grid],
        learning_rate=1.0,
        threshold_min=0.0,
    )


def _add(archive, rows: list[dict[str, float]], grid) -> None:
    if rows:
        archive.add(
            np.zeros((len(rows), 1)),
            np.array([objective(r["area"]) for r in rows]),
            np.array([[r[n] for n, _ in grid] for r in rows]),
        )


def era_map(seed: int) -> tuple[list[dict[str, float]], bool, float]:
    """One random map as ``era`` samples it (two-lane / random-lane by seed parity): its intersections' metrics,
    whether xodrcheck finds no error, and the seconds it took."""
    from junctionart import generate, to_bytes
    from junctionart.params import Params
    from junctionart.search.measure import measure_document
    from xodrcheck.check import check
    from xodrcheck.reader import read

    t0 = time.perf_counter()
    params = Params(width=1000.0, height=1000.0, randomize_lanes=bool(seed % 2))
    data = to_bytes(generate(params, seed), params.version)
    ok = check(data).ok
    document = read(data).document
    rows = [measure_document(document, j) for j in document.junctions] if document is not None else []
    rows = [r for r in rows if r["legs"] >= 3 and not any(np.isnan(v) for v in r.values())]
    return rows, ok, time.perf_counter() - t0


def _pool_map(pool: ProcessPoolExecutor, fn, items) -> list:
    return list(pool.map(fn, items, chunksize=1))


def random_genomes(pool, n: int, seed: int) -> tuple[list[dict[str, float]], float]:
    from junctionart.search.genome import random_genomes as draw

    t0 = time.perf_counter()
    vectors = [[float(v) for v in x] for x in draw(np.random.default_rng(seed + 1000), n)]
    results = _pool_map(pool, evaluate, vectors)
    return [r.metrics for r in results if r.feasible], time.perf_counter() - t0


def run_search(folder: Path, grid, budget: int, jobs: int, where: str | None = None, wanted: int | None = None):
    from junctionart.search.predicate import Predicate
    from junctionart.search.run import search

    predicate = Predicate.parse(where, NAMES) if where else None
    t0 = time.perf_counter()
    state = search(folder, Settings(grid, 0, 16), budget, predicate, wanted, jobs, progress=False)
    return state, time.perf_counter() - t0


def figure(path: Path, archives: list[tuple[str, object]]) -> None:
    from junctionart.extras import pyplot

    plt = pyplot("bench_search")
    fig, axes = plt.subplots(
        1, len(archives), figsize=(4.6 * len(archives), 4.4), dpi=100, squeeze=False, layout="constrained"
    )
    (lo_a, hi_a, _), (lo_b, hi_b, _) = METRICS["legs"], METRICS["min_angle"]
    for ax, (title, archive) in zip(axes[0], archives):
        grid = np.full((GRID[1][1], GRID[0][1]), np.nan)
        data = archive.data()
        for idx, value in zip(data["index"], data["objective"]):
            a, b = np.unravel_index(int(idx), [c for _, c in GRID])
            grid[b, a] = value
        mesh = ax.pcolormesh(
            np.linspace(lo_a, hi_a, 6), np.linspace(lo_b, hi_b, 13), grid, cmap="viridis", vmin=0, vmax=0.6
        )
        ax.set(xlabel="legs", ylabel="min_angle (deg)", title=f"{title}: {len(archive)} of 60 cells")
    fig.colorbar(mesh, ax=axes[0].tolist(), label="objective (compactness)")
    fig.savefig(path)
    plt.close(fig)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--evaluations", type=int, default=5000)
    ap.add_argument("--era-maps", type=int, default=20)
    ap.add_argument("--target", type=int, default=50, help="distinct valid 7-leg intersections to time")
    ap.add_argument("--target-budget", type=int, default=3000, help="give up the timed search after this many maps")
    ap.add_argument("-j", "--jobs", type=int, default=2)
    ap.add_argument("-o", "--output", type=Path, default=Path("bench_search"))
    args = ap.parse_args()
    args.output.mkdir(parents=True, exist_ok=True)
    out: dict[str, object] = {"evaluations": args.evaluations}

    state, qd_seconds = run_search(args.output / "qd", GRID, args.evaluations, args.jobs)
    with ProcessPoolExecutor(args.jobs) as pool:
        rand_rows, rand_seconds = random_genomes(pool, state.evaluated, 0)
        t0 = time.perf_counter()
        era = _pool_map(pool, era_map, range(args.era_maps))
        era_seconds = time.perf_counter() - t0
    random_archive, era_archive = _archive(GRID), _archive(GRID)
    _add(random_archive, rand_rows, GRID)
    era_rows = [r for rows, ok, _ in era if ok for r in rows]
    _add(era_archive, era_rows, GRID)
    qd = state.scheduler.archive
    table = [
        ("MAP-Elites (junctionart search)", state.evaluated, qd, qd_seconds),
        ("random genomes", state.evaluated, random_archive, rand_seconds),
        (f"random maps as era ({len(era_rows)} intersections)", args.era_maps, era_archive, era_seconds),
    ]
    print(f"{'sampler':52} {'maps':>6} {'cells':>6} {'coverage':>9} {'QD-score':>9} {'wall s':>7}")
    for name, maps, archive, seconds in table:
        s = archive.stats
        print(f"{name:52} {maps:6d} {len(archive):6d} {float(s.coverage):9.1%} {float(s.qd_score):9.3f} {seconds:7.0f}")
        out[name] = {"maps": maps, "cells": len(archive), "qd_score": float(s.qd_score), "seconds": seconds}
    ratio = len(qd) / max(len(random_archive), 1)
    print(
        f"filled cells, search / random genomes: {ratio:.2f}x; QD-score {float(qd.stats.qd_score):.3f} vs "
        f"{float(random_archive.stats.qd_score):.3f}"
    )
    figure(args.output / "bench_search.png", [(t[0].split(" (")[0], t[2]) for t in table])

    where = "legs >= 7"
    target_state, target_seconds = run_search(
        args.output / "seven", FINE, args.target_budget, args.jobs, where, args.target
    )
    from junctionart.search.engine import matches
    from junctionart.search.predicate import Predicate

    found = matches(target_state, Predicate.parse(where, NAMES))
    per_intersection = era_seconds / max(sum(len(rows) for rows, _, _ in era), 1)
    sevens = sum(1 for r in era_rows if r["legs"] >= 7)
    rate, source = (sevens / len(era_rows), "this run's sample") if sevens else (ERA_SEVEN / ERA_TOTAL, "docs/era")
    random_time = args.target * per_intersection / rate
    print(
        f"{args.target} distinct valid 7-leg intersections: search {target_seconds:.0f} s ({found} found in "
        f"{target_state.evaluated} maps); random generation {random_time:.0f} s expected "
        f"({per_intersection:.3f} s per intersection with its check, 1 in {1 / rate:.0f} has 7 legs, {source}); "
        f"ratio {random_time / target_seconds:.0f}x"
    )
    out["seven"] = {
        "search_seconds": target_seconds,
        "found": found,
        "maps": target_state.evaluated,
        "random_seconds": random_time,
        "rate_source": source,
    }
    (args.output / "bench_search.json").write_text(json.dumps(out, indent=1), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
