"""The expressive range report's section on a search archive (``junctionart era --archive``, issue 13)."""

from __future__ import annotations

import csv

import numpy as np
import pytest

from junctionart import cli, era
from junctionart.era_archive import from_archive, from_rows, table
from junctionart.search.measure import NAMES
from junctionart.search.outputs import HEAD


def _archive(folder, legs: list[int]) -> None:
    folder.mkdir()
    with open(folder / "archive.csv", "w", newline="", encoding="utf-8") as stream:
        writer = csv.DictWriter(stream, [*HEAD, *NAMES, "genome"], lineterminator="\n")
        writer.writeheader()
        for k, n in enumerate(legs):
            metrics = {"legs": n, "complexity": 0.3 + 0.1 * k, "lanes": 10 * n, "area": 1000.0 * n}
            writer.writerow({"cell": k, **dict.fromkeys(NAMES, 0.5), **metrics, "genome": "[]"})


def test_rows_become_intersections_with_leg_metrics_averaged():
    head = {"run": "r", "seed": 0, "legs": 3, "area": 500.0, "conflict_ratio": 0.4, "n_connection_lanes": 6}
    rows = [
        {**head, "junction_index": 0, "leg": i, "complexity": c, "fov": f}
        for i, (c, f) in enumerate([(0.2, 90.0), (0.4, 100.0), (0.6, "")])
    ]
    rows.append({**head, "junction_index": 1, "legs": 2, "leg": 0, "complexity": 0.9, "fov": 10.0})  # not one
    sample = from_rows("r", rows)
    assert len(sample) == 1
    assert sample.values["complexity"][0] == pytest.approx(0.4) and sample.values["fov"][0] == pytest.approx(95.0)
    assert sample.values["area"][0] == 500.0 and sample.values["n_connection_lanes"][0] == 6


def test_archive_table_gives_leg_shares_and_medians(tmp_path):
    _archive(tmp_path / "a", [3, 5, 7, 7])
    sample = from_archive(tmp_path / "a")
    assert len(sample) == 4 and np.array_equal(sample.values["n_connection_lanes"], [30, 50, 70, 70])
    row = table([sample])[2]
    assert "| 4 | 25.0 % | 0.0 % | 25.0 % | 0.0 % | 50.0 % |" in row
    assert "| 0.45 | 25.0 % |" in row  # median complexity of 0.3..0.6; only 0.6 is over 0.5


def test_era_report_gains_the_archive_section_beside_the_runs_and_carla(tmp_path, corpus_dir):
    _archive(tmp_path / "search", [3, 4, 6, 7, 7])
    out = tmp_path / "era"
    argv = ["era", "-o", str(out), "-n", "6", "--size", "500x500", "--runs", "two-lane", "-j", "1", "-q"]
    assert cli.main([*argv, "--compare", str(corpus_dir / "carla-towns"), "--archive", str(tmp_path / "search")]) == 0
    report = (out / "report.md").read_text(encoding="utf-8")
    section = report[report.index("## The search archive beside random generation and carla-towns") :]
    carla = {
        (r["seed"], r["junction_index"]) for r in era.measure_folder(corpus_dir / "carla-towns") if int(r["legs"]) >= 3
    }
    assert f"| carla-towns | {len(carla)} |" in section
    assert "| two-lane | 6 |" in section and "| search archive (search) | 5 |" in section
    assert "6- and 7-leg intersections:" in section and "search archive (search) 60.0 %" in section
    png = (out / "era_archive.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 20_000


def test_archive_option_without_an_archive_is_one_line(tmp_path, capsys):
    assert cli.main(["era", "-o", str(tmp_path / "era"), "--archive", str(tmp_path), "-q"]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "no archive.csv there" in err
