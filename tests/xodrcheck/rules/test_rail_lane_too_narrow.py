"""Rule rail-lane-too-narrow (W005): rail and tram lanes narrower than the assumed narrowest rail-bound vehicle."""

import pytest

from tests.xodrcheck.rules.helpers import code_of, findings, fixture, line_of
from xodrcheck.check import check
from xodrcheck.config import Config, Tolerances

RULE = "rail-lane-too-narrow"
UID = "asam.net:xodr:1.7.0:road.railroad.rail_lane_width_validity"


def test_lane_as_wide_as_the_gauge():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.rule_uid == UID
    assert (f.road, f.lane, f.section_s, f.s) == ("1", -1, 0.0, 0.0)
    assert f.line == line_of(path, 'type="tram"')
    assert "tram lane -1 of the lane section at s=0 is at most 1.435 m wide along the whole section" in f.message
    assert (
        "narrower than 2.2 m, the narrowest rail-bound vehicle assumed (tolerance rail_vehicle_min_width)" in f.message
    )


def test_dip_between_wide_ends_is_found_exactly():
    """2.6 m at both ends, 2.15 m at s=37.5 (the cubic's minimum), where no end or midpoint sample looks."""
    (f,) = findings(fixture(RULE, "fail_dip.xodr"), RULE)
    assert f.s == pytest.approx(37.5, abs=1e-6)
    assert "is 2.15 m wide at s=37.5:" in f.message
    assert (f.x, f.y) == (pytest.approx(37.5, abs=1e-6), pytest.approx(0.0, abs=1e-9))  # the lane's centre: on the line


def test_wide_lanes_pass():
    assert findings(fixture(RULE, "pass.xodr"), RULE) == []
    assert findings(fixture(RULE, "pass_widening.xodr"), RULE) == []


def test_the_assumed_width_is_a_tolerance():
    """Maps for wider vehicles raise it: a 2.65 m lane is then too narrow for 2.8 m trains, and 2.3 m is then fine."""
    code = code_of(RULE)
    wide = Config(tolerances=Tolerances(rail_vehicle_min_width=2.8))
    (f,) = [x for x in check(fixture(RULE, "pass.xodr"), wide, select=(code,)).findings if x.code == code]
    assert "narrower than 2.8 m" in f.message and "2.65 m wide" in f.message
    narrow = Config(tolerances=Tolerances(rail_vehicle_min_width=1.4))
    assert not [x for x in check(fixture(RULE, "fail.xodr"), narrow, select=(code,)).findings if x.code == code]
