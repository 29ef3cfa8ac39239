"""Crosswalks on the legs of signalised junctions (issue 16).

Each leg of a junction with traffic lights gets a ``crosswalk`` object across its carriageway (every lane but the
roadside lanes, kerb to kerb), :data:`WALK_WIDTH` wide along the road and :data:`GAP` short of the junction, its
outline four ``<cornerRoad>`` points on the kerbs, so it lies inside the road whatever the lane widths there. The stop
line of a signalised approach stands :data:`STOP_BEFORE` before the crosswalk. A leg too short for both of its ends'
crosswalks and stop lines gets none.
"""

from __future__ import annotations

from collections.abc import Callable

from ..opendrive import Corner, Road, RoadObject
from .roadside import ROADSIDE_TYPES

GAP = 1.0  #: m between the junction and the crosswalk
WALK_WIDTH = 4.0  #: m along the road (the usual 4 m of a signalised crossing)
STOP_BEFORE = 1.0  #: m between the stop line and the crosswalk
#: m from the junction to the stop line of a signalised approach with a crosswalk
STOP_BACK_WITH_WALK = GAP + WALK_WIDTH + STOP_BEFORE


def fits(road: Road) -> bool:
    """Whether ``road`` is long enough for a crosswalk and a stop line at both ends."""
    return road.length > 2.0 * (STOP_BACK_WITH_WALK + 1.0)


def carriageway(road: Road, s: float) -> tuple[float, float]:
    """t of the right and left kerb (outer borders of the outermost non-roadside lanes) at ``s``."""
    sec = [x for x in road.sections if x.s <= s + 1e-9][-1]
    ds = s - sec.s
    out = []
    for lanes in (sec.right, sec.left):
        t = 0.0
        for ln in sorted(lanes, key=lambda ln: abs(ln.id)):
            if ln.type in ROADSIDE_TYPES:
                break
            w = ln.widths[0]
            t += w.a + ds * (w.b + ds * (w.c + ds * w.d))
        out.append(t)
    return -out[0], out[1]


def crosswalk(road: Road, contact: str, new_id: Callable[[], str]) -> RoadObject:
    """The crosswalk across ``road`` near its ``contact`` end."""
    if contact == "end":
        s0, s1 = road.length - GAP - WALK_WIDTH, road.length - GAP
    else:
        s0, s1 = GAP, GAP + WALK_WIDTH
    r0, l0 = carriageway(road, s0)
    r1, l1 = carriageway(road, s1)
    outline = (Corner(s0, r0), Corner(s1, r1), Corner(s1, l1), Corner(s0, l0))
    mid = (s0 + s1) / 2.0
    rm, lm = carriageway(road, mid)
    # no bounding box: on a bend or a taper the road-frame outline is no rectangle in the object's own frame
    return RoadObject(new_id(), "crosswalk", "crosswalk", mid, (rm + lm) / 2.0, None, None, outline)
