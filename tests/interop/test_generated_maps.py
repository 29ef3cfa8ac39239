"""Interoperability acceptance of the generator: its maps load cleanly in the tools people use.

53 maps (seeds) across 500 m, 1 km and 2 km, two-lane and random-lane (some with curved roads, three with wide
medians and U-turns, every fourth written as OpenDRIVE 1.7, the rest 1.8), generated once per module. Each must pass:

* ``xodrcheck.check``: no error-level finding;
* ASAM ``asam-qc-opendrive``: no error-level issue and no checker ending in status "error";
* SUMO ``netconvert --opendrive-files MAP -o out.net.xml``: exit code 0;
* CARLA's parser: loads it and yields waypoints on every driving lane of every road.

Each tool runs from its own virtual environment (``scripts/setup`` creates them); a missing one fails the test.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import pytest

import junctionart as ja
from junctionart.params import Params
from tests.interop.asam_harness import AsamRun
from tests.interop.tools import (
    asam_problems,
    carla,
    driving_lanes,
    run_netconvert,
    start_asam,
    xodrcheck_errors,
)
from xodrcheck.check import check
from xodrcheck.config import Config
from xodrcheck.reader import read

#: Generated maps are judged as junctionart guarantees them: every rule at its own severity.
GENERATOR = Config(profile="generator")

pytestmark = pytest.mark.slow  # part of the full suite (CI); left out by -m "not slow"

#: The ASAM check each version skips (its rule applies to the other version only).
SKIPPED = {"1.7": "one_link_to_incoming", "1.8": "one_connection_element"}

#: Wide medians and U-turns on every leg where one fits (the defaults leave no room for a U-turn).
U_TURNS = {"median_width": 4.0, "median_probability": 0.7, "u_turn_probability": 1.0}

#: (size in m, randomize lanes, number of maps, other parameters): most at 500 m and 1 km, a few at 2 km.
PLAN = [
    (500, False, 18, {}),
    (500, True, 16, {}),
    (1000, False, 7, {}),
    (1000, True, 7, {}),
    (1000, True, 3, U_TURNS),
    (2000, False, 1, {}),
    (2000, True, 1, {}),
]


@dataclass(frozen=True)
class Map:
    path: Path
    size: int
    random_lanes: bool
    seed: int
    version: str

    @property
    def label(self) -> str:
        lanes = "random lanes" if self.random_lanes else "two lanes"
        return f"{self.path.name} ({self.size} m, {lanes}, seed {self.seed}, OpenDRIVE {self.version})"


@pytest.fixture(scope="module")
def maps(tmp_path_factory) -> list[Map]:
    folder = tmp_path_factory.mktemp("generated")
    out = []
    n = 0
    for size, random_lanes, count, extra in PLAN:
        for k in range(count):
            seed = 1000 * size // 500 + 100 * random_lanes + 50 * bool(extra) + k
            version = "1.7" if n % 4 == 3 else "1.8"
            params = Params(
                width=size,
                height=size,
                randomize_lanes=random_lanes,
                curved_roads=random_lanes and k % 2 == 1,
                version=version,
                **extra,
            )
            path = folder / f"{size}-{'random' if random_lanes else 'two'}{'-uturn' if extra else ''}-{seed}.xodr"
            ja.write(ja.generate(params, seed), path, version)
            out.append(Map(path, size, random_lanes, seed, version))
            n += 1
    return out


@pytest.fixture(scope="module")
def asam_run(maps, tmp_path_factory) -> AsamRun:
    """ASAM started in the background on every map (the slowest tool: the other tools run meanwhile)."""
    return start_asam([m.path for m in maps], tmp_path_factory.mktemp("asam"))


def test_plan_covers_sizes_lane_modes_and_at_least_50_seeds(maps, asam_run):
    """(Requests ``asam_run`` so that ASAM starts before the other tools' tests run.)"""
    assert len(maps) >= 50
    assert len({(m.size, m.seed) for m in maps}) == len(maps)
    assert {(m.size, m.random_lanes) for m in maps} == {(s, r) for s in (500, 1000, 2000) for r in (False, True)}
    assert {m.version for m in maps} == {"1.7", "1.8"}
    assert sum(_u_turns(m.path) for m in maps) >= 5, "the plan covers U-turn connection lanes"


def _same_end(road) -> bool:
    """A U-turn: the connecting road leaves and enters the same end of one road."""
    a, b = road.predecessor, road.successor
    return a.element_id == b.element_id and a.contact_point == b.contact_point


def _u_turns(path: Path) -> int:
    """Connecting roads that lead back to the road end they come from."""
    doc = read(path).document
    return sum(1 for r in doc.roads if r.junction is not None and _same_end(r))


def test_xodrcheck_finds_no_error(maps):
    bad = []
    for m in maps:
        report = check(m.path, GENERATOR)
        assert report.version == m.version
        bad += xodrcheck_errors(m.label, report)
    assert bad == []


def test_sumo_netconvert_converts_every_map(maps, tmp_path):
    bad = []
    for m in maps:
        proc, out = run_netconvert(m.path, tmp_path)
        if proc.returncode != 0 or not out.is_file():
            tail = "\n".join(proc.stderr.strip().splitlines()[-3:])
            bad.append(f"{m.label}: exit {proc.returncode}: {tail}")
    assert bad == []


def test_carla_loads_every_map_with_waypoints_on_every_driving_lane(maps):
    bad = []
    for m in maps:
        result = carla(m.path)
        if not result.loaded:
            bad.append(f"{m.label}: CARLA did not load it (exit {result.returncode}): {result.error}")
            continue
        lanes = driving_lanes(m.path)
        seen = {(w.road_id, w.lane_id) for w in result.waypoints}
        missing = sorted(lanes - seen)
        if missing:
            bad.append(
                f"{m.label}: no CARLA waypoint on {len(missing)} of {len(lanes)} driving lanes, e.g. {missing[:5]}"
            )
    assert bad == []


@pytest.fixture(scope="module")
def asam_reports(asam_run):
    return asam_run.reports()


def test_asam_reports_no_error_and_no_checker_error(maps, asam_reports):
    bad = []
    for m in maps:
        bad += asam_problems(m.label, asam_reports[m.path])
    assert bad == []


def test_asam_ran_its_checks(maps, asam_reports):
    """Guard against a vacuous pass: every check ran to completion, except the one each version does not have
    (ASAM runs "one connection element" on 1.7 files only, "one link to incoming" on 1.8 files only)."""
    for m in maps:
        statuses = asam_reports[m.path].statuses
        assert len(statuses) == 23, m.label
        skipped = {c for c, status in statuses.items() if status != "completed"}
        expected = {f"check_asam_xodr_junctions_connection_{SKIPPED[m.version]}"}
        assert skipped == expected, m.label
