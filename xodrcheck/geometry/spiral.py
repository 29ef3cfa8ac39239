"""Spiral (clothoid): curvature changes linearly from ``curvStart`` to ``curvEnd`` over the element's length.

With ``k0 = curvStart`` and ``c = (curvEnd - curvStart) / length`` the heading is ``hdg + k0 ds + c ds^2 / 2`` and the
position is ``(x0, y0) + ds * exp(i hdg) * I(k0 ds, c ds^2 / 2)`` where

    I(a, b) = integral_0^1 exp(i (a t + b t^2)) dt

is evaluated exactly (to double precision) in one of two ways, chosen per point by the conditioning of the first:

* Fresnel integrals (``scipy.special.fresnel``) after completing the square. This is the classic clothoid formula.
  Its rounding error grows like ``u * (a^2 / (4|b|) + 2 / sqrt|b|)`` where ``u`` is the Fresnel values' own error
  (scipy's: up to about 3 ulp, 6.7e-16 absolute against mpmath, hence :data:`_FRESNEL_ULPS`): harmless for
  ordinary spirals, catastrophic when the curvature change is tiny (nearly an arc: ``b -> 0``) or the spiral starts far
  from curvature 0 (``a^2 / b`` large), because the formula then subtracts two large, nearly equal Fresnel values and
  rotates by a huge angle.
* Otherwise a convergent double power series. ``[0, 1]`` is cut into ``K`` equal pieces so that on each piece the
  local linear and quadratic phase coefficients are at most 0.5 and 0.25 rad; there

      integral_0^1 exp(i (a' u + b' u^2)) du = sum_{j,n} (i a')^j (i b')^n / (j! n! (j + 2n + 1))

  converges to double precision within 17 x 14 terms with no cancellation (every term is smaller than the first).
"""

from __future__ import annotations

import math

import numpy as np

from xodrcheck.geometry.pose import Pose, as_array
from xodrcheck.model import Spiral

_EPS = float(np.finfo(float).eps)
#: Largest estimated relative rounding error accepted on the Fresnel path (1e-14: 1e-10 m over 10 km).
_FRESNEL_BUDGET = 1e-14
#: The Fresnel values' error in units of eps, rounded up (scipy.special.fresnel: at most 6.7e-16 absolute).
_FRESNEL_ULPS = 4
_J_TERMS, _N_TERMS = 17, 14  # series truncation for |a'| <= 0.5, |b'| <= 0.25: remainder below 1e-19
_J = np.arange(_J_TERMS)
_N = np.arange(_N_TERMS)
_J_FACT = np.array([math.factorial(j) for j in _J], dtype=float)
_N_FACT = np.array([math.factorial(n) for n in _N], dtype=float)
_SERIES_WEIGHTS = 1.0 / (_J[:, None] + 2 * _N[None, :] + 1)
_SQRT_2_OVER_PI = math.sqrt(2.0 / math.pi)
_MAX_PIECES = 1024  # most series pieces per point; past it (no real road) the b-expansion below takes over
_MOMENT_TERMS = 14
_CHUNK_PIECES = 1 << 16  # series pieces evaluated at once
_SQRT_PI_OVER_2 = math.sqrt(math.pi / 2.0)


def evaluate(g: Spiral, ds) -> Pose:
    ds = as_array(ds)
    k0, dk = g.curv_start, g.curv_end - g.curv_start
    c = dk / g.length if g.length > 0 else 0.0
    # the curvature change over ds as dk * (ds / length), not c * ds: the same value, and finite even for a damaged
    # element 1e-320 m long (whose rate c overflows to infinity)
    t = ds / g.length if g.length > 0 else np.zeros_like(ds)
    turn = 0.5 * dk * ds * t  # the quadratic part of the heading, 0.5 c ds^2
    offset = ds * np.exp(1j * g.hdg) * phase_integral(k0 * ds, turn)
    return Pose(
        g.x + offset.real,
        g.y + offset.imag,
        g.hdg + k0 * ds + turn,
        k0 + dk * t,
        np.full_like(ds, c),
    )


def phase_integral(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``integral_0^1 exp(i (a t + b t^2)) dt`` for arrays ``a``, ``b`` (complex result, double precision)."""
    a, b = np.broadcast_arrays(np.asarray(a, dtype=float), np.asarray(b, dtype=float))
    out = np.empty(a.shape, dtype=complex)
    # a damaged element (a curvature change over a length of 1e-320 m is an infinite rate, and times s = 0 a NaN) has
    # no value: NaN, which the rules report, instead of a piece count of "NaN" pieces
    finite = np.isfinite(a) & np.isfinite(b)
    out[~finite] = complex(math.nan, math.nan)
    abs_b = np.abs(b)
    use_fresnel = uses_fresnel(a, b)
    if use_fresnel.any():
        out[use_fresnel] = by_fresnel(a[use_fresnel], b[use_fresnel])
    rest = finite & ~use_fresnel
    # Far from curvature 0 with a tiny curvature change over an absurd length (a > 2048 rad of turning): the series
    # would need over a thousand pieces per point; expand in b instead (or take Fresnel when b is not small).
    long = rest & (np.abs(a) * 0.5 > _MAX_PIECES)
    if long.any():
        small_b = long & (abs_b <= 1.0)
        out[small_b] = _by_moments(a[small_b], b[small_b])
        big_b = long & ~small_b
        out[big_b] = by_fresnel(a[big_b], b[big_b])
        rest &= ~long
    if rest.any():
        out[rest] = _by_series(a[rest], b[rest])
    return out


def uses_fresnel(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Where :func:`phase_integral` takes the Fresnel formula (:func:`by_fresnel`) for arrays ``a``, ``b``: finite,
    ``b`` not 0, and the formula's estimated rounding error within ``_FRESNEL_BUDGET`` (elsewhere the series, exact
    where the formula would lose digits)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    abs_b = np.abs(b)
    with np.errstate(divide="ignore", invalid="ignore"):
        error = _FRESNEL_ULPS * _EPS * (a * a / (4.0 * abs_b) + 2.0 / np.sqrt(abs_b))
    return np.isfinite(a) & np.isfinite(b) & (abs_b > 0) & (error <= _FRESNEL_BUDGET)


def _by_moments(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``I(a, b) = sum_n (i b)^n / n! * M_2n(a)`` with ``M_m(a) = integral_0^1 t^m exp(i a t) dt`` by the recurrence
    ``M_m = (exp(i a) - m M_(m-1)) / (i a)``, stable for ``|a| > 2048`` and the few ``m`` needed; for ``|b| <= 1`` the
    series after ``_MOMENT_TERMS`` terms is below 1e-10 relative."""
    e = np.exp(1j * a)
    ia = 1j * a
    moment = (e - 1.0) / ia
    total = moment.copy()
    term = np.ones_like(total)
    for n in range(1, _MOMENT_TERMS):
        moment = (e - (2 * n - 1) * moment) / ia
        moment = (e - 2 * n * moment) / ia
        term = term * (1j * b) / n
        total += term * moment
    return total


def by_fresnel(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``I(a, b)`` by the classic clothoid formula: the Fresnel integrals after completing the square. Exact where
    :func:`uses_fresnel` says so; it loses many digits elsewhere (nearly an arc, or far from curvature 0)."""
    from scipy.special import fresnel  # here: only maps with spirals need scipy

    # For b < 0 use I(a, b) = conj(I(-a, -b)), so that the quadratic coefficient is positive.
    negative = b < 0
    a = np.where(negative, -a, a)
    b = np.abs(b)
    root = np.sqrt(b)
    w0 = a / (2.0 * root)  # a t + b t^2 = (sqrt(b) t + w0)^2 - w0^2
    # both ends in one call (the same values as two calls: fresnel is elementwise)
    s, c = fresnel(np.concatenate([w0 * _SQRT_2_OVER_PI, (w0 + root) * _SQRT_2_OVER_PI]))
    s0, s1 = np.split(s, 2)
    c0, c1 = np.split(c, 2)
    value = np.exp(-1j * w0 * w0) * (_SQRT_PI_OVER_2 * ((c1 - c0) + 1j * (s1 - s0))) / root
    return np.where(negative, np.conj(value), value)


def _by_series(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    pieces = np.maximum(1, np.ceil(2.0 * (np.abs(a) + 2.0 * np.abs(b)))).astype(np.int64)
    if pieces.sum() > _CHUNK_PIECES:  # bounded memory: a few points at a time (each point's sum unchanged)
        group = np.cumsum(pieces) // _CHUNK_PIECES
        cuts = np.flatnonzero(np.diff(group)) + 1
        return np.concatenate([_series_of(a[i], b[i], pieces[i]) for i in np.split(np.arange(len(a)), cuts)])
    return _series_of(a, b, pieces)


def _series_of(a: np.ndarray, b: np.ndarray, pieces: np.ndarray) -> np.ndarray:
    owner = np.repeat(np.arange(len(a)), pieces)
    first = np.cumsum(pieces) - pieces
    index = np.arange(owner.size) - first[owner]
    h = 1.0 / pieces[owner]
    tau = index * h
    a_o, b_o = a[owner], b[owner]
    a_local = (a_o + 2.0 * b_o * tau) * h
    b_local = b_o * h * h
    powers_a = (1j * a_local[:, None]) ** _J / _J_FACT
    powers_b = (1j * b_local[:, None]) ** _N / _N_FACT
    local = np.einsum("mj,jn,mn->m", powers_a, _SERIES_WEIGHTS, powers_b)
    terms = h * np.exp(1j * (a_o * tau + b_o * tau * tau)) * local
    n = len(a)
    return np.bincount(owner, terms.real, n) + 1j * np.bincount(owner, terms.imag, n)
