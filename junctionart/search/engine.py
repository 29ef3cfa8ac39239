"""MAP-Elites with pyribs over the intersection genome: the archive, the emitters, the loop, the checkpoint.

The archive is a :class:`ribs.archives.GridArchive` over the chosen descriptors (ranges and cells of
:data:`.measure.METRICS`), with ``threshold_min = 0`` and ``learning_rate = 1`` (plain MAP-Elites: a cell keeps its
best candidate; infeasible candidates score -1 and never enter). Every metric is stored beside each elite. Two
emitters sample it: a Gaussian emitter (isotropic mutation, sigma :data:`SIGMA` of the unit box) and an iso+line-DD
emitter (Vassiliades and Mouret 2018), each starting from its own uniform random batch. One *iteration* asks each
emitter for a batch, evaluates the candidates (local processes or Dask, results in ask order) and tells the scheduler.

The run depends only on the seed and the settings, never on the number of workers: the scheduler (archive, emitters
and their random generators) is pickled to ``search.pkl`` after every iteration, and a rerun on the same folder
resumes from it, giving the same archive as an uninterrupted run.
"""

from __future__ import annotations

import pickle
from collections.abc import Callable
from dataclasses import field
from pathlib import Path
from typing import Any

import numpy as np

from xodrcheck.classcache import dataclass

from ..errors import ParamsError
from .measure import INFEASIBLE, METRICS, NAMES, Evaluation, evaluate
from .predicate import Predicate

#: Mutation scale (unit box) of the Gaussian emitter; the iso+line emitter's iso sigma.
SIGMA = 0.1
#: Line sigma of the iso+line emitter.
LINE_SIGMA = 0.2
CHECKPOINT = "search.pkl"


@dataclass(frozen=True)
class Settings:
    """What fixes a search's results (a resumed run must match them)."""

    descriptors: tuple[tuple[str, int], ...]  #: (metric name, cells)
    seed: int = 0
    batch: int = 16  #: candidates per emitter per iteration


@dataclass
class State:
    """Everything a checkpoint holds."""

    settings: Settings
    generator: str
    scheduler: Any
    evaluated: int = 0
    feasible: int = 0
    history: list[dict[str, float]] = field(default_factory=list)  #: per iteration: evaluated, elites, qd_score
    failures: dict[str, int] = field(default_factory=dict)  #: first words of infeasible notes -> count


def new_scheduler(settings: Settings) -> Any:
    """A fresh pyribs scheduler for ``settings``."""
    from ribs.archives import GridArchive
    from ribs.emitters import GaussianEmitter, IsoLineEmitter
    from ribs.schedulers import Scheduler

    from .genome import DIM, random_genomes

    archive = GridArchive(
        solution_dim=DIM,
        dims=[cells for _, cells in settings.descriptors],
        ranges=[METRICS[name][:2] for name, _ in settings.descriptors],
        learning_rate=1.0,
        threshold_min=0.0,
        seed=settings.seed,
        extra_fields=dict.fromkeys(NAMES, ((), np.float64)),
    )
    rng = np.random.default_rng(settings.seed)
    box = [(0.0, 1.0)] * DIM
    emitters = [
        GaussianEmitter(
            archive,
            sigma=SIGMA,
            initial_solutions=random_genomes(rng, settings.batch),
            bounds=box,
            batch_size=settings.batch,
            seed=settings.seed + 1,
        ),
        IsoLineEmitter(
            archive,
            iso_sigma=SIGMA,
            line_sigma=LINE_SIGMA,
            initial_solutions=random_genomes(rng, settings.batch),
            bounds=box,
            batch_size=settings.batch,
            seed=settings.seed + 2,
        ),
    ]
    return Scheduler(archive, emitters)


def load_or_start(folder: Path, settings: Settings, generator: str) -> State:
    """The checkpoint in ``folder`` when there is one (its settings and generator must match), else a new state."""
    path = folder / CHECKPOINT
    if not path.exists():
        return State(settings, generator, new_scheduler(settings))
    try:
        with open(path, "rb") as stream:
            state = pickle.load(stream)  # the search's own file, written by save() below
    except (OSError, pickle.UnpicklingError, EOFError, AttributeError, ImportError) as exc:
        raise ParamsError(f"{path}: cannot resume from this checkpoint ({exc}); give a new output folder") from None
    if not isinstance(state, State):
        raise ParamsError(f"{path}: not a checkpoint of junctionart search; give a new output folder")
    if state.settings != settings:
        raise ParamsError(
            f"{folder}: its search ran with {_describe(state.settings)}, this one asks for {_describe(settings)}; "
            "give a new output folder (-o) or the same settings"
        )
    if state.generator != generator:
        raise ParamsError(
            f"{folder}: its maps were made by generator {state.generator}, this is {generator}; give a new output "
            "folder (-o)"
        )
    return state


def _describe(s: Settings) -> str:
    cells = ",".join(f"{name}:{n}" for name, n in s.descriptors)
    return f"--descriptors {cells} --seed {s.seed} --batch {s.batch}"


def save(folder: Path, state: State) -> None:
    from xodrcheck.atomic import atomic_file

    with atomic_file(folder / CHECKPOINT, "wb") as stream:
        pickle.dump(state, stream, protocol=pickle.HIGHEST_PROTOCOL)


def elites(state: State) -> dict[str, np.ndarray]:
    """The archive's elites: ``solution``, ``objective``, ``measures``, ``index`` and every metric, one row each."""
    return state.scheduler.archive.data()


def matches(state: State, where: Predicate | None) -> int:
    """Elites meeting ``where`` (all elites without one)."""
    data = elites(state)
    if where is None:
        return len(data["index"])
    return sum(1 for row in range(len(data["index"])) if where({n: float(data[n][row]) for n in NAMES}))


Evaluator = Callable[[list[list[float]]], list[Evaluation]]


def iterate(state: State, evaluate_batch: Evaluator) -> None:
    """One ask / evaluate / tell step."""
    scheduler = state.scheduler
    names = [name for name, _ in state.settings.descriptors]
    solutions = scheduler.ask()
    results = evaluate_batch([[float(v) for v in x] for x in solutions])
    objective = np.array([r.objective for r in results])
    lows = np.array([METRICS[n][0] for n in names])
    measures = np.array([[r.metrics[n] for n in names] for r in results], dtype=float)
    measures = np.where(np.isnan(measures), lows, measures)  # infeasible rows: anywhere, they are never added
    fields = {n: np.array([r.metrics[n] for r in results], dtype=float) for n in NAMES}
    scheduler.tell(objective, measures, **fields)
    state.evaluated += len(results)
    state.feasible += sum(1 for r in results if r.objective > INFEASIBLE)
    for r in results:
        if not r.feasible:
            key = r.note.split(":")[0][:60] or "unknown"
            state.failures[key] = state.failures.get(key, 0) + 1
    stats = scheduler.archive.stats
    state.history.append(
        {"evaluated": state.evaluated, "elites": int(stats.num_elites), "qd_score": float(stats.qd_score)}
    )


def evaluate_inline(batch: list[list[float]]) -> list[Evaluation]:
    """Evaluate in this process (``-j 1``)."""
    return [evaluate(x) for x in batch]
