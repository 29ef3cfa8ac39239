"""``<lanes>`` to the laneOffset profile and :class:`~xodrcheck.model.LaneSection` values.

Records inside a lane (width, border, height, roadMark, speed) keep ``s`` = their ``sOffset``. A lane without a usable
integer
``id`` is skipped (links name lanes by id); a lane whose type is unknown is kept as ``LaneType.UNKNOWN``.

OpenDRIVE 1.9 lane layers (11.2) are read from 1.9 files (and files of unknown version, read as 1.9): a lane link's
``layer``, a lane section's ``length`` and the ``<lanes layer>`` of a road's up to two ``<lanes>``. Older versions do
not have them (the schema reports them there); the reader ignores them.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from lxml import etree

from xodrcheck import model
from xodrcheck.model import (
    Cubic,
    Lane,
    LaneAdvisory,
    LaneDirection,
    LaneHeight,
    LaneLayer,
    LaneLinks,
    Lanes,
    LaneSection,
    LaneType,
    RoadMark,
    Speed,
)
from xodrcheck.reader.context import LEAF, SKIP_RECORD, Context, cubic, describe
from xodrcheck.rules import xml as R
from xodrcheck.rules.shared import lane_uids as U

if TYPE_CHECKING:  # pragma: no cover
    from xodrcheck.model import (
        LaneAccess,
        LaneMaterial,
        LaneRule,
        LaneVisibility,
        RoadMarkExplicit,
        RoadMarkSway,
        RoadMarkType,
    )

#: Lane type names in lower case -> type: the file's spelling is matched without regard to case.
LANE_TYPES = {t.value.lower(): t for t in LaneType if t is not LaneType.UNKNOWN}

#: The usual spellings of ``level``; anything else goes through :meth:`Context.boolean`.
_LEVELS = {"true": True, "false": False}
_SKIP_LANE = "the lane is skipped"
#: ``direction`` values (1.8), matched without regard to case.
DIRECTIONS = {d.value: d for d in LaneDirection}
_STANDARD = "read as standard, the standard's default"
#: ``layer`` values (1.9), matched without regard to case.
LAYERS = {layer.value: layer for layer in LaneLayer}
_PERMANENT = "read as permanent, the standard's default"

_SPEED = ["sOffset", "max"]
_HEIGHT = ["sOffset", "inner", "outer"]
_ADVISORIES = {a.value: a for a in LaneAdvisory}
#: Children each element reads (the others are unknown there).
_LANE = frozenset(
    {"link", "width", "border", "roadMark", "speed", "height", "access", "material", "rule", "visibility"}
)
_LINK = frozenset({"predecessor", "successor"})
#: The lane records :mod:`.lane_records` reads.
_RECORDS = frozenset({"access", "material", "rule", "visibility"})
#: The attributes most lanes give, in the usual orders: such a lane has none of the 1.8 ones.
_PLAIN = frozenset({("id", "type", "level"), ("id", "type"), ("id", "level", "type"), ("type", "id", "level"), ("id",)})
_NO_EXTRAS: tuple[None, None, None, None] = (None, None, None, None)
_NO_RECORDS: tuple[tuple[()], tuple[()], tuple[()], tuple[()]] = ((), (), (), ())
_ROAD_MARK = frozenset({"sway", "type", "explicit"})
_SECTION = frozenset({"left", "center", "right"})
_LANES = frozenset({"laneOffset", "laneSection"})

_Links = tuple[tuple[int, ...], tuple[int, ...], tuple[int, ...], tuple[int, ...]]


def _missing_centre_uid(ctx: Context, section: etree._Element, has_center: bool) -> str:
    """The Annex F rule a lane section without centre lane 0 breaks: in a 1.9 permanent layer
    ``layer.center_lane_permanent``; else, with a ``<center>`` that holds no lane 0, ``center_lane_singular`` (1.9:
    exactly one centre lane; dropped for older files), without ``<center>`` ``center_elem_definition``."""
    parent = section.getparent()
    if layered(ctx) and (parent is None or (parent.get("layer") or "permanent") == "permanent"):
        return U.LAYER_CENTER_PERMANENT
    return U.CENTER_LANE_SINGULAR if has_center else U.CENTER_ELEM_DEFINITION


def directed(ctx: Context) -> bool:
    """Whether the file's lanes may have ``@direction``: OpenDRIVE 1.8 or later, or a version the reader does not
    know (older files do not have it; the schema reports it there)."""
    return ctx.version is None or ctx.version >= (1, 8)


def layered(ctx: Context) -> bool:
    """Whether the file has lane layers: OpenDRIVE 1.9 or later, or a version the reader does not know."""
    return ctx.version is None or ctx.version >= (1, 9)


def _lane_links(ctx: Context, el: etree._Element) -> tuple[_Links, tuple[str, ...]]:
    """Predecessor and successor lane ids on the permanent layer, then on the temporary layer; and the tags of the
    ``<link>``'s children."""
    links: tuple[list[int], list[int], list[int], list[int]] = ([], [], [], [])
    with_layers = layered(ctx)
    tags = []
    for child in el:
        tag = child.tag
        tags.append(tag)
        if tag == "predecessor":
            k = 0
        elif tag == "successor":
            k = 1
        else:
            continue
        if (
            with_layers
            and child.get("layer") is not None
            and ctx.choice(child, "layer", LAYERS, _PERMANENT) is LaneLayer.TEMPORARY
        ):
            k += 2
        raw = child.get("id")
        try:
            links[k].append(int(raw))
        except (TypeError, ValueError):
            ctx.integer(child, "id", "the lane link is ignored")
    return (tuple(links[0]), tuple(links[1]), tuple(links[2]), tuple(links[3])), tuple(tags)


def _road_mark(ctx: Context, el: etree._Element) -> RoadMark | None:
    get = el.get
    try:
        s = ctx.numbers[get("sOffset")]
        if s < 0.0:
            raise ValueError
    except (TypeError, ValueError):
        given = ctx.number(el, "sOffset", SKIP_RECORD, nonneg=True)
        if given is None:
            return None
        s = given
    kind = get("type")
    if kind is None:
        ctx.missing(el, "type", SKIP_RECORD)
        return None
    width = get("width")
    if width is not None:
        try:
            width = ctx.numbers[width]
            if width < 0.0:
                raise ValueError
        except ValueError:
            width = ctx.number(el, "width", "the width is read as absent", nonneg=True)
    height = None if get("height") is None else ctx.opt_number(el, "height")
    lines: RoadMarkType | None = None
    explicit: RoadMarkExplicit | None = None
    sways: tuple[RoadMarkSway, ...] = ()
    if len(el):
        from xodrcheck.reader import lane_records  # here: most road marks have no stripes of their own

        for child in el:
            tag = child.tag
            if tag == "type" and lines is None:
                lines = lane_records.mark_type(ctx, child)
            elif tag == "explicit" and explicit is None:
                explicit = lane_records.explicit(ctx, child)
            elif tag == "sway":
                sways += (lane_records.sway(ctx, child),)
    return model.RoadMark(
        s,
        kind,
        get("weight"),
        get("color"),
        width,
        get("laneChange"),
        el.sourceline,
        get("material"),
        height,
        lines,
        explicit,
        sways,
        ctx.facts(el, _ROAD_MARK),
    )


def _speed(ctx: Context, el: etree._Element) -> Speed | None:
    v = ctx.floats(el, _SPEED, (0, 1), SKIP_RECORD)
    return None if v is None else model.Speed(v[0], v[1], el.get("unit"), el.sourceline, ctx.facts(el, LEAF))


def _height(ctx: Context, el: etree._Element) -> LaneHeight | None:
    v = ctx.floats(el, _HEIGHT, (0,), SKIP_RECORD)
    return None if v is None else model.LaneHeight(v[0], v[1], v[2], el.sourceline, ctx.facts(el, LEAF))


def _centre_type_optional(ctx: Context, el: etree._Element) -> bool:
    """Whether ``el`` is a centre lane whose ``type`` the file's schema makes optional: 1.1 to 1.4 (which require no
    attribute) and 1.8 on (``t_road_lanes_laneSection_center_lane``: ``type`` ``use="optional"``); 1.5 to 1.7
    require it. A file of unknown version is read as the latest."""
    parent = el.getparent()
    if parent is None or parent.tag != "center":
        return False
    version = ctx.version
    return version is None or version <= (1, 4) or version >= (1, 8)


def _lane_type(ctx: Context, el: etree._Element, name: str | None) -> LaneType:
    """The lane's type: as spelt by the standard, else matched without case or blanks (an unknown one, or none where
    it is required, is read as unknown with a finding)."""
    exact = None if name is None else LANE_TYPES.get(name)
    if exact is not None:
        return exact
    if name is None:
        if not _centre_type_optional(ctx, el):
            ctx.missing(el, "type", "the lane type is read as unknown")
        return LaneType.UNKNOWN
    lane_type = LANE_TYPES.get(name.strip().lower())
    if lane_type is None:
        ctx.report(
            R.UNKNOWN_LANE_TYPE,
            f'{describe(el)} has type="{name}", which no OpenDRIVE version defines; the lane is kept with type '
            "unknown and is not treated as drivable",
            el,
        )
        return LaneType.UNKNOWN
    return lane_type


def _lane(ctx: Context, el: etree._Element) -> Lane | None:
    """The lane of ``el`` with its records, or ``None`` (with a finding) when its id is not an integer."""
    try:
        lane_id = int(el.get("id"))
    except (TypeError, ValueError):
        ctx.integer(el, "id", _SKIP_LANE)
        return None
    ctx.lane = lane_id
    keys = tuple(el.keys())
    type_name = el.get("type")
    lane_type, level = _lane_type(ctx, el, type_name), _level(ctx, el)
    direction = None
    if el.get("direction") is not None and directed(ctx):
        direction = ctx.choice(el, "direction", DIRECTIONS, _STANDARD)
    records = _LaneRecords()
    tags = [records.add(ctx, child) for child in el]
    records.check_order(ctx, el)
    access, materials, rules, visibilities = _NO_RECORDS if not records.others else _records(ctx, records.others)
    advisory, dynamic_type, dynamic_direction, road_works = _NO_EXTRAS if keys in _PLAIN else _extras(ctx, el)
    links = records.links
    return model.Lane(
        id=lane_id,
        type=lane_type,
        level=level,
        predecessors=links[0],
        successors=links[1],
        widths=tuple(records.widths),
        borders=tuple(records.borders),
        road_marks=tuple(records.marks),
        speeds=tuple(records.speeds),
        type_name="" if type_name is None else type_name,
        line=el.sourceline,
        heights=tuple(records.heights),
        temporary_predecessors=links[2],
        temporary_successors=links[3],
        direction=direction,
        access=access,
        materials=materials,
        rules=rules,
        visibilities=visibilities,
        link=records.link_record,
        advisory=advisory,
        dynamic_lane_type=dynamic_type,
        dynamic_lane_direction=dynamic_direction,
        road_works=road_works,
        xml=ctx.facts(el, _LANE, keys, tuple(tags)),
    )


def _level(ctx: Context, el: etree._Element) -> bool:
    """``@level``: false when absent (the standard's default) or not a boolean (with a finding)."""
    level = el.get("level")
    if level is None:
        return False
    value = _LEVELS.get(level)
    if value is None:
        return bool(ctx.boolean(el, "level", "read as false, the standard's default"))
    return value


@dataclass
class _LaneRecords:
    """A lane's child records as they are read, in file order; access, material, rule and visibility records, rare,
    are kept as elements and read at the end."""

    links: _Links = ((), (), (), ())
    link: etree._Element | None = None
    link_record: LaneLinks | None = None
    widths: list[Cubic] = field(default_factory=list)
    borders: list[Cubic] = field(default_factory=list)
    marks: list[RoadMark] = field(default_factory=list)
    speeds: list[Speed] = field(default_factory=list)
    heights: list[LaneHeight] = field(default_factory=list)
    others: list[etree._Element] = field(default_factory=list)

    def add(self, ctx: Context, child: etree._Element) -> str:
        """Read one child of the ``<lane>``; its tag."""
        tag = child.tag
        if tag == "roadMark":
            self._keep(self.marks, _road_mark(ctx, child))
        elif tag == "width" or tag == "border":
            self._keep(self.widths if tag == "width" else self.borders, cubic(ctx, child, True))
        elif tag == "link":
            if self.link is not None:
                ctx.repeated(child, self.link)
            else:
                self.link = child
                self.links, link_tags = _lane_links(ctx, child)
                self.link_record = LaneLinks(child.sourceline, ctx.facts(child, _LINK, children=link_tags))
        elif tag == "speed":
            self._keep(self.speeds, _speed(ctx, child))
        elif tag == "height":
            self._keep(self.heights, _height(ctx, child))
        elif tag in _RECORDS:
            self.others.append(child)
        return tag

    @staticmethod
    def _keep(records: list, record: object) -> None:
        if record is not None:
            records.append(record)

    def check_order(self, ctx: Context, el: etree._Element) -> None:
        """Each kind of record in ascending ``sOffset`` (a finding for each out of order)."""
        for records, name, uid in (
            (self.widths, "<width>", U.WIDTH_ORDER),
            (self.borders, "<border>", U.BORDER_ORDER),
            (self.marks, "<roadMark>", U.ROAD_MARK_ORDER),
            (self.speeds, "<speed>", U.SPEED_ORDER),
            (self.heights, "<height>", U.HEIGHT_ORDER),
        ):
            if len(records) > 1:
                ctx.check_order(records, name, el, uid)


def _records(
    ctx: Context, elements: list[etree._Element]
) -> tuple[tuple[LaneAccess, ...], tuple[LaneMaterial, ...], tuple[LaneRule, ...], tuple[LaneVisibility, ...]]:
    """A lane's access, material, rule and visibility records (:mod:`.lane_records`, loaded for a lane with some)."""
    from xodrcheck.reader import lane_records

    access = tuple(lane_records.access(ctx, el) for el in elements if el.tag == "access")
    materials = tuple(lane_records.material(ctx, el) for el in elements if el.tag == "material")
    rules = tuple(lane_records.rule(ctx, el) for el in elements if el.tag == "rule")
    visibilities = tuple(lane_records.visibility(ctx, el) for el in elements if el.tag == "visibility")
    return access, materials, rules, visibilities


def _extras(ctx: Context, el: etree._Element) -> tuple[LaneAdvisory | None, bool | None, bool | None, bool | None]:
    """A lane's other 1.8 attributes: advisory, dynamicLaneType, dynamicLaneDirection, roadWorks."""
    return (
        ctx.opt_enum(el, "advisory", _ADVISORIES),
        ctx.opt_boolean(el, "dynamicLaneType"),
        ctx.opt_boolean(el, "dynamicLaneDirection"),
        ctx.opt_boolean(el, "roadWorks"),
    )


def _section(ctx: Context, el: etree._Element) -> LaneSection | None:
    try:
        s = ctx.numbers[el.get("s")]
        if s < 0.0:
            raise ValueError
    except (TypeError, ValueError):
        given = ctx.number(el, "s", "the lane section and its lanes are skipped", nonneg=True, uid=U.S_ATTR_VALUE)
        if given is None:
            return None
        s = given
    single_side = length = None
    if el.get("singleSide") is not None:
        single_side = ctx.boolean(el, "singleSide", "read as absent")
    if el.get("length") is not None and layered(ctx):
        length = ctx.number(el, "length", "read as absent (the section lasts until the next one)", nonneg=True)
    ctx.section_s = s
    left: tuple[Lane, ...] = ()
    center: tuple[Lane, ...] = ()
    right: tuple[Lane, ...] = ()
    seen: dict[str, etree._Element] = {}
    tags = []
    for child in el:
        tag = child.tag
        tags.append(tag)
        if tag == "left" or tag == "center" or tag == "right":
            if tag in seen:
                ctx.repeated(child, seen[tag], U.CENTER_ELEM_DEFINITION if tag == "center" else None)
                continue
            seen[tag] = child
            built = []
            for lane_el in child:
                if lane_el.tag == "lane":
                    lane = _lane(ctx, lane_el)
                    if lane is not None:
                        built.append(lane)
            ctx.lane = None
            lanes = tuple(built)
            if tag == "right":
                right = lanes
            elif tag == "left":
                left = lanes
            else:
                center = lanes
    for lane in center:
        if lane.id == 0:
            break
    else:
        where = "its <center> has none" if "center" in seen else "it has no <center>"
        ctx.report(
            R.MISSING_ELEMENT,
            f"{describe(el)} has no centre lane 0 ({where}); the other lanes are kept, measured from the "
            "reference line (shifted by laneOffset)",
            el,
            uid=_missing_centre_uid(ctx, el, "center" in seen),
        )
    ctx.section_s = None
    facts = ctx.facts(el, _SECTION, children=tuple(tags))
    return model.LaneSection(s, single_side, left, center, right, el.sourceline, length, facts)


def build_lanes(ctx: Context, el: etree._Element, layer: LaneLayer = LaneLayer.PERMANENT) -> Lanes:
    """A road's ``<lanes>`` of ``layer``: its laneOffset profile and lane sections."""
    offsets = []
    sections = []
    seen = False
    for child in el:
        tag = child.tag
        if tag == "laneSection":
            seen = True
            section = _section(ctx, child)
            if section is not None:
                sections.append(section)
        elif tag == "laneOffset":
            record = cubic(ctx, child)
            if record is not None:
                offsets.append(record)
    if len(offsets) > 1:
        ctx.check_order(offsets, "<laneOffset>", el, U.LANE_OFFSET_ORDER)
    if not seen:
        ctx.missing_child(el, "laneSection", "the road has no lanes", U.LANE_SECT_MIN_AMOUNT)
    elif len(sections) > 1:
        ctx.check_order(sections, "<laneSection>", el, U.SECTION_ORDER)
    return Lanes(tuple(offsets), tuple(sections), el.sourceline, layer, ctx.facts(el, _LANES))


def build_layers(ctx: Context, elements: list[etree._Element]) -> tuple[Lanes | None, Lanes | None]:
    """The permanent and the temporary layer of a road's ``<lanes>`` elements (1.9: one per layer, ``layer``
    defaulting to permanent; before 1.9 only the first is read). A second ``<lanes>`` of the same layer is reported
    and skipped; a road with only a temporary layer has no permanent lanes."""
    found: dict[LaneLayer, etree._Element] = {}
    for el in elements:
        layer = LaneLayer.PERMANENT
        if layered(ctx) and el.get("layer") is not None:
            layer = ctx.choice(el, "layer", LAYERS, _PERMANENT) or LaneLayer.PERMANENT
        if layer in found:
            ctx.repeated(el, found[layer], U.LAYER_LIMITS if layered(ctx) else None)
        else:
            found[layer] = el
    permanent = found.get(LaneLayer.PERMANENT)
    lanes = None
    if permanent is not None:
        lanes = build_lanes(ctx, permanent)
    else:
        ctx.report(
            R.MISSING_ELEMENT,
            f"{describe(elements[0].getparent())} has no <lanes> of the permanent layer; the road has no lanes",
            elements[0],
            uid=U.LAYER_LIMITS,
        )
    temporary = found.get(LaneLayer.TEMPORARY)
    return lanes, None if temporary is None else build_lanes(ctx, temporary, LaneLayer.TEMPORARY)
