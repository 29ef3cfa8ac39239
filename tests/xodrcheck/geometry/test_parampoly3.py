import math

import mpmath as mp
import numpy as np
import pytest

from tests.xodrcheck.geometry.mp_reference import DIGITS, Cubic2D, place
from xodrcheck.geometry import parampoly3
from xodrcheck.model import ParamPoly3, PRange

ARC, NORM = PRange.ARC_LENGTH, PRange.NORMALIZED

# (u coefficients, v coefficients, pRange, @length or None for "the curve's own length", hdg)
CASES = {
    "standard's example (arcLength)": (
        (0.0, 1.0, -4.666602734948e-09, -2.629787927644e-08),
        (0.0, 1.665334536938e-16, -1.987729787588e-04, -1.317158625579e-09),
        ARC,
        6.565893957370e01,
        5.287405485081,
    ),
    "arcLength, p far from arc length": ((0.0, 1.0, 0.01, 0.0), (0.0, 0.0, 0.02, -3e-4), ARC, 40.0, 0.3),
    "normalized, non-uniform speed": ((0.0, 10.0, 20.0, -5.0), (0.0, 0.0, 15.0, -10.0), NORM, None, -0.8),
    "normalized, S-curve": ((0.0, 30.0, 0.0, 0.0), (0.0, 0.0, 9.0, -6.0), NORM, None, 2.5),
    "normalized, negative curvature": ((1.0, 12.0, -2.0, 1.0), (-0.5, -1.0, -6.0, 1.5), NORM, None, 0.0),
    "normalized, @length 1% longer than the curve": ((0.0, 20.0, 5.0, 0.0), (0.0, 0.0, 4.0, 1.0), NORM, 1.01, 1.0),
    "tiny": ((0.0, 1e-6, 0.0, 0.0), (0.0, 0.0, 1e-7, 0.0), NORM, None, 0.1),
}


def _element(name):
    u, v, p_range, length, hdg = CASES[name]
    p_max = 1.0 if p_range is NORM else length
    curve = Cubic2D(u, v, p_max)
    with mp.workdps(DIGITS):
        true_length = curve.total()
        if length is None:
            length = float(true_length)
        elif p_range is NORM:  # a factor on the curve's own length
            length = float(true_length) * length
    g = ParamPoly3(0.0, 4.0, -2.0, hdg, length, *u, *v, p_range=p_range)
    return g, curve, true_length


@pytest.mark.parametrize("name", CASES)
def test_parampoly3_matches_high_precision_integration(name):
    g, curve, true_length = _element(name)
    ds = np.concatenate([np.linspace(0.0, g.length, 5), [0.29 * g.length]])
    pose = parampoly3.evaluate(g, ds)
    with mp.workdps(DIGITS):
        for i, target in enumerate(ds):
            # ds is arc length, rescaled so that ds = @length is the curve's end (see the module docstring).
            p = curve.parameter(mp.mpf(target) * true_length / mp.mpf(g.length))
            x, y = place(g.x, g.y, g.hdg, *curve.point(p))
            assert math.hypot(pose.x[i] - x, pose.y[i] - y) < 1e-9, (name, target)
            assert abs(pose.hdg[i] - float(mp.mpf(g.hdg) + curve.angle(p))) < 1e-12, (name, target)
            k = float(curve.curvature(p))
            assert abs(pose.curvature[i] - k) < 1e-9 * max(1.0, abs(k)), (name, target)


@pytest.mark.parametrize("name", ["normalized, non-uniform speed", "arcLength, p far from arc length"])
def test_curvature_derivative_is_the_arc_length_derivative_of_curvature(name):
    g, curve, true_length = _element(name)
    pose = parampoly3.evaluate(g, np.array([0.2 * g.length, 0.7 * g.length]))
    with mp.workdps(DIGITS):
        scale = true_length / mp.mpf(g.length)
        for i, target in enumerate([0.2 * g.length, 0.7 * g.length]):
            p = curve.parameter(mp.mpf(target) * scale)
            dk_ds = mp.diff(curve.curvature, p) / curve.speed(p)
            assert abs(pose.dcurvature[i] - float(dk_ds)) < 1e-9 * max(1.0, abs(float(dk_ds)))


@pytest.mark.parametrize("name", CASES)
def test_element_ends_at_the_end_of_its_parameter_range(name):
    g, _, _ = _element(name)
    p = parampoly3.parameter_at(g, np.array([0.0, g.length]))
    p_max = 1.0 if g.p_range is NORM else g.length
    assert p[0] == pytest.approx(0.0, abs=1e-12 * p_max)
    assert p[1] == pytest.approx(p_max, rel=1e-12)


def test_arc_length_parameter_is_not_taken_as_arc_length():
    """With pRange=arcLength, p runs over [0, @length] but is not the distance: here p = 20 is 20.2 m along."""
    g, curve, _ = _element("arcLength, p far from arc length")
    naive = parampoly3.evaluate(g, 20.0)
    with mp.workdps(DIGITS):
        x, y = place(g.x, g.y, g.hdg, *curve.point(mp.mpf(20)))
    assert math.hypot(naive.x[0] - x, naive.y[0] - y) > 0.1


def _random_elements(seed: int, count: int) -> tuple[list[ParamPoly3], list[np.ndarray]]:
    rng = np.random.default_rng(seed)
    elements, runs = [], []
    for i in range(count):
        length = float(rng.uniform(0.5, 80.0))
        normalized = bool(rng.integers(2))
        p_max = 1.0 if normalized else length
        g = ParamPoly3(
            0.0,
            float(rng.uniform(-100, 100)),
            float(rng.uniform(-100, 100)),
            float(rng.uniform(-4, 4)),
            length,
            float(rng.normal(0, 1)),
            length / p_max,
            float(rng.normal(0, 3 / p_max)),
            float(rng.normal(0, 1 / p_max**2)),
            float(rng.normal(0, 1)),
            float(rng.normal(0, 0.1)),
            float(rng.normal(0, 5 / p_max**2)),
            float(rng.normal(0, 2 / p_max**3)),
            NORM if normalized else ARC,
        )
        n = int(rng.integers(1, 200))
        ds = np.linspace(0.0, length, n) if i % 4 == 0 else np.sort(rng.uniform(-1.0, length + 1.0, n))
        for repeat in range(int(rng.integers(1, 3))):  # the same element twice, with different points
            elements.append(g)
            runs.append(ds if repeat == 0 else ds[::2])
    return elements, runs


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_many_calls_at_once_are_each_call_to_the_last_bit(seed):
    elements, runs = _random_elements(seed, 150)
    counts = np.array([len(r) for r in runs])
    together = parampoly3.evaluate_runs(elements, np.concatenate(runs), counts)
    alone = [parampoly3.evaluate(g, ds) for g, ds in zip(elements, runs)]
    for name in ("x", "y", "hdg", "curvature", "dcurvature"):
        expected = np.concatenate([getattr(pose, name) for pose in alone])
        assert getattr(together, name).tobytes() == expected.tobytes(), name
