"""``check`` over the 128 third-party corpus maps: no crash, and the findings on a few maps, verified by reading them.

The whole run's time is printed (``-s`` shows it); the acceptance bound (under a minute for all 128) is not asserted,
tests never depend on timing.
"""

from __future__ import annotations

import pytest

from tests.conftest import corpus_files
from xodrcheck.check import check

pytestmark = [pytest.mark.corpus, pytest.mark.slow]

FILES = corpus_files()


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_no_crash(corpus_dir, path):
    """No rule crashes or runs out of time, and every finding that names a place (a road and an s) says where it is in
    x and y (issue 18: 581 of the corpus's 1,319 errors had no x)."""
    report = check(path)
    assert [f for f in report.findings if f.code in ("X900", "X901")] == []
    assert report.rules_run
    unplaced = [f for f in report.findings if f.road is not None and f.s is not None and (f.x is None or f.y is None)]
    assert unplaced == []


#: The non-geometric rules (schema, reference, road-link and lane topology, junction topology, redundant records).
TOPOLOGY = ("S", "R", "K0", "L0", "J0", "G9")

#: Codes that fire on a few maps, each checked by reading the map (see the comments).
EXPECTED = {
    # Only collinear line pairs and constant elevation records repeated (redundant-record, an info).
    "carla-towns/OpenDrive/Town01.xodr": {"G901"},
    # Road 13 (15 µm long) and road 14 both claim junction 678 as predecessor; 678 has no connection from 14 (K001).
    # Lanes of type none and sidewalks end at full width without links (L010); road 6 lane 2 / road 5 lane 2 one-way
    # link (L011); road 69 lane 1 (driving) into junction 793 has no laneLink (J005). Road 69's left sidewalk and
    # shoulders continue road 70's right ones end-to-start: no direction of travel, no L012. Junction 825 joins only
    # roads 23 and 24 (connecting road 827 one way, 828 the other): no road has two possible successors there, so a
    # junction is not needed (J019, when_to_use). No route reaches two driving lanes (L041): road 69 lane -1, out of
    # junction 793, which has no connection with road 69 at all, and road 84 lane 6 (road 84 is 1.3 mm long), which no
    # connecting road of junction 268 leads into.
    "carla-towns/OpenDrive/Town03.xodr": {"G901", "J005", "J019", "K001", "L010", "L011", "L041"},
    # Connection 2: incoming 103, connecting 151 contactPoint "start", but 151 starts at road 101 (J002); lane 1 of
    # section s=0.1 of road 103 narrows to 1.5 m and has no successor (L010); lanes link across road ends that have no
    # road link (R015, Annex F road.lane.link.no_link); <geoReference> stands beside <header>, 1.4 wants it inside
    # (S001); repeated laneOffset records (G901); roads 101 and 102 start in junction 1 yet their lanes name
    # predecessors (L024, Annex F no_link); road 103 lists its left lanes 1, 2 (L017, a warning).
    "ika-roadgeneration/test/gt/junction_ma.xodr": {"G901", "J002", "L010", "L017", "L024", "R015", "S001"},
    # Connection 2 links lane -1 of road 2 to lane -3 of road 4, which has only lane -1 (R012); 1.6 connections list
    # both directions of bidirectional connecting roads (J004 infos); empty <link/> in lanes of roads 0, 1, 2 (L024).
    "esmini/EnvironmentSimulator/Unittest/xodr/highway_merge.xodr": {"J004", "L024", "R012"},
    # A 1.7 file: connecting roads 100 and 101 each in two connections (J007); lane 2 of road 1 closes to zero width
    # but has a successor, lane 2 of road 2 opens from zero with a predecessor (L013); road 3 lane 2 into the junction
    # unlinked (J005); laneLinks from lanes leaving the junction (J004); empty <link/> in roads 3 and 4 (L024).
    "esmini/resources/xodr/parking_demo.xodr": {"J004", "J005", "J007", "L013", "L024"},
    # Road 2 lane -3's successor is lane 2 of road 1 (should be 3), and road 1 lane 3 is not returned (L011); so lane
    # 2 of road 1 leads into -3 and -2 while -3 also continues lane 3 (L025); centre lanes with an empty <link/> (L024).
    "esmini/EnvironmentSimulator/Unittest/xodr/straight_2x100m_opposite.xodr": {"L011", "L024", "L025"},
    # Centre lanes with <width> records (L002); every lane's <link/> is empty (L024).
    "esmini/EnvironmentSimulator/Unittest/xodr/mixed_roads.xodr": {"L002", "L024"},
}


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_rules_that_fire_on_known_maps(corpus_dir, name):
    report = check(corpus_dir / name, select=TOPOLOGY)
    assert {f.code for f in report.findings} == EXPECTED[name]
