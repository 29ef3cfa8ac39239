"""Rule outline-id-duplicate: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "outline-id-duplicate"


def test_two_outlines_with_one_id():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<outline id="0"', 2) and f.rule_uid.endswith("borders.different_outlineids")
    first = line_of(path, '<outline id="0"', 1)
    assert f"as the one at line {first}" in f.message


def test_files_before_1_9_are_checked_without_the_uid():
    """The 1.9 UID does not apply to a 1.8 file, but outline ids were unique within an object before it."""
    (f,) = findings(fixture(RULE, "fail_1_8.xodr"), RULE)
    assert f.rule_uid is None and "has id=0" in f.message
