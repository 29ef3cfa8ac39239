"""Run CARLA's OpenDRIVE parser on one file and print what it made of it as JSON (one object on stdout).

Run by :mod:`tests.interop.carla_harness` with the ``carla`` interpreter (``.venv-carla``), never imported by the test
process: CARLA can crash the process that loads a bad map. Usage: ``python _carla_worker.py MAP.xodr DISTANCE OUT.json
[WALKS.json]`` (a file rather than stdout, because CARLA writes its own messages to the standard streams). WALKS.json
lists ring walks: ``{"road": id, "lane": id, "s": s, "centre": [x, y], "step": m, "steps": n}`` starts at that
waypoint (``Map.get_waypoint_xodr``) and takes ``next(step)`` up to ``n`` times, at each fork the successor whose
distance from ``centre`` (OpenDRIVE's frame) stays nearest the start's, stopping when it is back on the start road
after leaving it, at the start's ``s`` (within half a step). A request with ``"reach": m`` instead of a centre follows
``next(step)`` on every branch from the start for up to ``m`` metres and gives every waypoint met (which roads a
lane leads to, e.g. both branches of a fork).

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


def _walk(world_map, request):
    """The waypoints of one ring walk (module docstring); empty when the start is not on the map."""
    start = world_map.get_waypoint_xodr(int(request["road"]), int(request["lane"]), float(request["s"]))
    if start is None:
        return []
    cx, cy = request["centre"]

    def reach(wp):
        p = _point(wp)
        return math.hypot(p["x"] - cx, p["y"] - cy)

    r0, wp, path, left = reach(start), start, [_point(start)], False
    for _ in range(int(request["steps"])):
        options = wp.next(float(request["step"]))
        if not options:
            break
        wp = min(options, key=lambda c: abs(reach(c) - r0))
        path.append(_point(wp))
        left = left or wp.road_id != start.road_id
        if left and wp.road_id == start.road_id and abs(wp.s - start.s) <= float(request["step"]) / 2:
            break
    return path


def _reach(world_map, request):
    """Every waypoint met following ``next(step)`` on every branch from the start for ``reach`` metres."""
    start = world_map.get_waypoint_xodr(int(request["road"]), int(request["lane"]), float(request["s"]))
    if start is None:
        return []
    step, reach = float(request["step"]), float(request["reach"])
    met, frontier, seen = [_point(start)], [(start, 0.0)], set()
    while frontier:
        wp, gone = frontier.pop()
        if gone + step > reach:
            continue
        for nxt in wp.next(step):
            key = (nxt.road_id, nxt.lane_id, round(nxt.s, 1))
            if key not in seen:
                seen.add(key)
                met.append(_point(nxt))
                frontier.append((nxt, gone + step))
    return met


def main(path: str, distance: float, out: str, walks: str | None = None) -> None:
    import carla  # imported here so that a missing carla is an error of this process only

    with open(path, encoding="utf-8") as f:
        text = f.read()
    world_map = carla.Map("xodrcheck-interop", text)
    waypoints = [_point(wp) for wp in world_map.generate_waypoints(distance)]
    topology = [[_point(a), _point(b)] for a, b in world_map.get_topology()]
    landmarks = [[str(m.id), str(m.type), str(m.road_id)] for m in world_map.get_all_landmarks()]
    requests = []
    if walks is not None:
        with open(walks, encoding="utf-8") as f:
            requests = json.load(f)
    walked = [_reach(world_map, r) if "reach" in r else _walk(world_map, r) for r in requests]
    with open(out, "w", encoding="utf-8") as f:
        json.dump({"waypoints": waypoints, "topology": topology, "landmarks": landmarks, "walks": walked}, f)


if __name__ == "__main__":
    main(sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4] if len(sys.argv) > 4 else None)
