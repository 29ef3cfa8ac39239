"""What a fix works on: the file's bytes and their elements, the typed model read from them, the findings of the
check, the tolerances, and the places where model and XML meet (a road's element, a lane's, a connection's).

Fixes read the model to decide and the located XML (:mod:`xodrcheck.fix.xmltext`) to edit; the model's source lines
pick the element where ids repeat.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from functools import cached_property
from typing import TYPE_CHECKING

from xodrcheck.config import Tolerances
from xodrcheck.findings import Finding
from xodrcheck.fix.xmltext import Element, XmlText, scan
from xodrcheck.model import Connection, ContactPoint, Document, Junction, JunctionLaneLink, Lane, Road

if TYPE_CHECKING:
    from xodrcheck.geometry.lanes import RoadGeometry

__all__ = ["Workspace"]


def _pick(candidates: list[Element], line: int) -> Element | None:
    """The candidate on ``line`` (model lines are libxml2's, as the scanner's); the only one when there is one."""
    if len(candidates) == 1:
        return candidates[0]
    return next((c for c in candidates if c.line == line), None)


class Workspace:
    """One round's view of a file for the fixes (built lazily: a fix that needs no geometry evaluates none)."""

    def __init__(
        self, data: bytes, document: Document, findings: Sequence[Finding], tolerances: Tolerances | None = None
    ) -> None:
        self.data = data
        self.document = document
        self.findings = tuple(findings)
        self.tolerances = tolerances or Tolerances()

    @cached_property
    def text(self) -> XmlText:
        return scan(self.data)

    @cached_property
    def geometry(self) -> Mapping[str, RoadGeometry]:
        from xodrcheck.geometry.lanes import geometry_of

        return geometry_of(self.document)

    # -------------------------------------------------------------------------------------------------- the model
    def road(self, road_id: str | None) -> Road | None:
        return None if road_id is None else self.document.road_by_id.get(road_id)

    def junction(self, junction_id: str | None) -> Junction | None:
        return None if junction_id is None else self.document.junction_by_id.get(junction_id)

    def end_s(self, road: Road, end: ContactPoint) -> float:
        return 0.0 if end is ContactPoint.START else float(road.length)

    # ----------------------------------------------------------------------------------------------- the elements
    def _children(self, parent: Element, tag: str, key: str, value: str) -> list[Element]:
        return [c for c in parent.children if c.tag == tag and c.get(key) == value]

    def road_element(self, road: Road) -> Element | None:
        return _pick(self._children(self.text.root, "road", "id", road.id), road.line)

    def junction_element(self, junction: Junction) -> Element | None:
        return _pick(self._children(self.text.root, "junction", "id", junction.id), junction.line)

    def connection_element(self, junction: Junction, connection: Connection) -> Element | None:
        parent = self.junction_element(junction)
        if parent is None:
            return None
        return _pick(self._children(parent, "connection", "id", connection.id), connection.line)

    def lane_link_element(
        self, junction: Junction, connection: Connection, lane_link: JunctionLaneLink
    ) -> Element | None:
        """The connection's ``<laneLink>`` read as ``lane_link`` (found by its line; ``None`` unless exactly one)."""
        element = self.connection_element(junction, connection)
        links = [e for e in element.findall("laneLink") if e.line == lane_link.line] if element is not None else []
        return links[0] if len(links) == 1 else None

    def road_link_element(self, road: Road, end: ContactPoint) -> Element | None:
        """The ``<predecessor>`` or ``<successor>`` of the road's ``<link>``."""
        element = self.road_element(road)
        link = element.find("link") if element is not None else None
        if link is None:
            return None
        found = link.findall("predecessor" if end is ContactPoint.START else "successor")
        return found[0] if len(found) == 1 else None

    def section_elements(self, road: Road) -> list[Element]:
        """The ``<laneSection>`` elements of the road's permanent lane layer, in file order (the model's order)."""
        element = self.road_element(road)
        if element is None:
            return []
        lanes = [e for e in element.findall("lanes") if e.get("layer") in (None, "permanent")]
        return lanes[0].findall("laneSection") if len(lanes) == 1 else []

    def lane_element(self, road: Road, section_index: int, lane: Lane) -> Element | None:
        sections = self.section_elements(road)
        if len(sections) != len(road.lane_sections) or not 0 <= section_index < len(sections):
            return None
        side = "left" if lane.id > 0 else "right" if lane.id < 0 else "center"
        found: list[Element] = []
        for part in sections[section_index].findall(side):
            found.extend(e for e in part.findall("lane") if _integer(e.get("id")) == lane.id)
        return _pick(found, lane.line)


def _integer(text: str | None) -> int | None:
    if text is None:
        return None
    try:
        return int(text.strip())
    except ValueError:
        try:
            value = float(text)
        except ValueError:
            return None
        return int(value) if value.is_integer() else None
