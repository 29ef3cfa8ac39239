"""xodrcheck against ASAM's ``asam-qc-opendrive`` on the same files: findings side by side, and time per file.

    python benchmarks/bench_asam.py [--venv .venv-asam] [--corpus ../shared/corpus] [files...]

By default: the corpus's OpenDRIVE 1.7 and 1.8 files plus a few 1.4-1.6 ones. The ASAM virtual environment is created
when missing. ASAM's time includes its start-up (it is run the way users run it, once per file); xodrcheck's is an
in-process ``check`` (``xodrcheck check`` on the command line adds its own start-up once per run); with
``--whole-process`` it is ``xodrcheck check FILE`` run as a new process per file too, start-up included, as ASAM's.
Both wall and CPU time (user + system of the child processes; of this process for in-process checks) are shown: on
a busy machine the CPU figures are the fairer comparison. The ``xodrcheck`` children run as on a user's machine:
without ``PYTHONDONTWRITEBYTECODE``, after one untimed run per file has filled xodrcheck's caches (the dataclass
byte code; a compiled XSD 1.1 schema, built only for a 1.8/1.9 file the fast verdict does not show valid).
Each file is checked ``--repeats`` times by each tool (default 3, alternating), and its figures are the medians.
Any ASAM error-level issue without a corresponding xodrcheck finding is printed as MISSED.
"""

from __future__ import annotations

import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import time
from collections import Counter
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from tests.interop.asam_harness import COVERED_BY, covered, run_asam  # noqa: E402 (after the sys.path entry)
from xodrcheck.check import check  # noqa: E402 (after the sys.path entry)

_MINOR = re.compile(rb'revMinor\s*=\s*"(\d+)"')
OLDER = ("Town01.xodr", "fabriksgatan.xodr", "junction_ma.xodr", "highway_merge.xodr")


def _children_cpu() -> float:
    """User + system CPU seconds of the finished child processes so far."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _median(runs: list[tuple[float, float]]) -> tuple[float, float]:
    """The median wall time of ``runs`` (wall, CPU) and the median CPU time."""
    return statistics.median(w for w, _ in runs), statistics.median(c for _, c in runs)


def ensure_venv(venv: Path) -> Path:
    """The ``qc_opendrive`` command of ``venv``, creating the environment (python -m venv + pip) when missing."""
    command = venv / "bin" / "qc_opendrive"
    if not command.exists():
        subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
        subprocess.run([str(venv / "bin" / "pip"), "install", "-q", "asam-qc-opendrive"], check=True)
    return command


def default_files(corpus: Path) -> list[Path]:
    files = []
    for path in sorted(corpus.rglob("*.xodr")):
        match = _MINOR.search(path.read_bytes()[:4096])
        minor = int(match.group(1)) if match else 0
        if minor >= 7 or path.name in OLDER:
            files.append(path)
    return files


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("files", nargs="*", type=Path)
    parser.add_argument("--venv", type=Path, default=REPO / ".venv-asam")
    parser.add_argument("--corpus", type=Path, default=REPO.parent / "shared" / "corpus")
    parser.add_argument("--whole-process", action="store_true", help="time `xodrcheck check FILE` as a new process")
    parser.add_argument(
        "--repeats",
        type=int,
        default=3,
        help="runs of each tool per file, alternating, each file's time their median (default 3: one run of a short "
        "process varies by a quarter on this machine kind)",
    )
    args = parser.parse_args()
    command = ensure_venv(args.venv)
    files = args.files or default_files(args.corpus)
    check(files[0])  # import and warm up once, as one CLI run over many files would
    ours_command = [str(Path(sys.executable).parent / "xodrcheck"), "check"]
    # children run as on a user's machine: byte code and xodrcheck's caches written (not under this machine's
    # PYTHONDONTWRITEBYTECODE), after one untimed whole-process run per file has filled them as any earlier run would
    # (the XSD 1.1 schema is only built, and cached, for a 1.8/1.9 file the fast verdict does not show valid)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    if args.whole_process:
        for path in files:
            subprocess.run([*ours_command, str(path)], env=env, capture_output=True, check=False)
    missed_total, asam_total, ours_total, asam_cpu_total, ours_cpu_total = 0, 0.0, 0.0, 0.0, 0.0
    for path in files:
        asam_runs, ours_runs = [], []
        for _ in range(max(1, args.repeats)):
            started, cpu = time.perf_counter(), _children_cpu()
            issues = run_asam(command, path)
            asam_runs.append((time.perf_counter() - started, _children_cpu() - cpu))
            started, cpu = time.perf_counter(), _children_cpu() + time.process_time()
            if args.whole_process:
                ours = [*ours_command, str(path)]
                subprocess.run(ours, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
            else:
                report = check(path)
            ours_runs.append((time.perf_counter() - started, _children_cpu() + time.process_time() - cpu))
        asam_time, asam_cpu = _median(asam_runs)
        ours_time, ours_cpu = _median(ours_runs)
        if args.whole_process:
            report = check(path)  # for the findings side by side (not timed)
        asam_total += asam_time
        ours_total += ours_time
        asam_cpu_total += asam_cpu
        ours_cpu_total += ours_cpu
        print(
            f"\n== {path.name}  (version {report.version})  ASAM {asam_time:.2f} s (CPU {asam_cpu:.2f})  "
            f"xodrcheck {ours_time:.3f} s (CPU {ours_cpu:.3f})  ratio {asam_time / max(ours_time, 1e-9):.0f}x"
        )
        by_rule = Counter((i.rule, i.level) for i in issues)
        for (rule, level), count in sorted(by_rule.items()):
            codes = sorted(COVERED_BY.get(rule, ()))
            ours = sum(1 for f in report.findings if f.code in codes)
            print(f"   ASAM {rule} (level {level}) x{count}  ->  {', '.join(codes) or '?'}: {ours} finding(s)")
        for issue in issues:
            if issue.is_error and not covered(issue, report.findings):
                missed_total += 1
                print(f"   !!! MISSED: ASAM error {issue.rule} on roads {sorted(issue.roads)}: {issue.description}")
        mine = Counter(f.code for f in report.findings)
        print(f"   xodrcheck: {dict(sorted(mine.items()))}")
    n = len(files)
    print(
        f"\n{n} files: ASAM {asam_total / n:.2f} s/file, xodrcheck {ours_total / n:.3f} s/file, "
        f"xodrcheck is {asam_total / max(ours_total, 1e-9):.1f}x faster (wall; "
        f"CPU: ASAM {asam_cpu_total / n:.2f} s/file, xodrcheck {ours_cpu_total / n:.3f} s/file, "
        f"{asam_cpu_total / max(ours_cpu_total, 1e-9):.1f}x); ASAM error issues missed: {missed_total}"
    )
    return 1 if missed_total else 0


if __name__ == "__main__":
    sys.exit(main())
