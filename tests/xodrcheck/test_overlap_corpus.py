"""The overlap rules on the CARLA towns and esmini maps of the corpus: every finding listed, each with the reason it is
true, checked by rendering the place (lane footprints coloured per road, heights annotated) and reading the file.

Maps not listed give no overlap finding at all.
"""

from __future__ import annotations

import re

import pytest

from tests.conftest import corpus_files, corpus_root
from xodrcheck.check import check

pytestmark = [pytest.mark.corpus, pytest.mark.slow]

FILES = [p for p in corpus_files() if p.relative_to(corpus_root()).parts[0] in ("carla-towns", "esmini")]

_STAR = "esmini/EnvironmentSimulator/Unittest/xodr/star.xodr"

#: file -> {(code, road, other road or lane)}.
EXPECTED: dict[str, set[tuple[str, str, str]]] = {
    # The sidewalk (lane -3, 4 m) on the inside of the right-hand corner of road 2: lanes -1 to -3 add up to 8.3 m
    # while the curve's radius drops to 7.5 m (curvature -0.133), so the sidewalk's outer border passes the curve's
    # centre and runs backwards: a fold of 2.6 m2, visible as a notch in the corner's inner edge.
    "carla-towns/OpenDrive/Town02.xodr": {("O002", "2", "-3")},
    # Town03 has roads made only of sidewalks and lanes of type none (42, 58, 59, 61, 63, 73, 28, 30, ...), laid
    # across each other at z = 0 without links or junctions: road 42 bends south through the 59/60/61 chain, 58 and
    # 59 run through 81, 61 and 63 through 73, 28 and 30 through 63, and the corner sidewalks of 23 and 24 reach into
    # 28. All roadside lanes only, hence warnings.
    "carla-towns/OpenDrive/Town03.xodr": {
        ("O004", "23", "28"),
        ("O004", "24", "28"),
        ("O004", "28", "63"),
        ("O004", "30", "63"),
        ("O004", "42", "61"),
        ("O004", "42", "59"),
        ("O004", "58", "81"),
        ("O004", "59", "81"),
        ("O004", "61", "73"),
        ("O004", "63", "73"),
        # Road 83 (13 m of the north-south road 82-83-84: parking, sidewalk and none lanes) lies across the
        # east-west S-bend connecting roads 285 and 288 of junction 268, which links roads 0 and 74; 83 is neither in
        # junction 268 nor one of its legs, so ~72 m2 of driving lane run through it.
        ("O003", "285", "83"),
        ("O003", "288", "83"),
        # Roads that share a junction but are not linked (road.no_overlap_outside_junction, overlap_inside_junction),
        # drawn: road 48 (parking, none and driving lanes), a leg of junction 298, lies wholly across the junction's
        # east-west connecting road 307 (142 m2); leg 69 of junction 793 runs 3.5 m past the start of connecting
        # roads 798, 806 and 807 (46, 17 and 17 m2); legs 27 and 93 leave one point as a fork and share 3.1 m2 of
        # shoulder and driving lane before they part; leg 64's driving-lane corner lies on leg 77's sidewalk (1.6 m2).
        ("O001", "27", "93"),
        ("O001", "64", "77"),
        ("O003", "307", "48"),
        ("O003", "798", "69"),
        ("O003", "806", "69"),
        ("O003", "807", "69"),
    },
    # Leg 21 of junction 386 curves into the end of leg 3, driving lanes over driving lanes (2.5 m2), drawn.
    "carla-towns/OpenDrive/Town04.xodr": {("O001", "3", "21")},
    # Shoulders of roads 7/21 and 25/67 cross at the outer corners of two T-shaped meetings (0.7 and 2.0 m2, z = 0).
    # Connecting road 219 of junction 218 starts 0.6 m inside its leg 44 (10.1 m2 of driving lanes) and connecting
    # road 202's first metres cross the shoulder of leg 36 (0.7 m2), drawn; neither leg is linked to them.
    "carla-towns/OpenDrive/Town06.xodr": {
        ("O004", "7", "21"),
        ("O004", "25", "67"),
        ("O003", "202", "36"),
        ("O003", "219", "44"),
    },
    # Town07's dead-end side roads (farm entrances) stop on the main roads without a link: road 30 ends 2 m into
    # junction 780 (over connecting road 787) and its sidewalk corners overlap driving lane -1 of roads 28 and 29;
    # road 54 likewise over connecting road 779 and roads 27/28; road 48's end lies on connecting road 444 of
    # junction 440; road 2 ends over connecting road 793 and the ends of roads 33 and 34. Road 17's and 65's
    # sidewalks cross at a corner. Where a pair's driving lanes overlap (O001), its roadside overlap (O004) is the
    # same place and is not reported beside it.
    "carla-towns/OpenDrive/Town07.xodr": {
        ("O001", "2", "33"),
        ("O004", "2", "34"),
        ("O004", "17", "65"),
        ("O001", "27", "54"),
        ("O001", "28", "54"),
        ("O001", "28", "30"),
        ("O001", "29", "30"),
        ("O003", "444", "48"),
        ("O003", "779", "54"),
        ("O003", "787", "30"),
        ("O003", "793", "2"),
    },
    # Each spoke of the star is three coincident roads from the same start point with slopes 0 and +-0.61: they share
    # their whole plan view and are within 4.5 m of each other in height for their first metres.
    _STAR: {
        ("O001", a, b)
        for first in range(0, 24, 3)
        for a, b in ((first, first + 1), (first, first + 2), (first + 1, first + 2))
        for a, b in [(str(a), str(b))]  # named in file order (roads 0, 1, 2, ... there)
    },
    # Road 0 (z = 3 m) overhangs road 1 (z = 0) by 3 m: 10.5 m2 of lane -1 with only 3 m of clearance.
    "esmini/EnvironmentSimulator/Unittest/xodr/two_roads_overhang.xodr": {("O001", "0", "1")},
}

_PAIR = re.compile(r"road (\S+) and road (\S+) overlap")


def overlap_findings(path) -> set[tuple[str, str, str]]:
    out = set()
    for f in check(path, select=("overlap",)).findings:
        assert f.code != "X900", f.message
        if f.code == "O002":
            out.add((f.code, f.road, str(f.lane)))
        else:
            a, b = _PAIR.search(f.message).groups()
            assert f.road == a
            out.add((f.code, a, b))
    return out


def test_the_listed_maps_exist(corpus_dir):
    names = {str(p.relative_to(corpus_dir)) for p in FILES}
    assert set(EXPECTED) <= names
    assert len(FILES) > 80


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_overlap_findings_are_the_listed_ones(corpus_dir, path):
    name = str(path.relative_to(corpus_dir))
    assert overlap_findings(path) == EXPECTED.get(name, set())


def test_overlaps_in_blocks_of_pairs_are_the_same(monkeypatch: pytest.MonkeyPatch):
    """Bounded memory: the lane-strip pairs are intersected a block at a time; any block size gives the same list."""
    from xodrcheck.mesh import footprint
    from xodrcheck.reader import read

    document = read(corpus_root() / "carla-towns/OpenDrive/Town03.xodr").document
    index = footprint.OverlapIndex(document, 0.1)
    whole = index.overlaps(0.01, 2.0)
    monkeypatch.setattr(footprint, "PAIR_BLOCK", 7)
    assert index.unrelated_pairs.shape[1] > 10 * 7 and len(whole) > 5
    assert index.overlaps(0.01, 2.0) == whole
