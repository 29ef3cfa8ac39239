"""Our Fresnel integrals against scipy's and against mpmath (40 digits), and the spirals they evaluate against the
scipy-based evaluation they replace. scipy is a test dependency only: xodrcheck never imports it."""

from __future__ import annotations

import math
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest
from scipy.special import fresnel as scipy_fresnel

from tests.conftest import corpus_files
from xodrcheck.geometry import fresnel as fresnel_module
from xodrcheck.geometry import spiral
from xodrcheck.geometry.fresnel import fresnel
from xodrcheck.model import Spiral
from xodrcheck.reader import read

EPS = np.finfo(float).eps


def _switch_points() -> np.ndarray:
    """Points on both sides of every switch of method (1, 5.5) and of every node's half-way point (n + 1/2) / 16."""
    edges = np.concatenate([[1.0, 5.5], (np.arange(16, 89) + 0.5) / 16])
    steps = np.arange(-20, 21) * 4 * EPS
    return np.unique(np.clip((edges[:, None] * (1 + steps)).ravel(), 0, None))


def _mpmath(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    with mp.workdps(40):
        s = np.array([float(mp.fresnels(mp.mpf(float(v)))) for v in x])
        c = np.array([float(mp.fresnelc(mp.mpf(float(v)))) for v in x])
    return s, c


def test_agrees_with_scipy_on_a_dense_grid() -> None:
    x = np.concatenate([np.linspace(0.0, 10.0, 200_001), _switch_points()])
    s, c = fresnel(x)
    s_ref, c_ref = scipy_fresnel(x)
    # scipy's own error reaches 6e-16 there (see the mpmath test): the two agree within it
    assert np.max(np.abs(s - s_ref)) <= 8e-16 and np.max(np.abs(c - c_ref)) <= 8e-16
    small = (x > 0) & (x < 1)
    assert np.max(np.abs(s - s_ref)[small] / s_ref[small]) <= 1e-15


def test_agrees_with_scipy_up_to_1e10_within_scipys_phase_error() -> None:
    """scipy rounds pi x^2 / 2 before its sine and cosine (an error of about x^2 eps in the phase, x eps / pi in the
    values); ours reduces the phase exactly. Within that, the two agree; past x = 1e8 scipy's phase is arbitrary."""
    x = np.geomspace(1e-300, 1e10, 100_001)
    s, c = fresnel(x)
    s_ref, c_ref = scipy_fresnel(x)
    bound = 8e-16 * np.maximum(np.abs(s_ref), 1.0) + 2.0 * x * EPS
    assert np.all(np.abs(s - s_ref) <= bound) and np.all(np.abs(c - c_ref) <= bound)


def test_within_an_ulp_of_mpmath_across_every_method_and_switch() -> None:
    rng = np.random.default_rng(11)
    x = np.concatenate(
        [
            rng.uniform(0, 1, 300),
            rng.uniform(1, 5.5, 600),
            rng.uniform(5.5, 12, 300),
            10 ** rng.uniform(1, 10, 300),
            10 ** rng.uniform(-300, 0, 100),
            _switch_points()[::7],
        ]
    )
    s, c = fresnel(x)
    s_ref, c_ref = _mpmath(x)
    # at most one ulp of values near 0.5; relative, a few ulp of the small values of the power series
    assert np.max(np.abs(s - s_ref)) <= 1.2e-16 and np.max(np.abs(c - c_ref)) <= 1.2e-16
    positive = s_ref > 1e-290  # not the subnormal S(x) of x < 1e-103, whose relative error is any
    assert np.max(np.abs(s - s_ref)[positive] / s_ref[positive]) <= 2.5 * EPS
    assert np.max(np.abs(c - c_ref)[positive] / c_ref[positive]) <= 2.5 * EPS


def test_odd_zero_nan_and_infinities() -> None:
    x = np.array([0.0, 0.3, 2.7, 7.0, 1e6, 3e300])
    s, c = fresnel(x)
    s_neg, c_neg = fresnel(-x)
    assert np.array_equal(s_neg, -s) and np.array_equal(c_neg, -c)
    s, c = fresnel(np.array([0.0, -0.0, math.nan, math.inf, -math.inf]))
    assert s[0] == 0.0 and c[0] == 0.0 and math.copysign(1.0, s[1]) == -1.0
    assert math.isnan(s[2]) and math.isnan(c[2])
    assert list(s[3:]) == [0.5, -0.5] and list(c[3:]) == [0.5, -0.5]
    assert np.array_equal(np.stack(scipy_fresnel(np.array([math.inf, -math.inf]))), np.stack([s[3:], c[3:]]))


def test_shapes_numbers_and_independence_of_the_batch() -> None:
    s, c = fresnel(2.0)
    assert np.ndim(s) == 0 and np.ndim(c) == 0 and float(c) == float(fresnel(np.array([2.0]))[1][0])
    x = np.array([[0.5, 1.5], [6.0, 1e5]])
    s, c = fresnel(x)
    assert s.shape == c.shape == (2, 2)
    # each point's value is that of the point alone: the methods and their term counts do not depend on the others
    for value, s_i, c_i in zip(x.ravel(), s.ravel(), c.ravel()):
        assert fresnel(value) == (s_i, c_i)


def test_node_values_are_correctly_rounded() -> None:
    nodes = fresnel_module._Nodes()
    nodes.need(np.array([0, 40, 72]))
    x0 = np.array([16, 56, 88]) / 16
    with mp.workdps(40):
        for i, x in zip([0, 40, 72], x0):
            exact = mp.fresnelc(mp.mpf(x))
            assert nodes.c_high[i] == float(exact)
            assert abs(float(exact - mp.mpf(nodes.c_high[i])) - nodes.c_low[i]) <= 1e-32
    assert nodes.done.sum() == 3  # a node is computed only when a point needs it


def _corpus_spirals() -> list[Spiral]:
    """Every spiral of the corpus (the files that have one: 54 of 128)."""
    found = []
    for path in corpus_files():
        if b"<spiral" in path.read_bytes():
            document = read(path).document
            found += [g for road in document.roads for g in road.plan_view if isinstance(g, Spiral)]
    return found


def _random_spirals(count: int) -> list[Spiral]:
    rng = np.random.default_rng(5)
    spirals = []
    for _ in range(count):
        k0, k1 = rng.normal(0, 0.05, 2) * 10 ** rng.uniform(-3, 0.5, 2)
        spirals.append(Spiral(0.0, *rng.normal(0, 500, 2), rng.uniform(-4, 4), 10 ** rng.uniform(-1, 3.3), k0, k1))
    return spirals


@pytest.mark.parametrize("source", ["corpus", "random"])
def test_spirals_evaluate_as_with_scipy(source: str, corpus_dir: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Within 1e-12 m of the scipy-based evaluation; for the random spirals (up to 2 km, far from curvature 0) within
    the evaluation's own rounding budget, 1e-14 of the distance, where the two differ by as much as each errs."""
    spirals = _corpus_spirals() if source == "corpus" else _random_spirals(400)
    ds = [np.linspace(0.0, g.length, 41) for g in spirals]
    ours = [spiral.evaluate(g, d) for g, d in zip(spirals, ds)]
    monkeypatch.setattr(spiral, "fresnel", scipy_fresnel)  # the evaluation as it was
    original, used = spiral._by_fresnel, []
    monkeypatch.setattr(spiral, "_by_fresnel", lambda a, b: used.append(len(a)) or original(a, b))
    before = [spiral.evaluate(g, d) for g, d in zip(spirals, ds)]
    assert len(spirals) >= 100 and sum(used) >= 1000  # the Fresnel path is exercised
    for g, d, new, old in zip(spirals, ds, ours, before):
        bound = 1e-12 + (0.0 if source == "corpus" else spiral._FRESNEL_BUDGET * d)
        assert np.all(np.hypot(new.x - old.x, new.y - old.y) <= bound), g
        assert np.array_equal(new.hdg, old.hdg) and np.array_equal(new.curvature, old.curvature)
