"""``xodrcheck graph FILE [--format json|dot|geojson]``: the lane graph of a map (:mod:`xodrcheck.graph`).

Nodes are the drivable lanes of every lane section, driven one way; edges the links between them and, unless
``--no-lane-changes``, the lane changes road marks allow (:mod:`xodrcheck.graph.export` says what each format holds).
Exit 0 when written, 1 when written but the reader found errors in the file, 2 when it cannot be read whole or the
output cannot be written (nothing written then).
"""

from __future__ import annotations

import argparse

from xodrcheck.cli.common import error, guarded, output, read_file, report_errors, target_ok
from xodrcheck.support.atomic import OutputError

NAME = "graph"
HELP = "Write the lane graph of a map (lanes, links, lane changes) as JSON, Graphviz DOT or GeoJSON."


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", metavar="FILE", help="OpenDRIVE file")
    parser.add_argument("--format", choices=("json", "dot", "geojson"), default="json", help="default: json")
    parser.add_argument(
        "--no-lane-changes", action="store_true", help="links only: no edges between neighbouring lanes"
    )
    parser.add_argument("-o", "--output", metavar="OUT", help="write here (atomically) instead of standard output")


def summary(graph) -> dict:
    """Counts: nodes, edges by kind, strongly connected parts, entries and exits at open map edges."""
    from xodrcheck.graph.reach import components, entries, exits

    count, _ = components(graph)
    return {
        "nodes": len(graph.nodes),
        "links": int((graph.kind == 0).sum()),
        "lane_changes": int((graph.kind == 1).sum()),
        "strong_components": count,
        "entries": len(entries(graph)),
        "exits": len(exits(graph)),
    }


def run(args: argparse.Namespace) -> int:
    if not target_ok(args.output):
        return 2

    def one() -> int:
        from xodrcheck.graph import lane_graph
        from xodrcheck.graph.export import graph_dot, graph_geojson, graph_json

        result = read_file(args.file)
        if result is None:
            return 2
        failed = report_errors(args.file, result)
        document = result.document
        assert document is not None  # read_file refuses a file without one
        graph = lane_graph(document, lane_changes=not args.no_lane_changes)
        try:
            with output(args.output) as stream:
                if args.format == "dot":
                    graph_dot(graph, stream)
                elif args.format == "geojson":
                    graph_geojson(document, graph, stream)
                else:
                    graph_json(document, graph, summary(graph), stream)
        except OutputError as exc:
            error(str(exc))
            return 2
        return 1 if failed else 0

    return guarded(args.file, one)
