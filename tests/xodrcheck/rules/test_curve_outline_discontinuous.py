"""Rule curve-outline-discontinuous: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check

RULE = "curve-outline-discontinuous"


def test_curve_starting_past_the_end_of_the_previous_one():
    """The half circle starts at u=11 where the 10 m line ends at u=10; shifted, it also ends 1 m off the next line."""
    path = fixture(RULE, "fail.xodr")
    first, second = findings(path, RULE)
    assert (first.road, first.line) == ("1", line_of(path, 'u="11"'))
    assert "ends at u=10.0000, v=0.0000, 1 m away" in first.message
    assert second.line == line_of(path, 'u="10" v="4"') and "ends at u=11.0000, v=4.0000" in second.message


def test_a_curve_without_length_reaches_the_next_curve_only_along_itself():
    path = fixture(RULE, "fail_no_length.xodr")
    found = findings(path, RULE)
    assert found[0].line == line_of(path, 'u="10" v="1"') and "1 m away" in found[0].message


def test_the_closing_joint_of_a_closed_outline_is_checked():
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8")
    opened = text.replace('<curveLocal id="0" u="-5" v="-2"', '<curveLocal id="0" u="-5" v="-1.5"')
    found = [f for f in check(opened.encode(), select=("G060",)).findings if f.code == "G060"]
    closing = [f for f in found if "starts at u=-5, v=-1.5" in f.message]  # the paramPoly3 ends at (-5, -2)
    assert 'u="-5" v="-1.5"' in opened and len(closing) == 1 and "0.5 m away" in closing[0].message
