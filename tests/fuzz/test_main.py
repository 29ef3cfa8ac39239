"""``python -m junctionart.fuzz``: runs the campaign for the time asked, prints its figures, exits 1 on a failure."""

from __future__ import annotations

import pytest
from hypothesis import settings

from junctionart.fuzz import __main__ as fuzz_main
from junctionart.fuzz import campaign, profiles


@pytest.fixture
def no_database(monkeypatch):
    """The runs here must not touch the committed example database."""
    real = profiles.budget
    monkeypatch.setattr(profiles, "budget", lambda prop, profile=None: settings(real(prop, profile), database=None))


def test_runs_until_time_is_up_and_prints_figures(no_database, capsys):
    before = campaign.TRIED["invalid-params"]
    assert fuzz_main.main(["--minutes", "0.02", "--profile", "ci", "--runs", "invalid-params"]) == 0
    out = capsys.readouterr().out
    assert campaign.TRIED["invalid-params"] > before
    assert "inputs tried:" in out and "failures: 0" in out and "invalid-params" in out


def test_a_failing_run_is_reported_and_exits_1(no_database, monkeypatch, capsys):
    def fails(case):
        raise AssertionError("planted failure")

    monkeypatch.setitem(
        campaign.RUNS,
        "planted",
        campaign.Run("planted", "invalid", campaign.RUNS["invalid-params"].strategy, fails, "always fails"),
    )
    assert fuzz_main.main(["--minutes", "0.05", "--profile", "ci", "--runs", "planted,invalid-params"]) == 1
    out = capsys.readouterr().out
    assert "FAILED planted" in out and "planted failure" in out and "failures: 1" in out


@pytest.mark.parametrize("argv", [["--runs", "nope"], ["--minutes", "0"], ["--runs", ","]])
def test_bad_arguments_exit_2(argv, capsys):
    assert fuzz_main.main(argv) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1
