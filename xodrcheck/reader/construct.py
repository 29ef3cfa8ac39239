"""Fast constructors for the model's frozen, slotted dataclasses.

A frozen dataclass's generated ``__init__`` sets each field through ``object.__setattr__`` looked up by name; on a
map of tens of thousands of records that is close to half of the reader's time. :func:`constructor` makes a function
with the same signature (same parameters, same defaults) that fills a record of an unfrozen twin class instead (same
``__slots__``, so the same memory layout, and plain attribute stores, which the interpreter specialises for slots),
then turns it into the frozen class by assigning ``__class__``, which Python allows between classes of the same
layout. A Cubic takes ~200 ns so, ~400 ns through the slots' descriptors' ``__set__``, ~1.3 us through the class.
It builds values equal to the class's own constructor, of the class itself; ``tests/xodrcheck/test_reader.py`` checks
that for every class the reader builds this way.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from typing import TypeVar, cast

from xodrcheck import model
from xodrcheck.classcache import compiled

T = TypeVar("T")


def constructor(cls: type[T]) -> Callable[..., T]:
    """A constructor of ``cls`` (a frozen dataclass with ``slots=True`` and no ``__post_init__``)."""
    if not dataclasses.is_dataclass(cls) or "__slots__" not in cls.__dict__ or hasattr(cls, "__post_init__"):
        raise TypeError(f"{cls.__name__} is not a slotted dataclass without __post_init__")
    fields = dataclasses.fields(cls)
    if any(not f.init for f in fields):
        raise TypeError(f"{cls.__name__} has a field outside __init__")
    twin = type(f"Unfrozen{cls.__name__}", (), {"__slots__": cls.__dict__["__slots__"], "__module__": __name__})
    namespace: dict[str, object] = {"_new": object.__new__, "_twin": twin, "_cls": cls}
    params = []
    for f in fields:
        if f.default is not dataclasses.MISSING:
            namespace[f"_default_{f.name}"] = f.default
            params.append(f"{f.name}=_default_{f.name}")
        elif f.default_factory is not dataclasses.MISSING:
            raise TypeError(f"{cls.__name__}.{f.name} has a default factory")
        else:
            params.append(f.name)
    body = "".join(f"    obj.{f.name} = {f.name}\n" for f in fields)
    source = f"def make({', '.join(params)}):\n    obj = _new(_twin)\n{body}    obj.__class__ = _cls\n    return obj\n"
    exec(compiled(source, __name__), namespace)  # the byte code from the dataclasses' cache (classcache)
    make = cast("Callable[..., T]", namespace["make"])  # the function exec just defined
    make.__name__ = make.__qualname__ = cls.__name__
    make.__doc__ = f"Build a {cls.__name__} (same parameters as the class)."
    return make


make_cubic = constructor(model.Cubic)
make_line = constructor(model.Line)
make_arc = constructor(model.Arc)
make_spiral = constructor(model.Spiral)
make_poly3 = constructor(model.Poly3)
make_param_poly3 = constructor(model.ParamPoly3)
make_road_link = constructor(model.RoadLink)
make_road = constructor(model.Road)
make_road_mark = constructor(model.RoadMark)
make_speed = constructor(model.Speed)
make_lane_height = constructor(model.LaneHeight)
make_lane = constructor(model.Lane)
make_lane_section = constructor(model.LaneSection)
make_lane_link = constructor(model.JunctionLaneLink)
make_connection = constructor(model.Connection)

#: model class -> its fast constructor (what the tests compare against the class itself).
CONSTRUCTORS = {
    model.Cubic: make_cubic,
    model.Line: make_line,
    model.Arc: make_arc,
    model.Spiral: make_spiral,
    model.Poly3: make_poly3,
    model.ParamPoly3: make_param_poly3,
    model.RoadLink: make_road_link,
    model.Road: make_road,
    model.RoadMark: make_road_mark,
    model.Speed: make_speed,
    model.LaneHeight: make_lane_height,
    model.Lane: make_lane,
    model.LaneSection: make_lane_section,
    model.JunctionLaneLink: make_lane_link,
    model.Connection: make_connection,
}
