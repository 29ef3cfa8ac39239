"""Lane layers of OpenDRIVE 1.9 (``L029``-``L035``): one permanent layer over the whole road, at most one temporary
layer on top of it, and lanes linked between them where the temporary layer starts and ends.

Read from the document: a road's ``lanes`` (the permanent layer) and ``temporary_lanes``. A *temporary lane layer
section* is a run of temporary lane sections, each ending where the next starts (a section ends at ``s + length``,
else where the next section of its layer starts, else at the road's end).
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

import numpy as np

from xodrcheck.findings import Category, Severity
from xodrcheck.model import Lane, LaneHeight, LaneSection, Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import lane_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.support.quantities import metres

if TYPE_CHECKING:  # pragma: no cover - the model's lane records load for a file with some
    from xodrcheck.model import LaneMaterial

_PERMANENT, _TEMPORARY = "permanent", "temporary"


def _layers(ctx: Context) -> dict[str, dict[str, list[LaneSection]]]:
    """Road id -> layer -> its lane sections, in file order (roads that share an id together)."""
    out: dict[str, dict[str, list[LaneSection]]] = {}
    for road in ctx.document.roads:
        for name, layer in ((_PERMANENT, road.lanes), (_TEMPORARY, road.temporary_lanes)):
            if layer is not None:
                out.setdefault(road.id, {}).setdefault(name, []).extend(layer.lane_sections)
    return out


def _permanent_lanes(ctx: Context) -> Iterator[tuple[Road, list[LaneSection], LaneSection, Lane]]:
    """Every lane of the permanent layers: its road, the road's permanent sections, its section and the lane."""
    for road in ctx.document.roads:
        if road.lanes is None:
            continue
        sections = list(road.lanes.lane_sections)
        for section in sections:
            for lane in (*section.left, *section.center, *section.right):
                yield road, sections, section, lane


def _where(road: str, section: LaneSection, lane: Lane, line: int | None = None) -> dict:
    """Finding location fields: road, lane, lane section, s and the line (the lane's unless given)."""
    return {"road": road, "lane": lane.id, "section_s": section.s, "s": section.s, "line": line or lane.line or None}


def _describe(road: str, section: LaneSection, lane: Lane) -> str:
    return f"road {road} lane {lane.id} (lane section s={metres(section.s)})"


def section_end(section: LaneSection, layer: list[LaneSection], road_length: float | None) -> float | None:
    """Where a lane section ends: ``s + length``, else the next section's start in its layer, else the road's end."""
    if section.length is not None:
        return section.s + section.length
    later = [other.s for other in layer if other.s > section.s]
    return min(later) if later else road_length


def _s(section: LaneSection) -> str:
    return metres(section.s)


def _road_length(ctx: Context, road_id: str) -> float | None:
    road = ctx.road(road_id)
    return None if road is None else road.length


def _number(value: float) -> str:
    """A number as a file would write it: ``50``, ``12.5`` (exactly)."""
    short = f"{value:g}"
    return short if float(short) == value else repr(value)


@rule("L029", "road-without-centre-lane", Category.LANE, Severity.ERROR, uids=(U.CENTER_LANE,))
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
    for road, layers in _layers(ctx).items():
        placed = [sections for sections in layers.values() if sections]
        if not placed or any(all(_has_centre(section) for section in sections) for sections in placed):
            continue
        found = ctx.road(road)
        yield road_without_centre_lane.finding(
            f"road {road}: no lane layer of the road has a centre lane 0 in each of its lane sections; give the "
            "permanent layer's lane sections their centre lane",
            road=road,
            line=(found.line if found is not None else None) or placed[0][0].line or None,
        )


def _has_centre(section: LaneSection) -> bool:
    return any(lane.id == 0 for lane in section.center)


@rule(
    "L033",
    "permanent-section-length",
    Category.LANE,
    Severity.ERROR,
    uids=(U.LAYER_LENGTH_ONLY_TEMPORARY, U.LAYER_MANDATORY_PERMANENT),
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
        permanent = layers.get(_PERMANENT, [])
        for section in permanent:
            length = section.xml.text("length") if section.length is None else _number(section.length)
            if length is None:
                continue
            here = f'road {road_id}: the permanent layer\'s lane section at s={_s(section)} has length="{length}"'
            fix = "only temporary lane sections have a length: remove it (the section lasts until the next one)"
            ends = section_end(section, permanent, None)
            later = [o.s for o in permanent if o is not section and o.s > section.s]
            after = min(later) if later else _road_length(ctx, road_id)
            if ends is not None and after is not None and after - ends > tol:
                yield permanent_section_length.finding(
                    f"{here}, so the road has no permanent lane from s={metres(ends)} to s={metres(after)}; {fix}",
                    uid=U.LAYER_MANDATORY_PERMANENT,
                    road=road_id,
                    section_s=section.s,
                    s=section.s,
                    line=section.line or None,
                )
                continue
            yield permanent_section_length.finding(
                f"{here}; {fix}",
                uid=U.LAYER_LENGTH_ONLY_TEMPORARY,
                road=road_id,
                section_s=section.s,
                s=section.s,
                line=section.line or None,
            )


@rule("L030", "temporary-lane-physical", Category.LANE, Severity.ERROR, uids=(U.LAYER_PHYS_ATTR_TEMPORARY,))
def temporary_lane_physical(ctx: Context):
    """A lane of the temporary lane layer has ``<height>`` or ``<material>`` records.

    Annex F ``road.lane.layer.lane_phys_attr_temporary`` (1.9): the temporary layer changes how the road is used, not
    the road itself; height and material come from the permanent layer, so temporary lanes have neither.

    Passes::

        <lanes layer="temporary"> ... <lane id="-1" type="driving"><width sOffset="0" a="3.25" .../></lane>

    Fails::

        <lanes layer="temporary"> ... <lane id="-1" type="driving"><width .../><material sOffset="0" friction="0.5"/>
    """
    for road in ctx.document.roads:
        if road.temporary_lanes is None:
            continue
        for section in road.temporary_lanes.lane_sections:
            for lane in (*section.left, *section.center, *section.right):
                physical = _physical(lane)
                if physical is None:
                    continue
                tag, line = physical
                yield temporary_lane_physical.finding(
                    f"{_describe(road.id, section, lane)}: a lane of the temporary layer has a <{tag}> (line {line}); "
                    f"the permanent layer's lanes give the road's {tag}: remove it",
                    **_where(road.id, section, lane, line),
                )


def _physical(lane: Lane) -> tuple[str, int | None] | None:
    """The lane's first ``<height>`` or ``<material>`` in the file and its line (the lane's when it was not read)."""
    records: dict[str, tuple[LaneHeight, ...] | tuple[LaneMaterial, ...]] = {
        "height": lane.heights,
        "material": lane.materials,
    }
    tags = [tag for tag in lane.xml.children if tag in records]
    if not tags:  # a lane built in code: its records
        firsts = sorted((found[0].line, tag) for tag, found in records.items() if found)
        tags = [tag for _, tag in firsts]
    if not tags:
        return None
    found = records[tags[0]]
    return tags[0], (found[0].line if found else lane.line) or None


def _links(lane: Lane, tag: str, layer: str) -> tuple[int, ...]:
    """Ids the lane links to with ``tag`` (predecessor/successor) on ``layer`` (an absent layer is permanent)."""
    if tag == "predecessor":
        return lane.predecessors if layer == _PERMANENT else lane.temporary_predecessors
    return lane.successors if layer == _PERMANENT else lane.temporary_successors


def _width_at(section: LaneSection, lane: Lane, s: float) -> float | None:
    """A lane's width at absolute ``s`` from its ``<width>`` records (``None`` without any: described by borders)."""
    if not lane.widths:
        return None
    from xodrcheck.geometry import profile

    return float(profile.evaluate(lane.widths, np.array([s]), origin=section.s)[0])


def temporary_runs(ctx: Context) -> list[tuple[str, float, float | None, LaneSection, LaneSection]]:
    """``(road, start, end, first section, last section)`` of every temporary lane layer section (``end`` is
    ``None`` when it cannot be told)."""
    out: list[tuple[str, float, float | None, LaneSection, LaneSection]] = []
    for road, layers in _layers(ctx).items():
        placed = sorted(((x.s, x) for x in layers.get(_TEMPORARY, ())), key=lambda item: item[0])
        sections = [x for _, x in placed]
        length = _road_length(ctx, road)
        run: list[tuple[float, LaneSection]] = []
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


@rule("L031", "temporary-layer-not-linked", Category.LANE, Severity.ERROR, uids=(U.LINK_TEMPORARY_TO_PERMANENT,))
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
    named: set[tuple[str | None, str, int]] = set()  # (road, predecessor/successor side, temporary lane id)
    for road_, _, _, lane_ in _permanent_lanes(ctx):
        named.update((road_.id, "successor", i) for i in lane_.temporary_successors)
        named.update((road_.id, "predecessor", i) for i in lane_.temporary_predecessors)
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
            for lane in (*section.left, *section.right):
                if not lane.drivable:
                    continue
                if _links(lane, tag, _PERMANENT) or (road, back, lane.id) in named:
                    continue
                width = _width_at(section, lane, at)
                if width is not None and abs(width) < ctx.tolerances.zero_width:
                    continue
                starts = tag == "predecessor"
                yield temporary_layer_not_linked.finding(
                    f"{_describe(road, section, lane)}: the temporary lane layer section "
                    f"{'starts' if starts else 'ends'} at s={metres(at)}, but this drivable lane has no {tag} on the "
                    f'permanent layer; link it (<{tag} id="..." layer="permanent"/>) so that traffic can '
                    f"{'enter' if starts else 'leave'} it",
                    **_where(road, section, lane) | {"s": at},
                )


@rule("L032", "layer-link-without-section", Category.LANE, Severity.ERROR, uids=(U.SECTION_NEW_TEMP_TO_PERM,))
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
    for road_id, start, end, _, _ in temporary_runs(ctx):
        runs.setdefault(road_id, []).append((start, end))
    layers = _layers(ctx)
    tol = ctx.tolerances.position
    for road, _, section, lane in _permanent_lanes(ctx):
        permanent = layers.get(road.id, {}).get(_PERMANENT, [])
        for tag, index in (("successor", 0), ("predecessor", 1)):
            targets = _links(lane, tag, _TEMPORARY)
            if not targets:
                continue
            length = _road_length(ctx, road.id)
            at = section_end(section, permanent, length) if index == 0 else section.s
            if at is not None and (at <= tol if index else length is not None and at >= length - tol):
                continue  # at the road's start or end the link reaches the linked road's temporary layer
            edges = [e for e in (run[index] for run in runs.get(road.id, ())) if e is not None]
            if at is not None and any(abs(at - edge) <= tol for edge in edges):
                continue
            where = "ends" if index == 0 else "starts"
            found = ", ".join(f"{metres(e)}" for e in edges) or "none"
            yield layer_link_without_section.finding(
                f"{_describe(road.id, section, lane)}: {tag} lane {', '.join(map(str, targets))} on the temporary "
                f"layer, but the lane section {where} at s={metres(at)}, where no temporary lane layer section "
                f"{'starts' if index == 0 else 'ends'} (temporary layer sections {'start' if index == 0 else 'end'} at "
                f"{found}); start a new permanent lane section where the lanes change layers",
                **_where(road.id, section, lane) | {"s": at},
            )
