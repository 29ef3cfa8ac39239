"""Interoperability of ``junctionart search``'s elites (issue 13): 20 elites of a small search load cleanly in ASAM's
checker (no error, no checker in error), SUMO's netconvert (exit 0) and CARLA's parser (waypoints on every driving
lane), like the generator's maps (``test_generated_maps.py``; the tool helpers are ``tools.py``'s)."""

from __future__ import annotations

import csv

import pytest

from junctionart.cli import main
from tests.interop.tools import asam_problems, carla, driving_lanes, run_netconvert, start_asam

ELITES = 20


@pytest.fixture(scope="module")
def elites(tmp_path_factory):
    folder = tmp_path_factory.mktemp("search")
    argv = ["search", "-o", str(folder), "--descriptors", "legs,min_angle:24,area:15", "--batch", "6"]
    assert main([*argv, "--seed", "5", "--evaluations", "36", "-j", "1", "-q"]) == 0
    with open(folder / "archive.csv", newline="", encoding="utf-8") as stream:
        rows = list(csv.DictReader(stream))
    assert len(rows) >= ELITES
    chosen = [rows[k * len(rows) // ELITES] for k in range(ELITES)]  # spread over the archive (rows go by cell)
    assert len({int(float(r["legs"])) for r in chosen}) >= 4  # not one kind of junction: 4 of the 5 leg counts
    return [folder / r["file"] for r in chosen]


def test_asam_finds_no_error_in_the_elites(elites, tmp_path):
    reports = start_asam(elites, tmp_path / "asam").reports()
    bad = []
    for path in elites:
        report = reports[path]
        assert len(report.statuses) == 23, path.name  # every check ran (guard against a vacuous pass)
        bad += asam_problems(path.name, report)
    assert bad == []


def test_sumo_and_carla_load_the_elites(elites, tmp_path):
    bad = []
    for path in elites:
        proc, out = run_netconvert(path, tmp_path)
        if proc.returncode != 0 or not out.is_file():
            bad.append(f"{path.name}: netconvert exit {proc.returncode}")
        result = carla(path)
        seen = {(w.road_id, w.lane_id) for w in result.waypoints}
        missing = sorted(driving_lanes(path) - seen) if result.loaded else ["not loaded"]
        if missing:
            bad.append(f"{path.name}: CARLA: no waypoint on {missing[:5]}")
    assert bad == []
