"""Rule object-orientation-missing: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check

RULE = "object-orientation-missing"


def test_object_without_orientation():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.line) == ("1", line_of(path, '<object id="1"')) and "has no orientation" in f.message


def test_an_unknown_orientation_specifies_no_direction():
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8").replace('orientation="none"', 'orientation="both"')
    (f,) = [f for f in check(text.encode(), select=("B002",)).findings if f.code == "B002"]
    assert 'has orientation="both"' in f.message
