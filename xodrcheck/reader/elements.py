"""The table of every element of the file (:class:`~xodrcheck.model.ElementTable`): line, number of children and tag
in document order, so that reports can give the XPath of a finding's line without the tree."""

from __future__ import annotations

from array import array

from lxml import etree

from xodrcheck.model import ElementTable


def element_table(root: etree._Element) -> ElementTable:
    """Every node under (and with) ``root``, in document order, in one pass of the tree's own iteration straight into
    the arrays (a list of tuples would hold about 100 bytes a node beside the tree while it is built); the parents
    follow from the child counts."""
    lines, counts, tags = array("i"), array("i"), array("i")
    names: dict[object, int] = {}
    number = names.setdefault
    for el in root.iter():
        lines.append(el.sourceline or 0)
        counts.append(len(el))
        tags.append(number(el.tag, len(names)))
    # an entity reference a recovering parse kept is a node without a tag name of its own
    tag_names = tuple(name if isinstance(name, str) else "node()" for name in names)
    return ElementTable(lines, counts, tags, tag_names)
