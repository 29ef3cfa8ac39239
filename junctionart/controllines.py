"""Control lines, control-line pairs and groups: read from JSON / GeoJSON or drawn automatically inside W x H.

A control line is a polyline (a sequence of segments joined at their endpoints). Connecting roads are only created
between the two lines of a pair; lines carry a group (distinct sub-networks, joined later so the map is connected)
and optionally a fixed lane configuration (lanes travelling along the line and against it).

JSON::

    {"lines": [{"id": "a", "points": [[0, 0], [400, 0]], "group": 0, "lanes": {"forward": 2, "backward": 1}}, ...],
     "pairs": [["a", "b"], ...],
     "roundabouts": [{"at": [200, 100], "radius": 18, "lanes": 1}]}

GeoJSON: a FeatureCollection of LineString features; ``properties`` may hold ``id``, ``group``, ``lanes`` and
``pair_with`` (a list of line ids). Without explicit pairs, consecutive lines of one group form the pairs.

A line (or a feature's ``properties``) may also ask for forks and ramps at given places (issue 28): ``"forks"`` and
``"ramps"``, lists of ``{"at": metres along the line from its first point, or a point [x, y] (its nearest point on
the line), "angle": degrees}`` (``angle`` optional: the branch's turn away from the road). The road running along the
line there gets the structure, centred as near the point as its straight stretch allows
(:mod:`junctionart.splits.network`); one that does not fit is reported::

    {"id": "a", "points": [[0, 0], [800, 0]], "forks": [{"at": 300, "angle": 15}], "ramps": [{"at": 600}]}

Roundabouts: each entry of ``"roundabouts"`` (in GeoJSON a ``Point`` feature whose properties say
``"roundabout": true``) asks for a roundabout at the junction whose control point is nearest to ``at`` (within 60 m;
a junction is where lines cross or the network joins them), with ``radius`` (m, the outer radius of the circulating
carriageway) and ``lanes`` (1 or 2 circulating lanes), each optional (drawn when missing). A junction with 3 to 6
legs becomes one whatever ``roundabout_probability`` is; a request no junction is near is left unused.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import shapely

from .errors import InputError
from .params import MAX_SIDE, ROUNDABOUT_LANES, ROUNDABOUT_RADIUS, Params

MAX_FILE_BYTES = 20_000_000
#: Largest total length (m) of the control lines of one file: about that of the automatic lines of the largest
#: automatic map (10 km x 10 km: 554 km; 100 km x 1 km: 580 km), which take 1-4 minutes here (see
#: :data:`junctionart.params.MAX_AREA`). Two parallel 300 km lines took 49 s; 1e12 m never finishes.
MAX_TOTAL_LENGTH = 600_000.0
#: Largest extent (m) of all control lines together, in x and in y: the largest side of an automatic map.
MAX_EXTENT = MAX_SIDE
#: Largest absolute coordinate (m): room for projected coordinates (UTM northings reach 1e7 m).
MAX_COORDINATE = 1e7


@dataclass(frozen=True)
class Request:
    """A structure a control-line file asks for: its kind ("fork" or "ramp"), the point on the line (x, y), the
    angle (degrees; None: drawn) and where it was asked (for messages)."""

    kind: str
    x: float
    y: float
    angle: float | None = None
    source: str = ""


@dataclass(frozen=True)
class ControlLine:
    """A control line: a polyline the road network follows, its group, its lane counts and the structures asked for
    along it ((kind, metres along the line, angle or None))."""

    id: str
    points: tuple[tuple[float, float], ...]
    group: int = 0
    lanes: tuple[int, int] | None = None  # (forward, backward) lane counts, None: drawn
    structures: tuple[tuple[str, float, float | None], ...] = ()

    @property
    def length(self) -> float:
        p = np.asarray(self.points)
        return float(np.hypot(*np.diff(p, axis=0).T).sum())

    def cumulative(self) -> np.ndarray:
        p = np.asarray(self.points)
        return np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(p, axis=0).T))])

    def point_at(self, a: float) -> tuple[float, float]:
        """The point at arc length ``a`` (clamped to the line)."""
        cum = self.cumulative()
        a = min(max(a, 0.0), cum[-1])
        i = int(min(np.searchsorted(cum, a, side="right") - 1, len(self.points) - 2))
        seg = cum[i + 1] - cum[i]
        t = 0.0 if seg <= 0 else (a - cum[i]) / seg
        (x0, y0), (x1, y1) = self.points[i], self.points[i + 1]
        return (x0 + t * (x1 - x0), y0 + t * (y1 - y0))

    def project(self, xy: tuple[float, float]) -> float:
        """Arc length of the point of the line nearest ``xy``."""
        cum = self.cumulative()
        best, best_d = 0.0, math.inf
        for i in range(len(self.points) - 1):
            (x0, y0), (x1, y1) = self.points[i], self.points[i + 1]
            dx, dy = x1 - x0, y1 - y0
            seg2 = dx * dx + dy * dy
            t = 0.0 if seg2 == 0 else max(0.0, min(1.0, ((xy[0] - x0) * dx + (xy[1] - y0) * dy) / seg2))
            d = math.hypot(x0 + t * dx - xy[0], y0 + t * dy - xy[1])
            if d < best_d:
                best, best_d = cum[i] + t * (cum[i + 1] - cum[i]), d
        return float(best)


@dataclass(frozen=True)
class RoundaboutRequest:
    """A roundabout asked for near point ``at``: outer radius (m) and circulating lanes, None where drawn."""

    at: tuple[float, float]
    radius: float | None = None
    lanes: int | None = None


@dataclass(frozen=True)
class ControlLines:
    """The control lines of a map, the pairs of them that the network joins, and the roundabouts asked for."""

    lines: tuple[ControlLine, ...]
    pairs: tuple[tuple[int, int], ...]  # indexes into lines
    roundabouts: tuple[RoundaboutRequest, ...] = ()

    @property
    def groups(self) -> tuple[int, ...]:
        return tuple(sorted({ln.group for ln in self.lines}))

    @property
    def requests(self) -> tuple[Request, ...]:
        """The forks and ramps the lines ask for, at their points on the lines."""
        out = []
        for ln in self.lines:
            for kind, at, angle in ln.structures:
                x, y = ln.point_at(at)
                out.append(Request(kind, x, y, angle, f"line {ln.id!r} at {at:g} m"))
        return tuple(out)


# ---------------------------------------------------------------------------------------------------------------------
# Automatic lines
# ---------------------------------------------------------------------------------------------------------------------
def automatic(params: Params, rng: np.random.Generator) -> ControlLines:
    """Lines across x = 0..W stacked upwards inside y = 0..H (both dimensions honoured), paired consecutively."""
    W, H = params.width, params.height
    lo, hi = params.line_spacing
    margin = min(20.0, 0.05 * H)
    y0 = y1 = margin
    lines: list[ControlLine] = []
    wanted = params.n_lines if params.n_lines is not None else 10**9
    while len(lines) < wanted:
        xs, xe = 0.0, W
        if rng.random() < 0.2:  # shortened by 20 % at one end
            if rng.random() < 0.5:
                xs = 0.2 * W
            else:
                xe = 0.8 * W
        k = len(lines)
        lanes = params.control_line_lanes[k] if k < len(params.control_line_lanes) else None
        lines.append(ControlLine(f"auto{k}", ((xs, y0), (xe, y1)), lanes=lanes))
        step = rng.uniform(lo, hi)
        if rng.random() < 0.25:
            step += 200.0
        y0n = y0 + step
        y1n = y1 + max(lo, step * rng.uniform(0.7, 1.3))
        top = H - margin
        if max(y0n, y1n) > top:
            if min(top - y0, top - y1) < lo or len(lines) >= wanted:
                break
            y0n, y1n = min(y0n, top), min(y1n, top)  # the last line runs along the top edge
            wanted = min(wanted, len(lines) + 1)
        y0, y1 = y0n, y1n
    if len(lines) < 2:
        # Height allows a single spacing draw only: put the second line at the top edge.
        lanes = params.control_line_lanes[1] if len(params.control_line_lanes) > 1 else None
        lines.append(ControlLine("auto1", ((0.0, H - margin), (W, H - margin)), lanes=lanes))
    pairs = tuple((i, i + 1) for i in range(len(lines) - 1))
    return ControlLines(tuple(lines), pairs)


# ---------------------------------------------------------------------------------------------------------------------
# Files
# ---------------------------------------------------------------------------------------------------------------------
def _points(where: str, raw: Any) -> tuple[tuple[float, float], ...]:
    if not isinstance(raw, list) or len(raw) < 2:
        raise InputError(f"{where}: needs a list of at least 2 points [x, y]")
    pts = []
    for k, p in enumerate(raw):
        if (
            not isinstance(p, (list, tuple))
            or len(p) < 2
            or not all(isinstance(c, (int, float)) and not isinstance(c, bool) and math.isfinite(c) for c in p[:2])
        ):
            raise InputError(f"{where}: point {k} is {p!r}, expected [x, y] with finite numbers")
        pts.append((float(p[0]), float(p[1])))
    for k in range(len(pts) - 1):
        if math.hypot(pts[k + 1][0] - pts[k][0], pts[k + 1][1] - pts[k][1]) < 1.0:
            raise InputError(f"{where}: points {k} and {k + 1} are less than 1 m apart")
    return tuple(pts)


def _lanes(where: str, raw: Any) -> tuple[int, int] | None:
    if raw is None:
        return None
    if isinstance(raw, dict):
        fwd = raw.get("forward", raw.get("right"))
        bwd = raw.get("backward", raw.get("left"))
    elif isinstance(raw, list) and len(raw) == 2:
        fwd, bwd = raw
    else:
        raise InputError(f'{where}: lanes must be {{"forward": n, "backward": m}} or [n, m]')
    for v in (fwd, bwd):
        if isinstance(v, bool) or not isinstance(v, int) or not 0 <= v <= 3:
            raise InputError(f"{where}: lane counts must be integers in [0, 3], got {fwd!r}, {bwd!r}")
    if fwd == 0 and bwd == 0:
        raise InputError(f"{where}: lanes cannot be 0 in both directions")
    assert isinstance(fwd, int) and isinstance(bwd, int)  # checked above
    return (fwd, bwd)


def _structures(
    where: str, raw: dict, points: tuple[tuple[float, float], ...]
) -> tuple[tuple[str, float, float | None], ...]:
    """The ``forks`` and ``ramps`` of a line through ``points`` (module docstring), each at metres along it."""
    out: list[tuple[str, float, float | None]] = []
    for key, kind in (("forks", "fork"), ("ramps", "ramp")):
        items = raw.get(key)
        if items is None:
            continue
        if not isinstance(items, list):
            raise InputError(f'{where}: "{key}" must be a list of {{"at": metres, "angle": degrees}}')
        for k, item in enumerate(items):
            if not isinstance(item, dict) or "at" not in item or set(item) - {"at", "angle"}:
                raise InputError(f'{where}: {key}[{k}] must be {{"at": metres along the line, "angle": degrees}}')
            at, angle = item["at"], item.get("angle")
            if isinstance(at, list) and len(at) == 2 and all(_finite(c) for c in at):
                at = ControlLine("", points).project((float(at[0]), float(at[1])))
            if not _finite(at) or at < 0:
                raise InputError(
                    f"{where}: {key}[{k}] at={at!r}: must be a distance along the line (m, >= 0) or a point [x, y]"
                )
            ok = angle is None or (
                isinstance(angle, (int, float)) and not isinstance(angle, bool) and math.isfinite(angle)
            )
            if not ok or (angle is not None and not 2.0 <= angle <= 90.0):
                raise InputError(f"{where}: {key}[{k}] angle={angle!r}: must be degrees in [2, 90]")
            out.append((kind, float(at), None if angle is None else float(angle)))
    return tuple(out)


def _finite(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _group(where: str, raw: Any) -> int:
    if raw is None:
        return 0
    if isinstance(raw, bool) or not isinstance(raw, int):
        raise InputError(f"{where}: group must be an integer, got {raw!r}")
    return raw


def _roundabout(where: str, raw: Any, at: Any = None) -> RoundaboutRequest:
    """One roundabout request: ``{"at": [x, y], "radius": r, "lanes": n}`` (``at`` given apart for a GeoJSON point)."""
    if not isinstance(raw, dict):
        raise InputError(f'{where}: a roundabout is an object {{"at": [x, y], "radius": m, "lanes": n}}')
    known = {"at", "radius", "lanes"} if at is None else {"roundabout", "radius", "lanes", "id", "name"}
    unknown = sorted(set(raw) - known)
    if unknown:
        raise InputError(f"{where}: unknown key {unknown[0]!r}; valid: {', '.join(sorted(known))}")
    point = raw.get("at") if at is None else at
    if (
        not isinstance(point, (list, tuple))
        or len(point) < 2
        or not all(isinstance(c, (int, float)) and not isinstance(c, bool) and math.isfinite(c) for c in point[:2])
    ):
        raise InputError(f"{where}: needs a point [x, y] with finite numbers, got {point!r}")
    radius, lanes = raw.get("radius"), raw.get("lanes")
    lo, hi = ROUNDABOUT_RADIUS
    if radius is not None and (
        isinstance(radius, bool) or not isinstance(radius, (int, float)) or not lo <= radius <= hi
    ):
        raise InputError(f"{where}: radius must be a number of metres in [{lo:g}, {hi:g}], got {radius!r}")
    if lanes is not None and (
        isinstance(lanes, bool) or lanes not in range(ROUNDABOUT_LANES[0], ROUNDABOUT_LANES[1] + 1)
    ):
        raise InputError(f"{where}: lanes must be {ROUNDABOUT_LANES[0]} or {ROUNDABOUT_LANES[1]}, got {lanes!r}")
    return RoundaboutRequest((float(point[0]), float(point[1])), None if radius is None else float(radius), lanes)


def _check_extent(source: str, lines: tuple[ControlLine, ...]) -> None:
    """Refuse lines a map cannot be generated from in reasonable time (the bounds above), naming the bound."""
    pts = np.array([p for ln in lines for p in ln.points])
    if np.abs(pts).max() > MAX_COORDINATE:
        raise InputError(
            f"{source}: a coordinate is {np.abs(pts).max():.3g} m from the origin; at most {MAX_COORDINATE:.0e} m"
        )
    extent = pts.max(axis=0) - pts.min(axis=0)
    if extent.max() > MAX_EXTENT:
        raise InputError(
            f"{source}: the control lines span {extent[0]:.6g} m x {extent[1]:.6g} m; at most {MAX_EXTENT:.6g} m each "
            "way (the largest automatic map's side)"
        )
    total = sum(ln.length for ln in lines)
    if total > MAX_TOTAL_LENGTH:
        raise InputError(
            f"{source}: the control lines are {total / 1000:.6g} km long in total; at most {MAX_TOTAL_LENGTH / 1000:g} "
            "km (what a 10 km x 10 km automatic map has, generated in 1-2 minutes): split the network into smaller maps"
        )


def _assemble(
    source: str, entries: list[tuple], pairs_raw: list[Any], roundabouts: tuple[RoundaboutRequest, ...] = ()
) -> ControlLines:
    if len(entries) < 2:
        raise InputError(f"{source}: needs at least 2 control lines, found {len(entries)}")
    ids = [e[0] for e in entries]
    if len(set(ids)) != len(ids):
        dup = next(i for i in ids if ids.count(i) > 1)
        raise InputError(f"{source}: line id {dup!r} is used twice")
    lines = tuple(ControlLine(*entry) for entry in entries)
    _check_extent(source, lines)
    for ln in lines:
        for kind, at, _ in ln.structures:
            if at > ln.length:
                raise InputError(
                    f"{source}: line {ln.id!r} asks for a {kind} at {at:g} m; it is {ln.length:.6g} m long"
                )
    index = {ln.id: k for k, ln in enumerate(lines)}
    pairs: list[tuple[int, int]] = []
    for p in pairs_raw:
        if not isinstance(p, (list, tuple)) or len(p) != 2 or any(str(x) not in index for x in p):
            raise InputError(f"{source}: pair {p!r} must name two line ids among {', '.join(ids)}")
        a, b = index[str(p[0])], index[str(p[1])]
        if a == b:
            raise InputError(f"{source}: pair {p!r} pairs a line with itself")
        if (a, b) not in pairs and (b, a) not in pairs:
            pairs.append((a, b))
    if not pairs:
        by_group: dict[int, list[int]] = {}
        for k, ln in enumerate(lines):
            by_group.setdefault(ln.group, []).append(k)
        for members in by_group.values():
            pairs.extend(itertools.pairwise(members))
    for a, b in pairs:
        shared = shapely.LineString(lines[a].points).intersection(shapely.LineString(lines[b].points)).length
        if shared > 1.0:
            raise InputError(
                f"{source}: lines {lines[a].id!r} and {lines[b].id!r} of a pair overlap along "
                f"{shared:.1f} m; the two lines of a pair must be apart"
            )
    return ControlLines(lines, tuple(pairs), roundabouts)


def parse(data: Any, source: str = "<input>") -> ControlLines:
    """Control lines from already-decoded JSON or GeoJSON."""
    if not isinstance(data, dict):
        raise InputError(f'{source}: expected a JSON object with "lines" or a GeoJSON FeatureCollection')
    entries: list[tuple] = []
    pairs_raw: list[Any] = []
    roundabouts: list[RoundaboutRequest] = []
    if data.get("type") == "FeatureCollection":
        feats = data.get("features")
        if not isinstance(feats, list):
            raise InputError(f"{source}: FeatureCollection without a features list")
        for k, f in enumerate(feats):
            where = f"{source}: feature {k}"
            geom = f.get("geometry") if isinstance(f, dict) else None
            props = (f.get("properties") if isinstance(f, dict) else None) or {}
            if not isinstance(props, dict):
                raise InputError(f"{where}: properties must be an object")
            if isinstance(geom, dict) and geom.get("type") == "Point" and props.get("roundabout") is True:
                roundabouts.append(_roundabout(where, props, geom.get("coordinates")))
                continue
            if not isinstance(geom, dict) or geom.get("type") != "LineString":
                raise InputError(
                    f"{where}: only LineString geometries are control lines (and Points with "
                    '"roundabout": true roundabouts)'
                )
            lid = str(props.get("id", f.get("id", k)))
            pts = _points(where, geom.get("coordinates"))
            entries.append(
                (
                    lid,
                    pts,
                    _group(where, props.get("group")),
                    _lanes(where, props.get("lanes")),
                    _structures(where, props, pts),
                )
            )
            for other in props.get("pair_with") or []:
                pairs_raw.append([lid, str(other)])
    elif "lines" in data:
        raw_lines = data["lines"]
        if not isinstance(raw_lines, list):
            raise InputError(f'{source}: "lines" must be a list')
        for k, ln in enumerate(raw_lines):
            where = f"{source}: line {k}"
            if not isinstance(ln, dict):
                raise InputError(f'{where}: must be an object with "points"')
            pts = _points(where, ln.get("points"))
            entries.append(
                (
                    str(ln.get("id", k)),
                    pts,
                    _group(where, ln.get("group")),
                    _lanes(where, ln.get("lanes")),
                    _structures(where, ln, pts),
                )
            )
        pairs_raw = data.get("pairs") or []
        if not isinstance(pairs_raw, list):
            raise InputError(f'{source}: "pairs" must be a list of [id, id]')
        raw_roundabouts = data.get("roundabouts") or []
        if not isinstance(raw_roundabouts, list):
            raise InputError(f'{source}: "roundabouts" must be a list of {{"at": [x, y], ...}}')
        roundabouts = [_roundabout(f"{source}: roundabout {k}", r) for k, r in enumerate(raw_roundabouts)]
    else:
        raise InputError(f'{source}: expected a JSON object with "lines" or a GeoJSON FeatureCollection')
    return _assemble(source, entries, pairs_raw, tuple(roundabouts))


def load(path: str | Path) -> ControlLines:
    """Read a JSON / GeoJSON control-line file; every problem is an :class:`InputError` naming the file."""
    import json  # here: a generated map without a control-line file reads no JSON

    p = Path(path)
    try:
        if p.stat().st_size > MAX_FILE_BYTES:
            raise InputError(f"{p}: larger than {MAX_FILE_BYTES} bytes")
        text = p.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"{p}: cannot read ({exc.__class__.__name__}: {exc})") from None
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise InputError(f"{p}: not valid JSON (line {exc.lineno}: {exc.msg})") from None
    return parse(data, str(p))
