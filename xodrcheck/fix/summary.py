"""What a fix did to one file, in lines a person reads: per rule, how many findings were fixed and how many are
left and why; what each unsafe repair moved; what was rolled back."""

from __future__ import annotations

from collections import Counter, defaultdict

from xodrcheck.findings import Severity
from xodrcheck.fix.result import FixResult

__all__ = ["summary_lines"]


def _reasons(reasons: Counter[str]) -> str:
    parts = [f"{why} ({n})" if len(reasons) > 1 else why for why, n in reasons.most_common(3)]
    more = len(reasons) - 3
    return "; ".join(parts) + (f"; and {more} other reason(s)" if more > 0 else "")


def summary_lines(result: FixResult, name: str, least: Severity = Severity.WARNING) -> list[str]:
    """The summary of ``result`` for the file shown as ``name``; rules whose findings left are all below ``least``
    are counted in the last line only."""
    fixed = result.fixed()
    names = {f.code: f.name for a in result.applied for f in a.repair.findings}
    left: dict[str, Counter[str]] = defaultdict(Counter)
    worst: dict[str, Severity] = {}
    for finding, why in result.remaining:
        names.setdefault(finding.code, finding.name)
        left[finding.code][why] += 1
        worst[finding.code] = max(worst.get(finding.code, Severity.INFO), finding.severity)
    report = result.report
    head = (
        f"{name}: {sum(fixed.values())} finding(s) fixed, {len(result.rolled_back)} repair(s) rolled back; left "
        f"{report.errors} error(s), {report.warnings} warning(s), {report.count(Severity.INFO)} info"
    )
    lines = [head]
    width = max((len(n) for n in names.values()), default=0)
    kinds = {a.repair.findings[0].code: a.fixer for a in result.applied if a.repair.findings}
    for code in sorted(fixed):
        fx = kinds.get(code)
        how = f"  ({fx.name}, {fx.kind})" if fx is not None else ""
        lines.append(f"  fixed  {code} {names[code]:<{width}} {fixed[code]:>6}{how}")
    quiet = 0
    for code in sorted(left, key=lambda c: (-worst[c], c)):
        count = sum(left[code].values())
        if worst[code] < least:
            quiet += count
            continue
        lines.append(f"  left   {code} {names[code]:<{width}} {count:>6}  {worst[code]}: {_reasons(left[code])}")
    for a in result.applied:
        if not a.fixer.safe:
            lines.append(f"  moved  {a.repair.action}: by {a.repair.moved:.3g} m ({a.fixer.name}, unsafe)")
    if quiet:
        lines.append(f"  ({quiet} finding(s) below {least} left, not listed)")
    return lines
