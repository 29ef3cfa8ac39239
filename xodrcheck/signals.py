"""Signals as plain, frozen, typed data, built from the file's XML: ``<road><signals>`` (signals with their boards,
lane validities, semantics and references; signal references), the ``<controller>`` elements and 1.9's
``<vmsGroup>`` elements (chapter 14).

What a signal holds here is what the signal rules need; raw attribute values are kept as written (``None`` when
absent) so that a rule can tell a missing attribute from a wrong one. Nothing here reports findings.
:func:`read_signals` builds the signals of a whole file; a rule gets them from
:attr:`xodrcheck.rules.context.Context.signals`, built once per file.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from lxml import etree

from xodrcheck.xmlvalues import integer, local, number


@dataclass(frozen=True, slots=True)
class Validity:
    """A ``<validity>``: the lanes from ``from_lane`` to ``to_lane`` (``None`` when not an integer)."""

    from_lane: int | None
    to_lane: int | None
    line: int = 0


@dataclass(frozen=True, slots=True)
class Sign:
    """A ``<sign>`` on a ``<staticBoard>`` (1.8)."""

    id: str | None
    type: str | None
    subtype: str | None
    country: str | None
    line: int = 0


@dataclass(frozen=True, slots=True)
class Signal:
    """A road's ``<signal>``: where it stands, what it shows and the lanes it applies to."""

    road: str
    id: str | None
    type: str | None
    subtype: str | None
    country: str | None
    dynamic: str | None
    orientation: str | None
    validities: tuple[Validity, ...] = ()
    s: float | None = None
    t: float | None = None
    #: The ``<sign>`` elements of each ``<staticBoard>``, one tuple per board (1.8).
    static_boards: tuple[tuple[Sign, ...], ...] = ()
    #: Number of ``<vmsBoard>`` children (1.8).
    vms_boards: int = 0
    #: For each ``<semantics>`` (of the signal and of its signs): its line and the names of its children.
    semantics: tuple[tuple[int, tuple[str, ...]], ...] = ()
    line: int = 0


@dataclass(frozen=True, slots=True)
class SignalReference:
    """A ``<signalReference>``: the signal ``id`` of another road, placed on ``road``."""

    road: str
    id: str | None
    orientation: str | None
    validities: tuple[Validity, ...] = ()
    line: int = 0
    s: float | None = None


@dataclass(frozen=True, slots=True)
class Control:
    """A controller's ``<control>``: the signal it switches."""

    signal_id: str | None
    line: int = 0


@dataclass(frozen=True, slots=True)
class Controller:
    """A ``<controller>``: the signals it switches together."""

    id: str | None
    controls: tuple[Control, ...] = ()
    line: int = 0


@dataclass(frozen=True, slots=True)
class VmsBoardReference:
    """A variable message sign's board reference in a VMS group."""

    signal_id: str | None
    vms_index: str | None
    line: int = 0


@dataclass(frozen=True, slots=True)
class VmsGroup:
    """A group of variable message sign boards."""

    id: str | None
    references: tuple[VmsBoardReference, ...] = ()
    line: int = 0


@dataclass(frozen=True, slots=True)
class Signals:
    """The file's signals, signal references, controllers and variable message board groups, in file order."""

    signals: tuple[Signal, ...] = ()
    references: tuple[SignalReference, ...] = ()
    controllers: tuple[Controller, ...] = ()
    vms_groups: tuple[VmsGroup, ...] = ()

    @property
    def by_id(self) -> dict[str, Signal]:
        """Signal id -> the first signal with it."""
        out: dict[str, Signal] = {}
        for signal in self.signals:
            if signal.id is not None:
                out.setdefault(signal.id, signal)
        return out


# ------------------------------------------------------------------------------------------------------------ reading
def _children(el: etree._Element, name: str) -> Iterator[etree._Element]:
    """Children named ``name`` whatever their namespace (``ctx.tree`` keeps a file's default namespace)."""
    for child in el:
        if local(child) == name:
            yield child


def _integer(el: etree._Element, name: str) -> int | None:
    return integer(el.get(name))


def _number(el: etree._Element, name: str) -> float | None:
    return number(el.get(name))


def _validities(el: etree._Element) -> tuple[Validity, ...]:
    return tuple(
        Validity(_integer(v, "fromLane"), _integer(v, "toLane"), v.sourceline or 0) for v in _children(el, "validity")
    )


def _semantics(el: etree._Element) -> list[tuple[int, tuple[str, ...]]]:
    return [
        (sem.sourceline or 0, tuple(name for name in map(local, sem) if name)) for sem in _children(el, "semantics")
    ]


def _signal(road_id: str, el: etree._Element) -> Signal:
    boards = []
    semantics = _semantics(el)
    for board in _children(el, "staticBoard"):
        signs = []
        for sign in _children(board, "sign"):
            signs.append(
                Sign(sign.get("id"), sign.get("type"), sign.get("subtype"), sign.get("country"), sign.sourceline or 0)
            )
            semantics.extend(_semantics(sign))
        boards.append(tuple(signs))
    return Signal(
        road_id,
        el.get("id"),
        el.get("type"),
        el.get("subtype"),
        el.get("country"),
        el.get("dynamic"),
        el.get("orientation"),
        _validities(el),
        _number(el, "s"),
        _number(el, "t"),
        tuple(boards),
        sum(1 for _ in _children(el, "vmsBoard")),
        tuple(semantics),
        el.sourceline or 0,
    )


def read_signals(root: etree._Element) -> Signals:
    """The signals of the file whose ``<OpenDRIVE>`` element is ``root``."""
    signals: list[Signal] = []
    references: list[SignalReference] = []
    for road in _children(root, "road"):
        road_id = road.get("id")
        if road_id is None:
            continue
        for group in _children(road, "signals"):
            for el in group:
                name = local(el)
                if name == "signal":
                    signals.append(_signal(road_id, el))
                elif name == "signalReference":
                    references.append(
                        SignalReference(
                            road_id,
                            el.get("id"),
                            el.get("orientation"),
                            _validities(el),
                            el.sourceline or 0,
                            _number(el, "s"),
                        )
                    )
    controllers = tuple(
        Controller(
            el.get("id"),
            tuple(Control(c.get("signalId"), c.sourceline or 0) for c in _children(el, "control")),
            el.sourceline or 0,
        )
        for el in _children(root, "controller")
    )
    groups = tuple(
        VmsGroup(
            el.get("id"),
            tuple(
                VmsBoardReference(r.get("signalId"), r.get("vmsIndex"), r.sourceline or 0)
                for r in _children(el, "vmsBoardReference")
            ),
            el.sourceline or 0,
        )
        for el in _children(root, "vmsGroup")
    )
    return Signals(tuple(signals), tuple(references), controllers, groups)
