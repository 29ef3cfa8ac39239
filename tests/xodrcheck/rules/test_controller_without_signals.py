"""Rule controller-without-signals (T006): the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "controller-without-signals"


def test_only_the_controller_of_a_missing_signal():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, 'controller id="2"') and "'99'" in f.message
