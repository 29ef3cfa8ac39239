"""Signals (chapter 14): a road's signals with their boards, positions, lane validities, dependencies, references
and semantics; signal references; the file's controllers and groups of variable message boards.

Read as the file gives them: a value that is absent or not of its type is ``None``
(:attr:`XmlFacts.invalid <xodrcheck.model.facts.XmlFacts>` keeps its text; the schema rule reports it).
"""

from __future__ import annotations

from dataclasses import dataclass

from xodrcheck.model.enums import Orientation, ReferenceType
from xodrcheck.model.facts import XmlFacts, facts_field
from xodrcheck.model.objects import LaneValidity

__all__ = [
    "Control",
    "Controller",
    "DisplayArea",
    "PositionInertial",
    "PositionRoad",
    "Semantic",
    "Semantics",
    "Sign",
    "Signal",
    "SignalDependency",
    "SignalLink",
    "SignalReference",
    "StaticBoard",
    "VmsBoard",
    "VmsBoardReference",
    "VmsGroup",
]


@dataclass(frozen=True, slots=True)
class Semantic:
    """One traffic behaviour of a ``<semantics>`` (14.8): ``kind`` is its element (``speed``, ``priority``,
    ``prohibited``...), with the ``type``, ``value`` and ``unit`` the kinds that have them give."""

    kind: str
    type: str | None = None
    value: float | None = None
    unit: str | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Semantics:
    """A ``<semantics>`` element: the behaviours it names, in file order."""

    items: tuple[Semantic, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class SignalDependency:
    """A signal's ``<dependency>``: another signal (a supplementary sign, say) that depends on it."""

    id: str | None
    type: str | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class SignalLink:
    """A signal's ``<reference>``: an object or another signal it relates to (``element_type`` ``None``: absent or
    neither ``object`` nor ``signal``)."""

    element_type: ReferenceType | None
    element_id: str | None
    type: str | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class PositionRoad:
    """A signal's ``<positionRoad>``: placed on road ``road_id`` at ``s``, ``t``."""

    road_id: str | None
    s: float | None
    t: float | None
    z_offset: float | None = None
    h_offset: float | None = None
    pitch: float | None = None
    roll: float | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class PositionInertial:
    """A signal's ``<positionInertial>``: placed at ``x``, ``y``, ``z`` with heading ``hdg``."""

    x: float | None
    y: float | None
    z: float | None
    hdg: float | None = None
    pitch: float | None = None
    roll: float | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Sign:
    """A ``<sign>`` on a ``<staticBoard>`` (1.8): a signal of its own kind, placed on the board at ``v``, ``z``."""

    id: str | None
    type: str | None
    subtype: str | None
    country: str | None
    line: int = 0
    name: str | None = None
    country_revision: str | None = None
    dynamic: bool | None = None
    orientation: Orientation | None = None
    value: float | None = None
    text: str | None = None
    unit: str | None = None
    height: float | None = None
    width: float | None = None
    v: float | None = None
    z: float | None = None
    validities: tuple[LaneValidity, ...] = ()
    dependencies: tuple[SignalDependency, ...] = ()
    references: tuple[SignalLink, ...] = ()
    semantics: Semantics | None = None
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class StaticBoard:
    """A ``<staticBoard>`` (1.8): signs on one sheet."""

    signs: tuple[Sign, ...] = ()
    validities: tuple[LaneValidity, ...] = ()
    dependencies: tuple[SignalDependency, ...] = ()
    references: tuple[SignalLink, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class DisplayArea:
    """A ``<displayArea>`` of a variable message board."""

    index: int | None = None
    width: str | None = None
    height: str | None = None
    v: float | None = None
    z: float | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class VmsBoard:
    """A ``<vmsBoard>`` (1.8): a variable message board."""

    display_type: str | None = None
    display_height: float | None = None
    display_width: float | None = None
    v: float | None = None
    z: float | None = None
    display_areas: tuple[DisplayArea, ...] = ()
    validities: tuple[LaneValidity, ...] = ()
    dependencies: tuple[SignalDependency, ...] = ()
    references: tuple[SignalLink, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Signal:
    """A road's ``<signal>``: where it stands, what it shows, the lanes it applies to. ``road`` is the id of the
    road it stands on; ``s``, ``t`` and ``z_offset`` are its place there."""

    road: str
    id: str | None
    type: str | None
    subtype: str | None
    country: str | None
    dynamic: bool | None
    orientation: Orientation | None
    s: float | None = None
    t: float | None = None
    line: int = 0
    z_offset: float | None = None
    name: str | None = None
    country_revision: str | None = None
    value: float | None = None
    text: str | None = None
    unit: str | None = None
    height: float | None = None
    length: float | None = None
    width: float | None = None
    h_offset: float | None = None
    pitch: float | None = None
    roll: float | None = None
    invalidated: bool | None = None  # 1.9
    temporary: bool | None = None  # 1.9
    validities: tuple[LaneValidity, ...] = ()
    dependencies: tuple[SignalDependency, ...] = ()
    references: tuple[SignalLink, ...] = ()
    position_road: PositionRoad | None = None
    position_inertial: PositionInertial | None = None
    semantics: Semantics | None = None
    static_boards: tuple[StaticBoard, ...] = ()
    vms_boards: tuple[VmsBoard, ...] = ()
    xml: XmlFacts = facts_field()

    @property
    def signs(self) -> tuple[Sign, ...]:
        """The signs of all its static boards."""
        return tuple(sign for board in self.static_boards for sign in board.signs)

    def all_semantics(self) -> tuple[Semantics, ...]:
        """Its own ``<semantics>`` and its signs', in file order."""
        own = () if self.semantics is None else (self.semantics,)
        return own + tuple(sign.semantics for sign in self.signs if sign.semantics is not None)


@dataclass(frozen=True, slots=True)
class SignalReference:
    """A ``<signalReference>`` (14.5): the signal ``id`` of another road, placed on ``road``."""

    road: str
    id: str | None
    s: float | None
    t: float | None
    orientation: Orientation | None = None
    validities: tuple[LaneValidity, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Control:
    """A controller's ``<control>``: the signal it switches."""

    signal_id: str | None
    type: str | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Controller:
    """A ``<controller>`` (14.6): the signals it switches together."""

    id: str | None
    name: str | None = None
    sequence: int | None = None
    controls: tuple[Control, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class VmsBoardReference:
    """A variable message board's reference in a VMS group."""

    signal_id: str | None
    vms_index: int | None = None
    group_index: int | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class VmsGroup:
    """A ``<vmsGroup>`` (1.9, 14.7.4): the variable message boards of one gantry."""

    id: str | None
    references: tuple[VmsBoardReference, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()
