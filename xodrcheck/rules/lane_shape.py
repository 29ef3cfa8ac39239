"""Lane shapes (``G010``, ``G011``): every lane's outer border stays on the outer side of its inner border over the
whole lane section, checked exactly rather than at samples.

Between consecutive knots (section ends, record starts of every lane, the laneOffset and the plan view) every border's
``t`` is one cubic polynomial in ``s``; each lane's signed width ``sign * (t_outer - t_inner)`` is recovered on each
piece from four evaluations and its minimum found from the roots of its derivative. A lane given by ``<width>``
records with a negative minimum has a negative width (``G010``); a lane given by ``<border>`` records crosses its inner
neighbour (``G011``, ASAM's ``road.lane.border.overlap_with_inner_lanes``).
"""

from __future__ import annotations

import weakref
from collections.abc import Iterator

import numpy as np

from xodrcheck.findings import Category, Severity
from xodrcheck.geometry.batch import Evaluation
from xodrcheck.model import Road
from xodrcheck.rules.registry import rule
from xodrcheck.rules.shared import lane_uids as U
from xodrcheck.rules.shared.context import Context
from xodrcheck.rules.shared.sampled import BATCH_SAMPLES
from xodrcheck.support.quantities import metres

_NODES = np.array([0.125, 0.375, 0.625, 0.875])
_FIT = np.linalg.inv(np.vander(_NODES, 4, increasing=True))  # values at the nodes -> coefficients in u


def _cubic_minimum(coef: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Minimum over ``u`` in [0, 1] of ``c0 + c1 u + c2 u^2 + c3 u^3`` for each column of ``coef`` (4, n): the values
    and where they are reached."""
    c0, c1, c2, c3 = coef
    candidates = [np.zeros_like(c0), np.ones_like(c0)]
    a, b, c = 3.0 * c3, 2.0 * c2, c1  # derivative a u^2 + b u + c; roots by the cancellation-free formula
    with np.errstate(divide="ignore", invalid="ignore"):
        disc = np.sqrt(np.maximum(b * b - 4.0 * a * c, 0.0))
        q = -0.5 * (b + np.where(b >= 0, disc, -disc))
        r1, r2 = q / a, c / q
    for r in (r1, r2):
        candidates.append(np.clip(np.where(np.isfinite(r), r, 0.0), 0.0, 1.0))
    u = np.stack(candidates)
    values = c0 + u * (c1 + u * (c2 + u * c3))
    k = np.argmin(values, axis=0)
    columns = np.arange(values.shape[1])
    return values[k, columns], u[k, columns]


_PIECES: weakref.WeakKeyDictionary[Context, dict] = weakref.WeakKeyDictionary()


def lane_pieces(ctx: Context, road: Road, index: int):
    """:func:`section_pieces` of a section, computed once per file for the rules that share it (G010, G011, G015):
    on first use for every usable road's sections, their borders evaluated together (:func:`_all_borders`: the same
    numbers as section by section)."""
    cache = _PIECES.get(ctx)
    if cache is None:
        cache = _PIECES[ctx] = {}
        nodes = {}
        for each in ctx.document.roads:
            if ctx.usable_geometry(each) is not None:
                for i in range(len(each.lane_sections)):
                    nodes[(id(each), i)] = (each, piece_nodes(ctx, each, i))
        for key, borders in _all_borders(ctx, nodes):  # one batch's borders alive at a time
            each, found = nodes[key]
            cache[key] = section_pieces(ctx, each, key[1], found, borders)
        for key, (each, found) in nodes.items():
            if key not in cache:
                cache[key] = None if found is None else section_pieces(ctx, each, key[1], found)
    key = (id(road), index)
    if key not in cache:  # a road the file-wide pass skipped (asked for by a caller of its own)
        cache[key] = section_pieces(ctx, road, index, piece_nodes(ctx, road, index))
    return cache[key]


#: Samples of the file-wide border pass evaluated together: half of the other passes' batch, as every sample holds
#: the borders of all of a section's lanes.
_BORDER_BATCH_SAMPLES = BATCH_SAMPLES // 2


def _all_borders(ctx: Context, nodes: dict) -> Iterator[tuple[tuple[int, int], dict[int, np.ndarray]]]:
    """(key, :meth:`RoadGeometry.borders` at the piece nodes) of every section with pieces, evaluated in batches of
    sections (the same numbers as section by section, with a fraction of the numpy calls)."""
    from xodrcheck.support.arrays import batches

    keys, sections, samples = [], [], []
    for key, (road, found) in nodes.items():
        if found is not None:
            keys.append(key)
            sections.append(ctx.road_geometry(road).rows(key[1]))
            samples.append(found[2])
    for lo, hi in batches([len(s) for s in samples], _BORDER_BATCH_SAMPLES):
        evaluation = Evaluation(sections[lo:hi], samples[lo:hi])
        yield from ((key, evaluation.borders(k)) for k, key in enumerate(keys[lo:hi]))


_EXTREMES: weakref.WeakKeyDictionary[Context, dict] = weakref.WeakKeyDictionary()


def _extremes(ctx: Context, road: Road, index: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(minimum, where, maximum)`` of every piece's cubic of a section (see :func:`_cubic_minimum`), for the whole
    file in one vectorised pass on first use (the same numbers as section by section: every column is its own cubic;
    a thousand small calls cost more than the arithmetic)."""
    cache = _EXTREMES.get(ctx)
    if cache is None:
        keys, blocks = [], []
        for each in ctx.document.roads:
            if ctx.usable_geometry(each) is not None:
                for i in range(len(each.lane_sections)):
                    pieces = lane_pieces(ctx, each, i)
                    if pieces is not None:
                        keys.append((id(each), i))
                        blocks.append(pieces[4])
        cache = _EXTREMES[ctx] = dict(zip(keys, _split_extremes(blocks)))
    key = (id(road), index)
    if key not in cache:  # a road the file-wide pass skipped (asked for by a caller of its own)
        pieces = lane_pieces(ctx, road, index)
        assert pieces is not None, "extremes are asked for sections with pieces only"
        cache[key] = _split_extremes([pieces[4]])[0]
    return cache[key]


def _split_extremes(blocks: list[np.ndarray]) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    if not blocks:
        return []
    together = np.concatenate(blocks, axis=1)
    with np.errstate(over="ignore", invalid="ignore"):
        low, where = _cubic_minimum(together)
        high = -_cubic_minimum(-together)[0]
    cuts = np.cumsum([block.shape[1] for block in blocks])[:-1]
    return list(zip(np.split(low, cuts), np.split(where, cuts), np.split(high, cuts)))


def piece_nodes(ctx: Context, road: Road, index: int) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """``(a, b, s)``: the pieces ``[a, b]`` between consecutive knots of a section and the ``s`` of their nodes
    (where :func:`section_pieces` evaluates the borders); ``None`` when the section has no piece."""
    cuts = ctx.road_geometry(road).knots(index)
    if len(cuts) < 2:
        return None
    a, b = cuts[:-1], cuts[1:]
    keep = b - a > 1e-9
    a, b = a[keep], b[keep]
    if not len(a):
        return None
    return a, b, (a[:, None] + (b - a)[:, None] * _NODES[None, :]).ravel()


def section_pieces(ctx: Context, road: Road, index: int, nodes, borders: dict[int, np.ndarray] | None = None):
    """Every lane with records in a section and its signed width as exact cubics: ``(lanes, a, b, coefficients)``
    with the pieces ``[a, b]`` between consecutive knots and ``coefficients[:, :, k]`` the cubic in ``u`` in [0, 1] of
    each lane's width on piece ``k`` (all lanes and pieces of the section in one vectorised pass); ``None`` when the
    section has no piece or no such lane. ``nodes``: :func:`piece_nodes`; ``borders``: the borders at them when
    evaluated already (else evaluated here, the section alone; :func:`lane_pieces` keeps them for the whole file)."""
    if nodes is None:
        return None
    a, b, s = nodes
    geometry = ctx.road_geometry(road)
    if borders is None:
        borders = geometry.borders(index, s)
    lanes, widths = [], []
    for sign, side in zip((+1, -1), geometry.side_lanes(index)):
        inner = borders[0]
        for lane, law in zip(side.lanes, side.laws):
            outer = borders[lane.id]
            if law is not None:
                lanes.append(lane)
                widths.append((sign * (outer - inner)).reshape(-1, 4))
            inner = outer
    if not lanes:
        return None
    raw = np.concatenate(widths)
    with np.errstate(over="ignore", invalid="ignore"):  # damaged widths near the float limit
        coefficients = _FIT @ np.where(np.isfinite(raw), raw, 0.0).T
    return lanes, a, b, raw, coefficients


def lane_minima(ctx: Context, road: Road, index: int):
    """(lane, minimum signed width, s where reached) for every lane with records in a section, from the exact
    per-piece cubics."""
    pieces = lane_pieces(ctx, road, index)
    if pieces is None:
        return
    lanes, a, b, raw, _ = pieces
    value, u, _ = _extremes(ctx, road, index)
    # Where the cubic fit overflows (widths near the float limit), fall back to the smallest width at the nodes.
    nodes = np.where(np.isnan(raw), np.inf, raw)
    lost = ~np.isfinite(value)
    value = np.where(lost, nodes.min(axis=1), value)
    u = np.where(lost, _NODES[np.argmin(nodes, axis=1)], u)
    value, u = value.reshape(len(lanes), -1), u.reshape(len(lanes), -1)
    for row, lane in enumerate(lanes):
        k = int(np.argmin(value[row]))
        yield lane, float(value[row, k]), float(a[k] + u[row, k] * (b[k] - a[k]))


def lane_width_bounds(ctx: Context, road: Road, index: int):
    """``(lanes, a, b, low, high)``: the smallest and largest signed width of every lane with records on every piece
    ``[a, b]`` of a section (exact per piece; ``None`` when there is nothing to bound)."""
    pieces = lane_pieces(ctx, road, index)
    if pieces is None:
        return None
    lanes, a, b, raw, _ = pieces
    low, _, high = _extremes(ctx, road, index)
    nodes = np.where(np.isfinite(raw), raw, np.nan)
    lost = ~(np.isfinite(low) & np.isfinite(high))
    with np.errstate(invalid="ignore"):
        low = np.where(lost, np.nanmin(np.where(np.isnan(nodes), np.inf, nodes), axis=1), low)
        high = np.where(lost, np.nanmax(np.where(np.isnan(nodes), -np.inf, nodes), axis=1), high)
    shape = (len(lanes), -1)
    return lanes, a, b, low.reshape(shape), high.reshape(shape)


_MINIMA: weakref.WeakKeyDictionary[Context, list] = weakref.WeakKeyDictionary()


def _width_findings(ctx: Context, by_widths: bool):
    """Lanes (with ``<width>`` records when ``by_widths``, else with ``<border>`` records) whose signed width drops
    under ``-zero_width``; the minima are computed once per file for both rules."""
    tol = ctx.tolerances.zero_width
    found = _MINIMA.get(ctx)
    if found is None:
        found = []
        for road, geometry, index, section in ctx.usable_sections():
            for lane, minimum, s in lane_minima(ctx, road, index):
                if minimum < -tol:
                    found.append((road, geometry, index, section, lane, minimum, s))
        _MINIMA[ctx] = found
    for road, geometry, index, section, lane, minimum, s in found:
        if bool(lane.widths) != by_widths:
            continue
        point = geometry.lane_points(index, lane.id, np.array([s]), "outer")
        where = {
            "road": road.id,
            "lane": lane.id,
            "section_s": section.s,
            "s": s,
            "x": float(point.x[0]),
            "y": float(point.y[0]),
            "line": lane.line or section.line or None,
        }
        yield lane, section, minimum, where


@rule("G010", "negative-width", Category.GEOMETRY, Severity.ERROR, uids=(U.WIDTH_VALIDITY,), every_version=True)
def negative_width(ctx: Context):
    """A lane's width becomes negative somewhere in its lane section.

    The width polynomials are minimised exactly over each record's interval (not only at sample points), so a cubic
    that dips below zero between its ends is found. A negative width puts the outer border inside the inner one
    (Annex F ``road.lane.width.lane_width_validity``: width(ds) >= 0).

    Passes (3.5 m narrowing linearly to 0 over the 50 m section)::

        <laneSection s="0"> ... <lane id="-1"><width sOffset="0" a="3.5" b="-0.07" c="0" d="0"/>

    Fails (narrowing to -1.5 m)::

        <laneSection s="0"> ... <lane id="-1"><width sOffset="0" a="3.5" b="-0.1" c="0" d="0"/>
    """
    for lane, section, minimum, where in _width_findings(ctx, True):
        yield negative_width.finding(
            f"road {where['road']}: lane {lane.id} of the lane section at s={metres(section.s)} is {minimum:.4g} m "
            f"wide at s={metres(where['s'])}; its width records must stay >= 0 over the section",
            **where,
        )


@rule(
    "G011",
    "border-crosses-inner",
    Category.GEOMETRY,
    Severity.ERROR,
    uids=(U.BORDER_OVERLAP_INNER,),
    every_version=True,
)
def border_crosses_inner(ctx: Context):
    """A lane given by ``<border>`` records has its outer border on the wrong side of its inner border.

    For a left lane the outer border's ``t`` must stay at or above the inner border's, for a right lane at or below,
    over the whole section (checked exactly per polynomial piece). Annex F
    ``road.lane.border.overlap_with_inner_lanes``.

    Passes (lane 1's border at t=3.5, outside lane 0 at t=0)::

        <left><lane id="1"><border sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left>

    Fails (the border crosses t=0 at s=35)::

        <left><lane id="1"><border sOffset="0" a="3.5" b="-0.1" c="0" d="0"/></lane></left>
    """
    for lane, section, minimum, where in _width_findings(ctx, False):
        yield border_crosses_inner.finding(
            f"road {where['road']}: lane {lane.id} of the lane section at s={metres(section.s)}: its outer border lies "
            f"{-minimum:.4g} m on the inner side of its inner border at s={metres(where['s'])}; the lane's borders "
            "cross",
            **where,
        )
