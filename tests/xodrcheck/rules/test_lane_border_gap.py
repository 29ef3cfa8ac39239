"""Rule lane-border-gap: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "lane-border-gap"


def test_linked_lane_of_another_width():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", -1)
    assert "0.5 m apart" in f.message
    assert f.line == line_of(path, '<lane id="-1"')


def test_junction_connection_lanes_are_compared():
    assert findings(fixture(RULE, "pass_junction.xodr"), RULE) == []
    crossed = fixture("junction-lane-links-crossed", "fail.xodr")
    found = findings(crossed, RULE)
    assert {(f.road, f.lane) for f in found} == {("1", -1), ("1", -2)}
    assert all("3.5 m apart" in f.message for f in found)


def test_gaps_at_junctions_name_the_junction_rules():
    from xodrcheck.rules.shared import junction_uids as U

    common = findings(fixture(RULE, "fail_t_junction.xodr"), RULE)
    assert common and {f.rule_uid for f in common} == {U.CONNECTION_SMOOTH_FIT}
    direct = findings(fixture(RULE, "fail_direct.xodr"), RULE)
    assert direct and {f.rule_uid for f in direct} == {U.DIRECT_SMOOTH}
