"""Interoperability acceptance of scenario maps (issue 16): signals, roadside and hilly terrain load in the tools.

50 maps (``--profile scenario --terrain hilly``, random lanes; every other one curved, every third with traffic lights
at every junction, every fifth left-hand traffic, every seventh rural), generated once per module. Each must pass:

* ``xodrcheck.check``: no error-level finding;
* ASAM ``asam-qc-opendrive``: no error-level issue and no checker ending in status "error";
* SUMO ``netconvert``: exit 0 and one ``tlLogic`` per junction that has ``<controller>`` references;
* CARLA's parser: ``Map.get_all_landmarks()`` lists every signal (each traffic light among them) and its waypoints
  follow the elevation (their heights span the map's z range read by xodrcheck).

Two more maps carry an overpass (``examples/overpass.json``: the bypass over the approach road, hilly and flat,
traffic lights at every junction): the same checks hold for them, and CARLA's waypoints reach the deck.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import pytest
from lxml import etree

import junctionart as ja
from junctionart import controllines
from junctionart.params import Params
from tests.interop.asam_harness import AsamRun
from tests.interop.tools import asam_problems, carla, run_netconvert, start_asam, xodrcheck_errors
from xodrcheck.analysis.elevation import elevation_info
from xodrcheck.check import check
from xodrcheck.config import Config
from xodrcheck.reader import read

#: Generated maps are judged as junctionart guarantees them: every rule at its own severity.
GENERATOR = Config(profile="generator")

pytestmark = pytest.mark.slow  # part of the full suite (CI); left out by -m "not slow"

COUNT = 50
#: (terrain, seed) of the maps with an overpass, drawn from examples/overpass.json after the COUNT seeds
OVERPASSES = (("hilly", 1), ("flat", 2))
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@dataclass(frozen=True)
class Scene:
    path: Path
    seed: int

    @property
    def root(self):
        return etree.parse(str(self.path)).getroot()


@pytest.fixture(scope="module")
def scenes(tmp_path_factory) -> list[Scene]:
    folder = tmp_path_factory.mktemp("scenario")
    out = []
    for k in range(COUNT):
        seed = 5000 + k
        p = Params.create(
            "scenario",
            terrain="hilly",
            randomize_lanes=True,
            curved_roads=k % 2 == 1,
            junction_control="traffic-lights" if k % 3 == 0 else "auto",
            traffic_rule="LHT" if k % 5 == 4 else "RHT",
            roadside="rural" if k % 7 == 6 else "urban",
        )
        out.append(Scene(ja.write(ja.generate(p, seed), folder / f"scene-{seed}.xodr"), seed))
    out += overpass_scenes(folder)
    return out


def overpass_scenes(folder: Path) -> list[Scene]:
    """The :data:`OVERPASSES` maps, each checked to hold its overpass."""
    lines = controllines.load(EXAMPLES / "overpass.json")
    out = []
    for terrain, seed in OVERPASSES:
        p = Params.create(
            "scenario",
            terrain=terrain,
            overpass_probability=1.0,
            junction_control="traffic-lights",
            randomize_lanes=True,
        )
        result = ja.generate_layout(p, seed, lines)
        assert len(result.layout.overpasses) == 1, f"{terrain} seed {seed}: no overpass ({result.layout.repairs})"
        out.append(Scene(ja.write(result.document, folder / f"overpass-{terrain}-{seed}.xodr"), seed))
    return out


@pytest.fixture(scope="module")
def asam_run(scenes, tmp_path_factory) -> AsamRun:
    return start_asam([s.path for s in scenes], tmp_path_factory.mktemp("asam"))


def test_plan_has_signals_sidewalks_and_hills(scenes, asam_run):
    """(Requests ``asam_run`` so that ASAM starts before the other tools' tests run.)"""
    lit = lights = sidewalks = 0
    for s in scenes:
        root = s.root
        lit += sum(j.find("controller") is not None for j in root.iter("junction"))
        lights += len(root.findall(".//signal[@type='1000001']"))
        sidewalks += len(root.findall(".//lane[@type='sidewalk']"))
    assert len(scenes) == COUNT + len(OVERPASSES) and lit > 100 and lights > 500 and sidewalks > 1000


def test_xodrcheck_finds_no_error(scenes):
    bad = []
    for s in scenes:
        bad += xodrcheck_errors(s.path.name, check(s.path, GENERATOR))
    assert bad == []


def test_sumo_builds_a_traffic_light_program_for_every_signalised_junction(scenes, tmp_path):
    bad = []
    for s in scenes:
        proc, out = run_netconvert(s.path, tmp_path)
        lit = sum(j.find("controller") is not None for j in s.root.iter("junction"))
        programs = len(etree.parse(str(out)).getroot().findall("tlLogic")) if out.is_file() else -1
        if proc.returncode != 0 or programs != lit:
            bad.append(f"{s.path.name}: exit {proc.returncode}, {programs} tlLogic for {lit} signalised junctions")
    assert bad == []


def test_carla_lists_the_signals_as_landmarks_and_follows_the_elevation(scenes):
    bad = []
    for s in scenes[: COUNT : max(1, COUNT // 12)] + scenes[COUNT:]:
        result = carla(s.path, distance=5.0)
        signals = {(el.get("id"), el.get("type")) for el in s.root.iter("signal")}
        marks = {(m[0], m[1]) for m in result.landmarks}
        e = elevation_info(read(s.path).document)
        zs = [w.z for w in result.waypoints]
        if not result.loaded or marks != signals:
            bad.append(f"{s.path.name}: {len(marks)} landmarks for {len(signals)} signals ({result.error})")
        elif min(zs) > e.min_z + 1.0 or max(zs) < e.max_z - 1.0:
            bad.append(f"{s.path.name}: waypoints z {min(zs):.2f}..{max(zs):.2f}, map {e.min_z:.2f}..{e.max_z:.2f}")
    assert bad == []


def test_asam_reports_no_error_and_no_checker_error(scenes, asam_run):
    reports = asam_run.reports()
    bad = []
    for s in scenes:
        bad += asam_problems(s.path.name, reports[s.path])
    assert bad == []
