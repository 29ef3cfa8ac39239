"""Road surfaces: OpenCRG references of roads and junctions (10.6, 12.12) and a road's cross section surface (10.5.4,
1.8). Read as the file gives them (``None``: absent or not of its type; the schema rule reports it)."""

from __future__ import annotations

from dataclasses import dataclass

from xodrcheck.model.enums import CrgMode, CrgOrientation, CrgPurpose
from xodrcheck.model.facts import XmlFacts, facts_field

__all__ = [
    "CrossSectionSurface",
    "Surface",
    "SurfaceCoefficients",
    "SurfaceCrg",
    "SurfacePolynomial",
    "SurfaceStrip",
]


@dataclass(frozen=True, slots=True)
class SurfaceCrg:
    """A ``<CRG>`` of a road's or junction's ``<surface>``: an OpenCRG file laid over ``s_start`` to ``s_end``.
    ``purpose`` is ``None`` when absent (the standard's default is elevation: :attr:`purpose_or_default`)."""

    file: str | None
    s_start: float | None
    s_end: float | None
    orientation: CrgOrientation | None = None
    mode: CrgMode | None = None
    purpose: CrgPurpose | None = None
    s_offset: float | None = None
    t_offset: float | None = None
    x_offset: float | None = None
    y_offset: float | None = None
    z_offset: float | None = None
    z_scale: float | None = None
    h_offset: float | None = None
    line: int = 0
    xml: XmlFacts = facts_field()

    @property
    def purpose_or_default(self) -> CrgPurpose | None:
        """The purpose, elevation when the file gives none (``None``: given but not a purpose)."""
        return CrgPurpose.ELEVATION if not self.xml.given("purpose") and self.purpose is None else self.purpose


@dataclass(frozen=True, slots=True)
class Surface:
    """A road's or junction's ``<surface>``: its OpenCRG files."""

    crgs: tuple[SurfaceCrg, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class SurfaceCoefficients:
    """A ``<coefficients>`` record of a cross section surface polynomial, from ``s`` on."""

    s: float | None
    a: float | None = None
    b: float | None = None
    c: float | None = None
    d: float | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class SurfacePolynomial:
    """One polynomial of a cross section surface: its ``tOffset``, or a strip's ``width``, ``constant``,
    ``linear``, ``quadratic`` or ``cubic`` (``kind``: the element name), as records along s."""

    kind: str
    coefficients: tuple[SurfaceCoefficients, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class SurfaceStrip:
    """A ``<strip>`` of a cross section surface: left (positive ``id``) or right (negative), with its polynomials in
    file order."""

    id: int | None
    mode: str | None = None
    polynomials: tuple[SurfacePolynomial, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()

    def polynomial(self, kind: str) -> SurfacePolynomial | None:
        """Its first polynomial of ``kind`` (``width``, ``constant``...)."""
        return next((p for p in self.polynomials if p.kind == kind), None)


@dataclass(frozen=True, slots=True)
class CrossSectionSurface:
    """A road's ``<crossSectionSurface>`` (1.8): its ``tOffset`` and strips (of every ``<surfaceStrips>``)."""

    t_offset: SurfacePolynomial | None = None
    strips: tuple[SurfaceStrip, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()
