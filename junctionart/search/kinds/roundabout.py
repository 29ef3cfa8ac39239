"""The ``roundabout`` kind of the search: one roundabout (:mod:`junctionart.intersections.roundabout`), built by
``junctionart intersection --roundabout`` and measured by :mod:`xodrcheck.structures.roundabout` on the written map.

Genome (each gene in [0, 1]; :func:`decode`):

* 0: arms, ``3 + floor(4 x)`` (3 to 6); 1: the angle from the first arm to the second, ``20 + (360 / arms - 20) x``
  degrees (up to an even spread: the gene that sets the tightest arm angle); 2: ``evenness``, how far the other arms'
  angles are pulled towards an even spread of the rest of the turn (as in the junction kind's genome, :mod:`..genome`);
  3: the outer radius asked for, ``9 + 41 x`` m (mini to large; the ring grows where its arms need room); 4: two
  circulating lanes (``x >= 0.5``); 5: ``width``, the level every arm's lane counts lean to;
* per arm slot k = 0..5 (slots past the arm count are ignored), four genes: ``gap`` (the angle after the arm as a
  share of the turn left after the second arm, as the junction kind's; slot 0's is unused), lanes ``in`` and ``out``
  (``1 + floor(3 (x + width) / 2)``) and ``median`` (on at 0.5 or more).

Why gene 1: a roundabout's tightest arm angle decides how large its ring must be (each arm's junction takes a sector
of the ring), and drawn as shares of the turn it hides in the corner of the box where every share but one is large;
one gene moving it from 20 degrees to the even spread makes the whole range one step away for the search's
mutations.

A vector decodes to exactly one description (a pure function). Arms closer together than the ring can serve at the
largest radius make the generator build an ordinary junction: the candidate then holds no roundabout and is
infeasible. Metrics: the roundabout kind's measures; default descriptors ``arms`` x ``arm_angle`` x ``radius``.
Objective: 1 for every feasible roundabout (the archive keeps the first of each cell).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ...intersection import IntersectionSpec, LegSpec, to_dict
from ..genome import MIN_SHARE
from .fork import _level, _metrics, structure_measures

__all__ = ["DEFAULT_DESCRIPTORS", "DIM", "METRICS", "decode", "map_bytes", "measure", "objective", "to_dict"]

KIND = "roundabout"
#: Genes before the arm slots: arms, first angle, evenness, radius, lanes, width.
HEAD = 6
#: Genes per arm slot: gap, in, out, median.
PER_ARM = 4
MAX_ARMS = 6
DIM = HEAD + MAX_ARMS * PER_ARM
#: Outer radius (m) a gene of 0 and of 1 asks for.
RADII = (9.0, 50.0)
#: Smallest first angle (degrees) gene 1 gives.
TIGHTEST = 20.0
METRICS = _metrics(KIND)
DEFAULT_DESCRIPTORS = ("arms", "arm_angle", "radius")


def decode(x: np.ndarray | list[float]) -> IntersectionSpec:
    v = np.clip(np.asarray(x, dtype=float), 0.0, 1.0)
    n = _level(float(v[0]), 3, MAX_ARMS - 2)
    first = TIGHTEST + (360.0 / n - TIGHTEST) * float(v[1])
    evenness, width = float(v[2]), float(v[5])
    slots = v[HEAD:].reshape(MAX_ARMS, PER_ARM)[:n]
    shares = MIN_SHARE + (1 - MIN_SHARE) * ((1 - evenness) * slots[1:, 0] + evenness / 2)
    rest = (360.0 - first) * np.cumsum(shares) / shares.sum()
    headings = np.concatenate([[0.0, first], first + rest[:-1]])
    legs = tuple(
        LegSpec(
            heading=round(float(h), 6),
            lanes_in=_level((float(s[1]) + width) / 2, 1, 3),
            lanes_out=_level((float(s[2]) + width) / 2, 1, 3),
            median=bool(s[3] >= 0.5),
        )
        for h, s in zip(headings, slots)
    )
    radius = round(RADII[0] + (RADII[1] - RADII[0]) * float(v[3]), 3)
    return IntersectionSpec(legs, roundabout_radius=radius, roundabout_lanes=2 if v[4] >= 0.5 else 1)


def map_bytes(spec: IntersectionSpec) -> bytes:
    from ... import to_bytes
    from ...intersection import build

    return to_bytes(build(spec).document, spec.version)


def measure(document: Any) -> dict[str, float] | None:
    return structure_measures(document, KIND)


def objective(metrics: dict[str, float]) -> float:
    """1 for every feasible roundabout (the archive keeps the first of each cell)"""
    return 1.0
