"""Stations (15.4): a station's platforms and the track segments beside them. (A road's switches are in
:mod:`.roads`.) Read as the file gives them (``None``: absent or not of its type)."""

from __future__ import annotations

from dataclasses import dataclass

from xodrcheck.model.enums import Side, StationType
from xodrcheck.model.facts import XmlFacts, facts_field

__all__ = ["Platform", "PlatformSegment", "Station"]


@dataclass(frozen=True, slots=True)
class PlatformSegment:
    """A platform's ``<segment>``: the track (road ``road_id``) it lies beside from ``s_start`` to ``s_end``, on
    ``side`` (left or right)."""

    road_id: str | None
    s_start: float | None = None
    s_end: float | None = None
    side: Side | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Platform:
    """A station's ``<platform>``: its segments."""

    id: str | None
    name: str | None = None
    segments: tuple[PlatformSegment, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class Station:
    """A ``<station>``: its platforms."""

    id: str | None
    name: str | None = None
    type: StationType | None = None
    platforms: tuple[Platform, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()
