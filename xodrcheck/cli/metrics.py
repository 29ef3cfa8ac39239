"""``xodrcheck metrics FILE... --format json|csv [-o OUT]``: expressive-range metrics of every junction.

The metrics are defined in :mod:`xodrcheck.analysis.metrics`. Column names carry their unit: ``_m`` metres, ``_m2``
square metres, ``_deg`` degrees, ``_deg_per_m`` degrees per metre; ``conflict_ratio`` (conflict area / area) and
``complexity`` are ratios in [0, 1], ``legs`` and the ``n_`` columns counts. A value that does not apply is null (JSON)
or empty (CSV).

* ``--format csv`` (default): one row per junction leg, with the junction's own columns repeated on each of its legs
  (a junction without legs gets one row with empty leg columns). Columns: :data:`COLUMNS`.
* ``--format json``: one object per file, one per line (JSON Lines): ``{"file", "junctions": [{junction columns...,
  "legs": n, "leg_metrics": [{leg columns...}]}]}``.
"""

from __future__ import annotations

import argparse
import csv
import json
import sys
from collections.abc import Iterator
from typing import IO

from xodrcheck.analysis.metrics import JunctionMetrics, LegMetrics, map_metrics
from xodrcheck.cli.common import error, guarded, read_file, report_errors, target_ok, written

NAME = "metrics"
HELP = "Expressive-range metrics of every junction: FOV, maxCurvature, cornerDeviation, complexity, area, conflicts."

JUNCTION_COLUMNS = (
    "junction",
    "junction_name",
    "junction_type",
    "legs",
    "n_connection_lanes",
    "n_u_turn_lanes",
    "area_m2",
    "conflict_area_m2",
    "conflict_ratio",
)
LEG_COLUMNS = (
    "leg",
    "road",
    "contact",
    "x_m",
    "y_m",
    "fov_deg",
    "max_curvature_deg_per_m",
    "corner_deviation_deg",
    "complexity",
)
#: CSV columns, in order.
COLUMNS = ("file", *JUNCTION_COLUMNS, *LEG_COLUMNS)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("files", nargs="+", metavar="FILE", help="OpenDRIVE files")
    parser.add_argument("--format", choices=("csv", "json"), default="csv", help="output format (default: csv)")
    parser.add_argument("-o", "--output", metavar="OUT", help="write to this file instead of standard output")


def junction_fields(m: JunctionMetrics) -> dict:
    return {
        "junction": m.junction,
        "junction_name": m.name,
        "junction_type": m.type.value,
        "legs": m.legs,
        "n_connection_lanes": m.n_connection_lanes,
        "n_u_turn_lanes": m.n_u_turn_lanes,
        "area_m2": m.area,
        "conflict_area_m2": m.conflict_area,
        "conflict_ratio": m.conflict_ratio,
    }


def leg_fields(index: int | None, leg: LegMetrics | None) -> dict:
    if leg is None:
        return dict.fromkeys(LEG_COLUMNS)
    return {
        "leg": index,
        "road": leg.road,
        "contact": leg.end.value,
        "x_m": leg.x,
        "y_m": leg.y,
        "fov_deg": leg.fov,
        "max_curvature_deg_per_m": leg.max_curvature,
        "corner_deviation_deg": leg.corner_deviation,
        "complexity": leg.complexity,
    }


def rows(path: str, metrics: tuple[JunctionMetrics, ...]) -> Iterator[dict]:
    """The CSV rows of one file (one per leg; one for a junction without legs)."""
    for m in metrics:
        head = {"file": path, **junction_fields(m)}
        legs: list[tuple[int | None, LegMetrics | None]] = list(enumerate(m.leg_metrics)) or [(None, None)]
        for index, leg in legs:
            yield {**head, **leg_fields(index, leg)}


def to_json(path: str, metrics: tuple[JunctionMetrics, ...]) -> dict:
    return {
        "file": path,
        "junctions": [
            {**junction_fields(m), "leg_metrics": [leg_fields(i, leg) for i, leg in enumerate(m.leg_metrics)]}
            for m in metrics
        ],
    }


def _cell(value):
    return "" if value is None else value


class _Writer:
    """Writes the files' metrics in the chosen format; the CSV header goes out with the first rows (a run whose
    files all fail to read prints nothing)."""

    def __init__(self, stream: IO[str], fmt: str) -> None:
        self.stream, self.fmt = stream, fmt
        self.csv: csv.DictWriter[str] | None = None

    def add(self, path: str, metrics: tuple[JunctionMetrics, ...]) -> None:
        if self.fmt == "json":
            self.stream.write(json.dumps(to_json(path, metrics)) + "\n")
            return
        if self.csv is None:
            self.csv = csv.DictWriter(self.stream, fieldnames=COLUMNS, lineterminator="\n")
            self.csv.writeheader()
        self.csv.writerows({k: _cell(v) for k, v in row.items()} for row in rows(path, metrics))


def _measure_all(files: list[str], sink) -> int:
    """Measure each file and hand its metrics to ``sink(path, metrics)``; return the worst exit code."""
    worst = 0
    for path in files:

        def one(path: str = path) -> int:
            result = read_file(path)
            if result is None:
                return 2
            code = 1 if report_errors(path, result) else 0
            assert result.document is not None  # read_file refuses a file without one
            sink(path, map_metrics(result.document))
            return code

        worst = max(worst, guarded(path, one))
    return worst


def run(args: argparse.Namespace) -> int:
    if args.output in (None, "-"):  # standard output: each file's metrics as soon as they are measured
        worst = _measure_all(args.files, _Writer(sys.stdout, args.format).add)
        sys.stdout.flush()
        return worst
    if not target_ok(args.output):
        return 2
    measured: list[tuple[str, tuple[JunctionMetrics, ...]]] = []
    worst = _measure_all(args.files, lambda path, metrics: measured.append((path, metrics)))
    if worst == 2:
        if measured:  # the others could be: say why their metrics are not in the file either
            error(f"nothing written to {args.output}: a file could not be measured")
        return 2

    def write(stream: IO[str]) -> None:
        writer = _Writer(stream, args.format)
        for path, metrics in measured:
            writer.add(path, metrics)

    return worst if written(args.output, write) else 2
