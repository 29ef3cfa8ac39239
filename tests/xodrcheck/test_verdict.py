"""Verdicts from the standard's words (issue 26): the default profile bounds each finding's severity by the level of
the Annex F rule it enforces, or by its basis; the strict and generator profiles give every rule its own severity."""

from __future__ import annotations

import dataclasses

import pytest

from tests.xodrcheck.rules.helpers import fixture
from xodrcheck.check import check
from xodrcheck.cli import main
from xodrcheck.config import PROFILES, Config, ConfigError, Tolerances, load_config
from xodrcheck.findings import Basis, Category, Finding, Severity
from xodrcheck.verdict import bound

SHALL = "asam.net:xodr:1.4.0:road.geometry.refline_no_gaps"
SHOULD = "asam.net:xodr:1.4.0:road.geometry.refline_no_kinks"
MAY = "asam.net:xodr:1.7.0:road.object.material.materials_may_differ"
RADIUS = fixture("lane-radius-too-small", "fail.xodr")  # C001 and C002: the project's 5 m minimum radius


def _finding(uid: str | None = None, basis: str = "") -> Finding:
    return Finding("Z000", "z", Category.GEOMETRY, Severity.ERROR, "m", rule_uid=uid, basis=basis)


@pytest.mark.parametrize(
    ("uid", "basis", "most"),
    [
        (SHALL, "", None),
        (SHOULD, "", Severity.WARNING),
        (MAY, "", Severity.INFO),
        (None, Basis.PLAUSIBILITY, Severity.WARNING),
        (None, Basis.SCHEMA, None),
        (None, Basis.READING, None),
        (None, Basis.INCOMPLETE, None),  # a check that did not finish is never passed off as a warning
    ],
)
def test_the_standard_s_words_bound_the_severity(uid, basis, most):
    assert bound(_finding(uid, basis)) is most


def test_a_plausibility_error_is_a_warning_by_default_and_an_error_for_the_generator():
    default = check(RADIUS)
    assert {(f.code, f.severity, f.basis) for f in default.findings} == {
        ("C001", Severity.WARNING, "plausibility"),
        ("C002", Severity.WARNING, "plausibility"),
    }
    assert default.ok and default.profile == "default"
    for name in ("generator", "strict"):
        judged = check(RADIUS, Config(profile=name))
        assert {f.severity for f in judged.findings} == {Severity.ERROR} and not judged.ok
        assert judged.profile == name
        assert [dataclasses.replace(f, severity=Severity.WARNING) for f in judged.findings] == list(default.findings)


def test_a_should_rule_gives_a_warning_and_keeps_its_uid():
    path = fixture("plan-view-kink", "fail.xodr")
    (f,) = check(path, select=("G002",)).findings
    assert (f.severity, f.rule_uid, f.basis) == (Severity.WARNING, SHOULD, SHOULD)
    (g,) = check(path, Config(profile="generator"), select=("G002",)).findings
    assert (g.severity, g.rule_uid) == (Severity.ERROR, SHOULD)


def test_a_shall_rule_keeps_its_error():
    path = fixture("plan-view-gap", "fail.xodr")
    (f,) = check(path, select=("G001",)).findings
    assert (f.severity, f.rule_uid) == (Severity.ERROR, SHALL)


def test_a_rule_s_own_choice_below_the_bound_is_kept():
    """J004 is a warning on 1.7 files and an info before: the bound only lowers."""
    warning = check(fixture("junction-lane-link-outbound", "fail.xodr"), select=("J004",)).findings
    info = check(fixture("junction-lane-link-outbound", "fail_14.xodr"), select=("J004",)).findings
    assert {f.severity for f in warning} == {Severity.WARNING} and {f.severity for f in info} == {Severity.INFO}
    generator = Config(profile="generator")
    assert check(fixture("junction-lane-link-outbound", "fail.xodr"), generator, select=("J004",)).findings == warning


def test_severity_selectors_see_the_judged_severity():
    assert check(RADIUS, select=("error",)).findings == ()
    assert check(RADIUS, select=("warning",)).findings == check(RADIUS).findings != ()
    assert check(RADIUS, Config(profile="generator"), select=("warning",)).findings == ()


def test_config_profile_gives_its_tolerances_unless_they_are_given():
    assert Config().tolerances == Tolerances() and Config().profile == "default"
    assert Config(profile="strict").tolerances.gap == Tolerances().position == 0.001
    assert Config(profile="strict").tolerances.junction_start == 0.05
    assert Config(profile="generator").tolerances == Tolerances()
    assert Config(tolerances=Tolerances(gap=0.5), profile="strict").tolerances.gap == 0.5
    assert Config(profile="generator").profile_spec is PROFILES["generator"]
    with pytest.raises(ConfigError, match="unknown profile 'lenient'"):
        Config(profile="lenient")


def test_profiles_are_typed_values():
    assert [p.name for p in PROFILES.values()] == ["default", "strict", "generator"]
    assert [p.capped for p in PROFILES.values()] == [True, False, False]
    assert PROFILES["generator"].tolerances == () and dict(PROFILES["strict"].tolerances)["gap"] == 0.001
    assert all(p.doc for p in PROFILES.values())


def test_the_configuration_file_names_the_profile(tmp_path):
    (tmp_path / "xodrcheck.toml").write_text('profile = "generator"\n', encoding="utf-8")
    config = load_config(tmp_path)
    assert config.profile == "generator" and config.tolerances == Tolerances()
    assert load_config(tmp_path, profile="default").profile == "default"
    (tmp_path / "xodrcheck.toml").write_text("profile = 3\n", encoding="utf-8")
    with pytest.raises(ConfigError, match="unknown profile 3"):
        load_config(tmp_path)


def test_command_line_profile_decides_the_exit_code(capsys):
    assert main(["check", str(RADIUS)]) == 0
    assert main(["check", "--profile", "generator", str(RADIUS)]) == 1
    assert main(["check", "--profile", "strict", str(RADIUS)]) == 1
    capsys.readouterr()
    with pytest.raises(SystemExit):
        main(["check", "--help"])
    assert "generator" in capsys.readouterr().out


def test_rules_tolerances_says_what_each_profile_does(capsys):
    assert main(["rules", "--tolerances"]) == 0
    out = capsys.readouterr().out
    for profile in PROFILES.values():
        assert f"  {profile.name}: {profile.doc}" in out
