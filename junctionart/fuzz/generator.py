"""Hypothesis strategies for the generator's inputs: control lines, control-line groups and parameters, valid and not.

Valid inputs lean on the awkward cases: nearly parallel lines, lines crossing at sharp angles, very short and very long
lines, polylines, many lanes. Invalid inputs are those the generator must refuse with one clear error: non-finite or
degenerate coordinates, overlapping lines, impossible lane counts and out-of-range parameters.
"""

from __future__ import annotations

import math

from hypothesis import strategies as st
from hypothesis.errors import InvalidArgument

from junctionart import Params
from junctionart.controllines import ControlLine, ControlLines, parse

__all__ = [
    "RELATIONS",
    "control_line_groups",
    "control_lines",
    "generator_params",
    "invalid_control_line_files",
    "invalid_generator_params",
]


#: Relations between two control lines of a pair that :func:`control_line_groups` draws.
RELATIONS = ("parallel", "nearly-parallel", "sharp-crossing", "crossing", "short", "polyline")


def _finite(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise InvalidArgument(f"{name}={value!r} must be a finite number")
    return float(value)


def _bounds(lo_name: str, lo, hi_name: str, hi, floor: float) -> None:
    if _finite(lo_name, lo) < floor:
        raise InvalidArgument(f"{lo_name}={lo!r} must be at least {floor:g}")
    if _finite(hi_name, hi) < lo:
        raise InvalidArgument(f"{lo_name}={lo!r} must not exceed {hi_name}={hi!r}")


def _lane_pairs(max_lanes: int):
    return st.tuples(st.integers(0, max_lanes), st.integers(0, max_lanes)).filter(lambda p: p != (0, 0))


def _rotate(points, angle: float, dx: float, dy: float):
    c, s = math.cos(angle), math.sin(angle)
    return [[dx + c * x - s * y, dy + s * x + c * y] for x, y in points]


@st.composite
def _line(draw, min_points, max_points, min_length, max_length, max_lanes, lanes):
    n = draw(st.integers(min_points, max_points))
    length = draw(st.floats(min_length, max_length))
    # interior points near even fractions of the length: at least half a step (>= 2.5 m) apart
    xs = [(k + draw(st.floats(-0.25, 0.25))) / (n - 1) for k in range(1, n - 1)]
    ys = draw(st.lists(st.floats(-0.15, 0.15), min_size=n - 2, max_size=n - 2))
    pts = [[0.0, 0.0], *([x * length, y * length] for x, y in zip(xs, ys)), [length, 0.0]]
    pts = _rotate(pts, draw(st.floats(-math.pi, math.pi)), draw(st.floats(-1e3, 1e3)), draw(st.floats(-1e3, 1e3)))
    return pts, (list(draw(_lane_pairs(max_lanes))) if lanes and draw(st.booleans()) else None)


def control_lines(
    *,
    min_points: int = 2,
    max_points: int = 4,
    min_length: float = 20.0,
    max_length: float = 500.0,
    max_lanes: int = 3,
    lanes: bool = True,
) -> st.SearchStrategy[ControlLine]:
    """Single control lines (:class:`junctionart.controllines.ControlLine`): polylines of ``min_points`` to
    ``max_points`` points, ``min_length`` to ``max_length`` m from end to end, anywhere and in any direction; with
    ``lanes`` some carry a fixed lane configuration (forward, backward) of up to ``max_lanes`` each."""
    if isinstance(min_points, bool) or not isinstance(min_points, int) or min_points < 2:
        raise InvalidArgument(f"min_points={min_points!r} must be an integer >= 2")
    if isinstance(max_points, bool) or not isinstance(max_points, int) or not min_points <= max_points <= 20:
        raise InvalidArgument(f"max_points={max_points!r} must be an integer in [min_points, 20]")
    _bounds("min_length", min_length, "max_length", max_length, 5.0 * (max_points - 1))
    if not isinstance(max_lanes, int) or not 1 <= max_lanes <= 3:
        raise InvalidArgument(f"max_lanes={max_lanes!r} must be 1, 2 or 3 (the generator's lane limit)")
    # parsed as a control-line file (its validation applies); the file needs a second line, kept far away
    return _line(min_points, max_points, float(min_length), float(max_length), max_lanes, lanes).map(
        lambda v: parse(
            {"lines": [{"id": "l", "points": v[0], "lanes": v[1]}, {"id": "m", "points": [[0, 2e4], [100, 2e4]]}]}
        ).lines[0]
    )


@st.composite
def _pair(draw, relation: str, extent: float, max_lanes: int, lanes: bool, offset_y: float):
    length = extent if relation != "short" else draw(st.floats(20.0, 60.0))
    gap = draw(st.floats(60.0, 0.5 * extent))
    base = [[0.0, offset_y], [length, offset_y]]
    if relation == "parallel" or relation == "short":
        other = [[0.0, offset_y + gap], [length, offset_y + gap]]
    elif relation == "nearly-parallel":
        tilt = math.radians(draw(st.floats(0.5, 5.0))) * draw(st.sampled_from((-1, 1)))
        other = [[0.0, offset_y + gap], [length, offset_y + gap + length * math.tan(tilt)]]
    elif relation in ("sharp-crossing", "crossing"):
        lo, hi = (5.0, 25.0) if relation == "sharp-crossing" else (25.0, 90.0)
        angle = math.radians(draw(st.floats(lo, hi)))
        half = 0.5 * length
        cx = draw(st.floats(0.3, 0.7)) * length
        other = [
            [cx - half * math.cos(angle), offset_y - half * math.sin(angle)],
            [cx + half * math.cos(angle), offset_y + half * math.sin(angle)],
        ]
    else:  # polyline: a bent line above a straight one
        bend = draw(st.floats(-0.2, 0.2)) * length
        other = [[0.0, offset_y + gap], [0.5 * length, offset_y + gap + abs(bend)], [length, offset_y + gap]]

    def conf():
        return draw(_lane_pairs(max_lanes)) if lanes and draw(st.booleans()) else None

    def asked() -> dict:
        """Now and then a fork or ramp asked for somewhere along the line (issue 28)."""
        kind = draw(st.sampled_from((None, None, None, "forks", "ramps")))
        if kind is None:
            return {}
        at = draw(st.floats(0.0, 0.95)) * length
        angle = draw(st.one_of(st.none(), st.floats(2.0, 90.0)))
        return {kind: [{"at": at} | ({} if angle is None else {"angle": angle})]}

    return [(base, conf(), asked()), (other, conf(), asked())]


@st.composite
def _groups(draw, min_lines, max_lines, extent, relations, max_lanes, lanes, as_json):
    n_pairs = draw(st.integers(max(1, min_lines // 2), max(1, max_lines // 2)))
    lines = []
    y = 0.0
    for _ in range(n_pairs):
        relation = draw(st.sampled_from(relations))
        lines.extend(draw(_pair(relation, extent, max_lanes, lanes, y)))
        y += 0.7 * extent + 150.0
    angle, dx, dy = draw(st.floats(-math.pi, math.pi)), draw(st.floats(-1e4, 1e4)), draw(st.floats(-1e4, 1e4))
    rotated = [_rotate(pts, angle, dx, dy) for pts, _, _ in lines]
    data = {
        "lines": [
            {
                "id": f"c{i}",
                "points": points,
                "group": i // 2,
                **({"lanes": list(conf)} if conf else {}),
                **structures,
            }
            for i, (points, (_, conf, structures)) in enumerate(zip(rotated, lines))
        ],
        "pairs": [[f"c{i}", f"c{i + 1}"] for i in range(0, len(lines), 2)],
    }
    if draw(st.booleans()):  # roundabouts asked for at points of the lines (the nearest junction, if any, gets one)
        ends = [points[k] for points in rotated for k in (0, 1)]
        data["roundabouts"] = [
            {
                "at": draw(st.sampled_from(ends)),
                **({"radius": draw(st.floats(6.0, 80.0))} if draw(st.booleans()) else {}),
                **({"lanes": draw(st.integers(1, 2))} if draw(st.booleans()) else {}),
            }
            for _ in range(draw(st.integers(1, 3)))
        ]
    return data if as_json else parse(data)


def control_line_groups(
    *,
    min_lines: int = 2,
    max_lines: int = 4,
    extent: float = 400.0,
    relations: tuple[str, ...] = RELATIONS,
    max_lanes: int = 3,
    lanes: bool = True,
    as_json: bool = False,
) -> st.SearchStrategy[ControlLines]:
    """Sets of control lines in pairs (one group per pair, pairs stacked apart): each pair's lines are related by one
    of ``relations`` (see :data:`RELATIONS`); lines span about ``extent`` metres; the whole set is moved and rotated
    anywhere. ``as_json``: the JSON object of a control-line file instead of :class:`ControlLines`."""
    for name, value in (("min_lines", min_lines), ("max_lines", max_lines)):
        if isinstance(value, bool) or not isinstance(value, int) or not 2 <= value <= 40:
            raise InvalidArgument(f"{name}={value!r} must be an integer in [2, 40]")
    if min_lines > max_lines:
        raise InvalidArgument(f"min_lines={min_lines} must not exceed max_lines={max_lines}")
    if _finite("extent", extent) < 150.0 or extent > 5000.0:
        raise InvalidArgument(f"extent={extent!r} must be in [150, 5000] m")
    if isinstance(relations, str) or not relations or any(r not in RELATIONS for r in relations):
        raise InvalidArgument(f"relations={relations!r} must be a non-empty collection of {', '.join(RELATIONS)}")
    if not isinstance(max_lanes, int) or not 1 <= max_lanes <= 3:
        raise InvalidArgument(f"max_lanes={max_lanes!r} must be 1, 2 or 3 (the generator's lane limit)")
    return _groups(min_lines, max_lines, float(extent), tuple(relations), max_lanes, lanes, as_json)


@st.composite
def _params(draw, min_size, max_size, many_lanes):
    size = st.floats(min_size, max_size)
    lo = draw(st.floats(40.0, 120.0))
    min_d = draw(st.floats(40.0, 150.0))
    lanes = (0.0, 0.1, 0.3, 0.6) if many_lanes else (0.15, 0.6, 0.2, 0.05)
    return Params.create(
        width=draw(size),
        height=draw(size),
        line_spacing=(lo, lo + draw(st.floats(0.0, 150.0))),
        snap_distance=draw(st.floats(0.0, 80.0)),
        min_distance=min_d,
        max_distance=min_d + draw(st.floats(0.0, 100.0)),
        randomize_lanes=draw(st.booleans()),
        lane_distribution_side=lanes,
        lane_width=draw(st.floats(2.5, 4.5)),
        median_probability=draw(st.floats(0.0, 1.0)),
        median_width=draw(st.floats(0.5, 4.0)),
        split_strategy=draw(st.sampled_from(("split-first", "split-last", "random"))),
        traffic_rule=draw(st.sampled_from(("RHT", "LHT"))),
        curved_roads=draw(st.booleans()),
        curve_probability=draw(st.floats(0.0, 1.0)),
        turn_lane_probability=draw(st.floats(0.0, 1.0)),
        min_turn_radius=draw(st.floats(3.0, 15.0)),
        min_leg_angle=draw(st.floats(0.0, 50.0)),
        taper_length=draw(st.floats(10.0, 60.0)),
        version=draw(st.sampled_from(("1.8", "1.7"))),
        # forks and ramps (issue 28): off in half the maps, so the other features keep their share of the budget
        fork_probability=draw(st.sampled_from((0.0, 0.0, 0.5, 1.0))),
        ramp_probability=draw(st.sampled_from((0.0, 0.0, 0.5, 1.0))),
        direct_junctions=draw(st.booleans()),
        roundabout_probability=draw(st.sampled_from((0.0, 0.0, 0.25, 1.0))),  # roundabouts: off in half the maps
    )


def generator_params(
    *, min_size: float = 150.0, max_size: float = 500.0, many_lanes: bool = False
) -> st.SearchStrategy[Params]:
    """Valid :class:`junctionart.Params` for maps of ``min_size`` to ``max_size`` metres a side (keep it small for
    fast runs); ``many_lanes`` favours three lanes a side."""
    _bounds("min_size", min_size, "max_size", max_size, 50.0)
    if max_size > 100_000:
        raise InvalidArgument(f"max_size={max_size!r} must be at most 100000 m (the generator's limit)")
    return _params(float(min_size), float(max_size), bool(many_lanes))


# ---------------------------------------------------------------------------------------------- invalid inputs
_BAD_NUMBERS = (math.nan, math.inf, -math.inf)


@st.composite
def invalid_control_line_files(draw) -> tuple[dict, str]:
    """``(JSON object of a control-line file, what is wrong)``: each must be refused with one clear error."""
    base = draw(control_line_groups(as_json=True, lanes=False))
    lines = base["lines"]
    i = draw(st.integers(0, len(lines) - 1))
    what = draw(
        st.sampled_from(
            (
                "non-finite",
                "degenerate",
                "single-point",
                "overlapping",
                "lane-count",
                "no-lanes",
                "one-line",
                "roundabout",
            )
        )
    )
    if what == "non-finite":
        p = draw(st.integers(0, len(lines[i]["points"]) - 1))
        lines[i]["points"][p][draw(st.integers(0, 1))] = draw(st.sampled_from(_BAD_NUMBERS))
    elif what == "degenerate":
        x, y = lines[i]["points"][0]
        lines[i]["points"] = [[x, y], [x + draw(st.floats(0.0, 0.5)), y]]
    elif what == "single-point":
        lines[i]["points"] = lines[i]["points"][:1]
    elif what == "overlapping":
        j = i + 1 if i % 2 == 0 else i - 1
        lines[j]["points"] = [list(p) for p in lines[i]["points"]]
    elif what == "lane-count":
        lines[i]["lanes"] = [draw(st.sampled_from((-1, 4, 7, 1.5))), draw(st.integers(0, 3))]
    elif what == "no-lanes":
        lines[i]["lanes"] = [0, 0]
    elif what == "roundabout":
        base["roundabouts"] = [
            draw(
                st.sampled_from(
                    (
                        {"at": [0, 0], "radius": 500},
                        {"at": [0, 0], "radius": math.nan},
                        {"at": [0, 0], "lanes": 3},
                        {"at": [math.inf, 0]},
                        {"at": [0]},
                        {"radius": 20},
                        [0, 0],
                    )
                )
            )
        ]
    else:
        base = {"lines": lines[:1]}
    return base, what


@st.composite
def invalid_generator_params(draw) -> tuple[dict, str]:
    """``(keyword arguments of Params.create, the parameter at fault)`` that :class:`Params` must refuse."""
    name, bad = draw(
        st.sampled_from(
            (
                ("width", st.sampled_from((math.nan, math.inf, -100.0, 0.0, 10.0, 1e9))),
                ("height", st.sampled_from((math.nan, -1.0, 0.0))),
                ("lane_width", st.sampled_from((math.nan, 0.0, -3.5, 1.0, 100.0))),
                ("median_probability", st.sampled_from((-0.1, 1.5, math.nan))),
                ("min_turn_radius", st.sampled_from((0.0, -5.0, math.inf))),
                ("min_leg_angle", st.sampled_from((-1.0, 90.0, math.nan))),
                ("line_spacing", st.sampled_from(((10.0, 20.0), (200.0, 100.0), (math.nan, 100.0)))),
                ("lane_distribution_side", st.sampled_from(((0.5, 0.5, 0.5, 0.5), (1.0, 0.0, 0.0, 0.0), (0.2, 0.8)))),
                ("n_lines", st.sampled_from((0, 1, -3, 10**6))),
                ("traffic_rule", st.sampled_from(("left", "", "rht"))),
                ("fork_probability", st.sampled_from((-0.5, 1.01, math.nan))),
                ("ramp_probability", st.sampled_from((2.0, -1e-9, math.inf))),
                ("direct_junctions", st.sampled_from((1, "yes", None))),
                ("roundabout_probability", st.sampled_from((-0.1, 1.5, math.nan))),
                ("version", st.sampled_from(("1.6", "2.0", ""))),
            )
        )
    )
    return {name: draw(bad)}, name
