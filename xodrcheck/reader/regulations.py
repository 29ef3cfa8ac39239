"""The header's ``<license>`` and ``<defaultRegulations>`` (1.8), read as the file gives them."""

from __future__ import annotations

from lxml import etree

from xodrcheck.model import DefaultRegulations, License, RoadRegulation, SignalRegulation
from xodrcheck.reader.context import LEAF, Context
from xodrcheck.reader.signals import semantics

_REGULATION = frozenset({"semantics"})
_REGULATIONS = frozenset({"roadRegulations", "signalRegulations"})


def default_regulations(ctx: Context, el: etree._Element) -> DefaultRegulations:
    roads = tuple(
        RoadRegulation(r.get("type"), semantics(ctx, r), r.sourceline, ctx.facts(r, _REGULATION))
        for r in el.iterchildren("roadRegulations")
    )
    signals = tuple(
        SignalRegulation(r.get("type"), r.get("subtype"), semantics(ctx, r), r.sourceline, ctx.facts(r, _REGULATION))
        for r in el.iterchildren("signalRegulations")
    )
    return DefaultRegulations(roads, signals, el.sourceline, ctx.facts(el, _REGULATIONS))


def license_of(ctx: Context, el: etree._Element) -> License:
    get = el.get
    return License(get("name"), get("spdxid"), get("text"), get("resource"), el.sourceline, ctx.facts(el, LEAF))
