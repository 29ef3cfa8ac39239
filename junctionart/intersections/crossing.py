"""Connection lanes leaving one incoming road must not cross (xodrcheck's J101 rule, checked here before writing).

Paths from different lanes keep :data:`CLEARANCE` apart; two paths from the same lane start together and are compared
from where they have parted by :data:`PARTED`, after which they must stay :data:`TOUCH` apart.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import shapely

from ..curves import HermiteFit
from ..errors import GenerationError


class LinkFit(NamedTuple):
    """One lane link of a junction with its fitted connection geometry (``fit`` None: no curve met the bound)."""

    leg_in: int
    lane_in: int  #: k, 1 = next to the centre
    leg_out: int
    lane_out: int
    id_in: int  #: lane id on the incoming road
    id_out: int  #: lane id on the outgoing road
    start: tuple[float, float]
    hdg: float
    fit: HermiteFit | None

    def curve(self) -> HermiteFit:
        """The fitted curve, of a link known to have one (a guard: the links compared or built all have one)."""
        if self.fit is None:
            raise GenerationError(
                f"link from leg {self.leg_in} to leg {self.leg_out} has no curve; please report the seed"
            )
        return self.fit


_P_CROSS = np.linspace(0.0, 1.0, 129)
CLEARANCE = 0.1  #: paths from different lanes of one road stay at least this far apart (m)
PARTED = 0.05  #: paths from one lane are compared from where they are this far apart (m)
TOUCH = 0.01  #: ... and must then stay this far apart
WINDOW = 2
HEAD = 16  #: samples searched for the point where two paths from one lane part


def crossing(rows: list[LinkFit], skip: set[int]) -> set[int]:
    """Links whose centre line crosses that of a link leaving another lane of the same incoming leg (the one of each
    crossing pair that comes later in the plan's order)."""
    by_leg: dict[int, list[int]] = {}
    for n, r in enumerate(rows):
        if n not in skip:
            by_leg.setdefault(r.leg_in, []).append(n)
    pairs = [(a, b) for group in by_leg.values() for i, a in enumerate(group) for b in group[i + 1 :]]
    if not pairs:
        return set()
    idx = sorted({n for pair in pairs for n in pair})
    pos = {n: k for k, n in enumerate(idx)}
    coef = np.array([rows[n].curve().coef for n in idx])
    p = _P_CROSS[None, :]
    u = coef[:, 0:1] + p * (coef[:, 1:2] + p * (coef[:, 2:3] + p * coef[:, 3:4]))
    v = coef[:, 4:5] + p * (coef[:, 5:6] + p * (coef[:, 6:7] + p * coef[:, 7:8]))
    x0 = np.array([rows[n].start[0] for n in idx])[:, None]
    y0 = np.array([rows[n].start[1] for n in idx])[:, None]
    h = np.array([rows[n].hdg for n in idx])[:, None]
    xy = np.stack([x0 + np.cos(h) * u - np.sin(h) * v, y0 + np.sin(h) * u + np.cos(h) * v], axis=-1)
    lines = shapely.linestrings(xy)
    pa = np.array([pos[x] for x, _ in pairs])
    pb = np.array([pos[y] for _, y in pairs])
    same = np.array([rows[x].lane_in == rows[y].lane_in for x, y in pairs])
    diff = ~same
    # one dwithin call for every pair: whole paths (different lanes) or their parted tails (one lane)
    first = np.empty(len(pairs), dtype=object)
    second = np.empty(len(pairs), dtype=object)
    gap = np.where(same, TOUCH, CLEARANCE)
    test = diff.copy()
    first[diff], second[diff] = lines[pa[diff]], lines[pb[diff]]
    if same.any():
        # two paths from one lane start together: compare them from where they have parted (both ways in one batch)
        sa, sb = pa[same], pb[same]
        k = len(sa)
        tails, parted = _parted(np.concatenate([xy[sa], xy[sb]]), np.concatenate([xy[sb], xy[sa]]))
        where = np.flatnonzero(same)
        first[where], second[where] = tails[:k], tails[k:]
        test[where] = parted[:k] & parted[k:]
    hit = np.zeros(len(pairs), dtype=bool)
    if test.any():
        a = first[test]
        shapely.prepare(a)  # an indexed distance: far fewer segment pairs measured than the plain one
        hit[test] = shapely.dwithin(a, second[test], gap[test])
    return {pairs[k][1] for k in np.flatnonzero(hit)}


def _parted(xy: np.ndarray, other: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per row of ``xy`` (paths x samples x 2): the polyline from the first sample further than PARTED from the
    matching row of ``other`` on, and whether there is one. Distances are to the segments of ``other`` within
    WINDOW samples (both paths start together, so the nearest point is near the same parameter)."""
    n, m, _ = xy.shape
    head = min(m, HEAD)
    seg0, seg1 = other[:, :-1], other[:, 1:]
    base = np.arange(head)
    j = np.minimum(np.maximum(base[None, :] + np.arange(-WINDOW, WINDOW + 1)[:, None], 0), m - 2)  # window x head
    nx, ny = xy[:, None, :head, 0], xy[:, None, :head, 1]
    ax, ay = seg0[:, j, 0], seg0[:, j, 1]
    abx, aby = seg1[:, j, 0] - ax, seg1[:, j, 1] - ay
    t = np.minimum(
        np.maximum(((nx - ax) * abx + (ny - ay) * aby) / np.maximum(abx * abx + aby * aby, 1e-300), 0.0), 1.0
    )
    dist = np.hypot(ax + t * abx - nx, ay + t * aby - ny).min(axis=1)
    far = dist > PARTED
    # not parted within the head: compare from the end of the head (they run together there: a near-touch)
    first = np.where(far.any(axis=1), far.argmax(axis=1), head - 1)
    ok = first <= m - 2
    first = np.minimum(first, m - 2)
    keep = np.arange(m)[None, :] >= first[:, None]
    return shapely.linestrings(xy[keep], indices=np.repeat(np.arange(n), keep.sum(axis=1))), ok
