"""The standard's own rulebook: ASAM OpenDRIVE 1.9.0 Annex F, "Checker rules" (normative).

Every checker rule of the annex has a UID such as ``asam.net:xodr:1.7.0:road.lane.link.zero_width_at_start``:
who declares it, the standard, the version of the standard in which the rule first applies, and the rule's dotted
name. xodrcheck's rules say which UIDs they enforce (``Rule.uids``); each finding names the UID it enforces
(``Finding.rule_uid``). This module holds the annex's list (``annex_f.tsv``, generated from the annex by
``scripts/annex_uids.py``: UIDs, section numbers, normative levels and each rule's description, the sentences a
finding enforces) and the version arithmetic.

Version rule: a UID applies to a file whose header declares OpenDRIVE ``major.minor`` at least the UID's
``major.minor`` (a 1.8.2 rule applies to every 1.8 file: the header has no patch level). 1.4.0 is the annex's oldest
version, the rules every earlier file already followed, so 1.4.0 rules apply to files of every version. One UID of the
annex carries no version (``asam.net:xodr:1.x.0:...``): it is taken to apply from 1.9, the version that lists it.
A file that declares no version is checked against every rule.
"""

from __future__ import annotations

import fnmatch
import functools
import re
from dataclasses import dataclass
from importlib import resources

from xodrcheck.findings import Severity

#: Where the annex is published (each UID's section number is given beside it).
ANNEX_URL = (
    "https://publications.pages.asam.net/standards/ASAM_OpenDRIVE/ASAM_OpenDRIVE_Specification/latest/"
    "specification/16_annexes/map_rules.html"
)
#: The standard version the annex belongs to.
ANNEX_VERSION = (1, 9)
_OLDEST = (1, 4)
_UID = re.compile(r"^(?P<entity>[^:]*):(?P<standard>[^:]*):(?P<version>[^:]*):(?P<name>[^:]+)$")
_LEVEL_SEVERITY = {"shall": Severity.ERROR, "should": Severity.WARNING, "may": Severity.INFO}


@dataclass(frozen=True, slots=True)
class AnnexRule:
    """One checker rule of Annex F: its UID, its section in the annex, its normative level and its description."""

    uid: str
    section: str
    #: ``shall`` (a requirement), ``should`` (a recommendation) or ``may`` (a permission or a plain statement).
    level: str
    #: The annex's words for the rule (plain text): what a finding that names the UID enforces.
    description: str = ""

    @property
    def name(self) -> str:
        """The rule's full dotted name (the UID's last part), e.g. ``road.lane.link.zero_width_at_start``."""
        return self.uid.rsplit(":", 1)[-1]

    @property
    def version(self) -> tuple[int, int]:
        return uid_version(self.uid)

    @property
    def severity(self) -> Severity:
        """The severity the standard's wording gives: shall -> error, should -> warning, may -> info."""
        return _LEVEL_SEVERITY[self.level]


@functools.cache
def annex_rules() -> dict[str, AnnexRule]:
    """Every Annex F rule by UID, in the annex's order."""
    text = (resources.files(__name__) / "annex_f.tsv").read_text(encoding="utf-8")
    out: dict[str, AnnexRule] = {}
    for row in text.splitlines():
        if row and not row.startswith("#"):
            uid, section, level, description = row.split("\t")
            out[uid] = AnnexRule(uid, section, level, description)
    return out


def is_uid(token: str) -> bool:
    """Whether a selector is a rule UID or a UID pattern (it has the UID's ``:`` separators)."""
    return token.count(":") == 3


def uid_version(uid: str) -> tuple[int, int]:
    """The ``(major, minor)`` from which a UID applies (see the module's version rule)."""
    m = _UID.match(uid)
    parts = m.group("version").split(".") if m else []
    try:
        version = (int(parts[0]), int(parts[1]))
    except (IndexError, ValueError):
        return ANNEX_VERSION
    return version


def applies(uid: str, file_version: tuple[int, int] | None) -> bool:
    """Whether the rule ``uid`` applies to a file of ``file_version`` (``None``: the file declares none)."""
    if file_version is None:
        return True
    version = uid_version(uid)
    return version <= _OLDEST or file_version >= version


def uid_matches(pattern: str, uid: str) -> bool:
    """UNIX-style pattern matching on UIDs, as the annex intends (``asam.net:xodr:*:road.lane.*``)."""
    return fnmatch.fnmatchcase(uid, pattern)


__all__ = [
    "ANNEX_URL",
    "ANNEX_VERSION",
    "AnnexRule",
    "annex_rules",
    "applies",
    "is_uid",
    "uid_matches",
    "uid_version",
]
