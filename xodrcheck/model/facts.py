"""What the file's XML said about an element beyond its values: the one place of the model that records it.

Every record of the model has two fields about its element besides its values:

* ``line``: the line the element starts on (0 when the record was not read from a file);
* ``xml``: an :class:`XmlFacts`, which says which attributes the element gave (so a value the standard defaults can be
  told from one the file wrote), the order of its child elements, the children the reader did not read at that place
  (not OpenDRIVE there) and the attributes whose text was not a value of their type.

Records whose elements say the same share one :class:`XmlFacts` (the reader keeps one of each): a map of 800,000
elements has a few thousand distinct ones, so the facts cost a pointer per record. Where the standard allows one
element and a file gives several, the record holds the first (the reader reports the others) and ``children`` still
lists them all. A record built in code (tests, the generator) has :data:`NO_FACTS`.

An element the reader reports and leaves out is no record; where a rule asks how such elements are written, it is
kept here: :class:`UnreadLink` (a road link without ``elementType`` or ``elementId``, on ``Road.unread_links``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

__all__ = ["NO_FACTS", "UnknownElement", "UnreadLink", "XmlFacts", "facts_field"]


@dataclass(frozen=True, slots=True)
class UnknownElement:
    """A child element that is not OpenDRIVE at its place (a vendor's element, a misspelt tag): its tag and line."""

    tag: str
    line: int


@dataclass(frozen=True, slots=True)
class XmlFacts:
    """The XML facts of one element (see the module's description)."""

    #: Names of the attributes the element gives, in file order.
    attributes: tuple[str, ...] = ()
    #: Tags of its child elements, in file order (comments and processing instructions left out).
    children: tuple[str, ...] = ()
    #: Child elements the reader does not read at this place, in file order.
    unknown: tuple[UnknownElement, ...] = ()
    #: ``(name, text)`` of each attribute given with text that is not a value of its type (the record holds ``None``
    #: or the standard's default instead), in file order.
    invalid: tuple[tuple[str, str], ...] = ()

    def given(self, name: str) -> bool:
        """Whether the element gives attribute ``name`` (a valid value or not)."""
        return name in self.attributes

    def text(self, name: str) -> str | None:
        """The text of attribute ``name`` when it is not a valid value (``None`` otherwise)."""
        for key, text in self.invalid:
            if key == name:
                return text
        return None

    def count(self, tag: str) -> int:
        """How many child elements ``tag`` the element has."""
        return self.children.count(tag)


#: The facts of a record built in code: nothing given, no children.
NO_FACTS = XmlFacts()


def facts_field() -> Any:
    """The ``xml`` field of a record: :data:`NO_FACTS` unless the reader gives it, left out of equality and ``repr``
    (two records of the same values are equal however the file spelt them)."""
    return field(default=NO_FACTS, compare=False, repr=False)


@dataclass(frozen=True, slots=True)
class UnreadLink:
    """A road's ``<predecessor>`` or ``<successor>`` the reader could not read: without ``elementType`` or
    ``elementId``, or with an ``elementType`` that is neither road nor junction. The reader reports it and the road
    has no such link; what the file wrote is kept here for the rules on how links are written (``K004``)."""

    tag: str
    #: ``elementType`` and ``elementId`` as written (``None``: absent).
    element_type: str | None
    element_id: str | None
    line: int = 0
    xml: XmlFacts = facts_field()
