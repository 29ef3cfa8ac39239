"""``xodrcheck mesh FILE -o OUT.glb|.obj|.ply``: the lane surfaces as a 3D mesh for viewers (Blender, game engines).

Lanes are meshed under a chord tolerance (``--chord``, default the configured ``Tolerances.chord``), elevation and
superelevation applied; ``--lane-types`` keeps only some lane types. Colours and grouping by lane type, axes and
atomic writing: :mod:`xodrcheck.mesh.export`. Exit 0 when written, 1 when written but the reader found errors in the
file (or there was nothing to mesh: no file then), 2 for a usage or I/O error (unknown extension, an input that cannot
be read whole, an unwritable output, a mesh of more than ``max_output_points`` vertices): nothing written.
"""

from __future__ import annotations

import argparse

from xodrcheck.cli.common import (
    error,
    guarded,
    positive_number,
    read_file,
    report_errors,
    target_ok,
)
from xodrcheck.config import ConfigError, load_config
from xodrcheck.mesh.export import FORMATS, ExportError, format_of, write
from xodrcheck.mesh.surfaces import MeshTooLarge, build_surfaces
from xodrcheck.model import LaneType
from xodrcheck.support.atomic import OutputError

NAME = "mesh"
HELP = "Write the lane surfaces as a 3D mesh (.glb, .obj or .ply), coloured by lane type."

_TYPE_NAMES = sorted(t.value for t in LaneType if t is not LaneType.UNKNOWN)


def _lane_types(text: str) -> tuple[str, ...]:
    names = tuple(name.strip() for name in text.split(",") if name.strip())
    unknown = [n for n in names if n not in _TYPE_NAMES]
    if unknown or not names:
        raise argparse.ArgumentTypeError(
            f"unknown lane type(s) {', '.join(unknown) or '(none given)'}; known: {', '.join(_TYPE_NAMES)}"
        )
    return names


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", metavar="FILE", help="OpenDRIVE file")
    parser.add_argument(
        "-o",
        "--output",
        required=True,
        metavar="OUT",
        help=f"mesh file; format from the extension ({', '.join(FORMATS)})",
    )
    parser.add_argument(
        "--chord", type=positive_number, metavar="TOL", help="chord tolerance in metres (default: configured)"
    )
    parser.add_argument(
        "--lane-types",
        type=_lane_types,
        metavar="T1,T2",
        help="mesh only these lane types, comma-separated (e.g. driving,sidewalk; default: all)",
    )


def run(args: argparse.Namespace) -> int:
    try:
        format_of(args.output)
    except ExportError as exc:
        error(str(exc))
        return 2
    if not target_ok(args.output):
        return 2

    def one() -> int:
        try:
            tolerances = load_config().tolerances
        except ConfigError as exc:
            error(f"configuration: {exc}")
            return 2
        chord = args.chord if args.chord is not None else tolerances.chord
        result = read_file(args.file)
        if result is None:
            return 2
        failed = report_errors(args.file, result)
        assert result.document is not None  # read_file refuses a file without one
        try:
            surfaces = build_surfaces(
                result.document, chord=chord, lane_types=args.lane_types, max_vertices=tolerances.max_output_points
            )
        except MeshTooLarge as exc:
            error(f"mesh: at --chord {chord:g}, {exc}; use a larger chord")
            return 2
        try:
            write(surfaces, args.output)
        except ExportError as exc:
            error(f"{args.file}: {exc}")
            return 1
        except OutputError as exc:
            error(str(exc))
            return 2
        print(f"{args.output}: {len(surfaces.vertices):,} vertices, {len(surfaces.faces):,} triangles")
        return 1 if failed else 0

    return guarded(args.file, one)
