"""Generation parameters: one frozen dataclass, validated before anything is drawn.

Every check raises :class:`junctionart.errors.ParamsError` naming the parameter, the bad value and the valid range.
Defaults follow the original JunctionArt (see ``junctionart-notes.md``) except where a defect is fixed.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass, field, fields, replace
from typing import Any

from .errors import ParamsError


class SplitStrategy(enum.Enum):
    """Which incoming lane feeds the extra outgoing lanes of a junction leg."""

    SPLIT_FIRST = "split-first"  # the lane nearest the centre line
    SPLIT_LAST = "split-last"  # the lane nearest the kerb
    RANDOM = "random"  # one of the two, drawn per incoming leg


class TrafficRule(enum.Enum):
    RHT = "RHT"
    LHT = "LHT"


class JunctionControl(enum.Enum):
    """How junctions of 3+ legs are controlled (:mod:`junctionart.scenario.signals`)."""

    AUTO = "auto"  #: by leg count and road class, with the documented probabilities
    TRAFFIC_LIGHTS = "traffic-lights"  #: every junction signalised
    STOP = "stop"  #: stop signs on the legs off the priority road
    YIELD = "yield"  #: yield signs on the legs off the priority road
    NONE = "none"  #: no signals (the paper's maps)


class Terrain(enum.Enum):
    """The ground the map is laid on (:mod:`junctionart.scenario.terrain`)."""

    FLAT = "flat"  #: every road at height 0 (the paper's maps)
    ROLLING = "rolling"  #: up to 5 % grade
    HILLY = "hilly"  #: up to 8 % grade


class Roadside(enum.Enum):
    """What lies beyond the outermost driving lanes (:mod:`junctionart.scenario.roadside`)."""

    URBAN = "urban"  #: kerb and sidewalk on both sides of every road, continued round junction corners
    RURAL = "rural"  #: paved shoulder and an unpaved border on both sides, continued round junction corners
    NONE = "none"  #: driving lanes and medians only (the paper's maps)


STATES = ("orthogonal", "parallel", "random", "commonEnd")

#: The original's MDP over the shape of the next section between a pair of control lines.
DEFAULT_TRANSITIONS: dict[str, dict[str, float]] = {
    "start": {"orthogonal": 0.3, "random": 0.7},
    "orthogonal": {"parallel": 0.4, "random": 0.3, "commonEnd": 0.3},
    "parallel": {"orthogonal": 0.4, "parallel": 0.3, "random": 0.2, "commonEnd": 0.1},
    "random": {"orthogonal": 0.1, "parallel": 0.5, "random": 0.3, "commonEnd": 0.1},
    "commonEnd": {"orthogonal": 0.5, "parallel": 0.1, "random": 0.4},
}

VERSIONS = ("1.8", "1.9", "1.7")

# Bounds of a map, set from measurements (2-core machine shared with other jobs, ``junctionart generate``, seed 1):
# 5 km x 5 km 16 s; 10 km x 10 km 49-106 s and 0.4 GB; 100 km x 1 km 231 s; 1 km x 100 km 159 s; 14.1 km x 14.1 km
# 203 s; time grows faster than the area (5 -> 10 km: x6.5) and with the total length of the control lines, about
# 550-580 km in each of the 1e8 m^2 maps. 100 km x 100 km was still in its second stage after 400 s.
#: Smallest and largest side (m) of an automatic map.
MIN_SIDE, MAX_SIDE = 50.0, 100_000.0
#: Outer radius (m) of a roundabout's circulating carriageway a control-line file or a description may ask for (the
#: generator makes it larger where the lanes or the arms need more room, and says so among the repairs).
ROUNDABOUT_RADIUS = (6.0, 80.0)
#: Circulating lanes a roundabout may have.
ROUNDABOUT_LANES = (1, 2)
#: Largest area (m^2) of an automatic map: 100 km^2, e.g. 10 km x 10 km, which takes 1-2 minutes.
MAX_AREA = 1e8


def _frozen_transitions(t: dict[str, dict[str, float]]) -> tuple[tuple[str, tuple[tuple[str, float], ...]], ...]:
    return tuple((k, tuple(sorted(v.items()))) for k, v in sorted(t.items()))


@dataclass(frozen=True)
class Params:
    """All parameters of one generation run (lengths in metres, probabilities in [0, 1])."""

    width: float = 500.0  #: map width W (automatic control lines span x = 0..W)
    height: float = 500.0  #: map height H (automatic control lines stay inside y = 0..H)
    n_lines: int | None = None  #: automatic control lines; None: as many as fit in H
    line_spacing: tuple[float, float] = (80.0, 200.0)  #: gap between consecutive automatic lines
    snap_distance: float = 60.0  #: control points on one line closer than this are merged
    min_distance: float = 100.0  #: smallest gap between adjacent control points on a line
    max_distance: float = 150.0  #: largest gap (before the scale factor)
    gap_scale: tuple[float, float] = (1.0, 2.1)  #: the gap is also multiplied by a factor drawn in this range
    transitions: tuple[tuple[str, tuple[tuple[str, float], ...]], ...] = field(
        default_factory=lambda: _frozen_transitions(DEFAULT_TRANSITIONS)
    )
    randomize_lanes: bool = False  #: False: one lane each way everywhere
    lane_distribution_side: tuple[float, float, float, float] = (0.15, 0.6, 0.2, 0.05)  #: P(0..3 lanes on a side)
    lane_distribution_control_lines: tuple[float, float, float, float] = (0.05, 0.45, 0.4, 0.1)
    #: controlLineLaneConfigurations: exact (forward, backward) lanes of the roads along automatic line i
    control_line_lanes: tuple[tuple[int, int], ...] = ()
    lane_width: float = 3.5
    median_probability: float = 0.3  #: chance that a two-way road gets a median lane
    median_width: float = 2.0
    split_strategy: SplitStrategy = SplitStrategy.RANDOM
    traffic_rule: TrafficRule = TrafficRule.RHT
    curved_roads: bool = False  #: bend long connections through an extra vertex
    curve_probability: float = 0.5  #: chance that an eligible connection is bent (with curved_roads)
    turn_lane_probability: float = 0.2  #: chance of a turn lane before a junction where the exits allow it
    #: chance that a leg gets a U-turn lane where one fits (lane-centre radius >= min_turn_radius: a median or
    #: several outgoing lanes)
    u_turn_probability: float = 0.3
    min_turn_radius: float = 5.0  #: smallest radius of any reference line or lane centre line written
    #: legs of one intersection closer than this angle (degrees) lose one of their roads where the map stays
    #: connected without it (0: keep every leg)
    min_leg_angle: float = 20.0
    taper_length: float = 25.0  #: length of a lane split / merge
    version: str = "1.8"  #: OpenDRIVE version written: "1.8", "1.9" or "1.7"
    # Scenario features (issue 16): off by default, so the defaults give the paper's maps byte for byte; the
    # "scenario" profile (:data:`PROFILES`) turns them on.
    roadside: Roadside = Roadside.NONE  #: sidewalks and kerbs, or shoulders, beside the driving lanes
    junction_control: JunctionControl = JunctionControl.NONE  #: traffic lights or signs at junctions
    terrain: Terrain = Terrain.FLAT  #: elevation profiles follow this ground
    #: chance that a crossing of two control lines becomes an overpass instead of a junction, where both roads are
    #: long enough for the ramps (:mod:`junctionart.scenario.overpass`); 0: every crossing is a junction
    overpass_probability: float = 0.0
    #: chance that a junction of 3 to 6 legs becomes a roundabout (:mod:`junctionart.intersections.roundabout`): a
    #: one-way ring of 1 or 2 lanes with a junction per arm; 0: every junction is an ordinary one
    roundabout_probability: float = 0.0
    country: str = "DE"  #: whose sign catalogue the signs come from (:mod:`junctionart.scenario.catalogue`)
    #: chance that a road with a long enough straight stretch forks: its outermost lane (or one it gains) splits off
    #: and joins it again further on (:mod:`junctionart.splits.network`); 0: no forks
    fork_probability: float = 0.0
    #: chance that such a road gains a ramp pair instead: an exit lane and off-ramp, a link road, an on-ramp and an
    #: entry lane; 0: no ramps
    ramp_probability: float = 0.0
    #: forks and ramps meet their road at direct junctions (OpenDRIVE 1.7+, 12.6; the default) or, false, at default
    #: junctions with connecting roads (what CARLA 0.9.16 and SUMO 1.28 read: neither loads a direct junction)
    direct_junctions: bool = True

    def __post_init__(self) -> None:
        validate(self)

    def transition_table(self) -> dict[str, dict[str, float]]:
        return {k: dict(v) for k, v in self.transitions}

    def with_(self, **changes: Any) -> Params:
        """A copy with some fields changed (validated again)."""
        return replace(self, **changes)

    @property
    def scenario(self) -> bool:
        """Whether any scenario feature is on (the "paper" profile has none)."""
        return (
            self.roadside is not Roadside.NONE
            or self.junction_control is not JunctionControl.NONE
            or self.terrain is not Terrain.FLAT
            or self.overpass_probability > 0.0
            or self.roundabout_probability > 0.0
        )

    @property
    def structures(self) -> bool:
        """Whether forks or ramps may be placed (the "paper" profile places none)."""
        return self.fork_probability > 0.0 or self.ramp_probability > 0.0

    @classmethod
    def create(cls, profile: str | None = None, **values: Any) -> Params:
        """Build from plain values (strings for enums, a nested dict for ``transitions``), validated. ``profile``
        ("paper", the default, or "scenario") sets the scenario features first; ``values`` override it."""
        names = {f.name for f in fields(cls)}
        unknown = sorted(set(values) - names)
        if unknown:
            raise ParamsError(f"unknown parameter {unknown[0]!r}; valid: {', '.join(sorted(names))}")
        if profile is not None and profile not in PROFILES:
            raise ParamsError(f"profile={profile!r}: must be one of {', '.join(PROFILES)}")
        v = {**PROFILES[profile or "paper"], **values}
        for name, kind in _ENUMS.items():
            if name in v and not isinstance(v[name], kind):
                v[name] = _enum(kind, name, v[name])
        if "transitions" in v and isinstance(v["transitions"], dict):
            _check_transition_dict(v["transitions"])
            v["transitions"] = _frozen_transitions(v["transitions"])
        for name in ("line_spacing", "gap_scale", "lane_distribution_side", "lane_distribution_control_lines"):
            if name in v and isinstance(v[name], list):
                v[name] = tuple(v[name])
        if "control_line_lanes" in v and isinstance(v["control_line_lanes"], list):
            v["control_line_lanes"] = tuple(tuple(x) if isinstance(x, list) else x for x in v["control_line_lanes"])
        return cls(**v)


#: Enum-valued parameters, read from their values' text by :meth:`Params.create`.
_ENUMS: dict[str, type[enum.Enum]] = {
    "split_strategy": SplitStrategy,
    "traffic_rule": TrafficRule,
    "roadside": Roadside,
    "junction_control": JunctionControl,
    "terrain": Terrain,
}

#: Named sets of parameter values. "paper" (the defaults): the JunctionArt paper's maps, every scenario feature off, so
#: earlier maps, the golden snapshots and the paper's ERA are reproduced byte for byte. "scenario": a drivable test
#: map with what scenarios need (urban roadside: kerbs and sidewalks continued round every junction corner; junction
#: control drawn per junction: traffic lights with signal groups, stop or yield signs; half of the crossings of control
#: lines long enough for ramps become overpasses, the others junctions; of the roads with a straight stretch for one,
#: 15 % fork and 10 % gain a ramp pair, joined by default junctions that CARLA and SUMO read; a quarter of the
#: junctions of 3 to 6 legs become roundabouts, with a yield sign, the roundabout sign and a yield line on every entry).
PROFILES: dict[str, dict[str, Any]] = {
    "paper": {},
    "scenario": {
        "roadside": Roadside.URBAN,
        "junction_control": JunctionControl.AUTO,
        "overpass_probability": 0.5,
        "fork_probability": 0.15,
        "ramp_probability": 0.1,
        "direct_junctions": False,
        "roundabout_probability": 0.25,
    },
}


def _enum(kind: type[enum.Enum], name: str, value: Any) -> Any:
    try:
        return kind(value)
    except ValueError:
        raise ParamsError(f"{name}={value!r}: must be one of {', '.join(m.value for m in kind)}") from None


def _number(name: str, value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ParamsError(f"{name}={value!r}: must be a finite number")
    return float(value)


def _range(name: str, value: Any, lo: float, hi: float, *, lo_open: bool = False) -> float:
    x = _number(name, value)
    if x < lo or x > hi or (lo_open and x == lo):
        left = "(" if lo_open else "["
        raise ParamsError(f"{name}={value!r}: must be in {left}{lo:g}, {hi:g}]")
    return x


def _pair(name: str, value: Any, lo: float, hi: float) -> None:
    if not isinstance(value, tuple) or len(value) != 2:
        raise ParamsError(f"{name}={value!r}: must be a pair (low, high)")
    a = _range(f"{name}[0]", value[0], lo, hi, lo_open=lo == 0)
    b = _range(f"{name}[1]", value[1], lo, hi, lo_open=lo == 0)
    if a > b:
        raise ParamsError(f"{name}={value!r}: low {a:g} must not exceed high {b:g}")


def _distribution(name: str, value: Any) -> None:
    if not isinstance(value, tuple) or len(value) != 4:
        raise ParamsError(f"{name}={value!r}: must be 4 probabilities for 0, 1, 2, 3 lanes")
    for i, p in enumerate(value):
        _range(f"{name}[{i}]", p, 0.0, 1.0)
    total = sum(value)
    if abs(total - 1.0) > 1e-9:
        raise ParamsError(f"{name}={value!r}: probabilities must sum to 1 (they sum to {total:g})")
    if sum(value[1:]) <= 0:
        raise ParamsError(f"{name}={value!r}: at least one of 1, 2, 3 lanes needs a positive probability")


def _check_transition_dict(t: Any) -> None:
    if not isinstance(t, dict):
        raise ParamsError(f"transitions={t!r}: must map a state to {{next state: probability}}")
    valid = ("start", *STATES)
    for state, row in t.items():
        if state not in valid:
            raise ParamsError(f"transitions: unknown state {state!r}; valid: {', '.join(valid)}")
        if not isinstance(row, dict) or not row:
            raise ParamsError(f"transitions[{state!r}]={row!r}: must be a non-empty {{next state: probability}}")
        for nxt, p in row.items():
            if nxt not in STATES:
                raise ParamsError(f"transitions[{state!r}]: unknown next state {nxt!r}; valid: {', '.join(STATES)}")
            _range(f"transitions[{state!r}][{nxt!r}]", p, 0.0, 1.0)
        total = sum(row.values())
        if abs(total - 1.0) > 1e-9:
            raise ParamsError(f"transitions[{state!r}]: probabilities must sum to 1 (they sum to {total:g})")
    missing = [s for s in valid if s not in t]
    if missing:
        raise ParamsError(f"transitions: no row for state {missing[0]!r}")


def size_check(width: Any, height: Any, typed: str | None = None) -> None:
    """Raise :class:`ParamsError` when an automatic map of ``width`` x ``height`` is outside the bounds (each side in
    [:data:`MIN_SIDE`, :data:`MAX_SIDE`], area at most :data:`MAX_AREA`). ``typed`` (``--size 0x0``) names the value
    as the user gave it; without it the message names the parameters."""
    for name, value in (("width", width), ("height", height)):
        if typed is None:
            _range(name, value, MIN_SIDE, MAX_SIDE)
        elif not (math.isfinite(value) and MIN_SIDE <= value <= MAX_SIDE):
            raise ParamsError(f"{typed}: the {name} must be in [{MIN_SIDE:g}, {MAX_SIDE:g}] m, got {value:g}")
    area = float(width) * float(height)
    if area > MAX_AREA:
        what = typed or f"width={width!r}, height={height!r}"
        raise ParamsError(
            f"{what}: the map would cover {area:.3g} m^2, more than the bound of {MAX_AREA:.0e} m^2 (10 km x 10 km "
            "takes 1-2 minutes; time grows faster than the area): generate several smaller maps"
        )


def validate(p: Params) -> None:
    """Raise :class:`ParamsError` for the first parameter outside its range."""
    size_check(p.width, p.height)
    if p.n_lines is not None and (
        isinstance(p.n_lines, bool) or not isinstance(p.n_lines, int) or not 2 <= p.n_lines <= 1000
    ):
        raise ParamsError(f"n_lines={p.n_lines!r}: must be an integer in [2, 1000] or None")
    _pair("line_spacing", p.line_spacing, 0.0, 10_000.0)
    if p.line_spacing[0] < 40.0:
        raise ParamsError(f"line_spacing={p.line_spacing!r}: low must be at least 40 m (roads would overlap)")
    _range("snap_distance", p.snap_distance, 0.0, 10_000.0)
    _range("min_distance", p.min_distance, 20.0, 10_000.0)
    _range("max_distance", p.max_distance, 20.0, 10_000.0)
    if p.min_distance > p.max_distance:
        raise ParamsError(f"min_distance={p.min_distance!r}: must not exceed max_distance={p.max_distance!r}")
    _pair("gap_scale", p.gap_scale, 0.0, 100.0)
    _check_transition_dict(p.transition_table())
    if not isinstance(p.randomize_lanes, bool):
        raise ParamsError(f"randomize_lanes={p.randomize_lanes!r}: must be true or false")
    _distribution("lane_distribution_side", p.lane_distribution_side)
    _distribution("lane_distribution_control_lines", p.lane_distribution_control_lines)
    if not isinstance(p.control_line_lanes, tuple):
        raise ParamsError(f"control_line_lanes={p.control_line_lanes!r}: must be a tuple of (forward, backward) pairs")
    for i, pair in enumerate(p.control_line_lanes):
        ok = (
            isinstance(pair, tuple)
            and len(pair) == 2
            and all(isinstance(n, int) and not isinstance(n, bool) and 0 <= n <= 3 for n in pair)
        )
        if not ok or pair == (0, 0):
            raise ParamsError(
                f"control_line_lanes[{i}]={pair!r}: must be (forward, backward) lane counts in [0, 3], not both 0"
            )
    _range("lane_width", p.lane_width, 2.0, 6.0)
    _range("median_probability", p.median_probability, 0.0, 1.0)
    _range("median_width", p.median_width, 0.5, 10.0)
    if not isinstance(p.split_strategy, SplitStrategy):
        raise ParamsError(f"split_strategy={p.split_strategy!r}: must be one of split-first, split-last, random")
    if not isinstance(p.traffic_rule, TrafficRule):
        raise ParamsError(f"traffic_rule={p.traffic_rule!r}: must be RHT or LHT")
    if not isinstance(p.curved_roads, bool):
        raise ParamsError(f"curved_roads={p.curved_roads!r}: must be true or false")
    _range("curve_probability", p.curve_probability, 0.0, 1.0)
    _range("turn_lane_probability", p.turn_lane_probability, 0.0, 1.0)
    _range("u_turn_probability", p.u_turn_probability, 0.0, 1.0)
    _range("min_turn_radius", p.min_turn_radius, 1.0, 50.0)
    _range("min_leg_angle", p.min_leg_angle, 0.0, 50.0)
    _range("taper_length", p.taper_length, 5.0, 200.0)
    if p.version not in VERSIONS:
        raise ParamsError(f"version={p.version!r}: must be one of {', '.join(VERSIONS)}")
    _validate_scenario(p)


def _validate_scenario(p: Params) -> None:
    _range("overpass_probability", p.overpass_probability, 0.0, 1.0)
    _range("fork_probability", p.fork_probability, 0.0, 1.0)
    _range("ramp_probability", p.ramp_probability, 0.0, 1.0)
    if not isinstance(p.direct_junctions, bool):
        raise ParamsError(f"direct_junctions={p.direct_junctions!r}: must be true or false")
    _range("roundabout_probability", p.roundabout_probability, 0.0, 1.0)
    for name, kind in _ENUMS.items():
        if not isinstance(getattr(p, name), kind):
            valid = ", ".join(str(m.value) for m in kind)
            raise ParamsError(f"{name}={getattr(p, name)!r}: must be one of {valid}")
    from .scenario.catalogue import COUNTRIES

    if p.country not in COUNTRIES:
        raise ParamsError(f"country={p.country!r}: must be one of {', '.join(sorted(COUNTRIES))}")
