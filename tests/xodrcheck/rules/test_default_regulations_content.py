"""Rule default-regulations-content: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "default-regulations-content"


def test_a_prohibition_among_the_default_regulations():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<prohibited/>") and f.road is None
    assert "<roadRegulations> (line 6) use <prohibited>" in f.message
