"""Rule cross-section-surface-strips (U012): the findings each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import feature_uids as U

RULE = "cross-section-surface-strips"


def test_inner_strip_without_width_and_single_strip_with_one():
    path = fixture(RULE, "fail.xodr")
    found = {f.rule_uid: f for f in findings(path, RULE)}
    assert set(found) == {U.SURFACE_USE_STRIP, U.SURFACE_USE_WIDTH}
    assert found[U.SURFACE_USE_WIDTH].line == line_of(path, '<strip id="1">')
    assert found[U.SURFACE_USE_STRIP].line == line_of(path, '<strip id="-1">')
    assert "the only strip on the right has a <width>" in found[U.SURFACE_USE_STRIP].message
