"""Circular arc of constant curvature ``k``.

The chord from the start to the point at distance ``ds`` has length ``ds * sin(k ds / 2) / (k ds / 2)`` and direction
``hdg + k ds / 2``. Written with ``np.sinc`` this is exact for every ``k`` and has no ``1/k`` cancellation when the arc
is nearly straight (``k -> 0`` gives the line).
"""

from __future__ import annotations

import numpy as np

from xodrcheck.geometry.pose import Pose, as_array, filled
from xodrcheck.model import Arc


def evaluate(g: Arc, ds) -> Pose:
    return at(g.x, g.y, g.hdg, g.curvature, as_array(ds))


def at(x0, y0, hdg, k, ds: np.ndarray) -> Pose:
    """Poses ``ds`` along arcs from ``(x0, y0)`` with heading ``hdg`` and curvature ``k`` (numbers, or arrays of one
    per point: many arcs evaluated together, each point with the same arithmetic)."""
    half_turn = 0.5 * k * ds
    chord = ds * np.sinc(half_turn / np.pi)  # np.sinc(x) = sin(pi x) / (pi x)
    direction = hdg + half_turn
    return Pose(
        x0 + chord * np.cos(direction),
        y0 + chord * np.sin(direction),
        hdg + k * ds,
        filled(k, ds),
        np.zeros_like(ds),
    )
