"""``xodrcheck info FILE...``: what is in each file (version, roads, junctions, lanes, geometry, extent, findings).

JSON output (``--format json``) is one object per file, one per line (JSON Lines), with these keys:

``file`` (str), ``opendrive_version`` ("major.minor" or null), ``roads`` (int), ``junction_roads`` (int: roads inside a
junction), ``junctions`` ({``total``: int, ``by_type``: {type: int}, ``by_legs``: {"legs": int}}; legs as in
:func:`xodrcheck.analysis.info.junction_legs`), ``lane_sections``
(int), ``lanes`` ({``total``: int, ``by_type``: {type: int}, ``counted``: "per lane section, centre lanes excluded"}),
``reference_line_length_m`` (float), ``geometry`` ({kind: int}), ``bounding_box`` ({``min_x``, ``min_y``, ``max_x``,
``max_y``: float, ``basis``: "lane borders" | "reference line" | "lane borders and reference line"} or null),
``findings`` ({``error``, ``warning``, ``info``: int}: what the reader found; the rules are not run, so a file
``xodrcheck check`` fails may show 0 errors here), ``findings_counted`` (str, says so), ``elevation`` ({``min_z``,
``max_z`` (m), ``max_grade`` (fraction), ``max_link_step_m``, ``links``: int} or null: see
:mod:`xodrcheck.analysis.elevation`).

A file that cannot be read whole (not well-formed, not OpenDRIVE) prints nothing and exits 2, as in every command; a
file read whole with reader errors is summarised and exits 1.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import sys

from xodrcheck.analysis.elevation import ElevationInfo
from xodrcheck.analysis.info import MapInfo, map_info
from xodrcheck.cli.common import guarded, read_file, report_errors

NAME = "info"
HELP = "Summarise OpenDRIVE files: version, roads, junctions, lanes, geometry, extent and reader findings."

#: How lanes are counted, as printed.
LANES_COUNTED = "per lane section, centre lanes excluded"
#: What the findings counts cover, as printed: ``info`` reads, it does not check.
FINDINGS_COUNTED = "found while reading (the rules are not run: `xodrcheck check` runs them)"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("files", nargs="+", metavar="FILE", help="OpenDRIVE files")
    parser.add_argument("--format", choices=("text", "json"), default="text", help="output format (default: text)")


def to_json(info: MapInfo) -> dict:
    """The JSON object of one file (keys documented in this module's docstring)."""
    box = info.bbox
    return {
        "file": info.path,
        "opendrive_version": info.version,
        "roads": info.roads,
        "junction_roads": info.junction_roads,
        "junctions": {
            "total": info.junctions,
            "by_type": dict(info.junctions_by_type),
            "by_legs": {str(legs): n for legs, n in info.junctions_by_legs.items()},
        },
        "lane_sections": info.lane_sections,
        "lanes": {"total": info.lanes, "by_type": dict(info.lanes_by_type), "counted": LANES_COUNTED},
        "reference_line_length_m": info.reference_length,
        "geometry": dict(info.geometries),
        "bounding_box": None
        if box is None
        else {"min_x": box.min_x, "min_y": box.min_y, "max_x": box.max_x, "max_y": box.max_y, "basis": box.basis},
        "findings": dict(info.findings),
        "findings_counted": FINDINGS_COUNTED,
        "elevation": None if info.elevation is None else _elevation_json(info.elevation),
    }


def _elevation_json(e: ElevationInfo) -> dict:
    return {
        "min_z": e.min_z,
        "max_z": e.max_z,
        "max_grade": e.max_grade,
        "max_link_step_m": e.max_link_step,
        "links": e.links,
    }


def _elevation_text(e: ElevationInfo | None) -> str:
    if e is None:
        return "none"
    return (
        f"z {e.min_z:.3f} .. {e.max_z:.3f} m, max grade {100 * e.max_grade:.2f} %, largest z step at a road link "
        f"{e.max_link_step:.3g} m ({e.links} links)"
    )


def _counts(mapping, unit: str = "") -> str:
    if not mapping:
        return "none"
    items = sorted(mapping.items(), key=lambda kv: (-kv[1], str(kv[0])))
    return ", ".join(f"{key}{unit} {n}" for key, n in items)


def to_text(info: MapInfo) -> str:
    box = info.bbox
    rows = [
        ("OpenDRIVE", info.version or "unknown"),
        ("roads", f"{info.roads} ({info.junction_roads} inside junctions)"),
        (
            "junctions",
            f"{info.junctions}"
            + (
                f"; by type: {_counts(info.junctions_by_type)}; by legs: {_counts(info.junctions_by_legs, '-leg')}"
                if info.junctions
                else ""
            ),
        ),
        ("lane sections", str(info.lane_sections)),
        ("lanes", f"{info.lanes} ({LANES_COUNTED}): {_counts(info.lanes_by_type)}"),
        ("length", f"{info.reference_length:.3f} m of reference line"),
        ("geometry", _counts(info.geometries)),
        (
            "bounding box",
            "none"
            if box is None
            else f"x {box.min_x:.3f} .. {box.max_x:.3f}, y {box.min_y:.3f} .. {box.max_y:.3f} "
            f"({box.max_x - box.min_x:.1f} m x {box.max_y - box.min_y:.1f} m, {box.basis})",
        ),
        ("elevation", _elevation_text(info.elevation)),
        ("findings", ", ".join(f"{n} {sev}" for sev, n in info.findings.items()) + f" {FINDINGS_COUNTED}"),
    ]
    width = max(len(label) for label, _ in rows)
    return "\n".join([str(info.path), *(f"  {label:<{width}}  {value}" for label, value in rows)])


def run(args: argparse.Namespace) -> int:
    worst = 0
    for index, path in enumerate(args.files):

        def one(path: str = path, first: bool = index == 0) -> int:
            result = read_file(path)
            if result is None:
                return 2
            info = dataclasses.replace(map_info(result), path=path)
            if args.format == "json":
                print(json.dumps(to_json(info)))
            else:
                print(("" if first else "\n") + to_text(info))
            return 1 if report_errors(path, result) else 0

        worst = max(worst, guarded(path, one))
        sys.stdout.flush()
    return worst
