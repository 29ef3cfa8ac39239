"""A finding's verdict under a profile: which Annex F rules apply to the file's version, and how severe the standard's
words let a finding be.

Rules declare a severity; the engine judges each finding once, here, after the rule gave it:

* a finding of an Annex F rule that does not apply to the file's version is dropped, or, for a rule that runs on
  every version, kept without the UID, resting on the rule's declared basis (by default ``plausibility``: the checker
  applies a rule the standard wrote down only later);
* under a capped profile (``default``) its severity is bounded by the standard's words: an Annex F rule worded
  "should" gives at most a warning, "may" at most an info (the levels of ``annex_f.tsv``), and the checker's own
  plausibility checks at most a warning. "Shall" rules, the schema and reading keep the rule's severity, and so do
  the engine's findings of an incomplete check. A rule that chooses a severity per finding (by version, by how far a
  joint is off) keeps that choice; the bound comes on top.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable, Iterator, Mapping

from xodrcheck.config import Profile
from xodrcheck.findings import Basis, Finding, Severity
from xodrcheck.rules.registry import Rule
from xodrcheck.standard import annex_rules, applies

__all__ = ["bound", "judge", "judged"]

#: The most severe a finding may be, by its Annex F rule's level or by its basis (absent: not bounded).
_LEVEL_BOUND = {"should": Severity.WARNING, "may": Severity.INFO}
_BASIS_BOUND = {Basis.PLAUSIBILITY: Severity.WARNING}


def bound(finding: Finding) -> Severity | None:
    """The most severe the standard's words let ``finding`` be; ``None``: the rule's severity stands."""
    if finding.rule_uid is None:
        return _BASIS_BOUND.get(finding.basis)
    rule = annex_rules().get(finding.rule_uid)
    return None if rule is None else _LEVEL_BOUND.get(rule.level)


def judge(finding: Finding, version: tuple[int, int] | None, rules: Mapping[str, Rule], profile: Profile):
    """``finding`` of a file of ``version`` as the profile judges it (see the module's docstring); ``None``: dropped,
    its rule of the standard does not apply to the file."""
    f = finding
    if f.rule_uid is not None and not applies(f.rule_uid, version):
        rule = rules.get(f.code)
        if rule is None or not rule.every_version:
            return None
        f = dataclasses.replace(f, rule_uid=None, basis=rule.basis or Basis.PLAUSIBILITY)
    if profile.capped:
        most = bound(f)
        if most is not None and f.severity > most:
            f = dataclasses.replace(f, severity=most)
    return f


def judged(
    findings: Iterable[Finding], version: tuple[int, int] | None, rules: Mapping[str, Rule], profile: Profile
) -> Iterator[Finding]:
    """:func:`judge` of each finding, those dropped left out."""
    for f in findings:
        out = judge(f, version, rules, profile)
        if out is not None:
            yield out
