"""Independent recomputation of the numbers the corpus's error findings state (``scripts/corpus_review.py``).

Each function takes the document, the parsed XML and one finding (the JSON dict of ``xodrcheck check --format
json``) and returns the recomputed number with a one-line explanation, and the scene to draw. They never call a rule:
plan-view positions come from :class:`xodrcheck.geometry.lanes.RoadGeometry` (points only; curvatures and overlaps are
recomputed here from those points by finite differences and shapely polygons) and the link records from the XML."""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Callable
from typing import Any

import numpy as np
from corpus_review_draw import Scene, lane_outlines

from xodrcheck.geometry.lanes import RoadGeometry
from xodrcheck.model import DRIVABLE_LANE_TYPES, Document

Finding = dict[str, Any]
Result = tuple[float | None, str, Scene | None]


def _number(pattern: str, message: str) -> float:
    match = re.search(pattern, message)
    return float(match.group(1)) if match else math.nan


def _circumradius(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Radius of the circle through each three consecutive points (inf on a straight)."""
    ax, ay, bx, by, cx, cy = x[:-2], y[:-2], x[1:-1], y[1:-1], x[2:], y[2:]
    a = np.hypot(bx - cx, by - cy)
    b = np.hypot(ax - cx, ay - cy)
    c = np.hypot(ax - bx, ay - by)
    cross = np.abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(cross > 0, a * b * c / (2.0 * cross), np.inf)


def _section_s(geometry: RoadGeometry, s: float, half: float = 1.5, step: float = 0.02) -> tuple[int, np.ndarray]:
    k = int(geometry.section_index(np.array([s]))[0])
    lo, hi = geometry.section_range(k)
    grid = np.arange(max(lo, s - half), min(hi, s + half), step)
    return k, grid


def radius(doc: Document, xml: Any, f: Finding) -> Result:
    """C001 / C002: smallest radius of the lane centre (lane-0 line) near s, from the circle through three points
    0.02 m apart on the evaluated line."""
    geometry = RoadGeometry(doc.road_by_id[f["road"]])
    k, grid = _section_s(geometry, f["s"])
    lane = f["lane"] if f["code"] == "C001" else 0
    points = geometry.lane_points(k, lane, grid, "centre")
    r = _circumradius(points.x, points.y)
    i = int(np.argmin(r))
    what = f"lane {lane} centre" if lane else "lane-0 line"
    note = f"{what}: r_min {r[i]:.2f} m at s={grid[i + 1]:.2f} (3-point circles)"
    scene = Scene(
        f"{f['file']} {f['code']}: road {f['road']} {what}",
        (float(points.x[i + 1]), float(points.y[i + 1])),
        12.0,
        roads=(f["road"],),
        point=(float(points.x[i + 1]), float(points.y[i + 1])),
        note=note,
    )
    scene.lines.append((points.x, points.y, "black", what))
    return float(r[i]), note, scene


def fold(doc: Document, xml: Any, f: Finding) -> Result:
    """C003: the outer border runs backwards (against the reference line's direction) near s: length of the
    stretch where the border's step points against the reference tangent."""
    geometry = RoadGeometry(doc.road_by_id[f["road"]])
    k, grid = _section_s(geometry, f["s"], half=3.0, step=0.005)
    outer = geometry.lane_points(k, f["lane"], grid, "outer")
    ref = geometry.reference(grid)
    dx, dy = np.diff(outer.x), np.diff(outer.y)
    along = dx * np.cos(ref.hdg[:-1]) + dy * np.sin(ref.hdg[:-1])
    backwards = float(np.sum(np.hypot(dx, dy)[along < 0]))
    rref = float(np.min(_circumradius(ref.x, ref.y)))
    note = f"outer border of lane {f['lane']}: {backwards:.2f} m run backwards; reference r_min {rref:.2f} m"
    scene = Scene(
        f"{f['file']} C003: road {f['road']} lane {f['lane']} folds",
        (f["x"], f["y"]),
        10.0,
        roads=(f["road"],),
        point=(f["x"], f["y"]),
        note=note,
    )
    scene.lines.append((outer.x, outer.y, "black", f"outer border lane {f['lane']}"))
    return backwards, note, scene


def _polygons(doc: Document, road_id: str, centre: tuple[float, float], reach: float) -> list[tuple[bool, Any]]:
    """(drivable, polygon) of each lane of a road's sections near ``centre``."""
    import shapely

    out = []
    for _lane, kind, x, y in lane_outlines(RoadGeometry(doc.road_by_id[road_id]), 0.05, centre, reach):
        out.append((kind in DRIVABLE_LANE_TYPES, shapely.make_valid(shapely.Polygon(np.column_stack([x, y])))))
    return out


def overlap(doc: Document, xml: Any, f: Finding) -> Result:
    """O001 / O003: plan-view area shared by the two roads' lanes, summed over the lane pairs with a drivable lane
    (roadside pairs are O004's), from shapely polygons of the evaluated lane borders."""
    other = re.search(r"and road (\S+) overlap", f["message"])
    assert other is not None
    centre = (f["x"], f["y"])
    mine, theirs = _polygons(doc, f["road"], centre, 80.0), _polygons(doc, other.group(1), centre, 80.0)
    area = sum(float(p.intersection(q).area) for dp, p in mine for dq, q in theirs if dp or dq)
    note = f"roads {f['road']} and {other.group(1)} share {area:.1f} m2 with a drivable lane (shapely)"
    scene = Scene(
        f"{f['file']} {f['code']}: road {f['road']} / {other.group(1)}",
        centre,
        20.0,
        roads=(f["road"], other.group(1)),
        point=centre,
        note=note,
    )
    return area, note, scene


def self_overlap(doc: Document, xml: Any, f: Finding) -> Result:
    """O002: area a lane covers twice: the areas of its triangles (two per 1 cm strip) minus the area of their
    union."""
    import shapely

    geometry = RoadGeometry(doc.road_by_id[f["road"]])
    k = int(geometry.section_index(np.array([f["s"]]))[0])
    lo, hi = geometry.section_range(k)
    s = np.linspace(lo, np.nextafter(hi, lo), int((hi - lo) / 0.01) + 2)
    inner = geometry.lane_points(k, f["lane"], s, "inner")
    outer = geometry.lane_points(k, f["lane"], s, "outer")
    a = np.column_stack([inner.x[:-1], inner.y[:-1]])
    b = np.column_stack([inner.x[1:], inner.y[1:]])
    c = np.column_stack([outer.x[1:], outer.y[1:]])
    d = np.column_stack([outer.x[:-1], outer.y[:-1]])
    triangles = shapely.polygons(np.concatenate([np.stack([a, b, c], axis=1), np.stack([a, c, d], axis=1)]))
    twice = float(shapely.area(triangles).sum() - shapely.union_all(triangles).area)
    note = f"lane {f['lane']} covers {twice:.2f} m2 twice (triangles minus their union)"
    scene = Scene(
        f"{f['file']} O002: road {f['road']} lane {f['lane']}",
        (f["x"], f["y"]),
        6.0,
        roads=(f["road"],),
        point=(f["x"], f["y"]),
        note=note,
    )
    scene.lines.append((outer.x, outer.y, "black", f"outer border lane {f['lane']}"))
    return twice, note, scene


def _road_end(doc: Document, road_id: str, end: str) -> tuple[float, float]:
    road = doc.road_by_id[road_id]
    pose = RoadGeometry(road).reference(np.array([0.0 if end == "start" else road.length]))
    return float(pose.x[0]), float(pose.y[0])


def ref_gap(doc: Document, xml: Any, f: Finding) -> Result:
    """K101: distance between the two reference lines' linked ends."""
    m = re.search(r"between the (start|end) of road (\S+) and the (start|end) of road (\S+?):", f["message"])
    assert m is not None
    p, q = _road_end(doc, m.group(2), m.group(1)), _road_end(doc, m.group(4), m.group(3))
    gap = math.dist(p, q)
    note = f"reference ends {gap:.3f} m apart"
    centre = ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2)
    scene = Scene(
        f"{f['file']} K101: road {m.group(2)} {m.group(1)} / road {m.group(4)} {m.group(3)}",
        centre,
        max(8.0, 2.0 * gap),
        roads=(m.group(2), m.group(4)),
        point=q,
        note=note,
    )
    scene.lines.append((np.array([p[0], q[0]]), np.array([p[1], q[1]]), "black", "gap"))
    return gap, note, scene


def _lane_end_border(doc: Document, road_id: str, end: str, lane: int) -> tuple[np.ndarray, np.ndarray]:
    """Plan-view points of a lane's inner and outer border at a road end."""
    road = doc.road_by_id[road_id]
    geometry = RoadGeometry(road)
    k = 0 if end == "start" else len(road.lane_sections) - 1
    s = np.array([0.0 if end == "start" else np.nextafter(road.length, 0.0)])
    inner = geometry.lane_points(k, lane, s, "inner")
    outer = geometry.lane_points(k, lane, s, "outer")
    return np.array([inner.x[0], inner.y[0]]), np.array([outer.x[0], outer.y[0]])


def border_gap(doc: Document, xml: Any, f: Finding) -> Result:
    """K103: the linked lanes' borders at the joint: the larger of the inner-inner and outer-outer distances, each
    lane's borders taken in the order that makes them touch (a lane reversed at an end-end or start-start joint)."""
    m = re.search(
        r"lane (-?\d+) of road (\S+) and lane (-?\d+) of road (\S+) are linked at the (start|end) of road \S+ and "
        r"the (start|end) of road",
        f["message"],
    )
    assert m is not None
    la, ra, lb, rb, ea, eb = int(m.group(1)), m.group(2), int(m.group(3)), m.group(4), m.group(5), m.group(6)
    ai, ao = _lane_end_border(doc, ra, ea, la)
    bi, bo = _lane_end_border(doc, rb, eb, lb)
    straight = max(np.linalg.norm(ai - bi), np.linalg.norm(ao - bo))
    crossed = max(np.linalg.norm(ai - bo), np.linalg.norm(ao - bi))
    gap = float(min(straight, crossed))
    note = f"border ends {gap:.3f} m apart (lane {la} of {ra} / lane {lb} of {rb})"
    mid = (ai + ao + bi + bo) / 4
    centre = (float(mid[0]), float(mid[1]))
    scene = Scene(
        f"{f['file']} K103: road {ra} lane {la} / road {rb} lane {lb}",
        centre,
        max(10.0, 1.2 * gap),
        roads=(ra, rb),
        point=(f["x"], f["y"]),
        note=note,
    )
    scene.lines.append((np.array([ai[0], ao[0]]), np.array([ai[1], ao[1]]), "black", f"lane {la} of {ra} at its {ea}"))
    scene.lines.append(
        (np.array([bi[0], bo[0]]), np.array([bi[1], bo[1]]), "#ff00ff", f"lane {lb} of {rb} at its {eb}")
    )
    return gap, note, scene


def section_jump(doc: Document, xml: Any, f: Finding) -> Result:
    """L101: a lane's border t just before and at the section boundary (the linked lane's in the next section)."""
    m = re.search(r"lane (-?\d+) of the lane section at s=(\S+) continues as lane (-?\d+) at s=(\S+?),", f["message"])
    assert m is not None
    road = doc.road_by_id[f["road"]]
    geometry = RoadGeometry(road)
    before_lane, after_lane, boundary = int(m.group(1)), int(m.group(3)), float(m.group(4))
    k = int(np.argmin([abs(sec.s - boundary) for sec in road.lane_sections]))  # the message rounds s
    boundary = road.lane_sections[k].s
    b = np.array([np.nextafter(boundary, 0.0)])
    a = np.array([boundary])
    bi, bo = geometry.inner_outer(k - 1, before_lane, b)
    ai, ao = geometry.inner_outer(k, after_lane, a)
    jump = float(max(abs(bi[0] - ai[0]), abs(bo[0] - ao[0])))
    note = f"t inner {bi[0]:.3f}->{ai[0]:.3f}, outer {bo[0]:.3f}->{ao[0]:.3f}: jump {jump:.3f} m"
    scene = Scene(
        f"{f['file']} L101: road {f['road']} s={boundary:.3g}",
        (f["x"], f["y"]),
        8.0,
        roads=(f["road"],),
        point=(f["x"], f["y"]),
        note=note,
    )
    return jump, note, scene


def elevation_step(doc: Document, xml: Any, f: Finding) -> Result:
    """G014: the previous <elevation> cubic evaluated at the next record's s, against that record's a."""
    road = xml.find(f".//road[@id='{f['road']}']")
    records = [tuple(float(e.get(k)) for k in ("s", "a", "b", "c", "d")) for e in road.find("elevationProfile")]
    worst = 0.0
    for (s0, a, b, c, d), nxt in itertools.pairwise(records):
        ds = nxt[0] - s0
        worst = max(worst, abs(a + b * ds + c * ds**2 + d * ds**3 - nxt[1]))
    note = f"largest elevation step between records: {worst:.5f} m"
    return worst, note, None


def crossing(doc: Document, xml: Any, f: Finding) -> Result:
    """J101: where the two connection lanes' centre lines (evaluated points, shapely) cross, and how far along the
    first path that is."""
    import shapely

    m = re.findall(r"-> road (\S+) lane (-?\d+)", f["message"])
    junction = re.search(r"junction (\S+):", f["message"])
    assert junction is not None
    lines = []
    for road_id, lane in m:
        road = doc.road_by_id[road_id]
        geometry = RoadGeometry(road)
        connection = xml.find(f".//junction[@id='{junction.group(1)}']/connection[@connectingRoad='{road_id}']")
        forward = connection.get("contactPoint") == "start"
        xs, ys = [], []
        lane_id: int | None = int(lane)
        order = range(len(road.lane_sections)) if forward else range(len(road.lane_sections) - 1, -1, -1)
        for k in order:
            this = road.lane_sections[k].lane(lane_id) if lane_id is not None else None
            if this is None:
                break
            lo, hi = geometry.section_range(k)
            s = np.linspace(lo, np.nextafter(hi, lo), int((hi - lo) / 0.05) + 2)
            p = geometry.lane_points(k, this.id, s if forward else s[::-1], "centre")
            xs.append(p.x)
            ys.append(p.y)
            links = this.successors if forward else this.predecessors
            lane_id = links[0] if links else None
        lines.append((np.concatenate(xs), np.concatenate(ys), road_id, lane))
    a = shapely.LineString(np.column_stack(lines[0][:2]))
    b = shapely.LineString(np.column_stack(lines[1][:2]))
    meet = a.intersection(b)
    points = [shapely.Point(xy) for xy in shapely.get_coordinates(meet)]
    starts = shapely.Point(lines[0][0][0], lines[0][1][0])
    far = max((float(a.project(p)) for p in points if p.distance(starts) > 0.05), default=0.0)
    note = f"centre lines cross {far:.2f} m along road {lines[0][2]} ({len(points)} meeting point(s))"
    scene = Scene(
        f"{f['file']} J101: {m[0][0]}/{m[1][0]} from road {f['road']}",
        (f["x"], f["y"]),
        18.0,
        roads=(f["road"],),
        point=(f["x"], f["y"]),
        note=note,
    )
    for (x, y, rid, lane), colour in zip(lines, ("black", "#ff00ff")):
        scene.lines.append((x, y, colour, f"road {rid} lane {lane} centre"))
    return far, note, scene


VERIFY: dict[str, Callable[[Document, Any, Finding], Result]] = {
    "C001": radius,
    "C002": radius,
    "C003": fold,
    "G014": elevation_step,
    "J101": crossing,
    "K101": ref_gap,
    "K103": border_gap,
    "L101": section_jump,
    "O001": overlap,
    "O002": self_overlap,
    "O003": overlap,
}

#: The number each code's message states, to pick the worst and a typical finding: (pattern, larger is worse).
STATED = {
    "C001": (r"radius of ([\d.e+-]+) m", False),
    "C002": (r"radius of ([\d.e+-]+) m", False),
    "C003": (r"radius ([\d.e+-]+) m at", False),
    "G014": (r"jumps by ([\d.e+-]+) m", True),
    "K101": (r"gap of ([\d.e+-]+) m", True),
    "K103": (r"are ([\d.e+-]+) m apart", True),
    "L101": (r"jump by ([\d.e+-]+) m", True),
    "O001": (r"by ([\d.e+-]+) m2", True),
    "O002": (r"covers ([\d.e+-]+) m2", True),
    "O003": (r"by ([\d.e+-]+) m2", True),
}


def stated(f: Finding) -> float:
    pattern, _ = STATED.get(f["code"], (r"$^", True))
    return _number(pattern, f["message"])


def _junction_links(xml: Any, junction: str, road: str) -> tuple[int, int]:
    """(connections of ``junction`` from ``road``, its connecting roads whose links name ``road``)."""
    element = xml.find(f".//junction[@id='{junction}']")
    connections = [c for c in element.iter("connection") if c.get("incomingRoad") == road]
    linking = 0
    for c in element.iter("connection"):
        connecting = xml.find(f".//road[@id='{c.get('connectingRoad')}']/link")
        if connecting is not None and any(
            e.get("elementType") == "road" and e.get("elementId") == road for e in connecting
        ):
            linking += 1
    return len(connections), linking


def junction_claim(doc: Document, xml: Any, f: Finding) -> Result:
    """K001 (a road naming a junction): the junction's connections from the road and connecting roads linking it."""
    m = re.search(r"road (\S+): (?:successor|predecessor) is junction (\S+),", f["message"])
    if m is None:
        m2 = re.search(
            r"road (\S+): \w+ is road (\S+) \((start|end)\), but road \S+'s (\w+) is (\S+) (\S+),", f["message"]
        )
        assert m2 is not None
        link = xml.find(f".//road[@id='{m2.group(2)}']/link/{m2.group(4)}")
        note = f"road {m2.group(2)}'s {m2.group(4)}: {link.get('elementType')} {link.get('elementId')}"
        return 0.0, note, None
    n, linking = _junction_links(xml, m.group(2), m.group(1))
    note = f"junction {m.group(2)}: {n} connection(s) from road {m.group(1)}, {linking} connecting road(s) linking it"
    return float(n + linking), note, None


def unlinked_lane(doc: Document, xml: Any, f: Finding) -> Result:
    """J005: laneLinks of the junction from the lane."""
    m = re.search(r"road (\S+) lane (-?\d+) \((\w+)\) runs into junction (\S+)", f["message"])
    assert m is not None
    element = xml.find(f".//junction[@id='{m.group(4)}']")
    links = [
        ll
        for c in element.iter("connection")
        if c.get("incomingRoad") == m.group(1)
        for ll in c.iter("laneLink")
        if ll.get("from") == m.group(2)
    ]
    return float(len(links)), f"{len(links)} laneLink(s) from lane {m.group(2)} of road {m.group(1)}", None


def unneeded_junction(doc: Document, xml: Any, f: Finding) -> Result:
    """J019: the roads each leg can reach through the junction (at most one each: no choice to make)."""
    m = re.search(r"junction (\S+) leads", f["message"])
    assert m is not None
    element = xml.find(f".//junction[@id='{m.group(1)}']")
    reach: dict[str, set[str]] = {}
    for c in element.iter("connection"):
        link = xml.find(f".//road[@id='{c.get('connectingRoad')}']/link")
        ends = {e.get("elementId") for e in link} if link is not None else set()
        reach.setdefault(c.get("incomingRoad"), set()).update(ends - {c.get("incomingRoad")})
    most = max((len(v) for v in reach.values()), default=0)
    legs = ", ".join(f"{k}->{'/'.join(sorted(v))}" for k, v in sorted(reach.items()))
    return float(most), f"{len(element.findall('connection'))} connection(s): {legs}", None


VERIFY.update({"K001": junction_claim, "J005": unlinked_lane, "J019": unneeded_junction})
