"""Rule junction-reference-line-shape: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import junction_uids as U

RULE = "junction-reference-line-shape"


def test_arc_as_junction_reference_line():
    path = fixture(RULE, "fail_arc.xodr")
    (f,) = findings(path, RULE)
    assert f.rule_uid == U.REFLINE_ONE_LINE
    assert f.line == line_of(path, '<arc curvature="0.001"/>')
    assert "<arc>" in f.message


def test_grid_without_reference_line():
    path = fixture(RULE, "fail_no_reference_line.xodr")
    (f,) = findings(path, RULE)
    assert f.rule_uid == U.GRID_PERPENDICULAR
    assert f.line == line_of(path, "<elevationGrid")
