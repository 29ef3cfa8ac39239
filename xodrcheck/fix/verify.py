"""Whether repairs did what they claim: compare the check before and after edits, finding by finding.

A finding is known by its rule, severity and place (road, lane, lane section, ``s`` to the millimetre, and line), its
line taken back to the line it had before the edits (:class:`~xodrcheck.fix.edits.LineMap`). The message is left out:
messages quote lines and measures that edits elsewhere move. A repair holds when every finding it claims is gone and
no finding is new.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from xodrcheck.findings import Finding
from xodrcheck.fix.edits import LineMap
from xodrcheck.fix.registry import Repair

__all__ = ["Verdict", "key", "place_key", "verify"]

Key = tuple


def place_key(f: Finding) -> Key:
    """A finding's rule and place without its line (what stays when lines move)."""
    section = None if f.section_s is None else round(f.section_s, 6)
    s = None if f.s is None else round(f.s, 3)
    return (f.code, f.road, f.lane, section, s)


def key(f: Finding, line: int | None = None) -> Key:
    return (*place_key(f), f.severity, f.line if line is None else line)


@dataclass(frozen=True, slots=True)
class Verdict:
    """The repairs whose claimed findings remain, and the findings that are new (each with its line before the
    edits, in ``new_lines``)."""

    unresolved: tuple[Repair, ...]
    new: tuple[Finding, ...]
    new_lines: tuple[int | None, ...] = ()

    @property
    def ok(self) -> bool:
        return not self.unresolved and not self.new


def verify(before: Sequence[Finding], after: Iterable[Finding], lines: LineMap, repairs: Sequence[Repair]) -> Verdict:
    """Judge ``repairs`` by the findings ``before`` and ``after`` their edits (``lines`` maps lines back)."""
    old = Counter(key(f) for f in before)
    new_keys: Counter = Counter()
    mapped: dict[Key, Finding] = {}
    for f in after:
        k = key(f, lines.old_line(f.line))
        new_keys[k] += 1
        mapped.setdefault(k, f)
    claimed = Counter(key(f) for r in repairs for f in r.findings)
    unresolved = tuple(r for r in repairs if any(new_keys[key(f)] > old[key(f)] - claimed[key(f)] for f in r.findings))
    fresh = [k for k, n in new_keys.items() if n > old[k]]
    return Verdict(unresolved, tuple(mapped[k] for k in fresh), tuple(k[-1] for k in fresh))
