"""The ``fork`` kind of the search: a fork or merge (:mod:`junctionart.splits`), measured by
:mod:`xodrcheck.structures.fork` on the written map.

Genome (each gene in [0, 1]; :func:`decode`):

* 0, 1: lanes of the left and right branch, ``1 + floor(3 x)``; 2: lanes of the other direction on the left (the
  near) branch, ``floor(4 x)``, 0 on half the box (``x < 0.5``: a one-way stem);
* 3: the split angle, ``2 + 88 x^2`` degrees (half the box below 24 degrees: the near-parallel forks that random
  generation never makes); 4: how the angle is shared, the left branch turning ``x`` of it to the left, the right
  branch the rest to the right;
* 5: the curves' radius, ``20 x 20^x`` m (20 to 400 m), raised where the lanes inside a curve need more;
* 6: a straight run of ``40 x`` m before the curves; 7: a merge (``x >= 0.5``) instead of a split; 8: a default
  junction with connecting roads (``x >= 0.5``) instead of a direct one.

Every vector decodes to a valid description (a pure function). Metrics: the fork kind's measures; default
descriptors ``split_angle`` (5-degree cells) x ``lanes_left`` x ``lanes_right``. Objective: 1 for every feasible
fork (no quality ranks one fork above another here; the archive keeps the first of each cell).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ...splits.spec import JUNCTION_LENGTH, MIN_RADIUS, Branch, ForkSpec, RampSpec, to_dict

__all__ = ["DEFAULT_DESCRIPTORS", "DIM", "METRICS", "decode", "map_bytes", "measure", "objective", "to_dict"]

DIM = 9
KIND = "fork"


def _metrics(kind: str) -> dict[str, tuple[float, float, int]]:
    from xodrcheck.structures import kind as structure_kind

    return {m.name: (m.low, m.high, m.cells) for m in structure_kind(kind).measures}


METRICS = _metrics(KIND)
DEFAULT_DESCRIPTORS = ("split_angle", "lanes_left", "lanes_right")


def _level(x: float, lo: int, count: int) -> int:
    return lo + min(math.floor(count * x), count - 1)


def _radius(x: float, inside: float) -> float:
    return round(max(20.0 * 20.0**x, inside + MIN_RADIUS + 1.0), 6)


def decode(x: np.ndarray | list[float]) -> ForkSpec:
    v = np.clip(np.asarray(x, dtype=float), 0.0, 1.0)
    left, right = _level(v[0], 1, 3), _level(v[1], 1, 3)
    oncoming = 0 if v[2] < 0.5 else _level(2 * v[2] - 1, 1, 3)
    angle = 2.0 + 88.0 * float(v[3]) ** 2
    turn_left = round(angle * float(v[4]), 6)
    turn_right = round(turn_left - angle, 6)
    w = 3.5
    inside = max(left, right, oncoming) * w  # the most any branch has inside its curve
    radius = _radius(float(v[5]), inside)
    lead = round(40.0 * float(v[6]), 6)
    length = max(150.0, lead + math.radians(max(turn_left, -turn_right)) * radius + JUNCTION_LENGTH + 40.0)
    return ForkSpec(
        left=Branch(left, turn_left, radius, lead),
        right=Branch(right, turn_right, radius, lead),
        oncoming=oncoming,
        merge=bool(v[7] >= 0.5),
        junction="default" if v[8] >= 0.5 else "direct",
        branch_length=round(length, 6),
    )


def map_bytes(spec: ForkSpec | RampSpec) -> bytes:
    from ... import to_bytes
    from ...splits.build import build

    return to_bytes(build(spec), spec.version)


def structure_measures(document: Any, kind: str) -> dict[str, float] | None:
    """The measures of the document's one structure, when it is of ``kind``."""
    from xodrcheck.structures import map_structures

    found = map_structures(document)
    if len(found) != 1 or found[0].kind != kind:
        return None
    return found[0].measures


def measure(document: Any) -> dict[str, float] | None:
    return structure_measures(document, KIND)


def objective(metrics: dict[str, float]) -> float:
    """1 for every feasible fork (the archive keeps the first of each cell)"""
    return 1.0
