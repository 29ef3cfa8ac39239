"""The engine's own rules: what :func:`xodrcheck.check` reports about running the other rules."""

from __future__ import annotations

from xodrcheck.findings import Category, Severity
from xodrcheck.rules.registry import declare

RULE_CRASHED = declare(
    "X900",
    "rule-crashed",
    Category.XML,
    Severity.ERROR,
    """A rule raised an exception instead of reporting; the file could not be fully checked.

    This is a fault of xodrcheck, not necessarily of the file: please report it with the file. The finding names the
    rule and the exception; the other rules still ran.

    Passing example: any file on which every rule runs to its end.

    Failing example: a file that makes a rule raise (there is none known; each such file is a bug to fix).
    """,
)

RULE_OUT_OF_TIME = declare(
    "X901",
    "rule-out-of-time",
    Category.XML,
    Severity.WARNING,
    """A rule was not run, or was stopped part way, because the file's time budget (tolerance ``time_budget``) was
    spent. A stopped rule keeps the findings it gave before.

    Raise ``time_budget`` (``--tolerance time_budget=600``) to check large maps completely.

    Passing example: a file whose rules all finish within the budget.

    Failing example: a map of several hundred megabytes checked with ``--tolerance time_budget=1``.
    """,
)
