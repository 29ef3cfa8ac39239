"""Figures and the one-page Markdown report of an expressive range analysis (the paper's Figures 13-19 and 21-28).

Input: rows as in ``legs.csv`` (see :mod:`junctionart.era`), already cut to the first N intersections of each run,
and optionally the rows of a comparison folder (third-party maps measured the same way).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from xodrcheck.support.atomic import atomic_file

from .extras import pyplot

#: (column, paper name, unit, paper figure, what the paper reports)
LEG_METRICS = (
    ("complexity", "complexity", "", 13, "almost half of the intersections have complexity over 0.5"),
    ("max_curvature", "maxCurvature", "deg/m", 14, "mostly low values, a tail to 20 deg/m and beyond"),
    ("fov", "FOV", "deg", 15, "FOV up to about 300 degrees; medians rise with the leg count"),
    ("corner_deviation", "cornerDeviation", "deg", 16, "large deviations from the sight line; medians rise with legs"),
)
JUNCTION_METRICS = (
    ("area", "area", "m^2", 21, "the median area grows with the leg count, more slowly than expected"),
    ("conflict_area", "conflictArea", "m^2", 22, "grows with the leg count, strongly correlated with the area"),
    ("conflict_ratio", "conflictRatio", "", 23, "varies widely for every leg count; high ratios occur"),
    ("n_connection_lanes", "nConnectionLanes", "", 24, "grows combinatorially with lanes and legs"),
)
#: (x column, y column, paper figure, what the paper reports)
HEATMAPS = (
    ("fov", "max_curvature", 17, "banding of maxCurvature near 5, 10 and 15 deg/m; high curvature goes with wide FOV"),
    ("fov", "corner_deviation", 18, "a strong co-occurrence line, with many values below it"),
    ("corner_deviation", "max_curvature", 19, "banding as in Figure 17"),
    ("fov", "conflict_area", 25, "high conflictArea with high FOV is rare"),
    ("max_curvature", "conflict_area", 26, "high conflictArea with high maxCurvature is rare"),
    ("fov", "conflict_ratio", 27, "high conflictRatio with high FOV is reachable"),
    ("max_curvature", "conflict_ratio", 28, "high conflictRatio with high maxCurvature is reachable"),
)
NAMES = {c: name for c, name, *_ in (*LEG_METRICS, *JUNCTION_METRICS)}
UNITS = {c: unit for c, _, unit, *_ in (*LEG_METRICS, *JUNCTION_METRICS)}
LEG_COUNTS = (3, 4, 5, 6, 7)


def _float(text: str) -> float:
    return float(text) if text not in ("", None) else math.nan


@dataclass(frozen=True)
class Sample:
    """One run's (or the comparison's) rows as arrays: per leg and per junction."""

    label: str
    legs: dict[str, np.ndarray]  # column -> values, one per leg row
    junctions: dict[str, np.ndarray]  # column -> values, one per junction

    @classmethod
    def of(cls, label: str, rows: Sequence[dict]) -> Sample:
        columns = ("legs", *(c for c, *_ in LEG_METRICS), *(c for c, *_ in JUNCTION_METRICS))
        leg_rows = [r for r in rows if r["leg"] not in ("", None)]
        first = [r for r in rows if r["leg"] in ("0", "", None, 0)]
        return cls(
            label,
            {c: np.array([_float(r[c]) for r in leg_rows]) for c in columns},
            {c: np.array([_float(r[c]) for r in first]) for c in columns},
        )

    def table(self, column: str) -> dict[str, np.ndarray]:
        return self.junctions if column in {c for c, *_ in JUNCTION_METRICS} else self.legs


#: fewer values than this are drawn as ticks, not as a density
MIN_DENSITY_SAMPLES = 10


def _bins(values: list[np.ndarray], n: int = 40) -> np.ndarray:
    finite = np.concatenate([v[np.isfinite(v)] for v in values]) if values else np.array([])
    if finite.size == 0:
        return np.linspace(0, 1, n + 1)
    lo, hi = float(finite.min()), float(np.percentile(finite, 99.5))
    if hi <= lo:
        hi = lo + 1.0
    return np.linspace(lo, hi, n + 1)


def distribution_figure(column: str, samples: Sequence[Sample], compare: Sample | None, path: Path) -> None:
    plt = pyplot("the expressive range figures")

    everything = [s.table(column)[column] for s in samples] + ([compare.table(column)[column]] if compare else [])
    bins = _bins(everything)
    fig, axes = plt.subplots(1, len(samples), figsize=(5.2 * len(samples), 3.6), sharey=True, squeeze=False)
    for ax, sample in zip(axes[0], samples):
        table = sample.table(column)
        for k, legs in enumerate(LEG_COUNTS):
            values = table[column][(table["legs"] == legs) & np.isfinite(table[column])]
            inside = values[(values >= bins[0]) & (values <= bins[-1])]
            if values.size < MIN_DENSITY_SAMPLES or inside.size == 0:
                # a density of a handful of values is a few spikes: show the values themselves
                if values.size:
                    ax.plot(
                        np.clip(values, bins[0], bins[-1]),
                        np.zeros(values.size),
                        linestyle="none",
                        marker="|",
                        markersize=22,
                        markeredgewidth=2.2,
                        clip_on=False,
                        color=f"C{k}",
                        label=f"{legs} legs (n={values.size}, values)",
                    )
                continue
            ax.hist(
                values,
                bins=bins,
                density=True,
                histtype="step",
                linewidth=1.4,
                color=f"C{k}",
                label=f"{legs} legs (n={values.size})",
            )
        if compare is not None:
            ctable = compare.table(column)
            values = ctable[column][(ctable["legs"] >= LEG_COUNTS[0]) & np.isfinite(ctable[column])]
            if ((values >= bins[0]) & (values <= bins[-1])).any():
                ax.hist(
                    values,
                    bins=bins,
                    density=True,
                    histtype="step",
                    linestyle="--",
                    color="black",
                    linewidth=1.4,
                    label=f"{compare.label}, all legs (n={values.size})",
                )
        ax.set_title(sample.label)
        unit = UNITS[column]
        ax.set_xlabel(f"{NAMES[column]}" + (f" ({unit})" if unit else ""))
        ax.legend(fontsize=7)
    axes[0][0].set_ylabel("probability density")
    fig.tight_layout()
    _save(fig, path)


def heatmap_figure(x: str, y: str, samples: Sequence[Sample], compare: Sample | None, path: Path) -> None:
    plt = pyplot("the expressive range figures")

    xs = [s.legs[x] for s in samples] + ([compare.legs[x]] if compare else [])
    ys = [s.legs[y] for s in samples] + ([compare.legs[y]] if compare else [])
    xbins, ybins = _bins(xs, 36), _bins(ys, 36)
    fig, axes = plt.subplots(1, len(samples), figsize=(5.2 * len(samples), 4.2), squeeze=False)
    for ax, sample in zip(axes[0], samples):
        vx, vy = sample.legs[x], sample.legs[y]
        ok = np.isfinite(vx) & np.isfinite(vy) & (sample.legs["legs"] >= LEG_COUNTS[0])
        counts, _, _ = np.histogram2d(vx[ok], vy[ok], bins=[xbins, ybins])
        total = max(counts.sum(), 1)
        image = ax.imshow(
            (counts / total).T,
            origin="lower",
            aspect="auto",
            cmap="magma",
            extent=(xbins[0], xbins[-1], ybins[0], ybins[-1]),
        )
        fig.colorbar(image, ax=ax, label="share of legs")
        if compare is not None:
            cx, cy = compare.legs[x], compare.legs[y]
            cok = np.isfinite(cx) & np.isfinite(cy) & (compare.legs["legs"] >= LEG_COUNTS[0])
            ax.scatter(cx[cok], cy[cok], s=9, marker="x", color="cyan", linewidths=0.8, label=compare.label)
            ax.legend(fontsize=7, loc="upper right")
        ax.set_xlim(xbins[0], xbins[-1])
        ax.set_ylim(ybins[0], ybins[-1])
        ax.set_title(f"{sample.label} (n={int(ok.sum())} legs)")
        ax.set_xlabel(NAMES[x] + (f" ({UNITS[x]})" if UNITS[x] else ""))
        ax.set_ylabel(NAMES[y] + (f" ({UNITS[y]})" if UNITS[y] else ""))
    fig.tight_layout()
    _save(fig, path)


def _median(values: np.ndarray) -> str:
    values = values[np.isfinite(values)]
    return f"{np.median(values):.3g}" if values.size else "-"


def _medians_line(column: str, sample: Sample) -> str:
    table = sample.table(column)
    parts = []
    for legs in LEG_COUNTS:
        values = table[column][table["legs"] == legs]
        if np.isfinite(values).any():
            parts.append(f"{legs} legs {_median(values)}")
    return ", ".join(parts) or "no data"


def _count_table(samples: Sequence[Sample], compare: Sample | None) -> list[str]:
    everyone = [*samples, *([compare] if compare else [])]
    lines = [
        "| | " + " | ".join(f"{n} legs" for n in LEG_COUNTS) + " | 8+ | total |",
        "|---|" + "---|" * (len(LEG_COUNTS) + 2),
    ]
    for s in everyone:
        legs = s.junctions["legs"]
        legs = legs[legs >= LEG_COUNTS[0]]
        cells = [str(int((legs == n).sum())) for n in LEG_COUNTS] + [str(int((legs > LEG_COUNTS[-1]).sum()))]
        lines.append(f"| {s.label} | " + " | ".join(cells) + f" | {legs.size} |")
    return lines


def write_report(
    folder: Path,
    samples: Sequence[Sample],
    compare: Sample | None,
    setup: Sequence[str],
    extra: Sequence[str] = (),
) -> Path:
    """Draw every figure into ``folder`` and write ``folder/report.md``; ``setup`` lines describe the run, ``extra``
    lines (a section of Markdown) end the report."""
    folder.mkdir(parents=True, exist_ok=True)
    lines = [
        "# Expressive range analysis",
        "",
        *setup,
        "",
        "## Intersections by leg count",
        "",
        *_count_table(samples, compare),
        "",
        "## Distributions by leg count",
        "",
    ]
    for column, name, _unit, figure, paper in (*LEG_METRICS, *JUNCTION_METRICS):
        png = f"dist_{column}.png"
        distribution_figure(column, samples, compare, folder / png)
        per = "incident road (leg)" if column in {c for c, *_ in LEG_METRICS} else "intersection"
        lines += [
            f"### {name} (paper Figure {figure})",
            "",
            f"![{name}]({png})",
            "",
            f"Distribution of {name} per {per}, one line per leg count"
            + (f", {compare.label} dashed" if compare else "")
            + f". Paper: {paper}. Here, medians: "
            + "; ".join(f"{s.label}: {_medians_line(column, s)}" for s in samples)
            + (f"; {compare.label}: {_medians_line(column, compare)}" if compare else "")
            + ".",
            "",
        ]
    lines += ["## Heatmaps of metric pairs", ""]
    for x, y, figure, paper in HEATMAPS:
        png = f"heat_{x}__{y}.png"
        heatmap_figure(x, y, samples, compare, folder / png)
        corr = []
        for s in samples:
            vx, vy = s.legs[x], s.legs[y]
            ok = np.isfinite(vx) & np.isfinite(vy)
            if ok.sum() > 2 and np.std(vx[ok]) > 0 and np.std(vy[ok]) > 0:
                corr.append(f"{s.label} r = {np.corrcoef(vx[ok], vy[ok])[0, 1]:.2f}")
        lines += [
            f"### {NAMES[x]} vs {NAMES[y]} (paper Figure {figure})",
            "",
            f"![{x} vs {y}]({png})",
            "",
            "Share of legs in each cell"
            + (f"; {compare.label} legs as crosses" if compare else "")
            + f". Paper: {paper}. Here, Pearson correlation: {', '.join(corr) or 'n/a'}.",
            "",
        ]
    lines += extra
    path = folder / "report.md"
    with atomic_file(path, "w") as stream:
        stream.write("\n".join(lines))
    return path


def _save(fig, path: Path) -> None:
    """Save a figure atomically (no partial PNG after an error, Ctrl-C or SIGTERM) and close it."""
    import matplotlib.pyplot as plt

    try:
        with atomic_file(path, "wb") as stream:
            fig.savefig(stream, dpi=110, format="png")
    finally:
        plt.close(fig)
