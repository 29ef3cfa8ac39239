"""The ``junctionart era`` subcommand: its arguments, the run it starts (:func:`junctionart.era.collect` for the
chosen runs, then the analysis) and the analysis of a finished table: each run cut to its first N intersections, the
comparison folder measured, figures and report written (:mod:`junctionart.era_report`, with a section on a search's
archive from :mod:`junctionart.era_archive`)."""

from __future__ import annotations

import time
from collections.abc import Iterable
from pathlib import Path

from . import era
from .errors import ParamsError


def analyse(
    folder: Path, run_names: Iterable[str], n: int, compare: Path | None, setup: list[str], archive: Path | None = None
) -> Path:
    """Cut each run to its first ``n`` intersections, measure the comparison folder and write figures and report
    (with a section on a search's archive folder when given, :mod:`junctionart.era_archive`)."""
    from .era_report import Sample, write_report
    from .era_structures import section as structures_section

    rows = era.read_csv(Path(folder) / "legs.csv")
    selected = {run: era.select(rows, run, n) for run in run_names}
    samples = [Sample.of(run, chosen) for run, chosen in selected.items()]
    other, compare_rows = None, None
    if compare is not None:
        compare_rows = era.measure_folder(compare)
        other = Sample.of(Path(compare).name, compare_rows)
    extra: list[str] = []
    if archive is not None:
        from . import era_archive as ea

        runs = [ea.from_rows(run, chosen) for run, chosen in selected.items()]
        theirs = ea.from_rows(Path(compare).name, compare_rows) if compare is not None and compare_rows else None
        extra = ea.section(Path(folder), runs, theirs, ea.from_archive(archive))
    structures = Path(folder) / "structures.csv"
    if structures.is_file():
        extra = [*structures_section(Path(folder), era.read_csv(structures), selected), *extra]
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
        "--runs",
        default="two-lane,random-lane",
        help="comma-separated runs: two-lane, random-lane (the paper's, the default), scenario (the scenario profile "
        "with random lanes: its maps also hold forks, ramps and other structures)",
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
    known = era.known_runs(width, height)
    names = [name.strip() for name in args.runs.split(",") if name.strip()]
    unknown = [name for name in names if name not in known]
    if unknown or not names:
        raise ParamsError(f"--runs {args.runs!r}: choose from {', '.join(known)}")
    if args.compare is not None and not args.compare.is_dir():
        raise ParamsError(f"--compare {args.compare}: not a folder")
    if args.archive is not None and not (args.archive / "archive.csv").is_file():
        raise ParamsError(f"--archive {args.archive}: no archive.csv there (the folder of a junctionart search)")
    t0 = time.perf_counter()
    table = era.collect(
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
            "Metrics: `xodrcheck.analysis.metrics` (definitions in its docstring), computed on each map after writing "
            "it and reading it back with the independent reader."
        ),
        f"Generator: junctionart {era.generator_version()} (package version + source hash, also in maps.csv).",
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
