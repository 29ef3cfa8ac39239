"""Hypothesis strategies for hostile documents: small OpenDRIVE files that describe a great deal of work.

A :class:`Growth` is one change that makes a document ask for more work without making it much larger: a number
scaled by a power of ten (huge lengths, tiny radii, wide lanes, dense repeats), an element repeated up to thousands of
times (records along a road: widths, lane sections, geometries, objects; those with an ``s`` or ``sOffset`` are spread
along the road), or an object repeated along a road at a small distance. :func:`hostile_documents` applies a few of
them, mixed with the random damage of :mod:`fuzz.mutations`, to the valid documents of :func:`fuzz.opendrive_documents`;
the slow-input hunt (:mod:`fuzz.hunt`) climbs on the checker's cost per kB over them.

Like a :class:`~fuzz.mutations.Mutation`, a :class:`Growth` is plain data (kind, picks, amount), so an example prints
readably and replays.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from hypothesis import strategies as st
from hypothesis.errors import InvalidArgument
from lxml import etree

from junctionart.fuzz.mutations import DAMAGE, document_mutations

__all__ = ["GROWTH", "MAX_COPIES", "MAX_SIZE", "Growth", "growths", "hostile_documents"]

#: Growth kinds.
GROWTH = ("scale", "repeat", "objects")
#: Most copies one ``repeat`` growth makes of an element.
MAX_COPIES = 3000
#: Largest document (bytes) :func:`hostile_documents` makes by default: the hunt's bound is for files under 100 kB.
MAX_SIZE = 100 * 1024 - 1
#: Powers of ten a ``scale`` growth multiplies a number by (``amount`` 0 to 1 runs through them).
_EXPONENTS = (-9, 12)

_PARSER = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False)


@dataclass(frozen=True)
class Growth:
    """One change that asks for more work: ``kind`` (one of :data:`GROWTH`), ``picks`` (indexes, taken modulo the
    number of candidates) and ``amount`` in [0, 1] (how much: a power of ten, a number of copies)."""

    kind: str
    picks: tuple[int, ...]
    amount: float = 0.5

    def pick(self, i: int, items):
        return items[self.picks[i % len(self.picks)] % len(items)]

    def apply(self, data: bytes, max_size: int | None = None) -> bytes | None:
        """The grown document, or ``None`` when this growth does not apply to it (nothing to change) or would make it
        larger than ``max_size`` bytes (a ``repeat`` makes fewer copies to stay under it)."""
        try:
            root = etree.fromstring(data, _PARSER)
        except etree.XMLSyntaxError:
            return None
        room = None if max_size is None else max_size - len(data)
        if not _FUNCS[self.kind](self, root, room):
            return None
        out = etree.tostring(root, xml_declaration=True, encoding="UTF-8")
        return None if max_size is not None and len(out) > max_size else out

    @property
    def exponent(self) -> int:
        lo, hi = _EXPONENTS
        return lo + round((hi - lo) * self.amount)

    @property
    def copies(self) -> int:
        return 1 + math.floor(self.amount**2 * (MAX_COPIES - 1))


def _elements(root) -> list:
    return [el for el in root.iter() if isinstance(el.tag, str) and el is not root]


def _number(text: str | None) -> float | None:
    try:
        value = float(text or "")
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def _value(el, name: str) -> float:
    """The attribute as a finite number, of an element picked because it has one."""
    value = _number(el.get(name))
    if value is None:
        raise ValueError(f"<{el.tag}> has no finite {name}")
    return value


def _scale(g: Growth, root, room: int | None) -> bool:
    numbers = [(el, name) for el in _elements(root) for name in el.keys() if _number(el.get(name))]  # noqa: SIM118
    if not numbers:
        return False
    el, name = g.pick(0, numbers)
    el.set(name, repr(_value(el, name) * 10.0**g.exponent))
    return True


def _repeat(g: Growth, root, room: int | None) -> bool:
    """``copies`` copies of an element after it (as many as fit in ``room`` bytes); one with ``s`` or ``sOffset``
    gets them a step apart (0.01 m to 100 m, by the second pick), as thousands of records along one road."""
    elements = _elements(root)
    if not elements:
        return False
    el = g.pick(0, elements)
    text = etree.tostring(el)
    copies = g.copies if room is None else min(g.copies, room // (len(text) + 8))
    if copies < 1:
        return False
    key = next((k for k in ("s", "sOffset") if _number(el.get(k)) is not None), None)
    step = 10.0 ** (g.picks[1 % len(g.picks)] % 5 - 2)
    at = el
    for k in range(1, copies + 1):
        copy = etree.fromstring(text, _PARSER)
        if key is not None:
            copy.set(key, repr(_value(el, key) + k * step))
        at.addnext(copy)
        at = copy
    return True


def _objects(g: Growth, root, room: int | None) -> bool:
    """A pole repeated along a road: over ``10**exponent`` times the road's length (at least 1 m), every 1 mm to
    1 m (by the second pick), with an outline of 3 to 50 corners (by the third)."""
    roads = root.findall("road")
    if not roads:
        return False
    road = g.pick(0, roads)
    length = max(_number(road.get("length")) or 1.0, 1.0) * 10.0**g.exponent
    distance = 10.0 ** -(g.picks[1 % len(g.picks)] % 4)
    corners = 3 + g.picks[2 % len(g.picks)] % 48
    objects = road.find("objects")
    if objects is None:
        objects = etree.SubElement(road, "objects")
    number = len(objects)
    obj = etree.SubElement(
        objects,
        "object",
        id=f"hostile{number}",
        s="0.0",
        t="-5.0",
        zOffset="0.0",
        hdg="0.0",
        pitch="0.0",
        roll="0.0",
        orientation="none",
        type="pole",
        name="pole",
        width="0.2",
        length="0.2",
        height="2.0",
    )
    etree.SubElement(
        obj,
        "repeat",
        s="0.0",
        length=repr(length),
        distance=repr(distance),
        tStart="-5.0",
        tEnd="-5.0",
        heightStart="2.0",
        heightEnd="2.0",
        zOffsetStart="0.0",
        zOffsetEnd="0.0",
    )
    outline = etree.SubElement(etree.SubElement(obj, "outlines"), "outline", id="0", closed="true")
    for k in range(corners):
        angle = 2 * math.pi * k / corners
        etree.SubElement(
            outline, "cornerLocal", u=repr(0.1 * math.cos(angle)), v=repr(0.1 * math.sin(angle)), z="0.0", height="2.0"
        )
    return True


_FUNCS = {"scale": _scale, "repeat": _repeat, "objects": _objects}


def growths(*, kinds: tuple[str, ...] = GROWTH) -> st.SearchStrategy[Growth]:
    """Single :class:`Growth` values of the given ``kinds`` (default: all of :data:`GROWTH`)."""
    if isinstance(kinds, str) or not kinds or any(k not in GROWTH for k in kinds):
        raise InvalidArgument(f"kinds={kinds!r} must be a non-empty collection of {', '.join(GROWTH)}")
    return st.builds(
        Growth,
        kind=st.sampled_from(tuple(kinds)),
        picks=st.tuples(*[st.integers(0, 2**31 - 1)] * 3),
        amount=st.floats(0.0, 1.0, allow_nan=False),
    )


@st.composite
def _hostile(draw, base, changes, min_changes: int, max_changes: int, max_size: int) -> bytes:
    data = draw(base)
    for _ in range(draw(st.integers(min_changes, max_changes))):
        change = draw(changes)
        out = change.apply(data, max_size) if isinstance(change, Growth) else change.apply(data)
        data = data if out is None or len(out) > max_size else out
    return data


def hostile_documents(
    base: st.SearchStrategy[bytes] | None = None,
    *,
    min_changes: int = 1,
    max_changes: int = 4,
    max_size: int = MAX_SIZE,
) -> st.SearchStrategy[bytes]:
    """Documents from ``base`` (default :func:`fuzz.opendrive_documents`) after ``min_changes`` to ``max_changes``
    changes, two in three a :class:`Growth` and the others random damage (:data:`fuzz.mutations.DAMAGE`); a change
    that would make the document larger than ``max_size`` bytes is left out (the hunt is for small files; a base
    document larger than that is kept as it is)."""
    for name, value in (("min_changes", min_changes), ("max_changes", max_changes)):
        if isinstance(value, bool) or not isinstance(value, int) or value < 0:
            raise InvalidArgument(f"{name}={value!r} must be a non-negative integer")
    if min_changes > max_changes or max_changes > 20:
        raise InvalidArgument(f"need min_changes={min_changes} <= max_changes={max_changes} <= 20")
    if isinstance(max_size, bool) or not isinstance(max_size, int) or max_size < 1024:
        raise InvalidArgument(f"max_size={max_size!r} must be an integer of at least 1024 (bytes)")
    if base is not None and not isinstance(base, st.SearchStrategy):
        raise InvalidArgument(f"base={base!r} must be a strategy of bytes")
    if base is None:
        from junctionart.fuzz.documents import opendrive_documents

        base = opendrive_documents()
    changes = st.one_of(growths(), growths(), document_mutations(defects=(), damage=DAMAGE))
    return _hostile(base, changes, min_changes, max_changes, max_size)
