"""``xodrcheck sample FILE --step D``: points along every lane's centre line (``--borders``: and its two borders).

Each lane section is sampled at its start, then every D metres of reference-line s, then at its end. Centre lanes (id 0)
are not sampled (with ``--borders`` their line is every ±1 lane's inner border).

* ``csv`` (default): a header line, then one row per point with columns
  ``road,section_s,lane,type,kind,s,x,y,z,hdg`` (``kind``: centre, inner or outer; ``hdg`` in radians;
  lengths in metres with 6 decimals).
* ``geojson``: a FeatureCollection with one LineString per lane line, coordinates ``[x, y, z]`` in the map's own
  metric frame (not WGS 84), properties ``road``, ``section_s``, ``lane``, ``kind``, ``type``.

A step that would give more than ``max_output_points`` points (10 million by default) is refused before anything is
written, with the smallest step that fits (exit 2).
"""

from __future__ import annotations

import argparse
import json
import math
from typing import IO

from xodrcheck.analysis.sample import LaneLine, sample_count, sample_lanes
from xodrcheck.cli.common import (
    error,
    guarded,
    positive_number,
    read_file,
    report_errors,
    target_ok,
    written,
)
from xodrcheck.config import ConfigError, load_config
from xodrcheck.model import Document

NAME = "sample"
HELP = "Sample every lane's centre line (and borders) at a fixed step, as CSV or GeoJSON."

CSV_COLUMNS = ("road", "section_s", "lane", "type", "kind", "s", "x", "y", "z", "hdg")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", metavar="FILE", help="OpenDRIVE file")
    parser.add_argument(
        "--step", type=positive_number, required=True, metavar="D", help="distance in s between samples (m)"
    )
    parser.add_argument("--borders", action="store_true", help="also sample each lane's inner and outer border")
    parser.add_argument("--format", choices=("csv", "geojson"), default="csv", help="output format (default: csv)")
    parser.add_argument("-o", "--output", metavar="OUT", help="write here (atomically) instead of standard output")


def _csv_field(value: str) -> str:
    """Quote a field only when it needs it (ids are free text in OpenDRIVE)."""
    if any(c in value for c in ',"\r\n'):
        return '"' + value.replace('"', '""') + '"'
    return value


def write_csv(lines, stream: IO[str]) -> None:
    stream.write(",".join(CSV_COLUMNS) + "\n")
    for line in lines:
        prefix = f"{_csv_field(line.road)},{line.section_s:.6f},{line.lane},{_csv_field(line.lane_type)},{line.kind}"
        stream.writelines(
            f"{prefix},{s:.6f},{x:.6f},{y:.6f},{z:.6f},{h:.9f}\n"
            for s, x, y, z, h in zip(
                line.s.tolist(), line.x.tolist(), line.y.tolist(), line.z.tolist(), line.hdg.tolist()
            )
        )


def _feature(line: LaneLine) -> dict:
    coords = [
        [round(x, 6), round(y, 6), round(z, 6)] for x, y, z in zip(line.x.tolist(), line.y.tolist(), line.z.tolist())
    ]
    return {
        "type": "Feature",
        "geometry": {"type": "LineString", "coordinates": coords},
        "properties": {
            "road": line.road,
            "section_s": line.section_s,
            "lane": line.lane,
            "kind": line.kind,
            "type": line.lane_type,
        },
    }


def write_geojson(lines, stream: IO[str]) -> None:
    stream.write('{"type": "FeatureCollection", "features": [')
    for index, line in enumerate(lines):
        stream.write(("\n" if index == 0 else ",\n") + json.dumps(_feature(line), allow_nan=False))
    stream.write("\n]}\n")


def _step_that_fits(document: Document, step: float, kinds: tuple[str, ...], cap: int) -> float:
    """The smallest step of three significant digits, from ``step`` up, whose sample count is within ``cap``."""
    while True:
        exponent = math.floor(math.log10(step)) - 2
        rounded = math.ceil(step / 10.0**exponent) * 10.0**exponent
        if sample_count(document, rounded, kinds) <= cap:
            return rounded
        step = rounded * 1.001


def run(args: argparse.Namespace) -> int:
    if not target_ok(args.output):
        return 2

    def one() -> int:
        try:
            cap = load_config().tolerances.max_output_points
        except ConfigError as exc:
            error(f"configuration: {exc}")
            return 2
        result = read_file(args.file)
        if result is None:
            return 2
        failed = report_errors(args.file, result)
        assert result.document is not None  # read_file refuses a file without one
        kinds = ("centre", "inner", "outer") if args.borders else ("centre",)
        count = sample_count(result.document, args.step, kinds)
        if count > cap:
            fits = _step_that_fits(result.document, args.step * count / cap, kinds, cap)
            error(
                f"sample: --step {args.step:g} would give {count:.3g} points, more than the bound of {cap:,} "
                f"(tolerance max_output_points); use a step of at least {fits:g} m"
            )
            return 2
        lines = sample_lanes(result.document, args.step, kinds, budget=cap)
        writer = write_geojson if args.format == "geojson" else write_csv
        if not written(args.output, lambda stream: writer(lines, stream)):
            return 2
        return 1 if failed else 0

    return guarded(args.file, one)
