"""Forks, merges and ramps as one layout: a stem whose lanes of one direction split between a near and a far branch.

The *near* branch keeps the stem's reference line and takes the lanes next to it (and every lane of the other
direction); the *far* branch starts beside it, its reference line at the border between the two groups of lanes,
with the same heading (12.6: a direct junction lies where the headings of road and ramp are identical). Under
right-hand traffic the near branch is the left one; under left-hand traffic the right one. A ramp is a far branch
whose lanes the stem only has near the junction (the exit or entry lane, widening over its taper). A merge is the
same layout run the other way: the branches end at the junction and the stem starts there.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..params import TrafficRule
from .spec import ForkSpec, RampSpec


@dataclass(frozen=True)
class Plan:
    """A fork, merge or ramp in near / far terms (module docstring); turns in radians, positive to the left."""

    n_near: int
    n_far: int
    oncoming: int
    near_turn: float
    far_turn: float
    near_radius: float
    far_radius: float
    near_lead: float
    far_lead: float
    merge: bool
    #: (taper length, full-width length) of the stem's far lanes, which exist only near the junction (a ramp)
    added: tuple[float, float] | None
    stem_far_type: str  #: type of the stem's far lanes: driving, or exit / entry (a ramp)
    far_type: str  #: type of the far branch's lanes: driving, or offRamp / onRamp
    junction: str
    lane_width: float
    stem_length: float
    branch_length: float
    rule: TrafficRule
    version: str
    name: str

    @property
    def forward_side(self) -> int:
        """Sign of the ids of the lanes that drive along ``s`` (-1: right lanes, right-hand traffic)."""
        return -1 if self.rule is TrafficRule.RHT else 1


def of_fork(spec: ForkSpec) -> Plan:
    rht = spec.traffic_rule is TrafficRule.RHT
    near, far = (spec.left, spec.right) if rht else (spec.right, spec.left)
    return Plan(
        near.lanes,
        far.lanes,
        spec.oncoming,
        math.radians(near.turn),
        math.radians(far.turn),
        near.radius,
        far.radius,
        near.lead,
        far.lead,
        spec.merge,
        None,
        "driving",
        "driving",
        spec.junction,
        spec.lane_width,
        spec.approach_length,
        spec.branch_length,
        spec.traffic_rule,
        spec.version,
        "merge" if spec.merge else "fork",
    )


def of_ramp(spec: RampSpec) -> Plan:
    away = -1.0 if spec.traffic_rule is TrafficRule.RHT else 1.0  # the ramp lies on the far side
    return Plan(
        spec.lanes,
        spec.ramp_lanes,
        spec.oncoming,
        0.0,
        away * math.radians(spec.angle),
        spec.radius,
        spec.radius,
        0.0,
        spec.parallel_length,
        spec.entry,
        (spec.taper_length, spec.lane_length),
        "entry" if spec.entry else "exit",
        "onRamp" if spec.entry else "offRamp",
        spec.junction,
        spec.lane_width,
        spec.approach_length,
        spec.branch_length,
        spec.traffic_rule,
        spec.version,
        "entry ramp" if spec.entry else "exit ramp",
    )


def of_spec(spec: ForkSpec | RampSpec) -> Plan:
    return of_fork(spec) if isinstance(spec, ForkSpec) else of_ramp(spec)
