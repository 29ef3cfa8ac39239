"""What the interoperability tests share: each tool started or run on one map, its verdict in one line a map.

``test_generated_maps.py``, ``test_scenario_maps.py`` and ``test_search_elites.py`` run the same tools on different
maps; a tool that is missing fails the test (never skips it), naming how to install it.
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

from tests.interop.asam_harness import AsamReport, AsamRun, AsamUnavailable
from tests.interop.carla_harness import CarlaResult, CarlaUnavailable, carla_waypoints
from xodrcheck.check import Report
from xodrcheck.model import LaneType
from xodrcheck.reader import read

REPO = Path(__file__).resolve().parents[2]


def start_asam(paths: list[Path], work: Path) -> AsamRun:
    """ASAM started in the background on ``paths`` (the slowest tool: the other tools run meanwhile)."""
    try:
        return AsamRun(paths, work)
    except AsamUnavailable as exc:
        pytest.fail(str(exc))


def asam_problems(label: str, report: AsamReport) -> list[str]:
    """ASAM's error-level issues and checkers in error on one map, in one line (none: an empty list)."""
    if not report.errors and not report.failed_checkers:
        return []
    issues = "; ".join(f"{i.rule} roads {sorted(i.roads)}: {i.description}" for i in report.errors[:3])
    return [f"{label}: {issues} checkers in error: {report.failed_checkers}"]


def xodrcheck_errors(label: str, report: Report) -> list[str]:
    """xodrcheck's error-level findings on one map (the first three), in one line (none: an empty list)."""
    errors = [f for f in report.findings if f.severity.name == "ERROR"]
    if not errors:
        return []
    return [f"{label}: " + "; ".join(f"{f.code} road {f.road}: {f.message}" for f in errors[:3])]


def netconvert() -> Path:
    """SUMO's ``netconvert`` in ``$SUMO_VENV`` (default ``<repo>/.venv-sumo``)."""
    venv = Path(os.environ.get("SUMO_VENV", REPO / ".venv-sumo"))
    command = venv / "bin" / "netconvert"
    if not command.is_file():
        pytest.fail(
            f"SUMO netconvert not found at {command}: run scripts/setup (it creates .venv-sumo with "
            "eclipse-sumo==1.28.0), or set SUMO_VENV to an environment that has it"
        )
    return command


def run_netconvert(path: Path, folder: Path) -> tuple[subprocess.CompletedProcess[str], Path]:
    """``netconvert --opendrive-files PATH -o FOLDER/<stem>.net.xml``: the process (its exit code is the caller's to
    judge) and the network file it was asked to write."""
    out = folder / f"{path.stem}.net.xml"
    proc = subprocess.run(
        [str(netconvert()), "--opendrive-files", str(path), "-o", str(out)],
        capture_output=True,
        text=True,
        timeout=300,
        stdin=subprocess.DEVNULL,
        check=False,
    )
    return proc, out


def carla(path: Path, **options) -> CarlaResult:
    """CARLA's parser on one map (:func:`carla_waypoints`), failing the test when CARLA is not installed."""
    try:
        return carla_waypoints(path, **options)
    except CarlaUnavailable as exc:
        pytest.fail(f"{exc} (scripts/setup creates .venv-carla)")


def driving_lanes(path: Path) -> set[tuple[str, int]]:
    """(road id, lane id) of every driving lane of the map, as xodrcheck reads it."""
    doc = read(path).document
    assert doc is not None
    return {
        (road.id, lane.id)
        for road in doc.roads
        for sec in road.lane_sections
        for lane in sec.lanes
        if lane.type is LaneType.DRIVING
    }
