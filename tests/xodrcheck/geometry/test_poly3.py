import math

import mpmath as mp
import numpy as np
import pytest

from tests.xodrcheck.geometry.mp_reference import DIGITS, Cubic2D, place
from xodrcheck.geometry import poly3
from xodrcheck.model import Poly3

CASES = {
    "gentle": (0.0, 0.0, 0.01, -0.0002, 50.0, 0.4),
    "shifted and turned start": (0.5, 0.1, -0.02, 0.0005, 40.0, -1.2),
    "straight": (0.0, 0.0, 0.0, 0.0, 30.0, 0.0),
    "strongly curved": (0.0, 0.0, 0.05, -0.001, 30.0, 2.0),
    "negative curvature": (0.0, -0.3, -0.04, 0.0008, 45.0, 3.0),
    "tiny length": (0.0, 0.0, 0.1, 0.0, 1e-6, 0.7),
}


@pytest.mark.parametrize("name", CASES)
def test_poly3_matches_arc_length_by_high_precision_integration(name):
    a, b, c, d, length, hdg = CASES[name]
    g = Poly3(s=0.0, x=-3.0, y=8.0, hdg=hdg, length=length, a=a, b=b, c=c, d=d)
    curve = Cubic2D((0, 1, 0, 0), (a, b, c, d), length)
    ds = np.concatenate([np.linspace(0.0, length, 5), [0.61 * length]])
    pose = poly3.evaluate(g, ds)
    with mp.workdps(DIGITS):
        for i, target in enumerate(ds):
            u = curve.parameter(mp.mpf(target))
            x, y = place(g.x, g.y, g.hdg, *curve.point(u))
            assert math.hypot(pose.x[i] - x, pose.y[i] - y) < 1e-9, (name, target)
            assert abs(pose.hdg[i] - float(mp.mpf(hdg) + curve.angle(u))) < 1e-12
            k = float(curve.curvature(u))
            assert abs(pose.curvature[i] - k) < 1e-9 * max(1.0, abs(k))


def test_poly3_starts_off_its_origin_by_a_and_turned_by_atan_b():
    g = Poly3(s=0.0, x=0.0, y=0.0, hdg=0.5, length=10.0, a=0.7, b=0.2, c=0.0, d=0.0)
    pose = poly3.evaluate(g, 0.0)
    assert pose.x[0] == pytest.approx(-0.7 * math.sin(0.5), abs=1e-15)
    assert pose.y[0] == pytest.approx(0.7 * math.cos(0.5), abs=1e-15)
    assert pose.hdg[0] == pytest.approx(0.5 + math.atan(0.2), abs=1e-15)


def test_straight_poly3_is_the_line_it_tilts_to():
    g = Poly3(s=0.0, x=0.0, y=0.0, hdg=0.0, length=20.0, a=0.0, b=0.75, c=0.0, d=0.0)
    pose = poly3.evaluate(g, np.array([5.0, 20.0]))
    # Along direction atan(0.75): (0.8, 0.6) per metre of arc length.
    assert np.allclose(pose.x, [4.0, 16.0], rtol=0, atol=1e-12)
    assert np.allclose(pose.y, [3.0, 12.0], rtol=0, atol=1e-12)
