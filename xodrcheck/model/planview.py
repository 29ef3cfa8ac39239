"""Piecewise cubic profiles and the plan view's geometry elements (one small class per element kind).

``s`` of a record inside a lane section (width, border, height...) is the standard's ``sOffset``: relative to the lane
section's start; ``s`` of a road-level record (geometry, elevation, superelevation, laneOffset) is absolute. A
``<geometry>`` and its shape child make one record: ``line`` and ``xml`` are the ``<geometry>``'s (its
``xml.children`` name the shape).
"""

from __future__ import annotations

from dataclasses import dataclass

from xodrcheck.model.enums import PRange
from xodrcheck.model.facts import XmlFacts, facts_field

__all__ = ["Arc", "Cubic", "Geometry", "Line", "ParamPoly3", "PlanViewElement", "Poly3", "Profile", "Spiral"]


@dataclass(frozen=True, slots=True)
class Cubic:
    """One record of a piecewise cubic profile: ``f(s) = a + b ds + c ds^2 + d ds^3`` with ``ds = s - self.s``.

    ``s`` is the record's start (absolute for road-level profiles, ``sOffset`` for lane records). One type for
    ``<width>``, ``<border>``, ``<laneOffset>``, ``<elevation>`` and ``<superelevation>``.
    """

    s: float
    a: float
    b: float
    c: float
    d: float
    line: int = 0
    xml: XmlFacts = facts_field()


#: A piecewise cubic profile: records sorted by ``s`` as the file gave them (the reader reports unsorted ones).
Profile = tuple[Cubic, ...]


@dataclass(frozen=True, slots=True)
class PlanViewElement:
    """What every element of the plan view has, the ``<geometry>``'s attributes: where it starts along the road
    (``s``), at which point and heading (``x``, ``y``, ``hdg``), and its ``length``."""

    s: float
    x: float
    y: float
    hdg: float
    length: float


@dataclass(frozen=True, slots=True)
class Line(PlanViewElement):
    """A straight line of the plan view (``<line>``)."""

    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Arc(PlanViewElement):
    """An arc of constant curvature of the plan view (``<arc>``)."""

    curvature: float
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Spiral(PlanViewElement):
    """A clothoid of the plan view (``<spiral>``): curvature linear in s from ``curv_start`` to ``curv_end``."""

    curv_start: float
    curv_end: float
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Poly3(PlanViewElement):
    """Cubic ``v(u) = a + b u + c u^2 + d u^3`` in the local (u, v) frame (deprecated in 1.6, still read)."""

    a: float
    b: float
    c: float
    d: float
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class ParamPoly3(PlanViewElement):
    """A parametric cubic of the plan view (``<paramPoly3>``): u and v cubic in a parameter p."""

    aU: float
    bU: float
    cU: float
    dU: float
    aV: float
    bV: float
    cV: float
    dV: float
    p_range: PRange = PRange.NORMALIZED
    line: int = 0
    xml: XmlFacts = facts_field()


Geometry = Line | Arc | Spiral | Poly3 | ParamPoly3
