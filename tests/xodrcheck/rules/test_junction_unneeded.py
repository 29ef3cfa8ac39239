"""Rule junction-unneeded: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity
from xodrcheck.rules import junction_uids as U

RULE = "junction-unneeded"


def test_two_roads_joined_by_a_junction():
    path = fixture(RULE, "fail_two_roads.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.severity, f.line) == (U.COMMON_WHEN_TO_USE, Severity.ERROR, line_of(path, "<junction"))
    assert "(1-2)" in f.message


def test_two_roads_in_a_1_9_file_are_also_only_two():
    found = findings(fixture(RULE, "fail_two_roads_1_9.xodr"), RULE)
    assert {(f.rule_uid, f.severity) for f in found} == {
        (U.COMMON_WHEN_TO_USE, Severity.ERROR),
        (U.COMMON_NOT_ONLY_TWO, Severity.WARNING),
    }
