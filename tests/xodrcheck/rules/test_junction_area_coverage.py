"""Rule junction-area-coverage: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import junction_uids as U

RULE = "junction-area-coverage"


def test_reference_line_away_from_the_boundary():
    path = fixture(RULE, "fail_line_away.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.line, f.x, f.y) == (
        U.REFLINE_MEETS_BOUNDARY,
        line_of(path, '<geometry s="0" x="45"'),
        45.0,
        -20.0,
    )


def test_reference_line_too_short():
    path = fixture(RULE, "fail_short_line.xodr")
    (f,) = findings(path, RULE)
    assert f.rule_uid == U.REFLINE_REACHES_ALL
    assert (f.x, f.y) == pytest.approx((70.0, -3.5))  # the farthest boundary point: 5 m past the line's end
    assert "s=25.000" in f.message


def test_grid_stopping_inside_the_boundary():
    path = fixture(RULE, "fail_grid.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.line) == (U.GRID_COVERS_BOUNDARY, line_of(path, "<elevationGrid"))
    assert f.x > 60.0  # rows at s=0..15 reach x=60


def test_all_three_hold_on_the_pass_fixture_and_other_boundaries():
    for name in ("pass.xodr",):
        assert findings(fixture(RULE, name), RULE) == []
    assert findings(fixture("junction-reference-line-shape", "pass.xodr"), RULE) == []


def test_reference_line_too_short_for_a_junction_without_boundary():
    """12.9's ref_line_definition holds for every junction with a reference line, not only those with a <boundary>:
    without one, the junction's points are its connecting roads' lanes."""
    assert findings(fixture(RULE, "pass_no_boundary.xodr"), RULE) == []
    path = fixture(RULE, "fail_short_line_no_boundary.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.line) == (U.REFLINE_REACHES_ALL, line_of(path, '<geometry s="0" x="45"'))
    assert (f.x, f.y) == pytest.approx((70.0, 0.0)) and "s=25.000" in f.message and "connecting road" in f.message
