"""Defect injection: each defect, written into a clean corpus map with lxml, yields a new finding.

For every kind of defect, the map is checked before and after the edit with the rules of the expected category only.
Under the ``generator`` profile (every rule at its own severity) the injected map must have an error of that category
whose (code, road) the clean map did not have; under the default profile the same defect must still be reported (at
least a warning), and a finding whose basis is the project's plausibility is never an error there.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Callable
from dataclasses import dataclass

import pytest
from lxml import etree

from tests.conftest import corpus_root
from xodrcheck.check import check
from xodrcheck.config import Config
from xodrcheck.findings import Severity

pytestmark = [pytest.mark.corpus, pytest.mark.slow]

CARLA = "carla-towns/OpenDrive/Town03.xodr"
ESMINI = "esmini/resources/xodr/fabriksgatan.xodr"
IKA = "ika-roadgeneration/test/gt/junction_4a.xodr"
SCENARIO = "scenariogeneration-examples/full_junction0.xodr"


def _roads(tree):
    return tree.getroot().findall("road")


def _road_links(tree, tag):
    """(road, link element) for links of kind ``tag`` (predecessor/successor) to a road."""
    for road in _roads(tree):
        link = road.find(f"link/{tag}")
        if link is not None and link.get("elementType") == "road":
            yield road, link


def _geometries(road):
    return road.findall("planView/geometry")


def planview_gap(tree):
    road = next(r for r in _roads(tree) if len(_geometries(r)) >= 2)
    g = _geometries(road)[1]
    g.set("x", repr(float(g.get("x")) + 0.02))  # 2 cm: over the 1 cm gap (from 1 mm a warning)
    return road.get("id")


def heading_kink(tree):
    road = next(r for r in _roads(tree) if len(_geometries(r)) >= 2)
    g = _geometries(road)[1]
    g.set("hdg", repr(float(g.get("hdg")) + 0.02))
    return road.get("id")


def elevation_step(tree):
    """A road linked at its end to another road lifted by 5 cm (every elevation record's ``a``): a step at its links."""
    road, _ = next(_road_links(tree, "successor"))
    records = road.findall("elevationProfile/elevation")
    if not records:
        profile = etree.SubElement(road, "elevationProfile")
        road.insert(list(road).index(road.find("planView")) + 1, profile)
        records = [etree.SubElement(profile, "elevation", s="0", a="0", b="0", c="0", d="0")]
    for record in records:
        record.set("a", repr(float(record.get("a")) + 0.05))
    return road.get("id")


def link_to_missing_road(tree):
    road, link = next(_road_links(tree, "successor"))
    link.set("elementId", "999999")
    return road.get("id")


def non_reciprocal_link(tree):
    road, link = next(_road_links(tree, "successor"))
    target = next(r for r in _roads(tree) if r.get("id") == link.get("elementId"))
    end = "predecessor" if link.get("contactPoint") == "start" else "successor"
    back = target.find(f"link/{end}")
    back.getparent().remove(back)
    return road.get("id")


def full_width_lane_appearing(tree):
    road, _ = next(_road_links(tree, "predecessor"))
    right = road.find("lanes/laneSection/right")
    outer = min(right.findall("lane"), key=lambda lane: int(lane.get("id")))
    new = etree.SubElement(right, "lane", id=str(int(outer.get("id")) - 1), type="driving", level="false")
    etree.SubElement(new, "width", sOffset="0", a="3.5", b="0", c="0", d="0")
    return road.get("id")


def lane_link_to_missing_lane(tree):
    for road in _roads(tree):
        for succ in road.iterfind("lanes/laneSection/*/lane/link/successor"):
            succ.set("id", "-42")
            return road.get("id")
    raise LookupError


def sharp_arc(tree):
    road = next(r for r in _roads(tree) if r.get("junction") == "-1" and _geometries(r)[0].find("line") is not None)
    g = _geometries(road)[0]
    g.remove(g.find("line"))
    etree.SubElement(g, "arc", curvature="2")  # radius 0.5 m
    return road.get("id")


def _connections(tree, min_links=2):
    for junction in tree.getroot().findall("junction"):
        for c in junction.findall("connection"):
            if len(c.findall("laneLink")) >= min_links and c.get("connectingRoad"):
                yield junction, c


def crossed_lane_links(tree):
    _, c = next(_connections(tree))
    a, b = c.findall("laneLink")[:2]
    to_a, to_b = a.get("to"), b.get("to")
    a.set("to", to_b)
    b.set("to", to_a)
    return c.get("incomingRoad")


def junction_merge(tree):
    _, c = next(_connections(tree))
    a, b = c.findall("laneLink")[:2]
    b.set("to", a.get("to"))
    return c.get("incomingRoad")


def junction_lane_link_to_missing_lane(tree):
    _, c = next(_connections(tree, 1))
    c.find("laneLink").set("to", "-42")
    return c.get("connectingRoad")


def connection_to_missing_road(tree):
    _, c = next(_connections(tree, 1))
    c.set("connectingRoad", "999999")
    # the finding names the junction's road or none


def duplicate_road_id(tree):
    road = _roads(tree)[0]
    road.addnext(copy.deepcopy(road))
    return road.get("id")


def parampoly3_length_wrong(tree):
    road = next(r for r in _roads(tree) if _geometries(r)[0].find("line") is not None)
    g = _geometries(road)[0]
    g.remove(g.find("line"))
    # p over [0, @length] (arcLength) draws a curve 1 % longer than @length: p is not chosen in [0, @length], an error
    # (Annex F paramPoly3.arcLength_range); the same mismatch with pRange="normalized" is a "should" (length_match)
    etree.SubElement(
        g,
        "paramPoly3",
        aU="0",
        bU="1.01",
        cU="0",
        dU="0",
        aV="0",
        bV="0",
        cV="0",
        dV="0",
        pRange="arcLength",
    )
    return road.get("id")


def negative_width(tree):
    for road in _roads(tree):
        width = road.find("lanes/laneSection/right/lane/width")
        if width is not None:
            width.set("a", "-0.5")
            for key in "bcd":
                width.set(key, "0")
            return road.get("id")
    raise LookupError


def _turn(road) -> float:
    """Heading change of a connecting road's plan view (curvature integrated over arcs and spirals)."""
    total = 0.0
    for g in _geometries(road):
        length = float(g.get("length"))
        if (arc := g.find("arc")) is not None:
            total += float(arc.get("curvature")) * length
        elif (spiral := g.find("spiral")) is not None:
            total += 0.5 * (float(spiral.get("curvStart")) + float(spiral.get("curvEnd"))) * length
    return total


def _mirror(road) -> None:
    """Mirror a road's plan view about its start tangent (a right turn becomes a left turn)."""
    first = _geometries(road)[0]
    x0, y0, h0 = (float(first.get(k)) for k in ("x", "y", "hdg"))
    c, s = math.cos(2 * h0), math.sin(2 * h0)
    for g in _geometries(road):
        dx, dy = float(g.get("x")) - x0, float(g.get("y")) - y0
        g.set("x", repr(x0 + c * dx + s * dy))
        g.set("y", repr(y0 + s * dx - c * dy))
        g.set("hdg", repr(2 * h0 - float(g.get("hdg"))))
        if (arc := g.find("arc")) is not None:
            arc.set("curvature", repr(-float(arc.get("curvature"))))
        if (spiral := g.find("spiral")) is not None:
            for key in ("curvStart", "curvEnd"):
                spiral.set(key, repr(-float(spiral.get(key))))


def crossing_connection_lanes(tree):
    """Mirror a right turn from the rightmost lane of an approach that also has a straight path from another lane:
    the right turn becomes a left turn from the right lane, across the straight path."""
    roads = {r.get("id"): r for r in _roads(tree)}
    for junction in tree.getroot().findall("junction"):
        by_incoming: dict[str, list] = {}
        for c in junction.findall("connection"):
            if c.get("contactPoint") == "start" and c.get("connectingRoad") in roads:
                by_incoming.setdefault(c.get("incomingRoad"), []).append(c)
        for incoming, group in by_incoming.items():
            lanes = {c.get("connectingRoad"): {int(ll.get("from")) for ll in c.findall("laneLink")} for c in group}
            right = [c for c in group if _turn(roads[c.get("connectingRoad")]) < -1.0]
            straight = [c for c in group if abs(_turn(roads[c.get("connectingRoad")])) < 0.1]
            for r in right:
                for s in straight:
                    if lanes[r.get("connectingRoad")] - lanes[s.get("connectingRoad")]:
                        _mirror(roads[r.get("connectingRoad")])
                        return incoming
    raise LookupError


@dataclass(frozen=True)
class Defect:
    name: str
    category: str
    inject: Callable
    map: str


DEFECTS = [
    Defect("planview-gap", "geometry", planview_gap, CARLA),
    Defect("planview-gap", "geometry", planview_gap, ESMINI),
    Defect("heading-kink", "geometry", heading_kink, CARLA),
    Defect("link-to-missing-road", "reference", link_to_missing_road, ESMINI),
    Defect("non-reciprocal-link", "link", non_reciprocal_link, CARLA),
    Defect("full-width-lane-appearing", "lane", full_width_lane_appearing, ESMINI),
    Defect("lane-link-to-missing-lane", "reference", lane_link_to_missing_lane, SCENARIO),
    Defect("sharp-arc", "curvature", sharp_arc, SCENARIO),
    Defect("crossed-junction-lane-links", "junction", crossed_lane_links, CARLA),
    Defect("junction-lane-link-to-missing-lane", "reference", junction_lane_link_to_missing_lane, IKA),
    Defect("connection-to-missing-road", "reference", connection_to_missing_road, SCENARIO),
    Defect("duplicate-road-id", "reference", duplicate_road_id, IKA),
    Defect("parampoly3-length-wrong", "geometry", parampoly3_length_wrong, SCENARIO),
    Defect("negative-width", "geometry", negative_width, IKA),
    Defect("junction-merge", "junction", junction_merge, CARLA),
    Defect("crossing-connection-lanes", "junction", crossing_connection_lanes, CARLA),
    Defect("heading-kink", "geometry", heading_kink, ESMINI),
    Defect("elevation-step", "link", elevation_step, CARLA),
    Defect("elevation-step", "link", elevation_step, ESMINI),
]


def _findings(data: bytes, category: str, profile: str, least: Severity) -> set[tuple[str, str | None, Severity, str]]:
    report = check(data, config=Config(profile=profile), select=(category,))
    assert not [f for f in report.findings if f.code in ("X900", "X901")], report.findings
    return {(f.code, f.road, f.severity, str(f.basis)) for f in report.findings if f.severity >= least}


def test_at_least_fifteen_kinds_on_four_maps():
    assert len({d.name for d in DEFECTS}) >= 15
    assert len({d.map for d in DEFECTS}) >= 4


@pytest.mark.parametrize("defect", DEFECTS, ids=lambda d: f"{d.name}@{d.map.split('/')[-1]}")
def test_injected_defect_gives_a_new_error(corpus_dir, defect):
    source = (corpus_root() / defect.map).read_bytes()
    parser = etree.XMLParser(resolve_entities=False, no_network=True, remove_blank_text=False)
    tree = etree.ElementTree(etree.fromstring(source, parser))
    defect.inject(tree)
    injected = etree.tostring(tree, xml_declaration=True, encoding="UTF-8")

    def new(profile: str, least: Severity):
        return _findings(injected, defect.category, profile, least) - _findings(source, defect.category, profile, least)

    assert new("generator", Severity.ERROR), f"{defect.name} in {defect.map}: no new {defect.category} error"
    reported = new("default", Severity.WARNING)
    assert reported, f"{defect.name} in {defect.map}: not reported under the default profile"
    assert not [f for f in reported if f[3] == "plausibility" and f[2] >= Severity.ERROR], reported
