"""``xodrcheck metrics FILE... --format json|csv [-o OUT]``: expressive-range metrics of every junction.

The metrics are defined in :mod:`xodrcheck.metrics`. Angles are in degrees, curvature in degrees per metre, areas in
square metres; a value that does not apply is null (JSON) or empty (CSV).

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

from xodrcheck.cli._common import error, guarded, output, read_file, report_errors
from xodrcheck.metrics import JunctionMetrics, LegMetrics, map_metrics

NAME = "metrics"
HELP = "Expressive-range metrics of every junction: FOV, maxCurvature, cornerDeviation, complexity, area, conflicts."

JUNCTION_COLUMNS = (
    "junction",
    "junction_name",
    "junction_type",
    "legs",
    "n_connection_lanes",
    "n_u_turn_lanes",
    "area",
    "conflict_area",
    "conflict_ratio",
)
LEG_COLUMNS = ("leg", "road", "contact", "x", "y", "fov", "max_curvature", "corner_deviation", "complexity")
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
        "area": m.area,
        "conflict_area": m.conflict_area,
        "conflict_ratio": m.conflict_ratio,
    }


def leg_fields(index: int | None, leg: LegMetrics | None) -> dict:
    if leg is None:
        return dict.fromkeys(LEG_COLUMNS)
    return {
        "leg": index,
        "road": leg.road,
        "contact": leg.end.value,
        "x": leg.x,
        "y": leg.y,
        "fov": leg.fov,
        "max_curvature": leg.max_curvature,
        "corner_deviation": leg.corner_deviation,
        "complexity": leg.complexity,
    }


def rows(path: str, metrics: tuple[JunctionMetrics, ...]) -> Iterator[dict]:
    """The CSV rows of one file (one per leg; one for a junction without legs)."""
    for m in metrics:
        head = {"file": path, **junction_fields(m)}
        legs = list(enumerate(m.leg_metrics)) or [(None, None)]
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


def run(args: argparse.Namespace) -> int:
    worst = 0
    try:
        with output(args.output) as stream:
            writer = None
            if args.format == "csv":
                writer = csv.DictWriter(stream, fieldnames=COLUMNS, lineterminator="\n")
                writer.writeheader()
            for path in args.files:

                def one(path: str = path) -> int:
                    result = read_file(path)
                    if result is None:
                        return 2
                    if result.document is None:
                        report_errors(path, result)
                        return 2
                    metrics = map_metrics(result.document)
                    if writer is not None:
                        writer.writerows({k: _cell(v) for k, v in row.items()} for row in rows(path, metrics))
                    else:
                        stream.write(json.dumps(to_json(path, metrics)) + "\n")
                    return 1 if report_errors(path, result) else 0

                worst = max(worst, guarded(path, one))
    except BrokenPipeError:
        raise
    except OSError as exc:
        error(f"cannot write {args.output}: {exc.strerror or exc}")
        return 2
    sys.stdout.flush()
    return worst
