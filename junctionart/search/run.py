"""The search loop: iterations until the budget is spent or enough elites meet ``--where``, on local processes
(all cores by default) or a Dask cluster (``scheduler=ADDRESS``, the executors of :mod:`junctionart.era`)."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from ..errors import ParamsError
from .engine import Evaluator, Settings, State, evaluate_inline, iterate, load_or_start, matches, save
from .measure import Evaluation, evaluate
from .predicate import Predicate


def _distributed(executor: Any, bar: Any, kind: str = "junction") -> Evaluator:
    """Evaluate a batch on ``executor`` (era's ``_Local`` or ``_Dask``), results in batch order."""

    def run(batch: list[list[float]]) -> list[Evaluation]:
        return executor.map_ordered(evaluate, [(x, kind) for x in batch], bar)

    return run


def _inline(bar: Any, kind: str = "junction") -> Evaluator:
    def run(batch: list[list[float]]) -> list[Evaluation]:
        out = []
        for x in batch:
            out += evaluate_inline([x], kind)
            if bar is not None:
                bar.update(1)
        return out

    return run


def search(
    folder: Path,
    settings: Settings,
    budget: int,
    where: Predicate | None = None,
    wanted: int | None = None,
    jobs: int | None = None,
    scheduler: Any = None,
    progress: bool = True,
) -> State:
    """Run (or resume) the search in ``folder`` until ``budget`` candidates have been evaluated, or ``wanted`` elites
    meet ``where``; the checkpoint is saved after every iteration."""
    from .. import era

    if budget < 1:
        raise ParamsError(f"--evaluations={budget}: must be at least 1")
    jobs = jobs or os.cpu_count() or 1
    if jobs < 1:
        raise ParamsError(f"-j {jobs}: must be at least 1")
    folder.mkdir(parents=True, exist_ok=True)
    state = load_or_start(folder, settings, era.generator_version())
    bar = None
    if progress:
        from tqdm import tqdm

        bar = tqdm(total=budget, initial=min(state.evaluated, budget), unit="map", desc="search")
    executor: Any = None
    if scheduler is not None:
        executor = era._Dask(scheduler)
    elif jobs > 1:
        executor = era._Local(jobs)
    kind = settings.kind
    evaluate_batch = _inline(bar, kind) if executor is None else _distributed(executor, bar, kind)
    try:
        while state.evaluated < budget and not _enough(state, where, wanted):
            iterate(state, evaluate_batch)
            save(folder, state)
            if bar is not None:
                bar.set_postfix(elites=state.history[-1]["elites"], matches=matches(state, where), refresh=False)
    finally:
        if executor is not None:
            executor.close()
        if bar is not None:
            bar.close()
    return state


def _enough(state: State, where: Predicate | None, wanted: int | None) -> bool:
    return wanted is not None and matches(state, where) >= wanted
