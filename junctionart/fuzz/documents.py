"""Hypothesis strategies for small, valid OpenDRIVE documents built without the generator.

A document is a three-leg junction: an incoming chain of roads ends at the junction; a straight connecting road leads
to a second chain, a right-turning arc to a third. Every chain is made of line, arc, spiral and paramPoly3 elements
with continuous position and heading, its heading kept inside a band so that no chain folds back onto itself or onto
another one, and its curvature kept well below what the narrowest lane centre tolerates. The checker must find no
error in any of them (a property of the test suite).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from hypothesis import strategies as st
from hypothesis.errors import InvalidArgument

from junctionart.fuzz import xodrbuild as xb

__all__ = [
    "DEFAULT_VERSIONS",
    "KINDS",
    "MAX_CURVATURE",
    "TURN_RADIUS",
    "VERSIONS",
    "document_specs",
    "opendrive_documents",
]


#: Element kinds that :func:`opendrive_documents` may use.
KINDS = ("line", "arc", "spiral", "paramPoly3")
#: OpenDRIVE versions (major, minor) the documents may declare.
VERSIONS = ((1, 4), (1, 5), (1, 6), (1, 7), (1, 8), (1, 9))
#: The versions drawn when none are asked for (1.9 only on request, so the derandomized examples stay the same).
DEFAULT_VERSIONS = VERSIONS[:-1]
#: Largest curvature (1/m) of any element: lane centres of three 4 m lanes stay above a 25 m radius.
MAX_CURVATURE = 1.0 / 40.0
#: Radius (m) of the junction's right turn, and half the length of its straight connection.
TURN_RADIUS = 30.0
_OUTER_TYPES = ("driving", "shoulder", "sidewalk", "border", "biking", "parking")


def _check_positive(name: str, value, *, integer: bool = False) -> None:
    kind = int if integer else (int, float)
    if isinstance(value, bool) or not isinstance(value, kind) or not math.isfinite(value) or value <= 0:
        what = "a positive integer" if integer else "a positive finite number"
        raise InvalidArgument(f"{name}={value!r} must be {what}")


def _check_bounds(lo_name: str, lo, hi_name: str, hi, *, integer: bool = False) -> None:
    _check_positive(lo_name, lo, integer=integer)
    _check_positive(hi_name, hi, integer=integer)
    if lo > hi:
        raise InvalidArgument(f"{lo_name}={lo!r} must not exceed {hi_name}={hi!r}")


@st.composite
def _element(draw, kinds: tuple[str, ...], min_length: float, max_length: float) -> xb.Element:
    kind = draw(st.sampled_from(kinds))
    length = draw(st.floats(min_length, max_length, allow_nan=False, allow_infinity=False))
    k = st.floats(-MAX_CURVATURE, MAX_CURVATURE, allow_nan=False, allow_infinity=False)
    if kind == "line":
        return xb.Element("line", length)
    if kind == "arc":
        return xb.Element("arc", length, (("curvature", draw(k)),))
    if kind == "spiral":
        return xb.Element("spiral", length, (("curvStart", draw(k)), ("curvEnd", draw(k))))
    frac = st.floats(-1.0, 1.0, allow_nan=False, allow_infinity=False)
    c_u, d_u, c_v, d_v = draw(frac) * 0.2, draw(frac) * 0.1, draw(frac) * 0.1, draw(frac) * 0.05
    return xb.param_poly3(length, c_u * length, d_u * length, c_v * length, d_v * length, draw(st.booleans()))


def _fits(e: xb.Element, heading: float, band: tuple[float, float]) -> bool:
    dh, k = xb.profile(e)
    h = heading + dh
    return bool(np.all(np.abs(k) <= MAX_CURVATURE * 1.0001) and h.min() >= band[0] and h.max() <= band[1])


@st.composite
def _chain(
    draw,
    start: xb.Pose,
    band: tuple[float, float],
    n_roads: int,
    prefix: str,
    kinds,
    min_length,
    max_length,
    max_elements,
) -> list[tuple[xb.Pose, tuple[xb.Element, ...]]]:
    """Roads (start pose, elements) chained end to start; headings stay in ``start.hdg + band``."""
    out = []
    pose = start
    absolute = (start.hdg + band[0], start.hdg + band[1])
    for _ in range(n_roads):
        elements = []
        road_start = pose
        for _ in range(draw(st.integers(1, max_elements))):
            e = draw(_element(kinds, min_length, max_length))
            if not _fits(e, pose.hdg, absolute):
                e = xb.Element("line", e.length)  # out of the band: a straight element keeps the heading
            elements.append(e)
            pose = xb.end_pose(pose, e)
        out.append((road_start, tuple(elements)))
    return out


def _lanes(
    n_left: int, n_right: int, widths: list[float], outer: str, pred: bool, succ: bool, flip: bool = False
) -> tuple:
    """Lanes of one road; linked lanes keep their id (``flip``: the neighbours' ids have the other sign)."""
    lanes = []
    for side, n in ((1, n_left), (-1, n_right)):
        for k in range(1, n + 1):
            lid = side * k
            other = -lid if flip else lid
            kind = outer if k == n and n > 1 else "driving"
            lanes.append(xb.LaneSpec(lid, kind, widths[k - 1], other if pred else None, other if succ else None))
    return tuple(lanes)


@st.composite
def _document_specs(
    draw,
    *,
    kinds: tuple[str, ...] = KINDS,
    min_length: float = 2.0,
    max_length: float = 80.0,
    max_roads_per_chain: int = 3,
    max_elements: int = 3,
    max_lanes: int = 3,
    versions: tuple[tuple[int, int], ...] = DEFAULT_VERSIONS,
) -> xb.DocumentSpec:
    lane_count = st.integers(1, max_lanes)
    n_left, n_right = draw(lane_count), draw(lane_count)
    widths = [draw(st.floats(2.5, 4.0, allow_nan=False)) for _ in range(max(n_left, n_right))]
    outer = draw(st.sampled_from(_OUTER_TYPES))
    origin = xb.Pose(draw(st.floats(-1e4, 1e4)), draw(st.floats(-1e4, 1e4)), draw(st.floats(-math.pi, math.pi)))
    n = st.integers(1, max_roads_per_chain)
    a, b, c = draw(n), draw(n), draw(n)
    twenty, forty = math.radians(20), math.radians(40)
    chain_a = draw(_chain(origin, (-twenty, twenty), a, "a", kinds, min_length, max_length, max_elements))
    p = _road_end(chain_a[-1])
    ch, sh = math.cos(p.hdg), math.sin(p.hdg)
    start_b = xb.Pose(p.x + 2 * TURN_RADIUS * ch, p.y + 2 * TURN_RADIUS * sh, p.hdg)
    start_c = xb.Pose(p.x + TURN_RADIUS * (ch + sh), p.y + TURN_RADIUS * (sh - ch), p.hdg - math.pi / 2)
    chain_b = draw(_chain(start_b, (-twenty, twenty), b, "b", kinds, min_length, max_length, max_elements))
    chain_c = draw(_chain(start_c, (0.0, forty), c, "c", kinds, min_length, max_length, max_elements))
    ids = iter(str(i) for i in draw(st.permutations(range(1, a + b + c + 5))))
    roads: list[xb.RoadSpec] = []

    def chain_roads(chain, first_pred, last_succ) -> list[str]:
        names = [next(ids) for _ in chain]
        for i, ((start, elements), rid) in enumerate(zip(chain, names)):
            pred = xb.LinkSpec("road", names[i - 1], "end") if i > 0 else first_pred
            succ = xb.LinkSpec("road", names[i + 1], "start") if i + 1 < len(chain) else last_succ
            lanes = _lanes(n_left, n_right, widths, outer, i > 0, i + 1 < len(chain))
            roads.append(xb.RoadSpec(rid, start, elements, lanes, "-1", pred, succ))
        return names

    jid = str(draw(st.integers(100, 10_000)))
    to_j = xb.LinkSpec("junction", jid)
    names_a = chain_roads(chain_a, None, to_j)
    names_b = chain_roads(chain_b, to_j, None)
    names_c = chain_roads(chain_c, to_j, None)
    plan = _LanePlan(n_left, n_right, widths, outer)
    connecting, junction = _junction(
        jid, [next(ids) for _ in range(4)], (p, start_b, start_c), (names_a, names_b, names_c), plan
    )
    roads += connecting
    order = draw(st.permutations(range(len(roads))))
    return xb.DocumentSpec(
        roads=tuple(roads[i] for i in order),
        junctions=(junction,),
        version=draw(st.sampled_from(versions)),
    )


class _LanePlan(NamedTuple):
    """The lanes of one document's roads: how many per side, their widths from the centre out, the outer lane's type."""

    n_left: int
    n_right: int
    widths: list[float]
    outer: str


def _junction(
    jid: str,
    jroads: list[str],
    starts: tuple[xb.Pose, xb.Pose, xb.Pose],
    names: tuple[list[str], list[str], list[str]],
    plan: _LanePlan,
) -> tuple[list[xb.RoadSpec], xb.JunctionSpec]:
    """The junction's four connecting roads (ids ``jroads``) and its connections, between the end of chain a (its
    pose ``starts[0]``) and the starts of chains b and c (``starts[1:]``); ``names``: each chain's road ids."""
    p, start_b, start_c = starts
    names_a, names_b, names_c = names
    n_left, n_right, widths, outer = plan
    right_only = _lanes(0, n_right, widths, outer, True, True)
    reverse_only = _lanes(0, n_left, widths, outer, True, True, flip=True)
    a_end, b_start, c_start = (
        xb.LinkSpec("road", names_a[-1], "end"),
        xb.LinkSpec("road", names_b[0], "start"),
        xb.LinkSpec("road", names_c[0], "start"),
    )
    # Each connecting road carries one direction (one connection per connecting road, as OpenDRIVE 1.7 requires):
    # straight on from a to b, right from a to c, and back from b and from c.
    table = (
        (p, 0.0, right_only, a_end, b_start),
        (p, -1 / TURN_RADIUS, right_only, a_end, c_start),
        (_reversed(start_b), 0.0, reverse_only, b_start, a_end),
        (_reversed(start_c), 1 / TURN_RADIUS, reverse_only, c_start, a_end),
    )
    roads = [
        xb.RoadSpec(rid, start, (_connecting_element(curvature),), lanes, jid, pred, succ)
        for rid, (start, curvature, lanes, pred, succ) in zip(jroads, table)
    ]
    into_a = tuple((-k, -k) for k in range(1, n_right + 1) if k < n_right or n_right == 1 or outer == "driving")
    into_bc = tuple((k, -k) for k in range(1, n_left + 1) if k < n_left or n_left == 1 or outer == "driving")
    connections = (
        xb.ConnectionSpec("0", names_a[-1], jroads[0], "start", into_a),
        xb.ConnectionSpec("1", names_a[-1], jroads[1], "start", into_a[-1:]),  # turn right from the outer lane
        xb.ConnectionSpec("2", names_b[0], jroads[2], "start", into_bc),
        xb.ConnectionSpec("3", names_c[0], jroads[3], "start", into_bc),
    )
    return roads, xb.JunctionSpec(jid, connections)


def _reversed(pose: xb.Pose) -> xb.Pose:
    return xb.Pose(pose.x, pose.y, pose.hdg + math.pi)


def _connecting_element(curvature: float) -> xb.Element:
    """A connecting road's one element: the straight connection (2 x :data:`TURN_RADIUS`), or a quarter turn."""
    if curvature == 0.0:
        return xb.Element("line", 2 * TURN_RADIUS)
    return xb.Element("arc", TURN_RADIUS * math.pi / 2, (("curvature", curvature),))


def _road_end(road: tuple[xb.Pose, tuple[xb.Element, ...]]) -> xb.Pose:
    pose = road[0]
    for e in road[1]:
        pose = xb.end_pose(pose, e)
    return pose


def opendrive_documents(
    *,
    kinds: tuple[str, ...] = KINDS,
    min_length: float = 2.0,
    max_length: float = 80.0,
    max_roads_per_chain: int = 3,
    max_elements: int = 3,
    max_lanes: int = 3,
    versions: tuple[tuple[int, int], ...] = DEFAULT_VERSIONS,
) -> st.SearchStrategy[bytes]:
    """Small valid OpenDRIVE files (bytes): three chains of roads around one default junction.

    ``kinds``: plan-view element kinds to draw from (a non-empty subset of :data:`KINDS`); ``min_length`` and
    ``max_length``: element lengths (m); ``max_roads_per_chain``, ``max_elements`` (per road) and ``max_lanes`` (per
    side, 1 to 3) bound the size; ``versions``: the (major, minor) OpenDRIVE versions to declare (from
    :data:`DEFAULT_VERSIONS`, any of :data:`VERSIONS`). The checker finds no error in any of them.
    """
    return document_specs(
        kinds=kinds,
        min_length=min_length,
        max_length=max_length,
        max_roads_per_chain=max_roads_per_chain,
        max_elements=max_elements,
        max_lanes=max_lanes,
        versions=versions,
    ).map(xb.to_bytes)


def document_specs(
    *,
    kinds: tuple[str, ...] = KINDS,
    min_length: float = 2.0,
    max_length: float = 80.0,
    max_roads_per_chain: int = 3,
    max_elements: int = 3,
    max_lanes: int = 3,
    versions: tuple[tuple[int, int], ...] = DEFAULT_VERSIONS,
) -> st.SearchStrategy[xb.DocumentSpec]:
    """Like :func:`opendrive_documents`, but the :class:`fuzz.xodrbuild.DocumentSpec` before it is written."""
    _validate(kinds, min_length, max_length, max_roads_per_chain, max_elements, max_lanes, versions)
    return _document_specs(
        kinds=tuple(kinds),
        min_length=float(min_length),
        max_length=float(max_length),
        max_roads_per_chain=max_roads_per_chain,
        max_elements=max_elements,
        max_lanes=max_lanes,
        versions=tuple((v[0], v[1]) for v in versions),
    )


def _validate(kinds, min_length, max_length, max_roads_per_chain, max_elements, max_lanes, versions) -> None:
    if isinstance(kinds, str) or not kinds or any(k not in KINDS for k in kinds):
        raise InvalidArgument(f"kinds={kinds!r} must be a non-empty collection of {', '.join(KINDS)}")
    _check_bounds("min_length", min_length, "max_length", max_length)
    if max_length > 1000:
        raise InvalidArgument(f"max_length={max_length!r} must be at most 1000 m (documents are kept small)")
    for name, value, top in (
        ("max_roads_per_chain", max_roads_per_chain, 20),
        ("max_elements", max_elements, 20),
        ("max_lanes", max_lanes, 3),
    ):
        _check_positive(name, value, integer=True)
        if value > top:
            raise InvalidArgument(f"{name}={value!r} must be at most {top}")
    if (
        isinstance(versions, str)
        or not versions
        or any(not isinstance(v, (tuple, list)) or tuple(v) not in VERSIONS for v in versions)
    ):
        raise InvalidArgument(f"versions={versions!r} must be a non-empty collection of {VERSIONS}")
