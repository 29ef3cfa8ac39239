"""Rule duplicate-road-id: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "duplicate-road-id"


def test_second_road_with_the_id_is_reported():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<road id="2"', occurrence=2)
    first = line_of(path, '<road id="2"')
    assert f"first at line {first}" in f.message
