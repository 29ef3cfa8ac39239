"""The ``ramp`` kind: an exit or entry ramp leaving or joining a road, read from the file.

A ramp is a fork-shaped junction (:mod:`.fork`) one of whose branches is a ramp: its lanes joined to the stem are of
a ramp type (``offRamp``, ``onRamp``, ``connectingRamp``), or are fed by (feed) the stem's ``exit`` (``entry``) lanes
(11.8, Figure 79). The other branch is the main road going on. On the stem, the lanes joined to the ramp are the
deceleration lane of an exit or the acceleration lane of an entry: the part of them narrower than their full width
is the taper.

Measures: ``ramp_angle``, the largest angle between the ramp's and the main road's headings away from the junction
within 100 m of it (as the fork's ``split_angle``); ``taper_length``, along the stem, how long the lane joined to the
ramp nearest the main lanes is narrower than its full width (0 when it is full width all along the stem);
``side_lane_length``, how far from the junction that lane reaches along the stem (where it starts at zero width or
the stem's far end); ``ramp_lanes``, lanes of the ramp joined to the stem; ``exit`` (1 for an exit, 0 for an entry).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from xodrcheck.analysis.metrics import Leg
from xodrcheck.geometry.lanes import geometry_of
from xodrcheck.model import ContactPoint, Document, Junction

from . import Kind, Measure, Structure
from .flows import RAMP_TYPES, SIDE_TYPES, Flow
from .fork import ForkShape, fork_shape, parting_angle

KIND = Kind(
    "ramp",
    "an exit or entry ramp: a lane leaving or joining a road beside its main lanes",
    (
        Measure("ramp_angle", "deg", 0.0, 90.0, 18, "angle between the ramp and the main road"),
        Measure("taper_length", "m", 0.0, 300.0, 15, "length over which the exit or entry lane widens (narrows)"),
        Measure("side_lane_length", "m", 0.0, 600.0, 12, "length of the exit or entry lane along the road"),
        Measure("ramp_lanes", "", 0.5, 3.5, 3, "lanes of the ramp"),
        Measure("exit", "", -0.5, 1.5, 2, "1 for an exit (off-ramp), 0 for an entry (on-ramp)"),
    ),
)

#: Width (m) below the lane's full width that counts as narrower (the taper; a cubic taper is that close to full
#: width for about 0.6 m at each end of a 60 m taper).
NARROWER = 0.001
#: Distance (m) between the points along which the lane's width is measured.
STEP = 0.1


def _rampish(flow: Flow) -> bool:
    return any(t in RAMP_TYPES or t in SIDE_TYPES for t in flow.types)


def _ramp_leg(shape: ForkShape) -> tuple[Leg, Leg] | None:
    """(ramp, main road) branches of ``shape``, or None when neither branch is a ramp."""
    ramps = [leg for leg in (shape.left, shape.right) if any(_rampish(f) for f in shape.branch_flows(leg))]
    if len(ramps) != 1:
        return None
    ramp = ramps[0]
    return ramp, shape.right if ramp is shape.left else shape.left


def _side_lane(document: Document, shape: ForkShape, ramp: Leg) -> tuple[float, float]:
    """(taper length, lane length) of the stem's lane joined to the ramp nearest the main lanes."""
    key = (shape.stem.road, shape.stem.end)
    lanes = {x.lane for f in shape.branch_flows(ramp) for x in (f.source, f.target) if (x.road, x.end) == key}
    road = document.road_by_id[shape.stem.road]
    geometry = geometry_of(document)[road.id]
    if not lanes or not road.lane_sections:
        return float("nan"), float("nan")
    lane_id = min(lanes, key=abs)
    at_end = shape.stem.end is ContactPoint.END
    order = range(len(road.lane_sections) - 1, -1, -1) if at_end else range(len(road.lane_sections))
    s_all: list[np.ndarray] = []
    w_all: list[np.ndarray] = []
    current: int | None = lane_id
    for index in order:
        lane = road.lane_sections[index].lane(current) if current is not None else None
        if lane is None:
            break
        s0, s1 = road.lane_sections[index].s, road.section_end(index)
        s = np.linspace(s0, s1, max(2, math.ceil((s1 - s0) / STEP) + 1))
        inner, outer = geometry.inner_outer(index, lane.id, s)
        s_all.append(s)
        w_all.append(np.abs(outer - inner))
        links = lane.predecessors if at_end else lane.successors
        current = links[0] if links else None
    if not s_all:
        return float("nan"), float("nan")
    s = np.concatenate(s_all)
    w = np.concatenate(w_all)
    distance = np.abs(s - (road.length if at_end else 0.0))  # from the junction
    order_ = np.argsort(distance, kind="stable")
    distance, w = distance[order_], w[order_]
    present = w > NARROWER
    reach = float(distance[present].max()) if present.any() else 0.0
    full = float(w.max())
    narrower = present & (w < full - NARROWER)
    taper = float(distance[narrower].max() - distance[narrower].min()) if narrower.any() else 0.0
    return taper, reach


def recognise(document: Document, free: Sequence[Junction]) -> list[Structure]:
    out = []
    for junction in free:
        shape = fork_shape(document, junction)
        legs = _ramp_leg(shape) if shape is not None else None
        if shape is None or legs is None:
            continue
        ramp, main = legs
        taper, reach = _side_lane(document, shape, ramp)
        values = (
            ("ramp_angle", parting_angle(document, ramp, main)),
            ("taper_length", taper),
            ("side_lane_length", reach),
            ("ramp_lanes", float(shape.branch_lanes(ramp))),
            ("exit", 0.0 if shape.merge else 1.0),
        )
        out.append(Structure(KIND.name, (junction.id,), values))
    return out
