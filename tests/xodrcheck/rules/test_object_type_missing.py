"""Rule object-type-missing: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check

RULE = "object-type-missing"


def test_object_without_type():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.line, f.s) == ("1", line_of(path, '<object id="1"'), 50.0)
    assert (f.x, f.y) == (50.0, -5.0), "the finding is placed at the object's s and t"
    assert "object 1 has no type" in f.message


def test_files_before_1_7_are_not_checked():
    text = fixture(RULE, "fail.xodr").read_text(encoding="utf-8").replace('revMinor="7"', 'revMinor="6"')
    assert [f for f in check(text.encode(), select=("B001",)).findings if f.code == "B001"] == []
