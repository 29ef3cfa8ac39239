"""Where links meet and how to add one: the two sides of a joint between lane sections (inside a road, or across a
road link both roads make), and the edit that puts a ``<predecessor>`` or ``<successor>`` into an element's
``<link>`` (creating the ``<link>`` as its first child when there is none)."""

from __future__ import annotations

from xodrcheck.fix.edits import Edit, child_indent, insert_child
from xodrcheck.fix.workspace import Workspace
from xodrcheck.fix.xmltext import Element
from xodrcheck.model import ContactPoint, ElementType
from xodrcheck.rules.shared.lane_joints import Side

__all__ = ["across", "add_link"]


def across(ws: Workspace, side: Side) -> Side | None:
    """The side across the joint: the neighbouring lane section of the road, or at a road end the linked road's
    section at the contact point when that road links back (``None`` otherwise: a junction, or one-sided links)."""
    road, index, end = side.road, side.index, side.end
    step = -1 if end is ContactPoint.START else 1
    if 0 <= index + step < len(road.lane_sections):
        return Side(road, index + step, ContactPoint.END if end is ContactPoint.START else ContactPoint.START)
    link = road.link_at(end)
    if link is None or link.element_type is not ElementType.ROAD or link.contact_point is None:
        return None
    target = ws.road(link.element_id)
    if target is None or not target.lane_sections:
        return None
    back = target.link_at(link.contact_point)
    if back is None or back.element_type is not ElementType.ROAD or back.element_id != road.id:
        return None
    other = 0 if link.contact_point is ContactPoint.START else len(target.lane_sections) - 1
    return Side(target, other, link.contact_point)


def add_link(ws: Workspace, parent: Element, markup: bytes, end: ContactPoint) -> Edit | None:
    """An edit giving ``parent`` (a road or lane element) the link ``markup`` at ``end``: into its ``<link>`` (a
    predecessor first, a successor last, as the schema orders them), or in a new ``<link>`` as its first child.
    ``None`` when the element has several ``<link>`` children."""
    links = parent.findall("link")
    if len(links) > 1:
        return None
    if links:
        return insert_child(ws.text, links[0], markup, first=end is ContactPoint.START)
    indent = child_indent(ws.text, parent)
    if indent is None:
        return insert_child(ws.text, parent, b"<link>" + markup + b"</link>", first=True)
    step = indent[len(ws.text.indent_of(parent) or b"") :] or b"  "
    nl = ws.text.newline
    wrapped = b"<link>" + nl + indent + step + markup + nl + indent + b"</link>"
    return insert_child(ws.text, parent, wrapped, first=True)
