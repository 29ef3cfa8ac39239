"""Poses along a curve: position, heading and curvature as parallel numpy arrays."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True, slots=True)
class Pose:
    """Points of a plane curve parametrised by arc length.

    ``hdg`` is the tangent direction (rad, not wrapped: it grows continuously along an element), ``curvature`` is
    signed (positive turning left, 1/m) and ``dcurvature`` is its derivative with respect to arc length (1/m^2),
    which the curvature of offset curves (lane borders) needs.
    """

    x: np.ndarray
    y: np.ndarray
    hdg: np.ndarray
    curvature: np.ndarray
    dcurvature: np.ndarray

    def __len__(self) -> int:
        return len(self.x)

    @staticmethod
    def empty(n: int) -> Pose:
        """``n`` poses filled with NaN (to be assigned piecewise)."""
        return Pose(*(np.full(n, np.nan) for _ in range(5)))

    def assign(self, index: np.ndarray | slice, other: Pose) -> None:
        """Write ``other`` into the positions ``index`` of this pose's arrays (the arrays are mutable, the fields
        not)."""
        self.x[index] = other.x
        self.y[index] = other.y
        self.hdg[index] = other.hdg
        self.curvature[index] = other.curvature
        self.dcurvature[index] = other.dcurvature


def filled(value, like: np.ndarray) -> np.ndarray:
    """A new array shaped as ``like`` holding ``value`` (a number, or an array of that shape)."""
    out = np.empty_like(like)
    out[...] = value
    return out


def as_array(ds) -> np.ndarray:
    """A 1-D float array (scalars become length-1 arrays)."""
    if type(ds) is np.ndarray and ds.dtype == np.float64 and ds.ndim == 1:
        return ds  # the common case, without the conversion calls
    return np.atleast_1d(np.asarray(ds, dtype=float))
