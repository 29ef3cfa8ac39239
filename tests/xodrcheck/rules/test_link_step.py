"""Rule link-step: linked roads and lanes must meet in height (elevation, superelevation, lane height)."""

import math

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "link-step"


def test_five_metre_step_in_elevation():
    path = fixture(RULE, "fail-elevation.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.severity) == ("1", None, Severity.WARNING)  # at the lane-0 line: everything steps alike
    assert f.basis == "plausibility" and findings(path, RULE, "generator")[0].severity is Severity.ERROR
    assert f.line == line_of(path, '<successor elementType="road" elementId="2"')
    assert "steps by 5 m" in f.message and "4 linked lane pair(s) step" in f.message
    assert (f.x, f.y, f.z) == pytest.approx((100.0, 0.0, 5.0))


def test_superelevation_on_one_side_only():
    """Road 1 rolls by 0.05 rad, road 2 does not: the edges of the outer lanes (5.5 m out) step by 5.5 sin(0.05)."""
    path = fixture(RULE, "fail-superelevation.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and abs(f.lane) == 2
    step = 5.5 * math.sin(0.05)
    assert f"steps by {step:.4g} m" in f.message
    assert abs(f.z) == pytest.approx(step)
    assert f.y == pytest.approx(math.copysign(5.5 * math.cos(0.05), f.lane))  # the rolled edge, in plan view


def test_lane_height_on_one_side_only():
    """The sidewalks of road 1 are raised 0.15 m (``<height>``), those of road 2 are not."""
    path = fixture(RULE, "fail-height.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.lane in (2, -2)
    assert "steps by 0.15 m" in f.message and "2 linked lane pair(s) step" in f.message
    assert f.z == pytest.approx(0.15)
    assert f.line == line_of(path, f'<lane id="{f.lane}" type="sidewalk"')


def test_steps_within_the_position_tolerance_pass(tmp_path):
    """A step of half a millimetre is no finding; the tolerance is the one for positions."""
    text = fixture(RULE, "fail-elevation.xodr").read_text(encoding="utf-8").replace('a="5.0"', 'a="0.0005"')
    path = tmp_path / "tiny.xodr"
    path.write_text(text, encoding="utf-8")
    assert findings(path, RULE) == []


def test_steps_at_junctions_name_the_junction_rules():
    from xodrcheck.rules.shared import junction_uids as U

    common = findings(fixture(RULE, "fail_t_junction.xodr"), RULE)
    assert len(common) == 2 and {f.rule_uid for f in common} == {U.CONNECTION_SMOOTH_FIT}
    (direct,) = findings(fixture(RULE, "fail_direct.xodr"), RULE)
    assert direct.rule_uid == U.DIRECT_SMOOTH
