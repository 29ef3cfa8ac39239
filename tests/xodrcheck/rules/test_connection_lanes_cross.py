"""Rule connection-lanes-cross: the finding each fail fixture gives."""

import re
from pathlib import Path

import numpy as np
import pytest

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.config import Tolerances, load_config
from xodrcheck.findings import Severity
from xodrcheck.rules.shared.lane_paths import crossing

RULE = "connection-lanes-cross"


def test_left_turn_from_the_right_lane_crosses_straight_on():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (
        f.road == "1" and f.severity is Severity.WARNING and f.basis == "plausibility"
    )  # the paper's, not the standard's
    assert [g.severity for g in findings(path, RULE, "generator")] == [Severity.ERROR]  # a generator invariant
    assert "road 10 lane -1" in f.message and "road 12 lane -1" in f.message
    assert f.y == pytest.approx(-1.75, abs=0.01)  # on the straight-on path of lane -1


def _weave(excursion: float) -> tuple[np.ndarray, np.ndarray]:
    """A straight-on path along y=0 and a turn from the same lane that drifts ``excursion`` to the left, crosses the
    straight-on path at x=20 and leaves to the right (v = c x^2 - d x^3, zero at x=0 and x=20)."""
    x = np.linspace(0.0, 40.0, 801)
    d = excursion / 1185.185185  # max of x^2 (20 - x) over 0..20 is 1185.19 (x = 13.33)
    straight = np.column_stack([x, np.zeros_like(x)])
    turn = np.column_stack([x, d * x**2 * (20.0 - x)])
    return straight, turn


@pytest.mark.parametrize("excursion", [0.07, 0.3, 0.9])
def test_paths_from_one_lane_weaving_under_a_metre_do_not_cross(excursion):
    """CARLA Town06 junctions 79, 393, 508: a turn and the straight-on path from one lane part with a weave of
    7-80 cm before the turn leaves to the right; vehicles of one lane follow each other there (no crossing)."""
    straight, turn = _weave(excursion)
    assert crossing(straight, turn, True, Tolerances().junction_start) is None


def test_paths_from_one_lane_crossing_after_they_parted():
    """A turn that leaves 1.5 m to the left of the straight-on path, then crosses it, is a crossing; with the strict
    profile's 5 cm the 7 cm weave is one too."""
    straight, turn = _weave(1.5)
    point = crossing(straight, turn, True, Tolerances().junction_start)
    assert point is not None and point[0] == pytest.approx(20.0, abs=0.05)
    straight, turn = _weave(0.07)
    strict = load_config(Path("/nonexistent"), profile="strict").tolerances.junction_start
    assert strict == 0.05 and crossing(straight, turn, True, strict) is not None


def test_carla_towns_keep_only_crossings_of_different_lanes(corpus_dir):
    """Town06's six J101 findings were same-lane weaves of 7-80 cm (docs/corpus-review.md); Town03's seven are turns
    from different lanes crossing (a right turn from the inner lane over the outer lane's straight-on path)."""
    town = corpus_dir / "carla-towns" / "OpenDrive"
    assert findings(town / "Town06.xodr", RULE) == []
    crossed = findings(town / "Town03.xodr", RULE)
    assert len(crossed) == 7
    for f in crossed:
        lanes = re.findall(r"lane (-?\d+) -> road", f.message)
        assert len(lanes) == 2 and lanes[0] != lanes[1], f.message
