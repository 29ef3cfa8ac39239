"""Rule repeat-size-overridden: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "repeat-size-overridden"


def test_widths_of_a_circular_object_and_heights_of_an_outlined_one():
    path = fixture(RULE, "fail.xodr")
    width, height = findings(path, RULE)
    assert width.rule_uid.endswith("no_widthstart_end_with_radius") and width.line == line_of(path, 'widthStart="0.2"')
    assert height.rule_uid.endswith("attributes_with_outline_skeleton") and height.line == line_of(
        path, 'heightEnd="0.01"'
    )
    assert "heightStart=0, heightEnd=0.01 (the object's height is 0)" in height.message
