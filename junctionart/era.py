"""Expressive range analysis: generate maps until N intersections are collected, measure them, draw the figures.

How a run goes
--------------
* A *run* is a named parameter set; the paper's two are :data:`PAPER_RUNS`: 2 km x 2 km maps with one lane each way
  ("two-lane") and with lane counts drawn from the paper's distributions ("random-lane": ``lane_distribution_side``
  [0.15, 0.6, 0.2, 0.05] and ``lane_distribution_control_lines`` [0.05, 0.45, 0.4, 0.1], the :class:`Params` defaults).
* Map ``k`` of a run is generated with seed ``k`` (0, 1, 2, ...), written as OpenDRIVE bytes and read back through the
  independent reader; :func:`xodrcheck.metrics.map_metrics` measures every junction. Results therefore depend only on
  the seeds, never on how many workers computed them or in which order they finished.
* An *intersection* is a junction with at least 3 legs (the paper's 3 to 7). The analysis takes the first N
  intersections in (seed, junction order in the file) order: the smallest prefix of seeds that holds N of them.
* Every finished map appends its rows to ``legs.csv`` (one row per junction leg, the junction's columns repeated; see
  ``xodrcheck metrics``) and one line to ``maps.csv`` (run, seed, status, counts, seconds). A rerun skips the seeds
  listed in ``maps.csv`` and first drops rows of maps that never got their ``maps.csv`` line (an interrupted write), so
  an interrupted run resumes where it stopped.
* Work runs on local processes (``concurrent.futures.ProcessPoolExecutor``, all cores by default) or on a Dask cluster
  (``scheduler=ADDRESS``; needs the ``[dask]`` extra).
"""

from __future__ import annotations

import csv
import functools
import hashlib
import os
import time
import traceback
from collections.abc import Callable, Iterable
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor
from concurrent.futures import wait as _wait
from dataclasses import field
from pathlib import Path
from typing import Any

from xodrcheck.classcache import dataclass

from .errors import JunctionArtError, ParamsError
from .params import Params

#: Columns of ``legs.csv``.
ROW_COLUMNS = (
    "run",
    "seed",
    "junction_index",
    "junction",
    "junction_type",
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


PAPER_RUNS = ("two-lane", "random-lane")


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


def _cell(value):
    return "" if value is None else value


def metric_rows(run: str, seed: int, metrics) -> list[dict]:
    """``legs.csv`` rows of one map's :class:`xodrcheck.metrics.JunctionMetrics` (a junction without legs: one row)."""
    out = []
    for index, m in enumerate(metrics):
        head = {
            "run": run,
            "seed": seed,
            "junction_index": index,
            "junction": m.junction,
            "junction_type": m.type.value,
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


def measure_map(run: str, params: Params, seed: int) -> MapResult:
    """Generate map ``seed`` of a run, read it back with xodrcheck and measure it (runs in a worker)."""
    from xodrcheck.metrics import map_metrics
    from xodrcheck.reader import read

    from . import generate, to_bytes

    t0 = time.perf_counter()
    try:
        data = to_bytes(generate(params, seed), params.version)
        document = read(data).document
        if document is None:
            raise JunctionArtError("the reader could not build the generated map")
        metrics = map_metrics(document)
    except Exception as exc:
        detail = traceback.format_exception_only(type(exc), exc)[-1].strip()
        return MapResult(run, seed, "failed", (), 0, 0, time.perf_counter() - t0, detail)
    rows = metric_rows(run, seed, metrics)
    intersections = sum(1 for m in metrics if m.legs >= MIN_LEGS)
    return MapResult(run, seed, "ok", tuple(rows), len(metrics), intersections, time.perf_counter() - t0)


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
        if self.legs_path.exists():  # drop rows of maps whose maps.csv line never got written
            rows = read_csv(self.legs_path)
            kept = [r for r in rows if (r["run"], int(r["seed"])) in self.done]
            if len(kept) != len(rows):
                _rewrite(self.legs_path, ROW_COLUMNS, kept)
        else:
            _write_header(self.legs_path, ROW_COLUMNS)
        return self

    def add(self, result: MapResult) -> None:
        with open(self.legs_path, "a", newline="", encoding="utf-8") as stream:
            csv.DictWriter(stream, ROW_COLUMNS, lineterminator="\n").writerows(result.rows)
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
    from xodrcheck.atomic import atomic_file

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
# Executors: local processes or a Dask cluster, behind one submit / wait pair
# --------------------------------------------------------------------------------------------------------------------
class _Executor:
    """What both executors share on top of their ``submit`` / ``wait_first``."""

    def submit(self, fn, *args):
        raise NotImplementedError

    def wait_first(self, pending):
        raise NotImplementedError

    def map_ordered(self, fn: Callable[..., Any], calls: Iterable[tuple], bar: Any = None) -> list[Any]:
        """``[fn(*args) for args in calls]`` on the workers: every call submitted at once, the results in the order
        of ``calls`` whatever order they finish in; ``bar`` (a tqdm bar or None) ticks once per finished call."""
        pending = {self.submit(fn, *args): k for k, args in enumerate(calls)}
        out: list[Any] = [None] * len(pending)
        while pending:
            done, _ = self.wait_first(pending)
            for future in done:
                out[pending.pop(future)] = future.result()
                if bar is not None:
                    bar.update(1)
        return out


class _Local(_Executor):
    def __init__(self, jobs: int):
        self.pool = ProcessPoolExecutor(max_workers=jobs)
        self.width = jobs

    def submit(self, fn, *args):
        return self.pool.submit(fn, *args)

    def wait_first(self, pending):
        return _wait(pending, return_when=FIRST_COMPLETED)

    def close(self):
        self.pool.shutdown(wait=True, cancel_futures=True)


class _Dask(_Executor):
    def __init__(self, address):
        try:
            from distributed import Client
        except ImportError:
            raise ParamsError("--scheduler needs dask: pip install 'junctionart[dask]'") from None
        try:
            self.client = address if isinstance(address, Client) else Client(address, timeout=30)
        except (OSError, TimeoutError) as exc:
            raise ParamsError(f"--scheduler {address}: cannot connect ({exc})") from None
        self.owned = not isinstance(address, Client)
        self.width = max(sum(self.client.nthreads().values()), 1)

    def submit(self, fn, *args):
        return self.client.submit(fn, *args, pure=False)

    def wait_first(self, pending):
        from distributed import wait

        return wait(list(pending), return_when="FIRST_COMPLETED")

    def close(self):
        if self.owned:
            self.client.close()


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


# --------------------------------------------------------------------------------------------------------------------
# Comparison maps, the whole analysis, and the ``junctionart era`` subcommand
# --------------------------------------------------------------------------------------------------------------------
def measure_folder(folder: Path) -> list[dict]:
    """``legs.csv``-style rows of every ``.xodr`` under ``folder`` (run = the folder's name, seed = file index);
    unreadable files are skipped with a note on stderr."""
    import sys

    from xodrcheck.findings import ReadError
    from xodrcheck.metrics import map_metrics
    from xodrcheck.reader import read

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
            rows += metric_rows(Path(folder).name, index, map_metrics(document))
    return rows


def analyse(
    folder: Path, run_names: Iterable[str], n: int, compare: Path | None, setup: list[str], archive: Path | None = None
) -> Path:
    """Cut each run to its first ``n`` intersections, measure the comparison folder and write figures and report
    (with a section on a search's archive folder when given, :mod:`junctionart.era_archive`)."""
    from .era_report import Sample, write_report

    rows = read_csv(Path(folder) / "legs.csv")
    selected = {run: select(rows, run, n) for run in run_names}
    samples = [Sample.of(run, chosen) for run, chosen in selected.items()]
    other, compare_rows = None, None
    if compare is not None:
        compare_rows = measure_folder(compare)
        other = Sample.of(Path(compare).name, compare_rows)
    extra: list[str] = []
    if archive is not None:
        from . import era_archive as ea

        runs = [ea.from_rows(run, chosen) for run, chosen in selected.items()]
        theirs = ea.from_rows(Path(compare).name, compare_rows) if compare is not None and compare_rows else None
        extra = ea.section(Path(folder), runs, theirs, ea.from_archive(archive))
    return write_report(Path(folder), samples, other, setup, extra)


def add_arguments(p) -> None:
    p.add_argument(
        "-o",
        "--output",
        type=Path,
        default=Path("era"),
        help="folder for legs.csv, maps.csv, figures and report.md (default: ./era); reused to resume",
    )
    p.add_argument(
        "-n",
        "--intersections",
        type=int,
        default=10_000,
        help="intersections (3+ legs) to collect per run (default 10000, as in the paper)",
    )
    p.add_argument(
        "--runs", default="two-lane,random-lane", help="comma-separated runs: two-lane, random-lane (default: both)"
    )
    p.add_argument("--size", default="2000x2000", help="map size WxH in metres (default 2000x2000)")
    p.add_argument("-j", "--jobs", type=int, default=None, help="worker processes (default: all cores)")
    p.add_argument(
        "--scheduler",
        default=None,
        metavar="ADDRESS",
        help="run on this Dask scheduler (e.g. tcp://host:8786) instead of local processes",
    )
    p.add_argument(
        "--compare",
        type=Path,
        default=None,
        metavar="DIR",
        help="overlay the distributions of the .xodr maps in DIR (e.g. the CARLA towns)",
    )
    p.add_argument(
        "--archive",
        type=Path,
        default=None,
        metavar="DIR",
        help="add a section setting the elites of a junctionart search folder (its archive.csv) beside the runs "
        "and --compare",
    )
    p.add_argument("--max-maps", type=int, default=100_000, help="give up on a run after this many seeds")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress bar")


def run(args) -> int:
    import resource
    import sys

    try:
        width, height = (float(v) for v in args.size.lower().split("x"))
    except ValueError:
        raise ParamsError(f"--size {args.size!r}: expected WxH in metres, e.g. 2000x2000") from None
    known = paper_runs(width, height)
    names = [name.strip() for name in args.runs.split(",") if name.strip()]
    unknown = [name for name in names if name not in known]
    if unknown or not names:
        raise ParamsError(f"--runs {args.runs!r}: choose from {', '.join(known)}")
    if args.compare is not None and not args.compare.is_dir():
        raise ParamsError(f"--compare {args.compare}: not a folder")
    if args.archive is not None and not (args.archive / "archive.csv").is_file():
        raise ParamsError(f"--archive {args.archive}: no archive.csv there (the folder of a junctionart search)")
    t0 = time.perf_counter()
    table = collect(
        {name: known[name] for name in names},
        args.intersections,
        args.output,
        args.jobs,
        args.scheduler,
        args.max_maps,
        not args.quiet,
    )
    seconds = time.perf_counter() - t0
    usage = [resource.getrusage(who) for who in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN)]
    peak = max(u.ru_maxrss for u in usage) / 1024
    setup = [
        (
            f"Runs: {', '.join(names)}; maps {width:g} m x {height:g} m, seeds 0, 1, 2, ... per run; the first "
            f"{args.intersections} intersections (junctions with 3+ legs) of each run in seed order."
        ),
        (
            "Metrics: `xodrcheck.metrics` (definitions in its docstring), computed on each map after writing it "
            "and reading it back with the independent reader."
        ),
        f"Generator: junctionart {generator_version()} (package version + source hash, also in maps.csv).",
    ]
    for name in names:
        seeds = [s for (r, s), v in table.done.items() if r == name]
        failed = sum(1 for (r, s), v in table.done.items() if r == name and v < 0)
        setup.append(f"{name}: {len(seeds)} maps measured ({failed} failed), {table.collected(name)} intersections.")
    setup.append(f"This invocation: {seconds:.0f} s wall, peak resident memory {peak:.0f} MB per process.")
    report = analyse(args.output, names, args.intersections, args.compare, setup, args.archive)
    print(
        f"{report}: {', '.join(f'{n} {table.collected(n)} intersections' for n in names)}, {seconds:.0f} s",
        file=sys.stderr,
    )
    short = [n for n in names if table.collected(n) < args.intersections]
    if short:
        print(
            f"junctionart: warning: {', '.join(short)} stopped short of {args.intersections} intersections "
            f"(--max-maps {args.max_maps})",
            file=sys.stderr,
        )
    return 0
