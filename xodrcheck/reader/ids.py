"""The elements that define or name ids, as written (:class:`~xodrcheck.model.IdTable`): one walk of the parts of the
tree that hold them, made with the document so that the id rules need no tree."""

from __future__ import annotations

from lxml import etree

from xodrcheck.model import RECORDED, IdElement, IdTable

#: The paths the walk descends: every path of :data:`RECORDED` and the paths above them.
_PREFIXES = frozenset(path.rsplit("/", k)[0] for path in RECORDED for k in range(path.count("/") + 1))


def id_table(root: etree._Element) -> IdTable:
    """Every element under ``root`` (``<OpenDRIVE>``) at a path of :data:`RECORDED`, by path, in file order."""
    found: dict[str, list[IdElement]] = {}
    _walk(root, "", None, found)
    return IdTable({path: tuple(elements) for path, elements in found.items()})


def _walk(el: etree._Element, path: str, road: str | None, out: dict[str, list[IdElement]]) -> None:
    for child in el:
        tag = child.tag
        if not isinstance(tag, str):
            continue
        name = tag.rpartition("}")[2]  # a tag in a namespace the reader keeps counts by its local name
        here = f"{path}/{name}" if path else name
        names = RECORDED.get(here)
        if names is not None:
            values = tuple((key, text) for key in names if (text := child.get(key)) is not None)
            out.setdefault(here, []).append(IdElement(here, child.sourceline or 0, road, values))
        if here in _PREFIXES:
            _walk(child, here, child.get("id") if here == "road" else road, out)
