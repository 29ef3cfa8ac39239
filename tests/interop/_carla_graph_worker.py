"""Walk CARLA's lane graph on one map and write what it found as JSON.

Run by :mod:`tests.interop.carla_graph` with the ``carla`` interpreter (``.venv-carla``), never imported by the test
process (CARLA can crash the process that loads a bad map). Usage:
``python _carla_graph_worker.py MAP.xodr REQUEST.json OUT.json``. The request is an object with

* ``ends``: ``[road, lane, s, end, past]`` lane ends: the waypoint at ``s`` of the lane, then ``Waypoint.next`` by the
  distance from there to ``end`` (the lane section's end in the direction of travel, measured from the waypoint's own
  s) plus ``past``; the answer is, per end, the waypoints ``next`` gives (road, section, lane, s, lane type): just past
  the lane's end, in the lanes CARLA continues it with;
* ``walk``: ``{"steps": [[road, lane], ...], "start": s, "end": s, "step": d}``: from the first lane at ``start``,
  ``next(d)`` again and again, keeping to the waypoint on the route's current lane or one of the next (a lane shorter
  than ``d`` may be passed over), until the last lane reaches ``end``; the answer is the length of the polyline walked
  (m) and the lanes it stepped on.
"""

import json
import math
import sys

#: How many of the route's lanes ahead a step may land in (a lane shorter than a step is passed over).
LOOKAHEAD = 4


def _where(wp):
    return [str(wp.road_id), int(wp.section_id), int(wp.lane_id), float(wp.s), str(wp.lane_type)]


def _ends(world_map, ends):
    out = []
    for road, lane, s, end, past in ends:
        wp = world_map.get_waypoint_xodr(int(road), int(lane), float(s))
        out.append(None if wp is None else [_where(n) for n in wp.next(abs(float(end) - wp.s) + float(past))])
    return out


def _distance(a, b):
    p, q = a.transform.location, b.transform.location
    return math.hypot(p.x - q.x, p.y - q.y)


def _walk(world_map, walk):
    steps = [(int(road), int(lane)) for road, lane in walk["steps"]]
    wp = world_map.get_waypoint_xodr(steps[0][0], steps[0][1], float(walk["start"]))
    last = world_map.get_waypoint_xodr(steps[-1][0], steps[-1][1], float(walk["end"]))
    k, length, passed = 0, 0.0, [[str(steps[0][0]), steps[0][1]]]
    forward = steps[-1][1] <= 0  # CARLA drives lanes with id <= 0 along s
    for _ in range(1_000_000):
        on_last = k == len(steps) - 1 and (wp.road_id, wp.lane_id) == steps[-1]
        if on_last and (walk["end"] - wp.s if forward else wp.s - walk["end"]) <= walk["step"]:
            break  # the end is within a step
        candidates = wp.next(float(walk["step"]))
        ahead = steps[k : k + LOOKAHEAD]
        keep = sorted(
            (ahead.index((n.road_id, n.lane_id)), i)
            for i, n in enumerate(candidates)
            if (n.road_id, n.lane_id) in ahead
        )
        if not keep:
            return {
                "length": None,
                "passed": passed,
                "error": f"no way on from {_where(wp)}: {[_where(n) for n in candidates]}",
            }
        following = candidates[keep[0][1]]
        if keep[0][0]:  # on to a later lane of the route (one shorter than a step may be passed over)
            k += keep[0][0]
            passed.append([str(steps[k][0]), steps[k][1]])
        length += _distance(wp, following)
        wp = following
    length += _distance(wp, last)
    return {"length": length, "passed": passed, "error": ""}


def main(path, request, out):
    import carla  # imported here so that a missing carla is an error of this process only

    with open(path, encoding="utf-8") as f:
        world_map = carla.Map("xodrcheck-graph", f.read())
    with open(request, encoding="utf-8") as f:
        asked = json.load(f)
    answer = {}
    if "ends" in asked:
        answer["ends"] = _ends(world_map, asked["ends"])
    if "walk" in asked:
        answer["walk"] = _walk(world_map, asked["walk"])
    with open(out, "w", encoding="utf-8") as f:
        json.dump(answer, f)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3])
