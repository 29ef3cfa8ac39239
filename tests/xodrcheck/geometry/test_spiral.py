import math

import mpmath as mp
import numpy as np
import pytest

from tests.xodrcheck.geometry.mp_reference import DIGITS, heading_curve
from xodrcheck.geometry import arc, spiral
from xodrcheck.model import Arc, Spiral

CASES = {
    "from zero": (0.0, 0.02, 100.0, 0.3),
    "negative": (0.0, -0.03, 80.0, -1.0),
    "non-zero start": (0.01, 0.04, 60.0, 2.0),
    "both negative": (-0.05, -0.005, 90.0, 0.0),
    "k to -k": (0.02, -0.02, 150.0, 1.0),
    "-k to k": (-0.01, 0.01, 200.0, 3.0),
    "nearly constant": (0.01, 0.01 + 1e-12, 300.0, 0.5),
    "nearly constant, tight": (0.2, 0.2 - 1e-9, 30.0, -2.0),
    "tiny start curvature": (1e-7, 0.01, 150.0, 0.0),
    "very long": (0.0, 0.02, 3000.0, 0.0),
    "very long, far from zero curvature": (0.005, 0.006, 5000.0, 0.2),
    "tiny length": (0.01, 0.02, 1e-6, 0.7),
}


def _reference(g: Spiral, ds: float):
    rate = (mp.mpf(g.curv_end) - mp.mpf(g.curv_start)) / mp.mpf(g.length)

    def heading(t):
        return mp.mpf(g.hdg) + mp.mpf(g.curv_start) * t + rate * t * t / 2

    x, y = heading_curve(g.x, g.y, heading, ds)
    with mp.workdps(DIGITS):
        return x, y, float(heading(mp.mpf(ds))), float(mp.mpf(g.curv_start) + rate * mp.mpf(ds))


@pytest.mark.parametrize("name", CASES)
def test_spiral_matches_high_precision_integration(name):
    k0, k1, length, hdg = CASES[name]
    g = Spiral(s=0.0, x=12.0, y=-7.0, hdg=hdg, length=length, curv_start=k0, curv_end=k1)
    ds = np.concatenate([np.linspace(0.0, length, 5), [0.37 * length]])
    pose = spiral.evaluate(g, ds)
    for i, d in enumerate(ds):
        x, y, h, k = _reference(g, d)
        assert math.hypot(pose.x[i] - x, pose.y[i] - y) < 1e-9, (name, d)
        assert abs(pose.hdg[i] - h) < 1e-12, (name, d)
        assert abs(pose.curvature[i] - k) < 1e-15 + 1e-12 * abs(k)
    assert np.all(pose.dcurvature == (k1 - k0) / length)


def _phase_reference(a: float, b: float) -> complex:
    with mp.workdps(DIGITS):
        a, b = mp.mpf(a), mp.mpf(b)
        pieces = int((abs(a) + 2 * abs(b)) / 2) + 2
        nodes = [mp.mpf(i) / pieces for i in range(pieces + 1)]
        re = mp.quad(lambda t: mp.cos(a * t + b * t * t), nodes)
        im = mp.quad(lambda t: mp.sin(a * t + b * t * t), nodes)
        return complex(re, im)


def test_phase_integral_is_exact_in_both_regimes_and_across_their_boundary():
    """a^2/(4|b|) large or |b| tiny goes to the series, the rest to the Fresnel integrals: both, and points on either
    side of the switch, must agree with the integral to double precision."""
    rng = np.random.default_rng(7)
    a = np.concatenate(
        [
            [0.0, 1e-8, 5.0, 30.0, 3.0, 3.0, 0.1, 60.0, -50.0, 2.0, 0.0, 39.0, 39.8],
            rng.normal(size=24) * 10 ** rng.uniform(-3, 1.5, 24),
        ]
    )
    b = np.concatenate(
        [
            [0.0, 0.0, 1e-9, 1e-5, 0.31, 0.28, 0.3, 4.0, 30.0, -2.0, 80.0, 35.5, 35.5],
            rng.normal(size=24) * 10 ** rng.uniform(-9, 1.5, 24),
        ]
    )
    by_fresnel = spiral.uses_fresnel(a, b)
    assert by_fresnel.sum() >= 10 and (~by_fresnel).sum() >= 10  # both paths are exercised
    got = spiral.phase_integral(a, b)
    for ai, bi, gi in zip(a, b, got):
        assert abs(gi - _phase_reference(ai, bi)) < 1e-14, (ai, bi)


@pytest.mark.parametrize("k", [0.05, -0.3, 1e-6])
def test_spiral_without_curvature_change_is_the_arc(k):
    g = Spiral(s=0.0, x=1.0, y=1.0, hdg=0.2, length=400.0, curv_start=k, curv_end=k)
    ds = np.linspace(0.0, 400.0, 17)
    a = arc.evaluate(Arc(s=0.0, x=1.0, y=1.0, hdg=0.2, length=400.0, curvature=k), ds)
    p = spiral.evaluate(g, ds)
    assert np.max(np.hypot(p.x - a.x, p.y - a.y)) < 1e-10
    assert np.allclose(p.hdg, a.hdg, rtol=0, atol=1e-13)


def test_plain_fresnel_formula_would_fail_the_nearly_arc_case():
    """The cases above are not easy ones: completing the square loses many digits there."""
    a, b = np.array([5.0, 0.2 * 30.0]), np.array([1e-9, -0.5e-9 * 900.0])
    naive = spiral.by_fresnel(a, b)
    exact = np.array([_phase_reference(ai, bi) for ai, bi in zip(a, b)])
    assert np.all(np.abs(naive - exact) > 1e-9)
    assert np.all(np.abs(spiral.phase_integral(a, b) - exact) < 1e-15)


def test_a_spiral_1e_320_m_long_evaluates_to_its_own_ends():
    """A damaged element so short that its curvature rate (curvEnd - curvStart) / length overflows to infinity still
    evaluates finitely: heading and curvature are taken as (curvEnd - curvStart) * (ds / length), and at its end the
    curvature is curvEnd (found by the long fuzz run: the rate times s = 0 gave NaN, and NaN series pieces crashed
    ten rules)."""
    g = Spiral(s=0.0, x=62.0, y=0.0, hdg=0.0, length=1e-320, curv_start=0.0, curv_end=0.015625)
    pose = spiral.evaluate(g, np.array([0.0, 1e-320]))
    assert np.isfinite(pose.x).all() and np.isfinite(pose.y).all() and np.isfinite(pose.hdg).all()
    assert pose.x[0] == 62.0 and pose.y[0] == 0.0
    assert pose.curvature[0] == 0.0 and pose.curvature[1] == 0.015625


@pytest.mark.filterwarnings("ignore::RuntimeWarning")
def test_phase_integral_of_non_finite_arguments_is_nan_not_an_error():
    out = spiral.phase_integral(np.array([0.0, math.nan, math.inf, 1.0]), np.array([math.nan, 0.0, 0.0, 0.5]))
    assert np.isnan(out[:3]).all()
    assert np.isfinite(out[3])
