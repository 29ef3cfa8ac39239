"""Quality-diversity search against random generation, at the same number of evaluated intersections, in one run
(issue 13).

    python benchmarks/bench_search.py --evaluations 5000 -j 2 -o /tmp/bench_search   # the issue's budget, idle machine
    nice -n 10 python benchmarks/bench_search.py --evaluations 480 -j 2 --random-cap 300   # ~20 min, busy 2 cores

Two samplers fill the same archive, ``junctionart search``'s default grid (legs x min_angle x area, 5 x 12 x 15 = 900
cells; feasible = 0 error-level xodrcheck findings; objective = compactness):

1. ``junctionart search`` (MAP-Elites with pyribs' bandit scheduler over its emitters), ``--evaluations`` maps, each
   one intersection;
2. random generation the way ``junctionart era`` samples it: 1 km x 1 km maps with seeds 0, 1, 2, ..., two-lane and
   random-lane in turn (``era``'s two runs), each map checked as a whole (the intersections of a map with an error
   are evaluated but infeasible) and every intersection of 3+ legs measured; the sample is the first N intersections
   in (seed, junction) order, ``era``'s own unit, N = the search's evaluated maps.

Both are also binned on the old 2-D grid (legs x min_angle, 60 cells) from the same evaluations, for comparison;
``rows.json`` keeps every feasible evaluated intersection's metrics of both samplers, to bin them on other grids.
``--descriptors`` (legs first) runs the comparison on another grid than the search's default.

Then the time to ``--target`` distinct valid 7-leg intersections (distinct = different file bytes; valid = 0 errors),
measured for both from the start of each sampler: the search keeps iterating past ``--evaluations`` until it has
evaluated that many (or ``--target-budget`` maps); random generation keeps generating maps until it has that many or
``--random-cap`` seconds have passed, and is then extrapolated from its measured 7-leg rate (the time so far x target
/ hits; with no hit, a lower bound from the rule of three, 3 / intersections as the 95 % upper bound of the rate).
7-leg intersections are so rare (9 in ``era``'s 20,000, on 2 km maps) that a cap of minutes sees none or one, so the
benchmark also prints random generation's time at ``era``'s rate and this run's seconds per intersection.
Times are wall clock of one process per sampler on this machine (absolute, noisy when it is shared); cells and
QD-scores are exact counts of the run. ``-j N`` gives both samplers N worker processes (the search evaluates its
batches on them, random generation makes N maps at a time and takes their results in seed order, so its sample is
the same as with one); ``-j 1`` (the default) runs everything in this process.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from junctionart.search.engine import Settings  # noqa: E402
from junctionart.search.genome import DIM  # noqa: E402
from junctionart.search.measure import DEFAULT_DESCRIPTORS, METRICS, Evaluation, evaluate, objective  # noqa: E402

GRID: tuple[tuple[str, int], ...] = tuple((name, METRICS[name][2]) for name in DEFAULT_DESCRIPTORS)
FLAT = (("legs", 5), ("min_angle", 12))
SEVEN = 7
#: 7-leg intersections in ``junctionart era``'s two runs of 10,000 (docs/era/report.md: two-lane 2, random-lane 7).
ERA_SEVENS, ERA_INTERSECTIONS = 9, 20_000


def _archive(grid: tuple[tuple[str, int], ...]) -> Any:
    from ribs.archives import GridArchive

    return GridArchive(
        solution_dim=1,
        dims=[c for _, c in grid],
        ranges=[METRICS[n][:2] for n, _ in grid],
        learning_rate=1.0,
        threshold_min=0.0,
    )


def filled(rows: list[dict[str, float]], grid: tuple[tuple[str, int], ...]) -> Any:
    """An archive of ``grid`` holding the best of ``rows`` (feasible metric rows) per cell."""
    archive = _archive(grid)
    if rows:
        archive.add(
            np.zeros((len(rows), 1)),
            np.array([objective(r["area"]) for r in rows]),
            np.array([[r[n] for n, _ in grid] for r in rows]),
        )
    return archive


def era_map(seed: int) -> tuple[list[dict[str, float]], list[str], bool]:
    """One random map as ``era`` samples it (two-lane / random-lane by seed parity): its intersections' metrics (NaN
    rows kept: evaluated, infeasible), a digest per intersection, and whether xodrcheck finds no error in it."""
    import hashlib

    from junctionart import generate, to_bytes
    from junctionart.params import Params
    from junctionart.search.measure import measure_document
    from xodrcheck.check import check
    from xodrcheck.reader import read

    params = Params(width=1000.0, height=1000.0, randomize_lanes=bool(seed % 2))
    data = to_bytes(generate(params, seed), params.version)
    ok = check(data).ok
    document = read(data).document
    rows, keys = [], []
    for j in document.junctions if document is not None else []:
        row = measure_document(document, j)
        if row["legs"] >= 3:
            rows.append(row)
            keys.append(hashlib.sha256(f"{seed}:{j.id}".encode()).hexdigest())
    return rows, keys, ok


def _feasible(row: dict[str, float]) -> bool:
    return not any(np.isnan(v) for v in row.values())


class Clock:
    """Wall time since a sampler started, and when it reached ``target`` distinct valid 7-leg intersections."""

    def __init__(self, target: int) -> None:
        self.start = time.perf_counter()
        self.target = target
        self.sevens: set[str] = set()
        self.reached: float | None = None
        self.reached_at = 0

    def seen(self, legs: float, digest: str, evaluated: int) -> None:
        if legs >= SEVEN and digest not in self.sevens:
            self.sevens.add(digest)
            if len(self.sevens) == self.target and self.reached is None:
                self.reached, self.reached_at = self.elapsed(), evaluated

    def elapsed(self) -> float:
        return time.perf_counter() - self.start


def run_search(folder: Path, n: int, args: argparse.Namespace) -> dict[str, Any]:
    """The search arm: iterate until ``n`` maps are evaluated and the 7-leg target is met (or the budget spent)."""
    from tqdm import tqdm

    from junctionart import era
    from junctionart.search.engine import iterate, load_or_start
    from junctionart.search.run import _distributed

    folder.mkdir(parents=True, exist_ok=True)
    state = load_or_start(folder, Settings(GRID, args.seed, args.batch), era.generator_version())
    clock = Clock(args.target)
    executor = era._Local(args.jobs) if args.jobs > 1 else None
    bar = tqdm(total=n, unit="map", desc="search")
    inner = _distributed(executor, None) if executor is not None else (lambda batch: [evaluate(x) for x in batch])
    rows: list[dict[str, float]] = []
    snapshot: dict[str, Any] = {}

    def recorded(batch: list[list[float]]) -> list[Evaluation]:
        results = inner(batch)
        for k, r in enumerate(results):
            if r.feasible:
                if not snapshot:  # the first n maps' feasible rows
                    rows.append(r.metrics)
                clock.seen(r.metrics["legs"], r.sha256, state.evaluated + k + 1)
        bar.update(len(results))
        return results

    try:
        while not snapshot or (clock.reached is None and state.evaluated < args.target_budget):
            iterate(state, recorded)
            if not snapshot and state.evaluated >= n:
                snapshot.update(seconds=clock.elapsed(), evaluated=state.evaluated)
                snapshot["archive"] = _copy(state.scheduler.archive)
                bar.close()
                bar = tqdm(total=args.target, unit="7-leg", desc="search, distinct 7-leg", initial=len(clock.sevens))
            elif snapshot:
                bar.n = len(clock.sevens)
                bar.refresh()
    finally:
        bar.close()
        if executor is not None:
            executor.close()
    return {**snapshot, "rows": rows, "clock": clock, "total": state.evaluated}


def _copy(archive: Any) -> Any:
    """A frozen copy of a search archive (index, objective) in a plain grid archive of the same shape."""
    data = archive.data()
    out = _archive(GRID)
    if len(data["index"]):
        out.add(np.zeros((len(data["index"]), 1)), data["objective"], data["measures"])
    return out


def run_random(n: int, args: argparse.Namespace) -> dict[str, Any]:
    """The random arm: era maps until ``n`` intersections are measured and the 7-leg target or the cap is reached."""
    from tqdm import tqdm

    from junctionart import era

    clock = Clock(args.target)
    sample: list[dict[str, float]] = []  # the first n intersections, NaN rows for infeasible ones
    measured = maps = 0
    coverage_seconds = None
    bar = tqdm(total=n, unit="intersection", desc="random generation")
    executor = era._Local(args.jobs) if args.jobs > 1 else None
    maps_in_seed_order: Iterator[tuple[list[dict[str, float]], list[str], bool]] = iter(())
    seed = 0
    while coverage_seconds is None or (clock.reached is None and clock.elapsed() < args.random_cap):
        result = next(maps_in_seed_order, None)
        if result is None:  # the next block of seeds, one per worker, results in seed order
            block = [(s,) for s in range(seed, seed + args.jobs)]
            seed += args.jobs
            done = executor.map_ordered(era_map, block) if executor is not None else [era_map(*b) for b in block]
            maps_in_seed_order = iter(done)
            continue
        rows, keys, ok = result
        maps += 1
        for row, key in zip(rows, keys):
            measured += 1
            feasible = ok and _feasible(row)
            if len(sample) < n:
                sample.append(row if feasible else dict.fromkeys(row, float("nan")))
            if feasible:
                clock.seen(row["legs"], key, measured)
        if coverage_seconds is None:
            bar.update(min(len(rows), n - bar.n))
            if len(sample) >= n:
                coverage_seconds = clock.elapsed()
                bar.close()
                bar = tqdm(unit="map", desc=f"random generation, 7-leg hits (cap {args.random_cap:.0f} s)")
        else:
            bar.update(1)
            bar.set_postfix(sevens=len(clock.sevens), intersections=measured, refresh=False)
    bar.close()
    if executor is not None:
        executor.close()
    return {
        "rows": [r for r in sample if _feasible(r)],
        "seconds": coverage_seconds,
        "clock": clock,
        "measured": measured,
        "maps": maps,
    }


def _time_to_target(arm: dict[str, Any], target: int) -> tuple[float, str]:
    clock: Clock = arm["clock"]
    if clock.reached is not None:
        return clock.reached, "measured"
    elapsed, hits = clock.elapsed(), len(clock.sevens)
    if hits:
        return elapsed * target / hits, f"extrapolated from {hits} hits in {elapsed:.0f} s"
    count = arm.get("measured", arm.get("total", 0))
    return elapsed * target / 3, f"lower bound: no hit in {count} in {elapsed:.0f} s (rule of three)"


def _era_rate_estimate(arm: dict[str, Any], target: int) -> tuple[float, str]:
    """Random generation's time to ``target`` 7-leg intersections at the rate of ``junctionart era``'s run of 10,000
    intersections per run (:data:`ERA_SEVENS` in :data:`ERA_INTERSECTIONS`, two-lane and random-lane together, as
    this arm alternates them) and this run's measured seconds per intersection: firmer than the arm's own few hits."""
    clock: Clock = arm["clock"]
    per = clock.elapsed() / max(arm["measured"], 1)
    seconds = per * ERA_INTERSECTIONS / ERA_SEVENS * target
    return seconds, f"{per:.3f} s per intersection x {ERA_INTERSECTIONS:,} / {ERA_SEVENS} intersections per 7-leg one"


def figure(path: Path, panels: list[tuple[str, Any]]) -> None:
    """Rows: samplers; columns: leg counts; each panel the 2nd x 3rd descriptor, colour = the cell's objective."""
    from junctionart.extras import pyplot

    plt = pyplot("bench_search")
    dims = [c for _, c in GRID]
    names = [n for n, _ in GRID]
    (lo_a, hi_a, _), (lo_c, hi_c, _) = METRICS[names[1]], METRICS[names[2]] if len(names) > 2 else (0.0, 1.0, 1)
    if len(dims) == 2:
        dims.append(1)
    fig, axes = plt.subplots(
        len(panels), dims[0], figsize=(3.0 * dims[0], 3.0 * len(panels)), sharex=True, sharey=True, squeeze=False
    )
    mesh = None
    for row, (title, archive) in enumerate(panels):
        cube = np.full(dims, np.nan)
        data = archive.data()
        for idx, value in zip(data["index"], data["objective"]):
            cube[np.unravel_index(int(idx), dims)] = value
        for legs in range(dims[0]):
            ax = axes[row][legs]
            mesh = ax.pcolormesh(
                np.linspace(lo_a, hi_a, dims[1] + 1),
                np.linspace(lo_c, hi_c, dims[2] + 1),
                cube[legs].T,
                cmap="viridis",
                vmin=0,
                vmax=0.8,
            )
            count = int(np.isfinite(cube[legs]).sum())
            ax.set_title(f"{legs + 3} legs: {count} cells", fontsize=9)
            if names[2:] == ["complexity"]:
                ax.set_ylim(0.15, 0.85)
            if legs == 0:
                ax.set_ylabel(f"{title}\n{names[2] if len(names) > 2 else ''}", fontsize=9)
            if row == len(panels) - 1:
                ax.set_xlabel(names[1])
    fig.suptitle(", ".join(f"{t}: {len(a)} cells, QD-score {float(a.stats.qd_score):.1f}" for t, a in panels))
    fig.tight_layout()
    if mesh is not None:
        fig.colorbar(mesh, ax=axes.ravel().tolist(), label="objective (compactness)", shrink=0.8)
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--evaluations", type=int, default=480, help="maps of the search = intersections of random")
    ap.add_argument("--target", type=int, default=50, help="distinct valid 7-leg intersections to time")
    ap.add_argument("--target-budget", type=int, default=3000, help="the search gives up after this many maps")
    ap.add_argument("--random-cap", type=float, default=600.0, help="seconds random generation looks for 7-leg ones")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--batch", type=int, default=16)
    ap.add_argument("-j", "--jobs", type=int, default=1)
    ap.add_argument("-o", "--output", type=Path, default=Path("bench_search"))
    ap.add_argument(
        "--descriptors", default=None, help="legs first, e.g. legs,min_angle:12,lanes (default: the search's default)"
    )
    args = ap.parse_args()
    if args.descriptors:
        from junctionart.search.cli import descriptors

        global GRID
        GRID = descriptors(args.descriptors)
        if GRID[0][0] != "legs":
            ap.error("--descriptors: legs must come first (the figure has a column per leg count)")
    args.output.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    evaluate(list(np.full(DIM, 0.5)))  # imports and caches, outside every timing
    print(f"warm-up {time.perf_counter() - t0:.0f} s", file=sys.stderr)

    qd = run_search(args.output / "qd", args.evaluations, args)
    rand = run_random(qd["evaluated"], args)
    random_archive = filled(rand["rows"], GRID)
    n = qd["evaluated"]
    out: dict[str, Any] = {"evaluations": n, "grid": [list(g) for g in GRID]}
    print(f"\n{n} evaluated intersections each; grid {' x '.join(f'{a}:{c}' for a, c in GRID)}")
    print(f"{'sampler':40} {'feasible':>8} {'cells':>6} {'QD-score':>9} {'2-D cells':>9} {'wall s':>7}")
    for name, archive, rows, seconds in (
        ("MAP-Elites (junctionart search)", qd["archive"], qd["rows"], qd["seconds"]),
        ("random generation as era samples", random_archive, rand["rows"], rand["seconds"]),
    ):
        flat = len(filled(rows, FLAT))
        print(
            f"{name:40} {len(rows):8d} {len(archive):6d} {float(archive.stats.qd_score):9.2f} {flat:9d} {seconds:7.0f}"
        )
        out[name] = {
            "feasible": len(rows),
            "cells": len(archive),
            "qd_score": float(archive.stats.qd_score),
            "cells_legs_x_min_angle": flat,
            "seconds": seconds,
        }
    ratio = len(qd["archive"]) / max(len(random_archive), 1)
    print(f"filled cells, search / random: {ratio:.2f}x")
    figure(args.output / "bench_search.png", [("search", qd["archive"]), ("random (era)", random_archive)])

    times = {}
    for name, arm in (("search", qd), ("random", rand)):
        seconds, how = _time_to_target(arm, args.target)
        times[name] = seconds
        out[f"seven_{name}"] = {"seconds": seconds, "how": how, "hits": len(arm["clock"].sevens)}
        print(f"{args.target} distinct valid 7-leg intersections, {name}: {seconds:.0f} s ({how})")
    out["seven_search"]["maps"] = qd["clock"].reached_at or qd["total"]
    out["seven_random"].update(intersections=rand["measured"], maps=rand["maps"])
    print(f"time ratio random / search: {times['random'] / times['search']:.0f}x")
    seconds, how = _era_rate_estimate(rand, args.target)
    out["seven_random"]["era_rate"] = {"seconds": seconds, "how": how}
    print(f"{args.target} distinct valid 7-leg intersections, random at era's rate: {seconds:.0f} s ({how})")
    print(f"time ratio random (era's rate) / search: {seconds / times['search']:.0f}x")
    (args.output / "bench_search.json").write_text(json.dumps(out, indent=1), encoding="utf-8")
    rows_out = {"search": qd["rows"], "random": rand["rows"]}  # every feasible evaluated row: other grids post hoc
    (args.output / "rows.json").write_text(json.dumps(rows_out), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
