import math

import numpy as np
import pytest

from tests.xodrcheck.geometry.mp_reference import heading_curve
from xodrcheck.geometry import arc, line
from xodrcheck.model import Arc, Line


@pytest.mark.parametrize("k", [0.02, -0.05, 0.5, -1e-3])
def test_arc_points_lie_on_the_circle_at_the_right_angle(k):
    g = Arc(s=0.0, x=5.0, y=-3.0, hdg=0.4, length=80.0, curvature=k)
    ds = np.linspace(0.0, g.length, 11)
    pose = arc.evaluate(g, ds)
    # Closed form: centre at (x0, y0) + (1/k) * left normal; point at angle hdg - pi/2 + k ds (k > 0).
    cx, cy = 5.0 - math.sin(0.4) / k, -3.0 + math.cos(0.4) / k
    assert np.allclose(pose.x, cx + np.sin(0.4 + k * ds) / k, rtol=0, atol=1e-9)
    assert np.allclose(pose.y, cy - np.cos(0.4 + k * ds) / k, rtol=0, atol=1e-9)
    assert np.allclose(np.hypot(pose.x - cx, pose.y - cy), 1 / abs(k), rtol=0, atol=1e-9)
    assert np.allclose(pose.hdg, 0.4 + k * ds, rtol=0, atol=1e-14)
    assert np.all(pose.curvature == k) and np.all(pose.dcurvature == 0)


@pytest.mark.parametrize("k", [0.013, -0.2])
def test_arc_matches_the_integral_of_its_heading(k):
    g = Arc(s=0.0, x=-1.0, y=2.0, hdg=-1.1, length=300.0, curvature=k)
    for ds in (0.0, 1.0, 77.7, 300.0):
        x, y = heading_curve(g.x, g.y, lambda t: g.hdg + k * t, ds)
        pose = arc.evaluate(g, ds)
        assert math.hypot(pose.x[0] - x, pose.y[0] - y) < 1e-9


@pytest.mark.parametrize("k", [1e-15, -1e-13, 0.0])
def test_nearly_straight_arc_has_no_cancellation(k):
    """The textbook form (sin(h + k s) - sin h) / k loses every digit for tiny k; the chord form must not."""
    g = Arc(s=0.0, x=0.0, y=0.0, hdg=0.3, length=1000.0, curvature=k)
    ds = np.linspace(0.0, 1000.0, 5)
    bent = arc.evaluate(g, ds)
    straight = line.evaluate(Line(s=0.0, x=0.0, y=0.0, hdg=0.3, length=1000.0), ds)
    # The true distance from the straight line is k ds^2 / 2 <= 5e-7 m at 1000 m for |k| = 1e-12.
    deviation = np.hypot(bent.x - straight.x, bent.y - straight.y)
    assert np.all(deviation <= abs(k) * ds**2 / 2 + 1e-12)
