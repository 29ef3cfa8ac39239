"""Rule surface-crg-count: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "surface-crg-count"


def test_two_crg_files():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "manhole_rim.crg") and "references 2 CRG files" in f.message
