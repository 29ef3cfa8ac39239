"""Second-order jets: a function of ``s`` carried as value, first and second derivative arrays.

Lane borders are sums and products of cubic profiles (and of ``cos``/``sin`` of the superelevation); carrying their
derivatives along exactly gives lane headings and offset-curve curvatures without finite differences.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True, slots=True)
class Jet:
    """Values and their first and second derivatives at the same points."""

    v: np.ndarray
    d1: np.ndarray
    d2: np.ndarray

    @staticmethod
    def zero(n: int) -> Jet:
        return Jet(np.zeros(n), np.zeros(n), np.zeros(n))

    def __add__(self, other: Jet) -> Jet:
        return Jet(self.v + other.v, self.d1 + other.d1, self.d2 + other.d2)

    def __sub__(self, other: Jet) -> Jet:
        return Jet(self.v - other.v, self.d1 - other.d1, self.d2 - other.d2)

    def __neg__(self) -> Jet:
        return Jet(-self.v, -self.d1, -self.d2)

    def __mul__(self, other: Jet) -> Jet:
        return Jet(
            self.v * other.v,
            self.d1 * other.v + self.v * other.d1,
            self.d2 * other.v + 2.0 * self.d1 * other.d1 + self.v * other.d2,
        )

    def scale(self, k: float) -> Jet:
        return Jet(k * self.v, k * self.d1, k * self.d2)

    def cos(self) -> Jet:
        c, s = np.cos(self.v), np.sin(self.v)
        return Jet(c, -s * self.d1, -c * self.d1 * self.d1 - s * self.d2)

    def sin(self) -> Jet:
        c, s = np.cos(self.v), np.sin(self.v)
        return Jet(s, c * self.d1, -s * self.d1 * self.d1 + c * self.d2)
