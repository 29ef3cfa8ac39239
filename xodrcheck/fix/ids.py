"""Fixes of ids (``R020``): an object or signal that repeats an id of its class, where nothing refers to that id."""

from __future__ import annotations

from collections.abc import Iterator

from xodrcheck.findings import Finding
from xodrcheck.fix.edits import set_attribute
from xodrcheck.fix.registry import Repair, Skip, fixer
from xodrcheck.fix.workspace import Workspace
from xodrcheck.fix.xmltext import Element

#: Classes whose repeated ids are renamed: element tag -> the tags of its class (ids unique across them).
CLASSES = {"object": ("object",), "bridge": ("bridge",), "tunnel": ("tunnel",), "signal": ("signal",)}

#: Where a file refers to an object or signal by id: element tag -> attribute.
REFERENCES = {
    "objectReference": "id",
    "dependency": "id",
    "signalReference": "id",
    "control": "signalId",
    "vmsBoardReference": "signalId",
    "reference": "elementId",
}


def _class_members(ws: Workspace, tag: str) -> list[Element]:
    """The elements of the class of ``tag`` inside roads (``<road>/<objects>`` or ``<signals>``), in file order."""
    tags = CLASSES[tag]
    return [
        e for e in ws.text.elements if e.tag in tags and e.parent is not None and e.parent.tag in ("objects", "signals")
    ]


def _fresh(taken: set[str], value: str) -> str:
    """A new id: the next whole number after the class's largest when its ids are whole numbers, else ``value_N``."""
    numbers = [int(t) for t in taken if t.strip().lstrip("-").isdigit()]
    if numbers and len(numbers) == len(taken):
        return str(max(numbers) + 1)
    k = 1
    while f"{value}_{k}" in taken:
        k += 1
    return f"{value}_{k}"


@fixer("R020", "rename-duplicate-id", safe=True, bound="moves nothing")
def rename_duplicate_id(ws: Workspace, findings: list[Finding]) -> Iterator[Repair | Skip]:
    """Gives an object, bridge, tunnel or signal that repeats an id of its class an id of its own, where nothing in
    the file refers to that id (no ``<control signalId>``, ``<signalReference>``, ``<objectReference>``,
    ``<dependency>``, ``<reference>``, ``<vmsBoardReference>`` names it).

    The first element keeps the id; a reference could not have told the two apart anyway. The new id is the class's
    largest whole-number id plus one (where its ids are whole numbers), else the old id with a suffix. Nothing moves
    and no route changes.
    """
    referred = {e.get(attr) for e in ws.text.elements for tag, attr in REFERENCES.items() if e.tag == tag}
    taken: dict[str, set[str]] = {}
    for finding in findings:
        found = [e for e in ws.text.at_line(finding.line or 0) if e.tag in CLASSES and e.get("id") is not None]
        if len(found) != 1:
            continue
        element, value = found[0], found[0].get("id") or ""
        if value in referred:
            yield Skip(
                finding, f"the id {value!r} is referred to elsewhere in the file; which element is meant is unclear"
            )
            continue
        ids = taken.setdefault(element.tag, {e.get("id") or "" for e in _class_members(ws, element.tag)})
        new = _fresh(ids, value)
        ids.add(new)
        yield Repair(
            (finding,),
            (set_attribute(ws.text, element, "id", new),),
            f"{element.tag} {value!r} repeated (road {finding.road}): renamed to {new!r}",
        )
