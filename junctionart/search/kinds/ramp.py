"""The ``ramp`` kind of the search: an exit or entry ramp (:mod:`junctionart.splits`), measured by
:mod:`xodrcheck.structures.ramp` on the written map.

Genome (each gene in [0, 1]; :func:`decode`):

* 0: the main road's lanes in the ramp's direction, ``1 + floor(3 x)``; 1: lanes the other way, ``floor(4 x)``;
  2: ramp lanes, 1 or 2 (``x >= 0.5``);
* 3: the taper, ``20 + 180 x`` m (at least what the ramp lanes' shift needs); 4: the exit (entry) lane at full width
  beside the main lanes, ``150 x`` m; 5: the ramp's run beside the main road before it turns, ``60 x`` m;
* 6: the ramp's angle, ``5 + 85 x`` degrees; 7: its radius, ``30 x 10^x`` m (30 to 300 m), raised where its lanes
  need more;
* 8: an entry (``x >= 0.5``) instead of an exit; 9: a default junction (``x >= 0.5``) instead of a direct one.

Metrics: the ramp kind's measures; default descriptors ``ramp_angle`` x ``taper_length``. Objective: 1 for every
feasible ramp.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ...splits.spec import JUNCTION_LENGTH, MIN_RADIUS, RampSpec, to_dict
from .fork import _level, _metrics, map_bytes, structure_measures

__all__ = ["DEFAULT_DESCRIPTORS", "DIM", "METRICS", "decode", "map_bytes", "measure", "objective", "to_dict"]

DIM = 10
KIND = "ramp"
METRICS = _metrics(KIND)
DEFAULT_DESCRIPTORS = ("ramp_angle", "taper_length")


def decode(x: np.ndarray | list[float]) -> RampSpec:
    v = np.clip(np.asarray(x, dtype=float), 0.0, 1.0)
    lanes, oncoming = _level(v[0], 1, 3), _level(v[1], 0, 4)
    ramp_lanes = 2 if v[2] >= 0.5 else 1
    w = 3.5
    needed = math.sqrt(24.0 * (ramp_lanes - 0.5) * w * MIN_RADIUS)
    taper = round(max(20.0 + 180.0 * float(v[3]), needed + 0.5), 6)
    full = round(150.0 * float(v[4]), 6)
    parallel = round(60.0 * float(v[5]), 6)
    angle = round(5.0 + 85.0 * float(v[6]), 6)
    radius = round(max(30.0 * 10.0 ** float(v[7]), ramp_lanes * w + MIN_RADIUS + 1.0), 6)
    branch = max(200.0, parallel + math.radians(angle) * radius + JUNCTION_LENGTH + 40.0)
    return RampSpec(
        entry=bool(v[8] >= 0.5),
        lanes=lanes,
        oncoming=oncoming,
        ramp_lanes=ramp_lanes,
        taper_length=taper,
        lane_length=full,
        parallel_length=parallel,
        angle=angle,
        radius=radius,
        junction="default" if v[9] >= 0.5 else "direct",
        approach_length=round(max(300.0, taper + full + 50.0), 6),
        branch_length=round(branch, 6),
    )


def measure(document: Any) -> dict[str, float] | None:
    return structure_measures(document, KIND)


def objective(metrics: dict[str, float]) -> float:
    """1 for every feasible ramp (the archive keeps the first of each cell)"""
    return 1.0
