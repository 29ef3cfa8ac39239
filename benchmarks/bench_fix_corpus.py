"""What the safe fixes remove on the corpus: errors per rule code before and after ``xodrcheck.fix`` (issue 29).

    nice python benchmarks/bench_fix_corpus.py [CORPUS_DIR]   # default $XODR_CORPUS or ../shared/corpus; a few minutes

Prints, per code, the errors under the default profile before and after the safe fixes and the share removed, and on
stderr every file whose fixed version has a finding code the original did not.
"""

from __future__ import annotations

import collections
import os
import sys
from pathlib import Path

import xodrcheck
from xodrcheck.check import check
from xodrcheck.findings import Severity

REPO = Path(__file__).resolve().parents[1]


def main(argv: list[str]) -> int:
    default = Path(os.environ.get("XODR_CORPUS", REPO.parent / "shared" / "corpus"))
    root = Path(argv[0]) if argv else default
    before: collections.Counter[str] = collections.Counter()
    after: collections.Counter[str] = collections.Counter()
    files = sorted(root.rglob("*.xodr"))
    for path in files:
        result = xodrcheck.fix(path)
        original = check(result.original)
        before.update(f.code for f in original.findings if f.severity >= Severity.ERROR)
        after.update(f.code for f in result.report.findings if f.severity >= Severity.ERROR)
        new = {f.code for f in result.report.findings} - {f.code for f in original.findings}
        if new:
            print(f"{path}: new finding codes {sorted(new)}", file=sys.stderr)
    total, left = sum(before.values()), sum(after.values())
    print(f"{len(files)} files; errors {total} -> {left} ({100 * (total - left) / max(total, 1):.1f} % fixed)")
    for code, count in before.most_common():
        print(f"{code}\t{count}\t{after[code]}\t{100 * (count - after[code]) / count:.0f} %")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
