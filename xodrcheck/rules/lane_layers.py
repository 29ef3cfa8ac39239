"""Lane layers of OpenDRIVE 1.9 (``L029``-``L035``): one permanent layer over the whole road, at most one temporary
layer on top of it, and lanes linked between them where the temporary layer starts and ends.

Read from the XML (:mod:`xodrcheck.rules.lane_xml`): every ``<lanes>`` of a road is one layer, ``layer`` absent
meaning ``permanent``. A *temporary lane layer section* is a run of temporary lane sections, each ending where the next
starts (a section ends at ``s + length``, else where the next section of its layer starts, else at the road's end).
"""

from __future__ import annotations

import numpy as np

from xodrcheck.findings import Category, Severity
from xodrcheck.model import DRIVABLE_LANE_TYPES, Cubic, LaneType
from xodrcheck.rules import lane_uids as U
from xodrcheck.rules.context import Context
from xodrcheck.rules.lane_xml import LaneXml, SectionXml, lane_elements, number
from xodrcheck.rules.registry import rule
from xodrcheck.support.quantities import metres

_TYPES = {t.value.lower(): t for t in LaneType}


def _layers(ctx: Context) -> dict[str, dict[str, list[SectionXml]]]:
    """Road id -> layer -> its lane sections, in file order."""
    out: dict[str, dict[str, list[SectionXml]]] = {}
    for section in lane_elements(ctx).sections:
        if section.road is not None:
            out.setdefault(section.road, {}).setdefault(section.layer, []).append(section)
    return out


def _lanes_by_section(ctx: Context) -> dict[int, list[LaneXml]]:
    out: dict[int, list[LaneXml]] = {}
    for lane in lane_elements(ctx).lanes:
        out.setdefault(id(lane.section), []).append(lane)
    return out


def section_end(section: SectionXml, layer: list[SectionXml], road_length: float | None) -> float | None:
    """Where a lane section ends: ``s + length``, else the next section's start in its layer, else the road's end."""
    if section.s is None:
        return None
    length = number(section.element.get("length"))
    if length is not None:
        return section.s + length
    later = [other.s for other in layer if other.s is not None and other.s > section.s]
    return min(later) if later else road_length


def _s(section: SectionXml) -> str:
    return metres(section.s)


def _road_length(ctx: Context, road_id: str) -> float | None:
    road = ctx.road(road_id)
    return None if road is None else road.length


@rule("L029", "road-without-centre-lane", Category.LANE, Severity.ERROR, uids=(U.CENTER_LANE,), xml=True)
def road_without_centre_lane(ctx: Context):
    """No lane layer of a road has a centre lane in every lane section.

    Annex F ``road.lane.center_lane`` (1.9): each road has at least one lane layer with a centre lane, the reference
    of its lane numbering. (Each lane section without centre lane 0 is reported while reading, as
    ``missing-element``; this says that the road as a whole has none.)

    Passes::

        <lanes><laneSection s="0"><center><lane id="0" type="none"/></center>...</laneSection></lanes>

    Fails::

        <lanes><laneSection s="0"><center/><right>...</right></laneSection></lanes>
    """
    lanes_of = _lanes_by_section(ctx)
    for road, layers in _layers(ctx).items():
        if any(all(_has_centre(lanes_of, section) for section in sections) for sections in layers.values()):
            continue
        found = ctx.road(road)
        first = next(iter(layers.values()))[0]
        yield road_without_centre_lane.finding(
            f"road {road}: no lane layer of the road has a centre lane 0 in each of its lane sections; give the "
            "permanent layer's lane sections their centre lane",
            road=road,
            line=(found.line if found is not None else None) or first.element.sourceline,
        )


def _has_centre(lanes_of: dict[int, list[LaneXml]], section: SectionXml) -> bool:
    return any(lane.group == "center" and lane.id == 0 for lane in lanes_of.get(id(section), ()))


@rule(
    "L033",
    "permanent-section-length",
    Category.LANE,
    Severity.ERROR,
    uids=(U.LAYER_LENGTH_ONLY_TEMPORARY, U.LAYER_MANDATORY_PERMANENT),
    xml=True,
)
def permanent_section_length(ctx: Context):
    """A lane section of the permanent lane layer has a ``length``.

    Annex F ``road.lane.layer.length_only_temporary`` (1.9): lanes in the permanent layer shall not use @length; a
    permanent lane section lasts until the next one or the road's end (the permanent layer covers the whole road).
    Where the ``length`` ends the section before the next one (or the road's end), the road has no permanent lane
    there, which ``road.lane.layer.layer_mandatory_permanent`` forbids ("at least one lane in the permanent layer at
    each s-coordinate"): one finding, under that UID, says both.

    Passes::

        <lanes><laneSection s="0">...</laneSection></lanes>

    Fails::

        <lanes><laneSection s="0" length="50">...</laneSection></lanes>
    """
    tol = ctx.tolerances.length_abs
    for road_id, layers in _layers(ctx).items():
        permanent = layers.get("permanent", [])
        for section in permanent:
            length = section.element.get("length")
            if length is None:
                continue
            here = f'road {road_id}: the permanent layer\'s lane section at s={_s(section)} has length="{length}"'
            fix = "only temporary lane sections have a length: remove it (the section lasts until the next one)"
            ends = section_end(section, permanent, None)
            later = [o.s for o in permanent if o is not section and o.s is not None and o.s > (section.s or 0.0)]
            after = min(later) if later else _road_length(ctx, road_id)
            if ends is not None and after is not None and after - ends > tol:
                yield permanent_section_length.finding(
                    f"{here}, so the road has no permanent lane from s={metres(ends)} to s={metres(after)}; {fix}",
                    uid=U.LAYER_MANDATORY_PERMANENT,
                    road=road_id,
                    section_s=section.s,
                    s=section.s,
                    line=section.element.sourceline,
                )
                continue
            yield permanent_section_length.finding(
                f"{here}; {fix}",
                uid=U.LAYER_LENGTH_ONLY_TEMPORARY,
                road=road_id,
                section_s=section.s,
                s=section.s,
                line=section.element.sourceline,
            )


@rule("L030", "temporary-lane-physical", Category.LANE, Severity.ERROR, uids=(U.LAYER_PHYS_ATTR_TEMPORARY,), xml=True)
def temporary_lane_physical(ctx: Context):
    """A lane of the temporary lane layer has ``<height>`` or ``<material>`` records.

    Annex F ``road.lane.layer.lane_phys_attr_temporary`` (1.9): the temporary layer changes how the road is used, not
    the road itself; height and material come from the permanent layer, so temporary lanes have neither.

    Passes::

        <lanes layer="temporary"> ... <lane id="-1" type="driving"><width sOffset="0" a="3.25" .../></lane>

    Fails::

        <lanes layer="temporary"> ... <lane id="-1" type="driving"><width .../><material sOffset="0" friction="0.5"/>
    """
    for lane in lane_elements(ctx).lanes:
        if lane.section.layer != "temporary":
            continue
        for child in lane.element.iterchildren("{*}height", "{*}material"):
            tag = child.tag.rsplit("}", 1)[-1]
            yield temporary_lane_physical.finding(
                f"{lane.describe()}: a lane of the temporary layer has a <{tag}> (line {child.sourceline}); the "
                f"permanent layer's lanes give the road's {tag}: remove it",
                **lane.where(child.sourceline),
            )
            break


def _links(lane: LaneXml, tag: str, layer: str) -> list[int]:
    """Ids the lane links to with ``tag`` (predecessor/successor) on ``layer`` (an absent layer is permanent)."""
    out = []
    for link in lane.element.iterchildren("{*}link"):
        for item in link.iterchildren(f"{{*}}{tag}"):
            if (item.get("layer") or "permanent") == layer:
                value = number(item.get("id"))
                if value is not None:
                    out.append(int(value))
    return out


def _width_at(lane: LaneXml, s: float) -> float | None:
    """A lane's width at absolute ``s`` from its ``<width>`` records (``None`` without any: described by borders)."""
    records = []
    for el in lane.element.iterchildren("{*}width"):
        s_offset, a, b, c, d = (number(el.get(k)) for k in ("sOffset", "a", "b", "c", "d"))
        if s_offset is not None and a is not None and b is not None and c is not None and d is not None:
            records.append(Cubic(s_offset, a, b, c, d, line=el.sourceline or 0))
    if not records or lane.section.s is None:
        return None
    from xodrcheck.geometry import profile

    return float(profile.evaluate(tuple(records), np.array([s]), origin=lane.section.s)[0])


def temporary_runs(ctx: Context) -> list[tuple[str, float, float | None, SectionXml, SectionXml]]:
    """``(road, start, end, first section, last section)`` of every temporary lane layer section (``end`` is
    ``None`` when it cannot be told)."""
    out: list[tuple[str, float, float | None, SectionXml, SectionXml]] = []
    for road, layers in _layers(ctx).items():
        placed = sorted(((x.s, x) for x in layers.get("temporary", ()) if x.s is not None), key=lambda item: item[0])
        sections = [x for _, x in placed]
        length = _road_length(ctx, road)
        run: list[tuple[float, SectionXml]] = []
        end: float | None = None
        for s, section in placed:
            if run and (end is None or abs(s - end) > ctx.tolerances.position):
                out.append((road, run[0][0], end, run[0][1], run[-1][1]))
                run = []
            run.append((s, section))
            end = section_end(section, sections, length)
        if run:
            out.append((road, run[0][0], end, run[0][1], run[-1][1]))
    return out


@rule(
    "L031", "temporary-layer-not-linked", Category.LANE, Severity.ERROR, uids=(U.LINK_TEMPORARY_TO_PERMANENT,), xml=True
)
def temporary_layer_not_linked(ctx: Context):
    """A drivable lane where a temporary lane layer section starts or ends is not linked to the permanent layer.

    Annex F ``road.lane.link.temporary_layer_section_link_permanent`` (1.9): at the start and the end of a temporary
    lane layer section, every drivable lane of non-zero width on the temporary layer is linked to a lane of the
    permanent layer, so that traffic can enter and leave it (its ``<predecessor layer="permanent">`` at the start, its
    ``<successor layer="permanent">`` at the end, or a permanent lane's link to it with ``layer="temporary"``). Where
    the temporary layer reaches the road's start or end, its lanes continue into the next road instead.

    Passes::

        <lanes layer="temporary"><laneSection s="20" length="30"> ...
          <lane id="-1" type="driving"><link><predecessor id="-1" layer="permanent"/>
                                             <successor id="-1" layer="permanent"/></link>...

    Fails::

        <lanes layer="temporary"><laneSection s="20" length="30"> ...
          <lane id="-1" type="driving"><link><successor id="-1" layer="permanent"/></link>...
    """
    lanes_of = _lanes_by_section(ctx)
    named: set[tuple[str | None, str, int]] = set()  # (road, predecessor/successor side, temporary lane id)
    for lane in lane_elements(ctx).lanes:
        if lane.section.layer == "permanent":
            named.update((lane.road, "successor", i) for i in _links(lane, "successor", "temporary"))
            named.update((lane.road, "predecessor", i) for i in _links(lane, "predecessor", "temporary"))
    for road, start, end, first, last in temporary_runs(ctx):
        length = _road_length(ctx, road)
        for at, section, tag, back in (
            (start, first, "predecessor", "successor"),
            (end, last, "successor", "predecessor"),
        ):
            if (
                at is None
                or at <= ctx.tolerances.position
                or (length is not None and at >= length - ctx.tolerances.position)
            ):
                continue
            for lane in lanes_of.get(id(section), ()):
                if (
                    lane.group == "center"
                    or _TYPES.get((lane.element.get("type") or "").lower()) not in DRIVABLE_LANE_TYPES
                ):
                    continue
                if _links(lane, tag, "permanent") or (road, back, lane.id) in named:
                    continue
                width = _width_at(lane, at)
                if width is not None and abs(width) < ctx.tolerances.zero_width:
                    continue
                starts = tag == "predecessor"
                yield temporary_layer_not_linked.finding(
                    f"{lane.describe()}: the temporary lane layer section {'starts' if starts else 'ends'} at "
                    f"s={metres(at)}, but this drivable lane has no {tag} on the permanent layer; link it "
                    f'(<{tag} id="..." layer="permanent"/>) so that traffic can {"enter" if starts else "leave"} it',
                    **lane.where() | {"s": at},
                )


@rule("L032", "layer-link-without-section", Category.LANE, Severity.ERROR, uids=(U.SECTION_NEW_TEMP_TO_PERM,), xml=True)
def layer_link_without_section(ctx: Context):
    """A permanent lane is linked to a temporary lane, but no permanent lane section starts or ends there.

    Annex F ``road.lane_section.new_lanesec_link_temp_to_perm`` (1.9): "a new lane section on the permanent lane layer
    shall be defined each time lanes on the permanent layer are linked to lanes on the temporary layer." A permanent
    lane's ``<successor layer="temporary">`` joins the lanes where its lane section ends, so a temporary lane layer
    section must start there (and a ``<predecessor layer="temporary">`` where one ends, at the permanent section's
    start). Otherwise the link joins lanes at two different places: split the permanent lane section where the
    temporary layer starts or ends. (At the road's start or end a layer link reaches the linked road's layer.)

    Passes (the permanent section ends at s=20, where the temporary layer starts)::

        <lanes><laneSection s="0"> ... <successor id="-1" layer="temporary"/> ... <laneSection s="20"> ...
        <lanes layer="temporary"><laneSection s="20" length="30"> ...

    Fails (the permanent section runs on to s=100)::

        <lanes><laneSection s="0"> ... <successor id="-1" layer="temporary"/> ...
        <lanes layer="temporary"><laneSection s="20" length="30"> ...
    """
    runs: dict[str, list[tuple[float, float | None]]] = {}
    for road, start, end, _, _ in temporary_runs(ctx):
        runs.setdefault(road, []).append((start, end))
    layers = _layers(ctx)
    tol = ctx.tolerances.position
    for lane in lane_elements(ctx).lanes:
        if lane.section.layer != "permanent" or lane.road is None or lane.section.s is None:
            continue
        permanent = layers.get(lane.road, {}).get("permanent", [])
        for tag, index in (("successor", 0), ("predecessor", 1)):
            targets = _links(lane, tag, "temporary")
            if not targets:
                continue
            length = _road_length(ctx, lane.road)
            at = section_end(lane.section, permanent, length) if index == 0 else lane.section.s
            if at is not None and (at <= tol if index else length is not None and at >= length - tol):
                continue  # at the road's start or end the link reaches the linked road's temporary layer
            edges = [e for e in (run[index] for run in runs.get(lane.road, ())) if e is not None]
            if at is not None and any(abs(at - edge) <= tol for edge in edges):
                continue
            where = "ends" if index == 0 else "starts"
            found = ", ".join(f"{metres(e)}" for e in edges) or "none"
            yield layer_link_without_section.finding(
                f"{lane.describe()}: {tag} lane {', '.join(map(str, targets))} on the temporary layer, but the lane "
                f"section {where} at s={metres(at)}, where no temporary lane layer section "
                f"{'starts' if index == 0 else 'ends'} (temporary layer sections {'start' if index == 0 else 'end'} at "
                f"{found}); start a new permanent lane section where the lanes change layers",
                **lane.where() | {"s": at},
            )
