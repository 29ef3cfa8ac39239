"""Object attributes and lane validity (``B001``-``B009``): what an object, a tunnel, a bridge or an object reference
says about itself (13.1, 13.6, 13.10-13.12).

The objects are the document's (``Road.objects``, ``object_references``, ``tunnels``, ``bridges``: the objects of
roads; a junction's own objects stand on no road's reference line). Every finding names the road, the object's ``s``
(the engine places it) and the line of the element concerned.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

import numpy as np

from xodrcheck.findings import Category, Severity
from xodrcheck.model import TrafficRule
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import object_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:
    from xodrcheck.model import Bridge, LaneValidity, ObjectReference, RoadObject, RoadStructure, Tunnel


def orientation_text(record: RoadObject | ObjectReference) -> str | None:
    """The ``orientation`` as the file wrote it (``None``: absent)."""
    return record.orientation.value if record.orientation is not None else record.xml.text("orientation")


def known_lanes(validities: tuple[LaneValidity, ...]) -> tuple[LaneValidity, ...]:
    """The validities whose ``fromLane`` and ``toLane`` are integers (the schema rule reports the others)."""
    return tuple(v for v in validities if v.from_lane is not None and v.to_lane is not None)


def label(obj: RoadObject) -> str:
    return f"road {obj.road} object {obj.id}"


def at(ctx: Context, obj: RoadObject | ObjectReference, line: int | None = None) -> dict:
    """Finding location fields of an object (or of one of its elements at ``line``): its road, ``s`` and plan-view
    ``x``, ``y`` at its ``s``/``t`` (by the road's reference line; left to the engine, which places ``s`` on the
    reference line, when the object has no ``t`` or the road no plan view)."""
    where: dict = {"road": obj.road, "s": obj.s, "line": line or obj.line}
    if obj.s is not None and obj.t is not None:
        geometry = ctx.geometry(obj.road)
        if geometry is not None and geometry.road.plan_view:
            from xodrcheck.geometry.object_place import road_xy

            x, y, _ = road_xy(geometry, [obj.s], [obj.t])
            if np.isfinite(x[0]) and np.isfinite(y[0]):
                where.update(x=float(x[0]), y=float(y[0]))
    return where


@rule("B001", "object-type-missing", Category.OBJECT, Severity.ERROR, uids=(U.TYPE_ATTR,))
def object_type_missing(ctx: Context):
    """An ``<object>`` has no ``type``.

    The type of an object shall be given by its ``@type`` (Annex F ``road.object.type_attr``, 13.1): it says what the
    object is (a barrier, a pole, a crosswalk ...), and which elements it may have (13.14).

    Passes::

        <object id="1" type="pole" subtype="bollard" s="5" t="-4" zOffset="0" orientation="none" radius="0.1" .../>

    Fails::

        <object id="1" s="5" t="-4" zOffset="0" orientation="none" radius="0.1" height="1"/>
    """
    for obj in ctx.road_objects():
        if not (obj.type or "").strip():
            yield object_type_missing.finding(
                f"{label(obj)} has no type: say what it is with @type (barrier, building, crosswalk, gantry, obstacle, "
                "parkingSpace, pole, roadMark, roadSurface, trafficIsland, tree, vegetation)",
                **at(ctx, obj),
            )


@rule("B002", "object-orientation-missing", Category.OBJECT, Severity.ERROR, uids=(U.ORIENTATION,))
def object_orientation_missing(ctx: Context):
    """An ``<object>`` does not say for which direction of travel it is valid.

    The direction for which an object is valid shall be specified (Annex F ``road.object.orientation``, 13.1):
    ``orientation`` is ``+`` (valid in positive ``s`` direction), ``-`` (negative) or ``none`` (both directions).

    Passes::

        <object id="1" type="pole" s="5" t="-4" zOffset="0" orientation="none" radius="0.1" height="1"/>

    Fails::

        <object id="1" type="pole" s="5" t="-4" zOffset="0" radius="0.1" height="1"/>
    """
    for obj in ctx.road_objects():
        if obj.orientation is not None:
            continue
        written = orientation_text(obj)
        what = "has no orientation" if written is None else f'has orientation="{written}"'
        yield object_orientation_missing.finding(
            f'{label(obj)} {what}: say for which direction of travel it is valid with orientation="+" (along s), '
            '"-" (against s) or "none" (both)',
            **at(ctx, obj),
        )


@rule("B003", "object-off-road", Category.OBJECT, Severity.ERROR, uids=(U.S_T_COORDS,))
def object_off_road(ctx: Context):
    """An object's origin is not a place on its road: ``s`` or ``t`` is missing, or ``s`` lies before the road's start
    or past its end.

    The origin of an object shall be described with ``s`` and ``t`` along the road (Annex F ``road.object.s_t_coords``,
    13.1): ``s`` from 0 to the road's length (within ``length_abs``).

    Passes (a 100 m road)::

        <object id="1" type="pole" s="99.5" t="-4" zOffset="0" orientation="none" radius="0.1" height="1"/>

    Fails::

        <object id="1" type="pole" s="120" t="-4" zOffset="0" orientation="none" radius="0.1" height="1"/>
    """
    slack = ctx.tolerances.length_abs
    for obj in ctx.road_objects():
        road = ctx.road(obj.road)
        if obj.s is None or obj.t is None:
            missing = " and ".join(name for name, value in (("s", obj.s), ("t", obj.t)) if value is None)
            yield object_off_road.finding(
                f"{label(obj)} has no valid {missing}: its origin is given by s and t along road {obj.road}",
                road=obj.road,
                line=obj.line,
            )
        elif road is not None and not -slack <= obj.s <= road.length + slack:
            yield object_off_road.finding(
                f"{label(obj)} stands at s={metres(obj.s)}, but road {obj.road} runs from s=0 to "
                f"{metres(road.length)}: place it on the road it belongs to (or on the road it stands beside)",
                road=obj.road,
                s=min(max(obj.s, 0.0), road.length),
                line=obj.line,
            )


@rule("B004", "object-shape-ambiguous", Category.OBJECT, Severity.ERROR, uids=(U.CIRCULAR_VS_ANGULAR,))
def object_shape_ambiguous(ctx: Context):
    """An object's bounding volume is both circular and angular, or only half of an angular one.

    Objects are circular (``radius``) or angular (``length`` and ``width``); the two are mutually exclusive and the
    attributes used define the shape (Annex F ``road.object.circular_vs_angular``, 13.1). An object with ``radius``
    and ``length`` or ``width`` has two bounding volumes; one with only one of ``length`` and ``width`` has none.

    Passes::

        <object id="1" type="pole" s="5" t="-4" zOffset="0" orientation="none" radius="0.1" height="1"/>

    Fails::

        <object id="1" type="pole" s="5" t="-4" zOffset="0" orientation="none" radius="0.1" length="0.2" height="1"/>
    """
    for obj in ctx.road_objects():
        given = [name for name in ("radius", "length", "width") if obj.xml.given(name)]
        if "radius" in given and len(given) > 1:
            why = (
                f"gives radius and {' and '.join(given[1:])}: it is circular or angular, not both; keep radius for a "
                "cylinder, or length and width for a box"
            )
        elif given in (["length"], ["width"]):
            why = f"gives {given[0]} without {'width' if given[0] == 'length' else 'length'}: a box needs both"
        else:
            continue
        yield object_shape_ambiguous.finding(f"{label(obj)} {why}", **at(ctx, obj))


_FROM_TO = {"object": U.VALIDITY_FROM_TO, "objectReference": U.REFERENCE_FROM_TO}
_FROM_TO.update({"tunnel": U.TUNNELS_FROM_TO, "bridge": U.BRIDGES_FROM_TO})


def _validities(ctx: Context) -> Iterator[tuple[str, str, str | None, float | None, LaneValidity]]:
    """(element name, road, id, s, validity) of every ``<validity>`` with integer lanes of objects, references,
    tunnels and bridges."""
    for road in ctx.document.roads:
        for obj in road.objects:
            for v in known_lanes(obj.validities):
                yield "object", obj.road, obj.id, obj.s, v
        for ref in road.object_references:
            for v in known_lanes(ref.validities):
                yield "objectReference", ref.road, ref.id, ref.s, v
        for kind, structure in _road_structures(road.tunnels, road.bridges):
            for v in known_lanes(structure.validities):
                yield kind, structure.road, structure.id, structure.s, v


@rule("B005", "validity-lanes-reversed", Category.OBJECT, Severity.ERROR, uids=tuple(_FROM_TO.values()))
def validity_lanes_reversed(ctx: Context):
    """A ``<validity>`` of an object, object reference, tunnel or bridge has ``fromLane`` greater than ``toLane``.

    ``fromLane`` is the lowest lane id the element is valid for, ``toLane`` the highest (13.6): ``fromLane`` shall be
    lower than or equal to ``toLane`` (Annex F ``road.object.validty.from_lower_equal_to`` for objects,
    ``.reference.from_lower_equal_to``, ``.tunnels.from_lower_equal_to``, ``.bridges.from_lower_equal_to``).

    Passes::

        <validity fromLane="-2" toLane="-1"/>

    Fails::

        <validity fromLane="-1" toLane="-2"/>
    """
    for kind, road, element_id, s, v in _validities(ctx):
        if v.from_lane is not None and v.to_lane is not None and v.from_lane > v.to_lane:
            yield validity_lanes_reversed.finding(
                f"road {road} {kind} {element_id}: <validity> has fromLane={v.from_lane} greater than "
                f"toLane={v.to_lane}: fromLane is the lowest lane id, toLane the highest; swap them",
                uid=_FROM_TO[kind],
                road=road,
                s=s,
                line=v.line,
            )


def _sides(validities: tuple[LaneValidity, ...]) -> set[int]:
    """The signs (+1, -1) of the lane ids the validities span (lane 0, the centre lane, has no side)."""
    out = set()
    for v in validities:
        if v.from_lane is None or v.to_lane is None:
            continue
        lo, hi = min(v.from_lane, v.to_lane), max(v.from_lane, v.to_lane)
        if lo < 0:
            out.add(-1)
        if hi > 0:
            out.add(+1)
    return out


def _oriented(ctx: Context) -> Iterator[tuple[str, RoadObject | ObjectReference]]:
    """(element name, record) of the objects and object references of the document's roads."""
    for road in ctx.document.roads:
        yield from (("object", obj) for obj in road.objects)
        yield from (("objectReference", ref) for ref in road.object_references)


@rule(
    "B006",
    "validity-against-orientation",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.VALIDITY_PARENT_ORIENTATION, U.VALIDITY_RHT, U.VALIDITY_LHT),
)
def validity_against_orientation(ctx: Context):
    """An object's (or object reference's) validity lanes carry another direction of travel than its orientation.

    Lanes of both directions need ``orientation="none"``.

    The lanes of all ``<validity>`` elements shall lie within the parent's ``orientation`` (Annex F
    ``road.object.validty.check_parent_orientation``, 13.6). In right-hand traffic (the road's ``rule``, default RHT),
    ``orientation="+"`` (valid along ``s``) allows only negative lane ids, ``"-"`` only positive ones
    (``.right_hand_traffic_lane_ids``); in left-hand traffic the other way round (``.left_hand_traffic_lane_ids``);
    validities spanning both sides need ``orientation="none"``. The centre lane 0 counts for neither side. A lane on
    the wrong side breaks both the parent-orientation rule and the rule of the road's traffic; one finding names each.

    Passes (right-hand traffic)::

        <object id="1" type="roadMark" orientation="+" ...><validity fromLane="-2" toLane="-1"/></object>

    Fails::

        <object id="1" type="roadMark" orientation="+" ...><validity fromLane="1" toLane="1"/></object>
    """
    for kind, parent in _oriented(ctx):
        validities = known_lanes(parent.validities)
        if not validities:
            continue
        road = ctx.road(parent.road)
        lht = road is not None and road.rule is TrafficRule.LHT
        traffic_uid, traffic = (U.VALIDITY_LHT, "left-hand") if lht else (U.VALIDITY_RHT, "right-hand")
        name = f"road {parent.road} {kind} {parent.id}"
        where = at(ctx, parent)
        sides = _sides(validities)
        written = orientation_text(parent)
        if written in ("+", "-"):
            allowed = (-1 if written == "+" else +1) * (-1 if lht else 1)
            wrong = sides - {allowed}
            if not wrong:
                continue
            lanes = "positive" if allowed < 0 else "negative"
            text = (
                f'{name} has orientation="{written}", but its <validity> spans {lanes} lane ids, which '
                f"in {traffic} traffic carry the other direction"
            )
            fix = f'; use orientation="none" or only {"negative" if allowed < 0 else "positive"} lane ids'
            yield validity_against_orientation.finding(
                text + ": the lanes shall lie within the orientation" + fix, uid=U.VALIDITY_PARENT_ORIENTATION, **where
            )
            yield validity_against_orientation.finding(text + fix, uid=traffic_uid, **where)
        elif sides == {-1, +1} and written != "none":
            what = "no orientation" if written is None else f'orientation="{written}"'
            yield validity_against_orientation.finding(
                f'{name} has {what}, but its <validity> spans lanes of both sides: use orientation="none"',
                uid=traffic_uid,
                **where,
            )


_TYPE_UID = {"tunnel": U.TUNNELS_TYPE, "bridge": U.BRIDGES_TYPE}
_TYPES = {"tunnel": "standard or underpass", "bridge": "concrete, steel, brick or wood"}


def _road_structures(tunnels: tuple[Tunnel, ...], bridges: tuple[Bridge, ...]) -> Iterator[tuple[str, RoadStructure]]:
    """(element name, record) of a road's tunnels and bridges."""
    yield from (("tunnel", t) for t in tunnels)
    yield from (("bridge", b) for b in bridges)


def _structures(ctx: Context) -> Iterator[tuple[str, RoadStructure]]:
    for road in ctx.document.roads:
        yield from _road_structures(road.tunnels, road.bridges)


@rule("B007", "structure-type-missing", Category.OBJECT, Severity.ERROR, uids=tuple(_TYPE_UID.values()))
def structure_type_missing(ctx: Context):
    """A ``<tunnel>`` or ``<bridge>`` has no ``type``.

    The type of a tunnel (13.11: ``standard``, ``underpass``) and of a bridge (13.12: ``concrete``, ``steel``,
    ``brick``, ``wood``) shall be specified (Annex F ``road.object.tunnels.type_definition``,
    ``.bridges.type_definition``).

    Passes::

        <bridge id="b1" s="20" length="30" type="concrete"/>

    Fails::

        <bridge id="b1" s="20" length="30"/>
    """
    for kind, structure in _structures(ctx):
        if (structure.type or "").strip():
            continue
        yield structure_type_missing.finding(
            f"road {structure.road} {kind} {structure.id} has no type: give it one ({_TYPES[kind]})",
            uid=_TYPE_UID[kind],
            road=structure.road,
            s=structure.s,
            line=structure.line,
        )
