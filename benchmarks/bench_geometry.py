"""Geometry speed: every lane border of a map sampled every 0.5 m, vectorised per road and lane section.

Prints, for CARLA Town07 (or the maps given), the median time over ``--repeats`` runs of evaluating every lane's outer
border (and lane 0's line, so every border of every lane) at 0.5 m steps from a freshly built geometry, the number of
points, the time of the adaptive sampler (``RoadGeometry.sample_s`` at the default chord tolerance) for the same map,
and the per-point cost relative to evaluating the reference line alone. Target: Town07's borders in under 1 s.

    python benchmarks/bench_geometry.py [--repeats 5] [--corpus DIR] [MAP.xodr ...]
"""

from __future__ import annotations

import argparse
import os
import statistics
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

from xodrcheck.geometry.lanes import RoadGeometry
from xodrcheck.reader import read

REPO = Path(__file__).resolve().parents[1]
STEP = 0.5
TARGET_S = 1.0


def median_time(fn: Callable[[], int], repeats: int) -> tuple[float, int]:
    times, value = [], 0
    for _ in range(repeats):
        start = time.perf_counter()
        value = fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times), value


def grid(start: float, end: float) -> np.ndarray:
    return np.unique(np.append(np.arange(start, end, STEP), end))


def sample_borders(document) -> int:
    points = 0
    for road in document.roads:
        geometry = RoadGeometry(road)
        for index in range(len(road.lane_sections)):
            start, end = geometry.section_range(index)
            if end > start:
                points += sum(len(line.x) for line in geometry.border_curves(index, grid(start, end)).values())
    return points


def sample_reference(document) -> int:
    points = 0
    for road in document.roads:
        geometry = RoadGeometry(road)
        for index in range(len(road.lane_sections)):
            start, end = geometry.section_range(index)
            if end > start:
                points += len(geometry.reference(grid(start, end)).x)
    return points


def sample_adaptive(document) -> int:
    points = 0
    for road in document.roads:
        geometry = RoadGeometry(road)
        for index in range(len(road.lane_sections)):
            points += len(geometry.sample_s(index))
    return points


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("maps", nargs="*", type=Path)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument(
        "--corpus", type=Path, default=Path(os.environ.get("XODR_CORPUS", REPO.parent / "shared" / "corpus"))
    )
    args = parser.parse_args()
    maps = args.maps or [args.corpus / "carla-towns" / "OpenDrive" / "Town07.xodr"]
    print(f"median of {args.repeats} runs; borders every {STEP} m; adaptive: sample_s at the default chord tolerance")
    print(f"{'map':28s} {'borders s':>10s} {'points':>8s} {'ref line s':>10s} {'ratio':>6s} {'adaptive s':>10s} target")
    for path in maps:
        document = read(path).document
        if document is None:
            print(f"{path.name:28s} could not be read")
            continue
        borders, points = median_time(lambda doc=document: sample_borders(doc), args.repeats)
        reference, _ = median_time(lambda doc=document: sample_reference(doc), args.repeats)
        adaptive, _ = median_time(lambda doc=document: sample_adaptive(doc), args.repeats)
        verdict = "ok" if borders < TARGET_S else "MISSED"
        print(
            f"{path.name:28s} {borders:10.3f} {points:8d} {reference:10.3f} {borders / reference:6.1f} {adaptive:10.3f}"
            f" < {TARGET_S:g} s {verdict}"
        )


if __name__ == "__main__":
    main()
