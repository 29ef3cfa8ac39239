"""Straight line: ``x = x0 + ds cos(hdg)``, ``y = y0 + ds sin(hdg)``, curvature 0."""

from __future__ import annotations

import numpy as np

from xodrcheck.geometry.pose import Pose, as_array, filled
from xodrcheck.model import Line


def evaluate(g: Line, ds) -> Pose:
    return at(g.x, g.y, g.hdg, as_array(ds))


def at(x0, y0, hdg, ds: np.ndarray) -> Pose:
    """Poses ``ds`` along lines from ``(x0, y0)`` with heading ``hdg`` (numbers, or arrays of one per point: many
    lines evaluated together, each point with the same arithmetic)."""
    zero = np.zeros_like(ds)
    return Pose(x0 + ds * np.cos(hdg), y0 + ds * np.sin(hdg), filled(hdg, ds), zero, zero.copy())
