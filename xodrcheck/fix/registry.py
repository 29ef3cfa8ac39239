"""The fixes, keyed by the code of the rule whose findings they remove.

A fix is a function of a :class:`~xodrcheck.fix.workspace.Workspace` and the findings of its rule; for each finding
it yields a :class:`Repair` (the edits that remove it, in words) or a :class:`Skip` (why this one is left alone). Its
docstring says what it does and what it may move; :func:`fixable` tells ``xodrcheck rules`` which rules have one.

*Safe* fixes move no geometry beyond the ``position`` tolerance and change no route a vehicle could take; *unsafe*
ones (``--unsafe``) may move geometry up to a stated bound or drop what a route might use, and each repair says what
it moved and by how much.
"""

from __future__ import annotations

import importlib
import inspect
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from xodrcheck.findings import Finding
from xodrcheck.fix.edits import Edit

if TYPE_CHECKING:
    from xodrcheck.fix.workspace import Workspace

__all__ = ["FIXERS", "Fixer", "Repair", "Skip", "fixable", "fixer", "fixers_for", "load_fixers"]

#: The modules holding the fixes, one family each (imported by :func:`load_fixers`).
FAMILIES = (
    "xodrcheck.fix.lane_links",
    "xodrcheck.fix.schema",
    "xodrcheck.fix.junctions",
    "xodrcheck.fix.road_links",
    "xodrcheck.fix.records",
    "xodrcheck.fix.ids",
    "xodrcheck.fix.geometry",
    "xodrcheck.fix.references",
)


@dataclass(frozen=True, slots=True)
class Repair:
    """What one fix does for some findings: ``edits`` that remove them, said in words (``action``, naming roads and
    lanes, not lines: lines move as other repairs land). ``moved`` is the largest distance in metres any point of the
    map's geometry moves (0 for a repair that moves nothing). ``scope`` is the byte span of the element the repair
    changes the meaning of (say, a whole ``<connection>`` whose contact point it sets); a new finding on its lines is
    laid at this repair's door (default: the lines its edits touch)."""

    findings: tuple[Finding, ...]
    edits: tuple[Edit, ...]
    action: str
    moved: float = 0.0
    scope: tuple[int, int] | None = None


@dataclass(frozen=True, slots=True)
class Skip:
    """A finding a fix looked at and left alone, and why."""

    finding: Finding
    reason: str


Plan = Callable[["Workspace", list[Finding]], Iterable["Repair | Skip"]]


@dataclass(frozen=True)
class Fixer:
    """A fix of rule ``code``: ``name`` (kebab-case), ``safe``, ``bound`` (what it may move, in words), the
    documentation (its function's docstring) and ``plan``."""

    code: str
    name: str
    safe: bool
    bound: str
    doc: str
    plan: Plan

    @property
    def summary(self) -> str:
        """The documentation's first sentence."""
        first = self.doc.strip().split("\n\n")[0].replace("\n", " ")
        return first

    @property
    def kind(self) -> str:
        return "safe" if self.safe else "unsafe"


#: Rule code -> its fixes, safe ones first.
FIXERS: dict[str, tuple[Fixer, ...]] = {}


def fixer(code: str, name: str, *, safe: bool, bound: str) -> Callable[[Plan], Fixer]:
    """Decorator registering a fix of rule ``code``; the function's docstring is its documentation."""

    def wrap(fn: Plan) -> Fixer:
        made = Fixer(code, name, safe, bound, inspect.cleandoc(fn.__doc__ or name), fn)
        known = FIXERS.get(code, ())
        if any(f.name == name for f in known):
            raise ValueError(f"fix {name} of rule {code} registered twice")
        FIXERS[code] = tuple(sorted((*known, made), key=lambda f: not f.safe))
        return made

    return wrap


def load_fixers() -> dict[str, tuple[Fixer, ...]]:
    """Every fix, by rule code (imports the families once)."""
    for module in FAMILIES:
        importlib.import_module(module)
    return FIXERS


def fixers_for(code: str) -> tuple[Fixer, ...]:
    return load_fixers().get(code, ())


def fixable(code: str) -> str | None:
    """``"safe"``, ``"unsafe"`` or ``"safe+unsafe"`` for a rule with fixes of those kinds; ``None`` without one."""
    kinds = sorted({f.kind for f in fixers_for(code)})
    return "+".join(kinds) if kinds else None
