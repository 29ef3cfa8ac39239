"""Rule lane-id-sequence: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "lane-id-sequence"


def test_gap_in_right_lane_ids():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert sorted(f.road for f in found) == ["1", "2"]
    assert all(f.lane == -2 and "skip id(s) -2" in f.message for f in found)


def test_a_huge_lane_id_is_reported_as_one_run_of_missing_ids(tmp_path):
    """A damaged id of -10**12 once made the rule list every missing id (the kernel killed a fuzzing run at 24 GB)."""
    text = fixture(RULE, "fail.xodr").read_text(encoding="utf-8")
    huge = tmp_path / "huge.xodr"
    huge.write_text(text.replace('id="-3"', 'id="-1000000000000"', 1), encoding="utf-8")
    found = [f for f in findings(huge, RULE) if "1000000000000" in f.message or "999999999999" in f.message]
    assert found, [f.message for f in findings(huge, RULE)]
    (f,) = found
    assert f.lane == -2 and "skip id(s) -2 to -999999999999 (999999999998 ids)" in f.message
    assert len(f.message) < 300


def testid_gaps_are_listed_by_runs():
    from xodrcheck.rules.lane import gap_text, id_gaps

    assert id_gaps([1, 2, 3]) == []
    assert id_gaps([2, 5, 6, 9]) == [(1, 1), (3, 4), (7, 8)]
    assert gap_text(id_gaps([2, 5, 6, 9]), -1) == "-1, -3 to -4, -7 to -8 (5 ids)"
    assert gap_text(id_gaps([2]), 1) == "1"
