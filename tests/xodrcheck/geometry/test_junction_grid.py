"""The junction elevation grid's interpolation (12.11.1): planes, cubics along a line and hand-computed values."""

from __future__ import annotations

import numpy as np
import pytest

from xodrcheck.geometry.junction_grid import edge_polynomial, grid_points, grid_surface
from xodrcheck.model import ElevationGrid, GridRow


def _grid(rows: list[tuple[list[float], float, list[float]]], s0: float = 0.0, spacing: float = 1.0) -> ElevationGrid:
    """A grid from (left inside out, centre, right inside out) per row."""
    return ElevationGrid(s0, spacing, tuple(GridRow((c,), tuple(lt), tuple(rt), 0) for lt, c, rt in rows), 0)


def _sampled(f, rows: int, left: list[int], right: list[int], s0: float, h: float) -> ElevationGrid:
    """A grid whose point (row i, t) holds f(s, t), with ``left[i]``/``right[i]`` points on each side."""
    out = []
    for i in range(rows):
        s = s0 + i * h
        out.append(
            (
                [f(s, k * h) for k in range(1, left[i] + 1)],
                f(s, 0.0),
                [f(s, -k * h) for k in range(1, right[i] + 1)],
            )
        )
    return _grid(out, s0, h)


def test_points_are_found_by_row_and_t_index():
    points = grid_points(_grid([([5.0, 6.0], 4.0, [3.0]), ([7.0], 8.0, []), ([9.0], float("nan"), [])]))
    assert points is not None
    rows = np.array([0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 3])
    k = np.array([-2, -1, 0, 1, 2, -1, 0, 1, 2, 0, 1, 0])
    z = points.z(rows, k)
    np.testing.assert_array_equal(z, [np.nan, 3.0, 4.0, 5.0, 6.0, np.nan, 8.0, 7.0, np.nan, np.nan, 9.0, np.nan])


def test_edge_polynomial_is_the_cubic_through_four_points_and_a_line_with_fewer():
    a, b, c, d = edge_polynomial(np.array([0.0]), np.array([0.0]), np.array([1.0]), np.array([0.0]))
    assert (a[0], b[0], c[0], d[0]) == pytest.approx((0.0, 1.0, 0.5, -0.5))  # x + x^2/2 - x^3/2
    a, b, c, d = edge_polynomial(np.array([np.nan]), np.array([2.0]), np.array([5.0]), np.array([9.0]))
    assert (a[0], b[0], c[0], d[0]) == (2.0, 3.0, 0.0, 0.0)  # c = d = 0: too few support points


def test_a_grid_sampled_from_a_plane_reproduces_the_plane_and_its_slopes():
    def plane(s, t):
        return 3.0 + 0.02 * s - 0.05 * t

    # rows of different widths, as 12.11's example has; the grid starts at s=2 with 4 m squares
    grid = _sampled(plane, 6, [2, 2, 3, 3, 2, 1], [2, 3, 3, 3, 2, 2], 2.0, 4.0)
    surface = grid_surface(grid)
    assert surface is not None
    rng = np.random.default_rng(7)
    s = rng.uniform(2.0, 22.0, 400)
    t = rng.uniform(-8.0, 4.0, 400)
    z, dz_ds, dz_dt = surface.evaluate(s, t)
    ok = np.isfinite(z)
    assert ok.sum() > 300  # most of them lie in complete squares
    np.testing.assert_allclose(z[ok], plane(s[ok], t[ok]), atol=1e-12)
    np.testing.assert_allclose(dz_ds[ok], 0.02, atol=1e-12)
    np.testing.assert_allclose(dz_dt[ok], -0.05, atol=1e-12)


def test_a_cubic_along_s_is_reproduced_where_four_rows_support_it():
    def cubic(s, t):
        return 0.001 * s**3 - 0.02 * s * s + 0.1 * s + 0.0 * t

    surface = grid_surface(_sampled(cubic, 7, [2] * 7, [2] * 7, 0.0, 5.0))
    assert surface is not None
    s = np.linspace(5.0, 24.5, 40)  # the squares between rows 1 and 5 have a row beyond each side
    t = np.full_like(s, 3.0)
    z, dz_ds, _ = surface.evaluate(s, t)
    np.testing.assert_allclose(z, cubic(s, t), atol=1e-12)
    np.testing.assert_allclose(dz_ds, 0.003 * s * s - 0.04 * s + 0.1, atol=1e-12)


def test_hand_computed_values():
    # rows 0..3 on the line at 0, 0, 1, 0; the left points all 0; 2 m squares
    surface = grid_surface(_grid([([0.0], 0.0, []), ([0.0], 0.0, []), ([0.0], 1.0, []), ([0.0], 0.0, [])], 0.0, 2.0))
    assert surface is not None
    # on the line, halfway between rows 1 and 2: the cubic x + x^2/2 - x^3/2 at x = 0.5
    z, dz_ds, dz_dt = surface.evaluate(np.array([3.0]), np.array([0.0]))
    assert z[0] == pytest.approx(0.5625)
    assert dz_ds[0] == pytest.approx((1.0 + 0.5 - 0.375) / 2.0)  # f'(0.5) per 2 m
    # across (two columns: the line through 0.5625 and 0): -0.5625 per 2 m
    assert dz_dt[0] == pytest.approx(-0.5625 / 2.0)
    # the minimal grid (four points) is bilinear: 1, 3 at s=0 and 5, 11 at s=10 -> centre 5, at (2.5, 7.5) ...
    square = grid_surface(_grid([([3.0], 1.0, []), ([11.0], 5.0, [])], 0.0, 10.0))
    assert square is not None
    z, _, _ = square.evaluate(np.array([5.0, 2.5]), np.array([5.0, 7.5]))
    assert z[0] == pytest.approx(5.0)
    # bilinear: (1-u)(1-v) 1 + u(1-v) 5 + (1-u)v 3 + uv 11 with u=0.25, v=0.75
    assert z[1] == pytest.approx(0.75 * 0.25 * 1 + 0.25 * 0.25 * 5 + 0.75 * 0.75 * 3 + 0.25 * 0.75 * 11)
    # its far corner and edges lie on the grid's border: still in the square
    z, _, _ = square.evaluate(np.array([10.0, 10.0, 0.0]), np.array([10.0, 5.0, 10.0]))
    np.testing.assert_allclose(z, [11.0, 8.0, 3.0])


def test_points_outside_complete_squares_have_no_height():
    surface = grid_surface(_grid([([1.0], 1.0, []), ([1.0], 1.0, [1.0]), ([], 1.0, [1.0])], 0.0, 1.0))
    assert surface is not None
    z, _, _ = surface.evaluate(np.array([0.5, 0.5, 1.5, 1.5, 2.5, -0.5]), np.array([0.5, -0.5, -0.5, 0.5, 0.0, 0.0]))
    assert np.isfinite(z).tolist() == [True, False, True, False, False, False]


def test_a_point_on_a_square_edge_takes_the_square_it_is_headed_into():
    # z = 0 for s <= 1, rising beyond: the slope at s=1 differs between the squares on each side
    surface = grid_surface(_grid([([0.0], 0.0, []), ([0.0], 0.0, []), ([1.0], 1.0, []), ([2.0], 2.0, [])], 0.0, 1.0))
    assert surface is not None
    s, t = np.array([1.0, 1.0]), np.array([0.5, 0.5])
    z, dz_ds, _ = surface.evaluate(s, t, (np.array([1.0, -1.0]), np.array([0.0, 0.0])))
    np.testing.assert_allclose(z, 0.0, atol=1e-12)
    assert dz_ds[0] != pytest.approx(dz_ds[1])


def test_a_bicubic_is_reproduced_inside_where_every_edge_has_four_points():
    # exact tangents and mixed derivatives: the patch is the bicubic itself (a wrong T_st or transposed block fails)
    def bicubic(s, t):
        return 0.5 + (0.01 * s**3 - 0.1 * s) * (0.02 * t**3 + 0.3 * t * t - t)

    surface = grid_surface(_sampled(bicubic, 6, [3] * 6, [3] * 6, 0.0, 1.0))
    assert surface is not None
    s, t = np.meshgrid(np.linspace(1.0, 3.95, 12), np.linspace(-1.95, 1.95, 12))
    z, dz_ds, dz_dt = surface.evaluate(s.ravel(), t.ravel())
    np.testing.assert_allclose(z, bicubic(s.ravel(), t.ravel()), atol=1e-12)
    step = 1e-6
    numeric = (bicubic(s.ravel() + step, t.ravel()) - bicubic(s.ravel() - step, t.ravel())) / (2 * step)
    np.testing.assert_allclose(dz_ds, numeric, atol=1e-8)
    numeric = (bicubic(s.ravel(), t.ravel() + step) - bicubic(s.ravel(), t.ravel() - step)) / (2 * step)
    np.testing.assert_allclose(dz_dt, numeric, atol=1e-8)


def test_far_away_and_undefined_points_have_no_height_and_no_warning():
    import warnings

    surface = grid_surface(_grid([([1.0], 1.0, []), ([1.0], 1.0, [])], 0.0, 1e-300))
    assert surface is not None
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        z, dz_ds, dz_dt = surface.evaluate(np.array([1.0, np.nan, 0.0, -1e300]), np.array([0.0, 0.0, np.inf, 5.0]))
    assert np.isnan(z).all() and np.isnan(dz_ds).all() and np.isnan(dz_dt).all()
