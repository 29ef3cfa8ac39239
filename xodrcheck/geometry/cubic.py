"""Parametric cubic curves ``(U(p), V(p))`` and their arc length, shared by poly3 and paramPoly3.

The arc length ``L(p) = integral_0^p |C'(q)| dq`` is tabulated once per curve at panel boundaries by Gauss-Legendre
quadrature (the number of panels is doubled until the total length agrees to 1e-15 relative), together with the
speed ``|C'|`` there. It is inverted, for all query points at once, by Newton's method,
``p <- p - (L(p) - sigma) / |C'(p)|``, where ``L(p)`` is the tabulated value at the panel start plus one more
Gauss-Legendre integral over the rest. The first guess is the cubic Hermite interpolant of ``p(sigma)`` on the panel
(values and slopes ``1 / |C'|`` at both boundaries; the tables start at 32 panels, so that this guess is typically
within 1e-9 of the root), and one Newton step usually reaches double precision. Iteration stops as soon as the residual
left after the step just taken, predicted from the
second-order term ``|C'|' dp^2 / 2`` with a wide margin, is under the tolerance (rather than paying one more
quadrature to measure it), or the measured residual already is.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from xodrcheck.geometry.pose import Pose

_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(16)
_UNIT_NODES = 0.5 * (_NODES + 1.0)  # the nodes on [0, 1]
_FIRST_PANELS = 32  # fine enough for the Hermite first guess to be within ~1e-9 of the root
_MAX_PANELS = 1 << 14
_NEWTON_STEPS = 12
_NEWTON_TOL = 1e-13  # m, residual of L(p) - sigma at which Newton stops
_PREDICTION_MARGIN = 100.0  # safety factor on the predicted residual after a step
_SMALL_STEP = 1e-4  # a step counts as small (its Taylor prediction trusted) below this fraction of its panel
_TINY = 1e-300


def _speed(u: np.ndarray, v: np.ndarray, p: np.ndarray) -> np.ndarray:
    """``|C'(p)|`` (Horner's scheme, the same arithmetic as :func:`frame`'s first derivative)."""
    du = u[1] + p * (2.0 * u[2] + p * (3.0 * u[3]))
    dv = v[1] + p * (2.0 * v[2] + p * (3.0 * v[3]))
    return np.hypot(du, dv)


@dataclass(frozen=True, eq=False)
class CubicCurve:
    """``C(p) = (U(p), V(p))`` with ``U``, ``V`` cubic (coefficients a, b, c, d) and arc-length tables on
    ``[0, p_max]`` (evaluation and inversion also work, less sharply, slightly outside)."""

    u: np.ndarray
    v: np.ndarray
    breaks: np.ndarray  # panel boundaries in p
    cumulative: np.ndarray  # arc length at each boundary
    inverse_span: np.ndarray  # 1 / (arc length of each panel), 0 for an empty panel
    guess: np.ndarray  # (panels, 4): cubic in t = (sigma - cumulative[k]) * inverse_span[k] giving a first p

    @classmethod
    def build(cls, u, v, p_max: float) -> CubicCurve:
        u = np.asarray(u, dtype=float)
        v = np.asarray(v, dtype=float)
        panels = _FIRST_PANELS
        lengths = _panel_lengths(u, v, np.linspace(0.0, p_max, panels + 1))
        while panels < _MAX_PANELS:
            finer = _panel_lengths(u, v, np.linspace(0.0, p_max, 2 * panels + 1))
            panels *= 2
            converged = abs(finer.sum() - lengths.sum()) <= 1e-15 * max(finer.sum(), 1e-300)
            lengths = finer
            if converged:
                break
        breaks = np.linspace(0.0, p_max, panels + 1)
        cumulative = np.concatenate(([0.0], np.cumsum(lengths)))
        return cls(u, v, breaks, cumulative, *_guess_table(breaks, cumulative, _speed(u, v, breaks)))

    @property
    def total(self) -> float:
        return float(self.cumulative[-1])

    def speed(self, p: np.ndarray) -> np.ndarray:
        return _speed(self.u, self.v, p)

    def parameter_at(self, sigma: np.ndarray) -> np.ndarray:
        """The parameter ``p`` at arc length ``sigma`` from ``p = 0`` (one call of :func:`parameters_at`)."""
        sigma = np.asarray(sigma, dtype=float)
        return parameters_at([self], sigma, np.array([len(sigma)]))


def _guess_table(breaks: np.ndarray, cumulative: np.ndarray, speed: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per panel, ``1 / span`` and the power coefficients in ``t`` (the panel's fraction of arc length) of the cubic
    Hermite interpolant of ``p(sigma)``: values ``p`` and slopes ``span / |C'|`` at both ends; the straight line
    between the ends where a boundary speed is zero or the panel has no length."""
    p0, dp = breaks[:-1], np.diff(breaks)
    span = np.diff(cumulative)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        inverse_span = np.where(span > 0, 1.0 / span, 0.0)
        m0, m1 = span / speed[:-1], span / speed[1:]
    usable = (span > 0) & np.isfinite(m0) & np.isfinite(m1)
    m0, m1 = np.where(usable, m0, dp), np.where(usable, m1, dp)
    return inverse_span, np.column_stack([p0, m0, 3.0 * dp - 2.0 * m0 - m1, m0 + m1 - 2.0 * dp])


def _panel_lengths(u: np.ndarray, v: np.ndarray, breaks: np.ndarray) -> np.ndarray:
    half = 0.5 * np.diff(breaks)
    nodes = breaks[:-1, None] + half[:, None] * (_NODES[None, :] + 1.0)
    return half * (_speed(u, v, nodes) @ _WEIGHTS)


def frame(u, v, p: np.ndarray):
    """Local position, tangent angle, curvature and its arc-length derivative at parameters ``p`` of the cubic with
    coefficients ``u = (a, b, c, d)`` and ``v`` (numbers, or arrays of one per point: many curves evaluated together,
    each point with the same arithmetic).

    Returns ``(U, V, angle, curvature, dcurvature)`` with ``angle = atan2(V', U')`` in (-pi, pi], curvature
    ``(U'V'' - V'U'') / |C'|^3`` and its derivative with respect to arc length (chain rule through ``|C'|``).
    """
    (ua, ub, uc, ud), (va, vb, vc, vd) = u, v
    # Horner's scheme for the value and first three derivatives.
    u0, v0 = ua + p * (ub + p * (uc + p * ud)), va + p * (vb + p * (vc + p * vd))
    u1, v1 = ub + p * (2.0 * uc + p * (3.0 * ud)), vb + p * (2.0 * vc + p * (3.0 * vd))
    u2, v2 = 2.0 * uc + p * (6.0 * ud), 2.0 * vc + p * (6.0 * vd)
    u3, v3 = 6.0 * ud, 6.0 * vd
    speed2 = u1 * u1 + v1 * v1
    speed = np.sqrt(speed2)
    cross = u1 * v2 - v1 * u2
    dcross = u1 * v3 - v1 * u3
    dspeed = (u1 * u2 + v1 * v2) / np.where(speed > 0, speed, np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        curvature = cross / (speed2 * speed)
        dcurvature = (dcross / (speed2 * speed) - 3.0 * cross * dspeed / (speed2 * speed2)) / speed
    return u0, v0, np.arctan2(v1, u1), curvature, dcurvature


def poses(curves: list[CubicCurve], scales, starts, ds: np.ndarray, counts: np.ndarray) -> Pose:
    """Poses of many calls at once: call ``i`` takes the next ``counts[i]`` distances ``ds`` along ``curves[i]`` (the
    parameter at arc length ``ds * scales[i]``), in the frame of an element starting at ``starts[i] = (x, y, hdg)``.
    Each call's numbers are its own to the last bit (:func:`parameters_at`, :func:`frame`)."""
    counts = np.asarray(counts, dtype=np.int64)
    owner = np.repeat(np.arange(len(curves)), counts)
    p = parameters_at(curves, ds * np.asarray(scales, dtype=float)[owner], counts)
    coef = np.array([(*c.u, *c.v) for c in curves]).reshape(-1, 8)[owner].T
    u0, v0, angle, curvature, dcurvature = frame(coef[:4], coef[4:], p)
    x0, y0, hdg = np.array(starts, dtype=float).reshape(-1, 3)[owner].T
    c, s = np.cos(hdg), np.sin(hdg)
    return Pose(x0 + c * u0 - s * v0, y0 + s * u0 + c * v0, hdg + angle, curvature, dcurvature)


def parameters_at(curves: list[CubicCurve], sigma: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """``CubicCurve.parameter_at`` of many calls in one pass: call ``i`` asks ``curves[i]`` about the next ``counts[i]``
    values of ``sigma``. The result is each call's own to the last bit: every point gets the same arithmetic, and each
    call's Newton iterations stop when its own tests say so (a call alone stops when all its points are done, so the
    number of steps a point gets depends on its call, and here too)."""
    counts = np.asarray(counts, dtype=np.int64)
    owner = np.repeat(np.arange(len(curves)), counts)
    p, start, width, base = _first_guesses(curves, sigma, counts, owner)
    return _newton(curves, sigma, counts, owner, p, start, width, base)


def _first_guesses(
    curves: list[CubicCurve], sigma: np.ndarray, counts: np.ndarray, owner: np.ndarray
) -> tuple[np.ndarray, ...]:
    """Each point's first guess of its parameter from its own call's table, and the start, width and arc length at
    the start of the table interval it falls in."""
    calls = len(curves)
    sizes = np.array([len(c.breaks) for c in curves], dtype=np.int64)
    table_at = np.concatenate(([0], np.cumsum(sizes)))
    breaks = np.concatenate([c.breaks for c in curves])
    cumulative = np.concatenate([c.cumulative for c in curves])
    inverse_span = np.concatenate([np.append(c.inverse_span, 0.0) for c in curves])  # padded to the table size
    guess = np.concatenate([np.vstack([c.guess, np.zeros((1, 4))]) for c in curves])
    # searchsorted(cumulative_i, sigma, side="right") of every point in its own call's table: merge the tables and
    # the points, sorted by call, then value, tables first on ties; a point counts the table entries before it
    n_tab = len(cumulative)
    keys_call = np.concatenate([np.repeat(np.arange(calls), sizes), owner])
    keys_value = np.concatenate([cumulative, sigma])
    keys_kind = np.concatenate([np.zeros(n_tab, dtype=np.int8), np.ones(len(sigma), dtype=np.int8)])
    order = np.lexsort((keys_kind, keys_value, keys_call))
    before = np.cumsum(keys_kind[order] == 0)
    found = np.empty(len(sigma), dtype=np.int64)
    is_point = order >= n_tab
    found[order[is_point] - n_tab] = before[is_point]
    right = found - table_at[owner]
    k = np.minimum(np.maximum(right - 1, 0), (sizes - 2)[owner])
    at = table_at[owner] + k
    a, b, c, d = guess[at].T
    t = (sigma - cumulative[at]) * inverse_span[at]
    p = a + t * (b + t * (c + t * d))
    start = breaks[at]
    width = breaks[at + 1] - start
    base = cumulative[at]
    return p, start, width, base


def _newton(
    curves: list[CubicCurve],
    sigma: np.ndarray,
    counts: np.ndarray,
    owner: np.ndarray,
    p: np.ndarray,
    start: np.ndarray,
    width: np.ndarray,
    base: np.ndarray,
) -> np.ndarray:
    """Newton iterations from the first guesses ``p`` (updated in place and returned), call by call as
    :func:`parameters_at` says."""
    calls = len(curves)
    u = np.array([c.u for c in curves])[owner]
    v = np.array([c.v for c in curves])[owner]
    u1, u2x, u3x = u[:, 1], 2.0 * u[:, 2], 3.0 * u[:, 3]
    v1, v2x, v3x = v[:, 1], 2.0 * v[:, 2], 3.0 * v[:, 3]
    u2, u3x6 = 2.0 * u[:, 2], 6.0 * u[:, 3]
    v2, v3x6 = 2.0 * v[:, 2], 6.0 * v[:, 3]
    live = np.arange(calls)  # calls still iterating
    rows = np.arange(len(sigma))  # their points, grouped by call
    for _ in range(_NEWTON_STEPS):
        if not len(live):
            break
        first = np.concatenate(([0], np.cumsum(counts[live])[:-1]))
        pr, st = p[rows], start[rows]
        q = np.empty((len(rows), len(_NODES) + 1))
        q[:, :-1] = st[:, None] + (pr - st)[:, None] * _UNIT_NODES
        q[:, -1] = pr
        du = u1[rows, None] + q * (u2x[rows, None] + q * u3x[rows, None])
        dv = v1[rows, None] + q * (v2x[rows, None] + q * v3x[rows, None])
        speeds = np.hypot(du, dv)
        # The quadrature sums call by call: a matrix product's rounding depends on how many rows it is given.
        integral = np.empty(len(rows))
        for lo, hi in zip(first.tolist(), np.cumsum(counts[live]).tolist()):
            integral[lo:hi] = speeds[lo:hi, :-1] @ _WEIGHTS
        residual = base[rows] + 0.5 * (pr - st) * integral - sigma[rows]
        speed = np.maximum(speeds[:, -1], _TINY)
        step = residual / speed
        p[rows] = pr - step
        going = np.logical_or.reduceat(np.abs(residual) > _NEWTON_TOL, first)
        with np.errstate(all="ignore"):
            ddu = u2[rows] + q[:, -1] * u3x6[rows]
            ddv = v2[rows] + q[:, -1] * v3x6[rows]
            slope = (du[:, -1] * ddu + dv[:, -1] * ddv) / speed
            predicted = _PREDICTION_MARGIN * 0.5 * np.abs(slope) * step * step
            settled = (predicted <= _NEWTON_TOL) & (np.abs(step) <= _SMALL_STEP * width[rows])
        going &= ~np.logical_and.reduceat(settled, first)
        live = live[going]
        rows = rows[np.repeat(going, np.diff(np.append(first, len(rows))))]
    return p
