"""MAP-Elites with pyribs over a kind's genome: the archive, the emitters, the loop, the checkpoint.

The archive is a :class:`ribs.archives.GridArchive` over the chosen descriptors (ranges and cells of the searched
kind's ``METRICS``, :mod:`.kinds`), with ``threshold_min = 0`` and ``learning_rate = 1`` (plain MAP-Elites: a cell
keeps its best candidate; infeasible candidates score -1 and never enter). Every metric is stored beside each elite.
A bandit scheduler (:class:`ribs.schedulers.BanditScheduler`, UCB1 over the emitters' share of archive improvements,
Cully 2021 and Sung et al. 2023) picks :data:`ACTIVE` emitters of a pool of five each iteration (:data:`EMITTERS`):
Gaussian mutation of random elites with a small and a large sigma (local refinement and long jumps, the way to cells
random sampling rarely reaches: 7 legs with a wide smallest angle, high complexity with few legs), iso+line-DD
(Vassiliades and Mouret 2018), and two CMA-ES emitters (CMA-ME, Fontaine et al. 2020) ranked by improvement of the
archive and by a random direction in descriptor space (they restart from a random elite when they stop improving).
One *iteration* asks the active emitters for a batch each, evaluates the candidates (local processes or Dask, results
in ask order) and tells the scheduler.

The run depends only on the seed and the settings, never on the number of workers: the scheduler (archive, emitters
and their random generators) is pickled to ``search.pkl`` after every iteration, and a rerun on the same folder
resumes from it, giving the same archive as an uninterrupted run.
"""

from __future__ import annotations

import pickle
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import ParamsError
from . import kinds
from .measure import INFEASIBLE, Evaluation, evaluate
from .predicate import Predicate

#: The bandit's pool: (kind, mutation scale in the unit box); CMA-ES emitters start from one random vector.
EMITTERS: tuple[tuple[str, float], ...] = (
    ("gaussian", 0.05),
    ("gaussian", 0.2),
    ("iso_line", 0.05),
    ("imp", 0.2),
    ("rd", 0.3),
)
#: Line sigma of the iso+line emitter.
LINE_SIGMA = 0.2
#: Emitters the bandit runs per iteration (each asks ``Settings.batch`` candidates).
ACTIVE = 2
CHECKPOINT = "search.pkl"


@dataclass(frozen=True)
class Settings:
    """What fixes a search's results (a resumed run must match them)."""

    descriptors: tuple[tuple[str, int], ...]  #: (metric name, cells)
    seed: int = 0
    batch: int = 16  #: candidates per emitter per iteration
    kind: str = "junction"  #: what is searched (:mod:`.kinds`)

    @property
    def metrics(self) -> dict[str, tuple[float, float, int]]:
        """The kind's metrics: name -> (low, high, default cells)."""
        return kinds.get(self.kind).METRICS


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
    """A fresh pyribs scheduler for ``settings``: a bandit over :data:`EMITTERS` (module docstring)."""
    from ribs.archives import GridArchive
    from ribs.emitters import EvolutionStrategyEmitter, GaussianEmitter, IsoLineEmitter
    from ribs.schedulers import BanditScheduler

    from .genome import random_genomes

    dim = kinds.get(settings.kind).DIM
    metrics = settings.metrics
    archive = GridArchive(
        solution_dim=dim,
        dims=[cells for _, cells in settings.descriptors],
        ranges=[metrics[name][:2] for name, _ in settings.descriptors],
        learning_rate=1.0,
        threshold_min=0.0,
        seed=settings.seed,
        extra_fields=dict.fromkeys(metrics, ((), np.float64)),
    )
    rng = np.random.default_rng(settings.seed)
    box = [(0.0, 1.0)] * dim
    pool: list[Any] = []
    for k, (kind, sigma) in enumerate(EMITTERS):
        seed = settings.seed + 1 + k
        if kind == "gaussian":
            start = random_genomes(rng, settings.batch, dim)
            pool.append(
                GaussianEmitter(
                    archive, sigma=sigma, initial_solutions=start, bounds=box, batch_size=settings.batch, seed=seed
                )
            )
        elif kind == "iso_line":
            start = random_genomes(rng, settings.batch, dim)
            pool.append(
                IsoLineEmitter(
                    archive,
                    iso_sigma=sigma,
                    line_sigma=LINE_SIGMA,
                    initial_solutions=start,
                    bounds=box,
                    batch_size=settings.batch,
                    seed=seed,
                )
            )
        else:  # "imp" / "rd": CMA-ES ranked by archive improvement or by a random direction in descriptor space
            x0 = random_genomes(rng, 1, dim)[0]
            # no bounds: CMA-ES resamples out-of-box candidates, possibly for ever; decode() clips into the box
            pool.append(
                EvolutionStrategyEmitter(
                    archive, x0=x0, sigma0=sigma, ranker=f"2{kind}", batch_size=settings.batch, seed=seed
                )
            )
    return BanditScheduler(archive, pool, num_active=ACTIVE, reselect="all")


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
    return f"--kind {s.kind} --descriptors {cells} --seed {s.seed} --batch {s.batch}"


def save(folder: Path, state: State) -> None:
    from xodrcheck.support.atomic import atomic_file

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
    names = state.settings.metrics
    return sum(1 for row in range(len(data["index"])) if where({n: float(data[n][row]) for n in names}))


Evaluator = Callable[[list[list[float]]], list[Evaluation]]


def iterate(state: State, evaluate_batch: Evaluator) -> None:
    """One ask / evaluate / tell step."""
    scheduler = state.scheduler
    names = [name for name, _ in state.settings.descriptors]
    metrics = state.settings.metrics
    solutions = scheduler.ask()
    results = evaluate_batch([[float(v) for v in x] for x in solutions])
    objective = np.array([r.objective for r in results])
    lows = np.array([metrics[n][0] for n in names])
    measures = np.array([[r.metrics[n] for n in names] for r in results], dtype=float)
    measures = np.where(np.isnan(measures), lows, measures)  # infeasible rows: anywhere, they are never added
    fields = {n: np.array([r.metrics[n] for r in results], dtype=float) for n in metrics}
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


def evaluate_inline(batch: list[list[float]], kind: str = "junction") -> list[Evaluation]:
    """Evaluate in this process (``-j 1``)."""
    return [evaluate(x, kind) for x in batch]
