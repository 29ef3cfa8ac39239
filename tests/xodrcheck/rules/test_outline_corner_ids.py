"""Rule outline-corner-ids: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "outline-corner-ids"


def test_ids_not_from_zero_and_not_counting_up():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert {f.severity for f in found} == {Severity.WARNING}
    by_uid = {f.rule_uid.rsplit(":", 1)[-1]: f for f in found}
    assert by_uid["road.corner_road.first_id_zero"].line == line_of(path, 'id="1"/>')
    assert by_uid["road.corner_road.sequential_id_values"].line == line_of(path, 'id="4"/>')
    assert 'with id="4" follows one with id="2"' in by_uid["road.corner_road.sequential_id_values"].message
    assert 'has id="2"' in by_uid["road.corner_local.first_id_zero"].message
    assert 'id="5" follows one with id="3"' in by_uid["road.corner_local.sequential_id_values"].message
