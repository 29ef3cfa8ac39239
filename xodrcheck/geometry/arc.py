"""Circular arc of constant curvature ``k``.

The chord from the start to the point at distance ``ds`` has length ``ds * sin(k ds / 2) / (k ds / 2)`` and direction
``hdg + k ds / 2``. Written with ``np.sinc`` this is exact for every ``k`` and has no ``1/k`` cancellation when the arc
is nearly straight (``k -> 0`` gives the line).
"""

from __future__ import annotations

import numpy as np

from xodrcheck.geometry.pose import Pose, as_array
from xodrcheck.model import Arc


def evaluate(g: Arc, ds) -> Pose:
    ds = as_array(ds)
    k = g.curvature
    half_turn = 0.5 * k * ds
    chord = ds * np.sinc(half_turn / np.pi)  # np.sinc(x) = sin(pi x) / (pi x)
    direction = g.hdg + half_turn
    return Pose(
        g.x + chord * np.cos(direction),
        g.y + chord * np.sin(direction),
        g.hdg + k * ds,
        np.full_like(ds, k),
        np.zeros_like(ds),
    )
