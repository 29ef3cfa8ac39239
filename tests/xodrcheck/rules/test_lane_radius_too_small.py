"""Rule lane-radius-too-small: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture
from xodrcheck.check import check

RULE = "lane-radius-too-small"


def test_lane_centres_inside_a_four_metre_arc():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert {f.lane for f in found} == {1}  # lane 1 centre at radius 2.25 m; lane -1 at 5.75 m is fine
    assert "radius of 2.25 m" in found[0].message


def test_a_lane_filed_on_the_wrong_side_is_skipped_not_a_crash(tmp_path):
    """Regression (found by fuzzing): lane 1 inside <right> has no place in the road; the rule skips it (and
    lane-id-sequence reports it) instead of failing with a KeyError."""
    text = fixture(RULE, "fail.xodr").read_text(encoding="utf-8")
    left = text[text.index("<left>") + len("<left>") : text.index("</left>")]
    moved = text.replace(f"<left>{left}</left>", "").replace("<right>", "<right>" + left)
    path = tmp_path / "wrong_side.xodr"
    path.write_text(moved, encoding="utf-8")
    assert findings(path, RULE) == []  # lane -1 (radius 5.75 m) passes; lane 1 is not placed
    assert "lane-id-sequence" in {f.name for f in check(path).findings}


def test_a_lane_whose_border_folds_is_border_folds_finding_only():
    """Radius 2 m, lane 1 reaching 3.5 m to the left: its outer border folds (border-folds), and the 0.25 m radius of
    its centre is that same defect, not a second one; lane -1 (outside the curve, radius 3.75 m) is still reported."""
    found = findings(fixture("border-folds", "fail.xodr"), RULE)
    assert [(f.road, f.lane) for f in found] == [("1", -1)]
