"""Rule lane-direction-reverses-traffic: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "lane-direction-reverses-traffic"


def test_all_drivable_lanes_reversed():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.line) == ("1", 1, line_of(path, '<lane id="1"'))
    assert "(1, -1)" in f.message and "RHT/LHT" in f.message


def test_a_contraflow_lane_is_fine():
    assert findings(fixture(RULE, "pass.xodr"), RULE) == []


def test_the_first_lane_the_file_lists_is_named(tmp_path):
    # <right> written before <left>: lane -1 is the first drivable lane listed
    lines = fixture(RULE, "fail.xodr").read_text(encoding="utf-8").splitlines()
    left = next(i for i, line in enumerate(lines) if "<left>" in line)
    right = next(i for i, line in enumerate(lines) if "<right>" in line)
    lines[left], lines[right] = lines[right], lines[left]
    path = tmp_path / "right-first.xodr"
    path.write_text("\n".join(lines), encoding="utf-8")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.line) == ("1", -1, line_of(path, '<lane id="-1"'))
    assert "(-1, 1)" in f.message
