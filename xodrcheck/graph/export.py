"""The lane graph and routes as JSON, Graphviz DOT and GeoJSON (what ``xodrcheck graph`` and ``route`` write).

A lane is named by its road, lane-section start ``section_s``, lane id and ``type`` (as the standard spells it) and the
way it is driven, ``travel``: ``forward`` along the reference line, ``backward`` against it (a lane driven both ways is
two nodes). An edge's ``length`` is how far traffic drives on the lane it leaves, entered at its start, before it takes
the edge: the whole lane for a ``link``, up to the first place the road marks allow it for a ``lane_change``. GeoJSON
coordinates are ``[x, y, z]`` in the map's own metric frame (not WGS 84), as ``xodrcheck sample`` writes them.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from typing import IO

import numpy as np

from xodrcheck.graph.build import KINDS, LaneGraph, Node
from xodrcheck.graph.lengths import centre_line, node_lengths
from xodrcheck.graph.routes import Route
from xodrcheck.model import Document
from xodrcheck.support.quantities import metres

__all__ = ["graph_dot", "graph_geojson", "graph_json", "route_geojson", "route_json", "route_text"]


def _travel(node: Node) -> str:
    return "forward" if node.travel > 0 else "backward"


def lane_json(node: Node) -> dict:
    """A node as the JSON outputs name it."""
    return {
        "road": node.road,
        "section_s": node.key.section_s,
        "lane": node.lane,
        "type": node.type,
        "travel": _travel(node),
    }


def _edges(document: Document, graph: LaneGraph) -> Iterator[dict]:
    lengths = node_lengths(document, graph)
    for a, b, kind, at in zip(graph.source.tolist(), graph.target.tolist(), graph.kind.tolist(), graph.at.tolist()):
        yield {
            "from": lane_json(graph.nodes[a]),
            "to": lane_json(graph.nodes[b]),
            "kind": KINDS[kind],
            "length": round(float(lengths[a]) * at, 6),
        }


def graph_json(document: Document, graph: LaneGraph, summary: dict, stream: IO[str]) -> None:
    """``{"summary": ..., "nodes": [...], "edges": [...]}``; a node also carries its ``length`` and, where no link
    leaves it, ``stop`` (``open`` at an open edge of the map, else why traffic cannot go on)."""
    lengths = node_lengths(document, graph)
    nodes = []
    for i, node in enumerate(graph.nodes):
        item = {**lane_json(node), "length": round(float(lengths[i]), 6)}
        stop = graph.stops.get(i)
        if stop is not None:
            item["stop"] = {"kind": stop.kind, "why": stop.why}
        nodes.append(item)
    data = {"summary": summary, "nodes": nodes, "edges": list(_edges(document, graph))}
    json.dump(data, stream, indent=1, allow_nan=False)
    stream.write("\n")


def _dot_text(text: str) -> str:
    return text.replace("\\", "\\\\").replace('"', '\\"')


def _dot_id(node: Node) -> str:
    suffix = "" if node.travel > 0 else "<"
    return json.dumps(f"{node.road}/{metres(node.key.section_s)}/{node.lane}{suffix}")


def graph_dot(graph: LaneGraph, stream: IO[str]) -> None:
    """A ``digraph``: a node per lane (``road/section_s/lane``, ``<`` appended when driven against s), solid edges for
    links, dashed for lane changes."""
    stream.write("digraph lanes {\n  node [shape=box, fontsize=10];\n")
    for node in graph.nodes:
        label = "\\n".join(
            _dot_text(part)
            for part in (f"road {node.road} lane {node.lane}", f"s={metres(node.key.section_s)} {node.type}")
        )
        stream.write(f'  {_dot_id(node)} [label="{label}"];\n')
    for a, b, kind in zip(graph.source.tolist(), graph.target.tolist(), graph.kind.tolist()):
        style = " [style=dashed]" if kind == 1 else ""
        stream.write(f"  {_dot_id(graph.nodes[a])} -> {_dot_id(graph.nodes[b])}{style};\n")
    stream.write("}\n")


def _coords(x, y, z) -> list[list[float]]:
    return [[round(a, 6), round(b, 6), round(c, 6)] for a, b, c in zip(x.tolist(), y.tolist(), z.tolist())]


def _ordered(document: Document, node: Node):
    """The node's lane centre in the direction of travel."""
    line = centre_line(document, node.road, node.index, node.lane)
    if node.travel > 0 or not len(line.s):
        return line
    return line.between(float(line.s[-1]), float(line.s[0]))


def graph_geojson(document: Document, graph: LaneGraph, stream: IO[str]) -> None:
    """A FeatureCollection: a LineString per node (its lane centre, in the direction of travel) and per edge (from
    where the edge is taken to where traffic enters the next lane)."""
    lines = [_ordered(document, node) for node in graph.nodes]
    stream.write('{"type": "FeatureCollection", "features": [')
    first = True
    for node, line in zip(graph.nodes, lines):
        feature = {
            "type": "Feature",
            "geometry": {"type": "LineString", "coordinates": _coords(line.x, line.y, line.z)},
            "properties": {"element": "lane", **lane_json(node), "length": round(line.length, 6)},
        }
        stream.write(("\n" if first else ",\n") + json.dumps(feature, allow_nan=False))
        first = False
    for edge, a, b, at in zip(_edges(document, graph), graph.source.tolist(), graph.target.tolist(), graph.at.tolist()):
        here, there = lines[a], lines[b]
        if not len(here.x) or not len(there.x):
            continue
        k = round(at * (len(here.x) - 1))
        points = np.array([[here.x[k], here.y[k], here.z[k]], [there.x[0], there.y[0], there.z[0]]])
        feature = {
            "type": "Feature",
            "geometry": {"type": "LineString", "coordinates": _coords(*points.T)},
            "properties": {"element": "edge", **edge},
        }
        stream.write(",\n" + json.dumps(feature, allow_nan=False))
    stream.write("\n]}\n")


# ------------------------------------------------------------------------------------------------------ routes
def _route_data(route: Route) -> dict:
    return {
        "found": route.found,
        "from": str(route.origin),
        "to": str(route.destination),
        "length": round(route.length, 6),
        "why": route.why,
        "steps": [
            {**lane_json(step.node), "s_from": step.s_from, "s_to": step.s_to, "entered": step.entered}
            for step in route.steps
        ],
    }


def route_json(route: Route, stream: IO[str]) -> None:
    """The route's steps (lanes from s to s, how each was entered), length, and polyline (``[x, y, z]`` points)."""
    data = {**_route_data(route), "polyline": _coords(route.x, route.y, route.z)}
    json.dump(data, stream, indent=1, allow_nan=False)
    stream.write("\n")


def route_geojson(route: Route, stream: IO[str]) -> None:
    """One LineString Feature; its properties are the JSON output's but the polyline."""
    feature = {
        "type": "Feature",
        "geometry": {"type": "LineString", "coordinates": _coords(route.x, route.y, route.z)},
        "properties": _route_data(route),
    }
    json.dump({"type": "FeatureCollection", "features": [feature]}, stream, allow_nan=False)
    stream.write("\n")


def route_text(route: Route, stream: IO[str]) -> None:
    """A line for the route, then a line per lane driven."""
    if route.found:
        stream.write(
            f"route from {route.origin} to {route.destination}: {route.length:.3f} m, {len(route.steps)} lane(s)\n"
        )
    else:
        stream.write(
            f"no route from {route.origin} to {route.destination}: {route.why}; the best partial route "
            f"({route.length:.3f} m, {len(route.steps)} lane(s)):\n"
        )
    for step in route.steps:
        node = step.node
        stream.write(
            f"  road {node.road} lane {node.lane} (lane section s={metres(node.key.section_s)}, {node.type}): "
            f"s {step.s_from:.3f} -> {step.s_to:.3f}, {step.entered}\n"
        )
