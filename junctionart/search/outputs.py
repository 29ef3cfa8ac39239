"""What a search leaves in its folder: ``archive.csv``, a heatmap PNG per descriptor pair, ``elites/`` and
``report.md``."""

from __future__ import annotations

import csv
import hashlib
import itertools
import json
from pathlib import Path
from typing import Any

import numpy as np

from . import kinds
from .engine import State, elites
from .predicate import Predicate

#: Columns of ``archive.csv`` before the metrics.
HEAD = ("cell", "objective", "meets_where", "file", "sha256")


def _rows(state: State, where: Predicate | None) -> list[dict[str, Any]]:
    data = elites(state)
    rows = []
    for k in np.argsort(data["index"], kind="stable"):
        values = {n: float(data[n][k]) for n in state.settings.metrics}
        cell = int(data["index"][k])
        rows.append(
            {
                "cell": cell,
                "objective": float(data["objective"][k]),
                "meets_where": "" if where is None else int(where(values)),
                "file": f"elites/cell{cell:05d}.xodr",
                **{n: round(v, 6) for n, v in values.items()},
                "genome": json.dumps([round(float(v), 9) for v in data["solution"][k]]),
                "solution": data["solution"][k],
            }
        )
    return rows


def write_elites(folder: Path, rows: list[dict[str, Any]], kind: str = "junction") -> None:
    """Each elite's map (regenerated from its vector) and its description as JSON beside it; fills ``sha256``."""
    from xodrcheck.support.atomic import atomic_file

    module = kinds.get(kind)
    (folder / "elites").mkdir(exist_ok=True)
    for row in rows:
        spec = module.decode(np.asarray(row["solution"]))
        data = module.map_bytes(spec)
        path = folder / str(row["file"])
        with atomic_file(path, "wb") as stream:
            stream.write(data)
        with atomic_file(path.with_suffix(".json"), "w") as stream:
            json.dump(module.to_dict(spec), stream, indent=1)
        row["sha256"] = hashlib.sha256(data).hexdigest()


def write_csv(folder: Path, rows: list[dict[str, Any]], names: tuple[str, ...]) -> Path:
    from xodrcheck.support.atomic import atomic_file

    path = folder / "archive.csv"
    columns = [*HEAD, *names, "genome"]
    with atomic_file(path, "w") as stream:
        writer = csv.DictWriter(stream, columns, lineterminator="\n", extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    return path


def heatmaps(folder: Path, state: State) -> list[Path]:
    """One PNG per descriptor pair: each cell's objective (the best over the other descriptors), empty cells blank."""
    from ..extras import pyplot

    plt = pyplot("junctionart search's heatmaps")

    data = elites(state)
    names = [n for n, _ in state.settings.descriptors]
    dims = [c for _, c in state.settings.descriptors]
    grid_index = np.array(np.unravel_index(data["index"].astype(int), dims)).T if len(data["index"]) else None
    out = []
    for a, b in itertools.combinations(range(len(names)), 2):
        grid = np.full((dims[b], dims[a]), np.nan)
        if grid_index is not None:
            for (ia, ib), value in zip(grid_index[:, [a, b]], data["objective"]):
                grid[ib, ia] = np.nanmax([grid[ib, ia], value])
        metrics = state.settings.metrics
        (lo_a, hi_a, _), (lo_b, hi_b, _) = metrics[names[a]], metrics[names[b]]
        fig, ax = plt.subplots(figsize=(6.4, 4.8), dpi=110)
        mesh = ax.pcolormesh(
            np.linspace(lo_a, hi_a, dims[a] + 1), np.linspace(lo_b, hi_b, dims[b] + 1), grid, cmap="viridis"
        )
        fig.colorbar(mesh, ax=ax, label="objective (compactness)")
        filled = int(np.isfinite(grid).sum())
        ax.set(xlabel=names[a], ylabel=names[b], title=f"{names[b]} vs {names[a]}: {filled} of {grid.size} cells")
        path = folder / f"heatmap_{names[a]}_{names[b]}.png"
        fig.tight_layout()
        fig.savefig(path)
        plt.close(fig)
        out.append(path)
    return out


def report(folder: Path, state: State, where: Predicate | None, rows: list[dict[str, Any]], images: list[Path]) -> Path:
    from xodrcheck.support.atomic import atomic_file

    archive = state.scheduler.archive
    stats = archive.stats
    s = state.settings
    met = [r for r in rows if r["meets_where"] == 1]
    metrics = s.metrics
    names = tuple(metrics)
    spans = ", ".join(f"{n} ({c} cells, {metrics[n][0]:g} to {metrics[n][1]:g})" for n, c in s.descriptors)
    lines = [
        "# junctionart search",
        "",
        f"- Kind: {s.kind}.",
        f"- Descriptors: {spans}; {archive.cells} cells in all.",
        f"- Seed {s.seed}, {s.batch} candidates per emitter per iteration, {len(state.history)} iterations.",
        f"- Evaluated {state.evaluated} maps, {state.feasible} feasible (0 xodrcheck errors)"
        + (
            f"; infeasible: {', '.join(f'{k} x{v}' for k, v in sorted(state.failures.items()))}"
            if state.failures
            else ""
        )
        + ".",
        f"- Coverage {float(stats.coverage):.1%} ({int(stats.num_elites)} of {archive.cells} cells), "
        f"QD-score {float(stats.qd_score):.3f} (sum of the elites' objectives; objective: "
        f"{_objective_text(s.kind)}).",
    ]
    if where is not None:
        lines.append(f"- `--where {where.text}`: {len(met)} distinct elites meet it.")
    lines += ["", *(f"![{p.stem}]({p.name})" for p in images), ""]
    if met:
        lines += [
            "## Elites meeting --where",
            "",
            "| file | " + " | ".join(names) + " |",
            "|---" * (len(names) + 1) + "|",
        ]
        lines += [f"| {r['file']} | " + " | ".join(f"{float(r[n]):.4g}" for n in names) + " |" for r in met]
    path = folder / "report.md"
    with atomic_file(path, "w") as stream:
        stream.write("\n".join(lines) + "\n")
    return path


def _objective_text(kind: str) -> str:
    doc = kinds.get(kind).objective.__doc__ or ""
    return doc.strip().rstrip(".") or "the kind's"


def write_all(folder: Path, state: State, where: Predicate | None, maps: bool = True) -> Path:
    """Every output of a finished (or stopped) search; the report's path."""
    rows = _rows(state, where)
    if maps:
        write_elites(folder, rows, state.settings.kind)
    write_csv(folder, rows, tuple(state.settings.metrics))
    return report(folder, state, where, rows, heatmaps(folder, state))
