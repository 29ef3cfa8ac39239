"""Roads (chapter 10): links, plan view, profiles, lane layers, road types, lateral shapes, surfaces, railroad
switches, and the road's objects and signals.

The reference line, profiles, lanes and links are read with findings for what is wrong (a record that cannot be used
is left out); the road's other records are read as the file gives them (``None``: absent or not of its type, the
schema rule reports it).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from xodrcheck.model.enums import ContactPoint, ElementDir, ElementType, MaxSpeed, SwitchPosition, TrafficRule
from xodrcheck.model.facts import XmlFacts, facts_field
from xodrcheck.model.lanes import Lanes, LaneSection
from xodrcheck.model.objects import Bridge, ObjectReference, RoadObject, Tunnel
from xodrcheck.model.planview import Geometry, Profile
from xodrcheck.model.signals import Signal, SignalReference
from xodrcheck.model.surface import CrossSectionSurface, Surface

__all__ = [
    "Railroad",
    "Road",
    "RoadLink",
    "RoadSpeed",
    "RoadType",
    "Shape",
    "Switch",
    "SwitchPartner",
    "SwitchTrack",
]


@dataclass(frozen=True, slots=True)
class RoadLink:
    """A road's ``predecessor`` or ``successor``."""

    element_type: ElementType
    element_id: str
    contact_point: ContactPoint | None = None
    element_s: float | None = None
    element_dir: ElementDir | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class RoadSpeed:
    """The ``<speed>`` of a road type: ``max`` a number (in ``unit``, km/h... ) or one of the words of
    :class:`MaxSpeed`."""

    max: float | MaxSpeed | None
    unit: str | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class RoadType:
    """A road's ``<type>`` (10.4): from ``s`` on, the kind of road (``town``, ``motorway``...) and its speed."""

    s: float | None
    type: str | None
    country: str | None = None
    speed: RoadSpeed | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Shape:
    """A ``<shape>`` of a road's lateral profile (10.5.3): ``h(dt) = a + b dt + c dt^2 + d dt^3`` from ``t`` on, at
    ``s``."""

    s: float | None
    t: float | None
    a: float | None
    b: float | None
    c: float | None
    d: float | None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class SwitchTrack:
    """A switch's ``<mainTrack>`` or ``<sideTrack>``: the road ``id`` the track runs on, at ``s``, in ``dir``."""

    id: str | None
    s: float | None = None
    dir: ElementDir | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class SwitchPartner:
    """A switch's ``<partner>``: the switch its side track leads to."""

    id: str | None
    name: str | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Switch:
    """A railroad ``<switch>`` (15.3) with its tracks and partner."""

    id: str | None
    name: str | None = None
    position: SwitchPosition | None = None
    main_track: SwitchTrack | None = None
    side_track: SwitchTrack | None = None
    partner: SwitchPartner | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Railroad:
    """A road's ``<railroad>``: its switches (of every ``<railroad>`` element, in file order)."""

    switches: tuple[Switch, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Road:
    """A road: reference line (plan view), profiles, lane layers, links, and what stands on it."""

    id: str
    length: float
    junction: str | None = None  # None for "-1" (not inside a junction)
    name: str | None = None
    rule: TrafficRule = TrafficRule.RHT
    predecessor: RoadLink | None = None
    successor: RoadLink | None = None
    plan_view: tuple[Geometry, ...] = ()
    elevation: Profile = ()
    superelevation: Profile = ()
    lane_offset: Profile = ()
    lane_sections: tuple[LaneSection, ...] = ()
    objects: tuple[RoadObject, ...] = ()
    signals: tuple[Signal, ...] = ()
    line: int = 0
    #: The temporary lane layer (1.9); ``lane_offset`` and ``lane_sections`` above are the permanent layer's.
    temporary_lanes: Lanes | None = None
    #: The permanent layer's ``<lanes>`` (the same offset and sections as above; ``None``: the road has none).
    lanes: Lanes | None = None
    types: tuple[RoadType, ...] = ()
    shapes: tuple[Shape, ...] = ()
    cross_section_surface: CrossSectionSurface | None = None
    surface: Surface | None = None
    railroad: Railroad | None = None
    object_references: tuple[ObjectReference, ...] = ()
    tunnels: tuple[Tunnel, ...] = ()
    bridges: tuple[Bridge, ...] = ()
    signal_references: tuple[SignalReference, ...] = ()
    xml: XmlFacts = facts_field()

    def section_end(self, index: int) -> float:
        """End s of lane section ``index`` (the next section's start or the road length; earlier when the section
        has a 1.9 ``length``)."""
        sections = self.lane_sections
        end = sections[index + 1].s if index + 1 < len(sections) else self.length
        length = sections[index].length
        return end if length is None else min(end, sections[index].s + length)

    def temporary_layer(self) -> Road | None:
        """The road seen through its temporary lane layer: the same road with the temporary layer's lane offset and
        lane sections (what :class:`xodrcheck.lanes.RoadGeometry` evaluates); ``None`` without one."""
        layer = self.temporary_lanes
        if layer is None:
            return None
        return replace(
            self, lane_offset=layer.lane_offset, lane_sections=layer.lane_sections, temporary_lanes=None, lanes=layer
        )
