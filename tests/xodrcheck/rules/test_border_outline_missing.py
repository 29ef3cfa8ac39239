"""Rule border-outline-missing: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "border-outline-missing"


def test_border_along_an_outline_the_object_lacks():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<border ") and f.rule_uid == "asam.net:xodr:1.4.0:ids.only_ref_defined_ids"
    assert "runs along outline 5" in f.message and "(its outlines: 50)" in f.message
