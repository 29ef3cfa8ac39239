"""Rule connection-road-attribute: one finding per Annex F UID that names the defect."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import junction_uids as U

RULE = "connection-road-attribute"


def test_connecting_road_in_a_direct_junction_names_three_rules():
    path = fixture(RULE, "fail_direct_connecting_road.xodr")
    found = findings(path, RULE)
    assert {f.rule_uid for f in found} == {
        U.DIRECT_NO_CONN_ROAD,
        U.DIRECT_CONNECTING_ROAD,
        U.CONNECTION_NO_CONNECTING_ROAD_DIRECT,
    }
    assert {(f.road, f.line) for f in found} == {("3", line_of(path, 'connectingRoad="3"'))}
    assert "linkedRoad" in found[0].message


def test_linked_road_in_a_common_junction():
    path = fixture(RULE, "fail_common_linked_road.xodr")
    found = findings(path, RULE)
    assert {f.rule_uid for f in found} == {U.DEFAULT_NO_LINKED_ROAD, U.DIRECT_LINKED_ROAD}
    assert {(f.road, f.line) for f in found} == {("17", line_of(path, 'linkedRoad="17"'))}


def test_linked_road_in_a_1_6_file_names_no_rule():
    """The UIDs are 1.7's: an older file is not checked for them (the rule does not run)."""
    path = fixture(RULE, "fail_common_linked_road.xodr")
    text = path.read_text(encoding="utf-8").replace('revMinor="7"', 'revMinor="6"')
    older = path.with_name("older.xodr")
    try:
        older.write_text(text, encoding="utf-8")
        assert findings(older, RULE) == []
    finally:
        older.unlink()
