"""Heights of a junction elevation grid (ASAM OpenDRIVE 1.8/1.9, 12.11.1), vectorised with numpy.

Where the points are (12.11, 12.9): ``<elevation>`` row ``i`` lies perpendicular to the junction reference line at
``s = sStart + i * gridSpacing``; its ``center`` value is on the line (``t = 0``), its ``left`` values at
``t = +k * gridSpacing`` and its ``right`` values at ``t = -k * gridSpacing`` (``k = 1, 2, ...``, inside out). The grid
is held as compactly as the file holds it (:class:`GridPoints`); a square is evaluated from the 4 x 4 points around
it, gathered for the points asked for only, so memory follows the file and the query, never the grid's bounding box.

How heights between the points are interpolated (12.11.1): in each square of four points the z-value is the bicubic
``z(u, v) = [1 u u^2 u^3] . alpha . [1 v v^2 v^3]^T``, ``alpha = A . F . A^T``, with ``A`` the spec's constant matrix,
``u, v`` in 0..1 across the square (scaled and shifted: one grid step is 1) and ``F`` the values ``Z``, the tangents
``T_s``, ``T_t`` and the mixed ``T_st`` at the corners. The tangents are derivatives of the polynomial
``f(x) = d x^3 + c x^2 + b x + a`` through the points along each edge:

* An edge's support points are its two corners and the grid's next point beyond each corner on the same line (the
  four points at -1, 0, 1, 2 steps; Figure 104). With all four, ``f`` is the cubic through them; with fewer, ``c`` and
  ``d`` are 0 (``junctions.elevation_grid.polynome_coefficient_values``: a cubic's ``c`` and ``d`` need four support
  points), so ``f`` is the line through the two corners.
* ``T_s`` at a corner is ``f'`` of the square's edge along ``s`` through it, ``T_t`` likewise along ``t``. ``T_st`` is
  the derivative along ``t`` of ``T_s``: ``f'`` of the polynomial, built the same way, through the ``T_s`` values of
  the square's ``s``-edges and of the parallel edges one step beyond each (the same 4 x 4 points as Figure 104).

``F`` is arranged so that the patch takes the corner values and tangents it is given (rows: ``s`` value and
derivative, columns: ``t``); 12.11.1 prints the blocks as ``[[Z, T_t], [T_s, T_st]]`` with ``Z`` laid out ``[t][s]``,
the transposed reading of the same patch. A plane is reproduced exactly, and so is any cubic along one grid line with
four points. Points outside every complete square (four corners present) have no height (NaN).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from xodrcheck.model import ElevationGrid

#: The constant matrix ``A`` of 12.11.1 (cubic Hermite basis: value and tangent at 0 and 1 -> coefficients).
HERMITE = np.array([[1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [-3.0, 3.0, -2.0, -1.0], [2.0, -2.0, 1.0, 1.0]])

#: Points this close to a square's edge (in grid steps) count as on it: they take the square their ``toward``
#: direction leads into (a road end is evaluated a relative 1e-9 before it, see ``rules.shared.road_ends.left_of``).
_EDGE = 1e-6


def edge_polynomial(
    before: np.ndarray, z0: np.ndarray, z1: np.ndarray, after: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Coefficients ``(a, b, c, d)`` of ``f(x) = a + b x + c x^2 + d x^3`` along edges from ``z0`` (x=0) to ``z1``
    (x=1): the cubic through ``before`` (x=-1), ``z0``, ``z1`` and ``after`` (x=2) where both neighbours are finite,
    else the line through ``z0`` and ``z1`` (``c = d = 0``). Element-wise over arrays."""
    z0, z1 = np.asarray(z0, dtype=float), np.asarray(z1, dtype=float)
    full = np.isfinite(before) & np.isfinite(after)
    c = np.where(full, 0.5 * (z1 + before) - z0, 0.0)
    d = np.where(full, (after - before + 3.0 * (z0 - z1)) / 6.0, 0.0)
    b = np.where(full, 0.5 * (z1 - before) - d, z1 - z0)
    return z0, b, c, d


def edge_tangents(before: np.ndarray, z0: np.ndarray, z1: np.ndarray, after: np.ndarray) -> tuple[np.ndarray, ...]:
    """``f'(0)`` and ``f'(1)`` of :func:`edge_polynomial` (per grid step)."""
    _, b, c, d = edge_polynomial(before, z0, z1, after)
    return b, b + 2.0 * c + 3.0 * d


@dataclass(frozen=True)
class GridPoints:
    """The grid's z-values, as compact as the file holds them: each row's centre value (NaN: none) and its left and
    right values in flat arrays with each row's start and count (inside out)."""

    center: np.ndarray
    left: np.ndarray
    left_start: np.ndarray
    left_count: np.ndarray
    right: np.ndarray
    right_start: np.ndarray
    right_count: np.ndarray

    def z(self, row: np.ndarray, k: np.ndarray) -> np.ndarray:
        """z of the points in rows ``row`` at ``t = k * gridSpacing`` (``k`` > 0 left, < 0 right); NaN where the grid
        has no such point. Element-wise over integer arrays."""
        row, k = np.asarray(row), np.asarray(k)
        rows = len(self.center)
        ok = (row >= 0) & (row < rows)
        r = np.where(ok, row, 0)
        out = np.where(ok & (k == 0), self.center[r], np.nan)
        for sign, values, start, count in (
            (1, self.left, self.left_start, self.left_count),
            (-1, self.right, self.right_start, self.right_count),
        ):
            m = sign * k
            there = ok & (m >= 1) & (m <= count[r])
            if there.any():
                out = np.where(there, values[np.where(there, start[r] + m - 1, 0)], out)
        return out


def grid_points(grid: ElevationGrid) -> GridPoints | None:
    """The grid's points (``None`` when a row's list does not parse or the grid has no row)."""
    rows = grid.rows
    if not rows or any(r.center is None or r.left is None or r.right is None for r in rows):
        return None
    center = np.array([r.center[0] if r.center else np.nan for r in rows], dtype=float)

    def flat(lists: list[tuple[float, ...]]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        count = np.array([len(v) for v in lists], dtype=np.intp)
        start = np.concatenate(([0], np.cumsum(count)[:-1])).astype(np.intp)
        values = np.fromiter((z for v in lists for z in v), dtype=float, count=int(count.sum()))
        return values, start, count

    # a row without its centre point breaks the squares through it: none of its points are used
    left = flat([(r.left or ()) if r.center else () for r in rows])
    right = flat([(r.right or ()) if r.center else () for r in rows])
    return GridPoints(center, *left, *right)


@dataclass(frozen=True)
class GridSurface:
    """A junction elevation grid ready to evaluate: rows ``sStart + i * gridSpacing`` along the junction reference
    line, points ``k * gridSpacing`` across it."""

    s0: float
    spacing: float
    points: GridPoints

    def evaluate(
        self, s: np.ndarray, t: np.ndarray, toward: tuple[np.ndarray, np.ndarray] | None = None
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """z and its derivatives ``dz/ds``, ``dz/dt`` at points ``(s, t)`` of the junction reference line's frame
        (NaN outside every complete square). A point on the edge between squares takes the square that
        ``toward`` (a direction ``(ds, dt)`` per point) leads into; without it, or where that square is incomplete,
        one that is complete."""
        with np.errstate(over="ignore", invalid="ignore"):
            u = (np.asarray(s, dtype=float) - self.s0) / self.spacing
            v = np.asarray(t, dtype=float) / self.spacing
        du, dv = (np.zeros_like(u), np.zeros_like(v)) if toward is None else toward
        finite = np.isfinite(u) & np.isfinite(v)
        # far outside any grid a file can hold: kept finite and small enough for integer indices
        u, v = np.clip(np.where(finite, u, 0.0), -1e12, 1e12), np.clip(np.where(finite, v, 0.0), -1e12, 1e12)
        i = np.floor(u + _EDGE * np.sign(du)).astype(np.intp)
        j = np.floor(v + _EDGE * np.sign(dv)).astype(np.intp)
        z, dz_ds, dz_dt = self._at(u, v, i, j)
        # on an edge, next to a missing square: the square on its other side
        near_i, near_j = _other_side(u, i), _other_side(v, j)
        retry = np.isnan(z) & ((near_i != i) | (near_j != j))
        for alt_i, alt_j in ((near_i, j), (i, near_j), (near_i, near_j)):
            if not retry.any():
                break
            k = np.flatnonzero(retry)
            found = self._at(u[k], v[k], alt_i[k], alt_j[k])
            for whole, part in zip((z, dz_ds, dz_dt), found):
                whole[k] = part
            retry[k] = np.isnan(found[0])
        bad = ~finite
        return np.where(bad, np.nan, z), np.where(bad, np.nan, dz_ds), np.where(bad, np.nan, dz_dt)

    def _at(self, u: np.ndarray, v: np.ndarray, i: np.ndarray, j: np.ndarray) -> tuple[np.ndarray, ...]:
        """The patch of square (row ``i``, column ``j``) per point, at grid coordinates ``u, v``."""
        offsets = np.arange(-1, 3)
        stencil = self.points.z(i[:, None, None] + offsets[None, :, None], j[:, None, None] + offsets[None, None, :])
        fs, ft = u - i, v - j
        ps, pt = _powers(fs), _powers(ft)
        with np.errstate(over="ignore", invalid="ignore"):  # absurd z-values or spacings: inf or NaN, no warning
            alpha = patch(stencil)
            z = np.einsum("na,nab,nb->n", ps, alpha, pt)
            dz_ds = np.einsum("na,nab,nb->n", _slopes(fs), alpha, pt) / self.spacing
            dz_dt = np.einsum("na,nab,nb->n", ps, alpha, _slopes(ft)) / self.spacing
        return z, dz_ds, dz_dt


def _other_side(x: np.ndarray, cell: np.ndarray) -> np.ndarray:
    """For coordinates on an edge between two squares (within ``_EDGE``), the square on the other side than
    ``cell``; elsewhere ``cell``."""
    edge = np.round(x).astype(np.intp)
    on_edge = np.abs(x - edge) < _EDGE
    return np.where(on_edge, np.where(cell == edge, edge - 1, edge), cell)


def patch(stencil: np.ndarray) -> np.ndarray:
    """``alpha`` (n x 4 x 4) of squares from their 4 x 4 surrounding points (n x 4 x 4: rows -1..2 along ``s``,
    columns -1..2 along ``t``, the square between rows and columns 0 and 1; NaN: no point). NaN for a square
    missing a corner."""
    z = stencil
    ts0, ts1 = edge_tangents(z[:, 0], z[:, 1], z[:, 2], z[:, 3])  # T_s at rows 0 and 1, per column (n x 4)
    tt0, tt1 = edge_tangents(z[:, :, 0], z[:, :, 1], z[:, :, 2], z[:, :, 3])  # T_t at columns 0 and 1, per row
    st00, st01 = edge_tangents(ts0[:, 0], ts0[:, 1], ts0[:, 2], ts0[:, 3])  # T_st: T_s differentiated along t
    st10, st11 = edge_tangents(ts1[:, 0], ts1[:, 1], ts1[:, 2], ts1[:, 3])
    f = np.empty((len(z), 4, 4))
    f[:, 0, 0], f[:, 0, 1], f[:, 1, 0], f[:, 1, 1] = z[:, 1, 1], z[:, 1, 2], z[:, 2, 1], z[:, 2, 2]
    f[:, 0, 2], f[:, 0, 3], f[:, 1, 2], f[:, 1, 3] = tt0[:, 1], tt1[:, 1], tt0[:, 2], tt1[:, 2]
    f[:, 2, 0], f[:, 2, 1], f[:, 3, 0], f[:, 3, 1] = ts0[:, 1], ts0[:, 2], ts1[:, 1], ts1[:, 2]
    f[:, 2, 2], f[:, 2, 3], f[:, 3, 2], f[:, 3, 3] = st00, st01, st10, st11
    return np.einsum("ab,nbc,dc->nad", HERMITE, f, HERMITE)


def _powers(x: np.ndarray) -> np.ndarray:
    return np.stack((np.ones_like(x), x, x * x, x * x * x), axis=-1)


def _slopes(x: np.ndarray) -> np.ndarray:
    return np.stack((np.zeros_like(x), np.ones_like(x), 2.0 * x, 3.0 * x * x), axis=-1)


def grid_surface(grid: ElevationGrid) -> GridSurface | None:
    """The grid's bicubic surface (``None`` without a positive spacing and ``sStart``, or with a row that does not
    parse: the structural rules report those)."""
    if grid.spacing is None or not grid.spacing > 0 or grid.s_start is None:
        return None
    points = grid_points(grid)
    return None if points is None else GridSurface(float(grid.s_start), float(grid.spacing), points)
