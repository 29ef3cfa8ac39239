"""The verdict of a check in one line: PASS, FAIL or INCOMPLETE, and why.

``FAIL: 3 errors of 2 rules in 1 of 4 files; 12 warnings, 40 info``; ``PASS: 0 errors; 12 warnings`` for one file.
The word is the exit code's: FAIL (1, or 2 when a file could not be checked), INCOMPLETE (3: a rule crashed or ran
out of time, X900/X901, and nothing else failed), PASS (0). After the first ``;`` come what does not fail the check:
warnings (unless ``--strict``) and infos, each left out when there is none.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from xodrcheck.findings import Finding, Severity

if TYPE_CHECKING:  # pragma: no cover
    from xodrcheck.check import Report

__all__ = ["count", "failing", "stopped", "verdict"]


def count(n: int, word: str) -> str:
    """``1 error``, ``2 errors``; ``info`` has no plural."""
    return f"{n} {word}" if n == 1 or word == "info" else f"{n} {word}s"


def failing(report: Report) -> list[Finding]:
    """The findings that fail ``report``'s check: errors, and warnings too in strict mode."""
    worst = Severity.WARNING if report.strict else Severity.ERROR
    return [f for f in report.findings if f.severity >= worst]


def stopped(report: Report) -> list[Finding]:
    """The findings that say a rule did not run to its end (X900, X901)."""
    from xodrcheck.rules.internal import ENGINE_CODES

    return [f for f in report.findings if f.code in ENGINE_CODES]


def _failed(findings: Sequence[Finding], strict: bool) -> str:
    """``3 errors``; in strict mode ``2 errors and 1 warning``, ``1 warning`` or ``0 errors, 0 warnings``."""
    errors = sum(1 for f in findings if f.severity is Severity.ERROR)
    if not strict:
        return count(errors, "error")
    parts = [count(errors, "error"), count(len(findings) - errors, "warning")]
    return " and ".join(p for p in parts if not p.startswith("0 ")) or ", ".join(parts)


def _of(k: int, n: int) -> str:
    """``1 of 4 files``; ``1 of 1 file``."""
    return f"{k} of {n} {'file' if n == 1 else 'files'}"


def _stopped(incomplete: Sequence[Report], n: int, several: bool) -> str:
    rules = sum(len(stopped(r)) for r in incomplete)
    where = f" in {_of(len(incomplete), n)}" if several else ""
    return f"{count(rules, 'rule')} did not run to {'its' if rules == 1 else 'their'} end{where} (X900/X901)"


def verdict(reports: Sequence[Report], unreadable: int = 0) -> str:
    """One line: the verdict over ``reports`` and ``unreadable`` files that could not be checked at all."""
    from xodrcheck.rules.internal import ENGINE_CODES

    n, several = len(reports), len(reports) + unreadable > 1
    strict = any(r.strict for r in reports)
    real = {id(r): [f for f in failing(r) if f.code not in ENGINE_CODES] for r in reports}
    failed = [r for r in reports if real[id(r)]]
    every = [f for r in failed for f in real[id(r)]]
    incomplete = [r for r in reports if not r.complete]
    word = "FAIL" if unreadable or failed else "INCOMPLETE" if incomplete else "PASS"

    clauses = []
    if unreadable:
        clauses.append(f"{_of(unreadable, n + unreadable) if n else count(unreadable, 'file')} could not be checked")
    main = _failed(every, strict)
    if every:
        main += " of " + count(len({f.code for f in every}), "rule") + (f" in {_of(len(failed), n)}" if several else "")
    elif several:
        main += " in " + count(n, "file")
    main += " (strict)" if strict else ""
    if word == "INCOMPLETE":
        no_other = "no other error" + (" or warning" if strict else "")
        clauses += [f"{_stopped(incomplete, n, several)}, so the verdict is not known", no_other]
    elif n:
        clauses += [main, *([f"incomplete: {_stopped(incomplete, n, several)}"] if incomplete else [])]
    rest = [] if strict else [count(sum(r.count(Severity.WARNING) for r in reports), "warning")]
    rest.append(count(sum(r.count(Severity.INFO) for r in reports), "info"))
    rest = [part for part in rest if not part.startswith("0 ")]
    return f"{word}: {'; '.join(clauses)}" + (f"; {', '.join(rest)}" if rest else "")
