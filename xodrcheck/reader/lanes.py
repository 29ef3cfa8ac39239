"""``<lanes>`` to the laneOffset profile and :class:`~xodrcheck.model.LaneSection` values.

Records inside a lane (width, border, height, roadMark, speed) keep ``s`` = their ``sOffset``. A lane without a usable
integer
``id`` is skipped (links name lanes by id); a lane whose type is unknown is kept as ``LaneType.UNKNOWN``.

OpenDRIVE 1.9 lane layers (11.2) are read from 1.9 files (and files of unknown version, read as 1.9): a lane link's
``layer``, a lane section's ``length`` and the ``<lanes layer>`` of a road's up to two ``<lanes>``. Older versions do
not have them (the schema reports them there); the reader ignores them.
"""

from __future__ import annotations

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
from xodrcheck.rules import lane_uids as U
from xodrcheck.rules import xml as R

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
    """The lane of ``el`` with its records, or ``None`` (with a finding) when its id is not an integer.

    One function rather than steps on purpose: it runs for every lane of a map, and handing its attributes or
    records to helpers measured 0.4 % of a CARLA town's read more (callgrind)."""
    get = el.get
    try:
        lane_id = int(get("id"))
    except (TypeError, ValueError):
        ctx.integer(el, "id", _SKIP_LANE)
        return None
    ctx.lane = lane_id
    keys = tuple(el.keys())

    type_name = get("type")
    lane_type: LaneType | None = None if type_name is None else LANE_TYPES.get(type_name)
    if lane_type is None:
        lane_type = _lane_type(ctx, el, type_name)
    level = get("level")
    if level is not None:
        level = _LEVELS.get(level)
        if level is None:
            level = bool(ctx.boolean(el, "level", "read as false, the standard's default"))
    else:
        level = False
    direction = None
    if get("direction") is not None and directed(ctx):
        direction = ctx.choice(el, "direction", DIRECTIONS, _STANDARD)

    links: _Links = ((), (), (), ())
    link = None
    link_record = None
    widths: list[Cubic] = []
    borders: list[Cubic] = []
    marks: list[RoadMark] = []
    speeds: list[Speed] = []
    heights: list[LaneHeight] = []
    others: list[etree._Element] = []  # access, material, rule and visibility records: rare, read at the end
    tags = []
    for child in el:
        tag = child.tag
        tags.append(tag)
        if tag == "roadMark":
            mark = _road_mark(ctx, child)
            if mark is not None:
                marks.append(mark)
        elif tag == "width" or tag == "border":
            record = cubic(ctx, child, True)
            if record is not None:
                (widths if tag == "width" else borders).append(record)
        elif tag == "link":
            if link is not None:
                ctx.repeated(child, link)
            else:
                link = child
                links, link_tags = _lane_links(ctx, child)
                link_record = LaneLinks(child.sourceline, ctx.facts(child, _LINK, children=link_tags))
        elif tag == "speed":
            speed = _speed(ctx, child)
            if speed is not None:
                speeds.append(speed)
        elif tag == "height":
            height = _height(ctx, child)
            if height is not None:
                heights.append(height)
        elif tag in _RECORDS:
            others.append(child)
    if len(widths) > 1:
        ctx.check_order(widths, "<width>", el, U.WIDTH_ORDER)
    if len(borders) > 1:
        ctx.check_order(borders, "<border>", el, U.BORDER_ORDER)
    if len(marks) > 1:
        ctx.check_order(marks, "<roadMark>", el, U.ROAD_MARK_ORDER)
    if len(speeds) > 1:
        ctx.check_order(speeds, "<speed>", el, U.SPEED_ORDER)
    if len(heights) > 1:
        ctx.check_order(heights, "<height>", el, U.HEIGHT_ORDER)
    access, materials, rules, visibilities = _NO_RECORDS if not others else _records(ctx, others)
    advisory, dynamic_type, dynamic_direction, road_works = _NO_EXTRAS if keys in _PLAIN else _extras(ctx, el)
    return model.Lane(
        lane_id,
        lane_type,
        level,
        links[0],
        links[1],
        tuple(widths),
        tuple(borders),
        tuple(marks),
        tuple(speeds),
        "" if type_name is None else type_name,
        el.sourceline,
        tuple(heights),
        links[2],
        links[3],
        direction,
        access,
        materials,
        rules,
        visibilities,
        link_record,
        advisory,
        dynamic_type,
        dynamic_direction,
        road_works,
        ctx.facts(el, _LANE, keys, tuple(tags)),
    )


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
        ctx.report(
            R.MISSING_ELEMENT,
            f"{describe(el)} has no <laneSection>; the road has no lanes",
            el,
            uid=U.LANE_SECT_MIN_AMOUNT,
        )
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
