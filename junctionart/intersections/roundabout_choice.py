"""Which junctions become roundabouts, and of what size: drawn, asked for by a control-line file, or described.

A junction of :data:`MIN_ARMS` to :data:`MAX_ARMS` legs becomes a roundabout when a control-line file asks for one
near it (:class:`junctionart.controllines.RoundaboutRequest`, within :data:`MATCH` of the junction's control point)
or when a draw is below ``roundabout_probability``. The draw and the size come from a generator seeded with the
control point's coordinates, not from the map's random stream, so a map with the probability at 0 draws nothing (the
paper's maps stay byte-identical) and a junction's fate does not depend on the order in which junctions are planned.

Sizes (the outer radius of the circulating carriageway, half the inscribed circle): a *mini* roundabout of 9-13 m,
a *compact* one of 13-20 m and a *large* one of 20-35 m (the ranges of common design guides for inscribed circles of
18-70 m), one circulating lane, or two on a large one half the time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..controllines import RoundaboutRequest
from ..params import Params

#: Arms a roundabout may have.
MIN_ARMS, MAX_ARMS = 3, 6
#: A request applies to the junction whose control point is nearest to it, within this distance (m).
MATCH = 60.0
#: (name, share of drawn roundabouts, smallest and largest outer radius in m).
SIZES = (("mini", 0.2, 9.0, 13.0), ("compact", 0.5, 13.0, 20.0), ("large", 0.3, 20.0, 35.0))
#: Share of large roundabouts drawn with two circulating lanes.
TWO_LANES = 0.5
#: Largest outer radius (m) a roundabout grows to when its arms need room (a drawn one: at most by :data:`DRAWN_GROWTH`
#: or 10 m, whichever is more; a junction whose arms need more becomes an ordinary junction).
MAX_RADIUS = 60.0
DRAWN_GROWTH = 1.5


@dataclass(frozen=True)
class RoundaboutSpec:
    """What a roundabout is asked to be: the outer radius (m) of its circulating carriageway and its lanes, and the
    largest radius it may grow to where its arms need room (None: :data:`MAX_RADIUS`, or ``radius`` if larger)."""

    radius: float
    lanes: int = 1
    limit: float | None = None

    @property
    def largest(self) -> float:
        return self.limit if self.limit is not None else max(MAX_RADIUS, self.radius)


def _rng(xy: tuple[float, float]) -> np.random.Generator:
    words = np.frombuffer(np.array(xy, dtype=np.float64).tobytes(), dtype=np.uint32)
    return np.random.default_rng([*words.tolist(), 28])


def drawn(rng: np.random.Generator) -> RoundaboutSpec:
    """A size class, a radius within it and the circulating lanes, from ``rng``."""
    shares = np.array([share for _, share, _, _ in SIZES])
    name, _, lo, hi = SIZES[int(rng.choice(len(SIZES), p=shares / shares.sum()))]
    radius = round(float(rng.uniform(lo, hi)), 3)
    lanes = 2 if name == "large" and rng.random() < TWO_LANES else 1
    return RoundaboutSpec(radius, lanes, round(min(MAX_RADIUS, max(DRAWN_GROWTH * radius, radius + 10.0)), 3))


def choose(
    xy: tuple[float, float], legs: int, params: Params, request: RoundaboutRequest | None = None
) -> RoundaboutSpec | None:
    """The roundabout a junction of ``legs`` legs at control point ``xy`` becomes (``request``: the one a control-line
    file asks for there, its missing values drawn), or None for an ordinary junction."""
    if not MIN_ARMS <= legs <= MAX_ARMS:
        return None
    rng = _rng(xy)
    if request is not None:
        spec = drawn(rng)
        return RoundaboutSpec(request.radius or spec.radius, request.lanes or spec.lanes)  # may grow to MAX_RADIUS
    if params.roundabout_probability <= 0.0 or rng.random() >= params.roundabout_probability:
        return None
    return drawn(rng)


def nearest_requests(
    requests: tuple[RoundaboutRequest, ...], points: dict[int, tuple[float, float]]
) -> dict[int, RoundaboutRequest]:
    """Each request's junction (node -> request): the nearest of ``points`` within :data:`MATCH`; a node asked for
    twice keeps the nearer request."""
    out: dict[int, tuple[float, RoundaboutRequest]] = {}
    for req in requests:
        best = min(points, key=lambda n: (math.dist(points[n], req.at), n), default=None)
        if best is None or math.dist(points[best], req.at) > MATCH:
            continue
        d = math.dist(points[best], req.at)
        if best not in out or d < out[best][0]:
            out[best] = (d, req)
    return {n: req for n, (_, req) in out.items()}
