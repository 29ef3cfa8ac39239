"""Rule signal-country-missing (T002): the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "signal-country-missing"


def test_a_signal_without_country():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.line == line_of(path, 'id="5"')
    assert "signal '5' has no country" in f.message
