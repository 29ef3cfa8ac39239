"""Repair what can be repaired in an OpenDRIVE file, safely: ``xodrcheck.fix(path)``, ``xodrcheck fix FILE``.

The flow: :mod:`.xmltext` locates elements in the file's bytes, :mod:`.edits` edits them, the fix families
(:mod:`.lane_links`, :mod:`.schema`, :mod:`.junctions`, :mod:`.road_links`, :mod:`.records`, :mod:`.geometry`,
:mod:`.references`; listed by :mod:`.registry`) plan repairs for the findings of their rules, :mod:`.driver` applies
and checks them again (:mod:`.verify`), and :mod:`.result` gives the fixed bytes with what was done and what is left.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from xodrcheck.fix.result import FixResult, fix

__all__ = ["FixResult", "fix"]


def __getattr__(name: str) -> Any:  # loaded on first use: `xodrcheck rules` reads the registry without the driver
    if name in __all__:
        from xodrcheck.fix import result

        return getattr(result, name)
    raise AttributeError(f"module 'xodrcheck.fix' has no attribute {name!r}")
