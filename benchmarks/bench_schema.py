"""OpenDRIVE 1.8 and 1.9 schema validation of valid files: the fast verdict (``xodrcheck.schema.fast``: lxml on the
XSD 1.0 part, alternatives made explicit, assertions one by one) against xmlschema's XSD 1.1 validator, as ratios
measured in one run on generated maps (random lanes, 500 m to 2 km, written as 1.8 and as 1.9).

    python benchmarks/bench_schema.py [--repeats 3] [--versions 1.8,1.9]

Target: the fast verdict in at most a quarter of xmlschema's time on maps of 1 km and more, for each version.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

from lxml import etree

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import junctionart as ja
from xodrcheck.schema import fast as schema_fast
from xodrcheck.schema import validate as schema

SIZES = (500, 1000, 2000)


def _median_time(fn, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--versions", default="1.8,1.9", help="OpenDRIVE versions written and validated")
    args = ap.parse_args(argv)
    documents = {size: ja.generate(ja.Params(width=size, height=size, randomize_lanes=True), 3) for size in SIZES}
    print(f"{'map':26} {'size kB':>8} {'xmlschema s':>12} {'fast s':>8} {'ratio':>6}  target <= 0.25")
    worst = 0.0
    for name in args.versions.split(","):
        version = (1, int(name.split(".")[1]))
        full = schema.compiled(version)
        folder, main_file = schema.SCHEMA_FOLDERS[version]
        schema_fast.derived(folder, main_file)  # compiled once per process, as in any run
        schema_fast.plan(folder)
        for size, document in documents.items():
            data = ja.to_bytes(document, name)
            tree = etree.ElementTree(etree.fromstring(data, etree.XMLParser(resolve_entities=False, no_network=True)))
            assert schema_fast.is_valid(tree, folder, main_file), "a generated map must take the fast path"
            slow = _median_time(lambda t=tree, f=full: list(f.iter_errors(t)), args.repeats)
            fast = _median_time(lambda t=tree, d=folder, m=main_file: schema_fast.is_valid(t, d, m), args.repeats)
            ratio = fast / slow
            if size >= 1000:
                worst = max(worst, ratio)
            label = f"{name}: {size} m random lanes"
            print(f"{label:26} {len(data) // 1000:8d} {slow:12.3f} {fast:8.3f} {ratio:6.2f}")
    print(f"worst ratio at 1 km and more: {worst:.2f} ({'met' if worst <= 0.25 else 'MISSED'})")
    return 0 if worst <= 0.25 else 1


if __name__ == "__main__":
    sys.exit(main())
