"""``xodrcheck sample FILE --step D``: points along every lane's centre line (``--borders``: and its two borders).

Each lane section is sampled at its start, then every D metres of reference-line s, then at its end. Centre lanes (id 0)
are not sampled (with ``--borders`` their line is every ±1 lane's inner border).

* ``csv`` (default): a header line, then one row per point with columns
  ``road,section_s,lane,type,kind,s,x,y,z,hdg`` (``kind``: centre, inner or outer; ``hdg`` in radians;
  lengths in metres with 6 decimals).
* ``geojson``: a FeatureCollection with one LineString per lane line, coordinates ``[x, y, z]`` in the map's own
  metric frame (not WGS 84), properties ``road``, ``section_s``, ``lane``, ``kind``, ``type``.
"""

from __future__ import annotations

import argparse
import json
from typing import IO

from xodrcheck.cli._common import (
    error,
    guarded,
    output,
    positive_number,
    read_file,
    report_errors,
)
from xodrcheck.sample import LaneLine, sample_lanes

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


def run(args: argparse.Namespace) -> int:
    def one() -> int:
        result = read_file(args.file)
        if result is None:
            return 2
        failed = report_errors(args.file, result)
        if result.document is None:
            return 1
        kinds = ("centre", "inner", "outer") if args.borders else ("centre",)
        lines = sample_lanes(result.document, args.step, kinds)
        writer = write_geojson if args.format == "geojson" else write_csv
        try:
            with output(args.output) as stream:
                writer(lines, stream)
        except BrokenPipeError:
            raise
        except OSError as exc:
            error(f"cannot write {args.output}: {exc.strerror or exc}")
            return 2
        return 1 if failed else 0

    return guarded(args.file, one)
