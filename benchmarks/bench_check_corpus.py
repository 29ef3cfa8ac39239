"""Checker speed over the whole corpus: ``check`` of every file, all rules, then one rule family at a time.

Prints the total time of checking every ``.xodr`` of the corpus with all rules, then for each rule family (category)
the time of checking every file with only that family selected (the file is read again each time, so each family's
figure includes reading), the slowest files of the full run, and the full run's limit (60 s) beside it.
``--dump FILE`` pickles every file's findings (code, road, lane, s, message) so that two versions can be compared.

    python benchmarks/bench_check_corpus.py [--corpus DIR] [--families] [--dump FILE]
"""

from __future__ import annotations

import argparse
import os
import pickle
import time
from pathlib import Path

from xodrcheck.check import check
from xodrcheck.findings import Category

REPO = Path(__file__).resolve().parents[1]
LIMIT_S = 60.0


def run_all(files: list[Path], select: tuple[str, ...] = ()) -> tuple[float, dict[str, float], dict[str, list]]:
    times: dict[str, float] = {}
    findings: dict[str, list] = {}
    for path in files:
        start = time.perf_counter()
        report = check(path, select=select)
        times[str(path)] = time.perf_counter() - start
        findings[str(path)] = [(f.code, f.road, f.lane, f.s, f.message) for f in report.findings]
    return sum(times.values()), times, findings


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    default = Path(os.environ.get("XODR_CORPUS", REPO.parent / "shared" / "corpus"))
    parser.add_argument("--corpus", type=Path, default=default)
    parser.add_argument("--families", action="store_true", help="also time each rule family alone")
    parser.add_argument("--dump", type=Path, help="pickle the findings of the full run here")
    args = parser.parse_args()
    files = sorted(args.corpus.rglob("*.xodr"))
    if not files:
        raise SystemExit(f"no .xodr files under {args.corpus}")
    check(files[0])  # imports and schema caches warm before timing
    total, times, findings = run_all(files)
    print(f"{len(files)} files, all rules: {total:.1f} s (limit {LIMIT_S:g} s)")
    for path, t in sorted(times.items(), key=lambda item: -item[1])[:5]:
        print(f"    {t:6.2f} s  {Path(path).relative_to(args.corpus)}")
    if args.dump:
        with args.dump.open("wb") as out:
            pickle.dump(findings, out)
    if args.families:
        for family in Category:
            family_total, _, _ = run_all(files, select=(family.value,))
            print(f"  {family.value:<10} {family_total:6.1f} s")


if __name__ == "__main__":
    main()
