"""Rule validity-against-orientation: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "validity-against-orientation"


def _names(found):
    return sorted(f.rule_uid.rsplit(".", 1)[-1] for f in found)


def test_right_hand_traffic_lane_against_the_orientation():
    path = fixture(RULE, "fail_rht.xodr")
    found = findings(path, RULE)
    assert _names(found) == ["check_parent_orientation", "right_hand_traffic_lane_ids"]
    assert {f.line for f in found} == {line_of(path, '<object id="7"')}
    assert all("spans positive lane ids" in f.message and "right-hand traffic" in f.message for f in found)


def test_left_hand_traffic_lane_against_the_orientation():
    found = findings(fixture(RULE, "fail_lht.xodr"), RULE)
    assert _names(found) == ["check_parent_orientation", "left_hand_traffic_lane_ids"]
    assert all(
        "spans negative lane ids" in f.message and 'use orientation="none" or only positive' in f.message for f in found
    )


def test_both_sides_need_orientation_none():
    (f,) = findings(fixture(RULE, "fail_both_sides.xodr"), RULE)
    assert "has no orientation" in f.message and "lanes of both sides" in f.message
