"""Rule border-corner-references: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "border-corner-references"


def test_complete_border_with_corner_references():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<cornerReference") and f.rule_uid.endswith("useCompleteOutline_true")
    assert "useCompleteOutline true" in f.message and "2 <cornerReference>" in f.message


def test_partial_borders_name_two_corners_of_their_outline():
    path = fixture(RULE, "fail_partial.xodr")
    one, unknown = findings(path, RULE)
    assert one.rule_uid is None and one.basis == "reading", "13.9 says so without a UID: the stretch cannot be read"
    assert unknown.rule_uid == unknown.basis == "asam.net:xodr:1.4.0:ids.only_ref_defined_ids"
    assert one.line == line_of(path, "<border ", 1) and "1 <cornerReference>" in one.message
    assert unknown.line == line_of(path, '<cornerReference id="9"') and "corner 9" in unknown.message
