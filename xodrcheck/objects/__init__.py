"""Where the document's road objects (:mod:`xodrcheck.model.objects`) are and what shape they have.

* :mod:`.shape`: outlines in the object's local ``u``/``v`` frame (``<curveLocal>`` curves evaluated by the plan-view
  evaluators) and repeat ``t``;
* :mod:`.place`: road ``s``/``t`` to inertial ``x``/``y`` by the road's exact reference line, the object's local
  frame, its bounding volume, its repeated instances.

The reader builds the objects; the object rules ask these helpers where they lie. The names load with their module
on first use, so that a file without objects loads neither.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from xodrcheck.objects.place import Frame, Instance, Volume, frame_of, instances, road_xy, volume_of
    from xodrcheck.objects.shape import curve_end, curve_points, outline_uv, repeat_t

#: Public name -> the submodule that defines it.
_EXPORTS = {
    "Frame": "xodrcheck.objects.place",
    "Instance": "xodrcheck.objects.place",
    "Volume": "xodrcheck.objects.place",
    "curve_end": "xodrcheck.objects.shape",
    "curve_points": "xodrcheck.objects.shape",
    "frame_of": "xodrcheck.objects.place",
    "instances": "xodrcheck.objects.place",
    "outline_uv": "xodrcheck.objects.shape",
    "repeat_t": "xodrcheck.objects.shape",
    "road_xy": "xodrcheck.objects.place",
    "volume_of": "xodrcheck.objects.place",
}

__all__ = [
    "Frame",
    "Instance",
    "Volume",
    "curve_end",
    "curve_points",
    "frame_of",
    "instances",
    "outline_uv",
    "repeat_t",
    "road_xy",
    "volume_of",
]


def __getattr__(name: str) -> Any:
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_EXPORTS))
