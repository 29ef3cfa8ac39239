"""Findings: what the reader and the rules say about a file, with where and why."""

from __future__ import annotations

import enum
from dataclasses import dataclass

__all__ = ["Basis", "Category", "Finding", "OutOfTime", "ReadError", "Severity", "XodrError"]


class Severity(enum.IntEnum):
    """Ordered so that ``max()`` gives the worst."""

    INFO = 0
    WARNING = 1
    ERROR = 2

    def __str__(self) -> str:
        return self.name.lower()


class Category(enum.Enum):
    XML = "xml"
    SCHEMA = "schema"
    REFERENCE = "reference"
    LINK = "link"
    LANE = "lane"
    GEOMETRY = "geometry"
    CURVATURE = "curvature"
    JUNCTION = "junction"
    OVERLAP = "overlap"
    HEADER = "header"
    OBJECT = "object"
    SIGNAL = "signal"
    RAILROAD = "railroad"
    SURFACE = "surface"
    SIGNAL_CONTROL = "signal-control"

    def __str__(self) -> str:
        return self.value


class Basis:
    """What a finding rests on (:attr:`Finding.basis`) when it names no Annex F rule; one that does rests on its UID.

    * ``schema``: the XSD of the file's declared OpenDRIVE version (an element or attribute it requires or forbids);
    * ``reading``: the file cannot be read as OpenDRIVE as it is written (not well-formed XML, a value that is not a
      number, a root that is not ``<OpenDRIVE>``, ...);
    * ``plausibility``: the checker's own judgement, which the standard does not state (a minimum radius, the
      JunctionArt paper's junction rules, overlaps the standard does not forbid, an Annex F rule applied to a file
      older than the rule): a warning at most under the default profile;
    * ``incomplete``: the check itself did not run to its end (a rule crashed or ran out of time), so the file is
      not known to be right.
    """

    SCHEMA = "schema"
    READING = "reading"
    PLAUSIBILITY = "plausibility"
    INCOMPLETE = "incomplete"
    #: Every basis a finding without a UID can have.
    ALL = (SCHEMA, READING, PLAUSIBILITY, INCOMPLETE)


@dataclass(frozen=True, slots=True)
class Finding:
    """One problem found in a file.

    ``code`` is stable (e.g. ``X101``); ``name`` is its kebab-case name. ``road``/``lane``/``s``/``x``/``y``/``z`` say
    where on the map, ``line`` where in the file; each is ``None`` where it does not apply. ``lane`` is the lane id;
    with ``section_s`` it completes the :class:`~xodrcheck.model.LaneKey`. ``rule_uid`` names the rule of the
    standard's Annex F that the finding enforces, where there is one; ``basis`` says what the finding rests on: that
    UID, or one of :class:`Basis` (``schema``, ``reading``, ``plausibility``, ``incomplete``). The engine fills it in
    from the rule's declaration (:meth:`xodrcheck.rules.registry.Rule.finding`).
    """

    code: str
    name: str
    category: Category
    severity: Severity
    message: str
    road: str | None = None
    lane: int | None = None
    section_s: float | None = None
    s: float | None = None
    x: float | None = None
    y: float | None = None
    line: int | None = None
    #: The ASAM OpenDRIVE Annex F rule this finding enforces (e.g.
    #: ``asam.net:xodr:1.7.0:road.lane.link.zero_width_at_start``); ``None`` for the project's own rules.
    rule_uid: str | None = None
    z: float | None = None
    #: What the finding rests on: its ``rule_uid`` when it has one, else a :class:`Basis` value. Given empty, it is
    #: the UID, or ``plausibility`` for a finding built by hand without one.
    basis: str = ""

    def __post_init__(self) -> None:
        if self.rule_uid is not None:
            if self.basis != self.rule_uid:
                object.__setattr__(self, "basis", self.rule_uid)
        elif not self.basis:
            object.__setattr__(self, "basis", Basis.PLAUSIBILITY)
        elif self.basis not in Basis.ALL:
            raise ValueError(f"a finding without a UID rests on one of {', '.join(Basis.ALL)}, not {self.basis!r}")


class XodrError(Exception):
    """Base of every error xodrcheck raises on purpose (one hierarchy, as in shapely)."""


class ReadError(XodrError):
    """The input cannot be read at all (missing file, not a file, too large to be an OpenDRIVE file).

    ``reason`` says why and ``path`` names the file (``None`` for bytes); the message names both:
    ``cannot read maps/a.xodr: no such file``."""

    def __init__(self, reason: str, path: str | None = None) -> None:
        super().__init__(f"cannot read {path}: {reason}" if path is not None else reason)
        self.reason = reason
        self.path = path


class OutOfTime(XodrError):
    """A long computation stopped because the check's time budget (tolerance ``time_budget``) was spent; the
    argument says what was being done."""
