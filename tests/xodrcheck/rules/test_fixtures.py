"""Every check rule has its own fixtures; fail fixtures trigger their rule, pass fixtures are valid maps."""

from __future__ import annotations

import pytest

from tests.xodrcheck.rules.helpers import FIXTURES, failing, findings, passing
from xodrcheck.check import check
from xodrcheck.findings import Severity
from xodrcheck.rules import load_rules

CHECK_RULES = sorted(r.name for r in load_rules().values() if r.check is not None)
#: Fixture folders name a check rule or a reader rule (reader rules that enforce Annex F UIDs have fixtures too).
RULE_NAMES = sorted(r.name for r in load_rules().values())
FOLDERS = sorted(p.name for p in FIXTURES.iterdir() if p.is_dir())


@pytest.mark.parametrize("rule_name", CHECK_RULES)
def test_rule_has_pass_and_fail_fixtures_and_a_test(rule_name):
    assert passing(rule_name), f"no fixtures/{rule_name}/pass*.xodr"
    assert failing(rule_name), f"no fixtures/{rule_name}/fail*.xodr"
    test_file = FIXTURES.parent / f"test_{rule_name.replace('-', '_')}.py"
    assert test_file.is_file(), f"no {test_file.name}"


@pytest.mark.parametrize("folder", FOLDERS)
def test_fixture_folder_names_a_rule(folder):
    assert folder in RULE_NAMES, f"fixtures/{folder} names no rule"


@pytest.mark.parametrize(
    "path", [p for folder in FOLDERS for p in failing(folder)], ids=lambda p: f"{p.parent.name}/{p.name}"
)
def test_fail_fixture_triggers_its_rule(path):
    assert findings(path, path.parent.name)


@pytest.mark.parametrize(
    "path", [p for folder in FOLDERS for p in passing(folder)], ids=lambda p: f"{p.parent.name}/{p.name}"
)
def test_pass_fixture_is_a_clean_map(path):
    """A pass fixture is valid OpenDRIVE as far as every rule can tell, not only for its own rule."""
    report = check(path)
    assert [f for f in report.findings if f.severity >= Severity.WARNING] == []
