"""The search's genome: a vector in the unit box [0, 1]^DIM, decoded into an :class:`IntersectionSpec`.

Every gene lies in [0, 1] (one mutation scale fits all of them); ``decode`` maps it to its value:

* gene 0, legs: ``3 + floor(5 x)`` (3 to 7); genes 1 and 2, turn lanes and U-turns: on at 0.5 or more;
* gene 3, ``width``: the level every leg's lane counts lean to (below); gene 4, ``evenness``: how far the legs'
  angles are pulled towards an even spread (0: as their own gap genes say, 1: 360 / legs apart);
* per leg slot k = 0..6 (slots past the leg count are ignored), five genes: ``gap`` (the angle before the leg as a share
  of the full turn, ``0.05 + 0.95 g``, with ``g = (1 - evenness) x + evenness / 2``; the shares of the legs used are
  scaled to 360 degrees, the first leg at heading 0, so no gap is under 3 degrees), lanes ``in`` and ``out``
  (``1 + floor(3 (x + width) / 2)``), ``median`` (on at 0.5 or more) and ``bend`` (the approach road's bend halfway
  out, ``(2 x - 1)**3 * 45`` degrees: mostly small).

Why the two shared genes: a junction's paved area grows with the lanes of all its legs, and its smallest angle is
widest when the legs are evenly spread. With per-leg genes alone both are sums or minima of independent draws, which
crowd the middle: a junction with one lane on every leg, or three, or with seven evenly spread legs, is a corner of
the box that neither random vectors nor a mutation of a few genes reach. One gene moving every leg's lanes, or every
angle towards the even spread, makes those corners one step away, and the search's mutations walk along them.
Measured (``benchmarks/bench_search.py``, seed 0, 480 maps, the default grid; the search's results depend only on its
seed and settings): 155 filled cells and QD-score 34.4 against 136 and 29.6 with the per-leg genes alone; random
generation as ``era`` samples it fills 46 (23.3). Of 80 uniform random vectors, all gave a feasible map.

The median width is 6 m on legs with a median (room for a U-turn lane; the default 2 m never allows one), lanes 3.5 m,
approaches 150 m, traffic on the right, split-first. A vector decodes to exactly one description (a pure function),
so a map is a function of its vector: the search keeps vectors and regenerates an elite's map when it writes it.
"""

from __future__ import annotations

import math

import numpy as np

from ..intersection import MAX_LEGS, MIN_LEGS, IntersectionSpec, LegSpec

#: Genes per leg slot: gap, in, out, median, bend.
PER_LEG = 5
#: Genes before the leg slots: legs, turn lanes, U-turns, width, evenness.
HEAD = 5
DIM = HEAD + MAX_LEGS * PER_LEG
#: Largest bend (degrees) of an approach road.
BEND = 45.0
#: Median width (m) of legs with a median.
MEDIAN_WIDTH = 6.0
#: Smallest share of the full turn a gap gene gives.
MIN_SHARE = 0.05


def _level(x: float, lo: int, count: int) -> int:
    """``lo + floor(count x)``, the top of the interval included in the last level."""
    return lo + min(math.floor(count * x), count - 1)


def random_genomes(rng: np.random.Generator, n: int, dim: int = DIM) -> np.ndarray:
    """``n`` vectors of ``dim`` genes drawn uniformly in the unit box."""
    return rng.random((n, dim))


def decode(x: np.ndarray | list[float]) -> IntersectionSpec:
    """The description a vector stands for (values outside the unit box are clipped into it first)."""
    v = np.clip(np.asarray(x, dtype=float), 0.0, 1.0)
    n = _level(v[0], MIN_LEGS, MAX_LEGS - MIN_LEGS + 1)
    width, evenness = float(v[3]), float(v[4])
    slots = v[HEAD:].reshape(MAX_LEGS, PER_LEG)[:n]
    shares = MIN_SHARE + (1 - MIN_SHARE) * ((1 - evenness) * slots[:, 0] + evenness / 2)
    shares /= shares.sum()
    headings = 360.0 * np.concatenate([[0.0], np.cumsum(shares[1:])])
    legs = tuple(
        LegSpec(
            heading=round(float(h), 6),
            lanes_in=_level((s[1] + width) / 2, 1, 3),
            lanes_out=_level((s[2] + width) / 2, 1, 3),
            median=bool(s[3] >= 0.5),
            bend=round((2 * float(s[4]) - 1) ** 3 * BEND, 6),
        )
        for h, s in zip(headings, slots)
    )
    return IntersectionSpec(legs, turn_lanes=bool(v[1] >= 0.5), u_turns=bool(v[2] >= 0.5), median_width=MEDIAN_WIDTH)
