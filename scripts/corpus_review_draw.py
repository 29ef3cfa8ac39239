"""Plan-view pictures of a place in a map for the corpus review (``scripts/corpus_review.py``).

Lanes are drawn from :mod:`xodrcheck.geometry.lanes` (the checker's own lane geometry, which the review's numbers
recompute independently of the rules): every lane of every road near the place as a filled polygon between its
borders, the roads a finding names outlined in colour, the finding's point marked."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from xodrcheck.geometry.lanes import RoadGeometry
from xodrcheck.model import Document, LaneType, Road

_FILL = {"driving": "#b8b8b8", "sidewalk": "#e8d9b0", "shoulder": "#d5e6c8", "parking": "#c9d7ea"}
_HIGHLIGHT = ("#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e")


@dataclass
class Scene:
    """What to draw: the window (centre, half size in m), the roads to outline, extra lines and the finding."""

    title: str
    centre: tuple[float, float]
    half: float
    roads: Sequence[str] = ()
    point: tuple[float, float] | None = None
    note: str = ""
    lines: list[tuple[np.ndarray, np.ndarray, str, str]] = field(default_factory=list)  # x, y, colour, label


def _near(geometry: RoadGeometry, road: Road, centre: tuple[float, float], reach: float) -> bool:
    s = np.linspace(0.0, road.length, max(2, int(road.length / 2.0) + 2))
    pose = geometry.reference(s)
    return bool(np.any(np.hypot(pose.x - centre[0], pose.y - centre[1]) < reach))


def lane_outlines(
    geometry: RoadGeometry, step: float = 0.05, centre: tuple[float, float] | None = None, reach: float = np.inf
) -> list[tuple[int, LaneType, np.ndarray, np.ndarray]]:
    """(lane id, lane type, polygon x, polygon y) of every non-centre lane of every section of one road (of the
    sections whose reference line comes within ``reach`` of ``centre``)."""
    out = []
    road = geometry.road
    for k, section in enumerate(road.lane_sections):
        start, end = section.s, road.section_end(k)
        if end <= start:
            continue
        if centre is not None:
            ref = geometry.reference(np.linspace(start, end, max(2, int((end - start) / 2.0) + 2)))
            if not np.any(np.hypot(ref.x - centre[0], ref.y - centre[1]) < reach):
                continue
        s = np.linspace(start, end, max(2, int((end - start) / step) + 2))
        s[-1] = np.nextafter(end, start)  # the section's own last point, not the next section's first
        for lane in section.lanes:
            if lane.id == 0:
                continue
            inner = geometry.lane_points(k, lane.id, s, "inner")
            outer = geometry.lane_points(k, lane.id, s, "outer")
            x = np.concatenate([inner.x, outer.x[::-1]])
            y = np.concatenate([inner.y, outer.y[::-1]])
            out.append((lane.id, lane.type, x, y))
    return out


def draw(document: Document, scene: Scene, path: Path, size: float = 4.2) -> None:
    """Write a PNG of ``scene`` (about 420 px square at 100 dpi)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(size, size), dpi=100)
    reach = scene.half * 1.5 + 30.0
    step = max(0.02, scene.half / 250.0)
    highlight = {rid: _HIGHLIGHT[i % len(_HIGHLIGHT)] for i, rid in enumerate(scene.roads)}
    for road in document.roads:
        geometry = RoadGeometry(road)
        if road.id not in highlight and not _near(geometry, road, scene.centre, reach):
            continue
        colour = highlight.get(road.id)
        for _lane_id, kind, x, y in lane_outlines(geometry, step, scene.centre, reach):
            ax.fill(x, y, color=_FILL.get(kind.value, "#dddddd"), alpha=0.55 if colour is None else 0.7, lw=0)
            ax.plot(x, y, color=colour or "#777777", lw=1.2 if colour else 0.4)
        if colour is not None:
            s = np.linspace(0.0, road.length, max(2, int(road.length / 0.1) + 2))
            ref = geometry.reference(s)
            ax.plot(ref.x, ref.y, color=colour, lw=0.8, ls="--", label=f"road {road.id}")
    for x, y, colour, label in scene.lines:
        ax.plot(x, y, color=colour, lw=1.6, label=label)
    if scene.point is not None:
        ax.plot(*scene.point, marker="x", color="black", ms=10, mew=2)
    cx, cy = scene.centre
    ax.set_xlim(cx - scene.half, cx + scene.half)
    ax.set_ylim(cy - scene.half, cy + scene.half)
    ax.set_aspect("equal")
    ax.tick_params(labelsize=7)
    ax.set_title(scene.title, fontsize=8)
    if scene.note:
        ax.text(
            0.02,
            0.02,
            scene.note,
            transform=ax.transAxes,
            fontsize=7,
            va="bottom",
            ha="left",
            bbox={"facecolor": "white", "alpha": 0.85, "lw": 0},
        )
    if highlight or scene.lines:
        ax.legend(fontsize=6, loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
