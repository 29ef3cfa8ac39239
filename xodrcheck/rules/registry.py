"""The rule registry: every finding xodrcheck can report has a rule here, with a stable code.

Two kinds of rule share one registry:

* *reader rules* (``check is None``) are emitted while the file is read (XML, attributes, structure);
* *check rules* are functions of a :class:`~xodrcheck.rules.context.Context` yielding findings.

Each rule's docstring carries a passing and a failing example; ``xodrcheck rules`` prints them.
"""

from __future__ import annotations

import inspect
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from xodrcheck.findings import Category, Finding, Severity

CheckFn = Callable[..., Iterable[Finding]]


@dataclass(frozen=True)
class Rule:
    code: str
    name: str
    category: Category
    severity: Severity
    doc: str
    check: CheckFn | None = None

    @property
    def summary(self) -> str:
        return self.doc.strip().splitlines()[0] if self.doc.strip() else self.name

    def finding(self, message: str, *, severity: Severity | None = None, **where) -> Finding:
        """A finding of this rule; ``where`` takes the :class:`Finding` location fields (road, lane, section_s, s,
        x, y, line)."""
        return Finding(
            code=self.code,
            name=self.name,
            category=self.category,
            severity=self.severity if severity is None else severity,
            message=message,
            **where,
        )


RULES: dict[str, Rule] = {}
_NAMES: dict[str, str] = {}


def _register(rule: Rule) -> Rule:
    if rule.code in RULES:
        raise ValueError(f"rule code {rule.code} registered twice")
    if rule.name in _NAMES:
        raise ValueError(f"rule name {rule.name} registered twice ({_NAMES[rule.name]} and {rule.code})")
    RULES[rule.code] = rule
    _NAMES[rule.name] = rule.code
    return rule


def declare(code: str, name: str, category: Category, severity: Severity, doc: str) -> Rule:
    """Register a reader rule (emitted while reading) and return it."""
    return _register(Rule(code, name, category, severity, inspect.cleandoc(doc)))


def rule(code: str, name: str, category: Category, severity: Severity) -> Callable[[CheckFn], Rule]:
    """Decorator registering a check function as a rule; its docstring is the rule's documentation."""

    def wrap(fn: CheckFn) -> Rule:
        return _register(Rule(code, name, category, severity, inspect.cleandoc(fn.__doc__ or ""), fn))

    return wrap
