"""Gaps, steps and kinks are graded by two tolerances (issue 18): nothing up to the strict value (``position`` 1 mm,
``heading`` 1 mrad), a warning up to the error threshold (``gap`` 1 cm, ``kink`` 0.01 rad), an error above it; the
``strict`` profile makes errors of everything over the strict values (the verdicts before issue 18). Above the error
threshold the finding names its Annex F rule where there is one: under the default profile an error only where that
rule says "shall" (issue 26), a warning for a "should" rule or the checker's own plausibility check; the generator
profile keeps every rule's own error.

Each case takes a rule's fail fixture and writes the defect at three sizes: under the strict value, between, above."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.xodrcheck.rules.helpers import code_of, fixture
from xodrcheck.check import check
from xodrcheck.config import PROFILES, ConfigError, Tolerances, load_config
from xodrcheck.findings import Severity

E, W = Severity.ERROR, Severity.WARNING
#: rule, fixture, text to replace, the replacements for a defect of (under, between, over) the thresholds, and the
#: default profile's severity over the error threshold (an error for a "shall" rule of the standard).
CASES = [
    ("plan-view-gap", "fail.xodr", 'x="50.05"', ('x="50.0005"', 'x="50.005"', 'x="50.05"'), E),  # refline_no_gaps
    ("plan-view-kink", "fail.xodr", 'hdg="0.1"', ('hdg="0.0005"', 'hdg="0.005"', 'hdg="0.05"'), W),  # a "should"
    ("link-gap", "fail.xodr", 'x="100.05"', ('x="100.0005"', 'x="100.005"', 'x="100.05"'), E),  # contact_point
    ("link-kink", "fail.xodr", 'hdg="0.1"', ('hdg="0.0005"', 'hdg="0.005"', 'hdg="0.05"'), W),  # no UID: plausibility
    ("lane-border-gap", "fail.xodr", 'a="3.0"', ('a="3.4995"', 'a="3.495"', 'a="3.45"'), W),
    ("lane-border-discontinuous", "fail.xodr", 'a="2.5"', ('a="3.4995"', 'a="3.495"', 'a="3.45"'), W),
    ("link-step", "fail-elevation.xodr", 'a="5.0"', ('a="0.0005"', 'a="0.005"', 'a="0.05"'), W),
    ("profile-step", "fail_elevation.xodr", 'a="1.05"', ('a="1.0005"', 'a="1.005"', 'a="1.05"'), W),
]


def _variant(tmp_path: Path, rule: str, name: str, old: str, new: str) -> Path:
    text = fixture(rule, name).read_text(encoding="utf-8")
    assert old in text, f"{old} not in {rule}/{name}"
    path = tmp_path / f"{rule}-{sum(map(ord, new))}.xodr"
    path.write_text(text.replace(old, new), encoding="utf-8")
    return path


def _severities(path: Path, rule: str, profile: str = "default") -> list[Severity]:
    code = code_of(rule)
    report = check(path, load_config(overrides={}, profile=profile), select=(code,))
    return [f.severity for f in report.findings if f.code == code]


@pytest.mark.parametrize("rule, name, old, sizes, standard", CASES, ids=[c[0] for c in CASES])
def test_under_between_and_over_the_thresholds(tmp_path, rule, name, old, sizes, standard):
    under, between, over = (_variant(tmp_path, rule, name, old, new) for new in sizes)
    assert _severities(under, rule) == []
    assert set(_severities(between, rule)) == {Severity.WARNING}
    assert set(_severities(over, rule)) == {standard}
    assert set(_severities(over, rule, "generator")) == {Severity.ERROR}  # the rule's own verdict
    assert set(_severities(between, rule, "generator")) == {Severity.WARNING}  # with the default tolerances
    assert set(_severities(between, rule, "strict")) == {Severity.ERROR}  # one option away: the old verdict
    assert _severities(under, rule, "strict") == []


def test_warning_says_which_threshold_it_stays_under(tmp_path):
    path = _variant(tmp_path, "lane-border-gap", "fail.xodr", 'a="3.0"', 'a="3.495"')
    (f,) = check(path, select=("K103",)).findings
    assert f.severity is Severity.WARNING
    assert "0.005 m apart" in f.message and "within the 0.01 m gap" in f.message
    assert check(path, select=("K103",)).ok  # a warning does not fail the check


def test_grade():
    t = Tolerances()
    assert [t.grade(d) for d in (0.0, 0.001, 0.0011, 0.01, 0.0101)] == [
        None,
        None,
        Severity.WARNING,
        Severity.WARNING,
        Severity.ERROR,
    ]
    assert t.grade(float("nan")) is None
    assert t.grade(0.0049, "heading") is Severity.WARNING and t.grade(0.011, "heading") is Severity.ERROR


def test_profiles_and_precedence(tmp_path):
    """Defaults, then the profile, then the file's tolerances, then the flags."""
    assert load_config(tmp_path).tolerances.gap == 0.01
    assert load_config(tmp_path, profile="strict").tolerances.gap == Tolerances().position
    (tmp_path / "xodrcheck.toml").write_text('profile = "strict"\n[tolerances]\nkink = 0.004\n', encoding="utf-8")
    config = load_config(tmp_path)
    assert (config.tolerances.gap, config.tolerances.kink) == (0.001, 0.004)
    assert load_config(tmp_path, overrides={"gap": "0.02"}).tolerances.gap == 0.02
    assert load_config(tmp_path, profile="default").tolerances.gap == 0.01
    with pytest.raises(ConfigError, match="unknown profile 'lax'"):
        load_config(tmp_path, profile="lax")
    assert set(PROFILES) == {"default", "strict", "generator"}
    generator = load_config(tmp_path, profile="generator").tolerances  # the default values, then the file's
    assert (generator.gap, generator.kink, generator.junction_start) == (0.01, 0.004, 1.0)
    assert load_config(tmp_path, profile="generator").profile == "generator"
