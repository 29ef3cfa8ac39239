"""Every line xodrcheck's curvature rules measure stays within ``min_turn_radius``, for the whole range Params allow:
the lane-0 line beside a drivable lane (C002), every drivable lane centre (C001), and no border folds (C003)."""

import numpy as np
import pytest

import junctionart as ja
from junctionart.lanegeom import min_curve_radius, side_width, taper_length
from junctionart.params import Params
from xodrcheck.check import check
from xodrcheck.config import Config, Tolerances

SMALLEST = 1.0  #: the smallest min_turn_radius Params accept
CURVATURE = ("C001", "C002", "C003")

LANES = {
    "two-lane": {},
    "random-curved": {
        "randomize_lanes": True,
        "curved_roads": True,
        "median_probability": 0.6,
        "median_width": 4.0,
        "turn_lane_probability": 0.7,
        "u_turn_probability": 1.0,
    },
    "narrow-lht": {
        "randomize_lanes": True,
        "lane_width": 2.0,
        "median_width": 0.5,
        "traffic_rule": "LHT",
        "taper_length": 5.0,
        "u_turn_probability": 1.0,
        "lane_distribution_side": (0.0, 0.2, 0.3, 0.5),
    },
}


def _curvature_findings(params: Params, seed: int) -> list[str]:
    data = ja.to_bytes(ja.generate(params, seed), params.version)
    report = check(
        data, Config(tolerances=Tolerances(min_radius=params.min_turn_radius), profile="generator"), select=CURVATURE
    )
    return [f"{f.code} {f.message}" for f in report.findings if f.code in CURVATURE]


@pytest.mark.parametrize("lanes", sorted(LANES))
@pytest.mark.parametrize("seed", [0, 1, 2, 3, 4])
def test_smallest_turn_radius_holds_on_every_measured_line(lanes, seed):
    params = Params.create(width=400.0, height=400.0, min_turn_radius=SMALLEST, **LANES[lanes])
    assert _curvature_findings(params, seed) == []


@pytest.mark.parametrize("seed", [0, 1])
def test_fuzzer_case_u_turn_beside_lane_zero(seed):
    """The fuzzer's map: 3 m lanes, 3 m bound; a U-turn's lane-0 line once had half the bound's radius."""
    params = Params.create(
        width=150.0,
        height=150.0,
        line_spacing=(40.0, 40.0),
        snap_distance=0.0,
        min_distance=43.0,
        max_distance=43.0,
        randomize_lanes=True,
        lane_width=3.0,
        median_probability=0.0,
        split_strategy="split-first",
        turn_lane_probability=0.0,
        min_turn_radius=3.0,
        taper_length=10.0,
    )
    assert _curvature_findings(params, seed) == []


def test_largest_turn_radius_with_a_taper_on_a_curve():
    """A lane added before a junction on a curve: the curve's radius counts the added lane and the taper's bend
    (seed 1 once had a 49 m lane centre under a 50 m bound)."""
    params = Params(width=500.0, height=500.0, min_turn_radius=50.0)
    assert _curvature_findings(params, 1) == []


@pytest.mark.parametrize("m", [1.0, 5.0, 50.0])
@pytest.mark.parametrize("end", [(1, 1), (2, 1), (3, 1), (3, 3)])
def test_curve_radius_bounds_a_taper_on_the_arc(m, end):
    """The exact curvature of the tapering lane's centre, on the inside of an arc of the radius returned, stays
    within 1 / min_turn_radius all along the taper."""
    p = Params(min_turn_radius=m, taper_length=5.0)
    mid = (1, 1)
    widest = max(side_width(n, False, p.lane_width, p.median_width) for n in (*mid, *end))
    r = min_curve_radius(p, widest, (end, mid), mid)
    assert r > widest  # no border folds
    length = taper_length(p, end, mid)
    x = np.linspace(0.0, 1.0, 2001)
    # the outermost lane's centre: from its inner border (fixed) out by half its width, which goes 0 -> lane width
    changed = max(abs(a - b) for a, b in zip(end, mid))
    inner = widest - p.lane_width
    d = (changed - 0.5) * p.lane_width if changed else 0.0
    t = inner + p.lane_width / 2 - d * (1 - (3 * x**2 - 2 * x**3)) if changed else np.full_like(x, widest - 1.75)
    t1 = -d * (-(6 * x - 6 * x**2)) / max(length, 1.0)
    t2 = -d * (-(6 - 12 * x)) / max(length, 1.0) ** 2
    k = 1.0 / r
    a = 1.0 - t * k
    curvature = (a * a * k + a * t2 + 2.0 * t1 * t1 * k) / (a * a + t1 * t1) ** 1.5
    assert np.abs(curvature).max() <= 1.0 / m
    assert r >= widest + m * 4.0 / 3.0 + 0.5 - 1e-9
