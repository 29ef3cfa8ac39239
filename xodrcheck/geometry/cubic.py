"""Parametric cubic curves ``(U(p), V(p))`` and their arc length, shared by poly3 and paramPoly3.

The arc length ``L(p) = integral_0^p |C'(q)| dq`` is tabulated at panel boundaries by Gauss-Legendre quadrature (the
number of panels is doubled until the total length agrees to 1e-15 relative), then inverted pointwise by Newton's
method, ``p <- p - (L(p) - sigma) / |C'(p)|``, where ``L(p)`` is the tabulated value at the panel start plus one more
Gauss-Legendre integral over the rest. Everything is vectorised over the query points.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(16)
_MAX_PANELS = 1 << 14
_NEWTON_STEPS = 12
_NEWTON_TOL = 1e-13  # m, residual of L(p) - sigma at which Newton stops


def _horner(coef: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Value and first three derivatives of ``a + b p + c p^2 + d p^3``."""
    a, b, c, d = coef
    return (
        a + p * (b + p * (c + p * d)),
        b + p * (2.0 * c + p * (3.0 * d)),
        2.0 * c + p * (6.0 * d),
        np.full_like(p, 6.0 * d),
    )


@dataclass(frozen=True, eq=False)
class CubicCurve:
    """``C(p) = (U(p), V(p))`` with ``U``, ``V`` cubic (coefficients a, b, c, d) and arc-length tables on
    ``[0, p_max]`` (evaluation and inversion also work, less sharply, slightly outside)."""

    u: np.ndarray
    v: np.ndarray
    breaks: np.ndarray  # panel boundaries in p
    cumulative: np.ndarray  # arc length at each boundary

    @classmethod
    def build(cls, u, v, p_max: float) -> CubicCurve:
        u = np.asarray(u, dtype=float)
        v = np.asarray(v, dtype=float)
        panels = 8
        lengths = _panel_lengths(u, v, np.linspace(0.0, p_max, panels + 1))
        while panels < _MAX_PANELS:
            finer = _panel_lengths(u, v, np.linspace(0.0, p_max, 2 * panels + 1))
            panels *= 2
            converged = abs(finer.sum() - lengths.sum()) <= 1e-15 * max(finer.sum(), 1e-300)
            lengths = finer
            if converged:
                break
        breaks = np.linspace(0.0, p_max, panels + 1)
        return cls(u, v, breaks, np.concatenate(([0.0], np.cumsum(lengths))))

    @property
    def total(self) -> float:
        return float(self.cumulative[-1])

    def speed(self, p: np.ndarray) -> np.ndarray:
        return np.hypot(_horner(self.u, p)[1], _horner(self.v, p)[1])

    def parameter_at(self, sigma: np.ndarray) -> np.ndarray:
        """The parameter ``p`` at arc length ``sigma`` from ``p = 0`` (inverse of :meth:`arc_length`)."""
        sigma = np.asarray(sigma, dtype=float)
        last = len(self.breaks) - 2
        k = np.clip(np.searchsorted(self.cumulative, sigma, side="right") - 1, 0, last)
        span = self.cumulative[k + 1] - self.cumulative[k]
        fraction = np.divide(sigma - self.cumulative[k], span, out=np.zeros_like(sigma), where=span > 0)
        p = self.breaks[k] + fraction * (self.breaks[k + 1] - self.breaks[k])
        tiny = 1e-300
        for _ in range(_NEWTON_STEPS):
            residual = self._from_panel(k, p) - sigma
            p = p - residual / np.maximum(self.speed(p), tiny)
            if not np.any(np.abs(residual) > _NEWTON_TOL):
                break
        return p

    def derivatives(self, p: np.ndarray):
        """``(U, U', U'', U''')`` and ``(V, V', V'', V''')`` at ``p``."""
        return _horner(self.u, p), _horner(self.v, p)

    def _from_panel(self, k: np.ndarray, p: np.ndarray) -> np.ndarray:
        start = self.breaks[k]
        half = 0.5 * (p - start)
        nodes = start[:, None] + half[:, None] * (_NODES[None, :] + 1.0)
        return self.cumulative[k] + half * (self.speed(nodes) @ _WEIGHTS)


def _panel_lengths(u: np.ndarray, v: np.ndarray, breaks: np.ndarray) -> np.ndarray:
    half = 0.5 * np.diff(breaks)
    nodes = breaks[:-1, None] + half[:, None] * (_NODES[None, :] + 1.0)
    speed = np.hypot(_horner(u, nodes)[1], _horner(v, nodes)[1])
    return half * (speed @ _WEIGHTS)


def frame(curve: CubicCurve, p: np.ndarray):
    """Local position, tangent angle, curvature and its arc-length derivative of ``curve`` at parameters ``p``.

    Returns ``(U, V, angle, curvature, dcurvature)`` with ``angle = atan2(V', U')`` in (-pi, pi], curvature
    ``(U'V'' - V'U'') / |C'|^3`` and its derivative with respect to arc length (chain rule through ``|C'|``).
    """
    (u0, u1, u2, u3), (v0, v1, v2, v3) = curve.derivatives(p)
    speed2 = u1 * u1 + v1 * v1
    speed = np.sqrt(speed2)
    cross = u1 * v2 - v1 * u2
    dcross = u1 * v3 - v1 * u3
    dspeed = (u1 * u2 + v1 * v2) / np.where(speed > 0, speed, np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        curvature = cross / (speed2 * speed)
        dcurvature = (dcross / (speed2 * speed) - 3.0 * cross * dspeed / (speed2 * speed2)) / speed
    return u0, v0, np.arctan2(v1, u1), curvature, dcurvature
