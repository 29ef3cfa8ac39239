"""Road records the model does not read (road types, lateral shapes), built from the file's XML once per check.

Plain frozen records with their source line; a value that is missing or not a finite number is ``None`` (the schema
rule reports it). Cached per :class:`~xodrcheck.rules.context.Context`, so every rule that asks shares one pass over
the tree.
"""

from __future__ import annotations

from dataclasses import dataclass

from xodrcheck.rules.context import Context
from xodrcheck.xmlvalues import number


@dataclass(frozen=True, slots=True)
class RoadType:
    """A road's ``<type>``: where it starts, the type, the country code and the speed limit (``max``, ``unit``)."""

    road: str
    s: float | None
    type: str | None
    country: str | None
    speed: tuple[str | None, str | None] | None
    line: int


@dataclass(frozen=True, slots=True)
class Shape:
    """A ``<shape>`` of a road's lateral profile: ``h(dt) = a + b dt + c dt^2 + d dt^3`` from ``t`` on, at ``s``."""

    road: str
    s: float | None
    t: float | None
    a: float | None
    b: float | None
    c: float | None
    d: float | None
    line: int


@dataclass(frozen=True, slots=True)
class RoadRecords:
    """A road's extra records, in file order."""

    road: str
    line: int
    types: tuple[RoadType, ...]
    shapes: tuple[Shape, ...]


def road_records(ctx: Context) -> tuple[RoadRecords, ...]:
    """Every ``<road>``'s types and shapes (roads without an id are left out; the reader reports them)."""
    return ctx.xml_view("road_records", lambda: tuple(_build(ctx)))


def _build(ctx: Context):
    tree = ctx.tree
    if tree is None:
        return
    for road in tree.getroot().iterchildren("{*}road"):
        road_id = road.get("id")
        if road_id is None:
            continue
        types = []
        for el in road.iterchildren("{*}type"):
            speed = next(el.iterchildren("{*}speed"), None)
            types.append(
                RoadType(
                    road_id,
                    number(el.get("s")),
                    el.get("type"),
                    el.get("country"),
                    None if speed is None else (speed.get("max"), speed.get("unit")),
                    el.sourceline or 0,
                )
            )
        shapes = []
        for profile in road.iterchildren("{*}lateralProfile"):
            for el in profile.iterchildren("{*}shape"):
                s, t, a, b, c, d = (number(el.get(name)) for name in ("s", "t", "a", "b", "c", "d"))
                shapes.append(Shape(road_id, s, t, a, b, c, d, el.sourceline or 0))
        yield RoadRecords(road_id, road.sourceline or 0, tuple(types), tuple(shapes))
