"""Structures: what each junction of a map is part of, recognised from the file alone, with its kind's own measures.

A *structure* is a junction, or several junctions together, that a driver meets as one thing. Its *kind* is one of
:data:`KINDS`: an ordinary ``junction``, or a special layout with its own measures (a ``fork`` or merge: one road
splitting into two, or two joining; a ``ramp``: an exit or entry lane leaving or joining a road; a ``roundabout``...).
Like :mod:`xodrcheck.analysis.metrics`, everything is read from the document the independent reader builds, so a
generated map and a third-party one are classified the same way, and never from what a generator remembers.

Recognition runs the kinds' recognisers in :data:`KINDS` order. Each one looks at the junctions no earlier recogniser
claimed and returns the structures it recognises; the junctions left at the end are each a ``junction``. A kind's
module (``xodrcheck.structures.<name>``) defines ``KIND`` (a :class:`Kind`: its name, meaning and :class:`Measure`
list) and ``recognise(document, free) -> list[Structure]``; adding a kind is adding its module to :data:`MODULES`.
Measure names are unique over all kinds (``junctionart search --where`` and ``junctionart era``'s columns use them
bare); a value that cannot be measured is NaN.
"""

from __future__ import annotations

import importlib
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from xodrcheck.model import Document, Junction

__all__ = [
    "KINDS",
    "MODULES",
    "Kind",
    "Measure",
    "Structure",
    "kind",
    "map_structures",
    "measure_names",
]


@dataclass(frozen=True, slots=True)
class Measure:
    """One measure of a kind: its name, unit, the range a search grid spans (``low`` to ``high`` in ``cells``) and
    what it means."""

    name: str
    unit: str
    low: float
    high: float
    cells: int
    meaning: str


@dataclass(frozen=True, slots=True)
class Kind:
    """A kind of structure: its name, what it is and its measures."""

    name: str
    meaning: str
    measures: tuple[Measure, ...]

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(m.name for m in self.measures)


@dataclass(frozen=True, slots=True)
class Structure:
    """One structure of a map: its kind, the ids of its junctions (file order) and its measures, ``(name, value)`` in
    the kind's order (NaN: not measurable)."""

    kind: str
    junctions: tuple[str, ...]
    values: tuple[tuple[str, float], ...]

    @property
    def measures(self) -> dict[str, float]:
        return dict(self.values)


Recogniser = Callable[[Document, Sequence[Junction]], list[Structure]]

#: Recogniser modules under ``xodrcheck.structures``, in recognition order (a group of junctions first, then the
#: single-junction layouts); ``junction`` (every junction left) is last and always there.
MODULES: tuple[str, ...] = (
    "roundabout",
    "ramp",
    "fork",
    "junction",
)


def _load() -> tuple[tuple[Kind, Recogniser], ...]:
    out = []
    for name in MODULES:
        module = importlib.import_module(f"{__name__}.{name}")
        out.append((module.KIND, module.recognise))
    return tuple(out)


_RECOGNISERS = _load()
#: Every kind, in recognition order.
KINDS: tuple[Kind, ...] = tuple(k for k, _ in _RECOGNISERS)
_BY_NAME = {k.name: k for k in KINDS}
_seen: dict[str, str] = {}
for _k in KINDS:
    for _m in _k.measures:
        if _seen.setdefault(_m.name, _k.name) != _k.name:  # pragma: no cover - a mistake in a kind's module
            raise RuntimeError(f"measure {_m.name!r} of kind {_k.name!r} is already {_seen[_m.name]!r}'s")


def kind(name: str) -> Kind:
    """The kind called ``name``; ``KeyError`` listing the kinds when there is none."""
    try:
        return _BY_NAME[name]
    except KeyError:
        raise KeyError(f"unknown kind {name!r}; kinds: {', '.join(_BY_NAME)}") from None


def measure_names() -> tuple[str, ...]:
    """Every measure name of every kind, kinds in :data:`KINDS` order."""
    return tuple(m.name for k in KINDS for m in k.measures)


def map_structures(document: Document) -> tuple[Structure, ...]:
    """Every structure of ``document``, ordered by their first junction in file order; each junction is in exactly
    one."""
    free = list(document.junctions)
    found: list[Structure] = []
    for _, recognise in _RECOGNISERS:
        if not free:
            break
        made = recognise(document, tuple(free))
        claimed = {j for s in made for j in s.junctions}
        found += made
        free = [j for j in free if j.id not in claimed]
    order = {j.id: k for k, j in enumerate(document.junctions)}
    return tuple(sorted(found, key=lambda s: min((order.get(j, math.inf) for j in s.junctions), default=math.inf)))
