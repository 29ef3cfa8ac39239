"""Hypothesis profiles: ``ci`` (bounded, run by the test suite) and ``long`` (for hours on a workstation).

Failing examples are stored in :data:`DATABASE_DIR` (inside the repository) and replayed first on the next run;
explicit regressions live in :data:`REGRESSIONS`. The profile is chosen with ``$XODR_FUZZ_PROFILE`` (default ``ci``).
"""

from __future__ import annotations

import json
import os
from pathlib import Path

from hypothesis import HealthCheck, settings
from hypothesis.database import DirectoryBasedExampleDatabase

DATABASE_DIR = Path(__file__).resolve().parent / ".examples"
REGRESSIONS = Path(__file__).resolve().parent / "regressions.json"
PROFILES = ("ci", "long")

#: Examples per property and profile. ``ci`` meets the acceptance budget: >= 200 generated maps and >= 2,000
#: damaged documents per run, in well under 10 minutes on two cores.
BUDGETS: dict[str, dict[str, int]] = {
    "ci": {"maps": 210, "damaged": 2050, "documents": 120, "defects": 280, "metamorphic": 40, "invalid": 150,
           "round-trip": 40, "faults": 60},
    "long": {"maps": 5000, "damaged": 50_000, "documents": 5000, "defects": 10_000, "metamorphic": 2000,
             "invalid": 5000, "round-trip": 2000, "faults": 200},
}

_COMMON = dict(
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.filter_too_much,
                           HealthCheck.function_scoped_fixture],
    print_blob=True,
)


def database() -> DirectoryBasedExampleDatabase:
    return DirectoryBasedExampleDatabase(str(DATABASE_DIR))


settings.register_profile("ci", database=database(), **_COMMON)
settings.register_profile("long", database=database(), **_COMMON)


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


def add_regression(entry: dict) -> None:
    """Append one entry to :data:`REGRESSIONS` (kept sorted by insertion)."""
    data = {"regressions": regressions()}
    data["regressions"].append(entry)
    REGRESSIONS.write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")
