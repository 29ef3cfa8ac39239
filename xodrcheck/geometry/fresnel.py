"""Fresnel integrals ``S(x) = integral_0^x sin(pi t^2 / 2) dt`` and ``C(x) = integral_0^x cos(pi t^2 / 2) dt``.

Same convention and return order as ``scipy.special.fresnel`` (``(S, C)``), vectorised over numpy arrays, in double
precision; written here so that evaluating a spiral does not import scipy (0.25-0.3 s per ``xodrcheck check``
process). ``F = C + iS`` is odd, so each point is evaluated at ``|x|`` and the sign restored; NaN gives NaN and
``+-inf`` gives ``+-0.5``. Three methods, each used where it loses nothing to cancellation:

* ``|x| < 1``: the power series ``F(x) = x sum_k (iz)^k / (k! (2k + 1))``, ``z = pi x^2 / 2``, split into its real
  (even ``k``) and imaginary (odd ``k``) parts as polynomials in ``x^4`` (12 terms each, the last below 1e-18). Every
  term is smaller than the sum (``z <= pi / 2``), so Horner's rule keeps the relative error at a few ulp, also for tiny
  ``x`` (``S ~ pi x^3 / 6``).
* ``1 <= |x| < 5.5``: the Taylor expansion about the nearest node ``x0 = n / 16`` (``|h| = |x - x0| <= 1/32``)

      F(x0 + h) = F(x0) + exp(i z0) integral_0^h exp(i (pi x0 u + pi u^2 / 2)) du = F(x0) + sum_k d_k h^(k+1)

  where the integrand's Taylor coefficients follow from ``y' = i (pi x0 + pi u) y``:
  ``c_0 = 1, (k + 1) c_(k+1) = i pi x0 c_k + i pi c_(k-1)``, and ``d_k = exp(i z0) c_k / (k + 1)`` (17 terms:
  ``|pi x0 h| <= 0.54``, no cancellation). The node values ``F(x0)`` (as a double plus its rounding remainder) and
  ``exp(i z0)`` are computed by the power series above in exact integer fixed-point arithmetic (256 fractional bits,
  pi by Machin's formula), where its terms reach ``e^z0 ~ 1e20`` and cancel at no cost; each node when a point first
  needs it (0.02-0.1 ms: the spirals of most roads never leave the power series). No coefficient is copied from
  elsewhere.
* ``|x| >= 5.5``: the asymptotic expansions of the auxiliary functions (Abramowitz & Stegun 7.3.9-10, 7.3.27-28)

      C = 1/2 + f sin(pi x^2 / 2) - g cos(pi x^2 / 2),   S = 1/2 - f cos(pi x^2 / 2) - g sin(pi x^2 / 2),
      f ~ 1/(pi x) sum_m (-1)^m (4m - 1)!! / (pi x^2)^(2m),   g ~ 1/(pi^2 x^3) sum_m (-1)^m (4m + 1)!! / (pi x^2)^(2m),

  summed until a term is below 2^-60 (19 terms at 5.5, where the smallest term is about ``e^(-pi x^2 / 2) ~ 1e-21``;
  7 at 10, 2 from 1e4). The phase is reduced exactly: ``x^2 mod 4`` from the exact products of the halves of ``x``
  (Dekker's split), so ``sin`` and ``cos`` are right to about an ulp for every ``x``. (scipy rounds ``pi x^2 / 2``
  first: its values err by up to about ``x eps / 5``, 4e-13 at ``x = 1e4``, and by up to ``1 / (pi x)`` past 1e8.)

Each point's value depends on that point only (not on the others of the array). Measured against mpmath (40 digits)
with ``benchmarks/fresnel_accuracy.py`` on 203,075 points (random in [0, 1), [1, 5.5), [5.5, 12), log-uniform in
1e-300 .. 1e10, and within 80 eps of every switch of method or node): at most 1.11e-16 absolute (an ulp of values in
[0.5, 1)); relative, at most 4.7e-16 below 1 and 2.2e-16 from 1 on. scipy.special.fresnel on the same points: up to
6.7e-16 absolute and 1.3e-15 relative (on [5.5, 12)). Time per point on 1e5 points: 1.6 times scipy's on [0, 10].
"""

from __future__ import annotations

import functools
import math

import numpy as np

__all__ = ["fresnel"]

_SERIES_END = 1.0  # power series below, node expansion from here
_ASYMPTOTIC_START = 5.5  # node expansion below, asymptotic expansion from here
_NODES_PER_UNIT = 16  # nodes n / 16: |h| <= 1/32
_FIRST_NODE = int(_SERIES_END * _NODES_PER_UNIT)
_LAST_NODE = int(_ASYMPTOTIC_START * _NODES_PER_UNIT)
_TAYLOR_TERMS = 17  # |pi x0 h| <= 0.54: the 17th term is below 3e-18 of h
_SERIES_TERMS = 12  # z <= pi / 2: the 12th term of each part is below 1e-18
_FIXED_BITS = 256  # fractional bits of the integer arithmetic of the node values
_ASYMPTOTIC_TAIL = 2.0**-60  # last term of the asymptotic sums, relative to their first
_MAX_ASYMPTOTIC_TERMS = 40
_TWO_53 = 2.0**53  # from here x is even: x^2 = 0 mod 4
_SPLIT = 2.0**27 + 1.0  # Dekker's splitter: halves of 26 bits, whose products are exact


def fresnel(x) -> tuple[np.ndarray, np.ndarray]:
    """``(S(x), C(x))`` for an array (or number) ``x``: arrays of its shape (numpy scalars for a number)."""
    x = np.asarray(x, dtype=float)
    ax = np.abs(x)
    s = np.full(x.shape, math.nan)
    c = np.full(x.shape, math.nan)
    for method, mask in (
        (_by_series, ax < _SERIES_END),
        (_by_nodes, (ax >= _SERIES_END) & (ax < _ASYMPTOTIC_START)),
        (_by_asymptotics, ax >= _ASYMPTOTIC_START),  # NaN is in none of the three: stays NaN
    ):
        if mask.all():
            s, c = method(ax)
            break
        if mask.any():
            s[mask], c[mask] = method(ax[mask])
    return np.copysign(s, x)[()], np.copysign(c, x)[()]


def _by_series(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``|x| < 1``: the power series in ``x^4`` (see the module docstring)."""
    even, odd = _series_coefficients()
    t = (x * x) * (x * x)
    c = np.full_like(x, even[-1])
    s = np.full_like(x, odd[-1])
    for k in range(len(even) - 2, -1, -1):
        c = c * t + even[k]
        s = s * t + odd[k]
    return s * (x * x * x), c * x


def _by_nodes(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``1 <= |x| < 5.5``: ``F(x0) + sum_k d_k h^(k+1)`` about the nearest node ``x0 = n / 16``."""
    n = np.rint(x * _NODES_PER_UNIT).astype(np.intp)
    h = x - n / _NODES_PER_UNIT  # exact: x and x0 within a factor of 2
    i = n - _FIRST_NODE
    nodes = _node_tables()
    nodes.need(i)
    re = nodes.d_real[-1][i]
    im = nodes.d_imag[-1][i]
    for k in range(_TAYLOR_TERMS - 2, -1, -1):
        re = re * h + nodes.d_real[k][i]
        im = im * h + nodes.d_imag[k][i]
    # the node value's remainder first: F(x0) + (remainder + increment) rounds once, to about half an ulp
    c = nodes.c_high[i] + (nodes.c_low[i] + re * h)
    s = nodes.s_high[i] + (nodes.s_low[i] + im * h)
    return s, c


def _by_asymptotics(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``|x| >= 5.5`` (and infinity): the auxiliary functions' asymptotic series and an exactly reduced phase."""
    sin, cos = _sin_cos_half_pi_square(x)
    with np.errstate(over="ignore"):
        w = 1.0 / (math.pi * (x * x))  # 0 for x^2 = inf
    inv_pi_x = 1.0 / (math.pi * x)
    u = w * w
    f_sum = np.ones_like(x)
    g_sum = np.ones_like(x)
    f_term = np.ones_like(x)
    g_term = np.ones_like(x)
    for m in range(1, _MAX_ASYMPTOTIC_TERMS):
        f_term = f_term * (-(4 * m - 3) * (4 * m - 1) * u)
        g_term = g_term * (-(4 * m - 1) * (4 * m + 1) * u)
        f_sum += f_term
        g_sum += g_term
        if np.max(np.abs(g_term), initial=0.0) < _ASYMPTOTIC_TAIL:  # |g_term| >= |f_term|
            break
    f = inv_pi_x * f_sum
    g = inv_pi_x * w * g_sum
    return 0.5 - (f * cos + g * sin), 0.5 + (f * sin - g * cos)


def _sin_cos_half_pi_square(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``sin(pi x^2 / 2)`` and ``cos(pi x^2 / 2)`` for ``x >= 0``, the argument reduced exactly.

    ``x = hi + lo`` with halves of 26 bits makes ``hi^2``, ``2 hi lo`` and ``lo^2`` exact doubles; each is reduced
    modulo 4 (``fmod`` is exact) and their sum, carried with its rounding error, is split into the nearest integer
    ``q`` (the quadrant) and ``r`` in ``[-1/2, 1/2]``: ``pi x^2 / 2 = q pi / 2 + pi r / 2`` (mod 2 pi)."""
    safe = np.where(x < _TWO_53, x, 0.0)  # x >= 2^53 is even: x^2 = 0 mod 4 (and infinity: the limit)
    scaled = _SPLIT * safe
    hi = scaled - (scaled - safe)
    lo = safe - hi
    total, error = _two_sum(np.fmod(hi * hi, 4.0), np.fmod(2.0 * hi * lo, 4.0))
    total, error2 = _two_sum(np.fmod(total, 4.0), np.fmod(lo * lo, 4.0))
    quadrant = np.rint(total)
    r = (total - quadrant) + (error + error2)  # the difference is exact (|r| <= 1/2)
    phi = (math.pi / 2.0) * r
    sin_phi, cos_phi = np.sin(phi), np.cos(phi)
    q = quadrant.astype(np.intp) % 4
    sin = np.choose(q, (sin_phi, cos_phi, -sin_phi, -cos_phi))
    cos = np.choose(q, (cos_phi, -sin_phi, -cos_phi, sin_phi))
    return sin, cos


def _two_sum(a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``a + b`` rounded and its rounding error exactly (Knuth's two-sum)."""
    total = a + b
    b_virtual = total - a
    error = (a - (total - b_virtual)) + (b - b_virtual)
    return total, error


# -- constants, computed on first use from their formulas ----------------------------------------------------------


class _Nodes:
    """Per node ``x0 = n / 16``, ``n = 16 .. 88``: ``C(x0)``, ``S(x0)`` as double plus remainder and the Taylor
    coefficients ``d_k`` of the increment (``d_real[k]``, ``d_imag[k]``: arrays over the nodes). A node is computed
    when a point first needs it (about 0.1 ms each): the spirals of most roads never leave the power series."""

    def __init__(self) -> None:
        count = _LAST_NODE - _FIRST_NODE + 1
        self.done = np.zeros(count, dtype=bool)
        self.c_high, self.c_low, self.s_high, self.s_low = np.zeros((4, count))
        self.d_real, self.d_imag = np.zeros((2, _TAYLOR_TERMS, count))

    def need(self, index: np.ndarray) -> None:
        """Compute the nodes ``index`` (offsets from the first node) not computed yet."""
        for i in np.unique(index[~self.done[index]]).tolist():
            self._compute(i)
            self.done[i] = True

    def _compute(self, i: int) -> None:
        one = 1 << _FIXED_BITS
        n = _FIRST_NODE + i
        # z0 = pi x0^2 / 2 = pi n^2 / 512 (nodes n / 16)
        z = (_pi_fixed(_FIXED_BITS + 64) * n * n) >> (2 * 4 + 1 + 64)
        cos_z, sin_z, c_sum, s_sum = _exp_and_fresnel_sums(z)
        # F(x0) = x0 * sum with x0 = n / 2^4
        self.c_high[i], self.c_low[i] = _double_double((c_sum * n) >> 4)
        self.s_high[i], self.s_low[i] = _double_double((s_sum * n) >> 4)
        phase = complex(cos_z / one, sin_z / one)
        x0 = n / _NODES_PER_UNIT
        coefficients = [1.0 + 0j, 1j * math.pi * x0]
        for k in range(1, _TAYLOR_TERMS - 1):
            coefficients.append(1j * math.pi * (x0 * coefficients[k] + coefficients[k - 1]) / (k + 1))
        d = [phase * c_k / (k + 1) for k, c_k in enumerate(coefficients)]
        self.d_real[:, i] = [d_k.real for d_k in d]
        self.d_imag[:, i] = [d_k.imag for d_k in d]


@functools.cache
def _node_tables() -> _Nodes:
    return _Nodes()


@functools.cache
def _series_coefficients() -> tuple[tuple[float, ...], tuple[float, ...]]:
    """Coefficients, correctly rounded, of ``C / x`` and ``S / x^3`` in powers of ``x^4``:
    ``(-1)^n (pi/2)^(2n) / ((2n)! (4n + 1))`` and ``(-1)^n (pi/2)^(2n+1) / ((2n+1)! (4n + 3))``."""
    bits = 128
    half_pi = _pi_fixed(bits + 64) >> 1
    scale = 1 << (bits + 64)
    even: list[float] = []
    odd: list[float] = []
    power = scale  # (pi/2)^k / k! in fixed point
    for k in range(2 * _SERIES_TERMS):
        if k:
            power = power * half_pi // scale // k
        value = (-1) ** (k // 2) * power / (scale * (2 * k + 1))  # int / int: correctly rounded
        (odd if k % 2 else even).append(value)
    return tuple(even), tuple(odd)


def _exp_and_fresnel_sums(z: int) -> tuple[int, int, int, int]:
    """Fixed point (``_FIXED_BITS`` fractional bits) ``cos z``, ``sin z`` and the real and imaginary parts of
    ``sum_k (iz)^k / (k! (2k + 1))`` for a fixed-point ``z > 0``, summed until the terms vanish."""
    exp_re = exp_im = sum_re = sum_im = 0
    term = 1 << _FIXED_BITS  # z^k / k!
    k = 0
    while term:
        # i^k = 1, i, -1, -i: four terms at a time
        exp_re += term
        sum_re += term // (2 * k + 1)
        term = ((term * z) >> _FIXED_BITS) // (k + 1)
        exp_im += term
        sum_im += term // (2 * k + 3)
        term = ((term * z) >> _FIXED_BITS) // (k + 2)
        exp_re -= term
        sum_re -= term // (2 * k + 5)
        term = ((term * z) >> _FIXED_BITS) // (k + 3)
        exp_im -= term
        sum_im -= term // (2 * k + 7)
        term = ((term * z) >> _FIXED_BITS) // (k + 4)
        k += 4
    return exp_re, exp_im, sum_re, sum_im


def _double_double(value: int) -> tuple[float, float]:
    """A fixed-point number (``_FIXED_BITS`` fractional bits) as a correctly rounded double and its remainder."""
    scale = 1 << _FIXED_BITS
    high = value / scale
    numerator, denominator = high.as_integer_ratio()
    return high, (value - numerator * (scale // denominator)) / scale


@functools.cache
def _pi_fixed(bits: int) -> int:
    """``pi * 2^bits`` rounded down to within a few units (Machin: ``pi = 16 atan(1/5) - 4 atan(1/239)``)."""
    guard = 16
    one = 1 << (bits + guard)

    def atan_inverse(m: int) -> int:
        total, power, k = 0, one // m, 0
        while power:
            total += (-1) ** k * (power // (2 * k + 1))
            power //= m * m
            k += 1
        return total

    return (16 * atan_inverse(5) - 4 * atan_inverse(239)) >> guard
