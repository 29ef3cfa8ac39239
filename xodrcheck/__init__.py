"""xodrcheck: an independent OpenDRIVE reader and checker.

Point it at any ``.xodr`` from any tool::

    import xodrcheck

    result = xodrcheck.read("map.xodr")  # ReadResult: .document (typed model, or None) and .findings
    report = xodrcheck.check("map.xodr")  # Report: .ok, .complete, .findings (every rule run)
    xodrcheck.is_valid("map.xodr")  # True or False; is_valid_reason(path) says why not, in words

Every error xodrcheck raises on purpose derives from :class:`XodrError` (``ReadError``: the input cannot be read at
all; ``ConfigError``: a bad configuration or tolerance; ``OutputError``: an output file cannot be written). Problems
*in* a map are never raised: they are :class:`Finding` s of the report.

The other names load on first use (PEP 562), so ``import xodrcheck`` and the command line start fast.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

# Eager: the submodule xodrcheck.check shares its name with the function, and importing a submodule binds the
# package attribute to the module, so the function must be bound after it, here.
from xodrcheck.check import Report, check, is_valid, is_valid_reason

if TYPE_CHECKING:
    from xodrcheck.atomic import OutputError
    from xodrcheck.config import Config, ConfigError, Tolerances
    from xodrcheck.findings import Category, Finding, ReadError, Severity, XodrError
    from xodrcheck.model import Document, LaneKey
    from xodrcheck.reader import ReadResult, read

#: Public name -> module that defines it.
_EXPORTS = {
    "Category": "xodrcheck.findings",
    "Config": "xodrcheck.config",
    "ConfigError": "xodrcheck.config",
    "Document": "xodrcheck.model",
    "Finding": "xodrcheck.findings",
    "LaneKey": "xodrcheck.model",
    "OutputError": "xodrcheck.atomic",
    "ReadError": "xodrcheck.findings",
    "ReadResult": "xodrcheck.reader",
    "Severity": "xodrcheck.findings",
    "Tolerances": "xodrcheck.config",
    "XodrError": "xodrcheck.findings",
    "read": "xodrcheck.reader",
}

__all__ = [
    "Category",
    "Config",
    "ConfigError",
    "Document",
    "Finding",
    "LaneKey",
    "OutputError",
    "ReadError",
    "ReadResult",
    "Report",
    "Severity",
    "Tolerances",
    "XodrError",
    "check",
    "is_valid",
    "is_valid_reason",
    "read",
]


def __getattr__(name: str) -> Any:
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'xodrcheck' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_EXPORTS))
