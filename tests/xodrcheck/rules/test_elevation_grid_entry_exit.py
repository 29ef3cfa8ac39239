"""Rule elevation-grid-entry-exit (J032): roads meet a junction's elevation grid without a step or a kink."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity
from xodrcheck.rules.shared import junction_uids as U

RULE = "elevation-grid-entry-exit"


def test_a_grid_holding_the_roads_plane_passes_superelevation_included():
    # road 3 and the arcs carry the plane z = 0.02 x across their lanes by superelevation: without it their lane
    # edges would lie 7 cm off the grid
    assert findings(fixture(RULE, "pass.xodr"), RULE) == []


def test_transition_zones_join_a_grid_that_lies_off_the_roads():
    assert findings(fixture(RULE, "pass_transition.xodr"), RULE) == []


def test_a_grid_5cm_above_the_roads_steps_at_every_entry():
    path = fixture(RULE, "fail_step.xodr")
    found = findings(path, RULE)
    assert sorted(f.road for f in found) == ["1", "2", "3"]
    for f in found:
        assert (f.severity, f.rule_uid) == (Severity.WARNING, U.GRID_SMOOTH)
        assert "steps by 0.05 m" in f.message and "kinks" not in f.message
        assert f.line == line_of(path, f'<segment type="joint" roadId="{f.road}"')
    by_road = {f.road: f for f in found}
    assert (by_road["1"].x, by_road["1"].s, by_road["1"].z) == pytest.approx((50.0, 50.0, 1.0))
    assert "road z=1.000, grid z=1.050" in by_road["1"].message
    assert by_road["2"].x == pytest.approx(70.0) and by_road["2"].s == 0.0
    assert by_road["3"].y == pytest.approx(10.0)


def test_a_grid_meeting_the_heights_but_not_the_grade_kinks():
    found = findings(fixture(RULE, "fail_kink.xodr"), RULE)
    assert sorted(f.road for f in found) == ["1", "2", "3"]
    for f in found:
        assert "kinks" in f.message and "steps" not in f.message
        turn = float(re.search(r"a ([0-9.]+) rad change of pitch", f.message).group(1))  # type: ignore[union-attr]
        assert 0.04 < turn < 0.05  # the hump adds 25 cm over a 5 m square: about 4.2 % of grade
    road1 = next(f for f in found if f.road == "1")
    assert "the road's grade is 2 %" in road1.message


def test_a_transition_zone_the_boundary_cannot_build_is_no_excuse():
    path = fixture(RULE, "fail_zone.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "2" and f.line == line_of(path, 'transitionLength="50"')
    assert "builds no transition zone" in f.message and "only 20 m long" in f.message


def test_without_a_boundary_the_incoming_road_ends_are_the_entries(tmp_path: Path):
    text = fixture(RULE, "fail_step.xodr").read_text(encoding="utf-8")
    path = tmp_path / "no_boundary.xodr"
    path.write_text(re.sub(r"<boundary>.*?</boundary>", "", text, flags=re.S), encoding="utf-8")
    found = findings(path, RULE)
    assert sorted(f.road for f in found) == ["1", "2", "3"]
    assert all(f.line is None and "steps by 0.05 m" in f.message for f in found)
