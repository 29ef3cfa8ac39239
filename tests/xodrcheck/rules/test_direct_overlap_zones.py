"""Rule direct-overlap-zones: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "direct-overlap-zones"


def test_single_overlap_zone():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, 'overlapZone="30"')
    assert "one link alone" in f.message


def test_pair_that_does_not_overlap():
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8")
    text = text.replace('<laneLink from="-2" to="-2" overlapZone="30"/>', '<laneLink from="-2" to="-2"/>')
    text = text.replace('<laneLink from="-1" to="-1"/>', '<laneLink from="-1" to="-1" overlapZone="30"/>')
    variant = fixture(RULE, "pass.xodr").with_name("variant.xodr")
    try:
        variant.write_text(text, encoding="utf-8")
        (f,) = findings(variant, RULE)
        assert "do not leave the same lane" in f.message
    finally:
        variant.unlink()
