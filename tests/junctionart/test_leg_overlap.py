"""Two legs of one junction may meet only at its edge: a leg bent back along its neighbour overlaps it (xodrcheck
O001, "both are legs of junction N, not linked to each other"), and stage 3 must repair that like any other overlap.

The case: urban roadside lanes make a bend next to a junction too sharp, the bend is straightened, and the leg left
behind runs back from the junction's side along another of its legs for some 200 m (390 m2 of shared lanes). The
overlap test used to let any two roads sharing an end node touch, so it never compared them."""

from __future__ import annotations

import junctionart as ja
from junctionart import controllines
from junctionart.params import Params
from junctionart.writer import write
from xodrcheck.check import check
from xodrcheck.config import Config

from .overlap import overlaps

#: Generated maps are judged as junctionart guarantees them: every rule at its own severity.
GENERATOR = Config(profile="generator")

#: five crossing control lines (one pair); with the scenario profile, random lanes and seed 15 the map had the overlap
LINES = {
    "lines": [
        {"id": "l0", "points": [[1471.1, 619.9], [220.5, 1216.6]], "group": 0},
        {"id": "l1", "points": [[1588.7, 236.8], [1140.3, 1320.5]], "group": 1},
        {"id": "l2", "points": [[1472.9, 197.4], [146.9, 1580.6]], "group": 2},
        {"id": "l3", "points": [[186.8, 282.9], [919.9, 714.0]], "group": 3},
        {"id": "l4", "points": [[1200.6, 304.9], [502.1, 499.6]], "group": 4},
    ],
    "pairs": [["l0", "l1"]],
}


def test_a_leg_bent_back_along_its_neighbour_is_removed(tmp_path):
    lines = controllines.parse(LINES)
    for overpass in (0.5, 0.0):
        p = Params.create("scenario", randomize_lanes=True, overpass_probability=overpass)
        result = ja.generate_layout(p, 15, lines)
        path = write(result.document, tmp_path / f"o{overpass}.xodr")
        report = check(path, GENERATOR)
        assert [(f.code, f.message) for f in report.findings if f.severity.name == "ERROR"] == []
        assert overlaps(path) == [], "two roads overlap where the map does not connect them"
        assert any("overlapped another road" in r for r in result.layout.repairs), result.layout.repairs


def test_the_paper_profile_on_the_same_lines_is_unchanged():
    """Without roadside lanes the bend fits: no leg runs back, nothing is removed (the paper's map as before)."""
    result = ja.generate_layout(Params(randomize_lanes=True), 15, controllines.parse(LINES))
    assert not any("overlapped" in r for r in result.layout.repairs)
    assert len(result.layout.roads) == 16 and len(result.layout.junctions) == 8
