"""Plan view (PNG, JPEG, SVG, PDF or WebP, by the output's suffix) of any .xodr file, read with xodrcheck's reader
and lane geometry (not the generator's model).

Lanes are filled by type (driving grey, median green, sidewalk and shoulder lighter, exit and entry lanes violet,
ramps blue, others tan) with a thin light seam between neighbouring lanes; lanes of connecting roads inside junctions
are drawn in a light orange so junctions stand out, and a direct junction (which has no connecting road) as an orange
bar across the roads where they meet; reference lines are thin light lines.
On a map whose heights vary, lanes and reference lines are drawn in pieces of :data:`PIECE` samples (about 50 m),
lowest first, so that an overpass's deck covers the road below it.
"""

from __future__ import annotations

from pathlib import Path
from typing import NamedTuple

import numpy as np

from xodrcheck.support.atomic import OutputError as TargetError
from xodrcheck.support.atomic import atomic_file

from .errors import InputError, OutputError, ParamsError
from .extras import pyplot

COLOURS = {
    "driving": "#5f6368",
    "median": "#7fb77e",
    "sidewalk": "#c9c9c9",
    "walking": "#c9c9c9",
    "shoulder": "#a9a9a9",
    "border": "#b0b0b0",
    "biking": "#b5651d",
    "parking": "#8a8fb5",
    "exit": "#9b7fc4",
    "entry": "#9b7fc4",
    "offRamp": "#5b8fc7",
    "onRamp": "#5b8fc7",
    "connectingRamp": "#5b8fc7",
    "none": "#d8d8d8",
}
JUNCTION_COLOUR = "#f0a04b"
SEAM_COLOUR = "#f7f7f2"  #: the background: a thin seam of it between neighbouring lanes
OTHER_COLOUR = "#c8b48a"
REFERENCE_COLOUR = "#f5d76e"
#: Samples (2 m apart) per piece of a lane drawn by height on a map whose heights vary.
PIECE = 25
#: Half-width (m) of a reference line drawn as a strip among the lanes on such a map.
REFERENCE_HALF = 0.2
#: Height (m) a reference-line strip is drawn as if lifted, so that it stays above its own road's neighbouring pieces
#: (well below an overpass's 5.5 m).
REFERENCE_LIFT = 1.0


def _legend_entries(used: list[str]) -> list[tuple[str, str]]:
    """(label, colour) for each colour drawn: lane types in the order of ``COLOURS``, then junctions, then others."""
    seen = set(used)
    entries, taken = [], set()
    for colour in COLOURS.values():
        if colour in seen and colour not in taken:
            label = " / ".join(n for n, c in COLOURS.items() if c == colour)
            entries.append((f"{label} lane", colour))
            taken.add(colour)
    if JUNCTION_COLOUR in seen:
        entries.append(("junction (connecting road lanes)", JUNCTION_COLOUR))
    if OTHER_COLOUR in seen:
        entries.append(("other lane type", OTHER_COLOUR))
    return entries


#: Image formats by file suffix (what matplotlib writes without extra packages).
FORMATS = {".png": "png", ".jpg": "jpeg", ".jpeg": "jpeg", ".svg": "svg", ".pdf": "pdf", ".webp": "webp"}


class Rendered(NamedTuple):
    """What :func:`render` wrote: the file, its image format, and how many roads and junctions it shows."""

    path: Path
    format: str
    roads: int
    junctions: int


def _heights_vary(doc) -> bool:
    """Whether any road of ``doc`` leaves height 0 (then lanes are drawn by height)."""
    return any(e.a != 0.0 or e.b != 0.0 or e.c != 0.0 or e.d != 0.0 for road in doc.roads for e in road.elevation)


def _pieces(n: int, layered: bool) -> list[tuple[int, int]]:
    """Index ranges [lo, hi) of ``n`` samples: the whole when not ``layered``, else pieces of :data:`PIECE` samples
    sharing their end samples."""
    if not layered:
        return [(0, n)]
    return [(lo, min(lo + PIECE + 1, n)) for lo in range(0, n - 1, PIECE)]


def image_format(output: str | Path) -> str:
    """The image format the suffix of ``output`` names; :class:`ParamsError` for a suffix not in :data:`FORMATS`."""
    suffix = Path(output).suffix.lower()
    if suffix not in FORMATS:
        known = ", ".join(FORMATS)
        raise ParamsError(f"-o {output}: unknown image format {suffix or '(no suffix)'!r}; use one of {known}")
    return FORMATS[suffix]


def render(
    source: str | Path, output: str | Path, *, dpi: int = 150, size: float = 10.0, title: str | None = None
) -> Rendered:
    """Draw ``source`` to ``output`` in the format its suffix names (:data:`FORMATS`), written atomically. Raises
    :class:`ParamsError` for an unknown suffix, :class:`InputError` when the map cannot be opened or read whole (as
    every xodrcheck command refuses it: no image of part of a map) and :class:`OutputError` when ``output`` cannot be
    written."""
    fmt = image_format(output)
    plt = pyplot("junctionart render")
    doc = _read_map(source)
    layered = _heights_vary(doc)
    shapes = _gather(doc, layered)
    fig, ax = _draw(plt, shapes, layered, size)
    n_roads, n_j = _label(ax, doc, source, title, shapes)
    _save(plt, fig, output, dpi, fmt)
    return Rendered(Path(output), fmt, n_roads, n_j)


def _read_map(source: str | Path):
    """The document of ``source``; :class:`InputError` when it cannot be read, or not whole, or has no road."""
    from xodrcheck.findings import ReadError
    from xodrcheck.reader import read

    try:
        result = read(source)
    except ReadError as exc:
        raise InputError(str(exc)) from None
    why = result.not_whole()
    if why is not None:
        raise InputError(f"cannot read {source} whole, so nothing is written for it: {why}")
    doc = result.document
    if doc is None or not doc.roads:
        raise InputError(f"{source}: no road could be read")
    return doc


class _Shapes:
    """What :func:`render` draws, gathered road by road: polygons (lane pieces, and on a map whose heights vary the
    reference-line strips) with their colours and mean heights, the flat reference lines, and whether any strip was
    drawn."""

    __slots__ = ("colours", "drawn_refs", "heights", "joints", "polys", "refs")

    def __init__(self) -> None:
        self.polys: list[np.ndarray] = []
        self.colours: list[str] = []
        self.heights: list[float] = []
        self.refs: list[np.ndarray] = []
        self.drawn_refs = False
        self.joints: list[np.ndarray] = []

    def add(self, ring: np.ndarray, colour: str, height: float) -> None:
        self.polys.append(ring)
        self.colours.append(colour)
        self.heights.append(height)


def _gather(doc, layered: bool) -> _Shapes:
    """The lanes and reference lines of every road of ``doc``; a road the geometry cannot evaluate is left out of the
    picture (what it added before failing stays), never fatal."""
    from xodrcheck.geometry.lanes import geometry_of

    geos = geometry_of(doc)
    shapes = _Shapes()
    direct = {j.id for j in doc.junctions if j.type.value == "direct"}
    for road in doc.roads:
        try:
            geo = geos[road.id]
            _add_lanes(shapes, road, geo, layered)
            _add_reference(shapes, road, geo, layered)
            _add_joints(shapes, road, geo, direct)
        except (ArithmeticError, ValueError, KeyError, IndexError, TypeError):
            continue
    return shapes


def _add_joints(shapes: _Shapes, road, geo, direct: set[str]) -> None:
    """Where ``road`` touches a direct junction: a bar across its lanes at that end (the junction has no connecting
    road to draw)."""
    for link, at_end in ((road.predecessor, False), (road.successor, True)):
        if link is None or link.element_type.value != "junction" or link.element_id not in direct:
            continue
        if not road.lane_sections:
            continue
        idx = len(road.lane_sections) - 1 if at_end else 0
        s = np.array([road.length if at_end else 0.0])
        lanes = [lane.id for lane in road.lane_sections[idx].lanes if lane.id != 0]
        if not lanes:
            continue
        top, bottom = max(lanes), min(lanes)  # each edge: the outermost lane's outer border (inner: no lane that side)
        a = geo.lane_points(idx, top, s, where="outer" if top > 0 else "inner")
        b = geo.lane_points(idx, bottom, s, where="outer" if bottom < 0 else "inner")
        bar = np.array([[a.x[0], a.y[0]], [b.x[0], b.y[0]]])
        if np.all(np.isfinite(bar)):
            shapes.joints.append(bar)


def _add_lanes(shapes: _Shapes, road, geo, layered: bool) -> None:
    """One polygon per side lane of each of ``road``'s lane sections (per piece when ``layered``), coloured by lane
    type, or in :data:`JUNCTION_COLOUR` on a connecting road; pieces that do not evaluate to finite numbers are
    left out."""
    in_junction = road.junction is not None
    for idx, sec in enumerate(road.lane_sections):
        s0, s1 = sec.s, road.section_end(idx)
        if s1 - s0 <= 1e-9:
            continue
        s = np.linspace(s0, s1, max(2, min(400, int((s1 - s0) / 2.0) + 2)))
        z = geo.elevation(s)
        for lane in (*sec.left, *sec.right):
            inner = geo.lane_points(idx, lane.id, s, where="inner")
            outer = geo.lane_points(idx, lane.id, s, where="outer")
            colour = JUNCTION_COLOUR if in_junction else COLOURS.get(lane.type.value, OTHER_COLOUR)
            for lo, hi in _pieces(len(s), layered):
                ring = np.column_stack(
                    [
                        np.concatenate([inner.x[lo:hi], outer.x[lo:hi][::-1]]),
                        np.concatenate([inner.y[lo:hi], outer.y[lo:hi][::-1]]),
                    ]
                )
                if not np.all(np.isfinite(ring)):
                    continue
                shapes.add(ring, colour, float(z[lo:hi].mean()))


def _add_reference(shapes: _Shapes, road, geo, layered: bool) -> None:
    """``road``'s reference line (none for a connecting road): a thin line on a flat map; where heights vary, a strip
    of :data:`REFERENCE_HALF` among the lanes, in pieces lifted by :data:`REFERENCE_LIFT` above the road's own."""
    in_junction = road.junction is not None
    s = np.linspace(0.0, road.length, max(2, min(400, int(road.length / 2.0) + 2)))
    pose = geo.reference(s)
    if not in_junction and not layered:
        shapes.refs.append(np.column_stack([pose.x, pose.y]))
    elif not in_junction:  # a strip among the lanes, above the road's own pieces
        z = geo.elevation(s)
        nx, ny = -np.sin(pose.hdg) * REFERENCE_HALF, np.cos(pose.hdg) * REFERENCE_HALF
        for lo, hi in _pieces(len(s), layered):
            xs, ys = pose.x[lo:hi], pose.y[lo:hi]
            ring = np.column_stack(
                [
                    np.concatenate([xs + nx[lo:hi], (xs - nx[lo:hi])[::-1]]),
                    np.concatenate([ys + ny[lo:hi], (ys - ny[lo:hi])[::-1]]),
                ]
            )
            shapes.add(ring, REFERENCE_COLOUR, float(z[lo:hi].mean()) + REFERENCE_LIFT)
        shapes.drawn_refs = True


def _draw(plt, shapes: _Shapes, layered: bool, size: float):
    """A new figure of ``size`` inches with the lanes (lowest first when ``layered``) and reference lines drawn,
    framed with a margin around all polygons: (figure, axes)."""
    from matplotlib.collections import LineCollection, PolyCollection

    fig, ax = plt.subplots(figsize=(size, size))
    polys, colours = shapes.polys, shapes.colours
    if layered:  # lowest first; each piece edged in its own colour so that no seam shows between pieces
        order = np.argsort(np.asarray(shapes.heights), kind="stable")
        polys, colours = [polys[k] for k in order], [colours[k] for k in order]
        ax.add_collection(PolyCollection(polys, facecolors=colours, edgecolors=colours, linewidths=0.3))
    else:
        ax.add_collection(
            PolyCollection(polys, facecolors=colours, edgecolors=SEAM_COLOUR, linewidths=0.25, alpha=0.95)
        )
    ax.add_collection(LineCollection(shapes.refs, colors=REFERENCE_COLOUR, linewidths=0.4))
    if shapes.joints:
        ax.add_collection(LineCollection(shapes.joints, colors=JUNCTION_COLOUR, linewidths=2.5))
    pts = np.concatenate(polys) if polys else np.zeros((1, 2))
    pad = 10.0
    ax.set_xlim(pts[:, 0].min() - pad, pts[:, 0].max() + pad)
    ax.set_ylim(pts[:, 1].min() - pad, pts[:, 1].max() + pad)
    ax.set_aspect("equal")
    ax.set_facecolor("#f7f7f2")
    return fig, ax


def _label(ax, doc, source: str | Path, title: str | None, shapes: _Shapes) -> tuple[int, int]:
    """Title (``title``, or the file name with its counts), a legend of the colours drawn beside the map, and axis
    labels; returns (roads outside junctions, junctions)."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    legend: list[Patch | Line2D] = [Patch(color=c, label=name) for name, c in _legend_entries(shapes.colours)]
    if shapes.joints:
        legend.append(Line2D([], [], color=JUNCTION_COLOUR, linewidth=2.5, label="direct junction (roads meet)"))
    if shapes.refs or shapes.drawn_refs:
        legend.append(Line2D([], [], color=REFERENCE_COLOUR, linewidth=1.5, label="reference line"))
    n_j = len(doc.junctions)
    n_roads = sum(r.junction is None for r in doc.roads)
    ax.set_title(title or f"{Path(str(source)).name}: {n_roads} roads, {n_j} junctions")
    ax.legend(handles=legend, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False, fontsize=9)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    return n_roads, n_j


def _save(plt, fig, output: str | Path, dpi: int, fmt: str) -> None:
    """Write ``fig`` to ``output`` atomically (:class:`OutputError` when it cannot be written) and close it."""
    try:
        with atomic_file(output, "wb") as stream:
            fig.savefig(stream, dpi=dpi, bbox_inches="tight", format=fmt)
    except TargetError as exc:
        raise OutputError(str(exc)) from None
    finally:
        plt.close(fig)
