"""Checking many files: in this process, in local worker processes, or on a Dask cluster, with the results in the
order the files were given whatever order they finish in (so a report is the same however it was computed).

>>> outcomes = check_files(["a.xodr", "b.xodr"], jobs=2)          # doctest: +SKIP
>>> [o.report.ok if o.report else o.error for o in outcomes]      # doctest: +SKIP

Local workers are processes (``concurrent.futures``); the largest files are started first, so that one big file does
not run alone at the end. ``scheduler`` is a Dask scheduler address (or a ``distributed.Client``): the files are
checked on its workers, which need ``xodrcheck`` installed and must see the paths (a shared file system).
"""

from __future__ import annotations

import os
import re
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from xodrcheck.check import Report, check
from xodrcheck.config import Config
from xodrcheck.findings import ReadError, XodrError


@dataclass(frozen=True)
class Outcome:
    """One file's result: its :class:`~xodrcheck.check.Report`, or the one line saying why it could not be checked."""

    path: str
    report: Report | None = None
    #: ``"cannot read PATH: why"`` or ``"internal error on PATH: ..."`` (``report`` is then ``None``).
    error: str | None = None


class BatchError(XodrError):
    """The batch cannot run at all (no Dask installed, no scheduler at the address)."""


def check_one(path: str, config: Config | None = None) -> Outcome:
    """:func:`~xodrcheck.check.check` of one file, its failure as an :class:`Outcome` instead of an exception."""
    import numpy as np

    try:
        with np.errstate(all="ignore"):  # as the command line: damaged numbers are findings, not warnings
            return Outcome(path, report=check(path, config))
    except ReadError as exc:
        return Outcome(path, error=str(exc))
    except Exception as exc:
        return Outcome(path, error=f"internal error on {path}: {type(exc).__name__}: {exc}")


def _size(path: str) -> int:
    try:
        return os.stat(path).st_size
    except OSError:
        return 0


def _largest_first(paths: Sequence[str]) -> list[int]:
    return sorted(range(len(paths)), key=lambda i: (-_size(paths[i]), i))


def check_files(
    paths: Sequence[str],
    config: Config | None = None,
    jobs: int | None = None,
    scheduler: Any = None,
    progress: bool = False,
) -> list[Outcome]:
    """Check every file; return one :class:`Outcome` per path, in the order of ``paths``.

    ``jobs``: worker processes (default: all cores; 1 or a single file: this process). ``scheduler``: a Dask scheduler
    address or client instead of local processes. ``progress``: a progress bar on stderr (tqdm)."""
    paths = [str(p) for p in paths]
    jobs = jobs or os.cpu_count() or 1
    if jobs < 1:
        raise ValueError(f"jobs must be at least 1, got {jobs}")
    bar = _bar(len(paths)) if progress and paths else None
    tick = bar.update if bar is not None else (lambda n=1: None)
    try:
        if scheduler is not None:
            return _on_dask(paths, config, scheduler, tick)
        if jobs == 1 or len(paths) <= 1:
            out = []
            for path in paths:
                out.append(check_one(path, config))
                tick(1)
            return out
        return _in_processes(paths, config, min(jobs, len(paths)), tick)
    finally:
        if bar is not None:
            bar.close()


def _bar(total: int):
    from tqdm import tqdm  # here: only a terminal shows a progress bar

    return tqdm(total=total, unit="file", file=sys.stderr, desc="xodrcheck", leave=False)


def _in_processes(paths: list[str], config: Config | None, jobs: int, tick: Callable[[int], Any]) -> list[Outcome]:
    from concurrent.futures import ProcessPoolExecutor, as_completed

    _warm(paths)
    results: list[Outcome | None] = [None] * len(paths)
    pool = ProcessPoolExecutor(max_workers=jobs, initializer=_worker_init)
    finished = False
    try:
        futures = {pool.submit(check_one, paths[i], config): i for i in _largest_first(paths)}
        for future in as_completed(futures):
            results[futures[future]] = future.result()
            tick(1)
        finished = True
    finally:
        if not finished:  # Ctrl-C or a broken worker: stop the files in progress instead of finishing them
            for process in list(getattr(pool, "_processes", {}).values()):
                process.terminate()
        pool.shutdown(wait=finished, cancel_futures=True)
    return [r for r in results if r is not None]


_VERSION = re.compile(rb'revMajor\s*=\s*"(\d+)"\s+revMinor\s*=\s*"(\d+)"')


def _warm(paths: Sequence[str]) -> None:
    """Load in this process what every worker would load for itself (the geometry and overlap modules, the schema of
    each declared version): forked workers share it instead of each building it again. Nothing here changes a
    result; a file whose header cannot be read here is simply not warmed for."""
    from xodrcheck.schema import fast as schema_fast
    from xodrcheck.schema import validate as schema

    versions = set()
    for path in paths:
        try:
            with open(path, "rb") as stream:
                head = stream.read(4096)
        except OSError:
            continue
        match = _VERSION.search(head)
        if match:
            versions.add((int(match.group(1)), int(match.group(2))))
    for version in sorted(versions & set(schema.SCHEMA_FOLDERS)):
        try:
            if version in schema.XSD11:  # the fast verdict; xmlschema's only for files it does not show valid
                folder, main = schema.SCHEMA_FOLDERS[version]
                schema_fast.derived(folder, main)
                schema_fast.plan(folder)
            else:
                schema.compiled(version)
        except Exception:
            continue


def _worker_init() -> None:
    """Workers leave Ctrl-C to the parent, which stops them (no traceback from every worker)."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _on_dask(paths: list[str], config: Config | None, scheduler: Any, tick: Callable[[int], Any]) -> list[Outcome]:
    try:
        from distributed import Client, as_completed
    except ImportError:
        raise BatchError("--scheduler needs dask: pip install 'junctionart[dask]'") from None
    owned = not isinstance(scheduler, Client)
    try:
        client = Client(scheduler, timeout=30) if owned else scheduler
    except (OSError, TimeoutError, ValueError) as exc:
        raise BatchError(f"--scheduler {scheduler}: cannot connect ({exc})") from None
    try:
        order = _largest_first(paths)
        futures = client.map(check_one, [paths[i] for i in order], config=config, pure=False)
        index = {future.key: i for future, i in zip(futures, order)}
        results: list[Outcome | None] = [None] * len(paths)
        for future in as_completed(futures):
            results[index[future.key]] = future.result()
            tick(1)
        return [r for r in results if r is not None]
    finally:
        if owned:
            client.close()
