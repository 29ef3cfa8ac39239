"""The scenario stage: the paper's document dressed with what a scenario needs (after :mod:`junctionart.cleanup`).

Order: roadside corners (they are roads, so they come before anything that walks the roads), then elevation, then
signals and crosswalks. Each step reads the layout and the document so far and returns a new document.
"""

from __future__ import annotations

from ..intersections.model import Layout
from ..opendrive import Document
from ..params import JunctionControl, Params, Roadside, Terrain
from .corners import add_corners
from .ids import Ids


def dress(doc: Document, layout: Layout, params: Params, seed: int) -> Document:
    """``doc`` with the scenario features ``params`` asks for."""
    ids = Ids(doc)
    if params.roadside is not Roadside.NONE:
        doc = add_corners(doc, layout, params, ids)
    if params.terrain is not Terrain.FLAT or layout.overpasses:
        from .terrain import add_terrain

        doc = add_terrain(doc, layout, params, seed, ids)
    if params.junction_control is not JunctionControl.NONE:
        from .signals import add_signals

        entries: dict[str, list[tuple[str, str]]] = {}
        for ring in layout.roundabouts:
            for road, contact, j in ring.arms:
                entries.setdefault(doc.junctions[j].id, []).append((str(road + 1), contact))
        doc = add_signals(doc, params, seed, ids, entries)
    return doc
