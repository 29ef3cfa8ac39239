"""Mesh and overlap-check speed: lane meshes of each CARLA town and the overlap rules on them, and on a generated map.

For each CARLA town of the corpus, prints the CPU time of reading the file and building every lane's mesh at 0.1 m
chord tolerance (geometry evaluated from scratch), beside libOpenDRIVE's 0.11 s CPU for parsing and meshing Town07
on this machine kind (C++; issue 14's target: read + meshes at most 0.3 s CPU), then the time of the overlap rules
(``O``) at the default tolerances, mesh included. When ``junctionart.generate`` exists, does the same for a generated
5 km x 5 km map (target: overlap check at most 10 s); otherwise says why that line is missing. CPU times (this
process) are less sensitive to a busy machine than wall times.

    python benchmarks/bench_mesh.py [--corpus DIR] [--size 5000] [--seed 0]
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time
from pathlib import Path

from xodrcheck.check import check
from xodrcheck.mesh.surfaces import build_surfaces
from xodrcheck.reader import read

REPO = Path(__file__).resolve().parents[1]
LIBOPENDRIVE_TOWN07_S = 0.11
MESH_TARGET_S = 0.3
OVERLAP_TARGET_S = 10.0
CHORD = 0.1


def timed(fn):
    start = time.process_time()
    value = fn()
    return time.process_time() - start, value


def bench_file(path: Path, label: str) -> tuple[float, float]:
    mesh_s, surfaces = timed(lambda: build_surfaces(read(path).document, chord=CHORD))
    overlap_s, report = timed(lambda: check(path, select=("overlap",)))
    print(
        f"{label:<28} read + mesh {mesh_s:6.2f} s ({len(surfaces.faces):>7} faces, {len(surfaces):>5} lane strips)   "
        f"overlap check {overlap_s:6.2f} s ({len(report.findings)} findings)"
    )
    return mesh_s, overlap_s


def generated_map(size: float, seed: int) -> Path | None:
    try:
        import junctionart
    except ImportError as exc:
        print(f"generated {size / 1000:g} km map: skipped, junctionart not importable ({exc})")
        return None
    if not hasattr(junctionart, "generate"):
        print(f"generated {size / 1000:g} km map: skipped, junctionart.generate does not exist yet")
        return None
    params = junctionart.Params(width=size, height=size)
    elapsed, document = timed(lambda: junctionart.generate(params, seed=seed))
    path = Path(tempfile.mkdtemp(prefix="bench_mesh_")) / f"generated_{int(size)}m_seed{seed}.xodr"
    junctionart.write(document, path)
    print(f"generated {size / 1000:g} km x {size / 1000:g} km map (seed {seed}) in {elapsed:.1f} s: {path}")
    return path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    default = Path(os.environ.get("XODR_CORPUS", REPO.parent / "shared" / "corpus"))
    parser.add_argument("--corpus", type=Path, default=default)
    parser.add_argument("--size", type=float, default=5000.0, help="generated map side in metres")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()

    towns = sorted((args.corpus / "carla-towns").rglob("Town*.xodr"))
    if not towns:
        raise SystemExit(f"no CARLA towns under {args.corpus}/carla-towns")
    read(towns[0])  # imports and schema caches warm before timing
    print(f"lane meshes at {CHORD} m chord; overlap rules at the default tolerances (mesh included)")
    times = {path.stem: bench_file(path, path.stem) for path in towns}
    if "Town07" in times:
        mesh_s = times["Town07"][0]
        print(
            f"Town07 read + mesh: {mesh_s:.2f} s CPU vs libOpenDRIVE {LIBOPENDRIVE_TOWN07_S} s = "
            f"{mesh_s / LIBOPENDRIVE_TOWN07_S:.1f}x (target <= {MESH_TARGET_S:.1f} s): "
            f"{'met' if mesh_s <= MESH_TARGET_S else 'NOT met'}"
        )
    path = generated_map(args.size, args.seed)
    if path is not None:
        _, overlap_s = bench_file(path, path.stem)
        print(
            f"generated map overlap check: {overlap_s:.1f} s CPU (target <= {OVERLAP_TARGET_S:g} s): "
            f"{'met' if overlap_s <= OVERLAP_TARGET_S else 'NOT met'}"
        )


if __name__ == "__main__":
    main()
