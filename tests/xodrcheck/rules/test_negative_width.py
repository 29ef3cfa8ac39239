"""Rule negative-width: its pass fixtures give no finding, its fail fixtures one where the defect is."""

import pytest

from tests.xodrcheck.rules.helpers import assert_passes, findings, fixture

RULE = "negative-width"


def test_pass_fixtures_give_no_finding():
    assert_passes(RULE)


def test_width_negative_at_the_section_end():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", -1)
    assert f.s == pytest.approx(50.0)
    assert "-1.5 m wide" in f.message


def test_cubic_dipping_below_zero_between_positive_ends():
    path = fixture(RULE, "fail_dip.xodr")
    (f,) = findings(path, RULE)
    assert f.s == pytest.approx(25.0)
    assert "-0.25 m wide" in f.message
