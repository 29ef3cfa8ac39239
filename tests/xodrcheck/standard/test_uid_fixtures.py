"""Every rule of the standard that xodrcheck enforces has a failing and a passing fixture that says so.

Fixtures name the UIDs they exercise (see :mod:`tests.xodrcheck.standard.uidfixtures`). A fail fixture gives, with
only its folder's rule selected, a finding that names each of its UIDs, at the severity the standard's wording gives
(or the one ``SEVERITY_DEVIATIONS`` documents); a pass fixture gives no finding with its UIDs. An enforced UID
without both is a failure here.
"""

from __future__ import annotations

import pytest

from tests.xodrcheck.rules.helpers import code_of
from tests.xodrcheck.standard.uidfixtures import FIXTURES, uid_fixtures
from xodrcheck.check import check
from xodrcheck.rules import load_rules
from xodrcheck.standard import annex_rules
from xodrcheck.standard.status import MISSING, expected_severity, statuses

ENFORCED = sorted(row.uid for row in statuses(load_rules()) if row.status != MISSING)
FIXTURES_BY_UID = uid_fixtures()
NAMED = sorted((uid, kind, path) for uid, kinds in FIXTURES_BY_UID.items() for kind in kinds for path in kinds[kind])


@pytest.mark.parametrize("uid", ENFORCED)
def test_enforced_uid_has_a_failing_and_a_passing_fixture(uid):
    kinds = FIXTURES_BY_UID.get(uid, {"pass": [], "fail": []})
    assert kinds["fail"], f"no fail fixture names {uid} (<!-- uids: ... --> in a fixture of its rule)"
    assert kinds["pass"], f"no pass fixture names {uid}"


def _uid_findings(path, uid):
    rule_name = path.parent.name
    report = check(path, select=(code_of(rule_name),))
    assert not [f for f in report.findings if f.code == "X900"], report.findings
    return [f for f in report.findings if f.rule_uid == uid]


@pytest.mark.parametrize(
    ("uid", "kind", "path"), NAMED, ids=[f"{p.parent.name}/{p.name}:{u.rsplit(':', 1)[-1]}" for u, _, p in NAMED]
)
def test_fixture_gives_what_it_says(uid, kind, path):
    assert uid in annex_rules(), f"{path.relative_to(FIXTURES)} names an unknown UID {uid}"
    rule = next(r for r in load_rules().values() if r.name == path.parent.name)
    assert uid in rule.uids, f"{path.relative_to(FIXTURES)} names {uid}, which its rule {rule.code} does not enforce"
    found = _uid_findings(path, uid)
    if kind == "pass":
        assert found == []
    else:
        assert found, f"{path.relative_to(FIXTURES)} gives no finding with {uid}"
        assert {f.severity for f in found} == {expected_severity(uid)}, "the standard's wording sets the severity"
