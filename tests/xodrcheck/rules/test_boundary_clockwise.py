"""Rule boundary-clockwise: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import junction_uids as U

RULE = "boundary-clockwise"


def test_segments_in_reverse_order():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.line) == (U.BOUNDARY_COUNTER_CLOCKWISE, line_of(path, "<boundary>"))
    # the boundary encloses a 20 x 7 m rectangle, two quarter annuli and the 7 m x 6.5 m corner piece
    assert "run clockwise" in f.message and "203.7 m²" in f.message


def test_an_open_boundary_has_no_orientation():
    assert findings(fixture("boundary-not-closed", "fail.xodr"), RULE) == []
