"""The curves the generator writes: evaluation of its own geometry, fillet chains and cubic Hermite connections.

Everything here works on the generator's model (:mod:`junctionart.opendrive`). Arc lengths of paramPoly3 curves are
computed with composite Gauss-Legendre quadrature (error far below a micrometre), so the declared length is the
curve's length.
"""

from __future__ import annotations

import functools
import itertools
import math
from dataclasses import dataclass

import numpy as np

from .opendrive import Arc, Geometry, Line, ParamPoly3

_GL_X, _GL_W = np.polynomial.legendre.leggauss(24)
_PANELS = 8


@dataclass(frozen=True)
class Pose:
    """A position and heading in the plane."""

    x: float
    y: float
    hdg: float


def end_pose(g: Geometry) -> Pose:
    """Pose at the end of one element (the next element starts exactly here)."""
    if isinstance(g, Line):
        return Pose(g.x + g.length * math.cos(g.hdg), g.y + g.length * math.sin(g.hdg), g.hdg)
    if isinstance(g, Arc):
        k, L = g.curvature, g.length
        h1 = g.hdg + k * L
        return Pose(g.x + (math.sin(h1) - math.sin(g.hdg)) / k, g.y - (math.cos(h1) - math.cos(g.hdg)) / k, h1)
    u = g.au + g.bu + g.cu + g.du
    v = g.av + g.bv + g.cv + g.dv
    du = g.bu + 2 * g.cu + 3 * g.du
    dv = g.bv + 2 * g.cv + 3 * g.dv
    c, s = math.cos(g.hdg), math.sin(g.hdg)
    return Pose(g.x + c * u - s * v, g.y + s * u + c * v, g.hdg + math.atan2(dv, du))


@functools.lru_cache(maxsize=64)
def _steps(n: int) -> np.ndarray:
    """``n`` even steps from 0 to 1 (read-only: shared by every call)."""
    t = np.linspace(0.0, 1.0, n)
    t.flags.writeable = False
    return t


def sample(g: Geometry, n: int = 16) -> np.ndarray:
    """``n`` points (x, y) along one element, both ends included (for rendering and overlap tests)."""
    t = _steps(n)
    if isinstance(g, Line):
        d = t * g.length
        return np.column_stack([g.x + d * math.cos(g.hdg), g.y + d * math.sin(g.hdg)])
    if isinstance(g, Arc):
        d = t * g.length
        h = g.hdg + g.curvature * d
        return np.column_stack(
            [g.x + (np.sin(h) - math.sin(g.hdg)) / g.curvature, g.y - (np.cos(h) - math.cos(g.hdg)) / g.curvature]
        )
    u = g.au + t * (g.bu + t * (g.cu + t * g.du))
    v = g.av + t * (g.bv + t * (g.cv + t * g.dv))
    c, s = math.cos(g.hdg), math.sin(g.hdg)
    return np.column_stack([g.x + c * u - s * v, g.y + s * u + c * v])


def unit_tangents(pts: np.ndarray, first=0, last=None) -> np.ndarray:
    """Unit tangents of a polyline ``(n, 2)``: central differences inside, one-sided at both ends. Several polylines
    stored end to end are handled in one pass when ``first`` and ``last`` give, per point, the indexes of its own
    polyline's first and last point."""
    at = np.arange(len(pts))
    ahead = np.minimum(at + 1, len(pts) - 1 if last is None else last)
    behind = np.maximum(at - 1, first)
    tangent = pts[ahead] - pts[behind]
    return tangent / np.maximum(np.hypot(tangent[:, 0], tangent[:, 1]), 1e-12)[:, None]


def wrap(a: float) -> float:
    """Angle in (-pi, pi]."""
    a = math.fmod(a + math.pi, 2 * math.pi)
    if a <= 0:
        a += 2 * math.pi
    return a - math.pi


# ---------------------------------------------------------------------------------------------------------------------
# Cubic Hermite connections
# ---------------------------------------------------------------------------------------------------------------------
def _gl_nodes() -> tuple[np.ndarray, np.ndarray]:
    edges = np.linspace(0.0, 1.0, _PANELS + 1)
    half = 0.5 * (edges[1:] - edges[:-1])
    mid = 0.5 * (edges[1:] + edges[:-1])
    p = (mid[:, None] + half[:, None] * _GL_X[None, :]).ravel()
    w = (half[:, None] * _GL_W[None, :]).ravel()
    return p, w


_P_NODES, _P_WEIGHTS = _gl_nodes()
_P_CHECK = np.linspace(0.0, 1.0, 65)


def _derivatives(coef: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, ...]:
    bu, cu, du = coef[:, 1:2], coef[:, 2:3], coef[:, 3:4]
    bv, cv, dv = coef[:, 5:6], coef[:, 6:7], coef[:, 7:8]
    d1u = bu + p * (2 * cu + 3 * du * p)
    d1v = bv + p * (2 * cv + 3 * dv * p)
    d2u = 2 * cu + 6 * du * p
    d2v = 2 * cv + 6 * dv * p
    return d1u, d1v, d2u, d2v


def arc_lengths(coef: np.ndarray) -> np.ndarray:
    d1u, d1v, _, _ = _derivatives(coef, _P_NODES[None, :])
    return (np.hypot(d1u, d1v) * _P_WEIGHTS[None, :]).sum(axis=1)


@dataclass(frozen=True)
class HermiteFit:
    """A cubic fitted between two poses: its coefficients, length and smallest radius."""

    coef: tuple[float, ...]
    length: float
    min_radius: float  # smallest radius over the reference line and the given offset lines


def _bends(k, cu, du, cv, dv, p, outermost) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """At parameters ``p`` (1, samples) of each candidate: (nothing stalls or folds, the largest curvature magnitude
    on the reference line and the outermost offset lines, du/dp, dv/dp). The same operations in the same order as
    the plain expressions, written into few buffers (allocation was a large part of the cost on these small arrays)."""
    d1u = 3 * du[:, None] * p
    d1u += 2 * cu[:, None]
    d1u *= p
    d1u += k[:, None]
    d1v = 3 * dv[:, None] * p
    d1v += 2 * cv[:, None]
    d1v *= p
    d2u = 6 * du[:, None] * p
    d2u += 2 * cu[:, None]
    d2v = 6 * dv[:, None] * p
    d2v += 2 * cv[:, None]
    speed2 = d1u * d1u
    tmp = d1v * d1v
    speed2 += tmp  # squared speed: no hypot and no power over every sample (the costly steps)
    ok = speed2.min(axis=1) > 1e-18
    np.maximum(speed2, 1e-24, out=speed2)
    kappa = d1u * d2v
    np.multiply(d1v, d2u, out=tmp)
    kappa -= tmp
    np.sqrt(speed2, out=tmp)
    tmp *= speed2
    kappa /= tmp
    np.abs(kappa, out=tmp)
    worst = tmp.max(axis=1)
    for off in outermost:
        np.multiply(off, kappa, out=tmp)
        np.subtract(1.0, tmp, out=tmp)
        ok &= tmp.min(axis=1) > 0.05
        np.maximum(tmp, 0.05, out=tmp)
        np.divide(kappa, tmp, out=tmp)
        np.abs(tmp, out=tmp)
        worst = np.maximum(worst, tmp.max(axis=1))
    return ok, worst, d1u, d1v


def fit_connections(
    targets: np.ndarray, offsets: tuple[float, ...], min_radius: float, scales: np.ndarray
) -> list[HermiteFit | None]:
    """For each target (u1, v1, phi), the smoothest Hermite cubic from (0, 0) heading 0 meeting the radius bound on
    its reference line and on the lines at lateral ``offsets`` (lane centre, outer border); None when no candidate
    tangent length (``scales`` times the chord, equal at both ends) does. The candidate whose smallest radius is the
    largest wins; a candidate whose heading does not turn monotonically by exactly the needed angle is rejected.
    All targets and candidates are evaluated in one vectorised pass.
    """
    t = np.asarray(targets, dtype=float).reshape(-1, 3)
    n, m = len(t), len(scales)
    if n == 0:
        return []
    u1, v1, phi = (np.repeat(t[:, i], m) for i in range(3))
    chord = np.hypot(u1, v1)
    k = np.maximum(np.tile(scales, n) * chord, 1.0)
    c, s = np.cos(phi), np.sin(phi)
    cu = 3 * u1 - 2 * k - k * c
    du = -2 * u1 + k + k * c
    cv = 3 * v1 - k * s
    dv = -2 * v1 + k * s
    # |kappa / (1 - t kappa)| grows with t * kappa, so the outermost offset on each side bounds the others (and its
    # fold test implies theirs)
    outermost = [
        o
        for o in (max((o for o in offsets if o > 0), default=0.0), min((o for o in offsets if o < 0), default=0.0))
        if o != 0.0
    ]
    # a screen on every 8th sample first: a candidate failing there fails on all samples (a minimum can only be
    # lower and a maximum only higher with more samples), so only the others are evaluated in full
    ok, worst, _, _ = _bends(k, cu, du, cv, dv, _P_CHECK[None, ::8], outermost)
    live = np.flatnonzero(ok & (chord > 1e-6) & (1.0 / np.maximum(worst, 1e-300) >= min_radius))
    ok_live, worst_live, d1u, d1v = _bends(
        k[live], cu[live], du[live], cv[live], dv[live], _P_CHECK[None, :], outermost
    )
    radius_live = 1.0 / np.maximum(worst_live, 1e-300)
    ok_live &= radius_live >= min_radius
    radius = np.full(n * m, -1.0)
    radius[live] = radius_live
    flat_score = np.full(n * m, -1.0)
    flat_score[live] = np.where(ok_live, radius_live, -1.0)
    score = flat_score.reshape(n, m)
    at = np.full(n * m, -1)
    at[live] = np.arange(len(live))  # candidate -> its row in the full evaluation
    # the last condition, the costliest, only for each target's best candidate so far: total turning equals the
    # heading change (the heading increments never change sign); a best candidate failing it gives way to the next
    pending = np.arange(n)
    while True:
        best = score.argmax(axis=1)
        pending = pending[score[pending, best[pending]] >= 0]
        if not len(pending):
            break
        cand = pending * m + best[pending]
        rows = at[cand]
        dh = np.diff(np.arctan2(d1v[rows], d1u[rows]), axis=1)
        dh = np.where(dh > np.pi, dh - 2 * np.pi, np.where(dh < -np.pi, dh + 2 * np.pi, dh))  # into [-pi, pi]
        turned = dh.sum(axis=1)
        bad = ~(np.abs(np.abs(turned) - np.abs(phi[cand])) < 1e-6)
        score[pending[bad], best[pending[bad]]] = -1.0
        pending = pending[bad]
    sel = np.arange(n) * m + best
    zero = np.zeros(n)
    coefs = np.column_stack([zero, k[sel], cu[sel], du[sel], zero, zero, cv[sel], dv[sel]])
    lengths = arc_lengths(coefs)
    return [
        HermiteFit(tuple(coefs[i].tolist()), float(lengths[i]), float(radius[sel[i]]))
        if score[i, best[i]] >= 0
        else None
        for i in range(n)
    ]


def connection_geometry(x0: float, y0: float, h0: float, fit: HermiteFit) -> ParamPoly3:
    c = fit.coef
    return ParamPoly3(0.0, x0, y0, h0, fit.length, c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7])


def local_target(x0: float, y0: float, h0: float, x1: float, y1: float, h1: float) -> tuple[float, float, float]:
    """(u1, v1, phi): the end point and heading change in the frame of the start pose."""
    dx, dy = x1 - x0, y1 - y0
    c, s = math.cos(h0), math.sin(h0)
    return c * dx + s * dy, -s * dx + c * dy, wrap(h1 - h0)


# ---------------------------------------------------------------------------------------------------------------------
# Fillet chains: a polyline with circular arcs at its interior vertices
# ---------------------------------------------------------------------------------------------------------------------
def fillet_chain(
    start: tuple[float, float], vertices: list[tuple[float, float]], end: tuple[float, float], radii: list[float]
) -> tuple[Geometry, ...]:
    """Lines and arcs from ``start`` through the corners at ``vertices`` (rounded with ``radii``) to ``end``.

    Each element starts exactly at the end pose of the previous one (evaluated with :func:`end_pose`).
    """
    pts = [start, *vertices, end]
    dirs = []
    for a, b in itertools.pairwise(pts):
        dirs.append(math.atan2(b[1] - a[1], b[0] - a[0]))
    out: list[Geometry] = []
    s = 0.0
    pose = Pose(start[0], start[1], dirs[0])
    for i, v in enumerate(vertices):
        theta = wrap(dirs[i + 1] - dirs[i])
        r = radii[i]
        tangent = r * math.tan(abs(theta) / 2)
        # line up to the tangent point, measured along the current heading
        dx, dy = v[0] - pose.x, v[1] - pose.y
        along = dx * math.cos(pose.hdg) + dy * math.sin(pose.hdg) - tangent
        if along > 1e-9:
            line = Line(s, pose.x, pose.y, pose.hdg, along)
            out.append(line)
            s += along
            pose = end_pose(line)
        if abs(theta) > 1e-12:
            arc = Arc(s, pose.x, pose.y, pose.hdg, r * abs(theta), math.copysign(1.0 / r, theta))
            out.append(arc)
            s += arc.length
            pose = end_pose(arc)
    dx, dy = end[0] - pose.x, end[1] - pose.y
    along = dx * math.cos(pose.hdg) + dy * math.sin(pose.hdg)
    if along > 1e-9 or not out:
        out.append(Line(s, pose.x, pose.y, pose.hdg, max(along, 1e-3)))
    return tuple(out)
