"""Which attributes a road's ``<predecessor>`` and ``<successor>`` use (``K004``), read from the document.

Roads and junctions are linked with different attribute sets (10.3, Table 24): a road by ``elementType``,
``elementId`` and ``contactPoint``; a junction by ``elementType`` and ``elementId`` alone; a road joined inside
another road (a virtual junction's connection, 12.7) by ``elementType``, ``elementId``, ``elementS`` and
``elementDir``. A road link without ``contactPoint`` is ``link-contact-point-missing`` (``K002``).

Read from the document: a road's links, and the links the reader could not read (``Road.unread_links``: without
``elementType`` or ``elementId``); which attributes a link gives, from its XML facts.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.model import Document, JunctionType, RoadLink, UnreadLink, XmlFacts
from xodrcheck.rules.registry import NO_UID, rule
from xodrcheck.rules.shared import road_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.standard import applies

_USAGE = (U.LINKAGE_ROAD_ATTRIBUTES, U.LINKAGE_JUNCTION_ATTRIBUTES, U.LINKAGE_VIRTUAL_ATTRIBUTES)
_NOT_FOR_JUNCTIONS = ("contactPoint", "elementS", "elementDir")


@dataclass(frozen=True, slots=True)
class _Written:
    """A road's ``<predecessor>`` or ``<successor>`` as written: ``elementType`` (``None``: absent), ``elementId``,
    its line and facts."""

    tag: str
    kind: str | None
    target: str | None
    line: int
    xml: XmlFacts


def _links(ctx: Context) -> Iterator[tuple[str, str | None, _Written]]:
    """(road id, the road's junction, link) for every road's predecessor and successor, read or not, in file order."""
    for road in ctx.document.roads:
        found: list[_Written] = [
            _Written(tag, link.element_type.value, link.element_id, link.line, link.xml)
            for tag, link in (("predecessor", road.predecessor), ("successor", road.successor))
            if isinstance(link, RoadLink)
        ]
        found += [_unread(link) for link in road.unread_links]
        for link in sorted(found, key=lambda link: link.line):
            yield road.id, road.junction, link


def _unread(link: UnreadLink) -> _Written:
    return _Written(link.tag, link.element_type, link.element_id, link.line, link.xml)


def _main_roads(ctx: Context) -> dict[str, str]:
    """Virtual junction id -> its ``mainRoad``."""
    out: dict[str, str] = {}
    for junction in ctx.document.junctions:
        if junction.type is JunctionType.VIRTUAL and junction.main_road is not None:
            out.setdefault(junction.id, junction.main_road)
    return out


@rule(
    "K004",
    "link-attribute-usage",
    Category.LINK,
    Severity.ERROR,
    uids=_USAGE,
    basis=Basis.PLAUSIBILITY,
)
def link_attribute_usage(ctx: Context):
    """A road's ``<predecessor>`` or ``<successor>`` does not use the attribute set of what it links to.

    Annex F (10.3): a link to a road names ``elementType="road"`` (``road.linkage.road_link_attribute_usage``; its
    ``contactPoint`` is ``K002``'s); a link to a junction uses ``elementType="junction"`` and ``elementId``
    (``.junc_link_attribute_usage``); a connecting road of a virtual
    junction joins the junction's main road inside it with ``elementType``, ``elementId``, ``elementS`` and
    ``elementDir``, which go together (``.virtjunc_link_attribute_usage``, 12.7). ``elementS`` "shall only be used for
    elementType road" (Table 24), so a link to the virtual junction itself takes the junction's attribute set.

    A link to a junction that also carries ``contactPoint``, ``elementS`` or ``elementDir`` is a plausibility warning,
    not an error: the UID asks for ``elementType`` and ``elementId`` and does not forbid more, and only Table 24's text
    restricts ``elementS``/``elementDir`` to roads (a junction has no contact point; readers ignore it).

    Passes::

        <successor elementType="junction" elementId="100"/>

    Fails (junction 100 named without its elementType)::

        <successor elementId="100"/>
    """
    document = ctx.document
    main_roads = _main_roads(ctx)
    junction_rule = applies(U.LINKAGE_JUNCTION_ATTRIBUTES, ctx.version)
    for road_id, junction_id, link in _links(ctx):
        for message, uid in _misuses(document, main_roads, road_id, junction_id, link):
            if uid is None and not junction_rule:
                continue  # as the junction attribute rule: from OpenDRIVE 1.7 on
            yield link_attribute_usage.finding(
                message, uid=NO_UID if uid is None else uid, road=road_id, line=link.line or None
            )


def _misuses(
    document: Document, main_roads: dict[str, str], road_id: str, junction_id: str | None, link: _Written
) -> Iterator[tuple[str, str | None]]:
    """What road ``road_id``'s link gets wrong: (message, the Annex F UID it breaks, or None: no UID's words forbid
    it, a plausibility finding)."""
    kind, target, gives = link.kind, link.target, link.xml.given
    mine = f"road {road_id}: the {link.tag} {target!r} (line {link.line or None})"
    if kind is None:
        if target in document.road_by_id and target not in document.junction_by_id:
            yield (
                f'{mine} has no elementType; road {target} is linked with elementType="road"',
                U.LINKAGE_ROAD_ATTRIBUTES,
            )
        elif target in document.junction_by_id and target not in document.road_by_id:
            yield (
                f'{mine} has no elementType; junction {target} is linked with elementType="junction"',
                U.LINKAGE_JUNCTION_ATTRIBUTES,
            )
        return
    if kind == "junction":
        extra = [name for name in _NOT_FOR_JUNCTIONS if gives(name)]
        if extra:
            junction = document.junction_by_id.get(target or "")
            what = f"{junction.type.value} junction" if junction is not None else "junction"
            yield (
                f"{mine} links to a {what} with {', '.join(extra)}: a junction is linked by elementType and "
                f"elementId; {', '.join(extra)} mean nothing there (readers ignore them): remove them",
                None,
            )
        return
    if kind != "road":
        return  # not a link type (schema, reader)
    has_s, has_dir = gives("elementS"), gives("elementDir")
    if has_s != has_dir:
        given, missing = ("elementS", "elementDir") if has_s else ("elementDir", "elementS")
        yield (
            f"{mine} has {given} but no {missing}: a connection inside road {target} needs both",
            U.LINKAGE_VIRTUAL_ATTRIBUTES,
        )
    elif not has_s and junction_id is not None and main_roads.get(junction_id) == target:
        junction = document.junction_by_id.get(junction_id)
        if junction is not None and junction.type is JunctionType.VIRTUAL:
            yield (
                f"{mine} joins road {target}, the main road of virtual junction {junction_id}, without elementS "
                "and elementDir: say where on the main road (elementS) and in which direction (elementDir) the "
                "connection meets it",
                U.LINKAGE_VIRTUAL_ATTRIBUTES,
            )
