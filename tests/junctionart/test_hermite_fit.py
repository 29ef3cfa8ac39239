"""fit_connections (vectorised, screened, lazily tested) against its definition written plainly, one candidate at a
time: the same winner, radius and length for any target."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from junctionart.curves import arc_lengths, fit_connections
from junctionart.intersections.layout import SCALES

SAMPLES = np.linspace(0.0, 1.0, 65)
OFFSETS = (-1.75, -3.5)  # right-hand traffic, a 3.5 m lane: lane centre and outer border
MIN_RADIUS = 5.5


def _reference(u1: float, v1: float, phi: float) -> tuple[int, float] | None:
    """(index of the winning tangent scale, its smallest radius) by the definition, or None."""
    chord = math.hypot(u1, v1)
    best = None
    for i, scale in enumerate(SCALES):
        k = max(scale * chord, 1.0)
        cu, du = 3 * u1 - 2 * k - k * math.cos(phi), -2 * u1 + k + k * math.cos(phi)
        cv, dv = 3 * v1 - k * math.sin(phi), -2 * v1 + k * math.sin(phi)
        p = SAMPLES
        d1u, d1v = k + 2 * cu * p + 3 * du * p * p, 2 * cv * p + 3 * dv * p * p
        d2u, d2v = 2 * cu + 6 * du * p, 2 * cv + 6 * dv * p
        speed = np.hypot(d1u, d1v)
        if chord <= 1e-6 or speed.min() ** 2 <= 1e-18:
            continue
        kappa = (d1u * d2v - d1v * d2u) / speed**3
        off = min(OFFSETS)  # the outermost offset line bounds the others
        denom = 1.0 - off * kappa
        if denom.min() <= 0.05:
            continue  # the offset line folds
        worst = max(np.abs(kappa).max(), np.abs(kappa / denom).max())
        heading = np.unwrap(np.arctan2(d1v, d1u))
        if abs(abs(heading[-1] - heading[0]) - abs(phi)) >= 1e-6:
            continue  # the heading does not turn by exactly phi (a loop)
        radius = 1.0 / max(worst, 1e-300)  # a straight line: "infinite" radius, capped as the generator does
        if radius >= MIN_RADIUS and (best is None or radius > best[1] * (1 + 1e-12)):
            best = (i, radius)
    return best


targets = st.tuples(st.floats(-20.0, 90.0), st.floats(-90.0, 90.0), st.floats(-math.pi, math.pi))


@settings(max_examples=300, deadline=None, derandomize=True)
@given(st.lists(targets, min_size=1, max_size=12))
def test_fit_connections_picks_what_the_definition_picks(batch):
    fits = fit_connections(np.array(batch), OFFSETS, MIN_RADIUS, SCALES)
    assert len(fits) == len(batch)
    for (u1, v1, phi), fit in zip(batch, fits):
        ref = _reference(u1, v1, phi)
        if ref is None:
            assert fit is None
            continue
        assert fit is not None
        assert math.isclose(fit.min_radius, ref[1], rel_tol=1e-9)
        k = max(SCALES[ref[0]] * math.hypot(u1, v1), 1.0)
        assert math.isclose(fit.coef[1], k, rel_tol=1e-12)  # the winning tangent length
        assert math.isclose(fit.length, float(arc_lengths(np.array([fit.coef]))[0]), rel_tol=1e-12)


def test_a_quarter_turn_fits_and_a_hairpin_in_a_metre_does_not():
    turn, hairpin = fit_connections(
        np.array([[20.0, -20.0, -math.pi / 2], [0.0, -1.0, math.pi]]), OFFSETS, MIN_RADIUS, SCALES
    )
    assert turn is not None and turn.min_radius >= MIN_RADIUS
    assert hairpin is None
