"""Rule negative-width: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "negative-width"


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


def test_width_at_the_float_limit_is_still_negative():
    """A width of -1e308 overflows the exact cubic fit; the rule falls back to the sampled widths (found by fuzzing)."""
    text = fixture(RULE, "fail.xodr").read_text().replace('a="3.5" b="-0.1"', 'a="-1e308" b="0"')
    assert 'a="-1e308"' in text
    from xodrcheck import check

    found = [f for f in check(text.encode()).findings if f.name == RULE]
    assert len(found) == 1 and found[0].lane == -1 and "-1e+308 m wide" in found[0].message
