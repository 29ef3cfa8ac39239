"""Object markings (``B020``-``B023``): lines painted along a side of an object's bounding volume or through the
points of one of its outlines (13.8).

A marking of an object without outline runs along one side of the bounding volume (``@side``); a marking of an object
with an outline runs through outline points it names by id (``<cornerReference>``), in the outline's order, through
every point between two it names (13.8, Annex F F.6.16.7 and F.6.16.9). Since 1.9 such a marking sits in the
``<outline>`` whose points it names.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator
from typing import TYPE_CHECKING

from xodrcheck.findings import Category, Severity
from xodrcheck.rules.object_attributes import at, label
from xodrcheck.rules.object_outlines import name_of
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import object_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.feature_uids import ONLY_REF_DEFINED_IDS

if TYPE_CHECKING:
    from xodrcheck.model import Marking, Outline, RoadObject


def markings(ctx: Context) -> Iterator[tuple[RoadObject, Outline | None, Marking]]:
    """Every marking with its object and the outline it sits in (``None``: in the object's ``<markings>``)."""
    for obj in ctx.road_objects():
        for outline, marking in obj.all_markings():
            yield obj, outline, marking


def referenced_outline(obj: RoadObject, outline: Outline | None, marking: Marking) -> Outline | None:
    """The outline whose points a marking names: the one it sits in, else the first of the object's outlines that
    has a point with every id the marking references (``None``: no such outline, or a marking naming none)."""
    if outline is not None:
        return outline
    ids = {r.id for r in marking.references}
    if not ids or None in ids:
        return None
    return next((o for o in obj.outlines if ids <= {p.id for p in o.points}), None)


@rule(
    "B020",
    "marking-colour-missing",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.MARKING_COLOUR, U.OBJECT_MARKING_COLOUR),
)
def marking_colour_missing(ctx: Context):
    """An object's ``<marking>`` has no ``color``.

    The colour of a marking shall be defined (Annex F ``road.object.marking.colour`` and, from 1.8,
    ``road.object.object_marking.colour``, 13.8; one finding names each rule that applies).

    Passes::

        <marking side="left" color="white" width="0.1" spaceLength="0" lineLength="1" startOffset="0" stopOffset="0"/>

    Fails::

        <marking side="left" width="0.1" spaceLength="0" lineLength="1" startOffset="0" stopOffset="0"/>
    """
    for obj, _, marking in markings(ctx):
        if (marking.color or "").strip():
            continue
        for uid in (U.MARKING_COLOUR, U.OBJECT_MARKING_COLOUR):
            yield marking_colour_missing.finding(
                f"{label(obj)}: the <marking> at line {marking.line} has no color: give it one (white, yellow, ...)",
                uid=uid,
                **at(ctx, obj, marking.line),
            )


@rule(
    "B021",
    "marking-placement",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.MARKINGS_WITH_OUTLINE, U.MARKINGS_WITHOUT_OUTLINE, U.MARKING_ON_OUTLINE),
)
def marking_placement(ctx: Context):
    """An object's markings are not where OpenDRIVE 1.9 puts them, or not on one of its outlines.

    If an object has an outline, its ``<markings>`` are inside an ``<outline>`` (Annex F
    ``road.object.marking.markings_with_outline``, 13.8), and each marking lies completely or partly on one of the
    outlines: all its corner references name points of that outline (``.complete_or_partial_on_outline``). A marking
    that uses no outline (a ``side`` of the bounding volume, no corner references) belongs in the ``<object>``'s own
    ``<markings>`` (``.markings_without_outline``), not in an outline's.

    Passes (1.9)::

        <outline id="0">...<markings><marking color="white" ...><cornerReference id="0"/>
          <cornerReference id="1"/></marking></markings></outline>

    Fails (the markings of an object with an outline are outside it)::

        <outline id="0">...</outline></outlines><markings><marking color="white" ...>
          <cornerReference id="0"/><cornerReference id="1"/></marking></markings>
    """
    for obj in ctx.road_objects():
        if obj.outlines:
            for group in obj.markings:
                yield marking_placement.finding(
                    f"{label(obj)} has outlines, but its <markings> at line {group.line} are in the <object>: put "
                    "them into the <outline> whose points they run through",
                    uid=U.MARKINGS_WITH_OUTLINE,
                    **at(ctx, obj, group.line),
                )
        for outline, marking in obj.all_markings():
            if outline is not None and marking.side is not None and not marking.references:
                yield marking_placement.finding(
                    f"{label(obj)}: the <marking> at line {marking.line} runs along the {marking.side} side of the "
                    f"bounding volume, not through outline points, but sits in {name_of(outline)}: a marking that "
                    "uses no outline goes into the <object>'s <markings>",
                    uid=U.MARKINGS_WITHOUT_OUTLINE,
                    **at(ctx, obj, marking.line),
                )
            elif obj.outlines and referenced_outline(obj, outline, marking) is None:
                yield marking_placement.finding(
                    f"{label(obj)}: the <marking> at line {marking.line} {_not_on_outline(obj, outline, marking)}: "
                    "a marking of an object with outlines runs through the points of one of them",
                    uid=U.MARKING_ON_OUTLINE,
                    **at(ctx, obj, marking.line),
                )
            elif outline is not None and (missing := _unknown_ids(outline, marking)):
                yield marking_placement.finding(
                    f"{label(obj)}: the <marking> at line {marking.line} references corner "
                    f"{', '.join(map(str, missing))}, which {name_of(outline)} does not have: a marking runs through "
                    "points of its outline",
                    uid=U.MARKING_ON_OUTLINE,
                    **at(ctx, obj, marking.line),
                )


def _unknown_ids(outline: Outline, marking: Marking) -> list[int]:
    known = {p.id for p in outline.points}
    return [r.id for r in marking.references if r.id is not None and r.id not in known]


def _not_on_outline(obj: RoadObject, outline: Outline | None, marking: Marking) -> str:
    if not marking.references:
        return "names no outline point (it uses a side of the bounding volume)"
    ids = ", ".join(str(r.id) for r in marking.references)
    return f"references corners {ids}, which no single outline of the object has"


@rule(
    "B022",
    "marking-without-outline",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.NO_REFERENCE_WITHOUT_OUTLINE, U.SIDE_WITHOUT_OUTLINE),
)
def marking_without_outline(ctx: Context):
    """A marking of an object without outline names outline points, or no side of the bounding volume.

    Without an outline a marking runs along one side of the object's bounding volume: its ``side`` is mandatory
    (Annex F ``road.object.marking.no_outline_side_attr``, 13.8) and it cannot use ``<cornerReference>``, which names
    outline points (``.no_cornerreference_if_no_outline``).

    Passes::

        <object id="1" type="parkingSpace" ... length="5" width="2.5"><markings><marking side="left" color="white"
          width="0.1" spaceLength="0" lineLength="1" startOffset="0" stopOffset="0"/></markings></object>

    Fails::

        <object id="1" type="parkingSpace" ... length="5" width="2.5"><markings><marking color="white" width="0.1"
          spaceLength="0" lineLength="1" startOffset="0" stopOffset="0"><cornerReference id="0"/>...
    """
    for obj in ctx.road_objects():
        if obj.outlines:
            continue
        for _, marking in obj.all_markings():
            text = f"{label(obj)} has no outline, but the <marking> at line {marking.line}"
            if marking.references:
                yield marking_without_outline.finding(
                    f"{text} has {len(marking.references)} <cornerReference>: they name outline points; without an "
                    "outline, give the side of the bounding volume the marking runs along",
                    uid=U.NO_REFERENCE_WITHOUT_OUTLINE,
                    **at(ctx, obj, marking.references[0].line),
                )
            if marking.side is None:
                yield marking_without_outline.finding(
                    f"{text} has no side: say along which side of the bounding volume it runs (left, right, front, "
                    "rear)",
                    uid=U.SIDE_WITHOUT_OUTLINE,
                    **at(ctx, obj, marking.line),
                )


_COUNT_UIDS = (U.MARKING_REFERENCE_COUNT, U.OBJECT_MARKING_REFERENCE_COUNT)


def _positions(outline: Outline, marking: Marking) -> list[int] | None:
    index = {p.id: k for k, p in reversed(list(enumerate(outline.points))) if p.id is not None}
    found = [None if r.id is None else index.get(r.id) for r in marking.references]
    positions = [k for k in found if k is not None]
    return positions if len(positions) == len(found) else None


def _order_problem(positions: list[int], n: int, closed: bool) -> str | None:
    """Why corner references at these outline positions do not follow the outline (``None``: they do). On a
    closed outline they may run across the closing edge, once round at most."""
    steps = [b - a for a, b in itertools.pairwise(positions)]
    if not closed:
        return None if all(d > 0 for d in steps) else "do not follow the outline's order"
    travel = sum((d % n) or n for d in steps)
    return None if travel <= n else "do not follow the outline's order (they run round it more than once)"


@rule(
    "B023",
    "marking-corner-references",
    Category.OBJECT,
    Severity.ERROR,
    uids=(*_COUNT_UIDS, U.KEEP_ID_ORDERED, U.ENCLOSED_OUTLINE_MARKING, ONLY_REF_DEFINED_IDS),
)
def marking_corner_references(ctx: Context):
    """A marking names fewer than two outline points, names them out of the outline's order, or repeats one.

    (A repeated point is allowed only first and last, to enclose a closed outline.)

    With an outline, a marking needs at least two ``<cornerReference>`` elements (Annex F
    ``road.object.marking.outline_corner_reference_count``, from 1.8 also
    ``.object_marking.outline_corner_reference_count``; one finding names each rule that applies). They name points
    in the order of the outline (``.object_marking.keep_id_ordered``): on a closed outline (``closed`` true, the
    default for every object type, 13.14) the marking may run across the closing edge from the last point to the
    first. A marking that encloses the object on a closed outline names one point twice, first and last
    (``.object_marking.enclosed_outline_marking``): a repeated point anywhere else, or on an open outline, is no
    such marking. Before 1.9, a marking naming points no outline of the object has references undefined ids
    (``ids.only_ref_defined_ids``; from 1.9 ``marking-placement`` says so).

    Passes (a closed outline of points 0-3)::

        <marking color="white" ...><cornerReference id="3"/><cornerReference id="0"/></marking>

    Fails (0 to 2, then back to 1: round the outline more than once)::

        <marking color="white" ...><cornerReference id="0"/><cornerReference id="2"/><cornerReference id="1"/></marking>
    """
    old = ctx.version is not None and ctx.version < (1, 9)
    for obj, outline, marking in markings(ctx):
        if not obj.outlines:
            continue
        refs = marking.references
        where = at(ctx, obj, marking.line)
        if len(refs) < 2:
            for uid in _COUNT_UIDS:
                yield marking_corner_references.finding(
                    f"{label(obj)}: the <marking> at line {marking.line} has {len(refs)} <cornerReference>: a marking "
                    "of an object with an outline runs through at least two outline points",
                    uid=uid,
                    **where,
                )
            continue
        target = referenced_outline(obj, outline, marking)
        positions = None if target is None else _positions(target, marking)
        if target is None or positions is None:
            if old:  # 1.9 files: marking-placement's complete_or_partial_on_outline
                yield marking_corner_references.finding(
                    f"{label(obj)}: the <marking> at line {marking.line} references corners no outline of the "
                    "object has",
                    uid=ONLY_REF_DEFINED_IDS,
                    **where,
                )
            continue
        yield from _order(ctx, obj, target, marking, positions)


def _order(ctx: Context, obj: RoadObject, outline: Outline, marking: Marking, positions: list[int]):
    closed = outline.closed is not False
    ids = ", ".join(str(r.id) for r in marking.references)
    text = f"{label(obj)}: the <marking> at line {marking.line} names corners {ids} of {name_of(outline)}"
    where = at(ctx, obj, marking.line)
    repeated = len(set(positions)) < len(positions)
    encloses = positions[0] == positions[-1] and len(set(positions[:-1])) == len(positions) - 1
    if repeated and not (closed and encloses):
        why = "an open outline" if not closed else "a corner named twice other than first and last"
        yield marking_corner_references.finding(
            f"{text}: {why} does not enclose the object; to enclose it, name one corner of a closed outline first "
            "and last",
            uid=U.ENCLOSED_OUTLINE_MARKING,
            **where,
        )
        return
    problem = _order_problem(positions, len(outline.points), closed)
    if problem:
        yield marking_corner_references.finding(
            f"{text}, which {problem}: list corner references in the order of the outline's points",
            uid=U.KEEP_ID_ORDERED,
            **where,
        )
