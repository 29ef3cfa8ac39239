"""The compiled fast path of the reader, when the optional ``xodrcheck-speedups`` module is installed.

``speedups/`` (C: module.c, values.c, planview.c, lanes.c) builds a road's plan view, its cubic profiles and its
``<lanes>`` straight from libxml2's tree, without an lxml proxy per element, when every record there reads without a
finding; for anything else it answers ``None`` and the Python reader builds that part, findings and all. Its records
are made by the reader's own constructors from the read's own number cache, so the model is the same value for value
(checked on every corpus file by ``tests/xodrcheck/test_reader_fast.py``); only the time differs (about half the
model build of a CARLA town).

Each function here is ``None`` when the module is missing, was built for another layout of lxml's elements (checked
on import), or ``XODRCHECK_PURE_READER=1`` is set (to rule the compiled path out when hunting a reader problem).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import Any

from lxml import etree

from xodrcheck.model import PRange
from xodrcheck.reader import construct

#: ``plan_view(el, numbers)``, ``profile(el, numbers, tag)``, ``lanes(el, numbers, layered)`` (or ``None``).
plan_view: Callable[..., Any] | None = None
profile: Callable[..., Any] | None = None
lanes: Callable[..., Any] | None = None

#: Why the compiled path is off ("" when it is on; "not loaded" before :func:`load`).
UNAVAILABLE = "not loaded"

_LAYOUT_PROBE = b"<a>\n\n<b/></a>"

#: The compiled module's ``CONTRACT`` this reader was written against (speedups/module.c): a module built from other
#: sources (an older checkout, say) is not used.
CONTRACT = 2


def _layout_matches(module: Any) -> bool:
    """Whether the module reads lxml's elements as lxml does: the node under a known element has its name and line."""
    root = etree.fromstring(_LAYOUT_PROBE)
    return bool(module.node_line(root[0]) == ("b", 3) and module.node_line(root) == ("a", 1))


def load() -> None:
    """Turn the compiled path on when it can be (``xodrcheck.reader`` calls this once its modules are imported)."""
    global UNAVAILABLE
    UNAVAILABLE = _load()


def _load() -> str:
    global plan_view, profile, lanes
    if os.environ.get("XODRCHECK_PURE_READER") == "1":
        return "XODRCHECK_PURE_READER=1 is set"
    try:
        import xodrcheck_speedups as module
    except ImportError:
        return "the xodrcheck-speedups module is not installed (scripts/setup builds it)"
    found = getattr(module, "CONTRACT", "none")
    if found != CONTRACT:
        return f"xodrcheck-speedups has contract {found}, this reader needs {CONTRACT}: rebuild it (scripts/setup)"
    try:
        _configure(module)
    except (TypeError, ValueError, AttributeError) as exc:  # built for an lxml or a model this one is not
        return f"xodrcheck-speedups does not fit this installation ({exc}): rebuild it (scripts/setup)"
    if not _layout_matches(module):
        return "xodrcheck-speedups was built for another lxml: rebuild it (scripts/setup)"
    plan_view, profile, lanes = module.plan_view, module.profile, module.lanes
    return ""


def _configure(module: Any) -> None:
    """Hand the module lxml's element class, the reader's number cache, its constructors and its tables."""
    from xodrcheck.model import LaneType
    from xodrcheck.reader.context import REMEMBER, Numbers
    from xodrcheck.reader.lanes import LANE_TYPES  # here: lanes and roads import this module
    from xodrcheck.reader.roads import P_RANGES

    # the exact spellings the Python reader maps without a finding: lower case, and the standard's own (offRamp...)
    lane_types = {**LANE_TYPES, **{t.value: t for t in LaneType if t is not LaneType.UNKNOWN}}
    p_ranges = {**P_RANGES, **{p.value: p for p in PRange}}
    module.configure(
        etree._Element,
        Numbers,
        REMEMBER,
        make_cubic=construct.make_cubic,
        make_line=construct.make_line,
        make_arc=construct.make_arc,
        make_spiral=construct.make_spiral,
        make_poly3=construct.make_poly3,
        make_param_poly3=construct.make_param_poly3,
        make_road_mark=construct.make_road_mark,
        make_speed=construct.make_speed,
        make_lane_height=construct.make_lane_height,
        make_lane=construct.make_lane,
        make_lane_section=construct.make_lane_section,
        lane_types=lane_types,
        p_ranges=p_ranges,
    )
