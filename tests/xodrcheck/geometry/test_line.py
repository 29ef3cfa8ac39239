import math

import numpy as np
import pytest

from xodrcheck.geometry import line
from xodrcheck.model import Line


@pytest.mark.parametrize("hdg", [0.0, 0.7, -2.9, 4.0])
def test_line_follows_its_closed_form(hdg):
    g = Line(s=10.0, x=3.0, y=-4.0, hdg=hdg, length=120.0)
    ds = np.linspace(0.0, g.length, 9)
    pose = line.evaluate(g, ds)
    assert np.allclose(pose.x, 3.0 + ds * math.cos(hdg), rtol=0, atol=1e-12)
    assert np.allclose(pose.y, -4.0 + ds * math.sin(hdg), rtol=0, atol=1e-12)
    assert np.all(pose.hdg == hdg)
    assert np.all(pose.curvature == 0) and np.all(pose.dcurvature == 0)


def test_line_points_are_at_distance_ds_from_the_start():
    g = Line(s=0.0, x=1.0, y=2.0, hdg=1.234, length=50.0)
    ds = np.array([0.0, 0.5, 17.25, 50.0])
    pose = line.evaluate(g, ds)
    assert np.allclose(np.hypot(pose.x - 1.0, pose.y - 2.0), ds, rtol=0, atol=1e-12)


def test_scalar_ds_gives_one_pose():
    pose = line.evaluate(Line(s=0.0, x=0.0, y=0.0, hdg=0.0, length=1.0), 0.25)
    assert pose.x.shape == (1,) and pose.x[0] == 0.25
