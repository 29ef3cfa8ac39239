"""A tiny OpenDRIVE writer for the fuzzers, independent of both the generator and the checker.

It knows just enough to write small, geometrically consistent maps: roads made of ``line``, ``arc``, ``spiral`` and
``paramPoly3`` elements chained with continuous position and heading, constant-width lanes on both sides, road links,
lane links and a default junction. End poses and paramPoly3 lengths are computed here with Gauss-Legendre quadrature
(no code is shared with :mod:`xodrcheck.geometry` or :mod:`junctionart.curves`, so a mistake in either is not
hidden by this one).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from lxml import etree

_GL_X, _GL_W = np.polynomial.legendre.leggauss(48)
_PANELS = 16


@dataclass(frozen=True)
class Pose:
    """A position and heading in the plane."""

    x: float
    y: float
    hdg: float


@dataclass(frozen=True)
class Element:
    """One plan-view element in its own frame: ``kind`` is line, arc, spiral or paramPoly3.

    ``params`` holds the kind's attributes: ``curvature`` (arc), ``curvStart``/``curvEnd`` (spiral), the eight
    ``aU``..``dV`` coefficients and ``pRange`` (paramPoly3). ``length`` is the arc length.
    """

    kind: str
    length: float
    params: tuple[tuple[str, float | str], ...] = ()

    def param(self, name: str):
        return dict(self.params)[name]


def _quad(fn, a: float, b: float) -> float:
    """Composite Gauss-Legendre integral of a vectorised ``fn`` over [a, b]."""
    edges = np.linspace(a, b, _PANELS + 1)
    half = 0.5 * np.diff(edges)
    mid = 0.5 * (edges[:-1] + edges[1:])
    x = (mid[:, None] + half[:, None] * _GL_X[None, :]).ravel()
    w = (half[:, None] * _GL_W[None, :]).ravel()
    return float(np.sum(w * fn(x)))


def _ppoly_derivative(e: Element, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    b_u, c_u, d_u = e.param("bU"), e.param("cU"), e.param("dU")
    b_v, c_v, d_v = e.param("bV"), e.param("cV"), e.param("dV")
    return b_u + 2 * c_u * p + 3 * d_u * p * p, b_v + 2 * c_v * p + 3 * d_v * p * p


def _normalised_length(coefficients: dict[str, float]) -> float:
    """Arc length of a paramPoly3 whose parameter runs over [0, 1]."""
    e = Element("paramPoly3", 1.0, tuple(coefficients.items()))
    return _quad(lambda p: np.hypot(*_ppoly_derivative(e, p)), 0.0, 1.0)


def param_poly3(b_u: float, c_u: float, d_u: float, c_v: float, d_v: float, arc_length: bool) -> Element:
    """A paramPoly3 starting at its own origin with heading 0 (``aU = aV = bV = 0``), written with either ``pRange``.

    The coefficients describe the curve for ``p`` in [0, 1]; with ``arc_length`` they are rescaled to ``p`` in
    [0, length] (same curve)."""
    normal = {"aU": 0.0, "bU": b_u, "cU": c_u, "dU": d_u, "aV": 0.0, "bV": 0.0, "cV": c_v, "dV": d_v}
    length = _normalised_length(normal)
    if not arc_length:
        return Element("paramPoly3", length, (*tuple(normal.items()), ("pRange", "normalized")))
    L = length
    scaled = {
        "aU": 0.0,
        "bU": b_u / L,
        "cU": c_u / L**2,
        "dU": d_u / L**3,
        "aV": 0.0,
        "bV": 0.0,
        "cV": c_v / L**2,
        "dV": d_v / L**3,
    }
    return Element("paramPoly3", length, (*tuple(scaled.items()), ("pRange", "arcLength")))


def _heading_change(e: Element, ds: np.ndarray) -> np.ndarray:
    """Heading change (relative to the element's start heading) at distances ``ds`` for line/arc/spiral."""
    if e.kind == "line":
        return np.zeros_like(ds)
    if e.kind == "arc":
        return e.param("curvature") * ds
    k0, k1 = e.param("curvStart"), e.param("curvEnd")
    return k0 * ds + 0.5 * (k1 - k0) / e.length * ds * ds


def profile(e: Element, n: int = 65) -> tuple[np.ndarray, np.ndarray]:
    """Heading change (from the element's start) and curvature at ``n`` points spread over the element."""
    if e.kind != "paramPoly3":
        ds = np.linspace(0.0, e.length, n)
        dh = _heading_change(e, ds)
        if e.kind == "line":
            return dh, np.zeros(n)
        if e.kind == "arc":
            return dh, np.full(n, e.param("curvature"))
        k0, k1 = e.param("curvStart"), e.param("curvEnd")
        return dh, k0 + (k1 - k0) * ds / e.length
    p_max = 1.0 if e.param("pRange") == "normalized" else e.length
    p = np.linspace(0.0, p_max, n)
    du, dv = _ppoly_derivative(e, p)
    ddu = 2 * e.param("cU") + 6 * e.param("dU") * p
    ddv = 2 * e.param("cV") + 6 * e.param("dV") * p
    return np.arctan2(dv, du), (du * ddv - dv * ddu) / np.hypot(du, dv) ** 3


def end_pose(start: Pose, e: Element) -> Pose:
    """Where an element that starts at ``start`` ends (position and heading)."""
    c, s = math.cos(start.hdg), math.sin(start.hdg)
    if e.kind == "paramPoly3":
        p_max = 1.0 if e.param("pRange") == "normalized" else e.length
        coef = {k: e.param(k) for k in ("aU", "bU", "cU", "dU", "aV", "bV", "cV", "dV")}
        u = coef["aU"] + coef["bU"] * p_max + coef["cU"] * p_max**2 + coef["dU"] * p_max**3
        v = coef["aV"] + coef["bV"] * p_max + coef["cV"] * p_max**2 + coef["dV"] * p_max**3
        du, dv = _ppoly_derivative(e, np.array([p_max]))
        dh = math.atan2(float(dv[0]), float(du[0]))
    elif e.kind == "line":
        u, v, dh = e.length, 0.0, 0.0
    elif e.kind == "arc" and abs(e.param("curvature")) > 1e-9:
        k = e.param("curvature")
        dh = k * e.length
        u, v = math.sin(dh) / k, (1.0 - math.cos(dh)) / k
    else:
        u = _quad(lambda d: np.cos(_heading_change(e, d)), 0.0, e.length)
        v = _quad(lambda d: np.sin(_heading_change(e, d)), 0.0, e.length)
        dh = float(_heading_change(e, np.array([e.length]))[0])
    return Pose(start.x + c * u - s * v, start.y + s * u + c * v, start.hdg + dh)


# ---------------------------------------------------------------------------------------------------------- roads
@dataclass(frozen=True)
class LaneSpec:
    """One lane: its id, type and constant width; links are lane ids on the neighbouring roads."""

    id: int
    type: str
    width: float
    predecessor: int | None = None
    successor: int | None = None


@dataclass(frozen=True)
class LinkSpec:
    """A road's predecessor or successor to write: element type and id, contact point."""

    element_type: str  # "road" or "junction"
    element_id: str
    contact_point: str | None = None


@dataclass(frozen=True)
class RoadSpec:
    """A road to write: start pose, plan-view elements, lanes and links."""

    id: str
    start: Pose
    elements: tuple[Element, ...]
    lanes: tuple[LaneSpec, ...]
    junction: str = "-1"
    predecessor: LinkSpec | None = None
    successor: LinkSpec | None = None

    @property
    def length(self) -> float:
        return float(sum(e.length for e in self.elements))

    def poses(self) -> list[Pose]:
        """Start pose of every element, then the road's end pose."""
        out = [self.start]
        for e in self.elements:
            out.append(end_pose(out[-1], e))
        return out


@dataclass(frozen=True)
class ConnectionSpec:
    """A junction connection to write: incoming and connecting roads, contact point, lane links."""

    id: str
    incoming: str
    connecting: str
    contact_point: str
    lane_links: tuple[tuple[int, int], ...]


@dataclass(frozen=True)
class JunctionSpec:
    """A junction to write: its id and connections."""

    id: str
    connections: tuple[ConnectionSpec, ...]


@dataclass(frozen=True)
class DocumentSpec:
    """A whole small map, before it is written."""

    roads: tuple[RoadSpec, ...]
    junctions: tuple[JunctionSpec, ...] = ()
    version: tuple[int, int] = (1, 8)
    name: str = "fuzz"
    meta: dict = field(default_factory=dict, compare=False)


def _num(x: float) -> str:
    return "0.0" if x == 0.0 else repr(float(x))


def _sub(parent, tag: str, **attrs) -> etree._Element:
    return etree.SubElement(parent, tag, {k: v for k, v in attrs.items() if v is not None})


def _write_link(parent, tag: str, link: LinkSpec | None) -> None:
    if link is not None:
        _sub(parent, tag, elementType=link.element_type, elementId=link.element_id, contactPoint=link.contact_point)


def _write_lane(parent, lane: LaneSpec, version: tuple[int, int]) -> None:
    el = _sub(parent, "lane", id=str(lane.id), type=lane.type, level="false")
    if lane.predecessor is not None or lane.successor is not None:
        link = _sub(el, "link")
        if lane.predecessor is not None:
            _sub(link, "predecessor", id=str(lane.predecessor))
        if lane.successor is not None:
            _sub(link, "successor", id=str(lane.successor))
    if lane.id != 0:
        _sub(el, "width", sOffset="0.0", a=_num(lane.width), b="0.0", c="0.0", d="0.0")
    mark = "solid" if lane.id == 0 else "broken"
    _sub(
        el,
        "roadMark",
        sOffset="0.0",
        type=mark,
        weight="standard",
        color="standard",
        width="0.12",
        laneChange="none" if lane.id == 0 else "both",
    )


def _write_road(root, road: RoadSpec, version: tuple[int, int]) -> None:
    el = _sub(
        root,
        "road",
        name=f"road {road.id}",
        length=_num(road.length),
        id=road.id,
        junction=road.junction,
        rule="RHT" if version >= (1, 5) else None,
    )
    if road.predecessor is not None or road.successor is not None:
        link = _sub(el, "link")
        _write_link(link, "predecessor", road.predecessor)
        _write_link(link, "successor", road.successor)
    plan = _sub(el, "planView")
    s = 0.0
    for pose, e in zip(road.poses(), road.elements):
        g = _sub(plan, "geometry", s=_num(s), x=_num(pose.x), y=_num(pose.y), hdg=_num(pose.hdg), length=_num(e.length))
        _sub(g, e.kind, **{k: (v if isinstance(v, str) else _num(v)) for k, v in e.params})
        s += e.length
    lanes = _sub(el, "lanes")
    _sub(lanes, "laneOffset", s="0.0", a="0.0", b="0.0", c="0.0", d="0.0")
    sec = _sub(lanes, "laneSection", s="0.0")
    left = sorted((ln for ln in road.lanes if ln.id > 0), key=lambda ln: ln.id)
    right = sorted((ln for ln in road.lanes if ln.id < 0), key=lambda ln: -ln.id)
    if left:
        side = _sub(sec, "left")
        for ln in reversed(left):
            _write_lane(side, ln, version)
    centre = _sub(sec, "center")
    _write_lane(centre, LaneSpec(0, "none", 0.0), version)
    if right:
        side = _sub(sec, "right")
        for ln in right:
            _write_lane(side, ln, version)


def _write_junction(root, j: JunctionSpec) -> None:
    el = _sub(root, "junction", id=j.id, name=f"junction {j.id}")
    for c in j.connections:
        ce = _sub(
            el,
            "connection",
            id=c.id,
            incomingRoad=c.incoming,
            connectingRoad=c.connecting,
            contactPoint=c.contact_point,
        )
        for a, b in c.lane_links:
            _sub(ce, "laneLink", **{"from": str(a), "to": str(b)})


def to_tree(doc: DocumentSpec) -> etree._Element:
    root = etree.Element("OpenDRIVE")
    xs = [p.x for r in doc.roads for p in r.poses()]
    ys = [p.y for r in doc.roads for p in r.poses()]
    _sub(
        root,
        "header",
        revMajor=str(doc.version[0]),
        revMinor=str(doc.version[1]),
        name=doc.name,
        version="1.00",
        date="2024-01-01T00:00:00",
        north=_num(max(ys, default=0.0)),
        south=_num(min(ys, default=0.0)),
        east=_num(max(xs, default=0.0)),
        west=_num(min(xs, default=0.0)),
        vendor="fuzz",
    )
    for road in doc.roads:
        _write_road(root, road, doc.version)
    for j in doc.junctions:
        _write_junction(root, j)
    return root


def to_bytes(doc: DocumentSpec) -> bytes:
    """The document as UTF-8 OpenDRIVE XML with a declaration."""
    return etree.tostring(to_tree(doc), xml_declaration=True, encoding="UTF-8", pretty_print=True)
