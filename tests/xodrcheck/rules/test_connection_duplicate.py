"""Rule connection-duplicate: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "connection-duplicate"


def test_two_connections_for_one_incoming_and_connecting_road():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "10"
    assert f.line == line_of(path, '<connection id="2"')


def test_duplicate_in_a_1_8_file_names_one_link_to_incoming():
    from xodrcheck.rules.shared import junction_uids as U

    path = fixture(RULE, "fail_1_8.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.road, f.line) == (U.CONNECTION_ONE_LINK, "16", line_of(path, '<connection id="4"'))
