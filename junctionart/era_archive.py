"""The expressive range report's section on a search archive (``junctionart era --archive DIR``, issue 13).

It sets the elites of a ``junctionart search`` folder (its ``archive.csv``) beside the intersections of the random
runs and of the comparison maps (``--compare``, e.g. CARLA's towns), per intersection: the share of each leg count,
the mean complexity and FOV of its legs, its conflictRatio, area and connection lanes. One figure
(``era_archive.png``) and one table. The archive holds one elite per cell of its descriptor grid, so its distribution
shows what the search reaches, not how often anything occurs.
"""

from __future__ import annotations

import csv
import math
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .errors import ParamsError
from .extras import pyplot

#: Per-intersection columns compared (``legs.csv`` names; ``archive.csv`` calls the last one ``lanes``).
COLUMNS = ("legs", "complexity", "fov", "conflict_ratio", "area", "n_connection_lanes")
LEG_COUNTS = (3, 4, 5, 6, 7)
FIGURE = "era_archive.png"


@dataclass(frozen=True)
class Junctions:
    """One sample's intersections (3+ legs), one value per intersection and column."""

    label: str
    values: dict[str, np.ndarray]

    def __len__(self) -> int:
        return len(self.values["legs"])


def _float(text: Any) -> float:
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def from_rows(label: str, rows: Sequence[dict]) -> Junctions:
    """Intersections of ``legs.csv``-style rows (one row per leg): leg metrics averaged over the junction's legs."""
    groups: dict[tuple[str, str, str], list[dict]] = {}
    for r in rows:
        groups.setdefault((str(r["run"]), str(r["seed"]), str(r["junction_index"])), []).append(r)
    out: dict[str, list[float]] = {c: [] for c in COLUMNS}
    for legs in groups.values():
        if _float(legs[0]["legs"]) < LEG_COUNTS[0]:
            continue
        for c in COLUMNS:
            values = [_float(r[c]) for r in legs] if c in ("complexity", "fov") else [_float(legs[0][c])]
            finite = [v for v in values if math.isfinite(v)]
            out[c].append(float(np.mean(finite)) if finite else math.nan)
    return Junctions(label, {c: np.array(v, dtype=float) for c, v in out.items()})


def from_archive(folder: Path) -> Junctions:
    """The elites of a ``junctionart search`` folder."""
    path = Path(folder) / "archive.csv"
    try:
        with open(path, newline="", encoding="utf-8") as stream:
            rows = list(csv.DictReader(stream))
    except OSError as exc:
        raise ParamsError(f"--archive {folder}: cannot read {path.name} ({exc.strerror or exc})") from None
    if not rows or "legs" not in rows[0] or "lanes" not in rows[0]:
        raise ParamsError(f"--archive {folder}: {path.name} is not the archive of a junctionart search")
    names = {c: ("lanes" if c == "n_connection_lanes" else c) for c in COLUMNS}
    return Junctions(
        f"search archive ({Path(folder).name})",
        {c: np.array([_float(r[names[c]]) for r in rows], dtype=float) for c in COLUMNS},
    )


def _median(values: np.ndarray) -> str:
    finite = values[np.isfinite(values)]
    return f"{float(np.median(finite)):.3g}" if finite.size else "n/a"


def table(samples: Sequence[Junctions]) -> list[str]:
    """Markdown rows: leg-count shares and medians per sample."""
    lines = [
        "| sample | intersections | " + " | ".join(f"{n} legs" for n in LEG_COUNTS) + " | median complexity "
        "| complexity > 0.5 | median conflictRatio | median area (m^2) | median connection lanes |",
        "|---" * (len(LEG_COUNTS) + 7) + "|",
    ]
    for s in samples:
        n = max(len(s), 1)
        legs = s.values["legs"]
        shares = " | ".join(f"{100 * np.sum(legs == k) / n:.1f} %" for k in LEG_COUNTS)
        high = 100 * np.sum(s.values["complexity"] > 0.5) / n
        lines.append(
            f"| {s.label} | {len(s)} | {shares} | {_median(s.values['complexity'])} | {high:.1f} % "
            f"| {_median(s.values['conflict_ratio'])} | {_median(s.values['area'])} "
            f"| {_median(s.values['n_connection_lanes'])} |"
        )
    return lines


def figure(samples: Sequence[Junctions], kinds: Sequence[str], path: Path) -> None:
    """Leg-count shares and the distributions of complexity, conflictRatio and area, one line per sample (the
    archive's thick, the comparison maps' dashed)."""
    plt = pyplot("the expressive range figures")
    fig, axes = plt.subplots(1, 4, figsize=(18, 3.8))
    width = 0.8 / max(len(samples), 1)
    for k, (s, kind) in enumerate(zip(samples, kinds)):
        style = _style(k, kind)
        counts = np.array([np.sum(s.values["legs"] == n) for n in LEG_COUNTS], dtype=float)
        axes[0].bar(
            np.array(LEG_COUNTS) - 0.4 + width * (k + 0.5),
            100 * counts / max(len(s), 1),
            width,
            color=style["color"],
            hatch="//" if kind == "compare" else None,
            edgecolor="white" if kind == "compare" else None,
            label=f"{s.label} (n={len(s)})",
        )
        for ax, column, log in zip(axes[1:], ("complexity", "conflict_ratio", "area"), (False, False, True)):
            values = s.values[column][np.isfinite(s.values[column])]
            if log:
                values = values[values > 0]
            if values.size:
                weights = np.full(values.size, 100.0 / values.size)
                ax.hist(values, bins=_bins(samples, column, log), weights=weights, histtype="step", **style)
    axes[0].set(xlabel="legs", ylabel="share of intersections (%)", yscale="log", xticks=LEG_COUNTS)
    axes[0].legend(fontsize=7)
    for ax, column in zip(axes[1:], ("complexity", "conflictRatio", "area (m^2)")):
        ax.set(xlabel=f"{column} per intersection", ylabel="share of intersections (%)")
    axes[3].set_xscale("log")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def _style(k: int, kind: str) -> dict:
    if kind == "archive":
        return {"color": "crimson", "linewidth": 2.4}
    if kind == "compare":
        return {"color": "black", "linewidth": 1.4, "linestyle": "--"}
    return {"color": f"C{k}", "linewidth": 1.4}


def _bins(samples: Sequence[Junctions], column: str, log: bool) -> np.ndarray:
    values = np.concatenate([s.values[column][np.isfinite(s.values[column])] for s in samples])
    if log:
        values = values[values > 0]
        if values.size == 0:
            return np.logspace(1, 4, 31)
        return np.logspace(np.log10(values.min()), np.log10(values.max()) + 1e-9, 31)
    if values.size == 0:
        return np.linspace(0, 1, 31)
    return np.linspace(float(values.min()), float(values.max()) + 1e-9, 31)


def section(folder: Path, runs: Sequence[Junctions], compare: Junctions | None, archive: Junctions) -> list[str]:
    """The report's Markdown lines (the figure is drawn into ``folder``)."""
    samples = [*runs, *([compare] if compare is not None else []), archive]
    kinds = ["run"] * len(runs) + (["compare"] if compare is not None else []) + ["archive"]
    figure(samples, kinds, Path(folder) / FIGURE)
    rare = {s.label: 100 * np.sum(s.values["legs"] >= 6) / max(len(s), 1) for s in samples}
    return [
        "## The search archive beside random generation" + (f" and {compare.label}" if compare is not None else ""),
        "",
        f"![archive]({FIGURE})",
        "",
        f"{archive.label}: {len(archive)} elites, one per filled cell of its descriptor grid, so the shares below say "
        "what the search reaches, not how often the generator makes it. 6- and 7-leg intersections: "
        + "; ".join(f"{label} {share:.1f} %" for label, share in rare.items())
        + ". Leg metrics (complexity, FOV) are means over each intersection's legs.",
        "",
        *table(samples),
        "",
    ]
