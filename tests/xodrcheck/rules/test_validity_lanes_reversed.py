"""Rule validity-lanes-reversed: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "validity-lanes-reversed"


def test_each_kind_of_parent_names_its_own_rule():
    path = fixture(RULE, "fail.xodr")
    found = {f.rule_uid.rsplit(":", 1)[-1]: f for f in findings(path, RULE)}
    assert set(found) == {
        "road.object.validty.from_lower_equal_to",
        "road.object.reference.from_lower_equal_to",
        "road.object.tunnels.from_lower_equal_to",
        "road.object.bridges.from_lower_equal_to",
    }
    tunnel = found["road.object.tunnels.from_lower_equal_to"]
    assert (tunnel.line, tunnel.s) == (line_of(path, '<tunnel id="t1"'), 10.0)
    reference = found["road.object.reference.from_lower_equal_to"]
    assert reference.road == "2" and "objectReference 7" in reference.message
    assert "fromLane=-1 greater than toLane=-2" in found["road.object.validty.from_lower_equal_to"].message
