"""Rule duplicate-junction-id: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "duplicate-junction-id"


def test_second_junction_with_the_id_is_reported():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<junction id="100"', occurrence=2)
