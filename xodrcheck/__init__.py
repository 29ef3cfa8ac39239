"""xodrcheck: an independent OpenDRIVE reader and checker.

Point it at any ``.xodr`` from any tool::

    import xodrcheck

    result = xodrcheck.read("map.xodr")  # ReadResult: .document (typed model, or None) and .findings
    report = xodrcheck.check("map.xodr")  # Report: .ok, .complete, .findings (every rule run)
    fixed = xodrcheck.fix("map.xodr")  # FixResult: .data (the fixed bytes), .applied, .remaining, .report
    xodrcheck.is_valid("map.xodr")  # True or False; is_valid_reason(path) says why not, in words

Every error xodrcheck raises on purpose derives from :class:`XodrError` (``ReadError``: the input cannot be read at
all; ``ConfigError``: a bad configuration or tolerance; ``OutputError``: an output file cannot be written). Problems
*in* a map are never raised: they are :class:`Finding` s of the report.

Every name loads on first use (PEP 562; ``check`` through the package's module type, :class:`_Package`), so
``import xodrcheck`` and the command line start fast: ``import xodrcheck`` imports no other module of the package.
"""

from __future__ import annotations

import importlib
import sys
from types import ModuleType
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from xodrcheck.check import Report, check, is_valid, is_valid_reason
    from xodrcheck.config import Config, ConfigError, Tolerances
    from xodrcheck.findings import Category, Finding, ReadError, Severity, XodrError
    from xodrcheck.fix import FixResult, fix
    from xodrcheck.model import Document, LaneKey
    from xodrcheck.reader import ReadResult, read
    from xodrcheck.support.atomic import OutputError

#: Public name -> module that defines it.
_EXPORTS = {
    "Category": "xodrcheck.findings",
    "Config": "xodrcheck.config",
    "ConfigError": "xodrcheck.config",
    "Document": "xodrcheck.model",
    "Finding": "xodrcheck.findings",
    "FixResult": "xodrcheck.fix.result",
    "LaneKey": "xodrcheck.model",
    "OutputError": "xodrcheck.support.atomic",
    "ReadError": "xodrcheck.findings",
    "ReadResult": "xodrcheck.reader",
    "Report": "xodrcheck.check",
    "Severity": "xodrcheck.findings",
    "Tolerances": "xodrcheck.config",
    "XodrError": "xodrcheck.findings",
    "is_valid": "xodrcheck.check",
    "is_valid_reason": "xodrcheck.check",
    "read": "xodrcheck.reader",
}

__all__ = [
    "Category",
    "Config",
    "ConfigError",
    "Document",
    "Finding",
    "FixResult",
    "LaneKey",
    "OutputError",
    "ReadError",
    "ReadResult",
    "Report",
    "Severity",
    "Tolerances",
    "XodrError",
    "check",
    "fix",
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
    return sorted(set(globals()) | set(_EXPORTS) | {"check", "fix"})


class _Package(ModuleType):
    """The package's module type: ``xodrcheck.check`` is the function :func:`xodrcheck.check.check` and
    ``xodrcheck.fix`` the function :func:`xodrcheck.fix.fix`, loaded on first use, although the submodule (package)
    of that name binds itself to the package when it is imported (the import system sets the parent's attribute after
    loading a submodule; these properties keep the function there instead)."""

    @property
    def check(self) -> Any:
        override = vars(self).get("_check_function")
        if override is not None:
            return override
        from xodrcheck.check import check

        return check

    @check.setter
    def check(self, value: Any) -> None:
        if isinstance(value, ModuleType) and value.__name__ == f"{__name__}.check":
            return  # the submodule binding itself: the package keeps naming the function
        vars(self)["_check_function"] = value  # an explicit assignment (a test's monkeypatch, say) wins

    @property
    def fix(self) -> Any:
        override = vars(self).get("_fix_function")
        if override is not None:
            return override
        from xodrcheck.fix.result import fix

        return fix

    @fix.setter
    def fix(self, value: Any) -> None:
        if isinstance(value, ModuleType) and value.__name__ == f"{__name__}.fix":
            return  # the sub-package binding itself: the package keeps naming the function
        vars(self)["_fix_function"] = value


sys.modules[__name__].__class__ = _Package
