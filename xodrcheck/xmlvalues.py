"""Attribute values and tag names of OpenDRIVE XML, read leniently: what does not parse is ``None``.

The rules that read the XML (``ctx.tree``) share these; the reader and S001 report bad values, so here they only
turn into ``None``.
"""

from __future__ import annotations

import math

from lxml import etree


def local(element: etree._Element) -> str:
    """An element's tag without its namespace ('' for comments and processing instructions)."""
    return etree.QName(element).localname if isinstance(element.tag, str) else ""


def number(text: str | None) -> float | None:
    """A finite float from an attribute, or ``None``."""
    if text is None:
        return None
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def integer(text: str | None) -> int | None:
    """An integer from an attribute, or ``None``."""
    if text is None:
        return None
    try:
        return int(text)
    except ValueError:
        return None


def numbers(text: str | None) -> tuple[float, ...] | None:
    """A whitespace-separated list of finite floats (``t_junction_grid_position_list``); ``()`` when absent,
    ``None`` when an item does not parse."""
    if text is None:
        return ()
    out = []
    for item in text.split():
        value = number(item)
        if value is None:
            return None
        out.append(value)
    return tuple(out)
