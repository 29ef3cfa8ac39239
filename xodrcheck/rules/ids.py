"""Ids of the classes beyond roads, junctions, connections and lanes (those are :mod:`.reference`'s): unique within
their class, and every id a file refers to defined (Annex F ``ids``): ``R020``, ``R021``.

The classes and references are those the 1.8.1 schema declares keys for (objects, bridges, tunnels, signals,
controllers, junction groups, stations, platforms, switches, vmsGroups) plus the references it leaves out (object
references, signal dependencies and references, junction controllers, junction group members), so that files of
every version are held to them, not only those the 1.8 schema validates.
"""

from __future__ import annotations

from collections.abc import Iterator

from lxml import etree

from xodrcheck.findings import Category, Finding, Severity
from xodrcheck.rules import feature_uids as F
from xodrcheck.rules.context import Context, describe_junction
from xodrcheck.rules.registry import rule

#: Class name -> path of its elements below ``<OpenDRIVE>`` (ids unique file-wide, as in the 1.8.1 schema's keys).
_CLASSES = {
    "object": "road/objects/object",
    "bridge": "road/objects/bridge",
    "tunnel": "road/objects/tunnel",
    "signal": "road/signals/signal",
    "controller": "controller",
    "junction group": "junctionGroup",
    "station": "station",
    "platform": "station/platform",
    "switch": "road/railroad/switch",
    "vmsGroup": "vmsGroup",
}

#: (path of the referring element, its attribute, what it names, the classes that may hold the id).
_REFERENCES = (
    ("road/objects/objectReference", "id", "object", ("object",)),
    ("road/signals/signal/dependency", "id", "signal", ("signal", "sign")),
    ("road/signals/signal/positionRoad", "roadId", "road", ("road",)),
    ("road/signals/signalReference", "id", "signal", ("signal", "object", "road", "junction", "controller")),
    ("road/railroad/switch/mainTrack", "id", "road", ("road",)),
    ("road/railroad/switch/sideTrack", "id", "road", ("road",)),
    ("road/railroad/switch/partner", "id", "switch", ("switch",)),
    ("controller/control", "signalId", "signal", ("signal", "sign")),
    ("junction", "mainRoad", "road", ("road",)),
    ("junction/controller", "id", "controller", ("controller",)),
    ("junction/priority", "high", "road", ("road",)),
    ("junction/priority", "low", "road", ("road",)),
    ("junction/crossPath", "crossingRoad", "road", ("road",)),
    ("junction/crossPath", "roadAtStart", "road", ("road",)),
    ("junction/crossPath", "roadAtEnd", "road", ("road",)),
    ("junction/roadSection", "roadId", "road", ("road",)),
    ("junction/boundary/segment", "roadId", "road", ("road",)),
    ("junction/connection/predecessor", "elementId", "road", ("road",)),
    ("junction/connection/successor", "elementId", "road", ("road",)),
    ("junctionGroup/junctionReference", "junction", "junction", ("junction",)),
    ("station/platform/segment", "roadId", "road", ("road",)),
    ("vmsGroup/vmsBoardReference", "signalId", "signal", ("signal",)),
)


def _road_of(el: etree._Element) -> str | None:
    for parent in el.iterancestors():
        if isinstance(parent.tag, str) and etree.QName(parent).localname == "road":
            return parent.get("id")
    return None


@rule("R020", "duplicate-element-id", Category.REFERENCE, Severity.ERROR, uids=(F.ID_UNIQUE_IN_CLASS,), xml=True)
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
    index = _index(ctx)
    for name, path in _CLASSES.items():
        first: dict[str, etree._Element] = {}
        for el in index[path]:
            ident = el.get("id")
            if ident is None:
                continue
            if ident not in first:
                first[ident] = el
                continue
            yield duplicate_element_id.finding(
                f"{name} id {ident!r} is used again (first at line {first[ident].sourceline}): ids are unique "
                f"within their class; give this {name} an id of its own",
                road=_road_of(el),
                line=el.sourceline,
            )


_SIGNS = "road/signals/signal/staticBoard/sign"
_LINKS = "road/signals/signal/reference"
_WANTED = frozenset([*_CLASSES.values(), *(path for path, *_ in _REFERENCES), "road", "junction", _SIGNS, _LINKS])
_PREFIXES = frozenset(path.rsplit("/", k)[0] for path in _WANTED for k in range(path.count("/") + 1))


def _index(ctx: Context) -> dict[str, list[etree._Element]]:
    """The elements at each path of :data:`_WANTED` (local names from ``<OpenDRIVE>``), in file order: one walk of
    the parts of the tree that hold them, shared by the rules of one file (dropped with the tree)."""

    def build() -> dict[str, list[etree._Element]]:
        found: dict[str, list[etree._Element]] = {path: [] for path in _WANTED}
        tree = ctx.tree
        if tree is not None:
            _walk(tree.getroot(), "", found)
        return found

    return ctx.xml_view("ids.index", build)


def _walk(el: etree._Element, path: str, out: dict[str, list[etree._Element]]) -> None:
    for child in el:
        tag = child.tag
        if not isinstance(tag, str):
            continue
        here = f"{path}/{tag.rpartition('}')[2]}" if path else tag.rpartition("}")[2]
        if here in out:
            out[here].append(child)
        if here in _PREFIXES:
            _walk(child, here, out)


def _defined(index: dict[str, list[etree._Element]]) -> dict[str, set[str]]:
    out = {name: {el.get("id") for el in index[path]} for name, path in _CLASSES.items()}
    out["road"] = {el.get("id") for el in index["road"]}
    out["junction"] = {el.get("id") for el in index["junction"]}
    out["sign"] = {el.get("id") for el in index[_SIGNS]}
    return out


def _dangling(index: dict[str, list[etree._Element]]) -> Iterator[tuple[etree._Element, str, str, str]]:
    """(element, attribute, the id, what it should name) for each reference to an id the file does not define."""
    defined = _defined(index)
    for path, attr, what, classes in _REFERENCES:
        for el in index[path]:
            ident = el.get(attr)
            if ident is not None and not any(ident in defined[c] for c in classes):
                yield el, attr, ident, what
    for el in index[_LINKS]:
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
    xml=True,
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
    for el, attr, ident, what in _dangling(_index(ctx)):
        tag, article = etree.QName(el).localname, "an" if what[0] in "aeiou" else "a"
        yield undefined_reference.finding(
            f"<{tag} {attr}={ident!r}> names {article} {what} that the file does not define: correct the id or add "
            f"the {what}",
            road=_road_of(el),
            line=el.sourceline,
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
