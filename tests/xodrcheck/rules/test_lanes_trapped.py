"""Rule lanes-trapped: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.findings import Severity

RULE = "lanes-trapped"


def test_a_loop_without_a_way_out_traps_what_enters_it():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    # reported once, where traffic enters the loop: the start of road 2, from connecting road 10
    assert (f.road, f.lane, f.section_s, f.s) == ("2", -1, 0.0, 0.0)
    assert f.severity is Severity.WARNING
    assert "the 2 lanes of road(s) 2, 11" in f.message


def test_the_loop_with_a_way_out_traps_nothing():
    assert findings(fixture(RULE, "pass.xodr"), RULE) == []
