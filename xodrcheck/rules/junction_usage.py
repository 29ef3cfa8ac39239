"""Which attributes and elements a junction of each type may use (``J010``-``J014``), read from the file's XML.

ASAM OpenDRIVE 1.9 has four junction types (12.1): common (``default``), ``direct``, ``virtual`` and ``crossing``, and
each takes its own set of attributes and children: ``connectingRoad`` for the common and virtual junctions'
connections, ``linkedRoad`` for the direct junction's (12.6), ``overlapZone`` on a direct junction's lane links only,
``mainRoad``/``orientation``/``sStart``/``sEnd`` on a virtual junction only (12.7), ``<roadSection>`` elements and no
connections on a crossing (12.8), a boundary on a common junction only (12.10). The parts come from
the document (:mod:`xodrcheck.model`). Some of these the 1.8/1.9 schemas catch as well (``S001``); the rules here name
the rule of the standard and say what to change, for every version the rule applies to.

Where Annex F states one requirement under several UIDs (``connectingRoad`` in a direct junction is
``type_direct_no_conn_road``, ``direct.connecting_road_attribute_usage`` and, from 1.9, ``connection
.no_connecting_road_direct``), one finding is given per UID, so a report counts each rule of the standard.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from xodrcheck.findings import Category, Finding, Severity
from xodrcheck.model import ConnectionType, JunctionType
from xodrcheck.rules.registry import Rule, rule
from xodrcheck.rules.shared import junction_uids as U
from xodrcheck.rules.shared.context import Context, describe_junction, written_id

if TYPE_CHECKING:
    from xodrcheck.model import Connection, ConnectionEnd, Junction

_VIRTUAL_ATTRIBUTES = ("mainRoad", "orientation", "sStart", "sEnd")


def _each(check: Rule, uids: tuple[str, ...], message: str, **where) -> Iterator[Finding]:
    """One finding per UID (the same defect, named by several rules of the standard)."""
    for uid in uids:
        yield check.finding(message, uid=uid, **where)


@rule(
    "J010",
    "connection-road-attribute",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(
        U.DEFAULT_NO_LINKED_ROAD,
        U.DIRECT_LINKED_ROAD,
        U.DIRECT_NO_CONN_ROAD,
        U.DIRECT_CONNECTING_ROAD,
        U.CONNECTION_NO_CONNECTING_ROAD_DIRECT,
    ),
)
def connection_road_attribute(ctx: Context):
    """A connection names its road with the attribute of another junction type.

    A connection of a direct junction joins its incoming road to a *linked* road (``linkedRoad``); connections of
    common and virtual junctions lead into a *connecting* road (``connectingRoad``), 12.2-12.7. Annex F:
    ``junctions.type_direct_no_conn_road``, ``junctions.direct.connecting_road_attribute_usage`` and (1.9)
    ``junctions.connection.no_connecting_road_direct`` (no ``connectingRoad`` in a direct junction);
    ``junctions.type_default_no_linked_road`` (no ``linkedRoad`` in a default or virtual junction) and
    ``junctions.direct.correct_type_linked_road_usage`` (``linkedRoad`` only in a direct junction). One finding per
    UID.

    Passes::

        <junction id="111" type="direct">
          <connection id="0" incomingRoad="1" linkedRoad="2" contactPoint="start"/></junction>

    Fails (a direct junction has no connecting roads)::

        <junction id="111" type="direct">
          <connection id="0" incomingRoad="1" connectingRoad="2" contactPoint="start"/></junction>
    """
    for j in ctx.document.junctions:
        for c in j.connections:
            at = f"{describe_junction(j)} connection {written_id(c)}"
            where = {"road": c.linked_road or c.connecting_road, "line": c.line or j.line or None}
            if j.type is JunctionType.DIRECT and c.connecting_road is not None:
                yield from _each(
                    connection_road_attribute,
                    (U.DIRECT_NO_CONN_ROAD, U.DIRECT_CONNECTING_ROAD, U.CONNECTION_NO_CONNECTING_ROAD_DIRECT),
                    f'{at} has connectingRoad="{c.connecting_road}": a direct junction links its roads directly, '
                    "without connecting roads; name the road with linkedRoad",
                    **where,
                )
            if j.type is not JunctionType.DIRECT and c.linked_road is not None:
                uids: tuple[str, ...] = (U.DIRECT_LINKED_ROAD,)
                if j.type in (JunctionType.DEFAULT, JunctionType.VIRTUAL):
                    uids = (U.DEFAULT_NO_LINKED_ROAD, U.DIRECT_LINKED_ROAD)
                fix = (
                    "connectingRoad"
                    if j.type in (JunctionType.DEFAULT, JunctionType.VIRTUAL)
                    else "nothing (a crossing has no connections)"
                )
                yield from _each(
                    connection_road_attribute,
                    uids,
                    f'{at} has linkedRoad="{c.linked_road}": linkedRoad is for direct junctions only; a {j.type.value} '
                    f"junction's connection names its road with {fix}",
                    **where,
                )


@rule(
    "J011",
    "junction-type-attribute",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(U.COMMON_DIRECT_ATTRIBUTES, U.COMMON_VIRTUAL_ATTRIBUTES, U.VIRTUAL_CONNECTIONS),
)
def junction_type_attribute(ctx: Context):
    """A junction or its connection uses an attribute that belongs to another junction type.

    ``overlapZone`` on a ``<laneLink>`` is for direct junctions only (``junctions.common.direct_junction_attributes``,
    12.6); ``mainRoad``, ``orientation``, ``sStart`` and ``sEnd`` on a ``<junction>`` are for virtual junctions only
    (``junctions.common.virtual_junction_attributes``, 12.7); a virtual connection (``<connection type="virtual">``,
    deprecated) belongs in a virtual junction only (``junctions.virtual.connections.only_virtual_junctions``).

    Passes::

        <junction id="555" type="virtual" mainRoad="1" sStart="50" sEnd="70" orientation="+">...</junction>

    Fails (a common junction has no main road)::

        <junction id="100" mainRoad="1" sStart="50" sEnd="70">...</junction>
    """
    for j in ctx.document.junctions:
        if j.type is not JunctionType.DIRECT:
            for c in j.connections:
                for ll in c.all_lane_links:
                    if ll.xml.given("overlapZone"):
                        yield junction_type_attribute.finding(
                            f"{describe_junction(j)} connection {written_id(c)}: laneLink {ll.from_lane} -> "
                            f"{ll.to_lane} has overlapZone, which only a direct junction's lane links have (the length "
                            "over which two lanes that split or merge share their space); remove it",
                            uid=U.COMMON_DIRECT_ATTRIBUTES,
                            road=c.connecting_road or c.linked_road,
                            line=ll.line or c.line or None,
                        )
        if j.type is not JunctionType.VIRTUAL:
            given = [name for name in _VIRTUAL_ATTRIBUTES if j.xml.given(name)]
            if given:
                yield junction_type_attribute.finding(
                    f"{describe_junction(j)} has {', '.join(given)}: these say where a virtual junction lies on its "
                    'main road and belong to junctions of type="virtual" only; remove them or make the junction '
                    "virtual",
                    uid=U.COMMON_VIRTUAL_ATTRIBUTES,
                    road=j.main_road,
                    line=j.line or None,
                )
            for c in j.connections:
                if c.type is ConnectionType.VIRTUAL:
                    yield junction_type_attribute.finding(
                        f"{describe_junction(j)} connection {written_id(c)} is a virtual connection "
                        '(type="virtual"), which only a virtual junction may define; model the path with a '
                        "connecting road",
                        uid=U.VIRTUAL_CONNECTIONS,
                        line=c.line or j.line or None,
                    )


def first_lines(j: Junction) -> dict[str, int]:
    """Tag -> the line of the junction's first child element of that tag, for the tags J012 names."""
    first = {u.tag: u.line for u in reversed(j.xml.unknown)}
    for tag, records in (
        ("connection", j.connections),
        ("crossPath", j.cross_paths),
        ("boundary", j.boundaries),
        ("elevationGrid", j.grids),
    ):
        if records:
            first[tag] = records[0].line
    return first


def _ends(c: Connection) -> list[tuple[str, ConnectionEnd]]:
    """A connection's ``<predecessor>`` and ``<successor>`` with their tags, in file order."""
    ends = [(tag, end) for tag, end in (("predecessor", c.predecessor), ("successor", c.successor)) if end is not None]
    return sorted(ends, key=lambda item: item[1].line)


def _type_elements(j: Junction) -> Iterator[tuple[str, str, int]]:
    """(UID, message, line) for each child element the junction's type does not allow."""
    first = first_lines(j)
    who = describe_junction(j)
    if j.boundaries and j.type is not JunctionType.DEFAULT:
        yield (
            U.BOUNDARY_ONLY_COMMON,
            f"{who} has a <boundary>: junction boundaries are only valid for common junctions (12.10); remove it",
            j.boundaries[0].line,
        )
    if j.type is JunctionType.CROSSING:
        extra = [name for name in ("connection", "crossPath", "boundary", "elevationGrid") if name in first]
        if extra:
            yield (
                U.CROSSING_ONLY_ROAD_SECTIONS,
                f"{who} has {', '.join(f'<{n}>' for n in extra)}: a crossing only names the crossing roads' "
                "ranges with <roadSection> elements (traffic does not change roads there, 12.8); use a common or "
                "virtual junction for connections",
                first[extra[0]],
            )
        elif not j.road_sections:
            yield (
                U.CROSSING_ONLY_ROAD_SECTIONS,
                f"{who} has no <roadSection>: a crossing names the range of each crossing road with one",
                j.line,
            )
    if len(j.grids) > 1:
        yield (
            U.GRID_ONLY_ONE,
            f"{who} has {len(j.grids)} <elevationGrid> elements (lines "
            f"{', '.join(str(g.line) for g in j.grids)}); a junction has only one elevation grid",
            j.grids[1].line,
        )
    for name in ("link", "predecessor", "successor"):
        if name in first:
            yield (
                U.COMMON_NO_PRED_SUCC,
                f"{who} has a <{name}>: unlike roads, junctions have no predecessor or successor; the "
                "roads link to the junction",
                first[name],
            )
    for c in j.connections:
        for tag, end in _ends(c):
            element_type = end.element_type.value if end.element_type is not None else end.xml.text("elementType")
            line = end.line
            if element_type is not None and element_type != "road":
                yield (
                    U.COMMON_NO_PRED_SUCC,
                    f"{who} connection {written_id(c)}: its <{tag}> names a {element_type}; a virtual connection joins "
                    "roads, and junctions have no predecessor or successor",
                    line,
                )


@rule(
    "J012",
    "junction-type-elements",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(U.BOUNDARY_ONLY_COMMON, U.CROSSING_ONLY_ROAD_SECTIONS, U.GRID_ONLY_ONE, U.COMMON_NO_PRED_SUCC),
)
def junction_type_elements(ctx: Context):
    """A junction holds an element its type does not allow, or one too many.

    A ``<boundary>`` is valid for common junctions only (``junctions.boundary.only_for_common_junctions``, 12.10); a
    crossing has ``<roadSection>`` elements and no connections, cross paths, boundary or elevation grid
    (``junctions.crossing.only_road_sections``, 12.8; its priorities, controllers and reference line are allowed);
    a junction has at most one ``<elevationGrid>`` (``junctions.elevation_grid.only_one_elev_grid``, 12.11); and a
    junction has no predecessor or successor (``junctions.common.junctions_no_pred_succ``, 12.2: no ``<link>``,
    ``<predecessor>`` or ``<successor>`` of its own, and a virtual connection's ends name roads).

    Passes::

        <junction id="555" type="crossing"><priority high="2" low="1"/>
          <roadSection id="0" roadId="1" sStart="50" sEnd="60"/><roadSection id="1" roadId="2" .../></junction>

    Fails (a crossing with a connection)::

        <junction id="555" type="crossing"><connection id="0" incomingRoad="1" connectingRoad="3" .../>
          <roadSection id="0" roadId="1" sStart="50" sEnd="60"/></junction>
    """
    for j in ctx.document.junctions:
        for uid, message, line in _type_elements(j):
            yield junction_type_elements.finding(message, uid=uid, line=line or j.line or None)


@rule(
    "J013",
    "junction-reference-line-shape",
    Category.JUNCTION,
    Severity.ERROR,
    uids=(U.REFLINE_ONE_LINE, U.GRID_PERPENDICULAR),
)
def junction_reference_line_shape(ctx: Context):
    """A junction reference line is not one straight ``<geometry>``, or an elevation grid has no reference line.

    A junction's ``<planView>`` has exactly one ``<geometry>`` whose only shape is a ``<line>``
    (``junctions.geometry.only_one_line_element``, 12.9). The rows of an elevation grid run perpendicular to the
    junction reference line, at ``sStart`` plus multiples of ``gridSpacing`` along it
    (``junctions.elevation_grid.perpendicular_vectors``, 12.11): a grid in a junction without a reference line has
    no such direction (the file cannot state another one), and neither has a grid without a positive spacing.

    Passes::

        <planView><geometry s="0" x="-20" y="-20" hdg="0" length="40"><line/></geometry></planView>
        <elevationGrid sStart="0" gridSpacing="10">...</elevationGrid>

    Fails (an arc)::

        <planView><geometry s="0" x="-20" y="-20" hdg="0" length="40"><arc curvature="0.01"/></geometry></planView>
    """
    for j in ctx.document.junctions:
        for view in j.plan_views:
            shapes = [(g, g.shapes) for g in view.geometries]
            if len(shapes) != 1 or shapes[0][1] != ("line",):
                what = (
                    f"{len(shapes)} <geometry> elements"
                    if len(shapes) != 1
                    else f"a <geometry> of {', '.join(f'<{s}>' for s in shapes[0][1]) or 'no shape'}"
                )
                yield junction_reference_line_shape.finding(
                    f"{describe_junction(j)}: its reference line (<planView>) has {what}; a junction reference line is "
                    "one <geometry> with one <line>",
                    uid=U.REFLINE_ONE_LINE,
                    line=(shapes[1][0].line if len(shapes) > 1 else shapes[0][0].line if shapes else view.line) or None,
                )
        for grid in j.grids:
            if not j.plan_views or not j.plan_views[0].geometries:
                yield junction_reference_line_shape.finding(
                    f"{describe_junction(j)} has an <elevationGrid> but no junction reference line (<planView> with a "
                    "<geometry>): the grid's rows run perpendicular to that line, so without it the grid has no place",
                    uid=U.GRID_PERPENDICULAR,
                    line=grid.line or j.line or None,
                )
            elif grid.spacing is None or not grid.spacing > 0:
                yield junction_reference_line_shape.finding(
                    f"{describe_junction(j)}: its <elevationGrid> has gridSpacing {grid.spacing}: the rows "
                    "perpendicular to the reference line need a positive spacing",
                    uid=U.GRID_PERPENDICULAR,
                    line=grid.line or j.line or None,
                )
