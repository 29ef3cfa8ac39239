"""``xodrcheck view FILE -o map.html``: the map of a file as one self-contained HTML page (no findings).

The page draws the lanes in plan view from the exact geometry, filled by lane type, with lane borders, road marks and
shaded junctions; it pans, zooms and names the lane under the pointer (road, lane section, lane, type, s). Nothing is
fetched from a network: scripts and styles are inline. Exit 0 when written, 1 when written but the reader found
errors in the file, or when there is nothing to draw (nothing written), 2 for a usage or I/O error or a file that
cannot be read whole (nothing written).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from xodrcheck.cli.common import error, guarded, positive_number, read_file, report_errors, target_ok, written

NAME = "view"
HELP = "Write the map of a file as one self-contained HTML page (pan, zoom, hover a lane for its name and s)."


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", metavar="FILE", help="OpenDRIVE file")
    parser.add_argument("-o", "--output", required=True, metavar="OUT", help="the HTML file to write")
    parser.add_argument(
        "--chord", type=positive_number, metavar="TOL", help="chord tolerance of the drawn lines in metres (0.05)"
    )


def run(args: argparse.Namespace) -> int:
    from xodrcheck.mapview import CHORD, map_data
    from xodrcheck.mapview.page import FilePage, render_page

    if not target_ok(args.output):
        return 2

    def one() -> int:
        result = read_file(args.file)
        if result is None or result.document is None:
            return 2
        failed = report_errors(args.file, result)
        data, note = map_data(result.document, chord=args.chord or CHORD)
        if data["bounds"] is None:
            error(f"{args.file}: nothing to draw: no road with a plan view and lanes{f' ({note})' if note else ''}")
            return 1
        version = None if result.document.version is None else "{}.{}".format(*result.document.version)
        page = render_page([FilePage(args.file, version, None, data, note)], f"xodrcheck view: {Path(args.file).name}")
        if not written(args.output, lambda stream: stream.write(page)):
            return 2
        print(f"{args.output}: map of {len(data['roads'])} roads, {len(data['sections'])} lane sections")
        return 1 if failed else 0

    return guarded(args.file, one)
