"""Lane attributes (``L014``-``L016``, ``L023``): ``level``, ``access`` and ``direction`` values that contradict each
other or the road. Read from the document: the lanes of every lane layer."""

from __future__ import annotations

from collections.abc import Iterator

from xodrcheck.findings import Basis, Category, Severity
from xodrcheck.model import DRIVABLE_LANE_TYPES as DRIVABLE
from xodrcheck.model import Lane, LaneAccess, LaneDirection, LaneSection, Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import lane_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.lane_joints import Joint, linked_lane_pairs
from xodrcheck.support.quantities import metres


@rule("L014", "lane-level-one-side", Category.LANE, Severity.ERROR, uids=(U.LEVEL_TRUE_ONE_SIDE,), every_version=True)
def lane_level_one_side(ctx: Context):
    """On one side of a lane section, a lane with ``level="false"`` lies outside a lane with ``level="true"``.

    A level lane is kept out of superelevation; lanes outside it must be level too, or the surface would fold where
    the level lane meets the tilted one (Annex F ``road.lane.level_true_one_side``, 1.7).

    Passes::

        <right><lane id="-1" level="false"/><lane id="-2" level="true"/></right>

    Fails::

        <right><lane id="-1" level="true"/><lane id="-2" level="false"/></right>
    """
    for road in ctx.document.roads:
        for section in road.lane_sections:
            for lanes in (section.left, section.right):
                level_seen = None
                for lane in sorted(lanes, key=lambda lane_: abs(lane_.id)):
                    if lane.level:
                        level_seen = level_seen if level_seen is not None else lane.id
                    elif level_seen is not None:
                        yield lane_level_one_side.finding(
                            f"road {road.id} lane section s={metres(section.s)}: lane {lane.id} is not level but lies "
                            f"outside lane {level_seen}, which is",
                            road=road.id,
                            lane=lane.id,
                            section_s=section.s,
                            s=section.s,
                            line=lane.line or None,
                        )


@rule("L015", "lane-level-changes", Category.LANE, Severity.WARNING, basis=Basis.PLAUSIBILITY)
def lane_level_changes(ctx: Context):
    """Two linked lanes of consecutive lane sections of a road differ in ``level``: the surface steps at the joint.

    Plausibility: the standard states no rule on the level of linked lanes; a warning whatever the profile.

    Passes::

        <laneSection s="0">  ... <lane id="-1" level="true"><link><successor id="-1"/></link>...
        <laneSection s="50"> ... <lane id="-1" level="true">...

    Fails::

        <laneSection s="0">  ... <lane id="-1" level="true"><link><successor id="-1"/></link>...
        <laneSection s="50"> ... <lane id="-1" level="false">...
    """

    def steps(joint: Joint, lane: Lane, target: Lane) -> bool:
        return joint.mine.road is joint.other.road and target.level != lane.level

    for joint, lane, target in linked_lane_pairs(ctx, steps):
        mine = joint.mine
        yield lane_level_changes.finding(
            f"{mine.describe()}: lane {lane.id} (level={str(lane.level).lower()}) is linked to lane "
            f"{target.id} of {joint.other.describe()} (level={str(target.level).lower()})",
            line=lane.line or None,
            **mine.where(lane.id),
        )


@rule("L016", "lane-access-mixed", Category.LANE, Severity.ERROR, uids=(U.ACCESS_NO_MIX,), every_version=True)
def lane_access_mixed(ctx: Context):
    """A lane's ``<access>`` records mix ``rule="allow"`` and ``rule="deny"`` at one ``sOffset``.

    At a given position either only allow or only deny values shall be given (Annex F
    ``road.lane.access.no_mix_of_deny_or_allow``, 1.7); mixed, the lane's permissions are undefined.

    Passes::

        <access sOffset="0" rule="allow" restriction="bus"/><access sOffset="0" rule="allow" restriction="taxi"/>

    Fails::

        <access sOffset="0" rule="allow" restriction="bus"/><access sOffset="0" rule="deny" restriction="truck"/>
    """
    for road, section in _sections(ctx):
        for lane in (*section.left, *section.center, *section.right):
            rules: dict[str, tuple[str, int]] = {}
            for access in lane.access:
                rule_ = _rule(access)
                if rule_ is None:
                    continue
                offset = _offset(access)
                key = _offset_key(offset)
                if key in rules and rules[key][0] != rule_:
                    yield lane_access_mixed.finding(
                        f"lane {lane.id} of road {road.id}: access records at sOffset {offset} mix "
                        f'rule="{rules[key][0]}" (line {rules[key][1]}) and rule="{rule_}"',
                        road=road.id,
                        lane=lane.id,
                        line=access.line,
                    )
                rules.setdefault(key, (rule_, access.line))


def _sections(ctx: Context) -> Iterator[tuple[Road, LaneSection]]:
    """Every lane section of every lane layer (the permanent one, then the temporary one) of every road."""
    for road in ctx.document.roads:
        for layer in (road.lanes, road.temporary_lanes):
            if layer is not None:
                for section in layer.lane_sections:
                    yield road, section


def _rule(access: LaneAccess) -> str | None:
    """The access record's ``rule`` as written (``None``: absent)."""
    return access.rule.value if access.rule is not None else access.xml.text("rule")


def _offset(access: LaneAccess) -> str:
    """The access record's ``sOffset``: the value, or its text when it is not a number ('' when absent)."""
    if access.s is not None:
        return metres(access.s)
    return (access.xml.text("sOffset") or "").strip()


def _offset_key(text: str) -> str:
    try:
        return f"{float(text):.6f}"
    except ValueError:
        return text


@rule(
    "L023",
    "lane-direction-reverses-traffic",
    Category.LANE,
    Severity.ERROR,
    uids=(U.LANE_REVERSE_LEFT_RIGHT,),
)
def lane_direction_reverses_traffic(ctx: Context):
    """Every drivable lane of a lane section has ``direction="reversed"``: the road's traffic rule is turned round.

    ``@direction="reversed"`` (1.8) reverses one lane's driving direction, for a contraflow lane say. Reversing all of
    a lane section's drivable lanes drives right-hand traffic on the left (or left-hand traffic on the right): Annex F
    ``road.lane.lane_reverse_left_right`` says the attribute shall not be used to change from right-hand to left-hand
    traffic and back. Set the road's ``rule`` (``RHT``/``LHT``) instead, or put the lanes on the side whose default
    direction they have.

    Passes (one contraflow lane)::

        <left><lane id="1" type="driving"/></left>
        <right><lane id="-1" type="driving" direction="reversed"/><lane id="-2" type="driving"/></right>

    Fails::

        <left><lane id="1" type="driving" direction="reversed"/></left>
        <right><lane id="-1" type="driving" direction="reversed"/></right>
    """
    for road, section in _sections(ctx):
        drivable = [lane for lane in _side_lanes_as_written(section) if lane.type in DRIVABLE]
        if drivable and all(lane.direction is LaneDirection.REVERSED for lane in drivable):
            first = drivable[0]
            ids = ", ".join(str(lane.id) for lane in drivable)
            yield lane_direction_reverses_traffic.finding(
                f"road {road.id} lane {first.id} (lane section s={metres(section.s)}): every drivable lane of the "
                f'lane section ({ids}) has direction="reversed", which turns the road\'s traffic rule round; set the '
                "road's rule (RHT/LHT) instead",
                road=road.id,
                lane=first.id,
                section_s=section.s,
                s=section.s,
                line=first.line,
            )


def _side_lanes_as_written(section: LaneSection) -> list[Lane]:
    """The lanes of the section's ``<left>`` and ``<right>``, in the order the file lists them."""
    groups = dict.fromkeys(tag for tag in section.xml.children if tag in ("left", "right")) or ("left", "right")
    return [lane for group in groups for lane in (section.left if group == "left" else section.right)]
