"""Rule road-without-centre-lane: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "road-without-centre-lane"


def test_no_layer_with_a_centre_lane():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.line) == ("1", line_of(path, '<road id="1"'))
