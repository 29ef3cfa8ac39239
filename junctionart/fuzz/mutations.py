"""Hypothesis strategies for damaged OpenDRIVE documents.

Two families of damage, both applied to the XML of any OpenDRIVE file (those of :func:`fuzz.opendrive_documents`, the
generator's, the corpus'):

* **Defects** (:data:`DEFECTS`): one realistic mistake the checker knows how to find, e.g. a road moved away from its
  neighbour, a link to a road that does not exist, a lane link dropped. Each names the rule codes that report it.
* **Random damage** (:data:`DAMAGE`): elements dropped, duplicated or swapped, attributes removed or set to empty, NaN,
  infinite, huge or negative values, tags renamed, the file cut short.

A :class:`Mutation` is plain data (kind plus the choices drawn), so a failing example prints readably and replays.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from hypothesis import assume
from hypothesis import strategies as st
from hypothesis.errors import InvalidArgument
from lxml import etree

__all__ = [
    "BAD_VALUES",
    "DAMAGE",
    "DEFECTS",
    "Mutation",
    "damaged_documents",
    "defective_documents",
    "document_mutations",
]


#: Defect kind -> rule codes that report it (any one of them is enough).
DEFECTS: dict[str, frozenset[str]] = {
    "road-gap": frozenset({"K101", "K103"}),
    "road-kink": frozenset({"K101", "K102", "K103"}),
    "planview-gap": frozenset({"G001"}),
    "planview-kink": frozenset({"G002"}),
    "road-length": frozenset({"G004"}),
    "link-target-missing": frozenset({"R010"}),
    "link-contact-flipped": frozenset({"K001", "K101"}),
    "duplicate-road-id": frozenset({"R001"}),
    "lane-link-dropped": frozenset({"L010", "L011"}),
    "lane-width-step": frozenset({"K103"}),
    "lane-id-gap": frozenset({"L003"}),
    "junction-lane-link-dropped": frozenset({"J005"}),
    "connecting-road-missing": frozenset({"R011"}),
    "geometry-nan": frozenset({"X206"}),
}

#: Random damage kinds.
DAMAGE = ("drop", "duplicate", "swap", "attribute", "remove-attribute", "rename", "truncate")

#: Values an attribute is set to by the ``attribute`` damage.
BAD_VALUES = (
    "",
    " ",
    "NaN",
    "nan",
    "inf",
    "-INF",
    "1e308",
    "-1e308",
    "1e999",
    "-1",
    "-0",
    "0",
    "1e-320",
    "99999999999999999999999",
    "-99999999999999999999999",
    "abc",
    "1,5",
    "0x10",
    "true",
    "start",
    "-1.5e-9",
)

_PARSER = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False)


@dataclass(frozen=True)
class Mutation:
    """One change to a document: ``kind`` (a :data:`DEFECTS` key or a :data:`DAMAGE` kind), ``picks`` (indexes,
    taken modulo the number of candidates, so any integers are valid), ``amount`` (a magnitude in [0, 1]) and
    ``value`` (for ``attribute``)."""

    kind: str
    picks: tuple[int, ...]
    amount: float = 0.5
    value: str = ""

    def pick(self, i: int, items: Sequence):
        return items[self.picks[i % len(self.picks)] % len(items)]

    def apply(self, data: bytes) -> bytes | None:
        """The damaged document, or ``None`` when this mutation does not apply to it (nothing to change)."""
        if self.kind == "truncate":
            cut = self.picks[0] % max(len(data), 1)
            return data[:cut]
        try:
            root = etree.fromstring(data, _PARSER)
        except etree.XMLSyntaxError:
            return None
        done = (_DEFECT_FUNCS.get(self.kind) or _DAMAGE_FUNCS[self.kind])(self, root)
        if not done:
            return None
        return etree.tostring(root, xml_declaration=True, encoding="UTF-8")


# ---------------------------------------------------------------------------------------------------------- helpers
def _roads(root, outside_junction: bool | None = None):
    roads = root.findall("road")
    if outside_junction is None:
        return roads
    return [r for r in roads if (r.get("junction", "-1") == "-1") == outside_junction]


def _geometries(road):
    return road.findall("planView/geometry")


def _float(el, name: str) -> float | None:
    try:
        v = float(el.get(name, ""))
    except ValueError:
        return None
    return v if math.isfinite(v) else None


def _picked(el, name: str) -> float:
    """The attribute as a finite number, of an element picked because it has one."""
    v = _float(el, name)
    if v is None:
        raise ValueError(f"<{el.tag}> has no finite {name}")
    return v


def _linked_roads(root):
    """Roads (outside junctions) with at least one road or junction link and a readable plan view."""
    out = []
    for r in _roads(root, True):
        gs = _geometries(r)
        if r.find("link/predecessor") is None and r.find("link/successor") is None:
            continue
        if gs and all(_float(g, k) is not None for g in gs for k in ("x", "y", "hdg")):
            out.append(r)
    return out


def _road_gap(m: Mutation, root) -> bool:
    roads = _linked_roads(root)
    if not roads:
        return False
    road = m.pick(0, roads)
    d = 0.05 + 4.95 * m.amount
    angle = (m.picks[-1] % 360) * math.pi / 180
    for g in _geometries(road):
        g.set("x", repr(_picked(g, "x") + d * math.cos(angle)))
        g.set("y", repr(_picked(g, "y") + d * math.sin(angle)))
    return True


def _road_kink(m: Mutation, root) -> bool:
    roads = [r for r in _linked_roads(root) if r.find("link/predecessor") is not None]
    if not roads:
        return False
    road = m.pick(0, roads)
    gs = _geometries(road)
    a = (0.02 + 0.48 * m.amount) * (1 if m.picks[-1] % 2 else -1)
    x0, y0 = _picked(gs[0], "x"), _picked(gs[0], "y")
    c, s = math.cos(a), math.sin(a)
    for g in gs:
        dx, dy = _picked(g, "x") - x0, _picked(g, "y") - y0
        g.set("x", repr(x0 + c * dx - s * dy))
        g.set("y", repr(y0 + s * dx + c * dy))
        g.set("hdg", repr(_picked(g, "hdg") + a))
    return True


def _planview(m: Mutation, root, attribute: str) -> bool:
    roads = [
        r
        for r in _roads(root)
        if len(_geometries(r)) >= 2 and all(_float(g, k) is not None for g in _geometries(r) for k in ("x", "y", "hdg"))
    ]
    if not roads:
        return False
    gs = _geometries(m.pick(0, roads))
    g = m.pick(1, gs[1:])
    if attribute == "xy":
        d = 0.05 + 2.0 * m.amount
        g.set("x", repr(_picked(g, "x") + d))
        g.set("y", repr(_picked(g, "y") - d))
    else:
        g.set("hdg", repr(_picked(g, "hdg") + (0.02 + 0.5 * m.amount)))
    return True


def _road_length(m: Mutation, root) -> bool:
    roads = [r for r in _roads(root) if _float(r, "length")]
    if not roads:
        return False
    road = m.pick(0, roads)
    road.set("length", repr(_picked(road, "length") * (1.05 + m.amount)))
    return True


def _road_links(root, kind: str = "road"):
    return [
        el
        for r in _roads(root)
        for el in (r.find("link/predecessor"), r.find("link/successor"))
        if el is not None and el.get("elementType") == kind
    ]


def _link_target_missing(m: Mutation, root) -> bool:
    links = _road_links(root) + _road_links(root, "junction")
    if not links:
        return False
    m.pick(0, links).set("elementId", "no-such-element")
    return True


def _link_contact_flipped(m: Mutation, root) -> bool:
    links = [el for el in _road_links(root) if el.get("contactPoint") in ("start", "end")]
    if not links:
        return False
    el = m.pick(0, links)
    el.set("contactPoint", "end" if el.get("contactPoint") == "start" else "start")
    return True


def _duplicate_road_id(m: Mutation, root) -> bool:
    roads = _roads(root)
    if len(roads) < 2:
        return False
    a = m.pick(0, roads)
    b = m.pick(1, [r for r in roads if r is not a])
    b.set("id", a.get("id", ""))
    return True


def _lane_link_dropped(m: Mutation, root) -> bool:
    lanes = [
        ln
        for r in _roads(root, True)
        for ln in r.iterfind("lanes/laneSection/*/lane")
        if ln.get("id") != "0" and ln.find("link") is not None and len(ln.find("link")) > 0
    ]
    if not lanes:
        return False
    link = m.pick(0, lanes).find("link")
    link.remove(m.pick(1, list(link)))
    return True


def _lane_width_step(m: Mutation, root) -> bool:
    widths = [
        w
        for r in _roads(root, True)
        if r.find("link") is not None
        for w in r.iterfind("lanes/laneSection/*/lane/width")
        if _float(w, "a")
    ]
    if not widths:
        return False
    w = m.pick(0, widths)
    w.set("a", repr(_picked(w, "a") + 0.5 + m.amount))
    return True


def _lane_id_gap(m: Mutation, root) -> bool:
    sides = [side for r in _roads(root) for side in r.iterfind("lanes/laneSection/right") if side.findall("lane")]
    if not sides:
        return False
    lanes = m.pick(0, sides).findall("lane")
    ids = [int(ln.get("id")) for ln in lanes if (ln.get("id") or "").lstrip("-").isdigit()]
    if not ids:
        return False
    outer = lanes[
        [int(ln.get("id")) if (ln.get("id") or "").lstrip("-").isdigit() else 0 for ln in lanes].index(min(ids))
    ]
    outer.set("id", str(min(ids) - 1))
    return True


def _junction_lane_link_dropped(m: Mutation, root) -> bool:
    """Every laneLink from one (incoming road, lane), as long as each connection keeps one."""
    options = []
    for j in root.findall("junction"):
        conns = j.findall("connection")
        keys = {(c.get("incomingRoad"), ll.get("from")) for c in conns for ll in c.findall("laneLink")}
        for key in sorted(keys, key=str):
            hit = [c for c in conns if c.get("incomingRoad") == key[0]]
            if all(len([ll for ll in c.findall("laneLink") if ll.get("from") != key[1]]) > 0 for c in hit):
                options.append((hit, key[1]))
    if not options:
        return False
    hit, lane = m.pick(0, options)
    for c in hit:
        for ll in c.findall("laneLink"):
            if ll.get("from") == lane:
                c.remove(ll)
    return True


def _connecting_road_missing(m: Mutation, root) -> bool:
    conns = [c for c in root.iterfind("junction/connection") if c.get("connectingRoad")]
    if not conns:
        return False
    m.pick(0, conns).set("connectingRoad", "no-such-road")
    return True


def _geometry_nan(m: Mutation, root) -> bool:
    gs = [g for r in _roads(root) for g in _geometries(r)]
    if not gs:
        return False
    m.pick(0, gs).set(("x", "y", "hdg", "length")[m.picks[-1] % 4], "NaN")
    return True


_DEFECT_FUNCS = {
    "road-gap": _road_gap,
    "road-kink": _road_kink,
    "planview-gap": lambda m, r: _planview(m, r, "xy"),
    "planview-kink": lambda m, r: _planview(m, r, "hdg"),
    "road-length": _road_length,
    "link-target-missing": _link_target_missing,
    "link-contact-flipped": _link_contact_flipped,
    "duplicate-road-id": _duplicate_road_id,
    "lane-link-dropped": _lane_link_dropped,
    "lane-width-step": _lane_width_step,
    "lane-id-gap": _lane_id_gap,
    "junction-lane-link-dropped": _junction_lane_link_dropped,
    "connecting-road-missing": _connecting_road_missing,
    "geometry-nan": _geometry_nan,
}


# ------------------------------------------------------------------------------------------------- random damage
def _elements(root):
    return [el for el in root.iter() if isinstance(el.tag, str)]


def _drop(m: Mutation, root) -> bool:
    els = [el for el in _elements(root) if el is not root]
    if not els:
        return False
    el = m.pick(0, els)
    el.getparent().remove(el)
    return True


def _duplicate(m: Mutation, root) -> bool:
    els = [el for el in _elements(root) if el is not root]
    if not els:
        return False
    el = m.pick(0, els)
    el.addnext(etree.fromstring(etree.tostring(el)))
    return True


def _swap(m: Mutation, root) -> bool:
    els = [el for el in _elements(root) if el is not root]
    if len(els) < 2:
        return False
    a = m.pick(0, els)
    others = [el for el in els if el is not a and a not in el.iterancestors() and el not in a.iterancestors()]
    if not others:
        return False
    b = m.pick(1, others)
    marker = etree.Element("marker")
    a.addprevious(marker)
    b.addprevious(a)
    marker.addprevious(b)
    marker.getparent().remove(marker)
    return True


def _attributed(root):
    return [(el, name) for el in _elements(root) for name in el.keys()]  # noqa: SIM118 - lxml: attribute names


def _attribute(m: Mutation, root) -> bool:
    pairs = _attributed(root)
    if not pairs:
        return False
    el, name = m.pick(0, pairs)
    el.set(name, m.value)
    return True


def _remove_attribute(m: Mutation, root) -> bool:
    pairs = _attributed(root)
    if not pairs:
        return False
    el, name = m.pick(0, pairs)
    del el.attrib[name]
    return True


def _rename(m: Mutation, root) -> bool:
    els = _elements(root)
    tags = sorted({el.tag for el in els})
    el = m.pick(0, els)
    el.tag = m.pick(1, [*tags, "bogus"])
    return True


_DAMAGE_FUNCS = {
    "drop": _drop,
    "duplicate": _duplicate,
    "swap": _swap,
    "attribute": _attribute,
    "remove-attribute": _remove_attribute,
    "rename": _rename,
}


# ------------------------------------------------------------------------------------------------------ strategies
def _validate_kinds(name: str, kinds, valid) -> tuple[str, ...]:
    if isinstance(kinds, str) or not kinds:
        raise InvalidArgument(f"{name}={kinds!r} must be a non-empty collection of kinds")
    unknown = [k for k in kinds if k not in valid]
    if unknown:
        raise InvalidArgument(f"{name}: unknown kind {unknown[0]!r}; valid: {', '.join(valid)}")
    return tuple(kinds)


def document_mutations(
    *, defects: Sequence[str] | None = None, damage: Sequence[str] | None = None
) -> st.SearchStrategy[Mutation]:
    """Single :class:`Mutation` values: defects from ``defects`` (default: all of :data:`DEFECTS`) and random damage
    from ``damage`` (default: all of :data:`DAMAGE`); pass an empty tuple to leave a family out (not both)."""
    d = tuple(DEFECTS) if defects is None else (_validate_kinds("defects", defects, tuple(DEFECTS)) if defects else ())
    r = DAMAGE if damage is None else (_validate_kinds("damage", damage, DAMAGE) if damage else ())
    if not d and not r:
        raise InvalidArgument("document_mutations: defects and damage are both empty; nothing to draw")
    return st.builds(
        Mutation,
        kind=st.sampled_from(d + r),
        picks=st.tuples(*[st.integers(0, 2**31 - 1)] * 3),
        amount=st.floats(0.0, 1.0, allow_nan=False),
        value=st.sampled_from(BAD_VALUES),
    )


@st.composite
def _damaged(draw, base, mutations, min_mutations: int, max_mutations: int) -> bytes:
    data = draw(base)
    for _ in range(draw(st.integers(min_mutations, max_mutations))):
        out = draw(mutations).apply(data)
        data = data if out is None else out
    return data


def damaged_documents(
    base: st.SearchStrategy[bytes] | None = None,
    *,
    min_mutations: int = 1,
    max_mutations: int = 3,
    defects: Sequence[str] | None = None,
    damage: Sequence[str] | None = None,
) -> st.SearchStrategy[bytes]:
    """Documents from ``base`` (default :func:`fuzz.opendrive_documents`) after ``min_mutations`` to
    ``max_mutations`` mutations from :func:`document_mutations` (a mutation that does not apply changes nothing)."""
    for name, value in (("min_mutations", min_mutations), ("max_mutations", max_mutations)):
        if isinstance(value, bool) or not isinstance(value, int) or value < 0:
            raise InvalidArgument(f"{name}={value!r} must be a non-negative integer")
    if min_mutations > max_mutations:
        raise InvalidArgument(f"min_mutations={min_mutations} must not exceed max_mutations={max_mutations}")
    if max_mutations > 50:
        raise InvalidArgument(f"max_mutations={max_mutations} must be at most 50")
    if base is not None and not isinstance(base, st.SearchStrategy):
        raise InvalidArgument(f"base={base!r} must be a strategy of bytes")
    if base is None:
        from junctionart.fuzz.documents import opendrive_documents

        base = opendrive_documents(max_roads_per_chain=2, max_elements=2, max_lanes=2)
    return _damaged(base, document_mutations(defects=defects, damage=damage), min_mutations, max_mutations)


@st.composite
def _defective(draw, base, kinds) -> tuple[bytes, str]:
    data = draw(base)
    m = draw(document_mutations(defects=kinds, damage=()))
    out = m.apply(data)
    assume(out is not None)
    return out, m.kind


def defective_documents(
    base: st.SearchStrategy[bytes] | None = None, *, defects: Sequence[str] | None = None
) -> st.SearchStrategy[tuple[bytes, str]]:
    """``(document, defect kind)``: a document from ``base`` with exactly one defect of :data:`DEFECTS`."""
    kinds = tuple(DEFECTS) if defects is None else _validate_kinds("defects", defects, tuple(DEFECTS))
    if base is not None and not isinstance(base, st.SearchStrategy):
        raise InvalidArgument(f"base={base!r} must be a strategy of bytes")
    if base is None:
        from junctionart.fuzz.documents import opendrive_documents

        base = opendrive_documents()
    return _defective(base, kinds)
