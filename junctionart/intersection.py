"""One intersection from an explicit description: ``junctionart intersection`` and the genome of ``junctionart search``.

A description names each leg by its *heading* (degrees, counter-clockwise from east, the direction from the junction
outwards), its lanes *in* (towards the junction) and *out*, whether its road has a *median*, and an optional *bend*
(degrees) of its approach road halfway out; plus, for the whole junction, turn lanes, U-turn lanes, the traffic rule,
lane and median widths and the length of the approach roads. The map is the one junction at the origin with one road
per leg, long enough to drive into it, built by the generator's own intersection stage
(:mod:`junctionart.intersections`), so it meets the same radius and overlap bounds as any generated map.

JSON::

    {"legs": [{"heading": 0, "in": 2, "out": 2, "median": true},
              {"heading": 100, "in": 1, "out": 1, "bend": 20},
              {"heading": 230, "in": 2, "out": 1}],
     "turn_lanes": true, "u_turns": false, "traffic_rule": "RHT", "lane_width": 3.5, "median_width": 2.0,
     "approach_length": 150}

Every approach road ends in a dead end, which traffic must be able to leave, so each leg has 1 to 3 lanes each way.
Where the legs do not fit as described, the stage repairs as it does in any map (e.g. drops a leg it cannot fit): the
result says so (:attr:`Built.repairs`) and the map's measured legs can then be fewer than requested.

A roundabout instead of a junction (3 to 6 legs, its arms): ``"roundabout": {"radius": 18, "lanes": 1}`` (the outer
radius of the circulating carriageway in metres, 1 or 2 circulating lanes; :mod:`junctionart.intersections.roundabout`).
Where its arms need more room the ring grows (up to 60 m, a repair says so); where even that does not fit them it is
built as an ordinary junction (the result's :attr:`Built.roundabout` is then None).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, fields
from typing import TYPE_CHECKING, Any

from .controllines import RoundaboutRequest
from .errors import ParamsError
from .lanes import LaneConfig, LanedNetwork
from .network import Edge, Network
from .opendrive import Document
from .params import ROUNDABOUT_LANES, ROUNDABOUT_RADIUS, Params, SplitStrategy, TrafficRule

if TYPE_CHECKING:
    from .intersections.model import RoundaboutPlan

#: Legs of one intersection (the generator's bound, :data:`junctionart.intersections.legs.MAX_LEGS`).
MIN_LEGS, MAX_LEGS = 3, 7
#: Arms of one roundabout (:data:`junctionart.intersections.roundabout_choice.MAX_ARMS`).
MAX_ARMS = 6
#: Largest bend (degrees) of an approach road halfway out.
MAX_BEND = 60.0
#: Bounds (m) of the approach length, from the junction's centre to the road's far end.
MIN_APPROACH, MAX_APPROACH = 80.0, 1000.0


@dataclass(frozen=True)
class LegSpec:
    """One leg: heading (degrees, from the junction outwards), lanes towards the junction and away from it."""

    heading: float
    lanes_in: int = 1
    lanes_out: int = 1
    median: bool = False
    bend: float = 0.0  #: degrees the approach road turns halfway out (positive: counter-clockwise)


@dataclass(frozen=True)
class IntersectionSpec:
    """A whole intersection (see the module docstring)."""

    legs: tuple[LegSpec, ...]
    turn_lanes: bool = False
    u_turns: bool = False
    traffic_rule: TrafficRule = TrafficRule.RHT
    split_strategy: SplitStrategy = SplitStrategy.SPLIT_FIRST
    lane_width: float = 3.5
    median_width: float = 2.0
    approach_length: float = 150.0
    version: str = "1.8"
    roundabout_radius: float | None = None  #: a roundabout of this outer radius (m) instead of a junction
    roundabout_lanes: int = 1  #: its circulating lanes

    def __post_init__(self) -> None:
        validate(self)

    def params(self) -> Params:
        """The generator parameters this description implies (validated by :class:`Params`)."""
        return Params(
            lane_width=self.lane_width,
            median_width=self.median_width,
            traffic_rule=self.traffic_rule,
            split_strategy=self.split_strategy,
            turn_lane_probability=1.0 if self.turn_lanes else 0.0,
            u_turn_probability=1.0 if self.u_turns else 0.0,
            min_leg_angle=0.0,
            version=self.version,
        )


def _count(where: str, value: Any, lo: int, hi: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or not lo <= value <= hi:
        raise ParamsError(f"{where}={value!r}: must be an integer in [{lo}, {hi}]")
    return value


def _finite(where: str, value: Any, lo: float, hi: float) -> float:
    ok = isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)
    if not ok or not lo <= value <= hi:
        raise ParamsError(f"{where}={value!r}: must be a number in [{lo:g}, {hi:g}]")
    return float(value)


def validate(spec: IntersectionSpec) -> None:
    """Raise :class:`ParamsError` naming the first bad value of ``spec``."""
    if not isinstance(spec.legs, tuple) or not MIN_LEGS <= len(spec.legs) <= MAX_LEGS:
        n = len(spec.legs) if isinstance(spec.legs, tuple) else spec.legs
        raise ParamsError(f"legs: {n} given, an intersection has {MIN_LEGS} to {MAX_LEGS}")
    for k, leg in enumerate(spec.legs):
        _finite(f"leg {k} heading", leg.heading, -360.0, 720.0)
        _count(f"leg {k} in", leg.lanes_in, 1, 3)
        _count(f"leg {k} out", leg.lanes_out, 1, 3)
        _finite(f"leg {k} bend", leg.bend, -MAX_BEND, MAX_BEND)
        if not isinstance(leg.median, bool):
            raise ParamsError(f"leg {k} median={leg.median!r}: must be true or false")
    headings = sorted(leg.heading % 360.0 for leg in spec.legs)
    gaps = [(b - a) for a, b in zip(headings, [*headings[1:], headings[0] + 360.0])]
    if min(gaps) < 1.0:
        raise ParamsError(f"legs: two headings are {min(gaps):.3g} deg apart; legs need at least 1 deg between them")
    _finite("approach_length", spec.approach_length, MIN_APPROACH, MAX_APPROACH)
    if spec.roundabout_radius is not None:
        _finite("roundabout radius", spec.roundabout_radius, *ROUNDABOUT_RADIUS)
        _count("roundabout lanes", spec.roundabout_lanes, *ROUNDABOUT_LANES)
        if len(spec.legs) > MAX_ARMS:
            raise ParamsError(f"legs: {len(spec.legs)} given, a roundabout has {MIN_LEGS} to {MAX_ARMS} arms")
    spec.params()  # lane and median width, version: the generator's own checks and messages


def network(spec: IntersectionSpec) -> LanedNetwork:
    """The generator's laned network of ``spec``: node 0 the junction (or roundabout), one road per leg (two edges
    when it bends)."""
    nodes: list[tuple[float, float]] = [(0.0, 0.0)]
    edges: list[Edge] = []
    lanes: list[LaneConfig] = []
    half = spec.approach_length / 2
    for leg in spec.legs:
        h = math.radians(leg.heading)
        mid = (half * math.cos(h), half * math.sin(h))
        h2 = h + math.radians(leg.bend)
        end = (mid[0] + half * math.cos(h2), mid[1] + half * math.sin(h2))
        config = LaneConfig(leg.lanes_out, leg.lanes_in, leg.median)  # edges run outwards: forward = out
        if leg.bend == 0.0:
            nodes.append(end)
            edges.append(Edge(0, len(nodes) - 1))
            lanes.append(config)
            continue
        nodes += [mid, end]
        edges += [Edge(0, len(nodes) - 2), Edge(len(nodes) - 2, len(nodes) - 1)]
        lanes += [config, config]
    rings: tuple[RoundaboutRequest, ...] = ()
    if spec.roundabout_radius is not None:
        rings = (RoundaboutRequest((0.0, 0.0), spec.roundabout_radius, spec.roundabout_lanes),)
    return LanedNetwork(Network(tuple(nodes), tuple(edges), (), rings), tuple(lanes))


@dataclass(frozen=True)
class Built:
    """A generated intersection: its document and the repairs the stage made to fit it."""

    document: Document
    legs: int  #: legs of the junction (arms of the roundabout) as built
    repairs: tuple[str, ...]
    roundabout: RoundaboutPlan | None = None  #: the roundabout as built, when one was asked for and fits


def build(spec: IntersectionSpec, seed: int = 0) -> Built:
    """The intersection of ``spec`` as the generator's document (same spec and seed: same document)."""
    import numpy as np

    from . import cleanup, intersections

    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise ParamsError(f"seed={seed!r}: must be a non-negative integer")
    params = spec.params()
    rng = np.random.default_rng(seed)
    layout = intersections.build(network(spec), params, rng)
    document = cleanup.document(layout, params, name=f"junctionart intersection seed {seed}")
    ring = layout.roundabouts[0] if layout.roundabouts else None
    legs = len(ring.arms) if ring is not None else max((j.legs for j in layout.junctions), default=0)
    return Built(document, legs, tuple(str(r) for r in layout.repairs), ring)


# --------------------------------------------------------------------------------------------------------------------
# Plain values (JSON) and the command line's leg syntax
# --------------------------------------------------------------------------------------------------------------------
_LEG_KEYS = {"heading", "in", "out", "median", "bend"}
_RING_FIELDS = {"roundabout_radius": "radius", "roundabout_lanes": "lanes"}
_SPEC_KEYS = {f.name for f in fields(IntersectionSpec)} - set(_RING_FIELDS) | {"roundabout"}


def _leg_from(k: int, raw: Any) -> LegSpec:
    if not isinstance(raw, dict):
        raise ParamsError(f'leg {k}: expected an object {{"heading": deg, "in": n, "out": m}}, got {raw!r}')
    unknown = sorted(set(raw) - _LEG_KEYS)
    if unknown:
        raise ParamsError(f"leg {k}: unknown key {unknown[0]!r}; valid: {', '.join(sorted(_LEG_KEYS))}")
    if "heading" not in raw:
        raise ParamsError(f"leg {k}: needs a heading (degrees)")
    return LegSpec(raw["heading"], raw.get("in", 1), raw.get("out", 1), raw.get("median", False), raw.get("bend", 0.0))


def from_dict(raw: Any) -> IntersectionSpec:
    """A description from plain values (parsed JSON); bad values raise :class:`ParamsError`."""
    if not isinstance(raw, dict) or not isinstance(raw.get("legs"), list):
        raise ParamsError('an intersection is a JSON object with a list "legs"')
    unknown = sorted(set(raw) - _SPEC_KEYS)
    if unknown:
        raise ParamsError(f"unknown key {unknown[0]!r}; valid: {', '.join(sorted(_SPEC_KEYS))}")
    values = dict(raw)
    values["legs"] = tuple(_leg_from(k, leg) for k, leg in enumerate(raw["legs"]))
    ring = values.pop("roundabout", None)
    if ring is not None:
        if not isinstance(ring, dict) or set(ring) - {"radius", "lanes"} or "radius" not in ring:
            raise ParamsError(f'roundabout={ring!r}: expected {{"radius": metres, "lanes": 1 or 2}}')
        values["roundabout_radius"], values["roundabout_lanes"] = ring["radius"], ring.get("lanes", 1)
    for name, kind in (("traffic_rule", TrafficRule), ("split_strategy", SplitStrategy)):
        if name in values:
            try:
                values[name] = kind(values[name])
            except ValueError:
                valid = ", ".join(m.value for m in kind)
                raise ParamsError(f"{name}={values[name]!r}: must be one of {valid}") from None
    for name in ("turn_lanes", "u_turns"):
        if name in values and not isinstance(values[name], bool):
            raise ParamsError(f"{name}={values[name]!r}: must be true or false")
    return IntersectionSpec(**values)


def to_dict(spec: IntersectionSpec) -> dict[str, Any]:
    """Plain values of ``spec`` (``from_dict(to_dict(s)) == s``)."""
    legs = [
        {"heading": g.heading, "in": g.lanes_in, "out": g.lanes_out, "median": g.median, "bend": g.bend}
        for g in spec.legs
    ]
    out: dict[str, Any] = {"legs": legs}
    for name in sorted(_SPEC_KEYS - {"legs", "roundabout"}):
        value = getattr(spec, name)
        out[name] = value.value if isinstance(value, (TrafficRule, SplitStrategy)) else value
    if spec.roundabout_radius is not None:  # only then: a junction's description stays as it was
        out["roundabout"] = {"radius": spec.roundabout_radius, "lanes": spec.roundabout_lanes}
    return out


def load(text: str) -> IntersectionSpec:
    """A description from JSON text."""
    try:
        raw = json.loads(text)
    except json.JSONDecodeError as exc:
        raise ParamsError(f"intersection description: not JSON ({exc})") from None
    return from_dict(raw)


def parse_roundabout(text: str) -> tuple[float, int]:
    """``RADIUS[:LANES]``, e.g. ``18`` or ``25:2``: the outer radius (m) and circulating lanes of a roundabout."""
    parts = text.split(":")
    try:
        if len(parts) > 2:
            raise ValueError
        return float(parts[0]), int(parts[1]) if len(parts) == 2 else 1
    except ValueError:
        raise ParamsError(f"--roundabout {text!r}: expected RADIUS[:LANES], e.g. 18 or 25:2") from None


def parse_leg(text: str) -> LegSpec:
    """``HEADING:IN:OUT[:median][:bend=DEG]``, e.g. ``90:2:1:median:bend=15``."""
    parts = text.split(":")
    if len(parts) < 3:
        raise ParamsError(f"--leg {text!r}: expected HEADING:IN:OUT[:median][:bend=DEG], e.g. 90:2:1:median")
    try:
        heading, n_in, n_out = float(parts[0]), int(parts[1]), int(parts[2])
    except ValueError:
        raise ParamsError(f"--leg {text!r}: HEADING is a number of degrees, IN and OUT lane counts") from None
    median, bend = False, 0.0
    for extra in parts[3:]:
        if extra == "median":
            median = True
        elif extra.startswith("bend="):
            try:
                bend = float(extra[5:])
            except ValueError:
                raise ParamsError(f"--leg {text!r}: bend=DEG needs a number of degrees") from None
        else:
            raise ParamsError(f"--leg {text!r}: unknown part {extra!r} (median or bend=DEG)")
    return LegSpec(heading, n_in, n_out, median, bend)
