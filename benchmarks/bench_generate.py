"""The paper's Table 1 configurations, timed in one run: CPU time per valid map (whole pipeline, file written), peak
traced memory, tries and valid maps, with the original JunctionArt's figures measured on the same kind of machine
(``junctionart-notes.md``) printed beside.

    python benchmarks/bench_generate.py            # 500 m and 1 km: 10 maps each, 5 km: 1 map
    python benchmarks/bench_generate.py --maps 50 --big-maps 3 --repeats 3

The CPU time of a configuration is the median over ``--repeats`` passes over the same seeds (this machine is a VM
whose CPU time per pass varies by up to 20 %); tries and valid maps are counted once.
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys
import tempfile
import time
import tracemalloc
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

import junctionart as ja  # noqa: E402 (after the sys.path entry)
from junctionart import controllines  # noqa: E402 (after the sys.path entry)
from junctionart.params import Params  # noqa: E402 (after the sys.path entry)

#: (label, size, randomize lanes, original CPU s per valid map, original tries per valid map)
CONFIGS = [
    ("500 x 500 m, 2 lanes", 500, False, 0.105, 1.0),
    ("500 x 500 m, random lanes", 500, True, 0.124, 1.0),
    ("1 x 1 km, 2 lanes", 1000, False, 0.44, 1.0),
    ("1 x 1 km, random lanes", 1000, True, 0.53, 1.0),
    ("5 x 5 km, 2 lanes", 5000, False, 26.0, 14 / 5),
    ("5 x 5 km, random lanes", 5000, True, 37.0, 21 / 5),
]


def _run(params: Params, seeds: range, lines, out: Path, repeats: int = 1) -> tuple[float, int, int, dict]:
    """Median CPU time of ``repeats`` passes over ``seeds``; tries, valid maps and statistics of the first pass."""
    first = _pass(params, seeds, lines, out)
    times = [first[0]] + [_pass(params, seeds, lines, out)[0] for _ in range(repeats - 1)]
    return (statistics.median(times), *first[1:])


def _pass(params: Params, seeds: range, lines, out: Path) -> tuple[float, int, int, dict]:
    tries = valid = 0
    stats = {"roads": 0, "junctions": 0, "connections": 0, "repairs": 0}
    t0 = time.process_time()
    for seed in seeds:
        tries += 1
        result = ja.generate_layout(params, seed, lines)
        ja.write(result.document, out)
        valid += 1
        lay = result.layout
        stats["roads"] += len(lay.roads)
        stats["junctions"] += len(lay.junctions)
        stats["connections"] += sum(len(j.connections) for j in lay.junctions)
        stats["repairs"] += len(lay.repairs)
    cpu = time.process_time() - t0
    return cpu, tries, valid, stats


def _peak(params: Params, seed: int, lines, out: Path) -> float:
    tracemalloc.start()
    ja.write(ja.generate(params, seed, lines), out)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    return peak / 1e6


def _rss_mb() -> float:
    import resource

    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0  # kB on Linux


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--maps", type=int, default=10, help="maps per 500 m / 1 km configuration")
    ap.add_argument("--big-maps", type=int, default=1, help="maps per 5 km configuration (0: skip)")
    ap.add_argument("--repeats", type=int, default=1, help="timed passes per configuration (median; 5 km: one pass)")
    args = ap.parse_args(argv)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "map.xodr"
        # warm-up, untimed: first calls import and build lazily (scipy, shapely, caches), as in any long run
        ja.write(ja.generate(Params(width=500, height=500, randomize_lanes=True), 10**6), out)
        for label, size, rnd, orig_cpu, orig_tries in CONFIGS:
            n = args.big_maps if size >= 5000 else args.maps
            if n <= 0:
                continue
            params = Params(width=size, height=size, randomize_lanes=rnd)
            cpu, tries, valid, st = _run(params, range(n), None, out, 1 if size >= 5000 else args.repeats)
            peak = _peak(params, 0, None, out) if size < 5000 else float("nan")
            rows.append((label, cpu / valid, orig_cpu, tries, valid, orig_tries, peak, st, valid))
        a_shape = controllines.load(REPO / "examples" / "a_shape.json")
        for rnd in (False, True):
            params = Params(randomize_lanes=rnd)
            cpu, tries, valid, st = _run(params, range(args.maps), a_shape, out, args.repeats)
            rows.append(
                (
                    f"A shape, {'random' if rnd else '2'} lanes",
                    cpu / valid,
                    float("nan"),
                    tries,
                    valid,
                    1.0,
                    _peak(params, 0, a_shape, out),
                    st,
                    valid,
                )
            )
    print(
        f"{'configuration':28} {'CPU s/map':>10} {'original':>9} {'orig+retry':>10} {'ratio':>6} {'tries':>6} "
        f"{'valid':>6} {'orig tries/map':>14} {'peak MB':>8} {'roads':>7} {'junct.':>7} {'conn.':>7} {'repairs':>8}"
    )
    for label, per, orig, tries, valid, orig_tries, peak, st, n in rows:
        with_retries = orig * orig_tries
        ratio = float("nan") if math.isnan(orig) else per / with_retries
        print(
            f"{label:28} {per:10.3f} {orig:9.3f} {with_retries:10.3f} {ratio:6.2f} {tries:6d} {valid:6d} "
            f"{orig_tries:14.1f} {peak:8.1f} {st['roads'] / n:7.0f} {st['junctions'] / n:7.0f} "
            f"{st['connections'] / n:7.0f} {st['repairs'] / n:8.1f}"
        )
    print(
        "original: CPU s per successful map, generation only, 2 cores (junctionart-notes.md); 'orig+retry' adds its "
        "discarded tries (5 km: 14 and 21 tries for 5 maps); its 1 km run peaks at about 200 MB (process RSS)."
    )
    print(
        "here: whole pipeline including the written file, every try a valid map; peak = Python heap (tracemalloc) "
        f"for one map; process peak RSS over the whole run: {_rss_mb():.0f} MB"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
