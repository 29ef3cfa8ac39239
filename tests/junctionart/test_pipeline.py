"""End to end over many seeds: written maps read back by xodrcheck without error, pass `xodrcheck check`, and keep
the geometric promises measured through xodrcheck's own geometry."""

from __future__ import annotations

import math
import re

import pytest

import junctionart as ja
from junctionart.params import Params, TrafficRule
from xodrcheck.config import Config

from .geomcheck import measure
from .overlap import overlaps

#: Generated maps are judged as junctionart guarantees them: every rule at its own severity.
GENERATOR = Config(profile="generator")

TOL_GAP = 1e-6
TOL_HDG = 1e-6

SMALL = [
    (
        Params(
            randomize_lanes=bool(seed % 2),
            curved_roads=seed % 3 == 0,
            traffic_rule=TrafficRule.LHT if seed % 5 == 4 else TrafficRule.RHT,
        ),
        seed,
    )
    for seed in range(20)
]
BIG = [
    (Params(width=1000, height=1000, randomize_lanes=r, curved_roads=True), seed)
    for seed, r in ((100, False), (101, True), (102, True))
]


def _assert_map(params: Params, seed: int, tmp_path, version: str = "1.8") -> None:
    import xodrcheck

    path = ja.write(ja.generate(params, seed), tmp_path / f"m{seed}.xodr", version)
    m = measure(path)
    assert m.read_errors == ()
    assert m.links > 0
    assert m.max_gap < TOL_GAP, f"seed {seed}: contact points {m.max_gap} m apart"
    assert m.max_heading < TOL_HDG, f"seed {seed}: heading kink {m.max_heading} rad"
    assert m.min_radius >= params.min_turn_radius, f"seed {seed}: radius {m.min_radius}"
    assert m.min_lane_radius >= params.min_turn_radius, f"seed {seed}: lane centre radius {m.min_lane_radius}"
    assert overlaps(path) == [], "road bodies overlap where the map does not connect them"
    report = xodrcheck.check(path, GENERATOR)
    errors = [f"{f.code} {f.message}" for f in report.findings if f.severity.name == "ERROR"]
    assert report.ok, errors[:5]


@pytest.mark.parametrize("params, seed", SMALL, ids=[f"500m-{s}" for _, s in SMALL])
def test_500m_maps(params, seed, tmp_path):
    _assert_map(params, seed, tmp_path)


@pytest.mark.slow
@pytest.mark.parametrize("params, seed", BIG, ids=[f"1km-{s}" for _, s in BIG])
def test_1km_maps(params, seed, tmp_path):
    _assert_map(params, seed, tmp_path)


def test_17_output_checks_too(tmp_path):
    _assert_map(Params(randomize_lanes=True, version="1.7"), 3, tmp_path, "1.7")


def test_no_discarded_maps():
    """Tries equal maps: every seed produces a map on the first try, including dense random-lane ones."""
    params = Params(randomize_lanes=True, curved_roads=True, width=700, height=700)
    maps = [ja.generate_layout(params, seed) for seed in range(10)]
    assert all(r.layout.junctions for r in maps)
    legs = {j.legs for r in maps for j in r.layout.junctions}
    assert {3, 4} <= legs
    assert all(math.isfinite(rp.length) for r in maps for rp in r.layout.roads)


def test_bytes_do_not_depend_on_the_hash_seed(tmp_path):
    """The same seed gives the same file in separate processes with different string-hash seeds."""
    import os
    import subprocess
    import sys

    outs = []
    for hs in ("1", "2"):
        out = tmp_path / f"h{hs}.xodr"
        env = dict(os.environ, PYTHONHASHSEED=hs)
        subprocess.run(
            [
                sys.executable,
                "-m",
                "junctionart",
                "generate",
                "--seed",
                "9",
                "--randomize-lanes",
                "true",
                "--curved-roads",
                "true",
                "-q",
                "-o",
                str(out),
            ],
            check=True,
            env=env,
        )
        outs.append(out.read_bytes())
    assert outs[0] == outs[1]


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_short_tapers_and_big_turn_radius_keep_every_lane_centre_above_the_bound(seed, tmp_path):
    """Lane splits and merges are lengthened until no lane centre bends tighter than min_turn_radius."""
    params = Params(
        randomize_lanes=True,
        curved_roads=True,
        taper_length=5.0,
        min_turn_radius=12.0,
        turn_lane_probability=0.8,
        lane_distribution_side=(0.1, 0.2, 0.3, 0.4),
    )
    path = ja.write(ja.generate(params, seed), tmp_path / "t.xodr")
    m = measure(path)
    assert m.min_lane_radius >= 12.0
    assert m.min_radius >= 12.0


def test_a_step_in_height_at_a_link_fails_the_check(tmp_path):
    """A generated map with road 1 raised by 5 m (its ``<elevation a="5.0">``) fails: every road touching road 1 meets
    it 5 m lower (issue 18: `check` used to say 0 errors)."""
    from lxml import etree

    import xodrcheck

    path = ja.write(ja.generate(Params(), 0), tmp_path / "m.xodr")
    assert xodrcheck.check(path, GENERATOR).ok
    tree = etree.parse(str(path))
    (elevation,) = tree.getroot().findall("road[@id='1']/elevationProfile/elevation")
    elevation.set("a", "5.0")
    tree.write(str(path))
    report = xodrcheck.check(path, GENERATOR)
    steps = [f for f in report.findings if f.code == "K104"]
    assert not report.ok
    assert steps and all(f.severity.name == "ERROR" for f in steps)
    assert all("steps by 5 m" in f.message for f in steps), [f.message for f in steps]
    assert all(re.search(r"\broad 1\b", f.message) for f in steps)  # every step is at one of road 1's ends
