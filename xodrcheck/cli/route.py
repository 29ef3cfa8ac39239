"""``xodrcheck route FILE --from ROAD:LANE[:S] --to ROAD:LANE[:S]``: the shortest route between two lanes.

Without ``S`` a route starts where its lane starts and ends where the destination lane ends (each in its direction of
travel); :mod:`xodrcheck.graph.routes` says how it is found and measured. ``text`` (default) names each lane driven,
``json`` adds the polyline, ``geojson`` is the polyline as a Feature. Exit 0 with a route; 1 when there is none (the
best partial route is written, and why it stops, also on stderr); 2 for a place that names no drivable lane, a file
that cannot be read whole or an output that cannot be written (one line, nothing written).
"""

from __future__ import annotations

import argparse

from xodrcheck.cli.common import error, guarded, target_ok, written
from xodrcheck.cli.graph import read_lane_graph

NAME = "route"
HELP = "Find the shortest route between two lanes (ROAD:LANE[:S]): its length, lanes and polyline."


def _place(text: str):
    from xodrcheck.graph.routes import PlaceError, parse_place

    try:
        return parse_place(text)
    except PlaceError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", metavar="FILE", help="OpenDRIVE file")
    parser.add_argument("--from", dest="origin", type=_place, required=True, metavar="ROAD:LANE[:S]", help="start")
    parser.add_argument("--to", dest="destination", type=_place, required=True, metavar="ROAD:LANE[:S]", help="end")
    parser.add_argument("--format", choices=("text", "json", "geojson"), default="text", help="default: text")
    parser.add_argument("--no-lane-changes", action="store_true", help="follow links only")
    parser.add_argument("-o", "--output", metavar="OUT", help="write here (atomically) instead of standard output")


def run(args: argparse.Namespace) -> int:
    if not target_ok(args.output):
        return 2

    def one() -> int:
        from xodrcheck.graph.export import route_geojson, route_json, route_text
        from xodrcheck.graph.routes import PlaceError, route

        read = read_lane_graph(args)
        if read is None:
            return 2
        _, document, graph = read
        try:
            found = route(document, graph, args.origin, args.destination)
        except PlaceError as exc:
            error(f"route: {exc}")
            return 2
        writer = route_json if args.format == "json" else route_geojson if args.format == "geojson" else route_text
        if not written(args.output, lambda stream: writer(found, stream)):
            return 2
        if not found.found:
            error(f"no route from {found.origin} to {found.destination}: {found.why}")
        return 0 if found.found else 1

    return guarded(args.file, one)
