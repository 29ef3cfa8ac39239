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
