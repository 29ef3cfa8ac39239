"""Interoperability acceptance of forks, merges and ramps (issue 28): the maps load cleanly in the tools people use.

Maps, generated once per module: every preset of ``junctionart intersection`` (the Yosemite fork, a Y fork, a merge,
an exit and an entry ramp) with a direct and with a default junction; ``examples/forks_ramps.json`` both ways; and 16
held-out-like generated maps (seeds from 7000, 800 m, fork and ramp probability 0.6: half the paper profile with
direct junctions, half the scenario profile with default ones, some hilly, LHT, rural, OpenDRIVE 1.7). Each must pass:

* ``xodrcheck.check``: no error-level finding; each map holds the forks or ramps it was made for;
* ASAM ``asam-qc-opendrive``: no error-level issue and no checker ending in status "error";
* maps with default junctions (CARLA 0.9.16 and SUMO 1.28 read no direct junction: both refuse a connection without
  ``connectingRoad``): SUMO ``netconvert`` exits 0; CARLA's parser loads them, and from every lane feeding a fork (a
  split) CARLA's ``Waypoint.next`` reaches both branches, from both branches of a merge the road they join.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import pytest

import junctionart as ja
from junctionart import controllines
from junctionart.params import Params
from junctionart.splits.build import build
from junctionart.splits.spec import PRESETS, from_dict
from tests.interop.asam_harness import AsamRun
from tests.interop.tools import asam_problems, carla, run_netconvert, start_asam, xodrcheck_errors
from xodrcheck.analysis.metrics import Leg
from xodrcheck.check import check
from xodrcheck.model import ContactPoint
from xodrcheck.reader import read
from xodrcheck.structures import map_structures
from xodrcheck.structures.fork import fork_shape

pytestmark = pytest.mark.slow  # part of the full suite (CI); left out by -m "not slow"

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "forks_ramps.json"
#: (profile, extra parameters) of the generated maps, two seeds each
GENERATED = [
    ("paper", {}),
    ("paper", {"traffic_rule": "LHT", "median_probability": 1.0}),
    ("paper", {"version": "1.7", "curved_roads": True}),
    ("paper", {"lane_distribution_side": (0.0, 0.3, 0.5, 0.2)}),
    ("scenario", {}),
    ("scenario", {"terrain": "hilly"}),
    ("scenario", {"roadside": "rural", "traffic_rule": "LHT"}),
    ("scenario", {"version": "1.7", "junction_control": "traffic-lights"}),
]


@dataclass(frozen=True)
class Case:
    path: Path
    direct: bool
    kinds: frozenset[str]  #: what the map was made to hold


@pytest.fixture(scope="module")
def cases(tmp_path_factory) -> list[Case]:
    folder = tmp_path_factory.mktemp("splits")
    out = []
    for name, raw in PRESETS.items():
        for junction in ("direct", "default"):
            spec = from_dict({**raw, "junction": junction})
            path = ja.write(build(spec), folder / f"{name}-{junction}.xodr", spec.version)
            out.append(Case(path, junction == "direct", frozenset({raw["kind"]})))
    lines = controllines.load(EXAMPLE)
    for direct in (True, False):
        p = Params.create(randomize_lanes=True, direct_junctions=direct)
        path = ja.write(ja.generate(p, 0, lines), folder / f"example-{direct}.xodr")
        out.append(Case(path, direct, frozenset({"fork", "ramp"})))
    seed = 7000
    for profile, extra in GENERATED:
        for _ in range(2):
            p = Params.create(profile, width=800, height=800, randomize_lanes=True, **extra).with_(
                fork_probability=0.6, ramp_probability=0.6
            )
            path = ja.write(ja.generate(p, seed), folder / f"{profile}-{seed}.xodr", p.version)
            out.append(Case(path, p.direct_junctions, frozenset({"fork"})))
            seed += 1
    return out


@pytest.fixture(scope="module")
def asam_run(cases, tmp_path_factory) -> AsamRun:
    return start_asam([c.path for c in cases], tmp_path_factory.mktemp("asam"))


def test_xodrcheck_finds_no_error_and_each_map_holds_what_it_was_made_for(cases, asam_run):
    """(Requests ``asam_run`` so that ASAM starts before the other tools' tests run.)"""
    bad = []
    for c in cases:
        bad += xodrcheck_errors(c.path.name, check(c.path))
        kinds = {s.kind for s in map_structures(read(c.path).document)}
        if not c.kinds <= kinds:
            bad.append(f"{c.path.name}: holds {sorted(kinds)}, made for {sorted(c.kinds)}")
    assert len(cases) == 2 * len(PRESETS) + 2 + 2 * len(GENERATED) and bad == []


def test_sumo_builds_every_map_with_default_junctions(cases, tmp_path):
    bad = []
    for c in cases:
        if c.direct:
            continue
        proc, out = run_netconvert(c.path, tmp_path)
        if proc.returncode != 0 or not out.is_file():
            bad.append(f"{c.path.name}: netconvert exit {proc.returncode}: {proc.stderr.strip()[-300:]}")
    assert bad == []


def _walks(document) -> list[tuple[dict, set[str]]]:
    """(start, roads it must reach) for every lane feeding a split and every lane of a merge's branches."""
    out = []
    for structure in map_structures(document):
        if structure.kind != "fork":
            continue
        shape = fork_shape(document, document.junction_by_id[structure.junctions[0]])
        assert shape is not None
        feeding: list[tuple[Leg, set[str]]] = (
            [(leg, {shape.stem.road}) for leg in (shape.left, shape.right)]
            if shape.merge
            else [(shape.stem, {shape.left.road, shape.right.road})]
        )
        for leg, targets in feeding:
            road = document.road_by_id[leg.road]
            lanes = {f.source.lane for f in shape.flows if f.source.road == leg.road}
            s = max(road.length - 5.0, 0.0) if leg.end is ContactPoint.END else min(5.0, road.length)
            # 200 m: past the longest connecting road (88 m in these maps)
            out += [
                ({"road": leg.road, "lane": lane, "s": s, "step": 2.0, "reach": 200.0}, targets)
                for lane in sorted(lanes)
            ]
    return out


def test_carla_loads_them_and_its_waypoints_lead_from_each_fork_into_both_branches(cases):
    bad = []
    walked = 0
    for c in cases:
        if c.direct:
            continue
        walks = _walks(read(c.path).document)
        result = carla(c.path, distance=2.0, walks=[start for start, _ in walks])
        if not result.loaded:
            bad.append(f"{c.path.name}: CARLA did not load it ({result.error})")
            continue
        together: dict[tuple[str, float], set[str]] = {}  # the roads a road's lanes together reach
        for (start, _), met in zip(walks, result.walks):
            together.setdefault((start["road"], start["s"]), set()).update(p.road_id for p in met)
            walked += 1
        for start, targets in walks:
            missing = targets - together[(start["road"], start["s"])]
            if missing:
                bad.append(
                    f"{c.path.name}: from road {start['road']} lane {start['lane']} CARLA reaches no lane of {missing}"
                )
    assert walked >= 30 and bad == []


def test_asam_reports_no_error_and_no_checker_error(cases, asam_run):
    reports = asam_run.reports()
    bad = []
    for c in cases:
        bad += asam_problems(c.path.name, reports[c.path])
    assert bad == []
