"""Lane ids and lateral offsets: the one formula both the junction builder and the road writer use.

A road carries ``forward`` lanes (travelling along s) and ``backward`` lanes. Right-hand traffic puts forward lanes on
the right (negative ids), left-hand traffic on the left. An optional median is left lane 1.
"""

from __future__ import annotations

import math

from .params import Params, TrafficRule


def forward_side(rule: TrafficRule) -> int:
    """-1 when forward lanes are right lanes (RHT), +1 when they are left lanes (LHT)."""
    return -1 if rule is TrafficRule.RHT else 1


def lane_id(forward: bool, k: int, median: bool, rule: TrafficRule) -> int:
    """Id of the k-th driving lane (1 = next to the centre) travelling forward / backward."""
    side = forward_side(rule) if forward else -forward_side(rule)
    return k + (1 if median else 0) if side > 0 else -k


def inner_offset(lid: int, median: bool, width: float, median_width: float) -> float:
    """Lateral offset t of the inner border (the one nearer the reference line) of driving lane ``lid``."""
    if lid < 0:
        return -(-lid - 1) * width
    if median:
        return median_width + (lid - 2) * width
    return (lid - 1) * width


def side_width(n: int, median: bool, width: float, median_width: float) -> float:
    return n * width + (median_width if median else 0.0)


def border_point(x: float, y: float, hdg: float, t: float) -> tuple[float, float]:
    return x - t * math.sin(hdg), y + t * math.cos(hdg)


def taper_length(params: Params, end: tuple[int, int], middle: tuple[int, int]) -> float:
    """Length of the lane split / merge between lane counts ``middle`` and ``end`` ((forward, backward) each), 0 when
    they are equal.

    A lane whose inner border moves by ``d`` along a smooth cubic over ``L`` bends with curvature up to ``6 d / L^2``;
    the length keeps that under a quarter of ``1 / min_turn_radius`` for every lane centre (the rest of the budget
    belongs to the road's own curve), and is never shorter than ``params.taper_length``.
    """
    changed = max(abs(a - b) for a, b in zip(end, middle))
    if changed == 0:
        return 0.0
    shift = (changed - 0.5) * params.lane_width
    return max(params.taper_length, math.sqrt(24.0 * shift * params.min_turn_radius))


def min_curve_radius(
    params: Params, widest: float, ends: tuple[tuple[int, int], ...], middle: tuple[int, int]
) -> float:
    """Smallest reference-line arc radius on a road whose widest side is ``widest`` (m, at any s) and whose lane
    counts go from ``middle`` to each of ``ends`` through tapers (:func:`taper_length`).

    Every lane centre lies at most ``t = widest - lane_width / 2`` from the reference line, so on an arc of radius
    ``R`` its radius is at least ``R - t``; that keeps 3/4 of the ``1 / min_turn_radius`` budget. Where a taper lies
    on the arc, the lane centre's offset ``t(s)`` also bends: with ``a = 1 - t / R`` the centre's curvature is
    ``(a^2 / R + a t'' + 2 t'^2 / R) / (a^2 + t'^2)^1.5``, at most ``1 / (a R) + t'' / a^2 + 2 t'^2 / (a^3 R)``. The
    radius returned keeps that bound under ``1 / min_turn_radius`` for the steepest taper of the road.
    """
    m = params.min_turn_radius
    r_min = widest + m * 4.0 / 3.0 + 0.5
    bend = slope2 = 0.0
    for end in ends:
        length = taper_length(params, end, middle)
        if length > 0:
            shift = (max(abs(a - b) for a, b in zip(end, middle)) - 0.5) * params.lane_width
            bend = max(bend, 6.0 * shift / length**2)
            slope2 = max(slope2, (1.5 * shift / length) ** 2)
    if bend == 0.0:
        return r_min
    t = widest - params.lane_width / 2

    def fits(r: float) -> bool:
        a = 1.0 - t / r
        return 1.0 / (a * r) + bend / a**2 + 2.0 * slope2 / (a**3 * r) <= 1.0 / m

    if fits(r_min):
        return r_min
    lo, hi = r_min, 2.0 * r_min
    while not fits(hi):
        lo, hi = hi, 2.0 * hi
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if fits(mid) else (mid, hi)
    return hi
