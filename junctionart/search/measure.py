"""What the search measures on each candidate: the written map, read back and checked by xodrcheck.

Metrics (names for ``--descriptors`` and ``--where``), all from :mod:`xodrcheck.analysis.metrics` on the map's one
junction:

========================  ==========================================================  ================  =======
name                      meaning                                                      descriptor range  cells
========================  ==========================================================  ================  =======
``legs``                  legs of the junction                                         2.5 .. 7.5        5
``min_angle``             smallest angle between neighbouring legs (degrees)           0 .. 120          12
``fov``                   mean of the legs' FOV (degrees)                              0 .. 360          12
``complexity``            mean of the legs' complexity (the paper's, fixed scales)     0 .. 1            10
``conflict_ratio``        conflict area / junction area                                0 .. 1            10
``area``                  area of the connection lanes' union (m^2)                    0 .. 15000        15
``lanes``                 connection lanes (U-turns included)                          0 .. 80           16
``u_turns``               U-turn lanes                                                 0 .. 8            8
========================  ==========================================================  ================  =======

Default descriptors: ``legs`` x ``min_angle`` x ``area``. Random generation (``junctionart era``) puts 96 % of its
intersections on 3 or 4 legs, at 265 to 3,500 m^2; the tail is many legs, legs close together (the issue's "approach
angle under 30 degrees") or evenly spread (a wide smallest angle, which uniform draws of the headings rarely give),
and wide multi-lane junctions. Measured on the same evaluations (``benchmarks/bench_search.py``, ``rows.json``, 320
per sampler, binned after the fact): legs x min_angle alone (60 cells, about 41 reachable) is filled by uniform
random vectors as fast as by the search (0.94x); a third descriptor ``complexity`` follows ``min_angle`` closely (a
diagonal band, 1.46x against era's sampling); ``conflict_ratio`` 1.27x, ``fov`` 1.69x, ``lanes`` 2.1x, ``area``
2.64x with a higher QD-score (the objective then ranks junctions of one size). With ``area`` a cell's objective is
bounded by its area range, so the QD-score weighs small and large junctions alike per cell.

*Feasible*: the map has one junction and xodrcheck finds no error-level finding in it. *Objective* (the quality an
elite maximises within its cell): compactness, ``1 / (1 + area / 1000 m^2)`` in (0, 1], the same layout built on
less paved area (infeasible candidates score -1 and never enter the archive).
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from typing import Any

import numpy as np

#: name -> (low, high, default cells) of each metric used as a descriptor.
METRICS: dict[str, tuple[float, float, int]] = {
    "legs": (2.5, 7.5, 5),
    "min_angle": (0.0, 120.0, 12),
    "fov": (0.0, 360.0, 12),
    "complexity": (0.0, 1.0, 10),
    "conflict_ratio": (0.0, 1.0, 10),
    "area": (0.0, 15000.0, 15),
    "lanes": (0.0, 80.0, 16),
    "u_turns": (0.0, 8.0, 8),
}
NAMES = tuple(METRICS)
#: Default descriptors: the long tail in three dimensions, 5 x 12 x 15 = 900 cells (module docstring).
DEFAULT_DESCRIPTORS = ("legs", "min_angle", "area")
#: Area (m^2) at which the objective is one half.
AREA_SCALE = 1000.0
#: Objective of an infeasible candidate (below every feasible one, so the archive never takes it).
INFEASIBLE = -1.0


@dataclass(frozen=True)
class Evaluation:
    """One candidate's result (plain values: it travels back from worker processes or a Dask cluster)."""

    feasible: bool
    objective: float
    metrics: dict[str, float]  #: every metric of the candidate's kind (NaN where not measured)
    errors: int  #: error-level xodrcheck findings (-1: the generator or reader failed)
    sha256: str  #: of the written bytes ("" when nothing was written)
    note: str = ""  #: first error, for the report


def objective(area: float) -> float:
    """Compactness (module docstring)."""
    return 1.0 / (1.0 + max(area, 0.0) / AREA_SCALE)


def measure_document(document: Any, junction: Any = None) -> dict[str, float]:
    """Every metric of ``junction`` (default: the first) of a document read by xodrcheck's reader."""
    from xodrcheck.analysis.metrics import junction_legs, junction_metrics, smallest_leg_angle

    junction = document.junctions[0] if junction is None else junction
    m = junction_metrics(document, junction)
    angle = smallest_leg_angle(junction_legs(document, junction))

    def mean(values: list[float | None]) -> float:
        kept = [v for v in values if v is not None]
        return float(np.mean(kept)) if kept else float("nan")

    return {
        "legs": float(m.legs),
        "min_angle": float("nan") if angle is None else angle,
        "fov": mean([leg.fov for leg in m.leg_metrics]),
        "complexity": mean([leg.complexity for leg in m.leg_metrics]),
        "conflict_ratio": float("nan") if m.conflict_ratio is None else float(m.conflict_ratio),
        "area": float("nan") if m.area is None else float(m.area),
        "lanes": float(m.n_connection_lanes),
        "u_turns": float(m.n_u_turn_lanes),
    }


def _failed(note: str, names: tuple[str, ...], errors: int = -1, digest: str = "") -> Evaluation:
    return Evaluation(False, INFEASIBLE, dict.fromkeys(names, float("nan")), errors, digest, note)


def evaluate(genome: list[float], kind: str = "junction") -> Evaluation:
    """Decode, build, write, check (the checker's ``generator`` profile: what junctionart guarantees), read back and
    measure one candidate of ``kind`` (runs in a worker)."""
    from xodrcheck.check import check
    from xodrcheck.config import Config
    from xodrcheck.findings import Severity
    from xodrcheck.reader import read

    from ..errors import JunctionArtError
    from . import kinds

    module = kinds.get(kind)
    names = tuple(module.METRICS)
    try:
        data = module.map_bytes(module.decode(genome))
    except JunctionArtError as exc:
        return _failed(f"generator: {exc}", names)
    digest = hashlib.sha256(data).hexdigest()
    errors = [f for f in check(data, Config(profile="generator")).findings if f.severity >= Severity.ERROR]
    document = read(data).document
    metrics = module.measure(document) if document is not None else None
    if metrics is None:
        return _failed(f"the map read back holds no single {kind}", names, len(errors), digest)
    if errors:
        return Evaluation(False, INFEASIBLE, metrics, len(errors), digest, f"{errors[0].code} {errors[0].message}")
    if any(np.isnan(v) for v in metrics.values()):
        return Evaluation(False, INFEASIBLE, metrics, 0, digest, "a metric could not be measured")
    return Evaluation(True, module.objective(metrics), metrics, 0, digest)
