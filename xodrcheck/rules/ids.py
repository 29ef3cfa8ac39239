"""Ids of the classes beyond roads, junctions, connections and lanes (those are :mod:`.reference`'s): unique within
their class, and every id a file refers to defined (Annex F ``ids``): ``R020``, ``R021``.

The classes and the references between them are :mod:`xodrcheck.model.ids`'s (the 1.8.1 schema's keys, and the
references it leaves out); the rules read the ids as the reader recorded them, wherever in the file they stand.
"""

from __future__ import annotations

from collections.abc import Iterator

from xodrcheck.findings import Category, Finding, Severity
from xodrcheck.model import ID_CLASSES, ID_REFERENCES, SIGNAL_LINKS, SIGNS, IdElement, IdTable
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import feature_uids as F
from xodrcheck.rules.shared.context import Context, describe_junction


def _table(ctx: Context) -> IdTable:
    """The file's ids as the reader recorded them (none for a document built in code)."""
    return ctx.document.ids or IdTable()


@rule("R020", "duplicate-element-id", Category.REFERENCE, Severity.ERROR, uids=(F.ID_UNIQUE_IN_CLASS,))
def duplicate_element_id(ctx: Context):
    """Two objects, signals, controllers, stations, switches... of one class share an id.

    IDs shall be unique within a class (Annex F ``ids.id_unique_in_class``): references name an element by its id
    alone, and reach only one of two. Objects, bridges, tunnels, signals, controllers, junction groups, stations,
    platforms, switches and vmsGroups are checked file-wide (as the 1.8.1 schema's keys do); roads, junctions and a
    junction's connections are ``duplicate-road-id``'s, ``duplicate-junction-id``'s and
    ``duplicate-connection-id``'s.

    Passes::

        <road id="1">...<signal id="5" .../></road> <road id="2">...<signal id="6" .../></road>

    Fails::

        <road id="1">...<signal id="5" .../></road> <road id="2">...<signal id="5" .../></road>
    """
    table = _table(ctx)
    for name, path in ID_CLASSES.items():
        first: dict[str, IdElement] = {}
        for el in table.at(path):
            ident = el.get("id")
            if ident is None:
                continue
            if ident not in first:
                first[ident] = el
                continue
            yield duplicate_element_id.finding(
                f"{name} id {ident!r} is used again (first at line {first[ident].line}): ids are unique "
                f"within their class; give this {name} an id of its own",
                road=el.road,
                line=el.line,
            )


def _defined(table: IdTable) -> dict[str, set[str | None]]:
    out = {name: {el.get("id") for el in table.at(path)} for name, path in ID_CLASSES.items()}
    out["road"] = {el.get("id") for el in table.at("road")}
    out["junction"] = {el.get("id") for el in table.at("junction")}
    out["sign"] = {el.get("id") for el in table.at(SIGNS)}
    return out


def _dangling(table: IdTable) -> Iterator[tuple[IdElement, str, str, str]]:
    """(element, attribute, the id, what it should name) for each reference to an id the file does not define."""
    defined = _defined(table)
    for path, attr, what, classes in ID_REFERENCES:
        for el in table.at(path):
            ident = el.get(attr)
            if ident is not None and not any(ident in defined[c] for c in classes):
                yield el, attr, ident, what
    for el in table.at(SIGNAL_LINKS):
        kind, ident = el.get("elementType"), el.get("elementId")
        known = defined["signal"] | defined["sign"] if kind == "signal" else defined.get(kind or "", set())
        if kind in ("signal", "object") and ident is not None and ident not in known:
            yield el, "elementId", ident, kind


@rule(
    "R021",
    "undefined-reference",
    Category.REFERENCE,
    Severity.ERROR,
    uids=(F.ONLY_REF_DEFINED_IDS,),
)
def undefined_reference(ctx: Context):
    """An element refers to an object, signal, controller, switch, road or junction id the file does not define.

    Only defined IDs may be referenced (Annex F ``ids.only_ref_defined_ids``). Checked here: object references,
    signal dependencies, signal references (``<signalReference>``, ``<reference>``), ``positionRoad``, controls of
    controllers, junction group members, switch tracks and partners, platform segments, vmsBoard references, and
    every road or lane a junction's children name: its ``mainRoad`` (virtual junctions), controllers, priorities
    (``high``, ``low``), cross paths (``crossingRoad``, ``roadAtStart``, ``roadAtEnd`` and the lanes of their
    ``<startLaneLink>``/``<endLaneLink>``), road sections, boundary segments and virtual connections' predecessors and
    successors. Road links, junction connections and lane links are ``road-link-target-missing``'s,
    ``connection-road-missing``'s, ``junction-lane-link-missing-lane``'s, ``road-junction-missing``'s and
    ``lane-link-missing-lane``'s.

    Passes::

        <objectReference id="7" .../>   <!-- object 7 exists -->

    Fails::

        <objectReference id="70" .../>  <!-- no object 70 -->
    """
    for el, attr, ident, what in _dangling(_table(ctx)):
        article = "an" if what[0] in "aeiou" else "a"
        yield undefined_reference.finding(
            f"<{el.tag} {attr}={ident!r}> names {article} {what} that the file does not define: correct the id or "
            f"add the {what}",
            road=el.road,
            line=el.line,
        )
    yield from _cross_path_lanes(ctx)


def _cross_path_lanes(ctx: Context) -> Iterator[Finding]:
    """Lanes a cross path's ``<startLaneLink>``/``<endLaneLink>`` names that its roads do not have there."""
    from xodrcheck.rules.junction_members import cross_path_lanes

    for j in ctx.document.junctions:
        for cp in j.cross_paths:
            for what, road, lane, lane_id, s, line in cross_path_lanes(ctx, cp):
                if lane is None and lane_id is not None:
                    yield undefined_reference.finding(
                        f"{describe_junction(j)} cross path {cp.id} names {what}, which the road does not have there: "
                        "correct the lane id",
                        road=road.id,
                        lane=lane_id,
                        s=s,
                        line=line or None,
                    )
