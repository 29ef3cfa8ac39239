"""Road objects (chapter 13): objects with their outlines, skeletons, markings, borders, repeats, materials, surfaces
and lane validities; object references, tunnels and bridges.

Read as the file gives them: a number or enumerated value that is absent or not of its type is ``None``
(:attr:`XmlFacts.invalid <xodrcheck.model.facts.XmlFacts>` keeps its text; the schema rule reports it). An object
without ``id`` is left out (nothing can refer to it). Outline corners and curves whose numbers do not parse are left
out of ``corners`` and ``curves`` but listed in :attr:`Outline.points`, which keeps every point element in file order.
"""

from __future__ import annotations

from dataclasses import dataclass

from xodrcheck.model.enums import VERTEX_LOCAL, LaneLayer, Orientation
from xodrcheck.model.facts import XmlFacts, facts_field
from xodrcheck.model.planview import Arc, Cubic, Line, ParamPoly3

__all__ = [
    "Bridge",
    "CornerLocal",
    "CornerReference",
    "CornerRoad",
    "CurveLocal",
    "CurveShape",
    "LaneValidity",
    "Marking",
    "Markings",
    "ObjectBorder",
    "ObjectCrg",
    "ObjectMaterial",
    "ObjectReference",
    "ObjectSurface",
    "Outline",
    "OutlinePoint",
    "ParkingSpace",
    "Polyline",
    "Repeat",
    "RoadObject",
    "RoadStructure",
    "Skeleton",
    "Tunnel",
    "Vertex",
]

#: The shapes a ``<curveLocal>`` may have, as plan-view elements starting at ``s = 0``.
CurveShape = Line | Arc | ParamPoly3


@dataclass(frozen=True, slots=True)
class LaneValidity:
    """The lanes an object, signal or reference applies to (``<validity>``: ``fromLane`` to ``toLane``; ``None``
    when not an integer), on ``layer`` (1.9; the permanent layer for older files)."""

    from_lane: int | None
    to_lane: int | None
    layer: LaneLayer = LaneLayer.PERMANENT
    line: int = 0
    xml: XmlFacts = facts_field()


# ------------------------------------------------------------------------------------------------------ outlines
@dataclass(frozen=True, slots=True)
class CornerRoad:
    """An outline corner in road coordinates (``<cornerRoad>``: s, t, dz, height)."""

    s: float
    t: float
    dz: float
    height: float
    id: int | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class CornerLocal:
    """An outline corner in the object's local coordinates (``<cornerLocal>``: u, v, z, height)."""

    u: float
    v: float
    z: float
    height: float
    id: int | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class CurveLocal:
    """A ``<curveLocal>`` (1.9): ``shape`` starts at (``u``, ``v``) with heading ``hdg``; ``None`` when its shape
    element is missing or does not parse. ``length`` ``None``: the file gave none (the curve "shall extend up to the
    next <curveLocal>")."""

    u: float
    v: float
    z: float
    height: float
    hdg: float
    length: float | None
    shape: CurveShape | None
    id: int | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class OutlinePoint:
    """One ``<cornerRoad>``, ``<cornerLocal>`` or ``<curveLocal>`` of an outline, whether its numbers parse or not:
    ``kind`` is the element name, ``id`` its ``@id`` as an integer (``None``: absent or not an integer; ``xml``
    tells which)."""

    kind: str
    id: int | None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class CornerReference:
    """A ``<cornerReference>`` of a marking or border: the ``@id`` of an outline point (``None``: absent or not an
    integer)."""

    id: int | None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Marking:
    """A ``<marking>`` (13.8): along a side of the bounding volume (``side``) or through outline points
    (``references``)."""

    color: str | None
    side: str | None = None
    width: float | None = None
    z_offset: float | None = None
    space_length: float | None = None
    line_length: float | None = None
    start_offset: float | None = None
    stop_offset: float | None = None
    weight: str | None = None
    references: tuple[CornerReference, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Markings:
    """A ``<markings>`` element: in an ``<object>`` or in one of its ``<outline>`` elements."""

    markings: tuple[Marking, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Outline:
    """An object's outline (``<outline>``): its corners or curves, closed or open, outer or inner. ``outer``
    defaults to true in 1.9 files only (13.2: "Omitting @outer shall default to @outer=true"); before 1.9 the
    standard gave no default and an absent one is ``None``."""

    id: int | None = None
    outer: bool | None = None
    closed: bool | None = None
    fill_type: str | None = None
    lane_type: str | None = None
    corners: tuple[CornerRoad | CornerLocal, ...] = ()
    curves: tuple[CurveLocal, ...] = ()
    line: int = 0
    #: Every corner and curve element in file order (see :class:`OutlinePoint`).
    points: tuple[OutlinePoint, ...] = ()
    #: The outline's own ``<markings>`` (13.2.4), ``None`` without.
    markings: Markings | None = None
    #: Whether the outline sits in an ``<outlines>`` element (1.5 on) rather than directly in the ``<object>`` (1.4).
    wrapped: bool = False
    xml: XmlFacts = facts_field()

    @property
    def kinds(self) -> frozenset[str]:
        """The element names of the outline's points (``cornerRoad``, ``cornerLocal``, ``curveLocal``)."""
        return frozenset(p.kind for p in self.points)

    @property
    def kind(self) -> str | None:
        """The one kind of point the outline uses; ``None`` when it has none or mixes kinds."""
        kinds = self.kinds
        return next(iter(kinds)) if len(kinds) == 1 else None


# ------------------------------------------------------------------------------------------------------ other parts
@dataclass(frozen=True, slots=True)
class Repeat:
    """An object repeated along the road (``<repeat>``): from s over a length at a distance (a repeat without its
    five required numbers is left out)."""

    s: float
    length: float
    distance: float
    t_start: float
    t_end: float
    bt: float | None = None
    ct: float | None = None
    dt: float | None = None
    line: int = 0
    z_offset_start: float | None = None
    z_offset_end: float | None = None
    length_start: float | None = None
    length_end: float | None = None
    width_start: float | None = None
    width_end: float | None = None
    height_start: float | None = None
    height_end: float | None = None
    radius_start: float | None = None
    radius_end: float | None = None
    detach: bool | None = None
    xml: XmlFacts = facts_field()

    @property
    def t_profile(self) -> Cubic:
        """``t`` along the repeat as one cubic record starting at ``s``: ``tStart + bT ds + cT ds^2 + dT ds^3`` when
        any of ``bT``, ``cT``, ``dT`` is given (1.9), else linear from ``tStart`` to ``tEnd`` (13.4)."""
        if self.bt is None and self.ct is None and self.dt is None:
            slope = (self.t_end - self.t_start) / self.length if self.length > 0 else 0.0
            return Cubic(self.s, self.t_start, slope, 0.0, 0.0, self.line)
        return Cubic(self.s, self.t_start, self.bt or 0.0, self.ct or 0.0, self.dt or 0.0, self.line)


@dataclass(frozen=True, slots=True)
class Vertex:
    """A ``<vertexRoad>`` (``kind`` ``vertexRoad``: ``a``, ``b``, ``c`` are ``s``, ``t``, ``dz``) or a ``<vertexLocal>``
    (``u``, ``v``, ``z``) of a skeleton polyline (13.3); ``width`` and ``length`` as the standard's examples write
    them (the XSD knows only ``radius``)."""

    kind: str
    a: float | None
    b: float | None
    c: float | None
    radius: float | None = None
    width: float | None = None
    length: float | None = None
    id: int | None = None
    intersection_point: bool | None = None
    line: int = 0
    xml: XmlFacts = facts_field()

    @property
    def local(self) -> bool:
        return self.kind == VERTEX_LOCAL


@dataclass(frozen=True, slots=True)
class Polyline:
    """A polyline of an object's skeleton (``<polyline>``) and its vertices."""

    id: int | None = None
    vertices: tuple[Vertex, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Skeleton:
    """An object's skeleton (``<skeleton>``): its polylines."""

    polylines: tuple[Polyline, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class ObjectBorder:
    """A ``<border>`` of an object's ``<borders>`` (13.9): a frame of ``width`` along the outline ``outline_id``,
    along all of it or along the outline points named by ``references``. ``use_complete_outline`` is ``None`` when the
    attribute is absent (the standard's default is true)."""

    outline_id: int | None
    type: str | None = None
    width: float | None = None
    use_complete_outline: bool | None = None
    references: tuple[CornerReference, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class ObjectMaterial:
    """An object's ``<material>``: surface, friction and roughness."""

    surface: str | None = None
    friction: float | None = None
    roughness: float | None = None
    road_mark_color: str | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class ObjectCrg:
    """A ``<CRG>`` of an object's ``<surface>`` (13.13)."""

    file: str | None
    hide_road_surface_crg: bool | None = None
    z_scale: float | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class ObjectSurface:
    """An object's ``<surface>``: its CRG records."""

    crgs: tuple[ObjectCrg, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class ParkingSpace:
    """An object's ``<parkingSpace>``: who may park there and what is restricted."""

    access: str | None = None
    restrictions: str | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


# ------------------------------------------------------------------------------------------------------ objects
@dataclass(frozen=True, slots=True)
class RoadObject:
    """A road object (``<object>``): where it stands, its size and shape, outlines, repeats, validity. ``road`` is
    the id of the road it lies on (for an object of a junction, the junction's id)."""

    road: str
    id: str
    type: str | None
    s: float | None
    t: float | None
    z_offset: float | None
    hdg: float | None = None
    length: float | None = None
    width: float | None = None
    radius: float | None = None
    height: float | None = None
    invalidated: bool | None = None  # 1.9
    temporary: bool | None = None  # 1.9
    outlines: tuple[Outline, ...] = ()
    repeats: tuple[Repeat, ...] = ()
    validities: tuple[LaneValidity, ...] = ()
    line: int = 0
    orientation: Orientation | None = None
    subtype: str | None = None
    name: str | None = None
    pitch: float | None = None
    roll: float | None = None
    perp_to_road: bool | None = None
    valid_length: float | None = None
    #: Line of the (first) ``<outlines>`` element (``None``: the object has none).
    outlines_line: int | None = None
    skeleton: Skeleton | None = None
    #: The object's own ``<markings>`` elements (the schema allows one), not those of its outlines.
    markings: tuple[Markings, ...] = ()
    borders: tuple[ObjectBorder, ...] = ()
    materials: tuple[ObjectMaterial, ...] = ()
    surfaces: tuple[ObjectSurface, ...] = ()
    dynamic: bool | None = None  # up to 1.7
    parking_space: ParkingSpace | None = None
    xml: XmlFacts = facts_field()

    def outline_markings(self) -> tuple[tuple[Outline, Markings], ...]:
        """The ``<markings>`` of the object's outlines, each with its outline."""
        return tuple((o, o.markings) for o in self.outlines if o.markings is not None)

    def all_markings(self) -> tuple[tuple[Outline | None, Marking], ...]:
        """Every ``<marking>`` of the object with the outline it sits in (``None``: in the object's ``<markings>``)."""
        own = tuple((None, m) for group in self.markings for m in group.markings)
        return own + tuple((o, m) for o, group in self.outline_markings() for m in group.markings)


@dataclass(frozen=True, slots=True)
class ObjectReference:
    """An ``<objectReference>`` (13.10): the object ``id`` of another road, placed on this one."""

    road: str
    id: str | None
    s: float | None
    t: float | None
    z_offset: float | None = None
    valid_length: float | None = None
    orientation: Orientation | None = None
    validities: tuple[LaneValidity, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class RoadStructure:
    """What a tunnel and a bridge both are (13.11, 13.12): a structure of road ``road`` from ``s`` over ``length``,
    its ``type`` as the file spells it, for the lanes of its validities."""

    road: str
    id: str | None
    s: float | None
    length: float | None
    type: str | None = None
    name: str | None = None
    validities: tuple[LaneValidity, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Tunnel(RoadStructure):
    """A ``<tunnel>`` (13.11) with its degree of artificial ``lighting`` and of ``daylight`` inside, each 0 to 1."""

    lighting: float | None = None
    daylight: float | None = None


@dataclass(frozen=True, slots=True)
class Bridge(RoadStructure):
    """A ``<bridge>`` (13.12)."""
