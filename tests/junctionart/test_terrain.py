"""Terrain (issue 16): smooth elevation within the documented grade and vertical-curve limits, planar junctions,
continuous z and grade at every link, read back from the written file."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from lxml import etree

import junctionart as ja
from junctionart.params import Params, Terrain
from junctionart.scenario.terrain import LIMITS, profile, rise_bound
from junctionart.writer import to_bytes, write
from xodrcheck.check import check
from xodrcheck.config import Config

#: Generated maps are judged as junctionart guarantees them: every rule at its own severity.
GENERATOR = Config(profile="generator")


@pytest.fixture(scope="module")
def hilly(tmp_path_factory) -> list[Path]:
    folder = tmp_path_factory.mktemp("hilly")
    out = []
    for seed in range(4):
        p = Params.create("scenario", terrain="hilly", randomize_lanes=True, curved_roads=True, width=800, height=800)
        p = p.with_(fork_probability=0.0, ramp_probability=0.0)  # their joints follow the road's grade (test_splits)
        out.append(write(ja.generate(p, seed), folder / f"{seed}.xodr"))
    return out


def _profiles(path: Path) -> dict[str, tuple[dict, list[tuple[float, ...]]]]:
    """Road id -> (road attributes and links, elevation records (s, a, b, c, d)) as written."""
    root = etree.parse(str(path)).getroot()
    out = {}
    for road in root.iter("road"):
        recs = [tuple(float(e.get(k)) for k in "sabcd") for e in road.iterfind("elevationProfile/elevation")]
        links = {}
        for kind in ("predecessor", "successor"):
            el = road.find(f"link/{kind}")
            if el is not None:
                links[kind] = (el.get("elementType"), el.get("elementId"), el.get("contactPoint"))
        out[road.get("id")] = ({**road.attrib, **links}, recs)
    return out


def _z(recs, s: float) -> tuple[float, float, float]:
    """z, dz/ds and d2z/ds2 at ``s``."""
    s0, a, b, c, d = [r for r in recs if r[0] <= s + 1e-9][-1]
    u = s - s0
    return a + u * (b + u * (c + u * d)), b + u * (2 * c + 3 * d * u), 2 * c + 6 * d * u


def test_grades_and_vertical_curves_within_the_hilly_limits(hilly):
    grade, radius = LIMITS[Terrain.HILLY]
    steepest = sharpest = 0.0
    heights = []
    for path in hilly:
        for attrs, recs in _profiles(path).values():
            for s in np.linspace(0.0, float(attrs["length"]), 101):
                z, g, k = _z(recs, s)
                heights.append(z)
                steepest, sharpest = max(steepest, abs(g)), max(sharpest, abs(k))
    assert steepest <= grade + 1e-12 and sharpest <= 1.0 / radius + 1e-12
    assert steepest > 0.5 * grade and max(heights) - min(heights) > 10.0  # the limits bind: the map is really hilly


def test_junctions_are_planar_and_z_and_grade_continuous_at_every_link(hilly):
    links = 0
    for path in hilly:
        roads = _profiles(path)
        by_junction: dict[str, set[float]] = {}
        for attrs, recs in roads.values():
            if attrs["junction"] == "-1":
                continue
            assert len(recs) == 1 and recs[0][2:] == (0.0, 0.0, 0.0)  # flat
            by_junction.setdefault(attrs["junction"], set()).add(recs[0][1])
            for kind, at in (("predecessor", 0.0), ("successor", float(attrs["length"]))):
                _, other_id, contact = attrs[kind]
                other_attrs, other = roads[other_id]
                z0, g0, _ = _z(recs, at)
                z1, g1, _ = _z(other, 0.0 if contact == "start" else float(other_attrs["length"]))
                assert abs(z0 - z1) < 1e-9 and abs(g0) < 1e-12 and abs(g1) < 1e-12
                links += 1
        assert all(len(zs) == 1 for zs in by_junction.values())
    assert links > 200


def test_hilly_maps_clean_and_valid(hilly, schema18):
    for path in hilly[:3]:
        assert list(schema18.iter_errors(str(path))) == []
        report = check(path, GENERATOR)
        assert [f.code for f in report.findings if f.severity.name in ("ERROR", "WARNING")] == []


def test_profile_and_bound():
    (c,) = profile(2.0, 5.0, 100.0)
    assert (c.a, c.b) == (2.0, 0.0)
    assert c.a + 100.0 * (c.b + 100.0 * (c.c + 100.0 * c.d)) == pytest.approx(5.0)
    assert rise_bound(300.0, Terrain.HILLY) == pytest.approx(0.08 * 300 / 1.5)
    assert rise_bound(30.0, Terrain.HILLY) == pytest.approx(900 / 3600)


def test_terrain_changes_heights_only():
    """Terrain draws from its own stream: the plan view and lanes are those of the flat map; flat is the paper's."""
    flat = ja.generate(Params.create("scenario"), 1)
    hilly = ja.generate(Params.create("scenario", terrain="hilly"), 1)
    assert [r.__class__(**{**r.__dict__, "elevation": ()}) for r in hilly.roads] == [
        r.__class__(**{**r.__dict__, "elevation": ()}) for r in flat.roads
    ]
    assert any(r.elevation[0].a != 0.0 for r in hilly.roads)
    assert to_bytes(ja.generate(Params(), 1)) == to_bytes(ja.generate(Params.create(terrain="flat"), 1))
    with pytest.raises(ja.ParamsError, match="terrain"):
        Params.create(terrain="alpine")


def test_xodrcheck_info_reports_grade_and_link_steps_within_the_limits(hilly):
    """The acceptance figures as ``xodrcheck info`` reports them: max grade <= 8 %, largest z step at a link ~ 0."""
    from xodrcheck.analysis.elevation import elevation_info
    from xodrcheck.reader import read

    for path in hilly:
        e = elevation_info(read(path).document)
        assert 0.04 < e.max_grade <= LIMITS[Terrain.HILLY][0] + 1e-12
        assert e.max_link_step < 1e-9 and e.links > 50
        assert e.max_z - e.min_z > 5.0
