"""Rule road-length-mismatch: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "road-length-mismatch"


def test_declared_length_ten_metres_too_long():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and "-10 m" in f.message
    assert f.line == line_of(path, '<road id="1"')
