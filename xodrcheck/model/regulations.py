"""The header's licence and default regulations (1.8, 6.4.3): a country's default speeds per road type and
priorities per sign type. Read as the file gives them."""

from __future__ import annotations

from dataclasses import dataclass

from xodrcheck.model.facts import XmlFacts, facts_field
from xodrcheck.model.signals import Semantics

__all__ = ["DefaultRegulations", "License", "RoadRegulation", "SignalRegulation"]


@dataclass(frozen=True, slots=True)
class License:
    """The header's ``<license>`` (1.8)."""

    name: str | None = None
    spdxid: str | None = None
    text: str | None = None
    resource: str | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class RoadRegulation:
    """A ``<roadRegulations>`` of the default regulations: the semantics that hold on roads of ``type``."""

    type: str | None
    semantics: Semantics | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class SignalRegulation:
    """A ``<signalRegulations>`` of the default regulations: the semantics of signals of ``type`` and ``subtype``."""

    type: str | None
    subtype: str | None = None
    semantics: Semantics | None = None
    line: int = 0
    xml: XmlFacts = facts_field()


@dataclass(frozen=True, slots=True)
class DefaultRegulations:
    """The header's ``<defaultRegulations>`` (1.8, 6.4.3): a country's default speeds and priorities."""

    road_regulations: tuple[RoadRegulation, ...] = ()
    signal_regulations: tuple[SignalRegulation, ...] = ()
    line: int = 0
    xml: XmlFacts = facts_field()
