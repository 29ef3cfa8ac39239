"""Checker speed over the whole corpus: ``check`` of every file, all rules, then one rule family at a time.

Prints the total time of checking every ``.xodr`` of the corpus with all rules, then for each rule family (category)
the time of checking every file with only that family selected (the file is read again each time, so each family's
figure includes reading), the slowest files of the full run, and the full run's limit (60 s) beside it.
``--dump FILE`` pickles every file's findings (code, road, lane, s, message) so that two versions can be compared.
``--without CODES`` (comma-separated codes, UIDs or patterns, as ``--ignore``) times every file with all rules and
without those, alternately file by file in one run, and prints the ratio: the share of those rules in the total (the
rulebook's budget: all of Annex F's new rules together at most +25 %). The rules the rulebook work added are listed by
``--without rulebook`` (every rule registered since the rulebook's infrastructure, commit 8378eb9, minus the engine's
X codes: a superset of the Annex F rules, so the figure is an upper bound).

    python benchmarks/bench_check_corpus.py [--corpus DIR] [--families] [--dump FILE] [--without CODES|rulebook]
"""

from __future__ import annotations

import argparse
import os
import pickle
import time
from pathlib import Path

from xodrcheck.check import check
from xodrcheck.findings import Category
from xodrcheck.rules import load_rules

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


#: Codes registered when the rulebook's infrastructure landed (commit 8378eb9); every other check rule came with or
#: after the Annex F work.
_BEFORE = (
    "C001 C002 C003 G001 G002 G003 G004 G005 G006 G007 G010 G011 G012 G013 G901 J001 J002 J003 J004 J005 J006 J007 "
    "J008 J101 J102 K001 K002 K003 K101 K102 K103 L001 L002 L003 L010 L011 L012 L013 L014 L015 L016 L101 O001 O002 "
    "O003 O004 R001 R002 R003 R004 R010 R011 R012 R013 R014 R015 S001 S002"
)
BEFORE_RULEBOOK = frozenset(_BEFORE.split())


def rulebook_codes() -> tuple[str, ...]:
    return tuple(sorted(code for code in load_rules() if code not in BEFORE_RULEBOOK and not code.startswith("X")))


def share(files: list[Path], without: tuple[str, ...]) -> None:
    """CPU time of each file with all rules and without ``without``, alternately (the same machine state for both;
    CPU seconds of this process, which the other work of a busy machine disturbs far less than wall time).

    The rules are taken out of the registry for the second run rather than ignored: ``--ignore`` with a hundred
    selectors matches each of them against every finding, a cost of its own that would hide the rules' share."""
    import importlib

    checking = importlib.import_module("xodrcheck.check")  # the package exports the function check under that name

    every = checking.load_rules()
    fewer = {code: r for code, r in every.items() if not any(checking._rule_matches(t, r) for t in without)}
    full = less = 0.0
    for k, path in enumerate(files):
        for rules in (every, fewer) if k % 2 else (fewer, every):
            checking.load_rules = lambda rules=rules: rules  # type: ignore[assignment]
            start = time.process_time()
            check(path)
            elapsed = time.process_time() - start
            if rules is every:
                full += elapsed
            else:
                less += elapsed
    checking.load_rules = load_rules  # type: ignore[assignment]
    print(
        f"{len(files)} files, CPU: all {len(every)} rules {full:.1f} s, without {len(every) - len(fewer)} of them "
        f"{less:.1f} s: those add {100 * (full / less - 1):+.1f} % (ratio {full / less:.3f}, one run)"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    default = Path(os.environ.get("XODR_CORPUS", REPO.parent / "shared" / "corpus"))
    parser.add_argument("--corpus", type=Path, default=default)
    parser.add_argument("--families", action="store_true", help="also time each rule family alone")
    parser.add_argument("--dump", type=Path, help="pickle the findings of the full run here")
    parser.add_argument("--without", help="codes to time the share of ('rulebook': the rules added for Annex F)")
    args = parser.parse_args()
    files = sorted(args.corpus.rglob("*.xodr"))
    if not files:
        raise SystemExit(f"no .xodr files under {args.corpus}")
    check(files[0])  # imports and schema caches warm before timing
    if args.without:
        codes = rulebook_codes() if args.without == "rulebook" else tuple(args.without.split(","))
        share(files, codes)
        return
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
