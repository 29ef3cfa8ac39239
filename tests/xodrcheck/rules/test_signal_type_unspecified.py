"""Rule signal-type-unspecified (T001): the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "signal-type-unspecified"


def test_a_blank_subtype_is_found_on_its_signal_only():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.line == line_of(path, 'id="6"')
    assert "signal '6' has no subtype" in f.message
