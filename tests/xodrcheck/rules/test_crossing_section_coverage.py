"""Rule crossing-section-coverage: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import junction_uids as U

RULE = "crossing-section-coverage"


def test_section_shorter_than_the_overlap():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.rule_uid, f.road, f.line) == (U.CROSSING_COVERAGE, "2", line_of(path, 'roadId="2" sStart="98"'))
    # road 2's 2.5 m lane over y=2..3.5 and y=-3.5..-2 lies on road 1 but outside the section
    assert "7.50 m²" in f.message
    assert 98.75 <= f.x <= 101.25 and 2.0 <= abs(f.y) <= 3.5


def test_road_1s_section_covers_its_part():
    path = fixture(RULE, "fail.xodr")
    assert [f.road for f in findings(path, RULE)] == ["2"]
    assert findings(fixture(RULE, "pass.xodr"), RULE) == []
