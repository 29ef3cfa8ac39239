"""Rule cross-section-surface-with-shape (U010): the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "cross-section-surface-with-shape"


def test_superelevation_beside_a_surface():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<crossSectionSurface>")
    assert f"<superelevation> record(s) (first at line {line_of(path, '<superelevation')})" in f.message
