"""Rule coordinates-off-centre: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity

RULE = "coordinates-off-centre"


def test_utm_coordinates_without_offset():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.severity is Severity.WARNING and f.line == line_of(path, "<header")
    assert (f.x, f.y) == (500050.0, 5400000.0)
    assert "span x 500000.0..500100.0, y 5400000.0..5400000.0" in f.message
    assert "5423 km from (0, 0)" in f.message and "step by 0.5 m" in f.message
    assert "add (500050.0, 5400000.0) to the header's <offset>" in f.message


def test_the_extent_is_the_whole_reference_lines():
    """Not only the geometries' start points: a road from 15 km out to the origin reaches it; a road from 9 km out
    running 20 km on is centred 19 km out."""
    assert findings(fixture(RULE, "pass_reaching_the_origin.xodr"), RULE) == []
    (f,) = findings(fixture(RULE, "fail_long_road.xodr"), RULE)
    assert (f.x, f.y) == (19000.0, 0.0)
    assert "span x 9000.0..29000.0" in f.message and "move the geometry by (-19000.0, 0.0)" in f.message
