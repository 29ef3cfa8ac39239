"""Crosswalks on the legs of signalised junctions (issue 16).

Each leg of a junction with traffic lights gets a ``crosswalk`` object across its carriageway (every lane but the
roadside lanes, kerb to kerb), :data:`WALK_WIDTH` wide along the road and :data:`GAP` short of the junction, its
outline four ``<cornerRoad>`` points on the kerbs, so it lies inside the road whatever the lane widths there. The stop
line of a signalised approach stands :data:`STOP_BEFORE` before the crosswalk. A leg too short for both of its ends'
crosswalks and stop lines gets none.

Markings (13.8): the crosswalk's two edges across the road are painted as broken white lines, each a ``<marking>``
through the two outline corners of its edge (``<cornerReference>``), as in the standard's crosswalk example (13.8.3,
Figure 124). That is the marking of a pedestrian crossing at traffic lights in Germany, the catalogue's country (a
*Fußgängerfurt*: two narrow broken transverse lines about 4 m apart, a stop line at least 1 m before it; a zebra
crossing, sign 293, is for crossings without lights and is not marked at signals): lines :data:`LINE_WIDTH` wide,
dashes :data:`DASH` long with :data:`GAP_LENGTH` gaps. OpenDRIVE 1.9 writes the markings inside the outline, 1.7 and
1.8 in the object (the writer).
"""

from __future__ import annotations

from collections.abc import Callable

from ..opendrive import Corner, ObjectMarking, Road, RoadObject
from .roadside import ROADSIDE_TYPES

GAP = 1.0  #: m between the junction and the crosswalk
WALK_WIDTH = 4.0  #: m along the road (the usual 4 m of a signalised crossing)
STOP_BEFORE = 1.0  #: m between the stop line and the crosswalk
#: m from the junction to the stop line of a signalised approach with a crosswalk
STOP_BACK_WITH_WALK = GAP + WALK_WIDTH + STOP_BEFORE
LINE_WIDTH = 0.12  #: m, a narrow line (Schmalstrich)
DASH = 0.5  #: m, painted part of a broken line
GAP_LENGTH = 0.2  #: m, gap between dashes
#: The two edges across the road: outline corners 1 -> 2 (at the far s) and 3 -> 0 (at the near s, across the
#: closed outline's closing edge), in the outline's order.
EDGES = ((1, 2), (3, 0))


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
    marks = tuple(ObjectMarking(edge, "white", LINE_WIDTH, DASH, GAP_LENGTH) for edge in EDGES)
    return RoadObject(new_id(), "crosswalk", "crosswalk", mid, (rm + lm) / 2.0, None, None, outline, markings=marks)
