"""Repeated objects (``B040``-``B042``): where ``<repeat>`` elements place an object and what they may change about
it (13.4, OpenDRIVE 1.9's rules)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from xodrcheck.findings import Category, Severity
from xodrcheck.model import CORNER_ROAD
from xodrcheck.rules.object_attributes import at, label
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import object_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:
    from xodrcheck.model import Repeat, RoadObject


@rule("B040", "repeat-beyond-road", Category.OBJECT, Severity.ERROR, uids=(U.REPEAT_VALID_S_LENGTH,))
def repeat_beyond_road(ctx: Context):
    """A ``<repeat>`` starts before its road or runs past its end.

    Repeated objects shall have valid ``s`` coordinates and lengths (Annex F ``road.object.repeating.valid_s_length``,
    13.4): the repeat runs from its ``s`` to ``s + length`` along its road, so both lie within ``[0, road length]``
    (within ``length_abs``), and its ``length`` is not negative.

    Passes (a 100 m road)::

        <repeat s="10" length="80" distance="10" tStart="-5" tEnd="-5" zOffsetStart="0" zOffsetEnd="0"/>

    Fails::

        <repeat s="50" length="80" distance="10" tStart="-5" tEnd="-5" zOffsetStart="0" zOffsetEnd="0"/>
    """
    slack = ctx.tolerances.length_abs
    for obj in ctx.road_objects():
        road = ctx.road(obj.road)
        if road is None:
            continue
        for r in obj.repeats:
            end = r.s + r.length
            if r.length < 0:
                why = f"has length {metres(r.length)}: a repeat runs forward from its s"
            elif not -slack <= r.s <= road.length + slack:
                why = f"starts at s={metres(r.s)}, outside road {obj.road} (s=0 to {metres(road.length)})"
            elif end > road.length + slack:
                why = (
                    f"runs from s={metres(r.s)} to {metres(end)}, past the end of road {obj.road} at "
                    f"s={metres(road.length)}"
                )
            else:
                continue
            yield repeat_beyond_road.finding(
                f"{label(obj)}: the <repeat> at line {r.line} {why}; repeat along the road's own s range (continue on "
                "the next road with an object of its own)",
                road=obj.road,
                s=min(max(r.s, 0.0), road.length),
                line=r.line,
            )


_DIMENSIONS: tuple[tuple[str, str, str], ...] = (
    ("length", "lengthStart", "lengthEnd"),
    ("width", "widthStart", "widthEnd"),
    ("height", "heightStart", "heightEnd"),
)


def _changed(obj: RoadObject, repeat: Repeat, tol: float) -> list[str]:
    """The dimensions a repeat changes: ``*Start`` and ``*End`` that differ, or differ from the object's own value."""
    out = []
    for name, start, end in _DIMENSIONS:
        own = getattr(obj, name)
        values = [getattr(repeat, _FIELD[a]) for a in (start, end) if getattr(repeat, _FIELD[a]) is not None]
        reference = own if own is not None else (values[0] if values else None)
        if reference is not None and any(abs(v - reference) > tol for v in values):
            given = ", ".join(
                f"{a}={metres(getattr(repeat, _FIELD[a]))}"
                for a in (start, end)
                if getattr(repeat, _FIELD[a]) is not None
            )
            out.append(f"{given}" + (f" (the object's {name} is {metres(own)})" if own is not None else ""))
    return out


_FIELD = {
    f"{n}{end}": f"{n}_{end.lower()}" for n in ("length", "width", "height", "radius") for end in ("Start", "End")
}


def _given(repeat: Repeat, *names: str) -> tuple[str, ...]:
    """Which of the attributes ``names`` (``widthStart``, ...) the repeat gives with a number."""
    return tuple(name for name in names if getattr(repeat, _FIELD[name]) is not None)


@rule(
    "B041",
    "repeat-size-overridden",
    Category.OBJECT,
    Severity.ERROR,
    uids=(U.REPEAT_SIZE_WITH_SHAPE, U.REPEAT_WIDTH_WITH_RADIUS),
)
def repeat_size_overridden(ctx: Context):
    """A ``<repeat>`` changes a size the object's shape does not let it change.

    ``lengthStart``, ``lengthEnd``, ``widthStart``, ``widthEnd``, ``heightStart`` and ``heightEnd`` do not apply to
    objects with an outline or a skeleton (Annex F ``road.object.repeating.attributes_with_outline_skeleton``, 13.4:
    such objects "may not change their dimensions within or between sections"): since the schemas require
    ``heightStart`` and ``heightEnd`` on every repeat, they may be given, but only with the object's own value (or,
    where the object gives none, one value for both). ``widthStart`` and ``widthEnd`` do not apply to circular objects
    (``radius`` on the object or the repeat, ``.no_widthstart_end_with_radius``): they are not given at all.
    Sizes are compared within ``length_abs``.

    Passes::

        <object id="1" type="pole" ... radius="0.1" height="1"><repeat ... radiusStart="0.1" radiusEnd="0.15"
          heightStart="1" heightEnd="1" .../>

    Fails::

        <object id="1" type="pole" ... radius="0.1" height="1"><repeat ... widthStart="0.2" widthEnd="0.2"
          heightStart="1" heightEnd="1" .../>
    """
    tol = ctx.tolerances.length_abs
    for obj in ctx.road_objects():
        shaped = "an outline" if obj.outlines else "a skeleton" if obj.skeleton is not None else None
        for r in obj.repeats:
            changes = _changed(obj, r, tol) if shaped else []
            if changes:
                yield repeat_size_overridden.finding(
                    f"{label(obj)} has {shaped}, but the <repeat> at line {r.line} changes its size: "
                    f"{'; '.join(changes)}: an object with an outline or skeleton keeps its dimensions",
                    uid=U.REPEAT_SIZE_WITH_SHAPE,
                    **at(ctx, obj, r.line),
                )
            radius = obj.radius is not None or _given(r, "radiusStart", "radiusEnd")
            widths = _given(r, "widthStart", "widthEnd")
            if radius and widths:
                yield repeat_size_overridden.finding(
                    f"{label(obj)} is circular (radius), but the <repeat> at line {r.line} gives {', '.join(widths)}: "
                    "a circular object has no width; use radiusStart and radiusEnd",
                    uid=U.REPEAT_WIDTH_WITH_RADIUS,
                    **at(ctx, obj, r.line),
                )


@rule("B042", "repeat-outline-road-corners", Category.OBJECT, Severity.ERROR, uids=(U.REPEAT_OUTLINE_LOCAL,))
def repeat_outline_road_corners(ctx: Context):
    """A repeated object has an outline of ``<cornerRoad>`` points.

    Repeated objects with an outline shall use ``<cornerLocal>`` (Annex F
    ``road.object.repeating.outline_use_cornerlocal``, 13.4): local corners move with each instance, road corners
    (``s``/``t`` of the road) stay where they are, so every instance would have the first one's outline. (A 1.9
    ``<curveLocal>`` outline is in the same local frame and moves with the instance too.)

    Passes::

        <object ...><repeat .../><outline id="0"><cornerLocal u="-1" v="0" z="0" height="0" id="0"/>...</outline>

    Fails::

        <object ...><repeat .../><outline id="0"><cornerRoad s="10" t="-3" dz="0" height="0" id="0"/>...</outline>
    """
    for obj in ctx.road_objects():
        if not obj.repeats:
            continue
        for outline in obj.outlines:
            road_corner = next((p for p in outline.points if p.kind == CORNER_ROAD), None)
            if road_corner is not None:
                yield repeat_outline_road_corners.finding(
                    f"{label(obj)} is repeated (<repeat> at line {obj.repeats[0].line}), but its outline at line "
                    f"{outline.line} uses <cornerRoad>: road corners stay in place while the object repeats; give "
                    "the outline in <cornerLocal> coordinates",
                    **at(ctx, obj, road_corner.line),
                )
