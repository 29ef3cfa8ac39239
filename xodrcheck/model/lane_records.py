"""The records of a lane that neither geometry nor topology needs (11.8): access, material, rule and visibility, and
a road mark's stripes (``<type>``, ``<explicit>`` lines) and ``<sway>``. Read as the file gives them: ``None`` for a
value that is absent or not of its type (:attr:`XmlFacts.invalid <xodrcheck.model.facts.XmlFacts>` keeps its text).
"""

from __future__ import annotations

from dataclasses import dataclass

from xodrcheck.model.enums import AccessRule
from xodrcheck.model.facts import XmlFacts, facts_field

__all__ = [
    "LaneAccess",
    "LaneMaterial",
    "LaneRule",
    "LaneVisibility",
    "RoadMarkExplicit",
    "RoadMarkLine",
    "RoadMarkSway",
    "RoadMarkType",
]


# --------------------------------------------------------------------------------------------------------- road marks
@dataclass(frozen=True, slots=True)
class RoadMarkLine:
    """A ``<line>`` of a road mark's ``<type>`` or ``<explicit>``: a stripe ``length`` long, every ``length + space``
    (``space`` ``None`` for an explicit line), at ``t_offset`` from the lane border, from ``s`` (its ``sOffset``)."""

    length: float | None
    space: float | None
    t_offset: float | None
    s: float | None
    rule: str | None = None
    width: float | None = None
    color: str | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class RoadMarkType:
    """A road mark's ``<type>``: its name, width and stripes."""

    name: str | None
    width: float | None
    lines: tuple[RoadMarkLine, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class RoadMarkExplicit:
    """A road mark's ``<explicit>`` stripes (irregular marks)."""

    lines: tuple[RoadMarkLine, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class RoadMarkSway:
    """A road mark's ``<sway>``: its lateral offset ``a + b ds + c ds^2 + d ds^3`` from ``ds`` on."""

    ds: float | None
    a: float | None
    b: float | None
    c: float | None
    d: float | None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class LaneAccess:
    """A lane's ``<access>`` (11.8.2): from ``s`` on, ``rule`` (allow or deny) for the restriction of the attribute
    (up to 1.7) or of the ``<restriction>`` children (1.8: their ``type`` in ``restrictions``)."""

    s: float | None
    rule: AccessRule | None = None
    restriction: str | None = None
    restrictions: tuple[str | None, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class LaneMaterial:
    """A lane's ``<material>`` from ``s`` on: surface, friction and roughness."""

    s: float | None
    surface: str | None = None
    friction: float | None = None
    roughness: float | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class LaneRule:
    """A lane's ``<rule>`` from ``s`` on: a free-text value (``no stopping at any time``...)."""

    s: float | None
    value: str | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class LaneVisibility:
    """A lane's ``<visibility>`` (1.4, 1.5): how far one sees ahead, back, left and right from ``s`` on."""

    s: float | None
    forward: float | None = None
    back: float | None = None
    left: float | None = None
    right: float | None = None
    line: int = 0
    xml: XmlFacts = facts_field()
