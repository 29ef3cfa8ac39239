"""Lane validity of signals and signal references, and what a ``<signalReference>`` names (14.2, 14.5):
``T010``-``T013``.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from xodrcheck.findings import Category, Severity
from xodrcheck.model import TrafficRule
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import feature_uids as U
from xodrcheck.rules.shared.context import Context

if TYPE_CHECKING:  # pragma: no cover - the model's signal module loads for a file with signals
    from xodrcheck.model import LaneValidity, SignalReference

_ORIENTATIONS = ("+", "-", "none")


def _orientation(record: Any) -> str | None:
    """A signal's or reference's ``orientation`` as written (``None``: absent)."""
    value = record.orientation
    return record.xml.text("orientation") if value is None else value.value


def _references(ctx: Context) -> list[SignalReference]:
    return [ref for road in ctx.document.roads for ref in road.signal_references]


def _spans(validities: Iterable[LaneValidity]) -> tuple[bool, bool]:
    """Whether the validities span negative and positive lane ids."""
    negative = positive = False
    for v in validities:
        if v.from_lane is None or v.to_lane is None:
            continue
        low, high = min(v.from_lane, v.to_lane), max(v.from_lane, v.to_lane)
        negative |= low < 0
        positive |= high > 0
    return negative, positive


def _direction_problem(orientation: str | None, rht: bool, negative: bool, positive: bool) -> str | None:
    """What is wrong with ``orientation`` for validities spanning these sides, or ``None``."""
    if orientation not in ("+", "-"):
        return None
    if negative and positive:
        return 'its lane validity spans lanes on both sides, so orientation="none" shall be used'
    # Right-hand traffic drives along s on the right (negative) lanes; left-hand traffic on the left lanes.
    along_negative = rht == (orientation == "+")
    if along_negative and positive:
        return (
            f'with orientation="{orientation}" in {"right" if rht else "left"}-hand traffic its lane validity '
            "shall span negative lane ids only, but it spans positive ones"
        )
    if not along_negative and negative:
        return (
            f'with orientation="{orientation}" in {"right" if rht else "left"}-hand traffic its lane validity '
            "shall span positive lane ids only, but it spans negative ones"
        )
    return None


@rule(
    "T010",
    "signal-validity-direction",
    Category.SIGNAL,
    Severity.ERROR,
    uids=(U.VALIDITY_RHT, U.VALIDITY_LHT, U.REFERENCE_RHT, U.REFERENCE_LHT),
)
def signal_validity_direction(ctx: Context):
    """A signal's (or signal reference's) lane validity lies on the side its ``orientation`` does not apply to.

    In right-hand traffic ``orientation="+"`` (traffic along s) implies a ``<validity>`` spanning only negative lane
    ids and ``"-"`` only positive ones; in left-hand traffic the other way round; validities spanning both sides
    need ``orientation="none"`` (Annex F ``road.signal.validity.right_hand_traffic_lane_ids``,
    ``left_hand_traffic_lane_ids`` and the same two of ``road.signal.reference``; 14.2, 14.5). The road's ``rule``
    says which traffic it has (right-hand when absent).

    Passes::

        <road rule="RHT"> ... <signal orientation="+" ...><validity fromLane="-2" toLane="-1"/></signal>

    Fails::

        <road rule="RHT"> ... <signal orientation="+" ...><validity fromLane="1" toLane="1"/></signal>
    """
    signals = [signal for road in ctx.document.roads for signal in road.signals]
    items = [("signal", s.road, s.id, _orientation(s), s.validities, s.line, False) for s in signals]
    items += [("signal reference", r.road, r.id, _orientation(r), r.validities, r.line, True) for r in _references(ctx)]
    for what, road_id, ident, orientation, validities, line, is_reference in items:
        if not validities:
            continue
        road = ctx.road(road_id)
        rht = road is None or road.rule is not TrafficRule.LHT
        problem = _direction_problem(orientation, rht, *_spans(validities))
        if problem is None:
            continue
        if is_reference:
            uid = U.REFERENCE_RHT if rht else U.REFERENCE_LHT
        else:
            uid = U.VALIDITY_RHT if rht else U.VALIDITY_LHT
        yield signal_validity_direction.finding(
            f"{what} {ident!r} on road {road_id}: {problem}", uid=uid, road=road_id, line=line or None
        )


@rule("T011", "signal-reference-lane-order", Category.SIGNAL, Severity.ERROR, uids=(U.REFERENCE_LANE_ORDER,))
def signal_reference_lane_order(ctx: Context):
    """A signal reference's ``<validity>`` has ``fromLane`` greater than ``toLane``.

    ``fromLane`` shall be lower than or equal to ``toLane`` (Annex F ``road.signal.reference.from_lower_equal_to``,
    14.5): the validity runs from the lowest lane id to the highest.

    Passes::

        <signalReference ...><validity fromLane="-2" toLane="-1"/></signalReference>

    Fails::

        <signalReference ...><validity fromLane="-1" toLane="-2"/></signalReference>
    """
    for ref in _references(ctx):
        for v in ref.validities:
            if v.from_lane is not None and v.to_lane is not None and v.from_lane > v.to_lane:
                yield signal_reference_lane_order.finding(
                    f'signal reference {ref.id!r} on road {ref.road}: <validity fromLane="{v.from_lane}" '
                    f'toLane="{v.to_lane}">: fromLane shall not exceed toLane; swap them',
                    road=ref.road,
                    line=v.line or None,
                )


@rule("T012", "signal-reference-orientation", Category.SIGNAL, Severity.ERROR, uids=(U.REFERENCE_DIRECTION,))
def signal_reference_orientation(ctx: Context):
    """A ``<signalReference>`` does not say the direction it applies to.

    The direction on the road for which the referenced signal is valid shall be given for every signal reference
    with ``orientation`` (``+``, ``-`` or ``none``; Annex F ``road.signal.reference.specify_direction``, 14.5).

    Passes::

        <signalReference s="10" t="-4" id="5" orientation="+"/>

    Fails::

        <signalReference s="10" t="-4" id="5"/>
    """
    for ref in _references(ctx):
        orientation = _orientation(ref)
        if orientation not in _ORIENTATIONS:
            got = "no orientation" if orientation is None else f"orientation={orientation!r}"
            yield signal_reference_orientation.finding(
                f"signal reference {ref.id!r} on road {ref.road} has {got}: say which traffic it applies to with "
                'orientation="+" (along s), "-" (against s) or "none" (both)',
                road=ref.road,
                line=ref.line or None,
            )


@rule("T013", "signal-reference-not-signal", Category.SIGNAL, Severity.ERROR, uids=(U.REFERENCE_SIGNALS_ONLY,))
def signal_reference_not_signal(ctx: Context):
    """A ``<signalReference>`` names an object (or another element that is not a signal).

    Signal references shall be used for signals only (Annex F ``road.signal.reference.used_for_signals_only``,
    14.5); an object is placed on other roads with an ``<objectReference>``. A reference whose id names nothing at
    all is ``undefined-reference``'s.

    Passes::

        <signalReference s="10" t="-4" id="5" orientation="+"/>   <!-- signal 5 exists -->

    Fails::

        <signalReference s="10" t="-4" id="7" orientation="+"/>   <!-- 7 is an <object> -->
    """
    references = _references(ctx)
    if not references:
        return
    document = ctx.document
    signals = {signal.id for road in document.roads for signal in road.signals if signal.id is not None}
    others: dict[str, str] = {}
    for records, what in (
        ([obj for road in document.roads for obj in road.objects], "an object"),
        (document.roads, "a road"),
        (document.junctions, "a junction"),
        (document.controllers, "a controller"),
    ):
        for record in records:
            if record.id is not None:
                others.setdefault(record.id, f"{what} (line {record.line or None})")
    for ref in references:
        if ref.id is None or ref.id in signals or ref.id not in others:
            continue
        yield signal_reference_not_signal.finding(
            f"signal reference {ref.id!r} on road {ref.road} names {others[ref.id]}, not a signal: a signal "
            "reference places a signal on another road; use <objectReference> for objects",
            road=ref.road,
            line=ref.line or None,
        )
