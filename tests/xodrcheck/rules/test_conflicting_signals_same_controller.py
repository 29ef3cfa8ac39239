"""Rule conflicting-signals-same-controller (V001): lights of one controller releasing crossing movements."""

import numpy as np
import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check
from xodrcheck.findings import Severity

RULE = "conflicting-signals-same-controller"


def test_crossing_left_turn_in_the_straight_on_group():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.WARNING and f.code == "V001" and f.rule_uid is None
    assert f.line == line_of(path, '<controller id="1" name="group 1">')
    # the left turn (radius 11.75 m around (70, 10)) meets the westbound straight-on lane centre at y = 1.75
    assert f.y == pytest.approx(1.75, abs=0.01) and f.x == pytest.approx(70 - np.sqrt(11.75**2 - 8.25**2), abs=0.05)
    assert f.road == "2" and f.s == 5.0
    light12 = line_of(path, 'id="12"')
    expected = ("junction 100", "controller 1", "signal 12 (road 2", "signal 13 (road 3", "connecting road 11 lane -1")
    for words in (*expected, "connecting road 17 lane -1", f"line {light12})"):
        assert words in f.message, (words, f.message)


def test_a_signal_reference_places_the_light_on_another_road():
    path = fixture(RULE, "fail_reference.xodr")
    (f,) = findings(path, RULE)
    assert "signalReference to signal 11 (road 3" in f.message and "signal 12 (road 2" in f.message
    assert f.road == "3" and f.y == pytest.approx(1.75, abs=0.01)


def test_groups_that_take_turns_and_merges_pass():
    """The pass fixtures hold the same lights, grouped so that only a diverge or a merge shares a controller; the
    merge fixture's two released lanes really do meet at their ends (the rule leaves the merge out, not misses it)."""
    for name in ("pass.xodr", "pass_merge.xodr"):
        assert findings(fixture(RULE, name), RULE) == []
    report = check(fixture(RULE, "pass_merge.xodr"))
    assert [f for f in report.findings if f.severity >= Severity.WARNING] == []


def test_merge_fixture_is_a_real_merge():
    from xodrcheck.reader import read
    from xodrcheck.rules.shared.context import Context
    from xodrcheck.rules.signal_control import crossing, movements, placements

    path = fixture(RULE, "pass_merge.xodr")
    ctx = Context(read(path).document, data=path.read_bytes())
    lights = placements(ctx)
    assert sorted(lights) == ["11", "12", "13"]
    cache: dict = {}
    road1 = movements(ctx, lights["11"][0], cache)
    road3 = movements(ctx, lights["13"][0], cache)
    assert sorted((m.road.id, m.to_lane) for m in road1) == [("10", -2), ("10", -1)]
    (left,) = road3
    straight = next(m for m in road1 if m.to_lane == -1)
    assert np.hypot(*(left.xy[-1] - straight.xy[-1])) < 0.01  # both end on lane -1 of road 2
    assert crossing(left, straight, 0.05) is None
    # the same left turn against road 2's straight-on lane is a crossing
    (through, _) = sorted(movements(ctx, lights["12"][0], cache), key=lambda m: m.road.id)
    assert through.road.id == "11" and crossing(left, through, 0.05) is not None
