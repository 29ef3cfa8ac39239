"""The engine's own rules: what :func:`xodrcheck.check` reports about running the other rules."""

from __future__ import annotations

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.rules.registry import declare

RULE_CRASHED = declare(
    "X900",
    "rule-crashed",
    Category.XML,
    Severity.ERROR,
    """A rule raised an exception instead of reporting; the file could not be fully checked.

    This is a fault of xodrcheck, not necessarily of the file: please report it with the file. The finding names the
    rule and the exception; the other rules still ran. The check is incomplete: ``xodrcheck check`` exits with 3 when
    nothing else failed.

    Passing example: any file on which every rule runs to its end.

    Failing example: a file that makes a rule raise (there is none known; each such file is a bug to fix).
    """,
    basis=Basis.INCOMPLETE,
)

RULE_OUT_OF_TIME = declare(
    "X901",
    "rule-out-of-time",
    Category.XML,
    Severity.ERROR,
    """A rule was not run, or was stopped part way, because the check's time bound (tolerance ``time_budget``) was
    reached: the check is incomplete. A stopped rule keeps the findings it gave before.

    There is no time bound unless one is set (``time_budget`` is 0 by default), so a verdict never depends on how fast
    the machine is. A bound set with ``--tolerance time_budget=600`` (or in a configuration file) trades completeness
    for time: what was not checked is not known to be right, so this finding is an error and ``xodrcheck check`` exits
    with 3 ("incomplete") when nothing else failed.

    Passing example: any file checked without a time bound, or whose rules all finish within it.

    Failing example: a map of several hundred megabytes checked with ``--tolerance time_budget=1``.
    """,
    basis=Basis.INCOMPLETE,
)

#: Codes of the engine's own findings: a report with one of them is incomplete.
ENGINE_CODES = frozenset({RULE_CRASHED.code, RULE_OUT_OF_TIME.code})
