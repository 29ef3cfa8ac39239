"""Rule structure-type-missing: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "structure-type-missing"


def test_tunnel_and_bridge_without_type():
    path = fixture(RULE, "fail.xodr")
    tunnel, bridge = findings(path, RULE)
    assert (tunnel.line, tunnel.rule_uid.rsplit(":", 1)[-1]) == (
        line_of(path, "<tunnel"),
        "road.object.tunnels.type_definition",
    )
    assert (bridge.line, bridge.rule_uid.rsplit(":", 1)[-1]) == (
        line_of(path, "<bridge"),
        "road.object.bridges.type_definition",
    )
    assert "(standard or underpass)" in tunnel.message and "(concrete, steel, brick or wood)" in bridge.message
