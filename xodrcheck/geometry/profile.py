"""Piecewise cubic profiles (lane width and border, laneOffset, elevation, superelevation), vectorised over ``s``.

At ``s`` the record in force is the last one whose start is at or before ``s`` (for equal starts, the later one in
the file), and the value is ``a + b ds + c ds^2 + d ds^3`` with ``ds = s - start``. The last record holds to the end
(the standard: "valid until the next element starts or the road reference line ends"; for lane records "until ... the
lane section ends").

Decisions
---------
* An empty profile is 0 everywhere: the standard's defaults are zero elevation, zero superelevation and no lane offset.
* Before the first record the value is also 0, not the first record extrapolated backwards: the standard gives every
  record a start and says what holds from there on, so before the first start no record is in force and the default
  (zero) applies. For lane widths this makes a lane whose first ``<width>`` starts at ``sOffset > 0`` zero-wide until
  then, which the lane rules can report, rather than inventing a width the file did not give.

``origin`` shifts every record start (lane records keep ``sOffset`` relative to their lane section: pass the section's
``s`` as ``origin`` and absolute ``s``).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from xodrcheck.geometry.pose import as_array
from xodrcheck.model import Profile


class Piecewise:
    """A profile compiled for fast repeated evaluation (record starts shifted by ``origin``, sorted)."""

    __slots__ = ("coefficients", "starts")

    def __init__(self, profile: Profile, origin: float = 0.0):
        records = sorted(profile, key=lambda r: r.s)  # stable: equal starts keep file order
        self.starts = np.array([r.s + origin for r in records], dtype=float)
        self.coefficients = np.array([[r.a, r.b, r.c, r.d] for r in records], dtype=float).reshape(-1, 4)

    def jet(self, s) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Value, first and second derivative at ``s``."""
        s = as_array(s)
        if len(self.starts) == 0:
            return np.zeros_like(s), np.zeros_like(s), np.zeros_like(s)
        if len(self.starts) == 1:
            ds = s - self.starts[0]
            a, b, c, d = self.coefficients[0]
            active = ds >= 0
        else:
            index = np.searchsorted(self.starts, s, side="right") - 1
            active = index >= 0
            index = np.maximum(index, 0)
            ds = s - self.starts[index]
            a, b, c, d = self.coefficients[index].T
        value = a + ds * (b + ds * (c + ds * d))
        first = b + ds * (2.0 * c + ds * 3.0 * d)
        second = 2.0 * c + 6.0 * d * ds
        if active.all():
            return value, first, second
        return np.where(active, value, 0.0), np.where(active, first, 0.0), np.where(active, second, 0.0)


@lru_cache(maxsize=16384)
def compiled(profile: Profile, origin: float = 0.0) -> Piecewise:
    """The cached :class:`Piecewise` of a profile."""
    return Piecewise(profile, origin)


def jet(profile: Profile, s, origin: float = 0.0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Value, first and second derivative at ``s`` in one lookup."""
    return compiled(profile, origin).jet(s)


def evaluate(profile: Profile, s, origin: float = 0.0) -> np.ndarray:
    return jet(profile, s, origin)[0]


def derivative(profile: Profile, s, origin: float = 0.0) -> np.ndarray:
    return jet(profile, s, origin)[1]


def second_derivative(profile: Profile, s, origin: float = 0.0) -> np.ndarray:
    return jet(profile, s, origin)[2]


def breakpoints(profile: Profile, origin: float = 0.0) -> np.ndarray:
    """Record starts (shifted by ``origin``), sorted."""
    return compiled(profile, origin).starts
