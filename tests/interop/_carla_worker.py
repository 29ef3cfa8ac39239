"""Run CARLA's OpenDRIVE parser on one file and print what it made of it as JSON (one object on stdout).

Run by :mod:`tests.interop.carla_harness` with the ``carla`` interpreter (``.venv-carla``), never imported by the test
process: CARLA can crash the process that loads a bad map. Usage: ``python _carla_worker.py MAP.xodr DISTANCE OUT.json
[WALKS.json]`` (a file rather than stdout, because CARLA writes its own messages to the standard streams). WALKS is a
list of starts ``[road, lane, s, metres]``: from each, CARLA's ``Waypoint.next`` is followed on every branch for that
many metres, and the road ids it reaches are returned.

CARLA's y axis points the other way from OpenDRIVE's; ``y`` and ``hdg`` are turned back into OpenDRIVE's frame here.
"""

import json
import math
import sys


def _point(wp):
    loc = wp.transform.location
    return {
        "road_id": str(wp.road_id),
        "section_id": int(wp.section_id),
        "lane_id": int(wp.lane_id),
        "s": float(wp.s),
        "x": float(loc.x),
        "y": -float(loc.y),
        "z": float(loc.z),
        "hdg": -math.radians(float(wp.transform.rotation.yaw)),
    }


def _walk(world_map, start, distance: float) -> list:
    """Road ids reached by following ``Waypoint.next`` on every branch from ``start`` = [road, lane, s, metres]."""
    road, lane, s, metres = start
    first = world_map.get_waypoint_xodr(int(road), int(lane), float(s))
    if first is None:
        return []
    reached = {str(first.road_id)}
    frontier = [(first, 0.0)]
    seen = set()
    while frontier:
        wp, gone = frontier.pop()
        for nxt in wp.next(distance):
            key = (nxt.road_id, nxt.lane_id, round(nxt.s, 1))
            if key in seen or gone + distance > metres:
                continue
            seen.add(key)
            reached.add(str(nxt.road_id))
            frontier.append((nxt, gone + distance))
    return sorted(reached)


def main(path: str, distance: float, out: str, walks_path: str | None = None) -> None:
    import carla  # imported here so that a missing carla is an error of this process only

    with open(path, encoding="utf-8") as f:
        text = f.read()
    world_map = carla.Map("xodrcheck-interop", text)
    waypoints = [_point(wp) for wp in world_map.generate_waypoints(distance)]
    topology = [[_point(a), _point(b)] for a, b in world_map.get_topology()]
    landmarks = [[str(m.id), str(m.type), str(m.road_id)] for m in world_map.get_all_landmarks()]
    walks = []
    if walks_path is not None:
        with open(walks_path, encoding="utf-8") as f:
            walks = [_walk(world_map, start, distance) for start in json.load(f)]
    with open(out, "w", encoding="utf-8") as f:
        json.dump({"waypoints": waypoints, "topology": topology, "landmarks": landmarks, "walks": walks}, f)


if __name__ == "__main__":
    main(sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4] if len(sys.argv) > 4 else None)
