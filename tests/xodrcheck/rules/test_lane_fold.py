"""Rule lane-fold: a 3.5 m lane inside a 2 m radius folds over itself; inside a 20 m radius it does not."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check

RULE = "lane-fold"


def test_lane_wider_than_the_radius_folds():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s) == ("1", -1, 0.0)
    assert f.line == line_of(path, '<road id="1"')
    assert "folds over itself" in f.message


def test_a_road_winding_round_itself_is_named_not_united():
    """A 3 km arc of radius 0.5 m (issue 31): each lane says it winds round itself 955 times, and the union of its
    triangles (minutes of GEOS work) is never made: the footprint is left empty."""
    from xodrcheck.mesh.footprint import OverlapIndex
    from xodrcheck.reader import read
    from xodrcheck.support import work

    path = fixture(RULE, "fail-winding.xodr")
    found = findings(path, RULE)
    assert sorted(f.lane for f in found) == [-3, -2, -1, 1, 2, 3]
    for f in found:
        assert "winds round itself" in f.message and "955 full circles" in f.message, f.message
        assert "tolerance max_turns" in f.message and (f.road, f.section_s, f.s) == ("1", 0.0, 0.0)
    with work.counting() as done:
        index = OverlapIndex(read(path).document)
    assert sorted(round(t) for t in index.footprints.winding.values()) == [955] * 6
    assert all(index.footprints.polygons[i].is_empty for i in index.footprints.winding)
    assert done["union coordinates"] == 0


def test_winding_is_judged_against_max_turns():
    """The generator's map with a line turned into a 0.5 m circle winds 36 times: over the default 10 turns it is
    named; with max_turns=50 its lanes are united and reported as folds with their area."""
    from xodrcheck.config import Config, Tolerances

    path = fixture(RULE, "fail-winding-generated.xodr")
    found = findings(path, RULE)
    assert [(f.lane, "winds round itself" in f.message, "36 full circles" in f.message) for f in found] == [
        (-1, True, True),
        (1, True, True),
    ]
    report = check(path, Config(tolerances=Tolerances(max_turns=50)), select=("O002",))
    assert sorted((f.lane, "covers" in f.message and "twice" in f.message) for f in report.findings) == [
        (-1, True),
        (1, True),
    ]
