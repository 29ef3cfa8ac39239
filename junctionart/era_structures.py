"""The expressive range report's section on structures: how many of each kind (:mod:`xodrcheck.structures`) the runs
made, and the distributions of each kind's own measures (split angle of forks, taper length of ramps...).

Input: the rows of ``structures.csv`` (:func:`junctionart.era.structure_rows`) and each run's selected ``legs.csv``
rows; a run's structures are those of the maps (seeds) its selected intersections come from.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from xodrcheck.structures import KINDS, Kind
from xodrcheck.support.atomic import atomic_file

from .extras import pyplot


def _values(rows: Sequence[dict], name: str) -> np.ndarray:
    return np.array([float(r[name]) if r.get(name) not in ("", None) else math.nan for r in rows])


def figure(kind: Kind, by_run: Mapping[str, Sequence[dict]], path: Path) -> None:
    """One panel per measure of ``kind``: a histogram per run."""
    plt = pyplot("the expressive range figures")
    n = len(kind.measures)
    cols = min(3, n)
    grid_rows = math.ceil(n / cols)
    fig, axes = plt.subplots(grid_rows, cols, figsize=(4.4 * cols, 3.4 * grid_rows), squeeze=False)
    for ax in axes.ravel()[n:]:
        ax.set_visible(False)
    for ax, measure in zip(axes.ravel(), kind.measures):
        for k, (run, rows) in enumerate(by_run.items()):
            values = _values(rows, measure.name)
            values = values[np.isfinite(values)]
            if values.size:
                bins = np.linspace(measure.low, measure.high, 25)
                ax.hist(
                    np.clip(values, measure.low, measure.high),
                    bins=bins,
                    histtype="step",
                    linewidth=1.4,
                    color=f"C{k}",
                    label=f"{run} (n={values.size})",
                )
        ax.set_xlabel(measure.name + (f" ({measure.unit})" if measure.unit else ""))
        ax.set_title(measure.meaning, fontsize=8)
        ax.legend(fontsize=7)
    for row in axes:
        row[0].set_ylabel(f"{kind.name}s")
    fig.tight_layout()
    try:
        with atomic_file(path, "wb") as stream:
            fig.savefig(stream, dpi=110, format="png")
    finally:
        plt.close(fig)


def section(folder: Path, rows: Sequence[dict], selected: Mapping[str, Sequence[dict]]) -> list[str]:
    """The report's lines on structures (a table of counts per kind and run, a figure per kind that occurs)."""
    by_run: dict[str, list[dict]] = {}
    for run, chosen in selected.items():
        seeds = {int(r["seed"]) for r in chosen}
        by_run[run] = [r for r in rows if r["run"] == run and int(r["seed"]) in seeds]
    lines = [
        "## Structures by kind",
        "",
        "What each junction of the runs' maps is part of, recognised from the written file by "
        "`xodrcheck.structures` (the maps of each run's selected intersections).",
        "",
        "| | " + " | ".join(k.name for k in KINDS) + " |",
        "|---|" + "---|" * len(KINDS),
    ]
    for run, chosen in by_run.items():
        lines.append(f"| {run} | " + " | ".join(str(sum(r["kind"] == k.name for r in chosen)) for k in KINDS) + " |")
    lines.append("")
    for kind in KINDS:
        if kind.name == "junction":
            continue
        of_kind = {run: [r for r in chosen if r["kind"] == kind.name] for run, chosen in by_run.items()}
        if not any(of_kind.values()):
            continue
        png = f"kind_{kind.name}.png"
        figure(kind, of_kind, folder / png)
        medians = []
        for measure in kind.measures:
            parts = []
            for run, chosen in of_kind.items():
                v = _values(chosen, measure.name)
                if np.isfinite(v).any():
                    parts.append(f"{run} {np.nanmedian(v):.3g}")
            medians.append(f"{measure.name}: {', '.join(parts) or 'n/a'}")
        lines += [
            f"### {kind.name}",
            "",
            f"![{kind.name}]({png})",
            "",
            f"{kind.meaning}. Medians: " + "; ".join(medians) + ".",
            "",
        ]
    return lines
