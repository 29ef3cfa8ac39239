"""Lane lines in plan view: curves at a lateral offset from a road's reference line, with their heading, curvature
and speed.

A line is the offset curve ``P = R(s) + q(s) N(s)`` of the reference line ``R`` (``q``: the plan-view lateral
offset, ``N``: the left normal), lifted ``height`` above the road's elevation. With ``q'`` and ``q''`` carried exactly
(:mod:`xodrcheck.geometry.jet`) its heading is ``theta + atan2(q', 1 - q k)`` and its curvature
``(A^2 k + A q'' + 2 q'^2 k + q q' k') / (A^2 + q'^2)^(3/2)``, ``A = 1 - q k``: widening lanes contribute their width
change. :class:`Lines` holds many lines as flat (line, sample) pairs and places them (:func:`bend` and the formulas of
:meth:`Lines.points`) elementwise, so a line's numbers never depend on the others evaluated with it.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from xodrcheck.geometry.pose import Pose


@dataclass(frozen=True, slots=True)
class LanePoints:
    """Points on a lane line (centre or a border): inertial x, y, z, plan-view heading and curvature, and ``speed``,
    the plan-view length of the line per metre of reference-line ``s`` (``integral speed ds`` is the line's length)."""

    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    hdg: np.ndarray
    curvature: np.ndarray
    speed: np.ndarray

    def part(self, lo: int, hi: int) -> LanePoints:
        """Points ``lo:hi`` (views)."""
        return LanePoints(
            self.x[lo:hi], self.y[lo:hi], self.z[lo:hi], self.hdg[lo:hi], self.curvature[lo:hi], self.speed[lo:hi]
        )


class Samples(Protocol):
    """What lines are placed on: the reference poses and elevation at the samples, and the heading's sine and cosine
    (:class:`xodrcheck.geometry.batch.Evaluation`)."""

    @property
    def pose(self) -> Pose: ...

    @property
    def elevation(self) -> np.ndarray: ...

    def heading(self) -> tuple[np.ndarray, np.ndarray]: ...


def bend(q, dq, ddq, k, dk) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``A = 1 - q k``, the plan-view speed and the curvature of the offset curve at lateral offset ``q`` (with its
    derivatives) of a curve of curvature ``k`` and curvature derivative ``dk``."""
    a = 1.0 - q * k
    speed = np.hypot(a, dq)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        return a, speed, (a * a * k + a * ddq + 2.0 * dq * dq * k + q * dq * dk) / speed**3


class Lines:
    """Lines as flat pairs: pair ``i`` lies at sample ``sample[i]`` of ``at`` with plan-view lateral offset
    ``lateral[:, i]`` (a jet: value, first and second derivative) and ``height`` above the road's elevation (a number
    or one per pair); line ``j`` is pairs ``starts[j]:starts[j + 1]``."""

    __slots__ = ("_bend", "at", "height", "lateral", "sample", "starts")

    def __init__(self, at: Samples, sample: np.ndarray, lateral: np.ndarray, height, starts: np.ndarray):
        self.at = at
        self.sample = sample
        self.lateral = lateral
        self.height = height
        self.starts = starts
        self._bend: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None

    def __len__(self) -> int:
        return len(self.starts) - 1

    def bend(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``A``, speed and curvature of every pair (:func:`bend`; computed once)."""
        if self._bend is None:
            pose, at = self.at.pose, self.sample
            q, dq, ddq = self.lateral
            self._bend = bend(q, dq, ddq, pose.curvature[at], pose.dcurvature[at])
        return self._bend

    def xy(self, pairs: np.ndarray | slice | None = None) -> tuple[np.ndarray, np.ndarray]:
        """Plan-view ``x``, ``y`` of some pairs (all: ``None``)."""
        pick = slice(None) if pairs is None else pairs
        at, q = self.sample[pick], self.lateral[0, pick]
        sin_hdg, cos_hdg = self.at.heading()
        pose = self.at.pose
        return pose.x[at] - q * sin_hdg[at], pose.y[at] + q * cos_hdg[at]

    def z(self) -> np.ndarray:
        return self.at.elevation[self.sample] + self.height

    def points(self) -> LanePoints:
        """Every pair placed: x, y, z, heading, curvature and speed."""
        a, speed, curvature = self.bend()
        x, y = self.xy()
        hdg = self.at.pose.hdg[self.sample] + np.arctan2(self.lateral[1], a)
        return LanePoints(x, y, self.z(), hdg, curvature, speed)

    def tightest(self, bound: float) -> list[tuple[int, int] | None]:
        """:func:`tightest` of these lines."""
        _, speed, curvature = self.bend()
        return tightest(curvature, speed, self.starts, bound)


def tightest(
    curvature: np.ndarray, speed: np.ndarray, starts: np.ndarray, bound: float
) -> list[tuple[int, int] | None]:
    """For each line (pairs ``starts[j]:starts[j + 1]``), ``(pair, index in the line)`` of its largest
    ``|curvature|`` where it moves (``speed > 0``; NaN and infinities taken as 0, the first of equal ones) when that is
    above ``bound``, else ``None``."""
    lines = len(starts) - 1
    if lines <= 0:
        return []
    k = np.abs(np.nan_to_num(np.where(speed > 0, curvature, 0.0), nan=0.0, posinf=0.0, neginf=0.0))
    filled = np.diff(starts) > 0
    most = np.zeros(lines)
    if filled.any():
        most[filled] = np.maximum.reduceat(k, starts[:-1][filled])
    out: list[tuple[int, int] | None] = [None] * lines
    for j in np.flatnonzero(most > bound):
        lo, hi = int(starts[j]), int(starts[j + 1])
        i = int(np.argmax(k[lo:hi]))
        out[int(j)] = (lo + i, i)
    return out


def split(points: LanePoints, starts: Sequence[int] | np.ndarray) -> list[LanePoints]:
    """``points`` cut at ``starts`` (``starts[j]:starts[j + 1]``: line ``j``), as views."""
    return [points.part(int(lo), int(hi)) for lo, hi in itertools.pairwise(starts)]
