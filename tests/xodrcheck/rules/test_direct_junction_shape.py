"""Rule direct-junction-shape: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "direct-junction-shape"


def test_direct_junction_of_two_roads():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<junction id="111"')
    assert "roads 1-2" in f.message


def test_roads_on_both_sides():
    """Figure 92: roads 1 and 4 continue on roads 2 and 3 (no road in every connection)."""
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8")
    text = text.replace('incomingRoad="1" linkedRoad="3"', 'incomingRoad="4" linkedRoad="3"')
    variant = fixture(RULE, "pass.xodr").with_name("variant.xodr")
    try:
        variant.write_text(text, encoding="utf-8")
        (f,) = findings(variant, RULE)
        assert "several roads on both sides" in f.message
    finally:
        variant.unlink()
