"""Rule road-overlap: two unlinked roads crossing at one height are found; the same crossing as a 6 m bridge is not."""

import math

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "road-overlap"


def test_bridge_six_metres_above_is_no_overlap():
    (path,) = [fixture(RULE, "pass.xodr")]
    assert 'a="6.0"' in path.read_text(encoding="utf-8")  # the same plan view as fail.xodr, lifted 6 m
    assert findings(path, RULE) == []


def test_two_unlinked_roads_crossing():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.line == line_of(path, '<road id="1"')
    assert "road 1 and road 2 overlap by 49.0 m2" in f.message  # two 7 m wide roads crossing square: 7 x 7
    assert math.hypot(f.x, f.y) < 3.5 * math.sqrt(2) + 1e-6  # inside the crossing square


def test_the_pair_is_named_in_file_order_not_id_order(tmp_path):
    """Renaming the roads so that their ids sort the other way round names the same road (found by the renumbering
    property of the fuzzer: the finding moved from one road to the other)."""
    from junctionart.fuzz.transform import renumber_roads

    data = fixture(RULE, "fail.xodr").read_bytes()
    renamed = tmp_path / "renamed.xodr"
    renamed.write_bytes(renumber_roads(data, {"1": "z", "2": "a"}))
    (f,) = findings(renamed, RULE)
    assert f.road == "z" and "road z and road a overlap" in f.message


def test_two_legs_of_one_junction_overlapping():
    """Road 3 joins junction 100 from the south but runs 5.5 m into road 1, another leg: both are outside the
    junction, so they shall not overlap (sharing a junction does not allow it)."""
    path = fixture(RULE, "fail_junction_legs.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and "road 1 and road 3 overlap by 38.5 m2" in f.message  # 7 m x 5.5 m
    assert "both are legs of junction 100" in f.message


def test_a_bridge_three_metres_above_lacks_clearance():
    """pass.xodr's bridge lowered to 3 m: still an overlap, and the message says how much height is missing."""
    path = fixture(RULE, "fail_low_bridge.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "1" and "with 3.00 m between their surfaces" in f.message
    assert "(clearance 4.5 m: 1.50 m short of it as a bridge)" in f.message
    (at_grade,) = findings(fixture(RULE, "fail.xodr"), RULE)
    assert "short of it" not in at_grade.message  # roads crossing at one height: no bridge to speak of


def test_one_finding_for_two_roads_whose_drivable_and_roadside_lanes_overlap():
    """Two crossing roads with sidewalks: one O001 finding saying the sidewalks overlap too, no O004 beside it."""
    path = fixture(RULE, "fail_with_sidewalks.xodr")
    (f,) = findings(path, RULE)
    assert "their roadside lanes (no drivable lane) overlap too, by 16.0 m2" in f.message
    assert findings(path, "roadside-overlap") == []
