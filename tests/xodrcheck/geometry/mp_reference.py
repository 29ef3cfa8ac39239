"""High-precision references for the geometry tests: mpmath quadrature at 30 significant digits.

Every value here is computed from the defining integral, independently of the code under test.
"""

from __future__ import annotations

import itertools
import math

import mpmath as mp

DIGITS = 30


def heading_curve(x0, y0, heading, ds, max_turn=0.5):
    """Point at arc length ``ds`` of the curve starting at (x0, y0) whose heading is ``heading(t)`` (an mpmath
    function of the arc length ``t``): ``(x0, y0) + integral_0^ds (cos, sin)(heading(t)) dt``.

    The interval is cut where the heading has turned by about ``max_turn`` rad, so each quadrature piece is smooth.
    """
    with mp.workdps(DIGITS):
        ds = mp.mpf(ds)
        probe = [heading(ds * i / 64) for i in range(65)]
        turn = sum(abs(b - a) for a, b in itertools.pairwise(probe))
        pieces = max(4, math.ceil(float(turn) / max_turn))
        nodes = [ds * i / pieces for i in range(pieces + 1)]
        x = mp.mpf(x0) + mp.quad(lambda t: mp.cos(heading(t)), nodes)
        y = mp.mpf(y0) + mp.quad(lambda t: mp.sin(heading(t)), nodes)
        return float(x), float(y)


class Cubic2D:
    """``(U(p), V(p))`` with cubic U, V given as (a, b, c, d); arc length and its inverse in mpmath."""

    def __init__(self, u, v, p_max, pieces=2):
        with mp.workdps(DIGITS):
            self.u = [mp.mpf(c) for c in u]
            self.v = [mp.mpf(c) for c in v]
            self.p_max = mp.mpf(p_max)
        self.pieces = pieces
        self._total = None

    @staticmethod
    def _d(coef, p, order):
        a, b, c, d = coef
        return [a + p * (b + p * (c + p * d)), b + p * (2 * c + 3 * d * p), 2 * c + 6 * d * p, 6 * d][order]

    def point(self, p):
        return self._d(self.u, p, 0), self._d(self.v, p, 0)

    def speed(self, p):
        return mp.sqrt(self._d(self.u, p, 1) ** 2 + self._d(self.v, p, 1) ** 2)

    def length(self, p):
        nodes = [p * i / self.pieces for i in range(self.pieces + 1)]
        return mp.quad(self.speed, nodes)

    def total(self):
        if self._total is None:
            self._total = self.length(self.p_max)
        return self._total

    def parameter(self, sigma):
        """``p`` with ``length(p) == sigma`` (Newton iteration started from the proportional guess)."""
        total = self.total()
        if sigma == 0 or total == 0:
            return mp.mpf(0)
        return mp.findroot(
            lambda p: self.length(p) - sigma,
            self.p_max * sigma / total,
            solver="newton",
            df=self.speed,
            tol=mp.mpf(10) ** (-2 * DIGITS + 8),
        )

    def curvature(self, p):
        u1, u2 = self._d(self.u, p, 1), self._d(self.u, p, 2)
        v1, v2 = self._d(self.v, p, 1), self._d(self.v, p, 2)
        return (u1 * v2 - v1 * u2) / (u1 * u1 + v1 * v1) ** mp.mpf(1.5)

    def angle(self, p):
        return mp.atan2(self._d(self.v, p, 1), self._d(self.u, p, 1))


def place(x0, y0, hdg, u, v):
    """Local (u, v) of an element at (x0, y0) with heading hdg, to inertial (x, y), in mpmath."""
    c, s = mp.cos(mp.mpf(hdg)), mp.sin(mp.mpf(hdg))
    return float(mp.mpf(x0) + c * u - s * v), float(mp.mpf(y0) + s * u + c * v)
