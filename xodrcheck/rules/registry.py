"""The rule registry: every finding xodrcheck can report has a rule here, with a stable code.

Two kinds of rule share one registry:

* *reader rules* (``check is None``) are emitted while the file is read (XML, attributes, structure);
* *check rules* are functions of a :class:`~xodrcheck.rules.shared.context.Context` yielding findings.

Each rule's docstring carries a passing and a failing example; ``xodrcheck rules`` prints them.

A rule names the checker rules of the standard (ASAM OpenDRIVE 1.9.0 Annex F, :mod:`xodrcheck.standard`) it
enforces by their UIDs. A UID applies to a file only from the standard version in the UID on: a finding tagged with a
UID that does not apply to the file is dropped, and a rule none of whose UIDs applies is not run, unless the rule is
marked ``every_version`` (the project's own rule, which the annex later wrote down: it keeps checking older files,
without claiming the UID there).

Every finding states its basis (:attr:`Finding.basis <xodrcheck.findings.Finding.basis>`): the UID it enforces, or,
for a finding without one, the ``basis`` its rule declares (:class:`~xodrcheck.findings.Basis`: ``schema``,
``reading`` or ``plausibility``). A rule that can give a finding without a UID (it has none, passes :data:`NO_UID`,
or runs on files older than its UIDs) declares it; one whose findings always name a UID needs none.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from xodrcheck.findings import Basis, Category, Finding, Severity

CheckFn = Callable[..., Iterable[Finding]]

#: ``uid`` of a finding that enforces none of its rule's UIDs (a rule with one UID names it by default).
NO_UID = ""


@dataclass(frozen=True)
class Rule:
    """A rule of the checker: stable code, name, category, severity, documentation and, for a check rule, its
    function."""

    code: str
    name: str
    category: Category
    severity: Severity
    doc: str
    check: CheckFn | None = None
    #: Annex F UIDs this rule enforces (in full unless listed in ``partial``).
    uids: tuple[str, ...] = ()
    #: UIDs enforced only in part: UID -> what is not checked, in words.
    partial: Mapping[str, str] = field(default_factory=lambda: MappingProxyType({}))
    #: Run on files older than the rule's UIDs too (without claiming the UIDs there).
    every_version: bool = False
    #: What the rule's findings without a UID rest on (:class:`~xodrcheck.findings.Basis`); ``None`` for a rule whose
    #: findings always name a UID.
    basis: str | None = None

    def __post_init__(self) -> None:
        if self.basis is not None and self.basis not in Basis.ALL:
            raise ValueError(f"rule {self.code}: basis {self.basis!r} is not one of {', '.join(Basis.ALL)}")

    @property
    def summary(self) -> str:
        """The documentation's first sentence, whole, as plain text."""
        from xodrcheck.rules.shared.plaintext import summary

        return summary(self.doc) if self.doc.strip() else self.name

    def finding(self, message: str, *, severity: Severity | None = None, uid: str | None = None, **where) -> Finding:
        """A finding of this rule; ``where`` takes the :class:`Finding` location fields (road, lane, section_s, s,
        x, y, line). ``uid`` is the Annex F rule the finding enforces; it defaults to the rule's only UID
        (:data:`NO_UID`: none). The finding's basis is its UID, else the rule's declared :attr:`basis`."""
        if uid == NO_UID:
            uid = None
        elif uid is None and len(self.uids) == 1:
            uid = self.uids[0]
        elif uid is not None and uid not in self.uids:
            raise ValueError(f"rule {self.code} does not declare the UID {uid}")
        return Finding(
            code=self.code,
            name=self.name,
            category=self.category,
            severity=self.severity if severity is None else severity,
            message=message,
            rule_uid=uid,
            basis=uid if uid is not None else self.unnamed_basis(),
            **where,
        )

    def unnamed_basis(self) -> str:
        """The basis of this rule's findings that name no UID (its declared :attr:`basis`); a rule that gives such a
        finding without declaring one is a mistake in the checker."""
        if self.basis is None:
            raise ValueError(f"rule {self.code} gives a finding without a UID but declares no basis")
        return self.basis

    def runs_on(self, version: tuple[int, int] | None) -> bool:
        """Whether the rule applies to a file of this OpenDRIVE version (see the module's version rule)."""
        if self.every_version or not self.uids:
            return True
        from xodrcheck.standard import applies

        return any(applies(uid, version) for uid in self.uids)


#: Every registered rule by its code.
RULES: dict[str, Rule] = {}
#: The code of every registered rule by its name (names are unique, like codes).
NAMES: dict[str, str] = {}


def _register(rule: Rule) -> Rule:
    if rule.code in RULES:
        raise ValueError(f"rule code {rule.code} registered twice")
    if rule.name in NAMES:
        raise ValueError(f"rule name {rule.name} registered twice ({NAMES[rule.name]} and {rule.code})")
    RULES[rule.code] = rule
    NAMES[rule.name] = rule.code
    return rule


def declare(
    code: str,
    name: str,
    category: Category,
    severity: Severity,
    doc: str,
    *,
    uids: Iterable[str] = (),
    partial: Mapping[str, str] | None = None,
    every_version: bool = False,
    basis: str | None = None,
    check: CheckFn | None = None,
) -> Rule:
    """Register a rule and return it: a reader rule (emitted while reading) without ``check``, else the rule
    ``check`` runs (see :func:`rule`, which gives the other keywords' meaning)."""
    return _register(
        Rule(
            code,
            name,
            category,
            severity,
            inspect.cleandoc(doc),
            check,
            _uids(uids, partial),
            MappingProxyType(dict(partial or {})),
            every_version,
            basis,
        )
    )


def rule(
    code: str,
    name: str,
    category: Category,
    severity: Severity,
    *,
    uids: Iterable[str] = (),
    partial: Mapping[str, str] | None = None,
    every_version: bool = False,
    basis: str | None = None,
) -> Callable[[CheckFn], Rule]:
    """Decorator registering a check function as a rule; its docstring is the rule's documentation.

    ``uids`` are the Annex F rules it enforces; ``partial`` maps those it enforces only in part to what it leaves out
    (they are enforced UIDs too); ``every_version`` keeps it running on files older than its UIDs;
    ``basis`` is what its findings without a UID rest on (``schema``, ``reading``, ``plausibility``: see
    :class:`~xodrcheck.findings.Basis`).
    """

    def wrap(fn: CheckFn) -> Rule:
        return declare(
            code,
            name,
            category,
            severity,
            fn.__doc__ or "",
            uids=uids,
            partial=partial,
            every_version=every_version,
            basis=basis,
            check=fn,
        )

    return wrap


def _uids(uids: Iterable[str], partial: Mapping[str, str] | None) -> tuple[str, ...]:
    out = list(dict.fromkeys(uids))
    out.extend(uid for uid in (partial or {}) if uid not in out)
    return tuple(out)
