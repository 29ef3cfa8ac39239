"""Prove that a speed-up changed nothing: record, then compare, every observable result.

``record DIR`` writes into DIR: the JSON report of ``xodrcheck check`` for every corpus file (one file each, time
budget off so nothing depends on the machine's speed), a few generated maps (their bytes' SHA-256 and their JSON
reports) and SHA-256 hashes of the lane-mesh arrays of a few towns at two chord tolerances. ``compare A B`` says
which of them differ. Not a test: a tool to run before and after a change.

    python benchmarks/identity.py record /tmp/before [--corpus DIR] [--quick]
    python benchmarks/identity.py compare /tmp/before /tmp/after
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
MAPS = (("1000x1000", 1), ("1000x1000", 2), ("1000x1000", 3), ("2000x2000", 4))
TOWNS = ("Town01", "Town04", "Town07")
CHORDS = (0.1, 0.01)


def _report_json(path: Path) -> str:
    from xodrcheck.check import check
    from xodrcheck.config import Config, Tolerances
    from xodrcheck.report import render

    config = Config(tolerances=Tolerances(time_budget=1e9))
    return render("json", [check(path, config)])


def _mesh_hash(path: Path, chord: float) -> str:
    from xodrcheck.mesh.surfaces import build_surfaces
    from xodrcheck.reader import read

    surfaces = build_surfaces(read(path).document, chord=chord)
    digest = hashlib.sha256()
    for name in ("vertices", "faces", "face_lane", "face_s", "lane_vertices", "lane_faces"):
        array = getattr(surfaces, name)
        digest.update(f"{name}{array.dtype}{array.shape}".encode())
        digest.update(array.tobytes())
    digest.update(repr((surfaces.lanes, surfaces.lane_types)).encode())
    return digest.hexdigest()


def record(out: Path, corpus: Path, quick: bool) -> None:
    out.mkdir(parents=True, exist_ok=True)
    files = sorted(corpus.rglob("*.xodr"))
    if quick:
        files = files[::8]
    for i, path in enumerate(files):
        name = str(path.relative_to(corpus)).replace("/", "__")
        (out / f"check__{name}.json").write_text(_report_json(path))
        print(f"[{i + 1}/{len(files)}] {name}", file=sys.stderr)
    import junctionart

    with tempfile.TemporaryDirectory() as tmp:
        for size, seed in MAPS[:2] if quick else MAPS:
            width, height = (float(v) for v in size.split("x"))
            path = Path(tmp) / f"gen_{size}_{seed}.xodr"
            junctionart.write(junctionart.generate(junctionart.Params(width=width, height=height), seed=seed), path)
            (out / f"map__{path.stem}.sha256").write_text(hashlib.sha256(path.read_bytes()).hexdigest() + "\n")
            report = _report_json(path).replace(str(path), path.name)
            (out / f"check__{path.stem}.json").write_text(report)
            print(f"map {path.stem}", file=sys.stderr)
    towns = {p.stem: p for p in corpus.rglob("Town*.xodr")}
    for town in TOWNS:
        for chord in CHORDS:
            (out / f"mesh__{town}_{chord}.sha256").write_text(_mesh_hash(towns[town], chord) + "\n")
            print(f"mesh {town} {chord}", file=sys.stderr)


def compare(a: Path, b: Path) -> int:
    names = sorted({p.name for p in a.iterdir()} | {p.name for p in b.iterdir()})
    bad = 0
    for name in names:
        pa, pb = a / name, b / name
        if not pa.exists() or not pb.exists():
            print(f"only in {'B' if not pa.exists() else 'A'}: {name}")
            continue  # a quick record holds a subset
        if pa.read_bytes() != pb.read_bytes():
            bad += 1
            if name.endswith(".json"):
                fa, fb = (json.loads(p.read_text()) for p in (pa, pb))
                print(f"DIFFERS: {name}: {_json_diff(fa, fb)}")
            else:
                print(f"DIFFERS: {name}")
    common = sum(1 for n in names if (a / n).exists() and (b / n).exists())
    print(f"{common} results compared, {bad} differ")
    return 1 if bad else 0


def _json_diff(fa: object, fb: object) -> str:
    if isinstance(fa, dict) and isinstance(fb, dict):
        keys = [k for k in fa.keys() | fb.keys() if fa.get(k) != fb.get(k)]
        return ", ".join(f"{k}: {str(fa.get(k))[:200]} != {str(fb.get(k))[:200]}" for k in keys)
    return f"{str(fa)[:300]} != {str(fb)[:300]}"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    rec = sub.add_parser("record")
    rec.add_argument("out", type=Path)
    rec.add_argument("--corpus", type=Path, default=Path(os.environ.get("XODR_CORPUS", REPO.parent / "shared/corpus")))
    rec.add_argument("--quick", action="store_true", help="every 8th corpus file, two maps")
    cmp = sub.add_parser("compare")
    cmp.add_argument("a", type=Path)
    cmp.add_argument("b", type=Path)
    args = parser.parse_args()
    if args.command == "record":
        record(args.out, args.corpus, args.quick)
        return 0
    return compare(args.a, args.b)


if __name__ == "__main__":
    sys.exit(main())
