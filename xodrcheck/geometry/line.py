"""Straight line: ``x = x0 + ds cos(hdg)``, ``y = y0 + ds sin(hdg)``, curvature 0."""

from __future__ import annotations

import numpy as np

from xodrcheck.geometry.pose import Pose, as_array
from xodrcheck.model import Line


def evaluate(g: Line, ds) -> Pose:
    ds = as_array(ds)
    zero = np.zeros_like(ds)
    return Pose(
        g.x + ds * np.cos(g.hdg),
        g.y + ds * np.sin(g.hdg),
        np.full_like(ds, g.hdg),
        zero,
        zero.copy(),
    )
