"""Serialise a :class:`junctionart.opendrive.Document` to OpenDRIVE 1.8 (default) or 1.7 XML.

Element order follows the schema of the declared version. Floats are written with ``repr`` (the shortest string that
reads back to the same double), so the file round-trips exactly; the output bytes depend only on the document.
Files are written atomically: a temporary file in the target folder, then ``os.replace``.
"""

from __future__ import annotations

import math
import os
import tempfile
from pathlib import Path

from lxml import etree

from .errors import JunctionArtError
from .opendrive import (
    Arc,
    Cubic,
    Document,
    Geometry,
    Junction,
    Lane,
    LaneSection,
    Line,
    Link,
    ParamPoly3,
    Road,
)

REV_MINOR = {"1.8": 8, "1.7": 7}


def fmt(x: float) -> str:
    """Shortest round-trip text of a finite float; -0.0 is written as 0.0."""
    x = float(x)
    if not math.isfinite(x):
        raise JunctionArtError(f"cannot write non-finite number {x!r}")
    if x == 0.0:
        return "0.0"
    return repr(x)


def _sub(parent: etree._Element, tag: str, **attrs: str) -> etree._Element:
    return etree.SubElement(parent, tag, attrs)


def _link(parent: etree._Element, tag: str, link: Link) -> None:
    el = _sub(parent, tag, elementType=link.element_type, elementId=link.element_id)
    if link.contact_point is not None:
        el.set("contactPoint", link.contact_point)


def _geometry(plan: etree._Element, g: Geometry) -> None:
    el = _sub(plan, "geometry", s=fmt(g.s), x=fmt(g.x), y=fmt(g.y), hdg=fmt(g.hdg), length=fmt(g.length))
    if isinstance(g, Line):
        _sub(el, "line")
    elif isinstance(g, Arc):
        _sub(el, "arc", curvature=fmt(g.curvature))
    elif isinstance(g, ParamPoly3):
        _sub(
            el, "paramPoly3",
            aU=fmt(g.au), bU=fmt(g.bu), cU=fmt(g.cu), dU=fmt(g.du),
            aV=fmt(g.av), bV=fmt(g.bv), cV=fmt(g.cv), dV=fmt(g.dv),
            pRange="normalized",
        )
    else:  # pragma: no cover - the model has no other kinds
        raise JunctionArtError(f"unknown geometry {type(g).__name__}")


def _cubic(parent: etree._Element, tag: str, c: Cubic, s_name: str) -> None:
    etree.SubElement(parent, tag, {s_name: fmt(c.s), "a": fmt(c.a), "b": fmt(c.b), "c": fmt(c.c), "d": fmt(c.d)})


def _lane(parent: etree._Element, lane: Lane) -> None:
    el = _sub(parent, "lane", id=str(lane.id), type=lane.type, level="false")
    if lane.predecessor is not None or lane.successor is not None:
        link = _sub(el, "link")
        if lane.predecessor is not None:
            _sub(link, "predecessor", id=str(lane.predecessor))
        if lane.successor is not None:
            _sub(link, "successor", id=str(lane.successor))
    if lane.id != 0:
        for w in lane.widths:
            _cubic(el, "width", w, "sOffset")
    for m in lane.marks:
        mark = _sub(el, "roadMark", sOffset=fmt(m.s), type=m.type, weight="standard", color=m.color, width=fmt(m.width))
        if m.lane_change is not None:
            mark.set("laneChange", m.lane_change)


def _section(parent: etree._Element, sec: LaneSection) -> None:
    el = _sub(parent, "laneSection", s=fmt(sec.s))
    if sec.left:
        left = _sub(el, "left")
        for lane in sorted(sec.left, key=lambda l: -l.id):
            _lane(left, lane)
    center = _sub(el, "center")
    _lane(center, sec.center)
    if sec.right:
        right = _sub(el, "right")
        for lane in sorted(sec.right, key=lambda l: -l.id):
            _lane(right, lane)


def _road(root: etree._Element, road: Road) -> None:
    el = _sub(root, "road", name=road.name or f"road {road.id}", length=fmt(road.length), id=road.id,
              junction=road.junction, rule=road.rule)
    if road.predecessor is not None or road.successor is not None:
        link = _sub(el, "link")
        if road.predecessor is not None:
            _link(link, "predecessor", road.predecessor)
        if road.successor is not None:
            _link(link, "successor", road.successor)
    if road.speed_kmh is not None:
        t = _sub(el, "type", s="0.0", type="town")
        _sub(t, "speed", max=fmt(road.speed_kmh), unit="km/h")
    plan = _sub(el, "planView")
    for g in road.geometry:
        _geometry(plan, g)
    elev = _sub(el, "elevationProfile")
    _sub(elev, "elevation", s="0.0", a="0.0", b="0.0", c="0.0", d="0.0")
    lat = _sub(el, "lateralProfile")
    del lat  # an empty lateral profile is valid and tells readers there is no superelevation
    lanes = _sub(el, "lanes")
    for c in road.lane_offset:
        _cubic(lanes, "laneOffset", c, "s")
    for sec in road.sections:
        _section(lanes, sec)


def _junction(root: etree._Element, j: Junction) -> None:
    el = _sub(root, "junction", name=j.name, id=j.id)
    for c in j.connections:
        ce = _sub(el, "connection", id=c.id, incomingRoad=c.incoming_road, connectingRoad=c.connecting_road,
                  contactPoint=c.contact_point)
        for ll in c.lane_links:
            _sub(ce, "laneLink", **{"from": str(ll.from_lane), "to": str(ll.to_lane)})


def to_tree(doc: Document, version: str = "1.8") -> etree._Element:
    """The XML element tree of ``doc`` for OpenDRIVE ``version`` ("1.8" or "1.7")."""
    if version not in REV_MINOR:
        raise JunctionArtError(f"version {version!r}: must be one of {', '.join(REV_MINOR)}")
    root = etree.Element("OpenDRIVE")
    h = doc.header
    header = _sub(root, "header", revMajor="1", revMinor=str(REV_MINOR[version]), name=h.name, version="1.00")
    if h.date:
        header.set("date", h.date)
    for k in ("north", "south", "east", "west"):
        header.set(k, fmt(getattr(h, k)))
    header.set("vendor", h.vendor)
    for road in doc.roads:
        _road(root, road)
    for j in doc.junctions:
        _junction(root, j)
    return root


def to_bytes(doc: Document, version: str = "1.8") -> bytes:
    """The file content: the XML declaration first, UTF-8, indented, deterministic."""
    tree = to_tree(doc, version)
    return b'<?xml version="1.0" encoding="UTF-8"?>\n' + etree.tostring(tree, encoding="UTF-8", pretty_print=True)


def _umask() -> int:
    """The process's umask (read from /proc where it can be, so that it is never changed, even briefly)."""
    try:
        with open("/proc/self/status", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError):
        pass
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def write(doc: Document, path: str | os.PathLike[str], version: str = "1.8") -> Path:
    """Write ``doc`` to ``path`` atomically; on any error no file (and no temporary file) is left behind."""
    data = to_bytes(doc, version)
    target = Path(path)
    folder = target.parent if str(target.parent) else Path(".")
    if not folder.is_dir():
        raise JunctionArtError(f"{target}: folder {folder} does not exist")
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=folder)
    try:
        os.fchmod(fd, 0o666 & ~_umask())  # mkstemp makes the file 0600; give it the mode of any new file
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, target)
    except BaseException:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        raise
    return target
