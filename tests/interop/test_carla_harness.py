"""The CARLA harness loads maps in a separate process, and CARLA's lane centres agree with ours.

CARLA computes in float32, so agreement within 5e-4 m over town-sized coordinates is what two exact readers can show.
These tests need ``.venv-carla`` (created by ``.ci/run``); without it they fail, naming ``.ci/run``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tests.interop.carla_harness import (
    REPO,
    CarlaUnavailable,
    carla_python,
    carla_waypoints,
)
from xodrcheck.geometry.lanes import geometry_of
from xodrcheck.reader import read

pytestmark = pytest.mark.slow  # part of the full suite (CI); left out by -m "not slow"

#: Largest distance (m) between CARLA's waypoint and our lane centre at the same road, lane and s.
AGREEMENT = 5e-4

#: Town01 (lines and arcs) and esmini's multi_intersections (spirals, junctions). Not a paramPoly3 map: there CARLA
#: itself strays from esmini (6.5e-4 m on fabriksgatan road 0), while we agree with the lane-centre oracle there within
#: 2e-5 m.
MAPS = ["carla-towns/OpenDrive/Town01.xodr", "esmini/resources/xodr/multi_intersections.xodr"]

#: CARLA raises while building this map (a connection to a road it cannot find).
FAILS_IN_CARLA = "esmini/EnvironmentSimulator/Unittest/xodr/direct_junction_simple.xodr"


def _find(corpus_dir: Path, relative: str) -> Path:
    path = corpus_dir / relative
    assert path.is_file(), f"corpus file missing: {path}"
    return path


def _section_index(road, carla_section: int, s: float) -> int:
    """Our lane-section index for a CARLA waypoint: CARLA's section id where it covers s, else the section holding s."""
    sections = road.lane_sections
    if 0 <= carla_section < len(sections) and sections[carla_section].s <= s <= road.section_end(carla_section):
        return carla_section
    starts = np.array([sec.s for sec in sections])
    return int(np.searchsorted(starts, s, side="right") - 1)


@pytest.mark.corpus
@pytest.mark.parametrize("relative", MAPS)
def test_carla_lane_centres_agree_with_ours(corpus_dir, relative):
    path = _find(corpus_dir, relative)
    result = carla_waypoints(path, distance=2.0)
    assert result.loaded, f"CARLA did not load {relative}: {result.error}"
    assert len(result.waypoints) > 100 and result.topology

    document = read(path).document
    geometry = geometry_of(document)
    groups: dict[tuple[str, int, int], list] = {}
    for wp in result.waypoints:
        road = document.road_by_id[wp.road_id]
        groups.setdefault((wp.road_id, _section_index(road, wp.section_id, wp.s), wp.lane_id), []).append(wp)
    worst = 0.0
    for (road_id, section, lane), points in groups.items():
        s = np.array([p.s for p in points])
        ours = geometry[road_id].lane_points(section, lane, s, where="centre")
        gap = np.hypot(ours.x - np.array([p.x for p in points]), ours.y - np.array([p.y for p in points]))
        worst = max(worst, float(gap.max()))
        bad = np.flatnonzero(gap > AGREEMENT)
        assert not bad.size, (
            f"{relative}: road {road_id} section {section} lane {lane} s={s[bad[0]]:.3f}: "
            f"{gap[bad[0]]:.2e} m from CARLA"
        )
    assert worst < AGREEMENT


def test_a_map_carla_cannot_load_gives_loaded_false(corpus_dir):
    result = carla_waypoints(_find(corpus_dir, FAILS_IN_CARLA))
    assert not result.loaded
    assert result.returncode not in (0, None)
    assert result.waypoints == () and result.error


def test_not_an_opendrive_file_gives_loaded_false(tmp_path):
    bad = tmp_path / "bad.xodr"
    bad.write_text("<OpenDRIVE><road id=", encoding="utf-8")
    result = carla_waypoints(bad, timeout=60)
    assert not result.loaded and result.returncode == 1 and not result.crashed


def test_a_segfault_in_carla_is_a_result(tmp_path):
    # Lane links to lanes that do not exist make CARLA 0.9.16 dereference nothing and die of SIGSEGV.
    text = (REPO / "examples" / "t-junction.xodr").read_text(encoding="utf-8")
    good_links = '<link><predecessor id="-1"/><successor id="-1"/></link>'
    assert good_links in text
    crash = tmp_path / "crash.xodr"
    crash.write_text(text.replace(good_links, '<link><predecessor id="-7"/><successor id="-9"/></link>'), "utf-8")
    result = carla_waypoints(crash)
    assert not result.loaded
    assert result.crashed and result.returncode < 0


def test_missing_carla_interpreter_names_ci_run(monkeypatch, tmp_path):
    monkeypatch.setenv("CARLA_PYTHON", str(tmp_path / "no-python"))
    with pytest.raises(CarlaUnavailable, match=r"\.ci/run"):
        carla_waypoints(tmp_path / "map.xodr")


def test_carla_interpreter_is_installed():
    """CI creates .venv-carla; a missing one is a failure of the set-up, not a reason to skip."""
    try:
        python = carla_python()
    except CarlaUnavailable as exc:
        pytest.fail(str(exc))
    assert python.is_file()
