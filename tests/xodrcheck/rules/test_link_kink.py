"""Rule link-kink: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.findings import Severity

RULE = "link-kink"


def test_heading_kink_without_gap():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and (f.severity, f.basis) == (
        Severity.WARNING,
        "plausibility",
    )  # no Annex F rule outside junctions
    assert [g.severity for g in findings(path, RULE, "generator")] == [Severity.ERROR]
    assert "(0.1 rad)" in f.message


def test_kinks_at_junctions_name_the_junction_rules():
    from xodrcheck.rules.shared import junction_uids as U

    common = findings(fixture(RULE, "fail_t_junction.xodr"), RULE)
    assert {(f.road, f.rule_uid) for f in common} == {("1", U.CONNECTION_SMOOTH_FIT), ("10", U.CONNECTION_SMOOTH_FIT)}
    (direct,) = findings(fixture(RULE, "fail_direct.xodr"), RULE)
    assert (direct.rule_uid, direct.severity) == (U.DIRECT_HEADING, Severity.ERROR)
