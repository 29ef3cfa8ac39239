"""The legs of a junction: the roads meeting at one node, and the angular gaps between neighbouring legs.

A gap between two neighbouring legs decides three things in stage 3: which leg goes when a node has too many (the
one after the narrowest gap), which legs are too close to build (gaps under ``min_leg_angle``) and how far the
incident points sit from the control point (a narrow gap pushes them out). All three read :func:`neighbour_gaps`,
so they agree on what a gap is.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import NamedTuple

MAX_LEGS = 7  #: most legs a junction may have (the paper builds three- to seven-way intersections)


class LegKey(NamedTuple):
    """Names a leg for one pass: the road (chain index) and which of its ends meets the junction."""

    chain: int
    at_start: bool


@dataclass(frozen=True)
class Leg:
    """A leg of an intersection: its node and edge, heading, lanes in and out, and whether it has a median."""

    key: tuple[int, int]  #: (node, edge of the leg at the node): stable while repairs change the network
    angle: float  #: heading of the leg leaving the node
    n_in: int  #: lanes travelling into the node
    n_out: int  #: lanes travelling away from the node
    median: bool
    road: int = -1  #: the road (chain) the leg belongs to: two legs of one road are a loop back to the junction


class Gap(NamedTuple):
    """The angle from one leg to the next counter-clockwise (legs named by their index in the list given)."""

    angle: float  #: in [0, 2 pi)
    first: int
    second: int


def neighbour_gaps(legs: Sequence[Leg]) -> list[Gap]:
    """Each leg's gap to its counter-clockwise neighbour, counter-clockwise from the leg of smallest heading (legs of
    equal heading in list order). Sorting the result orders the gaps narrowest first, ties by leg index."""
    order = sorted(range(len(legs)), key=lambda i: legs[i].angle)
    return [Gap((legs[b].angle - legs[a].angle) % (2 * math.pi), a, b) for a, b in zip(order, order[1:] + order[:1])]
