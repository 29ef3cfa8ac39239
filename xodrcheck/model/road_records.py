"""A road's records beside its reference line and lanes: road types with their speed (10.4), the lateral profile's
shapes (10.5.3) and railroad switches (15.3). Read as the file gives them (``None``: absent or not of its type)."""

from __future__ import annotations

from dataclasses import dataclass

from xodrcheck.model.enums import ElementDir, MaxSpeed, SwitchPosition
from xodrcheck.model.facts import XmlFacts, facts_field

__all__ = ["Railroad", "RoadSpeed", "RoadType", "Shape", "Switch", "SwitchPartner", "SwitchTrack"]


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
