"""U-turn connection lanes: only where the road is wide enough for a lane-centre radius within the bound.

A U-turn leaves a leg's innermost incoming lane and comes back on the same leg's outgoing lane ``m``. The connecting
road's reference line is the lane's inner border (as for every connection lane): a half circle whose diameter is the
lateral distance between the two lanes' inner borders, ``median + (m - 1) * lane_width``. Its radius, the smallest of
the lane (the centre and outer border lie outside it), must meet ``min_turn_radius``: only a wide median or several
outgoing lanes allow it (with the defaults, 3.5 m lanes and a 2 m median, never). The nearest such ``m`` that the
junction already feeds is used, never a tighter turn.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely

from ..lanegeom import border_point
from ..opendrive import Arc
from ..params import Params, TrafficRule
from .crossing import CLEARANCE, PARTED, TOUCH, LinkFit
from .legs import LegKey
from .links import LinkPlan
from .model import ConnectionPlan, contact_point
from .roadshape import Contact

_SAMPLES = 129


@dataclass(frozen=True)
class UTurn:
    """A U-turn lane of a leg: from an incoming lane to the outgoing lane of the same road."""

    leg: int  #: index of the leg (incoming and outgoing)
    id_in: int  #: lane id on the incoming road
    id_out: int  #: lane id on the same road, travelling away
    geometry: Arc  #: the reference line (the lane's inner border)
    radius: float  #: of the reference line; the lane centre's is half a lane width larger


def candidate(leg: int, contact: Contact, median: bool, n_out_end: int, p: Params) -> UTurn | None:
    """The U-turn of one leg, from its innermost incoming lane to the nearest outgoing lane fed at the junction whose
    half circle meets the radius bound; None when there is none."""
    lid_in, (x0, y0) = contact.entering(1, median, p)
    for m in range(1, n_out_end + 1):
        lid_out, (x1, y1) = contact.leaving(m, median, p)
        radius = math.hypot(x1 - x0, y1 - y0) / 2
        if radius >= p.min_turn_radius:
            left = 1.0 if p.traffic_rule is TrafficRule.RHT else -1.0  # RHT turns back to the left
            arc = Arc(0.0, x0, y0, contact.inward, math.pi * radius, left / radius)
            return UTurn(leg, lid_in, lid_out, arc, radius)
    return None


def u_turns(
    keys: list[LegKey],
    plan: LinkPlan,
    contacts: list[Contact],
    medians: list[bool],
    fits: list[LinkFit],
    p: Params,
    rng: np.random.Generator,
) -> list[ConnectionPlan]:
    """U-turn lanes of a finished junction: on legs where one meets the radius bound and crosses none of its
    road's other connection lanes, each with probability ``u_turn_probability``. Drawn last in stage 3, so the
    rest of the map does not depend on them."""
    if p.u_turn_probability <= 0.0:
        return []
    out = []
    for i, key in enumerate(keys):
        if plan.n_in_end[i] == 0:
            continue
        turn = candidate(i, contacts[i], medians[i], plan.n_out_end[i], p)
        if turn is None or crosses(turn, 1, fits, p):
            continue
        if rng.random() >= p.u_turn_probability:
            continue
        end = contact_point(key.at_start)
        out.append(ConnectionPlan(key.chain, end, turn.id_in, key.chain, end, turn.id_out, turn.geometry, turn.radius))
    return out


def _centre_points(ref: Arc, w: float) -> np.ndarray:
    """The lane centre of a U-turn: half a lane width outside its reference arc."""
    radius = 1.0 / abs(ref.curvature) + w / 2
    x, y = border_point(ref.x, ref.y, ref.hdg, -math.copysign(w / 2, ref.curvature))
    a = Arc(0.0, x, y, ref.hdg, math.pi * radius, math.copysign(1.0 / radius, ref.curvature))
    d = np.linspace(0.0, a.length, _SAMPLES)
    hdg = a.hdg + a.curvature * d
    return np.column_stack(
        [a.x + (np.sin(hdg) - math.sin(a.hdg)) / a.curvature, a.y - (np.cos(hdg) - math.cos(a.hdg)) / a.curvature]
    )


def _hermite_centre(row: LinkFit, t: float) -> np.ndarray:
    """Lane-centre polyline of a fitted link (its reference line is the lane's inner border, ``t`` from the centre)."""
    c = row.curve().coef
    p = np.linspace(0.0, 1.0, _SAMPLES)
    u = c[0] + p * (c[1] + p * (c[2] + p * c[3]))
    v = c[4] + p * (c[5] + p * (c[6] + p * c[7]))
    hdg = row.hdg + np.arctan2(c[5] + p * (2 * c[6] + 3 * c[7] * p), c[1] + p * (2 * c[2] + 3 * c[3] * p))
    ch, sh = math.cos(row.hdg), math.sin(row.hdg)
    x = row.start[0] + ch * u - sh * v - t * np.sin(hdg)
    y = row.start[1] + sh * u + ch * v + t * np.cos(hdg)
    return np.column_stack([x, y])


def crosses(turn: UTurn, lane_in: int, rows: list[LinkFit], p: Params) -> bool:
    """Whether the U-turn's lane centre meets that of another link leaving the same incoming road: links from other
    lanes must stay :data:`CLEARANCE` away; links from the same lane, once parted by :data:`PARTED`, :data:`TOUCH`."""
    t = (-1.0 if p.traffic_rule is TrafficRule.RHT else 1.0) * p.lane_width / 2
    pts = _centre_points(turn.geometry, p.lane_width)
    mine = shapely.LineString(pts)
    for row in rows:
        if row.leg_in != turn.leg:
            continue
        other = shapely.LineString(_hermite_centre(row, t))
        if row.lane_in != lane_in:
            if shapely.dwithin(mine, other, CLEARANCE):
                return True
            continue
        far = np.flatnonzero(shapely.distance(shapely.points(pts), other) > PARTED)
        if len(far) == 0 or far[0] > _SAMPLES - 2:
            return True
        if shapely.dwithin(shapely.LineString(pts[far[0] :]), other, TOUCH):
            return True
    return False
