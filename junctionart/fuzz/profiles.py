"""Hypothesis profiles: ``ci`` (bounded, run by the test suite) and ``long`` (for hours on a workstation).

Failing examples of the ``long`` profile are stored in :data:`DATABASE_DIR` (inside the repository, committed) and
replayed first on the next run of ``python -m junctionart.fuzz`` (:mod:`junctionart.fuzz.campaign`). Hypothesis deletes
an entry there as soon as it no longer fails, and neither profile runs the ``target`` phase (whose pareto fronts would
be stored too), so the directory holds only open failures and stays small. Failures that were fixed are kept as explicit
regressions in :data:`REGRESSIONS`. The profile is chosen with ``$XODR_FUZZ_PROFILE`` (default ``ci``). ``ci`` is
derandomized: every CI run draws the same examples (seeded from each test), so a CI result is reproducible and a red
build always means a change broke something, never that the search got lucky; exploring is the ``long`` profile's job,
whose failures land in the database and, once understood, in :data:`REGRESSIONS`, which both profiles replay explicitly.
``ci`` does not shrink: a failure is reported with the example as found, within the time budget (shrinking one generated
map took minutes). ``long`` shrinks, to report a small example after hours of search.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

from hypothesis import HealthCheck, Phase, settings
from hypothesis.database import DirectoryBasedExampleDatabase

__all__ = [
    "BUDGETS",
    "DATABASE_DIR",
    "PROFILES",
    "REGRESSIONS",
    "budget",
    "current",
    "database",
    "regressions",
    "tolerated",
]


DATABASE_DIR = Path(__file__).resolve().parent / ".examples"
REGRESSIONS = Path(__file__).resolve().parent / "regressions.json"
PROFILES = ("ci", "long")

#: Examples per property and profile. ``ci`` exceeds the acceptance budget (>= 200 generated maps and >= 2,000
#: damaged documents per run) and keeps the whole of ``tests/fuzz`` to about four minutes on two shared cores
#: (measured: a generated map of the ``maps`` run costs ~0.13 s to generate and check on average, a damaged document
#: ~0.04 s); ``faults`` bounds the search of the fault-injection tests, which find their fault within a few examples.
#: ``long`` sizes the rounds of ``python -m junctionart.fuzz --profile long``, which repeats them until its time is up.
BUDGETS: dict[str, dict[str, int]] = {
    "ci": {
        "maps": 500,
        "damaged": 3000,
        "documents": 200,
        "defects": 280,
        "metamorphic": 60,
        "invalid": 200,
        "round-trip": 100,
        "faults": 30,
        "slow": 20,
    },
    "long": {
        "maps": 200,
        "damaged": 2000,
        "documents": 200,
        "defects": 500,
        "metamorphic": 100,
        "invalid": 500,
        "round-trip": 100,
        "faults": 200,
        "slow": 600,
    },
}

_COMMON: dict[str, Any] = {
    "deadline": None,
    "suppress_health_check": [
        HealthCheck.too_slow,
        HealthCheck.data_too_large,
        HealthCheck.filter_too_much,
        HealthCheck.function_scoped_fixture,
    ],
    "print_blob": True,
}


def database() -> DirectoryBasedExampleDatabase:
    return DirectoryBasedExampleDatabase(str(DATABASE_DIR))


settings.register_profile("ci", database=None, derandomize=True, phases=(Phase.explicit, Phase.generate), **_COMMON)
settings.register_profile(
    "long", database=database(), phases=(Phase.explicit, Phase.reuse, Phase.generate, Phase.shrink), **_COMMON
)


def current() -> str:
    """The profile named by ``$XODR_FUZZ_PROFILE`` (``ci`` by default)."""
    name = os.environ.get("XODR_FUZZ_PROFILE", "ci")
    if name not in PROFILES:
        raise ValueError(f"XODR_FUZZ_PROFILE={name!r}: must be one of {', '.join(PROFILES)}")
    return name


def budget(prop: str, profile: str | None = None) -> settings:
    """Settings for one property under a profile: its example budget on top of the profile."""
    name = profile or current()
    return settings(settings.get_profile(name), max_examples=BUDGETS[name][prop])


def regressions() -> list[dict]:
    """The explicit regression entries (replayed before any new example)."""
    if not REGRESSIONS.is_file():
        return []
    return json.loads(REGRESSIONS.read_text(encoding="utf-8"))["regressions"]


def tolerated(prop: str) -> frozenset[str]:
    """What the open known faults of property ``prop`` (``known_fault`` entries of :data:`REGRESSIONS`) let pass:
    finding codes for ``generated-map``, substrings of a rule's crash message for ``damaged``. The property counts
    them in ``STATS["tolerated"]`` instead of failing, while the entry's own regression test tracks the fault (and
    fails as soon as it is fixed, so that the tolerance goes with it)."""
    return frozenset(
        t for e in regressions() if e.get("known_fault") and e["property"] == prop for t in e.get("tolerate", ())
    )
