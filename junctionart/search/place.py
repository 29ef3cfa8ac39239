"""``junctionart search --network``: each elite placed into an ordinary generated map.

The map is made by the generator's own stages with a seed: control lines and the road graph as for ``junctionart
generate`` (:func:`junctionart.controllines.automatic`, :func:`junctionart.network.build`), then the graph is cleared
in a disc around its node nearest the map's centre (radius: the elite's approach length plus :data:`CLEARANCE`) and the
elite's own graph (:func:`junctionart.intersection.network`: the junction, one road per leg, bends) is put there. Each
leg's far end is joined by a new road to the nearest remaining node ahead of it (within :data:`AHEAD` degrees of the
leg's heading), the graph is made planar and connected as the network stage does, the lanes are drawn for the rest of
the map while the elite's legs keep their own lane counts and medians along their whole road, and the junction and
cleanup stages build the document. The map's junction-wide settings (turn lanes, U-turns, lane and median widths) are
the elite's, so the junction is built as the elite was.

A placement can change the junction (a new road meeting a leg's road, the stage's repairs), so every map is written,
read back with xodrcheck and measured: it is kept only when it has no error-level finding and at least one of its
junctions meets the target (the search's ``--where``, else the elite's leg count); otherwise the next seed is tried.
"""

from __future__ import annotations

import csv
import json
import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np

from ..intersection import IntersectionSpec
from ..lanes import LaneConfig, LanedNetwork
from ..network import Edge, Network

#: Metres of cleared ground beyond the elite's approach roads.
CLEARANCE = 40.0
#: A leg's end is joined only to a node within this many degrees of the leg's heading.
AHEAD = 60.0
#: Side (m) of the square map an elite is placed into.
MAP_SIZE = 700.0


@dataclass(frozen=True)
class Placed:
    """A map holding an elite: its bytes, the seed that made it and the junctions (ids) meeting the target."""

    data: bytes
    seed: int
    matching: tuple[str, ...]


def _segment_distance(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    d = b - a
    t = 0.0 if not d.any() else float(np.clip(np.dot(p - a, d) / np.dot(d, d), 0.0, 1.0))
    return float(np.hypot(*(p - (a + t * d))))


def _splice(net: Network, star: LanedNetwork) -> tuple[list[tuple[float, float]], dict[tuple[int, int], int], int]:
    """The generated graph with a disc cleared around its centre and ``star`` (translated there) added: nodes,
    edges ((a, b) -> control line, -1 for new roads) and the index of the star's junction node."""
    pts = np.asarray(net.nodes)
    middle = (pts.min(axis=0) + pts.max(axis=0)) / 2
    centre = pts[int(np.argmin(np.hypot(*(pts - middle).T)))]
    radius = max(math.hypot(*xy) for xy in star.network.nodes) + CLEARANCE
    nodes = [(float(x), float(y)) for x, y in pts]
    edges: dict[tuple[int, int], int] = {}
    for e in net.edges:
        if _segment_distance(centre, pts[e.u], pts[e.v]) > radius:
            edges[(min(e.u, e.v), max(e.u, e.v))] = e.line
    kept = sorted({n for key in edges for n in key})
    first = len(nodes)
    nodes += [(float(centre[0] + x), float(centre[1] + y)) for x, y in star.network.nodes]
    for e in star.network.edges:
        edges[(first + e.u, first + e.v)] = -1
    degree = star.network.degree()
    for end in (k for k, d in enumerate(degree) if d == 1):
        at = np.asarray(nodes[first + end])
        heading = math.atan2(*(at - centre)[::-1])
        best, best_d = None, math.inf
        for n in kept:
            d = np.asarray(nodes[n]) - at
            dist = float(np.hypot(*d))
            off = abs((math.degrees(math.atan2(d[1], d[0]) - heading) + 180.0) % 360.0 - 180.0)
            if 20.0 < dist < best_d and off <= AHEAD:
                best, best_d = n, dist
        if best is not None:
            edges[(min(best, first + end), max(best, first + end))] = -1
    return nodes, edges, first


def _finish(
    nodes: list[tuple[float, float]], edges: dict[tuple[int, int], int], centre: int
) -> tuple[Network, int, dict[int, int]]:
    """Planar, connected and renumbered as :func:`junctionart.network.build` leaves its graph; the junction's new
    index and the old -> new node numbers."""
    from ..network import _connect, _planarize, _split_at_nodes

    edges = _split_at_nodes(nodes, _planarize(nodes, edges))
    ends = {n for n in {x for key in edges for x in key} if sum(n in key for key in edges) == 1}
    _connect(nodes, edges, ends)
    edges = _split_at_nodes(nodes, _planarize(nodes, edges))
    used: dict[int, int] = {}
    for a, b in sorted(edges):
        for x in (a, b):
            used.setdefault(x, len(used))
    net = Network(
        tuple(nodes[old] for old in used), tuple(Edge(used[a], used[b], edges[(a, b)]) for a, b in sorted(edges))
    )
    return net, used.get(centre, -1), used


def _keep_leg_lanes(laned: LanedNetwork, centre: int, spec: IntersectionSpec) -> LanedNetwork:
    """Every road leaving the junction gets the lanes of the elite's leg nearest its heading, along its whole chain."""
    from ..graph import chains

    net = laned.network
    lanes = list(laned.lanes)
    for ch in chains(len(net.nodes), [(e.u, e.v) for e in net.edges]):
        if centre not in (ch.nodes[0], ch.nodes[-1]):
            continue
        outwards = ch.nodes[0] == centre  # the chain's direction runs away from the junction
        a = np.asarray(net.nodes[centre])
        b = np.asarray(net.nodes[ch.nodes[1] if outwards else ch.nodes[-2]])
        heading = math.degrees(math.atan2(b[1] - a[1], b[0] - a[0]))
        leg = min(spec.legs, key=lambda g: abs((g.heading - heading + 180.0) % 360.0 - 180.0))
        cfg = LaneConfig(leg.lanes_out, leg.lanes_in, leg.median)  # forward = away from the junction
        if not outwards:
            cfg = cfg.reversed()
        for e, fw in zip(ch.edges, ch.forward):
            lanes[e] = cfg if fw else cfg.reversed()
    return LanedNetwork(net, tuple(lanes))


def build_map(spec: IntersectionSpec, seed: int) -> tuple[bytes, int] | None:
    """One ordinary map of ``seed`` holding ``spec``'s junction: its bytes and the junction's graph node (None when
    the placement left no junction there)."""
    from .. import cleanup, controllines, intersections, lanes, network, to_bytes
    from ..intersection import network as star_network

    params = replace(spec.params(), width=MAP_SIZE, height=MAP_SIZE, randomize_lanes=True)
    rng = np.random.default_rng(seed)
    lines = controllines.automatic(params, rng)
    base = network.build(lines, params, rng)
    nodes, edges, first = _splice(base, star_network(spec))
    net, centre, _ = _finish(nodes, edges, first)
    if centre < 0 or net.degree()[centre] < 3:
        return None
    laned = _keep_leg_lanes(lanes.assign(net, lines, params, rng), centre, spec)
    layout = intersections.build(laned, params, rng)
    document = cleanup.document(layout, params, name=f"junctionart search --network seed {seed}")
    return to_bytes(document, spec.version), centre


def place(
    spec: IntersectionSpec, target: Callable[[dict[str, float]], bool], seed: int = 0, attempts: int = 8
) -> Placed | None:
    """The first of seeds ``seed``, ``seed + 1``, ... (at most ``attempts``) whose map has no error-level finding
    (the checker's ``generator`` profile: what junctionart guarantees) and a junction meeting ``target`` (module
    docstring); None when none does."""
    from xodrcheck.check import check
    from xodrcheck.config import Config
    from xodrcheck.findings import Severity
    from xodrcheck.reader import read

    from ..errors import JunctionArtError
    from .measure import measure_document

    for s in range(seed, seed + attempts):
        try:
            built = build_map(spec, s)
        except JunctionArtError:
            continue
        if built is None:
            continue
        data = built[0]
        if any(f.severity >= Severity.ERROR for f in check(data, Config(profile="generator")).findings):
            continue
        document = read(data).document
        if document is None:
            continue
        matching = tuple(j.id for j in document.junctions if target(measure_document(document, j)))
        if matching:
            return Placed(data, s, matching)
    return None


def place_genome(genome: list[float], where: str | None, legs: float, seed: int = 0) -> Placed | None:
    """:func:`place` for a search vector (runs in a worker): the target is ``where`` (the search's ``--where``
    text) when given, else a junction with at least the elite's ``legs``."""
    from .genome import decode
    from .measure import NAMES
    from .predicate import Predicate

    if where is not None:
        predicate = Predicate.parse(where, NAMES)
        return place(decode(genome), predicate, seed)
    return place(decode(genome), lambda m: m["legs"] >= legs, seed)


def place_all(folder: Path, rows: list[dict[str, Any]], where: str | None, jobs: int, progress: bool) -> Path:
    """Place every elite of ``rows`` (``archive.csv``'s, those meeting ``where`` when given) into its own map under
    ``folder/network`` and list them in ``folder/network.csv``; that file's path."""
    from xodrcheck.support.atomic import atomic_file

    from .. import era

    chosen = [r for r in rows if where is None or str(r["meets_where"]) == "1"]
    out_dir = folder / "network"
    out_dir.mkdir(exist_ok=True)
    executor: Any = era._Local(jobs) if jobs > 1 else None
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=len(chosen), unit="map", desc="network")
    calls = [(json.loads(r["genome"]), where, float(r["legs"])) for r in chosen]
    results: list[Placed | None] = []
    try:
        if executor is None:
            for call in calls:
                results.append(place_genome(*call))
                if bar is not None:
                    bar.update(1)
        else:
            results = executor.map_ordered(place_genome, calls, bar)
    finally:
        if executor is not None:
            executor.close()
        if bar is not None:
            bar.close()
    listing = []
    for r, placed in zip(chosen, results):
        name = Path(str(r["file"])).name
        if placed is not None:
            with atomic_file(out_dir / name, "wb") as stream:
                stream.write(placed.data)
        listing.append(
            {
                "elite": r["file"],
                "map": f"network/{name}" if placed is not None else "",
                "seed": placed.seed if placed is not None else "",
                "junctions": " ".join(placed.matching) if placed is not None else "",
            }
        )
    path = folder / "network.csv"
    with atomic_file(path, "w") as stream:
        writer = csv.DictWriter(stream, ["elite", "map", "seed", "junctions"], lineterminator="\n")
        writer.writeheader()
        writer.writerows(listing)
    return path
