"""The ids a file defines and names, as written: what the rules on ids read (Annex F ``ids``, ``R020`` and ``R021``).

The classes and references are those the 1.8.1 schema declares keys for (objects, bridges, tunnels, signals,
controllers, junction groups, stations, platforms, switches, vmsGroups) plus the references it leaves out (object
references, signal dependencies and references, junction controllers, junction group members), so that files of
every version are held to them, not only those the 1.8 schema validates.

The reader records every element at one of these paths (:class:`IdTable`), also where the document holds no record
of it: inside a road or junction without an id, in a road's second ``<objects>`` or ``<signals>``. An id written twice
is written twice wherever it stands, and a reference names an id wherever it stands.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

__all__ = ["ID_CLASSES", "ID_REFERENCES", "RECORDED", "SIGNAL_LINKS", "SIGNS", "IdElement", "IdTable"]

#: Class name -> path of its elements below ``<OpenDRIVE>`` (local names; ids unique file-wide, as in the 1.8.1
#: schema's keys).
ID_CLASSES = {
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
ID_REFERENCES = (
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

#: The signs of static boards (their ids are signal ids a reference may name) and a signal's ``<reference>``s.
SIGNS = "road/signals/signal/staticBoard/sign"
SIGNAL_LINKS = "road/signals/signal/reference"


def _recorded() -> dict[str, tuple[str, ...]]:
    out: dict[str, list[str]] = {"road": ["id"], "junction": ["id"], SIGNS: ["id"]}
    out[SIGNAL_LINKS] = ["elementType", "elementId"]
    for path in ID_CLASSES.values():
        out.setdefault(path, []).append("id")
    for path, attribute, _, _ in ID_REFERENCES:
        if attribute not in out.setdefault(path, []):
            out[path].append(attribute)
    return {path: tuple(names) for path, names in out.items()}


#: Path -> the attributes the reader records of each element there.
RECORDED = _recorded()


@dataclass(frozen=True, slots=True)
class IdElement:
    """An element at a path of :data:`RECORDED`: its id attributes as written (those it gives), its line and the id
    of the road it stands in (``None``: in no road, or in one without an id)."""

    path: str
    line: int
    road: str | None
    values: tuple[tuple[str, str], ...] = ()

    @property
    def tag(self) -> str:
        return self.path.rpartition("/")[2]

    def get(self, name: str) -> str | None:
        """Attribute ``name`` as written (``None``: not given)."""
        for key, text in self.values:
            if key == name:
                return text
        return None


@dataclass(frozen=True)
class IdTable:
    """The elements of each path of :data:`RECORDED` that the file has, in file order."""

    elements: Mapping[str, tuple[IdElement, ...]] = field(default_factory=dict)

    def at(self, path: str) -> tuple[IdElement, ...]:
        return self.elements.get(path, ())
