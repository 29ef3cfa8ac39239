"""The file's ``<header>`` (chapter 8): OpenDRIVE revision, name, version, extent, georeference, offset, licence and
default regulations (6.4)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from xodrcheck.model.facts import XmlFacts, facts_field

if TYPE_CHECKING:  # pragma: no cover - loaded when a file has them
    from xodrcheck.model.regulations import DefaultRegulations, License

__all__ = ["GeoReference", "Header", "Offset"]


@dataclass(frozen=True, slots=True)
class Offset:
    """The header's ``offset`` element (1.5+): the map is shifted by (x, y, z) and rotated by hdg."""

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0
    hdg: float = 0.0
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class GeoReference:
    """A ``<geoReference>``: the projection of the map's coordinates as a PROJ string (its text, stripped)."""

    text: str
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Header:
    """The file's ``<header>``: OpenDRIVE revision, name, version, date, vendor, extent and georeference.
    ``geo_reference`` and ``offset`` are the first of their elements; ``geo_references`` keeps every one."""

    rev_major: int | None
    rev_minor: int | None
    name: str | None = None
    version: str | None = None
    date: str | None = None
    vendor: str | None = None
    north: float | None = None
    south: float | None = None
    east: float | None = None
    west: float | None = None
    geo_reference: str | None = None
    offset: Offset | None = None
    line: int = 0
    geo_references: tuple[GeoReference, ...] = ()
    license: License | None = None
    default_regulations: DefaultRegulations | None = None
    xml: XmlFacts = facts_field()

    @property
    def version_tuple(self) -> tuple[int, int] | None:
        if self.rev_major is None or self.rev_minor is None:
            return None
        return (self.rev_major, self.rev_minor)
