"""The expressive range analysis: results depend on seeds only (worker count, Dask), resuming, the table, the CLI."""

from __future__ import annotations

import csv
import time
from pathlib import Path

import numpy as np
import pytest

import junctionart
from junctionart import cli, era
from junctionart.params import Params

SMALL = {"two-lane": Params(width=500.0, height=500.0)}


def _selected(folder: Path, n: int) -> list[dict]:
    rows = era.read_csv(folder / "legs.csv")
    return era.select(rows, "two-lane", n)


def _seeds(folder: Path) -> list[int]:
    return [int(r["seed"]) for r in era.read_csv(folder / "maps.csv")]


def _squared_later(k: int, seconds: float) -> int:
    time.sleep(seconds)
    return k * k


class _Ticks:
    """A stand-in for a tqdm bar: counts ``update`` calls."""

    def __init__(self) -> None:
        self.n = 0

    def update(self, k: int) -> None:
        self.n += k


def _map_ordered_keeps_the_order_of_the_calls(executor) -> None:
    calls = [(k, 0.5 if k == 0 else 0.0) for k in range(6)]  # the first call finishes last
    ticks = _Ticks()
    try:
        assert executor.map_ordered(_squared_later, calls, ticks) == [0, 1, 4, 9, 16, 25]
        assert executor.map_ordered(_squared_later, [], None) == []
    finally:
        executor.close()
    assert ticks.n == 6


def test_local_map_ordered_returns_results_in_call_order():
    _map_ordered_keeps_the_order_of_the_calls(era._Local(2))


def test_results_do_not_depend_on_the_number_of_workers(tmp_path):
    one = era.collect(SMALL, 12, tmp_path / "one", jobs=1, progress=False)
    two = era.collect(SMALL, 12, tmp_path / "two", jobs=2, progress=False)
    assert one.collected("two-lane") >= 12 and two.collected("two-lane") >= 12
    a, b = _selected(tmp_path / "one", 12), _selected(tmp_path / "two", 12)
    assert a == b
    assert len({(r["seed"], r["junction_index"]) for r in a}) == 12  # exactly the first 12 intersections
    assert all(int(r["legs"]) >= era.MIN_LEGS for r in a)


def test_rows_are_the_metrics_of_the_written_map(tmp_path):
    from xodrcheck.analysis.metrics import map_metrics
    from xodrcheck.reader import read

    params = SMALL["two-lane"]
    result = era.measure_map("two-lane", params, 3)
    assert result.status == "ok"
    path = junctionart.write(junctionart.generate(params, 3), tmp_path / "m.xodr")
    metrics = map_metrics(read(path).document)
    assert result.junctions == len(metrics)
    assert len(result.rows) == sum(max(len(m.leg_metrics), 1) for m in metrics)
    first = metrics[0]
    row = result.rows[0]
    assert float(row["area"]) == pytest.approx(first.area) and int(row["legs"]) == first.legs
    assert float(row["fov"]) == pytest.approx(first.leg_metrics[0].fov)
    # one structures.csv row per junction of a paper map, each an ordinary junction; legs.csv names the kind
    assert [r["kind"] for r in result.structures] == ["junction"] * len(metrics)
    assert [r["junctions"] for r in result.structures] == [m.junction for m in metrics]
    assert {r["kind"] for r in result.rows} == {"junction"}
    assert [float(r["legs"]) for r in result.structures] == [float(m.legs) for m in metrics]


def test_a_failing_map_is_recorded_not_raised(monkeypatch):
    def broken(params, seed):
        raise RuntimeError("boom")

    monkeypatch.setattr(junctionart, "generate", broken)
    result = era.measure_map("two-lane", SMALL["two-lane"], 0)
    assert result.status == "failed" and "boom" in result.error and result.rows == ()


def test_resume_skips_finished_seeds_and_drops_half_written_maps(tmp_path):
    folder = tmp_path / "run"
    era.collect(SMALL, 5, folder, jobs=1, progress=False)
    first = _seeds(folder)
    # an interrupted write: rows of a map whose maps.csv line never came
    with open(folder / "legs.csv", "a", newline="") as stream:
        csv.DictWriter(stream, era.ROW_COLUMNS).writerow(
            dict.fromkeys(era.ROW_COLUMNS, "") | {"run": "two-lane", "seed": 999, "junction_index": 0, "legs": 3}
        )
    era.collect(SMALL, 15, folder, jobs=1, progress=False)
    seeds = _seeds(folder)
    assert seeds[: len(first)] == first and len(seeds) == len(set(seeds)) > len(first)
    assert all(r["seed"] != "999" for r in era.read_csv(folder / "legs.csv"))
    fresh = tmp_path / "fresh"
    era.collect(SMALL, 15, fresh, jobs=1, progress=False)
    assert _selected(folder, 15) == _selected(fresh, 15)


def test_resume_refuses_maps_of_another_generator(tmp_path, monkeypatch):
    folder = tmp_path / "run"
    era.collect(SMALL, 3, folder, jobs=1, progress=False)
    (made_by,) = {r["generator"] for r in era.read_csv(folder / "maps.csv")}
    assert made_by == era.generator_version() and "+" in made_by
    monkeypatch.setattr(era, "generator_version", lambda: "0.1.0+changed")
    with pytest.raises(era.ParamsError, match=r"made by generator .*this is 0.1.0\+changed"):
        era.collect(SMALL, 6, folder, jobs=1, progress=False)


def test_dask_local_cluster_gives_the_local_results(tmp_path):
    try:
        import distributed
    except ImportError:  # the extra is optional for users, not for the suite
        pytest.fail("dask.distributed is missing: install the [dask] extra (scripts/setup does)")
    era.collect(SMALL, 10, tmp_path / "local", jobs=2, progress=False)
    with (
        distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster,
        distributed.Client(cluster) as client,
    ):
        era.collect(SMALL, 10, tmp_path / "dask", scheduler=client, progress=False)
        _map_ordered_keeps_the_order_of_the_calls(era._Dask(client))
    assert _selected(tmp_path / "local", 10) == _selected(tmp_path / "dask", 10)


def test_cli_writes_table_figures_and_report(tmp_path, corpus_dir):
    out = tmp_path / "era"
    compare = corpus_dir / "carla-towns"
    code = cli.main(
        [
            "era",
            "-o",
            str(out),
            "-n",
            "6",
            "--size",
            "500x500",
            "--runs",
            "two-lane",
            "-j",
            "1",
            "-q",
            "--compare",
            str(compare),
        ]
    )
    assert code == 0
    report = (out / "report.md").read_text()
    assert "complexity (paper Figure 13)" in report and "carla-towns" in report
    assert "## Structures by kind" in report
    structures = era.read_csv(out / "structures.csv")
    assert structures and {r["kind"] for r in structures} == {"junction"}
    pngs = sorted(p.name for p in out.glob("*.png"))
    assert len(pngs) == 8 + 7 and all((out / p).stat().st_size > 1000 for p in pngs)


def test_cli_bad_options_are_one_line(tmp_path, capsys):
    assert cli.main(["era", "-o", str(tmp_path), "--runs", "three-lane", "-q"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "three-lane" in err
    assert cli.main(["era", "-o", str(tmp_path), "--size", "big", "-q"]) == 2
    assert cli.main(["era", "-o", str(tmp_path), "-n", "0", "-q"]) == 2
    assert "Traceback" not in capsys.readouterr().err


def test_distribution_figure_draws_rare_leg_counts_as_values_without_warnings(tmp_path, monkeypatch):
    """Two 7-leg intersections are drawn as two ticks, not as a spiky density; a leg count whose values all lie past
    the shared bins (cut at the 99.5th percentile) does not divide by zero (RuntimeWarnings are errors here)."""
    import warnings

    import matplotlib.axes

    from junctionart import era_report

    rng = np.random.default_rng(0)
    legs = np.concatenate([np.full(400, 4.0), np.full(2, 7.0), np.full(3, 6.0)])
    area = np.concatenate([rng.uniform(500, 1500, 400), [900.0, 1100.0], [1e6, 2e6, 3e6]])
    sample = era_report.Sample("junctionart", {"legs": legs, "area": area}, {"legs": legs, "area": area})
    drawn = {"hist": [], "plot": []}
    real_hist, real_plot = matplotlib.axes.Axes.hist, matplotlib.axes.Axes.plot

    def hist(self, values, *args, **kwargs):
        drawn["hist"].append(kwargs.get("label"))
        return real_hist(self, values, *args, **kwargs)

    def plot(self, *args, **kwargs):
        drawn["plot"].append(kwargs.get("label"))
        return real_plot(self, *args, **kwargs)

    monkeypatch.setattr(matplotlib.axes.Axes, "hist", hist)
    monkeypatch.setattr(matplotlib.axes.Axes, "plot", plot)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        era_report.distribution_figure("area", [sample], None, tmp_path / "area.png")
    assert (tmp_path / "area.png").stat().st_size > 0
    assert drawn["hist"] == ["4 legs (n=400)"]
    assert drawn["plot"] == ["6 legs (n=3, values)", "7 legs (n=2, values)"]


def test_generator_version_ignores_presentation_only_sources(tmp_path):
    """Editing the report or figure code keeps the version (a finished run can be redrawn and resumed); editing
    anything that makes or measures maps changes it."""
    pkg = tmp_path / "junctionart"
    (pkg / "intersections").mkdir(parents=True)
    (pkg / "era_report.py").write_text("A = 1\n")
    (pkg / "curves.py").write_text("B = 1\n")
    (pkg / "intersections" / "layout.py").write_text("C = 1\n")
    before = era.source_hash([pkg])
    (pkg / "era_report.py").write_text("A = 2\n")
    assert era.source_hash([pkg]) == before
    (pkg / "intersections" / "layout.py").write_text("C = 2\n")
    assert era.source_hash([pkg]) != before
    checker = tmp_path / "xodrcheck"
    (checker / "cli").mkdir(parents=True)
    (checker / "cli" / "check.py").write_text("D = 1\n")
    (checker / "metrics.py").write_text("E = 1\n")
    both = era.source_hash([pkg, checker])
    (checker / "cli" / "check.py").write_text("D = 2\n")
    assert era.source_hash([pkg, checker]) == both
    (checker / "metrics.py").write_text("E = 2\n")
    assert era.source_hash([pkg, checker]) != both


def test_the_structures_section_counts_each_kind_and_draws_its_measures(tmp_path):
    """A run whose maps hold forks and ramps: the section counts them per kind and draws one figure per special kind
    with a panel per measure; structures of maps outside the selected intersections are not counted."""
    from junctionart.era_structures import section
    from xodrcheck.structures import KINDS, kind

    def row(seed, k, **measures):
        return {"run": "scenario", "seed": str(seed), "kind": k, **{n: str(v) for n, v in measures.items()}}

    rows = [
        row(0, "junction", legs=3, min_angle=80),
        row(0, "fork", split_angle=12.0, lanes_in=2, lanes_left=1, lanes_right=1, merge=0, direct=0),
        row(0, "fork", split_angle=12.0, lanes_in=2, lanes_left=1, lanes_right=1, merge=1, direct=0),
        row(1, "ramp", ramp_angle=30.0, taper_length=29.4, side_lane_length=49.7, ramp_lanes=1, exit=1),
        row(5, "ramp", ramp_angle=31.0, taper_length=29.4, side_lane_length=49.7, ramp_lanes=1, exit=0),
    ]
    selected = {"scenario": [{"seed": "0"}, {"seed": "1"}]}  # seed 5's intersections were not selected
    lines = section(tmp_path, rows, selected)
    counts = next(line for line in lines if line.startswith("| scenario |"))
    cells = dict(zip([k.name for k in KINDS], (c.strip() for c in counts.strip("|").split("|")[1:])))
    assert cells["junction"] == "1" and cells["fork"] == "2" and cells["ramp"] == "1"
    assert (tmp_path / "kind_fork.png").stat().st_size > 1000 and (tmp_path / "kind_ramp.png").stat().st_size > 1000
    text = "\n".join(lines)
    assert "### fork" in text and "split_angle: scenario 12" in text and "ramp_angle: scenario 30" in text
    assert len(kind("fork").measures) == 6
