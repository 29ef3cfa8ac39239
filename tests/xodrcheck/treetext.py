"""Attribute values of an lxml tree read leniently, for the tests that compare the reader's document with the tree:
what does not parse is ``None`` (the reader reports it; here it only has to agree with the document)."""

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
    """A whitespace-separated list of finite floats; ``()`` when absent, ``None`` when an item does not parse."""
    if text is None:
        return ()
    out = []
    for item in text.split():
        value = number(item)
        if value is None:
            return None
        out.append(value)
    return tuple(out)
