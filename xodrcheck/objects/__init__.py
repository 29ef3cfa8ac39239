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
"""

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
