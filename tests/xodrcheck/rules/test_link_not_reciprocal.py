"""Rule link-not-reciprocal: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "link-not-reciprocal"


def test_successor_not_returned():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.line == line_of(path, '<successor elementType="road" elementId="2"')
    assert "nothing" in f.message


def test_returned_at_the_wrong_end():
    path = fixture(RULE, "fail_contact.xodr")
    found = findings(path, RULE)
    assert {f.road for f in found} == {"1", "2"}
    first = next(f for f in found if f.road == "1")
    assert "at its start, not at its end" in first.message


def test_connecting_road_linking_a_road_that_does_not_link_to_its_junction():
    path = fixture(RULE, "fail_junction.xodr")
    found = findings(path, RULE)
    assert [f.road for f in found] == ["3"]
    assert "junction 100 has no connection from road 3" in found[0].message
