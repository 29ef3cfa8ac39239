"""Signals (chapter 14): type, country, signal boards, semantics, controllers, variable message board groups
(``T001``-``T007``), read from the document: each road's signals, the file's controllers and vmsGroups; lane
validities and signal references are :mod:`.signal_validity`'s.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from xodrcheck.findings import Category, Severity
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import feature_uids as U
from xodrcheck.rules.shared.context import Context

if TYPE_CHECKING:  # pragma: no cover - the model's signal module loads for a file with signals
    from xodrcheck.model import Signal


def _signals(ctx: Context) -> list[Signal]:
    """Every road's signals, in file order."""
    return [signal for road in ctx.document.roads for signal in road.signals]


def _dynamic(signal: Signal) -> str | None:
    """The signal's ``dynamic`` as written (``None``: absent)."""
    if signal.dynamic is None:
        return signal.xml.text("dynamic")
    return "yes" if signal.dynamic else "no"


def _blank(value: str | None) -> bool:
    return value is None or not value.strip()


@rule(
    "T001",
    "signal-type-unspecified",
    Category.SIGNAL,
    Severity.ERROR,
    partial={
        U.SIGNAL_TYPE: "whether the type and subtype name a sign of the country's catalogue is not checked (the "
        "catalogues are outside the file)"
    },
)
def signal_type_unspecified(ctx: Context):
    """A signal (or a sign on a static board) has no ``type`` or no ``subtype``, or an empty one.

    Signals shall have a specific type and subtype (Annex F ``road.signal.signal_type``, 14.1): together with
    ``country`` and ``countryRevision`` they say which sign it is; ``"-1"`` or ``"none"`` is written where the
    catalogue has none.

    Passes::

        <signal id="1" ... country="DE" type="274" subtype="100" .../>

    Fails::

        <signal id="1" ... country="DE" type="274" subtype="" .../>
    """
    for signal in _signals(ctx):
        items: list[tuple[str, str | None, str | None, str | None, int]] = [
            ("signal", signal.id, signal.type, signal.subtype, signal.line)
        ]
        items += [("sign", s.id, s.type, s.subtype, s.line) for board in signal.static_boards for s in board.signs]
        for what, ident, kind, subtype, line in items:
            missing = [name for name, value in (("type", kind), ("subtype", subtype)) if _blank(value)]
            if missing:
                yield signal_type_unspecified.finding(
                    f"{what} {ident!r} has no {' and no '.join(missing)}: give the sign's type and subtype from the "
                    'country\'s catalogue ("-1" or "none" where it has none)',
                    road=signal.road,
                    line=line or None,
                )


@rule("T002", "signal-country-missing", Category.SIGNAL, Severity.ERROR, uids=(U.SIGNAL_COUNTRY,))
def signal_country_missing(ctx: Context):
    """A signal (or a sign on a static board) has no ``country``.

    A country code shall be added to refer to country-specific rules (Annex F ``road.signal.use_country_code``,
    14.1): a signal's type and subtype mean something only in the catalogue of its country (ISO 3166-1 alpha-2, or
    ``OpenDRIVE`` for the types of the OpenDRIVE signal reference such as traffic lights and boards).

    Passes::

        <signal id="1" ... country="DE" type="274" subtype="100" .../>

    Fails::

        <signal id="1" ... type="274" subtype="100" .../>
    """
    for signal in _signals(ctx):
        items = [("signal", signal.id, signal.country, signal.line)]
        items += [("sign", s.id, s.country, s.line) for board in signal.static_boards for s in board.signs]
        for what, ident, country, line in items:
            if _blank(country):
                yield signal_country_missing.finding(
                    f'{what} {ident!r} has no country: add @country (ISO 3166-1 alpha-2, or "OpenDRIVE" for the '
                    "OpenDRIVE signal reference's types) so that its type and subtype can be looked up",
                    road=signal.road,
                    line=line or None,
                )


def _board_problems(signal: Signal) -> Iterator[tuple[str, str]]:
    """(UID, what is wrong) for one signal's boards."""
    static, vms = len(signal.static_boards), len(signal.vms_boards)
    is_multi = signal.type == "multiBoard" or (static and vms)
    if static and vms and signal.type != "multiBoard":
        yield (
            U.MULTI_BOARD_TYPE,
            (
                f"has {static} <staticBoard> and {vms} <vmsBoard>, which makes it a multi board, but type="
                f'{signal.type!r}: set type="multiBoard"'
            ),
        )
    elif static and not vms and signal.type != "staticBoard":
        yield U.STATIC_BOARD_TYPE, f'has a <staticBoard> but type={signal.type!r}: set type="staticBoard"'
    if signal.type == "multiBoard" and not (static and vms):
        yield (
            U.MULTI_BOARD_SUB_BOARDS,
            (
                f"is a multi board with {static} <staticBoard> and {vms} <vmsBoard>: a multi board has at least one "
                "of each (a board of one kind is a staticBoard or a vmsBoard)"
            ),
        )
    dynamic = _dynamic(signal)
    if is_multi and dynamic != "yes":
        yield (
            U.MULTI_BOARD_DYNAMIC,
            (f'is a multi board with dynamic={dynamic!r}: its variable message part changes, set dynamic="yes"'),
        )


@rule(
    "T003",
    "signal-board-type",
    Category.SIGNAL,
    Severity.ERROR,
    uids=(U.MULTI_BOARD_TYPE, U.STATIC_BOARD_TYPE, U.MULTI_BOARD_SUB_BOARDS, U.MULTI_BOARD_DYNAMIC),
)
def signal_board_type(ctx: Context):
    """A signal board's ``type`` or ``dynamic`` does not match its boards (14.7).

    A signal with static boards only shall be ``type="staticBoard"``; one with static and variable message boards
    is a multi board and shall be ``type="multiBoard"``; a multi board shall have at least one board of each kind
    and be ``dynamic="yes"`` (Annex F ``road.signal.boards.static_board_use_correct_type``,
    ``multi_board_use_correct_type``, ``multi_board_have_sub_boards``, ``multi_board_use_dynamic_true``).

    Passes::

        <signal ... type="multiBoard" dynamic="yes"><staticBoard>...</staticBoard><vmsBoard .../></signal>

    Fails::

        <signal ... type="multiBoard" dynamic="no"><vmsBoard .../></signal>
    """
    for signal in _signals(ctx):
        for uid, why in _board_problems(signal):
            yield signal_board_type.finding(
                f"signal {signal.id!r} {why}", uid=uid, road=signal.road, line=signal.line or None
            )


@rule("T004", "static-board-single-sign", Category.SIGNAL, Severity.ERROR, uids=(U.STATIC_BOARD_SINGLE,))
def static_board_single_sign(ctx: Context):
    """A static board carries a single sign (or none).

    Static boards shall not be used for single signals, such as a stop sign on its own sheet of metal (Annex F
    ``road.signal.boards.static_boards_no_single_signal``, 14.7.1): a single sign is a ``<signal>`` of its own type.
    Multi boards are not concerned (their variable message part is the other signal).

    Passes::

        <signal ... type="staticBoard"><staticBoard><sign .../><sign .../></staticBoard></signal>

    Fails::

        <signal ... type="staticBoard"><staticBoard><sign type="206" .../></staticBoard></signal>
    """
    for signal in _signals(ctx):
        if not signal.static_boards or signal.vms_boards or signal.type == "multiBoard":
            continue
        signs = sum(len(board.signs) for board in signal.static_boards)
        if signs < 2:
            yield static_board_single_sign.finding(
                f"static board {signal.id!r} carries {signs} sign{'' if signs == 1 else 's'}: a single sign is "
                "written as a <signal> with the sign's own type and subtype, not as a board",
                road=signal.road,
                line=signal.line or None,
            )


@rule(
    "T005",
    "signal-semantics-empty",
    Category.SIGNAL,
    Severity.ERROR,
    partial={
        U.SEMANTICS_CATEGORY: "whether the categories given fit the sign's traffic behaviour is not checked (that "
        "needs the country's sign catalogue); only semantics without any category are found"
    },
)
def signal_semantics_empty(ctx: Context):
    """A signal's (or sign's) ``<semantics>`` names no traffic behaviour.

    Signal semantics shall not be specified for signs if no category for the desired traffic behaviour exists
    (Annex F ``road.signal.semantics.no_semantics_without_category``, 14.8): a ``<semantics>`` holds one element per
    behaviour (``<speed>``, ``<priority>``, ``<prohibited>``...); an empty one says nothing and is left out.

    Passes::

        <semantics><speed type="maximum" value="60" unit="km/h"/></semantics>

    Fails::

        <semantics/>
    """
    for signal in _signals(ctx):
        owners = [signal.semantics, *(sign.semantics for board in signal.static_boards for sign in board.signs)]
        for semantics in owners:
            if semantics is not None and not semantics.items:
                yield signal_semantics_empty.finding(
                    f"signal {signal.id!r} has a <semantics> without any behaviour element: give the category "
                    "(<speed>, <priority>, <prohibited>, ...) or leave <semantics> out when none fits",
                    road=signal.road,
                    line=semantics.line or None,
                )


@rule("T006", "controller-without-signals", Category.SIGNAL, Severity.ERROR, uids=(U.CONTROLLER_SIGNALS,))
def controller_without_signals(ctx: Context):
    """A ``<controller>`` controls no signal of the file.

    Controllers shall be valid for one or more signals (Annex F ``road.signal.controller.valid_for_signals``, 14.6):
    at least one ``<control>`` naming a signal (or a sign of a board) of the file.

    Passes::

        <controller id="1"><control signalId="5"/></controller>   <!-- signal 5 exists -->

    Fails::

        <controller id="1"><control signalId="99"/></controller>  <!-- no signal 99 -->
    """
    controllers = ctx.document.controllers
    if not controllers:
        return
    signals = _signals(ctx)
    known = {s.id for s in signals} | {sign.id for s in signals for board in s.static_boards for sign in board.signs}
    for controller in controllers:
        named = [c.signal_id for c in controller.controls]
        if any(signal_id in known for signal_id in named):
            continue
        why = (
            "has no <control>"
            if not named
            else f"controls only signals the file does not have ({', '.join(repr(n) for n in named)})"
        )
        yield controller_without_signals.finding(
            f"controller {controller.id!r} {why}: a controller is valid for one or more signals; add a <control> "
            "for each signal it switches",
            line=controller.line or None,
        )


@rule(
    "T007",
    "vms-group-without-boards",
    Category.SIGNAL,
    Severity.ERROR,
    partial={
        U.GANTRY_VMS_GROUP: "whether every gantry has one <vmsGroup> is vms-boards-gantry's (T008), as far as the "
        "boards' positions tell"
    },
)
def vms_group_without_boards(ctx: Context):
    """A ``<vmsGroup>`` references no variable message board.

    Each gantry shall have one ``<vmsGroup>`` with at least one ``<vmsBoardReference>`` (Annex F
    ``road.signal.gantry.vmsgroup_at_least_one_reference``, 14.7.4), and a reference names a signal that has a
    ``<vmsBoard>``. A group none of whose references reaches such a signal groups nothing.

    Passes::

        <vmsGroup id="1"><vmsBoardReference signalId="10" vmsIndex="1" groupIndex="1"/></vmsGroup>

    Fails::

        <vmsGroup id="1"/>
    """
    groups = ctx.document.vms_groups
    if not groups:
        return
    boards = {s.id for s in _signals(ctx) if s.vms_boards}
    for group in groups:
        named = [r.signal_id for r in group.references]
        if any(signal_id in boards for signal_id in named):
            continue
        why = (
            "has no <vmsBoardReference>"
            if not named
            else f"references no signal with a <vmsBoard> ({', '.join(repr(n) for n in named)})"
        )
        yield vms_group_without_boards.finding(
            f"vmsGroup {group.id!r} {why}: list the variable message boards of its gantry, one <vmsBoardReference> "
            "each",
            line=group.line or None,
        )
