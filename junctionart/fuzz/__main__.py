"""``python -m junctionart.fuzz [--minutes N] [--profile ci|long] [--runs NAME,...] [--slowest DIR]``: fuzz until
time is up.

Every run of :mod:`junctionart.fuzz.campaign` is repeated in rounds, round-robin, until ``--minutes`` have passed
(one round: a
tenth of the run's example budget under the profile, so that no round overruns the time by much); stored failing
examples are replayed first. A run that fails is
reported and left out of the later rounds. Prints the figures at the end (inputs tried per run, generated maps,
damaged documents, failures, time) and exits 1 if any run failed. The ``slow`` run (the slow-input hunt,
:mod:`junctionart.fuzz.hunt`) also prints the slowest documents it checked, and ``--slowest DIR`` writes them there.
"""

from __future__ import annotations

import argparse
import sys
import time
import warnings
from pathlib import Path

from hypothesis import settings

from junctionart.fuzz import campaign, profiles
from junctionart.fuzz import properties as P

#: A round runs this fraction of each run's example budget.
ROUND_PARTS = 10


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="python -m junctionart.fuzz", description=__doc__.split("\n\n")[0])
    parser.add_argument("--minutes", type=float, default=10.0, help="wall-clock time to fuzz for (default 10)")
    parser.add_argument(
        "--profile",
        choices=profiles.PROFILES,
        default="long",
        help="Hypothesis profile: round sizes and shrinking (default long)",
    )
    parser.add_argument(
        "--runs", default=",".join(campaign.RUNS), help=f"comma-separated runs (default all: {','.join(campaign.RUNS)})"
    )
    parser.add_argument(
        "--slowest", type=Path, metavar="DIR", help="write the 20 slowest documents of the slow run to DIR (.xodr)"
    )
    return parser


def _report_slowest(directory: Path | None) -> None:
    """The slow run's slowest documents: printed, and written to ``directory`` when given."""
    from junctionart.fuzz import hunt

    if not hunt.SLOWEST:
        return
    print(
        f"slowest documents of the slow run ({len(hunt.SLOWEST)} kept; under {hunt.LARGE // 1024} kB and over "
        f"{hunt.SLOW_SECONDS:g} s of CPU: {P.STATS['slow']}):"
    )
    for cpu, digest, _, cost in sorted(hunt.SLOWEST, reverse=True)[:10]:
        print(f"  {cpu:7.2f} s CPU  {cost.per_kb:7.3f} s/kB  {cost.size:9,d} B  {digest}")
    if directory is not None:
        written = hunt.save_slowest(directory)
        print(f"{len(written)} written to {directory}")


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    names = [n.strip() for n in args.runs.split(",") if n.strip()]
    unknown = [n for n in names if n not in campaign.RUNS]
    if unknown or not names:
        print(
            f"python -m junctionart.fuzz: unknown run {unknown[0] if unknown else '(none)'}; "
            f"runs: {', '.join(campaign.RUNS)}",
            file=sys.stderr,
        )
        return 2
    if not args.minutes > 0:
        print("python -m junctionart.fuzz: --minutes must be positive", file=sys.stderr)
        return 2
    # damaged files overflow numpy on purpose (1e308, NaN); the checker turns that into findings
    warnings.simplefilter("ignore", RuntimeWarning)
    started = time.monotonic()
    deadline = started + 60.0 * args.minutes
    failed: dict[str, str] = {}
    rounds = 0
    while time.monotonic() < deadline and len(failed) < len(names):
        for name in names:
            if name in failed or time.monotonic() >= deadline:
                continue
            budget = profiles.budget(campaign.RUNS[name].budget, args.profile)
            config = settings(budget, max_examples=max(1, budget.max_examples // ROUND_PARTS))
            try:
                campaign.hypothesis_test(name, config)()
            except Exception as exc:
                failed[name] = f"{type(exc).__name__}: {exc}"
                print(f"FAILED {name}: {failed[name]}", flush=True)
                for note in getattr(exc, "__notes__", ()):  # Hypothesis's falsifying example and how to replay it
                    print(note, flush=True)
        rounds += 1
        print(
            f"round {rounds}: {sum(campaign.TRIED.values())} inputs in {time.monotonic() - started:.0f} s", flush=True
        )
    elapsed = time.monotonic() - started
    if "slow" in names:
        _report_slowest(args.slowest)
    print(f"\nprofile {args.profile}, {elapsed / 60.0:.1f} min, {rounds} round(s)")
    for name in names:
        status = "FAILED" if name in failed else "ok"
        print(f"  {name:15} {campaign.TRIED[name]:8d} inputs  {status}  ({campaign.RUNS[name].doc})")
    print(
        f"inputs tried: {sum(campaign.TRIED.values())}; generated maps: {P.STATS['maps']}; "
        f"damaged documents: {P.STATS['damaged']}; failures: {len(failed)}; "
        f"known faults tolerated: {P.STATS['tolerated']}; time: {elapsed:.0f} s"
    )
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
