"""Interoperability acceptance of roundabouts (issue 28): they load in the tools people use as roundabouts.

Maps, made once per module: single roundabouts (``junctionart intersection --roundabout``: 3 to 6 arms, one and two
circulating lanes, mini to large, right- and left-hand traffic, OpenDRIVE 1.8 and 1.7), generated maps of held-out
seeds with ``roundabout_probability`` 1 (two-lane, random-lane, left-hand traffic, the scenario profile) and the
control-line example ``examples/roundabouts.json``. Each must pass:

* ``xodrcheck.check``: no error-level finding;
* ASAM ``asam-qc-opendrive``: no error-level issue and no checker ending in status "error";
* SUMO ``netconvert``: exit 0, and the network holds a ``<roundabout>`` for every roundabout of the map, its edges the
  ring roads (SUMO recognises a roundabout from the file's geometry and links, ``--roundabouts.guess``, on by default);
* CARLA's parser: loads the map, and a waypoint walk (``Waypoint.next``, 1 m steps) from the middle of a ring road,
  keeping to the ring at every fork, goes round the ring and back to its start: a full turn round the centre (within
  5 degrees), never more than 0.5 m nearer or further from it (in left-hand traffic too: CARLA reads the roads'
  ``rule`` and walks lane 1 of a ring road along it).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from pathlib import Path

import pytest
from lxml import etree

import junctionart as ja
from junctionart import controllines
from junctionart.intersection import IntersectionSpec, LegSpec, build
from junctionart.intersections.model import Layout
from junctionart.params import Params, TrafficRule
from tests.interop.asam_harness import AsamRun
from tests.interop.tools import asam_problems, carla, run_netconvert, start_asam, xodrcheck_errors
from xodrcheck.check import check

pytestmark = pytest.mark.slow  # part of the full suite (CI); left out by -m "not slow"

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

#: Single roundabouts: (arm headings, lanes in and out, median, outer radius, ring lanes, traffic rule, version).
SINGLES = [
    ((0, 120, 240), (1, 1), False, 10.0, 1, "RHT", "1.8"),
    ((0, 90, 180, 270), (1, 1), True, 16.0, 1, "RHT", "1.8"),
    ((0, 80, 170, 260), (2, 2), True, 30.0, 2, "RHT", "1.7"),
    ((0, 72, 144, 216, 288), (2, 1), False, 22.0, 1, "RHT", "1.8"),
    ((10, 70, 130, 190, 250, 310), (1, 2), False, 34.0, 2, "RHT", "1.8"),
    ((0, 100, 220), (1, 1), False, 14.0, 1, "LHT", "1.8"),
]
#: Generated maps: (Params keywords, held-out seed).
GENERATED = [
    ({"roundabout_probability": 1.0}, 7001),
    ({"roundabout_probability": 1.0}, 7002),
    ({"roundabout_probability": 1.0, "randomize_lanes": True, "width": 1000, "height": 1000}, 7003),
    ({"roundabout_probability": 1.0, "randomize_lanes": True, "curved_roads": True}, 7004),
    ({"roundabout_probability": 1.0, "traffic_rule": "LHT"}, 7005),
    ({"profile": "scenario", "roundabout_probability": 1.0, "randomize_lanes": True}, 7006),
]


@dataclass(frozen=True)
class Case:
    path: Path
    layout: Layout
    rule: str


@pytest.fixture(scope="module")
def cases(tmp_path_factory) -> list[Case]:
    folder = tmp_path_factory.mktemp("roundabouts")
    out = []
    for k, (headings, (n_in, n_out), median, radius, lanes, rule, version) in enumerate(SINGLES):
        legs = tuple(LegSpec(h, n_in, n_out, median) for h in headings)
        spec = IntersectionSpec(
            legs, traffic_rule=TrafficRule(rule), version=version, roundabout_radius=radius, roundabout_lanes=lanes
        )
        layout = _layout_of(spec)
        out.append(Case(ja.write(build(spec).document, folder / f"single-{k}.xodr", version), layout, rule))
    for kwargs, seed in GENERATED:
        params = Params.create(**kwargs)
        result = ja.generate_layout(params, seed)
        out.append(
            Case(ja.write(result.document, folder / f"map-{seed}.xodr"), result.layout, params.traffic_rule.value)
        )
    lines = controllines.load(EXAMPLES / "roundabouts.json")
    result = ja.generate_layout(Params(), 1, lines)
    out.append(Case(ja.write(result.document, folder / "roundabouts-json.xodr"), result.layout, "RHT"))
    return out


def _layout_of(spec: IntersectionSpec) -> Layout:
    import numpy as np

    from junctionart import intersections
    from junctionart.intersection import network

    return intersections.build(network(spec), spec.params(), np.random.default_rng(0))


@pytest.fixture(scope="module")
def asam_run(cases, tmp_path_factory) -> AsamRun:
    return start_asam([c.path for c in cases], tmp_path_factory.mktemp("asam"))


def test_every_map_holds_roundabouts(cases, asam_run):
    """(Requests ``asam_run`` so that ASAM starts before the other tools' tests run.)"""
    counts = [len(c.layout.roundabouts) for c in cases]
    assert all(n >= 1 for n in counts) and sum(counts) >= 20, counts


def test_xodrcheck_finds_no_error(cases):
    bad = []
    for c in cases:
        bad += xodrcheck_errors(c.path.name, check(c.path))
    assert bad == []


def test_sumo_builds_the_net_with_every_roundabout(cases, tmp_path):
    bad = []
    for c in cases:
        proc, out = run_netconvert(c.path, tmp_path)
        rings = etree.parse(str(out)).getroot().findall("roundabout") if out.is_file() else []
        want = sorted(len(r.ring_roads) for r in c.layout.roundabouts)
        got = sorted(len(r.get("edges").split()) for r in rings)
        if proc.returncode != 0 or got != want:
            bad.append(f"{c.path.name}: exit {proc.returncode}, SUMO roundabouts of {got} edges, the map's {want}")
    assert bad == []


def test_carla_walks_round_every_roundabout_back_to_its_start(cases):
    bad = []
    for c in cases:
        walks = []
        for ring in c.layout.roundabouts:
            road = c.layout.roads[ring.ring_roads[0]]
            walks.append(
                {"road": road.index + 1, "lane": -1 if c.rule == "RHT" else 1, "s": road.length / 2}
                | {"centre": list(ring.centre), "step": 1.0}
                | {"steps": int(4 * math.pi * ring.radius) + 50}
            )
        result = carla(c.path, distance=5.0, walks=walks)
        if not result.loaded:
            bad.append(f"{c.path.name}: CARLA did not load it ({result.error})")
            continue
        for ring, walk, asked in zip(c.layout.roundabouts, result.walks, walks):
            problem = _round_trip(walk, ring.centre, str(asked["road"]))
            if problem:
                bad.append(f"{c.path.name}, ring at {ring.centre[0]:.0f},{ring.centre[1]:.0f}: {problem}")
    assert bad == []


def _round_trip(walk, centre: tuple[float, float], start: str) -> str:
    """What is wrong with a ring walk (empty when it went once round and back onto its start road)."""
    if len(walk) < 10:
        return f"{len(walk)} waypoints"
    if walk[-1].road_id != start or len({p.road_id for p in walk}) < 4:
        return f"ended on road {walk[-1].road_id} after roads {[p.road_id for p in walk[:: max(1, len(walk) // 12)]]}"
    angles = [math.atan2(p.y - centre[1], p.x - centre[0]) for p in walk]
    turned = sum((b - a + math.pi) % (2 * math.pi) - math.pi for a, b in itertools.pairwise(angles))
    if abs(abs(turned) - 2 * math.pi) > math.radians(5.0):
        return f"turned {math.degrees(turned):.0f} deg round the centre"
    reach = [math.hypot(p.x - centre[0], p.y - centre[1]) for p in walk]
    if max(reach) - min(reach) > 0.5:
        return f"left the ring: {min(reach):.2f} to {max(reach):.2f} m from its centre"
    return ""


def test_asam_reports_no_error_and_no_checker_error(cases, asam_run):
    reports = asam_run.reports()
    bad = []
    for c in cases:
        bad += asam_problems(c.path.name, reports[c.path])
    assert bad == []
