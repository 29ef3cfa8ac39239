"""The table of every element of the file (:class:`~xodrcheck.model.ElementTable`): line, parent and tag in document
order, so that reports can give the XPath of a finding's line without the tree."""

from __future__ import annotations

from array import array

from lxml import etree

from xodrcheck.model import ElementTable


def element_table(root: etree._Element) -> ElementTable:
    """Every element under (and with) ``root``, in document order."""
    lines = array("i")
    parents = array("i")
    tags = array("i")
    names: dict[str, int] = {}
    add_line, add_parent, add_tag = lines.append, parents.append, tags.append
    open_elements = [-1]  # the elements whose end is not reached yet, innermost last
    for event, el in etree.iterwalk(root, events=("start", "end"), tag=etree.Element):
        if event == "start":
            add_line(el.sourceline or 0)
            add_parent(open_elements[-1])
            tag = el.tag
            index = names.get(tag)
            if index is None:
                index = names[tag] = len(names)
            add_tag(index)
            open_elements.append(len(lines) - 1)
        else:
            open_elements.pop()
    return ElementTable(lines, parents, tags, tuple(names))
