"""Descriptions of forks, merges and ramps (``junctionart intersection --spec`` with a ``kind``, and its presets).

A *fork* is one road (the *stem*) whose lanes of one direction continue on two roads (the *branches*); a *merge* the
same run the other way (two roads whose lanes join one). Left and right are the driver's: for a fork, looking from
the stem into the branches; for a merge, driving towards the stem. A branch's ``turn`` is the angle (degrees) its far
part makes with the stem's line, positive when it lies to the left; the left branch turns left or goes straight on
(``turn >= 0``), the right branch turns right or goes straight on (``turn <= 0``), and they part: the *split angle*
``left.turn - right.turn`` is at least :data:`MIN_SPLIT` degrees. Lanes of the other direction (``oncoming``) continue
on the branch on their side (the left one under right-hand traffic).

A *ramp* is an exit or an entry beside a main road: an ``exit`` lane widens beside the main lanes over
``taper_length`` and runs ``lane_length`` at full width to where the ``offRamp`` road leaves (an entry: the
``onRamp`` road joins, its lanes run on as an ``entry`` lane that narrows away), as 11.8 (Figure 79) shows. The ramp
runs ``parallel_length`` beside the main road, then turns ``angle`` degrees away at ``radius``.

Both are built on one junction at the origin, the stem (main road) arriving from the west, with ``type="direct"``
(OpenDRIVE 1.7+, 12.6: the roads are linked to each other, no connecting roads) or, with ``junction="default"``, as a
common junction whose connecting roads carry each branch's first :data:`JUNCTION_LENGTH` metres (CARLA 0.9.16 and
SUMO 1.28 read no direct junction: their parsers require ``connectingRoad``).

JSON (``kind`` "fork" or "ramp"; every other key optional)::

    {"kind": "fork", "left": {"lanes": 1, "turn": 35, "radius": 60}, "right": {"lanes": 1, "turn": 0},
     "oncoming": 0, "merge": false, "junction": "direct", "lane_width": 3.5, "approach_length": 150,
     "branch_length": 150, "traffic_rule": "RHT", "version": "1.8"}
    {"kind": "ramp", "entry": false, "lanes": 2, "oncoming": 2, "ramp_lanes": 1, "taper_length": 60,
     "lane_length": 100, "parallel_length": 20, "angle": 30, "radius": 80, ...}
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Any

from ..errors import ParamsError
from ..params import VERSIONS, TrafficRule

#: Smallest split angle (degrees) of a fork: the branches must part.
MIN_SPLIT = 2.0
#: Largest turn (degrees) of a branch or a ramp.
MAX_TURN = 90.0
#: Length (m) of each branch's first stretch carried by a connecting road when the junction is a default one.
JUNCTION_LENGTH = 10.0
#: Radius (m) every lane centre keeps at least (the generator's default ``min_turn_radius``).
MIN_RADIUS = 5.0
JUNCTIONS = ("direct", "default")


@dataclass(frozen=True)
class Branch:
    """One branch of a fork: lanes continuing on it, its turn (degrees, positive: it lies left of the stem's line),
    the radius of its curve and the straight run before the curve."""

    lanes: int = 1
    turn: float = 0.0
    radius: float = 60.0
    lead: float = 0.0


@dataclass(frozen=True)
class Common:
    """What forks and ramps share: the junction's type, widths, lengths, traffic rule and version."""

    junction: str = "direct"
    lane_width: float = 3.5
    approach_length: float = 150.0  #: the stem (the main road before the junction)
    branch_length: float = 150.0  #: each branch (the main road after it, the ramp)
    traffic_rule: TrafficRule = TrafficRule.RHT
    version: str = "1.8"


@dataclass(frozen=True)
class ForkSpec(Common):
    """A fork (or, with ``merge``, a merge): module docstring."""

    left: Branch = Branch(1, 30.0)
    right: Branch = Branch(1, 0.0)
    oncoming: int = 0
    merge: bool = False

    def __post_init__(self) -> None:
        validate_fork(self)


@dataclass(frozen=True)
class RampSpec(Common):
    """An exit or entry ramp: module docstring."""

    approach_length: float = 300.0
    branch_length: float = 200.0
    entry: bool = False
    lanes: int = 2
    oncoming: int = 1
    ramp_lanes: int = 1
    taper_length: float = 60.0
    lane_length: float = 100.0
    parallel_length: float = 20.0
    angle: float = 30.0
    radius: float = 80.0

    def __post_init__(self) -> None:
        validate_ramp(self)


def _count(where: str, value: Any, lo: int, hi: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or not lo <= value <= hi:
        raise ParamsError(f"{where}={value!r}: must be an integer in [{lo}, {hi}]")
    return value


def _number(where: str, value: Any, lo: float, hi: float) -> float:
    ok = isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)
    if not ok or not lo <= value <= hi:
        raise ParamsError(f"{where}={value!r}: must be a number in [{lo:g}, {hi:g}]")
    return float(value)


def _common(spec: Common) -> None:
    if spec.junction not in JUNCTIONS:
        raise ParamsError(f"junction={spec.junction!r}: must be one of {', '.join(JUNCTIONS)}")
    _number("lane_width", spec.lane_width, 2.0, 6.0)
    _number("approach_length", spec.approach_length, 50.0, 2000.0)
    _number("branch_length", spec.branch_length, 50.0, 2000.0)
    if not isinstance(spec.traffic_rule, TrafficRule):
        raise ParamsError(f"traffic_rule={spec.traffic_rule!r}: must be RHT or LHT")
    if spec.version not in VERSIONS:
        raise ParamsError(f"version={spec.version!r}: must be one of {', '.join(VERSIONS)}")


def _curve_fits(where: str, radius: float, turn: float, inside: float, lead: float, length: float) -> None:
    """The branch's innermost lane centre keeps :data:`MIN_RADIUS`, and its lead and curve fit in its length."""
    if turn == 0.0:
        return
    if radius - inside < MIN_RADIUS:
        raise ParamsError(
            f"{where} radius={radius:g}: the lanes on the inside of its curve reach {inside:g} m in, leaving less "
            f"than {MIN_RADIUS:g} m of radius; give at least {inside + MIN_RADIUS:g}"
        )
    if lead + math.radians(abs(turn)) * radius > length - JUNCTION_LENGTH:
        raise ParamsError(
            f"{where}: its straight lead and curve ({lead + math.radians(abs(turn)) * radius:.1f} m) do not fit in "
            f"branch_length={length:g} m"
        )


def validate_fork(spec: ForkSpec) -> None:
    """Raise :class:`ParamsError` naming the first bad value of ``spec``."""
    _common(spec)
    _count("oncoming", spec.oncoming, 0, 3)
    if not isinstance(spec.merge, bool):
        raise ParamsError(f"merge={spec.merge!r}: must be true or false")
    rht = spec.traffic_rule is TrafficRule.RHT
    for name, b, lo, hi in (("left", spec.left, 0.0, MAX_TURN), ("right", spec.right, -MAX_TURN, 0.0)):
        if not isinstance(b, Branch):
            raise ParamsError(f"{name}={b!r}: must be a branch")
        _count(f"{name}.lanes", b.lanes, 1, 3)
        if isinstance(b.turn, (int, float)) and not isinstance(b.turn, bool) and not lo <= b.turn <= hi:
            raise ParamsError(
                f"{name}.turn={b.turn!r}: must be in [{lo:g}, {hi:g}] (the {name} branch turns {name} or goes "
                "straight on)"
            )
        _number(f"{name}.turn", b.turn, lo, hi)
        _number(f"{name}.radius", b.radius, 5.0, 2000.0)
        _number(f"{name}.lead", b.lead, 0.0, 500.0)
        oncoming = spec.oncoming if rht == (name == "left") else 0  # they stay on the branch on their side
        left, right = (oncoming, b.lanes) if rht else (b.lanes, oncoming)  # lanes each side of its reference line
        inside = (left if b.turn > 0 else right) * spec.lane_width
        _curve_fits(name, b.radius, b.turn, inside, b.lead, spec.branch_length)
    if spec.left.turn - spec.right.turn < MIN_SPLIT:
        raise ParamsError(
            f"left.turn={spec.left.turn:g}, right.turn={spec.right.turn:g}: the branches must part by at least "
            f"{MIN_SPLIT:g} degrees"
        )


def validate_ramp(spec: RampSpec) -> None:
    """Raise :class:`ParamsError` naming the first bad value of ``spec``."""
    _common(spec)
    if not isinstance(spec.entry, bool):
        raise ParamsError(f"entry={spec.entry!r}: must be true or false")
    _count("lanes", spec.lanes, 1, 3)
    _count("oncoming", spec.oncoming, 0, 3)
    _count("ramp_lanes", spec.ramp_lanes, 1, 2)
    _number("taper_length", spec.taper_length, 10.0, 300.0)
    _number("lane_length", spec.lane_length, 0.0, 500.0)
    _number("parallel_length", spec.parallel_length, 0.0, 300.0)
    _number("angle", spec.angle, MIN_SPLIT, MAX_TURN)
    _number("radius", spec.radius, 5.0, 2000.0)
    shift = (spec.ramp_lanes - 0.5) * spec.lane_width  # a lane centre's move over the taper
    needed = math.sqrt(24.0 * shift * MIN_RADIUS)  # curvature 6 shift / L^2 within a quarter of 1 / MIN_RADIUS
    if spec.taper_length < needed:
        raise ParamsError(
            f"taper_length={spec.taper_length:g}: {spec.ramp_lanes} lane(s) widening over it bend their centres "
            f"tighter than {MIN_RADIUS:g} m; give at least {needed:.1f}"
        )
    if spec.taper_length + spec.lane_length > spec.approach_length - 10.0:
        raise ParamsError(
            f"taper_length + lane_length = {spec.taper_length + spec.lane_length:g} m: must leave 10 m of the "
            f"approach_length={spec.approach_length:g} m"
        )
    # the ramp turns away from the main road: its own lanes are on the inside of its curve
    _curve_fits(
        "ramp", spec.radius, spec.angle, spec.ramp_lanes * spec.lane_width, spec.parallel_length, spec.branch_length
    )


# --------------------------------------------------------------------------------------------------------------------
# Plain values (JSON)
# --------------------------------------------------------------------------------------------------------------------
_BRANCH_KEYS = {f.name for f in fields(Branch)}
KINDS = {"fork": ForkSpec, "ramp": RampSpec}


def _branch(where: str, raw: Any) -> Branch:
    if isinstance(raw, Branch):
        return raw
    if not isinstance(raw, dict):
        raise ParamsError(f'{where}: expected an object {{"lanes": n, "turn": deg}}, got {raw!r}')
    unknown = sorted(set(raw) - _BRANCH_KEYS)
    if unknown:
        raise ParamsError(f"{where}: unknown key {unknown[0]!r}; valid: {', '.join(sorted(_BRANCH_KEYS))}")
    return Branch(**raw)


def from_dict(raw: Any) -> ForkSpec | RampSpec:
    """A fork or ramp description from plain values (``kind`` "fork" or "ramp"); :class:`ParamsError` for bad
    ones."""
    if not isinstance(raw, dict) or raw.get("kind") not in KINDS:
        raise ParamsError(f'a fork or ramp is a JSON object with "kind": {" or ".join(map(repr, KINDS))}')
    cls = KINDS[raw["kind"]]
    values = {k: v for k, v in raw.items() if k != "kind"}
    valid = {f.name for f in fields(cls)}
    unknown = sorted(set(values) - valid)
    if unknown:
        raise ParamsError(f"{raw['kind']}: unknown key {unknown[0]!r}; valid: {', '.join(sorted(valid))}")
    for side in ("left", "right"):
        if side in values:
            values[side] = _branch(side, values[side])
    if "traffic_rule" in values and not isinstance(values["traffic_rule"], TrafficRule):
        try:
            values["traffic_rule"] = TrafficRule(values["traffic_rule"])
        except ValueError:
            raise ParamsError(f"traffic_rule={values['traffic_rule']!r}: must be RHT or LHT") from None
    return cls(**values)


def to_dict(spec: ForkSpec | RampSpec) -> dict[str, Any]:
    """Plain values of ``spec`` (``from_dict(to_dict(s)) == s``)."""
    out: dict[str, Any] = {"kind": "fork" if isinstance(spec, ForkSpec) else "ramp"}
    for f in fields(spec):
        value = getattr(spec, f.name)
        if isinstance(value, Branch):
            value = {g.name: getattr(value, g.name) for g in fields(Branch)}
        elif isinstance(value, TrafficRule):
            value = value.value
        out[f.name] = value
    return out


#: Named descriptions for ``junctionart intersection --preset``.
PRESETS: dict[str, dict[str, Any]] = {
    # The JunctionArt paper's motivating case: a one-way, two-lane road in Yosemite splits in two, the left lane
    # curving off to the left, the right lane going straight on (towards the boulder cars on autopilot hit).
    "yosemite": {
        "kind": "fork",
        "left": {"lanes": 1, "turn": 40.0, "radius": 60.0},
        "right": {"lanes": 1, "turn": 0.0},
    },
    "y-fork": {
        "kind": "fork",
        "left": {"lanes": 1, "turn": 20.0, "radius": 120.0},
        "right": {"lanes": 1, "turn": -20.0, "radius": 120.0},
        "oncoming": 1,
    },
    "merge": {
        "kind": "fork",
        "merge": True,
        "left": {"lanes": 2, "turn": 0.0},
        "right": {"lanes": 1, "turn": -25.0, "radius": 100.0},
    },
    "exit": {"kind": "ramp", "lanes": 2, "oncoming": 2},
    "entry": {"kind": "ramp", "entry": True, "lanes": 2, "oncoming": 2},
}
