"""Road objects (chapter 13) as plain, frozen, typed data, built from the file's XML once per file.

* :mod:`.model`: the dataclasses - objects with their outlines (``<cornerRoad>``, ``<cornerLocal>``, 1.9's
  ``<curveLocal>``), skeletons (polylines of vertices), markings (with corner references), borders, repeats,
  materials, lane validity, surfaces (CRG); object references, tunnels and bridges;
* :mod:`.read`: the reader (:func:`read_road_objects`, :func:`read_objects`); a rule gets its result from
  :attr:`xodrcheck.rules.context.Context.road_objects` / ``.objects``, built once per file;
* :mod:`.shape`: outlines in the object's local ``u``/``v`` frame (``<curveLocal>`` curves evaluated by the plan-view
  evaluators) and repeat ``t``;
* :mod:`.place`: where an object is - road ``s``/``t`` to inertial ``x``/``y`` by the road's exact reference line
  (:meth:`xodrcheck.rules.context.Context.geometry`), the object's local frame, its bounding volume, its repeated
  instances.

Unparsable values are ``None`` (S001 reports them); nothing here reports findings.

The package names its submodules' public names lazily (as :mod:`xodrcheck` does): a rule module may import
:mod:`.kinds` at its top, and the dataclasses load when a file has objects (``Context.road_objects``) or a name is
first used.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from xodrcheck.objects.model import (
        Border,
        CornerLocal,
        CornerReference,
        CornerRoad,
        CurveLocal,
        CurveShape,
        LaneValidity,
        Marking,
        Markings,
        Material,
        ObjectCrg,
        ObjectReference,
        Outline,
        OutlinePoint,
        Polyline,
        Repeat,
        RoadObject,
        RoadObjects,
        Skeleton,
        Structure,
        Surface,
        Vertex,
    )
    from xodrcheck.objects.read import read_objects, read_road_objects
    from xodrcheck.objects.shape import curve_end, curve_points, outline_uv, repeat_t

#: Public name -> the submodule that defines it.
_EXPORTS = {
    "Border": "xodrcheck.objects.model",
    "CornerLocal": "xodrcheck.objects.model",
    "CornerReference": "xodrcheck.objects.model",
    "CornerRoad": "xodrcheck.objects.model",
    "CurveLocal": "xodrcheck.objects.model",
    "CurveShape": "xodrcheck.objects.model",
    "LaneValidity": "xodrcheck.objects.model",
    "Marking": "xodrcheck.objects.model",
    "Markings": "xodrcheck.objects.model",
    "Material": "xodrcheck.objects.model",
    "ObjectCrg": "xodrcheck.objects.model",
    "ObjectReference": "xodrcheck.objects.model",
    "Outline": "xodrcheck.objects.model",
    "OutlinePoint": "xodrcheck.objects.model",
    "Polyline": "xodrcheck.objects.model",
    "Repeat": "xodrcheck.objects.model",
    "RoadObject": "xodrcheck.objects.model",
    "RoadObjects": "xodrcheck.objects.model",
    "Skeleton": "xodrcheck.objects.model",
    "Structure": "xodrcheck.objects.model",
    "Surface": "xodrcheck.objects.model",
    "Vertex": "xodrcheck.objects.model",
    "curve_end": "xodrcheck.objects.shape",
    "curve_points": "xodrcheck.objects.shape",
    "outline_uv": "xodrcheck.objects.shape",
    "read_objects": "xodrcheck.objects.read",
    "read_road_objects": "xodrcheck.objects.read",
    "repeat_t": "xodrcheck.objects.shape",
}

__all__ = [
    "Border",
    "CornerLocal",
    "CornerReference",
    "CornerRoad",
    "CurveLocal",
    "CurveShape",
    "LaneValidity",
    "Marking",
    "Markings",
    "Material",
    "ObjectCrg",
    "ObjectReference",
    "Outline",
    "OutlinePoint",
    "Polyline",
    "Repeat",
    "RoadObject",
    "RoadObjects",
    "Skeleton",
    "Structure",
    "Surface",
    "Vertex",
    "curve_end",
    "curve_points",
    "outline_uv",
    "read_objects",
    "read_road_objects",
    "repeat_t",
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
