"""The lanes of a file as XML elements, indexed once per file for the rules that read what the model leaves out.

The model keeps what geometry and topology need; some of Annex F's lane rules concern elements it does not hold
(``<access>``, ``<material>``, ``<rule>``, an empty ``<link/>``, ``@direction``, lane layers) or the file's own
arrangement (the order of ``<left>``/``<center>``/``<right>`` and of the lanes in them). :func:`lane_elements` walks the
file's ``<road>/<lanes>/<laneSection>/<left|center|right>/<lane>`` once and keeps, for every lane, where it sits; the
rules read the elements from there (``element.sourceline`` for lines) and parse nothing themselves. Tags are matched
by local name (``{*}tag``, :func:`local`): 1.1/1.2 files may put their elements in a default namespace.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from lxml import etree

from xodrcheck.rules.context import Context
from xodrcheck.support.quantities import metres
from xodrcheck.xmlvalues import integer, local, number

GROUPS = ("left", "center", "right")


@dataclass(frozen=True, slots=True)
class SectionXml:
    """One ``<laneSection>`` element and where it sits."""

    road: str | None
    road_element: etree._Element
    lanes_element: etree._Element
    element: etree._Element
    #: Its ``s`` (``None`` when missing or not a number: the reader reports that).
    s: float | None
    #: The ``layer`` of its ``<lanes>`` (``permanent`` when absent, as the standard defaults it).
    layer: str


@dataclass(frozen=True, slots=True)
class LaneXml:
    """One ``<lane>`` element of a lane section's ``<left>``, ``<center>`` or ``<right>``."""

    section: SectionXml
    group: str
    element: etree._Element
    #: Its ``id`` (``None`` when missing or not an integer: the reader reports that).
    id: int | None

    @property
    def road(self) -> str | None:
        return self.section.road

    def where(self, line: int | None = None) -> dict:
        """Finding location fields: road, lane, lane section, s and the line (the lane's unless given)."""
        s = self.section.s
        return {
            "road": self.road,
            "lane": self.id,
            "section_s": s,
            "s": s,
            "line": line or self.element.sourceline,
        }

    def describe(self) -> str:
        s = self.section.s
        return f"road {self.road} lane {self.id} (lane section s={metres(s)})"


@dataclass(frozen=True, slots=True)
class LanesXml:
    """A file's lane sections and lanes as written in the XML (for the rules about attributes the model normalises)."""

    sections: tuple[SectionXml, ...]
    lanes: tuple[LaneXml, ...]


def lane_elements(ctx: Context) -> LanesXml:
    """Every lane section and lane of the file as elements (empty when the file is not XML, or built in memory)."""
    return ctx.xml_view("lane_xml.lanes", lambda: _lane_elements(ctx))


def _lane_elements(ctx: Context) -> LanesXml:
    sections: list[SectionXml] = []
    lanes: list[LaneXml] = []
    tree = ctx.tree
    if tree is not None:
        for road_el in tree.getroot().iterchildren("{*}road"):
            road_id = road_el.get("id")
            for lanes_el in road_el.iterchildren("{*}lanes"):
                layer = lanes_el.get("layer") or "permanent"
                for section_el in lanes_el.iterchildren("{*}laneSection"):
                    section = SectionXml(road_id, road_el, lanes_el, section_el, number(section_el.get("s")), layer)
                    sections.append(section)
                    for group_el in section_el.iterchildren(*(f"{{*}}{g}" for g in GROUPS)):
                        group = local(group_el)
                        for lane_el in group_el.iterchildren("{*}lane"):
                            lanes.append(LaneXml(section, group, lane_el, integer(lane_el.get("id"))))
    return LanesXml(tuple(sections), tuple(lanes))


def by_section(ctx: Context) -> Iterator[list[LaneXml]]:
    """The lanes of each lane section (that has any), in file order."""
    current: list[LaneXml] = []
    for lane in lane_elements(ctx).lanes:
        if current and current[0].section is not lane.section:
            yield current
            current = []
        current.append(lane)
    if current:
        yield current
