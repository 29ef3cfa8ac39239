"""Rule connection-contact-point: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "connection-contact-point"


def test_contact_point_end_for_a_road_that_starts_at_the_incoming_road():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "10"
    assert f.line == line_of(path, '<connection id="0"')
    assert "contactPoint should be start" in f.message


def test_contact_point_start_for_a_road_that_ends_at_the_incoming_road():
    from xodrcheck.rules.shared import junction_uids as U

    path = fixture(RULE, "fail_start.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.road, f.line) == (U.CONNECTION_START_ALONG, "16", line_of(path, 'incomingRoad="3"'))
    assert "contactPoint should be end" in f.message


def test_the_end_fixture_names_end_opposite_linkage():
    from xodrcheck.rules.shared import junction_uids as U

    (f,) = findings(fixture(RULE, "fail.xodr"), RULE)
    assert f.rule_uid == U.CONNECTION_END_OPPOSITE
