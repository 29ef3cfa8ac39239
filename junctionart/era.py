"""Expressive range analysis: generate maps until N intersections are collected, measure them, draw the figures.

How a run goes
--------------
* A *run* is a named parameter set; the paper's two are :data:`PAPER_RUNS`: 2 km x 2 km maps with one lane each way
  ("two-lane") and with lane counts drawn from the paper's distributions ("random-lane": ``lane_distribution_side``
  [0.15, 0.6, 0.2, 0.05] and ``lane_distribution_control_lines`` [0.05, 0.45, 0.4, 0.1], the :class:`Params` defaults).
* Map ``k`` of a run is generated with seed ``k`` (0, 1, 2, ...), written as OpenDRIVE bytes and read back through the
  independent reader; :func:`xodrcheck.analysis.metrics.map_metrics` measures every junction. Results therefore depend
  only on the seeds, never on how many workers computed them or in which order they finished.
* An *intersection* is a junction with at least 3 legs (the paper's 3 to 7). The analysis takes the first N
  intersections in (seed, junction order in the file) order: the smallest prefix of seeds that holds N of them.
* Every finished map appends its rows to ``legs.csv`` (one row per junction leg, the junction's columns repeated; see
  ``xodrcheck metrics``) and one line to ``maps.csv`` (run, seed, status, counts, seconds). A rerun skips the seeds
  listed in ``maps.csv`` and first drops rows of maps that never got their ``maps.csv`` line (an interrupted write), so
  an interrupted run resumes where it stopped.
* Work runs on local processes (``concurrent.futures.ProcessPoolExecutor``, all cores by default) or on a Dask cluster
  (``scheduler=ADDRESS``; needs the ``[dask]`` extra; :mod:`junctionart.era_executors`).

This module measures maps, keeps the table on disk and collects the runs; the ``junctionart era`` subcommand and the
analysis of a finished table (figures, report) are :mod:`junctionart.era_cli`.
"""

from __future__ import annotations

import csv
import functools
import hashlib
import os
import time
import traceback
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .era_executors import Dask as _Dask
from .era_executors import Local as _Local
from .errors import JunctionArtError, ParamsError
from .params import Params

#: Columns of ``legs.csv``.
ROW_COLUMNS = (
    "run",
    "seed",
    "junction_index",
    "junction",
    "junction_type",
    "kind",
    "legs",
    "n_connection_lanes",
    "n_u_turn_lanes",
    "area",
    "conflict_area",
    "conflict_ratio",
    "leg",
    "road",
    "contact",
    "x",
    "y",
    "fov",
    "max_curvature",
    "corner_deviation",
    "complexity",
)
#: Columns of ``structures.csv`` before the measures of every kind (:func:`structure_columns`).
STRUCTURE_HEAD = ("run", "seed", "structure", "kind", "junctions")
#: Columns of ``maps.csv``.
MAP_COLUMNS = ("run", "seed", "status", "junctions", "intersections", "seconds", "error", "generator")
#: Smallest leg count of an intersection.
MIN_LEGS = 3


def paper_runs(width: float = 2000.0, height: float = 2000.0) -> dict[str, Params]:
    """The paper's two runs on maps of ``width`` x ``height`` metres."""
    return {
        "two-lane": Params(width=width, height=height, randomize_lanes=False),
        "random-lane": Params(width=width, height=height, randomize_lanes=True),
    }


def known_runs(width: float = 2000.0, height: float = 2000.0) -> dict[str, Params]:
    """Every run ``junctionart era --runs`` knows: the paper's two and ``scenario`` (the scenario profile with random
    lanes, whose maps also hold the special structures: forks, ramps...)."""
    return {
        **paper_runs(width, height),
        "scenario": Params.create("scenario", width=width, height=height, randomize_lanes=True),
    }


PAPER_RUNS = ("two-lane", "random-lane")


def structure_columns() -> tuple[str, ...]:
    """Columns of ``structures.csv``: :data:`STRUCTURE_HEAD`, then every measure of every kind
    (:func:`xodrcheck.structures.measure_names`; empty where the structure's kind has no such measure)."""
    from xodrcheck.structures import measure_names

    return (*STRUCTURE_HEAD, *measure_names())


@dataclass(frozen=True)
class MapResult:
    """One generated map of an expressive range run: run, seed, status and its junctions' metric rows."""

    run: str
    seed: int
    status: str  # "ok" or "failed"
    rows: tuple[dict, ...]
    junctions: int
    intersections: int
    seconds: float
    error: str = ""
    structures: tuple[dict, ...] = ()  #: ``structures.csv`` rows


def _cell(value):
    return "" if value is None else value


def metric_rows(run: str, seed: int, metrics, kinds: dict[str, str] | None = None) -> list[dict]:
    """``legs.csv`` rows of one map's :class:`xodrcheck.analysis.metrics.JunctionMetrics` (a junction without legs: one
    row); ``kinds``: junction id -> the kind of the structure it is part of (:mod:`xodrcheck.structures`)."""
    out = []
    for index, m in enumerate(metrics):
        head = {
            "run": run,
            "seed": seed,
            "junction_index": index,
            "junction": m.junction,
            "junction_type": m.type.value,
            "kind": (kinds or {}).get(m.junction, ""),
            "legs": m.legs,
            "n_connection_lanes": m.n_connection_lanes,
            "n_u_turn_lanes": m.n_u_turn_lanes,
            "area": m.area,
            "conflict_area": m.conflict_area,
            "conflict_ratio": m.conflict_ratio,
        }
        legs: list[tuple[int | None, Any]] = list(enumerate(m.leg_metrics)) or [(None, None)]
        for i, leg in legs:
            row = dict(head, leg=i)
            if leg is not None:
                row.update(
                    road=leg.road,
                    contact=leg.end.value,
                    x=leg.x,
                    y=leg.y,
                    fov=leg.fov,
                    max_curvature=leg.max_curvature,
                    corner_deviation=leg.corner_deviation,
                    complexity=leg.complexity,
                )
            out.append({k: _cell(row.get(k)) for k in ROW_COLUMNS})
    return out


def structure_rows(run: str, seed: int, structures) -> list[dict]:
    """``structures.csv`` rows of one map's :class:`xodrcheck.structures.Structure` list."""
    out = []
    for index, st in enumerate(structures):
        row = {"run": run, "seed": seed, "structure": index, "kind": st.kind, "junctions": " ".join(st.junctions)}
        out.append(row | {name: "" if value != value else value for name, value in st.values})  # NaN: empty
    return out


def measure_map(run: str, params: Params, seed: int) -> MapResult:
    """Generate map ``seed`` of a run, read it back with xodrcheck and measure it (runs in a worker)."""
    from xodrcheck.analysis.metrics import map_metrics
    from xodrcheck.reader import read
    from xodrcheck.structures import map_structures

    from . import generate, to_bytes

    t0 = time.perf_counter()
    try:
        data = to_bytes(generate(params, seed), params.version)
        document = read(data).document
        if document is None:
            raise JunctionArtError("the reader could not build the generated map")
        metrics = map_metrics(document)
        structures = map_structures(document)
    except Exception as exc:
        detail = traceback.format_exception_only(type(exc), exc)[-1].strip()
        return MapResult(run, seed, "failed", (), 0, 0, time.perf_counter() - t0, detail)
    kinds = {j: st.kind for st in structures for j in st.junctions}
    rows = metric_rows(run, seed, metrics, kinds)
    intersections = sum(1 for m in metrics if m.legs >= MIN_LEGS)
    return MapResult(
        run,
        seed,
        "ok",
        tuple(rows),
        len(metrics),
        intersections,
        time.perf_counter() - t0,
        structures=tuple(structure_rows(run, seed, structures)),
    )


def measure_folder(folder: Path) -> list[dict]:
    """``legs.csv``-style rows of every ``.xodr`` under ``folder`` (run = the folder's name, seed = file index);
    unreadable files are skipped with a note on stderr."""
    import sys

    from xodrcheck.analysis.metrics import map_metrics
    from xodrcheck.findings import ReadError
    from xodrcheck.reader import read
    from xodrcheck.structures import map_structures

    files = sorted(Path(folder).rglob("*.xodr"))
    if not files:
        raise ParamsError(f"--compare {folder}: no .xodr files there")
    rows: list[dict] = []
    for index, path in enumerate(files):
        try:
            document = read(path).document
        except ReadError as exc:
            print(f"junctionart: skipping {path}: {exc}", file=sys.stderr)
            continue
        if document is not None:
            kinds = {j: st.kind for st in map_structures(document) for j in st.junctions}
            rows += metric_rows(Path(folder).name, index, map_metrics(document), kinds)
    return rows


# --------------------------------------------------------------------------------------------------------------------
# The table on disk
# --------------------------------------------------------------------------------------------------------------------
#: Sources that only present results (figures, report, command lines): editing them changes no row, so they are not
#: part of the generator version (anything else of either package is, to be safe).
PRESENTATION_ONLY = frozenset(
    {
        "junctionart/__main__.py",
        "junctionart/cli.py",
        "junctionart/era_report.py",
        "junctionart/render.py",
        "xodrcheck/__main__.py",
        "xodrcheck/cli",
        "xodrcheck/report",
    }
)


def source_hash(packages: Iterable[Path]) -> str:
    """sha256 (12 hex digits) of the ``.py`` files of ``packages`` (folders) and their paths, less
    :data:`PRESENTATION_ONLY`."""
    digest = hashlib.sha256()
    for package in packages:
        for path in sorted(package.rglob("*.py")):
            name = path.relative_to(package.parent).as_posix()
            if any(name == skip or name.startswith(skip + "/") for skip in PRESENTATION_ONLY):
                continue
            digest.update(name.encode())
            digest.update(path.read_bytes())
    return digest.hexdigest()[:12]


@functools.cache
def generator_version() -> str:
    """``VERSION+HASH``: the package version and a hash of the source of junctionart and xodrcheck (whose metrics
    fill the rows), so that a resumed run cannot mix maps of two different generators, installed or checked out."""
    from importlib import metadata

    import xodrcheck

    try:
        version = metadata.version("junctionart")
    except metadata.PackageNotFoundError:
        version = "unknown"
    return f"{version}+{source_hash([Path(__file__).parent, Path(xodrcheck.__file__).parent])}"


@dataclass
class Table:
    """``legs.csv`` and ``maps.csv`` in ``folder``, appended as maps finish."""

    folder: Path
    done: dict[tuple[str, int], int] = field(default_factory=dict)  # (run, seed) -> intersections (-1: failed)

    @property
    def legs_path(self) -> Path:
        return self.folder / "legs.csv"

    @property
    def maps_path(self) -> Path:
        return self.folder / "maps.csv"

    @property
    def structures_path(self) -> Path:
        return self.folder / "structures.csv"

    def open(self) -> Table:
        self.folder.mkdir(parents=True, exist_ok=True)
        if self.maps_path.exists():
            rows = read_csv(self.maps_path)
            made_by = sorted({row.get("generator") or "unrecorded" for row in rows} - {generator_version()})
            if made_by:
                raise ParamsError(
                    f"{self.folder}: its maps were made by generator {', '.join(made_by)}, this is "
                    f"{generator_version()}; give a new output folder (-o) or remove this one"
                )
            for row in rows:
                self.done[(row["run"], int(row["seed"]))] = int(row["intersections"]) if row["status"] == "ok" else -1
        else:
            _write_header(self.maps_path, MAP_COLUMNS)
        for path, columns in ((self.legs_path, ROW_COLUMNS), (self.structures_path, structure_columns())):
            if path.exists():  # drop rows of maps whose maps.csv line never got written
                rows = read_csv(path)
                kept = [r for r in rows if (r["run"], int(r["seed"])) in self.done]
                if len(kept) != len(rows):
                    _rewrite(path, columns, kept)
            else:
                _write_header(path, columns)
        return self

    def add(self, result: MapResult) -> None:
        with open(self.legs_path, "a", newline="", encoding="utf-8") as stream:
            csv.DictWriter(stream, ROW_COLUMNS, lineterminator="\n").writerows(result.rows)
        with open(self.structures_path, "a", newline="", encoding="utf-8") as stream:
            csv.DictWriter(stream, structure_columns(), lineterminator="\n").writerows(result.structures)
        with open(self.maps_path, "a", newline="", encoding="utf-8") as stream:
            csv.DictWriter(stream, MAP_COLUMNS, lineterminator="\n").writerow(
                {
                    "run": result.run,
                    "seed": result.seed,
                    "status": result.status,
                    "junctions": result.junctions,
                    "intersections": result.intersections,
                    "seconds": f"{result.seconds:.3f}",
                    "error": result.error,
                    "generator": generator_version(),
                }
            )
        self.done[(result.run, result.seed)] = result.intersections if result.status == "ok" else -1

    def collected(self, run: str) -> int:
        """Intersections in the longest prefix of seeds 0, 1, ... already done for ``run``."""
        total, seed = 0, 0
        while (run, seed) in self.done:
            total += max(self.done[(run, seed)], 0)
            seed += 1
        return total


def read_csv(path: Path) -> list[dict]:
    with open(path, newline="", encoding="utf-8") as stream:
        return list(csv.DictReader(stream))


def _write_header(path: Path, columns: Iterable[str]) -> None:
    with open(path, "w", newline="", encoding="utf-8") as stream:
        csv.writer(stream, lineterminator="\n").writerow(columns)


def _rewrite(path: Path, columns, rows) -> None:
    from xodrcheck.support.atomic import atomic_file

    with atomic_file(path, "w") as stream:
        writer = csv.DictWriter(stream, columns, lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)


def select(rows: list[dict], run: str, n: int) -> list[dict]:
    """The rows of the first ``n`` intersections of ``run`` in (seed, junction order) order."""
    by_junction: dict[tuple[int, int], list[dict]] = {}
    for r in rows:
        if r["run"] == run and int(r["legs"]) >= MIN_LEGS:
            by_junction.setdefault((int(r["seed"]), int(r["junction_index"])), []).append(r)
    keys = sorted(by_junction)[:n]
    return [row for key in keys for row in by_junction[key]]


# --------------------------------------------------------------------------------------------------------------------
# Collecting: maps generated and measured on the workers until every run has its intersections
# --------------------------------------------------------------------------------------------------------------------
def collect(
    runs: dict[str, Params],
    n: int,
    folder: Path,
    jobs: int | None = None,
    scheduler=None,
    max_maps: int = 100_000,
    progress: bool = True,
    on_map: Callable[[MapResult], None] | None = None,
) -> Table:
    """Generate and measure maps of every run until each has ``n`` intersections (resuming from ``folder``)."""
    if n < 1:
        raise ParamsError(f"intersections={n}: must be at least 1")
    jobs = jobs or os.cpu_count() or 1
    if jobs < 1:
        raise ParamsError(f"jobs={jobs}: must be at least 1")
    table = Table(Path(folder)).open()
    executor = _Dask(scheduler) if scheduler is not None else _Local(jobs)
    try:
        for run, params in runs.items():
            _collect_run(table, executor, run, params, n, max_maps, progress, on_map)
    finally:
        executor.close()
    return table


def _worth_more(table: Table, run: str, n: int, in_flight: int) -> bool:
    """Whether to start another map: the maps in flight, at the run's mean intersections per map so far, are not
    expected to reach ``n`` (keeps the overshoot at the end of a run small; results do not depend on it)."""
    counts = [v for (r, _), v in table.done.items() if r == run and v >= 0]
    if not counts or in_flight == 0:
        return True
    return table.collected(run) + in_flight * (sum(counts) / len(counts)) < n


def _collect_run(table, executor, run, params, n, max_maps, progress, on_map) -> None:
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=n, desc=run, unit="intersection")
        bar.update(min(table.collected(run), n))
    pending: dict = {}
    seed = 0
    window = 2 * executor.width
    while table.collected(run) < n:
        while len(pending) < window and seed < max_maps and _worth_more(table, run, n, len(pending)):
            if (run, seed) not in table.done:
                pending[executor.submit(measure_map, run, params, seed)] = seed
            seed += 1
        if not pending:
            break
        done, _ = executor.wait_first(pending)
        for future in done:
            pending.pop(future)
            result = future.result()
            table.add(result)
            if on_map is not None:
                on_map(result)
        if bar is not None:
            bar.update(min(table.collected(run), n) - bar.n)
    for future in list(pending):  # maps already running: keep them (a later, larger run can use them)
        table.add(future.result())
    if bar is not None:
        bar.close()
