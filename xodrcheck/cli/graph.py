"""``xodrcheck graph FILE [--format json|dot|geojson]``: the lane graph of a map (:mod:`xodrcheck.graph`).

Nodes are the drivable lanes of every lane section, driven one way; edges the links between them and, unless
``--no-lane-changes``, the lane changes road marks allow (:mod:`xodrcheck.graph.export` says what each format holds).
Exit 0 when written, 1 when written but the reader found errors in the file, 2 when it cannot be read whole or the
output cannot be written (nothing written then).
"""

from __future__ import annotations

import argparse
from typing import IO, TYPE_CHECKING

from xodrcheck.cli.common import guarded, read_file, report_errors, target_ok, written

if TYPE_CHECKING:
    from xodrcheck.graph import LaneGraph
    from xodrcheck.model import Document
    from xodrcheck.reader import ReadResult

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


def read_lane_graph(args: argparse.Namespace) -> tuple[ReadResult, Document, LaneGraph] | None:
    """The file of ``graph`` or ``route`` read, with its document and lane graph (lane changes unless
    ``--no-lane-changes``); ``None`` after one line on stderr when it cannot be read whole (exit 2)."""
    from xodrcheck.graph import lane_graph

    result = read_file(args.file)
    if result is None:
        return None
    document = result.document
    assert document is not None  # read_file refuses a file without one
    return result, document, lane_graph(document, lane_changes=not args.no_lane_changes)


def run(args: argparse.Namespace) -> int:
    if not target_ok(args.output):
        return 2

    def one() -> int:
        from xodrcheck.graph.export import graph_dot, graph_geojson, graph_json

        read = read_lane_graph(args)
        if read is None:
            return 2
        result, document, graph = read
        failed = report_errors(args.file, result)

        def write(stream: IO[str]) -> None:
            if args.format == "dot":
                graph_dot(graph, stream)
            elif args.format == "geojson":
                graph_geojson(document, graph, stream)
            else:
                graph_json(document, graph, summary(graph), stream)

        if not written(args.output, write):
            return 2
        return 1 if failed else 0

    return guarded(args.file, one)
