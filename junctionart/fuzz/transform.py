"""Metamorphic transforms of whole OpenDRIVE documents (on the XML, so they apply to any file).

* :func:`move_and_rotate` rotates every plan-view geometry about the origin and then shifts it: a rigid motion, after
  which every finding must stay the same.
* :func:`renumber_roads` gives every road a new id and rewrites every reference to it: findings must stay the same,
  up to the ids they name.
"""

from __future__ import annotations

import math

from lxml import etree

_PARSER = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False)


def _wrap(a: float) -> float:
    """An angle in (-pi, pi]."""
    a = math.remainder(a, 2 * math.pi)
    return math.pi if a == -math.pi else a


def move_and_rotate(data: bytes, dx: float, dy: float, angle: float) -> bytes:
    """Rotate every ``<geometry>`` by ``angle`` about the origin, then move it by (``dx``, ``dy``).

    Headings are written back in (-pi, pi]. Attributes that are not finite numbers are left alone."""
    root = etree.fromstring(data, _PARSER)
    c, s = math.cos(angle), math.sin(angle)
    for g in root.iter("geometry"):
        try:
            x, y, h = float(g.get("x")), float(g.get("y")), float(g.get("hdg"))
        except (TypeError, ValueError):
            continue
        if not all(map(math.isfinite, (x, y, h))):
            continue
        g.set("x", repr(dx + c * x - s * y))
        g.set("y", repr(dy + s * x + c * y))
        g.set("hdg", repr(_wrap(h + angle)))
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8")


def renumber_roads(data: bytes, mapping: dict[str, str]) -> bytes:
    """Rename roads by ``mapping`` (old id -> new id), in road ids, road links and junction connections."""
    root = etree.fromstring(data, _PARSER)
    for road in root.iter("road"):
        if road.get("id") in mapping:
            road.set("id", mapping[road.get("id")])
        for link in (road.find("link/predecessor"), road.find("link/successor")):
            if link is not None and link.get("elementType") == "road" and link.get("elementId") in mapping:
                link.set("elementId", mapping[link.get("elementId")])
    for conn in root.iter("connection"):
        for name in ("incomingRoad", "connectingRoad", "linkedRoad"):
            if conn.get(name) in mapping:
                conn.set(name, mapping[conn.get(name)])
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8")


def road_ids(data: bytes) -> list[str]:
    """Road ids in file order."""
    return [r.get("id") for r in etree.fromstring(data, _PARSER).iter("road") if r.get("id") is not None]
