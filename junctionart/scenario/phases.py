"""Signal groups of a signalised junction: which incoming lanes may be shown green together.

Two connection lanes conflict when their centre lines come closer than :data:`CLEARANCE` anywhere (they cross, merge
into the same outgoing lane, or pass too close for two cars side by side); connection lanes leaving the same incoming
lane never conflict with each other (one signal shows them all). Two incoming lanes are compatible when no connection
lane of one conflicts with one of the other. The groups are a colouring of the incompatibility graph (largest degree
first, then each lane to the first group it is compatible with, in a fixed order), so every group can be green while
all others are red, and the groups take turns in the order of their ``sequence`` (:mod:`.signals`). Left turns are
thereby always protected (no permissive phase).
"""

from __future__ import annotations

import numpy as np
import shapely

from ..curves import sample, unit_tangents
from ..opendrive import Road

#: m: connection lanes whose centre lines come closer than this conflict (about a car's width; lanes side by side,
#: 3.5 m apart, do not)
CLEARANCE = 2.0

#: (incoming road id, incoming lane id)
LaneKey = tuple[str, int]


def centre_line(road: Road) -> np.ndarray:
    """The centre line (x, y samples) of the one lane of a generated connecting road (no lane offset, one geometry)."""
    (g,) = road.geometry
    (sec,) = road.sections
    (lane,) = sec.left + sec.right
    pts = sample(g, max(8, int(g.length / 0.5) + 2))
    tangent = unit_tangents(pts)
    normal = np.column_stack([-tangent[:, 1], tangent[:, 0]])
    return pts + normal * (np.sign(lane.id) * lane.widths[0].a / 2.0)


def incompatible(movements: dict[LaneKey, list[Road]]) -> dict[LaneKey, set[LaneKey]]:
    """For each incoming lane, the incoming lanes one of whose connection lanes meets one of its own."""
    keys = sorted(movements)
    lines = {k: [shapely.LineString(centre_line(r)) for r in movements[k]] for k in keys}
    out: dict[LaneKey, set[LaneKey]] = {k: set() for k in keys}
    for i, a in enumerate(keys):
        for b in keys[i + 1 :]:
            if any(shapely.distance(la, lb) < CLEARANCE for la in lines[a] for lb in lines[b]):
                out[a].add(b)
                out[b].add(a)
    return out


def signal_groups(movements: dict[LaneKey, list[Road]]) -> list[list[LaneKey]]:
    """The incoming lanes in groups of mutually compatible lanes (each group sorted; groups in the order made)."""
    graph = incompatible(movements)
    groups: list[list[LaneKey]] = []
    for key in sorted(graph, key=lambda k: (-len(graph[k]), k)):
        for group in groups:
            if not graph[key] & set(group):
                group.append(key)
                break
        else:
            groups.append([key])
    return [sorted(g) for g in groups]
