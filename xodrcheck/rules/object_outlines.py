"""Object outlines and borders as the file writes them (``B010``-``B017``): which corners an outline uses, how many,
their ids, the outline ids and the borders that name them (13.2, 13.9).

An outline is made of two or more ``<cornerRoad>``, two or more ``<cornerLocal>`` or one or more ``<curveLocal>``
elements, never a mixture (13.2.1-13.2.3). Where outlines are in space (inside the bounding volume, inner outlines
touching the outer one) is :mod:`xodrcheck.rules.object_geometry`'s; curves of ``<curveLocal>`` outlines are
:mod:`xodrcheck.rules.outline_curves`'.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator
from typing import TYPE_CHECKING

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.model import CORNER_LOCAL, CORNER_ROAD, CURVE_LOCAL
from xodrcheck.rules.object_attributes import at, label
from xodrcheck.rules.registry import NO_UID, rule
from xodrcheck.rules.shared import object_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.feature_uids import ONLY_REF_DEFINED_IDS

if TYPE_CHECKING:
    from xodrcheck.model import Outline, OutlinePoint, RoadObject


def outlines(ctx: Context) -> Iterator[tuple[RoadObject, Outline]]:
    for obj in ctx.road_objects():
        for outline in obj.outlines:
            yield obj, outline


def id_text(record: Outline | OutlinePoint) -> str | None:
    """The ``@id`` of an outline or outline point as the file gives it: its text when not an integer, else the
    integer (``None``: absent)."""
    if not record.xml.given("id"):
        return None
    text = record.xml.text("id")
    return text if text is not None else str(record.id)


def name_of(outline: Outline) -> str:
    written = id_text(outline)
    return "outline" + (f" {written}" if written is not None else f" at line {outline.line}")


@rule(
    "B010",
    "outline-corners-mixed",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.ROAD_LOCAL_EXCLUSIVITY, U.LOCAL_NO_MIXING),
)
def outline_corners_mixed(ctx: Context):
    """An ``<outline>`` mixes ``<cornerRoad>``, ``<cornerLocal>`` and ``<curveLocal>`` elements.

    The three are mutually exclusive within one outline (13.2.1-13.2.3): Annex F
    ``road.corner_road.corner_road_local_exclusivity`` (any mixture, 1.9) and ``road.corner_local.no_mixing_road_local``
    (``<cornerRoad>`` beside ``<cornerLocal>``; its UID has no version, taken as 1.9). An outline mixing road and
    local corners breaks both; one finding names each.

    Passes::

        <outline id="0"><cornerLocal u="0" v="0" z="0" height="0.2" id="0"/>
          <cornerLocal u="2" v="0" z="0" height="0.2" id="1"/></outline>

    Fails::

        <outline id="0"><cornerLocal u="0" v="0" z="0" height="0.2" id="0"/>
          <cornerRoad s="12" t="-3" dz="0" height="0.2" id="1"/></outline>
    """
    for obj, outline in outlines(ctx):
        kinds = outline.kinds
        if len(kinds) < 2:
            continue
        first = outline.points[0].kind
        other = next(p for p in outline.points if p.kind != first)
        used = ", ".join(f"<{k}>" for k in (CORNER_ROAD, CORNER_LOCAL, CURVE_LOCAL) if k in kinds)
        text = f"{label(obj)}: {name_of(outline)} mixes {used} (the first <{other.kind}> at line {other.line})"
        fix = "; describe one outline with one kind of corner (or curve), a second shape with a second outline"
        if {CORNER_ROAD, CORNER_LOCAL} <= kinds:
            yield outline_corners_mixed.finding(
                text + ": road and local corners shall not be mixed" + fix,
                uid=U.LOCAL_NO_MIXING,
                **at(ctx, obj, other.line),
            )
        yield outline_corners_mixed.finding(
            text + ": they are mutually exclusive" + fix, uid=U.ROAD_LOCAL_EXCLUSIVITY, **at(ctx, obj, other.line)
        )


_MIN_UID = {CORNER_ROAD: U.ROAD_MIN_AMOUNT, CORNER_LOCAL: U.LOCAL_MIN_AMOUNT}


@rule(
    "B011",
    "outline-too-few-corners",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.OUTLINE_FOLLOWED_BY_CORNER, U.ROAD_MIN_AMOUNT, U.LOCAL_MIN_AMOUNT),
)
def outline_too_few_corners(ctx: Context):
    """An ``<outline>`` has fewer than two corners of its kind (or no corner or curve at all).

    An outline shall be followed by two or more ``<cornerRoad>``, two or more ``<cornerLocal>`` or one or more
    ``<curveLocal>`` elements (Annex F ``road.object.outline.outline_followed_by_corner``, 13.2); an outline with
    ``<cornerRoad>`` elements has at least two (``road.corner_road.element_min_amount``), one with ``<cornerLocal>``
    elements too (``road.corner_local.element_min_amount``). A single corner breaks both its kind's rule and the
    outline rule; one finding names each. (An empty outline of a 1.9 file is also ``outline-empty``'s.)

    Passes::

        <outline id="0"><cornerRoad s="10" t="-3" dz="0" height="0.2" id="0"/>
          <cornerRoad s="12" t="-3" dz="0" height="0.2" id="1"/></outline>

    Fails::

        <outline id="0"><cornerRoad s="10" t="-3" dz="0" height="0.2" id="0"/></outline>
    """
    for obj, outline in outlines(ctx):
        counts = {kind: sum(1 for p in outline.points if p.kind == kind) for kind in outline.kinds}
        enough = counts.get(CURVE_LOCAL, 0) >= 1 or any(counts.get(k, 0) >= 2 for k in _MIN_UID)
        where = at(ctx, obj, outline.line)
        for kind, uid in _MIN_UID.items():
            if counts.get(kind, 0) == 1:
                yield outline_too_few_corners.finding(
                    f"{label(obj)}: {name_of(outline)} has one <{kind}>: an outline needs at least two corners",
                    uid=uid,
                    **where,
                )
        if enough:
            continue
        found = ", ".join(f"{n} <{k}>" for k, n in sorted(counts.items())) or "no corner or curve"
        yield outline_too_few_corners.finding(
            f"{label(obj)}: {name_of(outline)} has {found}: an outline is two or more <cornerRoad>, two or more "
            "<cornerLocal> or one or more <curveLocal> elements",
            uid=U.OUTLINE_FOLLOWED_BY_CORNER,
            **where,
        )


def _id(text: str | None) -> str:
    return "no id" if text is None else f'id="{text}"'


_FIRST_UID = {CORNER_ROAD: U.ROAD_FIRST_ID_ZERO, CORNER_LOCAL: U.LOCAL_FIRST_ID_ZERO}
_SEQUENCE_UID = {CORNER_ROAD: U.ROAD_SEQUENTIAL_IDS, CORNER_LOCAL: U.LOCAL_SEQUENTIAL_IDS}


@rule(
    "B012",
    "outline-corner-ids",
    Category.OBJECT,
    Severity.WARNING,
    uids=(*_FIRST_UID.values(), *_SEQUENCE_UID.values()),
)
def outline_corner_ids(ctx: Context):
    """The corner ids of an outline do not count 0, 1, 2, ... in the order the corners are listed.

    Where an outline's ``<cornerRoad>`` or ``<cornerLocal>`` elements have ids, the first should be 0 (Annex F
    ``road.corner_road.first_id_zero``, ``road.corner_local.first_id_zero``) and each next one 1 more
    (``.sequential_id_values``), so that a marking's corner references (13.8) read as positions along the outline.
    Ids are counted per outline (they are unique within one outline, 13.2.1); outlines whose corners have no ids,
    and outlines mixing kinds of corner (``outline-corners-mixed``), are left alone.

    Passes::

        <cornerLocal u="0" v="0" z="0" height="0" id="0"/><cornerLocal u="1" v="0" z="0" height="0" id="1"/>

    Fails::

        <cornerLocal u="0" v="0" z="0" height="0" id="1"/><cornerLocal u="1" v="0" z="0" height="0" id="3"/>
    """
    for obj, outline in outlines(ctx):
        kind = outline.kind
        if kind not in _FIRST_UID or not any(p.xml.given("id") for p in outline.points):
            continue
        points = outline.points
        if points[0].id != 0:
            yield outline_corner_ids.finding(
                f"{label(obj)}: the first <{kind}> of {name_of(outline)} has {_id(id_text(points[0]))}: the ids of an "
                "outline's corners should start at 0",
                uid=_FIRST_UID[kind],
                **at(ctx, obj, points[0].line),
            )
        for before, after in itertools.pairwise(points):
            if before.id is None or after.id != before.id + 1:
                yield outline_corner_ids.finding(
                    f"{label(obj)}: in {name_of(outline)} a <{kind}> with {_id(id_text(after))} follows one with "
                    f"{_id(id_text(before))}: the ids should increase by 1 from corner to corner, in the order they "
                    "are listed",
                    uid=_SEQUENCE_UID[kind],
                    **at(ctx, obj, after.line),
                )
                break


_ID_UID = {CORNER_ROAD: U.ROAD_ID_WITH_MARKINGS, CORNER_LOCAL: U.LOCAL_ID_WITH_MARKINGS}


@rule("B013", "outline-corner-id-missing", Category.OBJECT, Severity.ERROR, uids=tuple(_ID_UID.values()))
def outline_corner_id_missing(ctx: Context):
    """A corner of an outline that has ``<markings>`` has no ``id``.

    Markings on an outline name the corners they run through by id (13.8: ``<cornerReference id=...>``), so the
    ``@id`` of every ``<cornerRoad>`` and ``<cornerLocal>`` of an outline with a ``<markings>`` element is mandatory
    (Annex F ``road.corner_road.mandatory_id_with_markings``, ``road.corner_local.mandatory_id_with_markings``).

    Passes::

        <outline id="0"><cornerLocal u="0" v="0" z="0" height="0" id="0"/>
          <cornerLocal u="2" v="0" z="0" height="0" id="1"/><markings>...</markings></outline>

    Fails::

        <outline id="0"><cornerLocal u="0" v="0" z="0" height="0"/>
          <cornerLocal u="2" v="0" z="0" height="0"/><markings>...</markings></outline>
    """
    for obj, outline in outlines(ctx):
        if outline.markings is None:
            continue
        for kind, uid in _ID_UID.items():
            missing = [p for p in outline.points if p.kind == kind and not p.xml.given("id")]
            if missing:
                yield outline_corner_id_missing.finding(
                    f"{label(obj)}: {len(missing)} <{kind}> of {name_of(outline)} (the first at line "
                    f"{missing[0].line}) have no id, but the outline has <markings>: give every corner an id for the "
                    "markings' corner references",
                    uid=uid,
                    **at(ctx, obj, missing[0].line),
                )


@rule(
    "B014",
    "outline-id-duplicate",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.BORDERS_DIFFERENT_OUTLINE_IDS,),
    every_version=True,
)
def outline_id_duplicate(ctx: Context):
    """Two outlines of one object have the same ``id``.

    An outline's id is unique within its object (13.2), so that a ``<border>``'s ``outlineId`` names one outline
    (Annex F ``road.object.borders.different_outlineids``, 1.9; checked in files of every version, since the id was
    "unique within one object" from the start - the official 1.8.1 and 1.9.0 schemas mean to say so with a key that
    selects nothing, see ``schemas/NOTICE.md``).

    Passes::

        <outlines><outline id="0">...</outline><outline id="1" outer="false">...</outline></outlines>

    Fails::

        <outlines><outline id="0">...</outline><outline id="0" outer="false">...</outline></outlines>
    """
    for obj in ctx.road_objects():
        seen: dict[int, Outline] = {}
        for outline in obj.outlines:
            if outline.id is None:
                continue
            first = seen.setdefault(outline.id, outline)
            if first is not outline:
                yield outline_id_duplicate.finding(
                    f"{label(obj)}: the outline at line {outline.line} has id={outline.id}, as the one at line "
                    f"{first.line}: outline ids are unique within an object; give each outline its own id",
                    **at(ctx, obj, outline.line),
                )


@rule("B015", "border-outline-missing", Category.OBJECT, Severity.ERROR, uids=(ONLY_REF_DEFINED_IDS,))
def border_outline_missing(ctx: Context):
    """A ``<border>`` names an outline its object does not have.

    A border runs along the outline whose id its ``outlineId`` gives (13.9); an id no outline of the object has
    leaves the border nowhere to go: Annex F ``ids.only_ref_defined_ids`` (only defined IDs may be referenced; the
    official 1.8.1 and 1.9.0 schemas mean to say so with a key reference that selects nothing, see
    ``schemas/NOTICE.md``).

    Passes::

        <outlines><outline id="50">...</outline></outlines><borders><border outlineId="50" .../></borders>

    Fails::

        <outlines><outline id="50">...</outline></outlines><borders><border outlineId="5" .../></borders>
    """
    for obj in ctx.road_objects():
        ids = {o.id for o in obj.outlines if o.id is not None}
        for border in obj.borders:
            if border.outline_id is None or border.outline_id in ids:
                continue
            have = ", ".join(str(i) for i in sorted(ids)) or "none with an id"
            yield border_outline_missing.finding(
                f"{label(obj)}: the <border> at line {border.line} runs along outline {border.outline_id}, which the "
                f"object does not have (its outlines: {have})",
                **at(ctx, obj, border.line),
            )


@rule(
    "B016",
    "border-corner-references",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.BORDERS_COMPLETE_OUTLINE, ONLY_REF_DEFINED_IDS),
    basis=Basis.READING,
)
def border_corner_references(ctx: Context):
    """A ``<border>``'s corner references do not match its ``useCompleteOutline``.

    A border along its whole outline (``useCompleteOutline`` true, the default) shall have no ``<cornerReference>``
    (Annex F ``road.object.borders.useCompleteOutline_true``, 13.9); one along part of it (``false``) needs at least
    two (13.9, no UID: without them the border's stretch cannot be read), and each names a corner of the outline
    (``ids.only_ref_defined_ids``).

    Passes::

        <border outlineId="0" type="curb" width="0.1" useCompleteOutline="true"/>

    Fails::

        <border outlineId="0" type="curb" width="0.1" useCompleteOutline="true"><cornerReference id="0"/>
          <cornerReference id="1"/></border>
    """
    for obj in ctx.road_objects():
        by_id = {o.id: o for o in obj.outlines if o.id is not None}
        for border in obj.borders:
            name = f"{label(obj)}: the <border> along outline {border.outline_id}"
            refs = border.references
            if border.use_complete_outline is not False and refs:
                yield border_corner_references.finding(
                    f"{name} runs along the complete outline (useCompleteOutline "
                    f"{'true' if border.use_complete_outline else 'not given: true'}) but has {len(refs)} "
                    '<cornerReference>: remove them, or set useCompleteOutline="false" for a partial border',
                    uid=U.BORDERS_COMPLETE_OUTLINE,
                    **at(ctx, obj, refs[0].line),
                )
            elif border.use_complete_outline is False and len(refs) < 2:
                yield border_corner_references.finding(
                    f'{name} has useCompleteOutline="false" and {len(refs)} <cornerReference>: a partial border '
                    "names at least two corners of its outline",
                    uid=NO_UID,  # 13.9 in words: the border's stretch cannot be read
                    **at(ctx, obj, border.line),
                )
            outline = None if border.outline_id is None else by_id.get(border.outline_id)
            if outline is None or border.use_complete_outline is not False:
                continue
            known = {p.id for p in outline.points if p.id is not None}
            for ref in refs:
                if ref.id is not None and ref.id not in known:
                    yield border_corner_references.finding(
                        f"{name} references corner {ref.id}, which the outline does not have",
                        uid=ONLY_REF_DEFINED_IDS,
                        **at(ctx, obj, ref.line),
                    )


@rule("B017", "outline-outer-count", Category.OBJECT, Severity.ERROR, uids=(U.EXACTLY_ONE_OUTER,))
def outline_outer_count(ctx: Context):
    """An ``<outlines>`` element has no outer outline, or more than one.

    ``<outlines>`` has exactly one ``<outline>`` with ``outer="true"`` (Annex F
    ``road.object.outline.exactly_one_outer``, 13.2): it gives the object's overall shape, the others lie inside it.
    In 1.9 an outline without ``outer`` is an outer one ("Omitting @outer shall default to @outer=true"), so each
    inner outline says ``outer="false"``.


    Passes::

        <outlines><outline id="0" outer="true">...</outline><outline id="1" outer="false">...</outline></outlines>

    Fails (both outlines are outer)::

        <outlines><outline id="0">...</outline><outline id="1">...</outline></outlines>
    """
    for obj in ctx.road_objects():
        wrapped = [o for o in obj.outlines if o.wrapped]
        if obj.outlines_line is None or not wrapped:
            continue
        outer = [o for o in wrapped if o.outer]
        if len(outer) == 1:
            continue
        if outer:
            lines = ", ".join(str(o.line) for o in outer)
            text = f"has {len(outer)} outer outlines (lines {lines}; an outline without @outer is outer)"
            fix = 'mark the inner ones outer="false"'
        else:
            text, fix = "has no outer outline", 'mark the one that gives the overall shape outer="true"'
        yield outline_outer_count.finding(
            f"{label(obj)}: its <outlines> {text}: exactly one outline is the outer one; {fix}",
            **at(ctx, obj, obj.outlines_line),
        )
