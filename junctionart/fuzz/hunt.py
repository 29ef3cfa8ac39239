"""The slow-input hunt: the checker's cost on hostile documents, which Hypothesis's target phase climbs.

:func:`check_is_bounded` checks one document in this process and measures the CPU seconds it took and the work it
counted (:mod:`xodrcheck.support.work`); it hands Hypothesis the cost per kB and the cost itself
(``hypothesis.target``), so that the search moves toward the worst cases (tiny radii, huge lengths, thousands of records
on one road, dense repeats), and keeps the slowest documents seen (:data:`SLOWEST`). It fails when a document needs more
work of some kind than :data:`WORK_BOUNDS` allows (counted, so the verdict is the same on any machine), or crashes the
checker; how many documents under :data:`LARGE` bytes took more than :data:`SLOW_SECONDS` of CPU is reported beside it.

Run it for a few minutes with ``python -m junctionart.fuzz --runs slow --minutes 10 --slowest DIR`` (the slowest
documents are written to ``DIR``); ``benchmarks/bench_worst_case.py`` measures them again and prints the slowest per
kB. The worst become regression documents (``tests/fuzz/slow``), checked within a fixed work bound.
"""

from __future__ import annotations

import contextlib
import hashlib
import heapq
import time
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

from hypothesis import target

from junctionart.fuzz import properties as P
from junctionart.fuzz.profiles import tolerated
from xodrcheck.findings import ReadError
from xodrcheck.support import work

__all__ = [
    "KEPT",
    "LARGE",
    "SLOWEST",
    "SLOW_SECONDS",
    "WORK_BOUNDS",
    "Cost",
    "check_is_bounded",
    "measure",
    "save_slowest",
]

#: CPU seconds a document under :data:`LARGE` bytes may take to check.
SLOW_SECONDS = 5.0
LARGE = 100 * 1024
#: How many of the slowest documents :data:`SLOWEST` keeps.
KEPT = 40
#: Most work of each kind (:mod:`xodrcheck.support.work`) a check of one hostile document may do: about two lane
#: sections sampled at the sample budget (``max_samples_per_section``, 200,000 samples) with every lane meshed, and
#: bounded GEOS work; about what 5 s of CPU buys here. Kinds not listed may not occur.
WORK_BOUNDS: dict[str, int] = {
    "line points": 10_000_000,
    "mesh vertices": 3_000_000,
    "union coordinates": 1_000_000,
    "overlay coordinates": 4_000_000,
}


@dataclass(frozen=True)
class Cost:
    """What checking one document cost: CPU seconds, its size and the work counted (:mod:`xodrcheck.support.work`)."""

    cpu: float
    size: int
    work: Counter

    @property
    def per_kb(self) -> float:
        return self.cpu / max(self.size / 1024, 1e-3)


#: The slowest documents seen in this process: a heap of (CPU s, digest, document, cost), the least slow first.
SLOWEST: list[tuple[float, str, bytes, Cost]] = []


def _warm() -> None:
    """Check an empty map of every OpenDRIVE version once, so that no document's cost includes compiling a schema or
    importing a module."""
    if not _WARM:
        from junctionart.fuzz.documents import VERSIONS

        for major, minor in VERSIONS:
            P.checked(f'<OpenDRIVE><header revMajor="{major}" revMinor="{minor}"/></OpenDRIVE>'.encode())
        _WARM.append(True)


_WARM: list[bool] = []


def measure(data: bytes) -> Cost:
    """Check ``data`` in this process (asserting the checker did not crash, :func:`fuzz.properties.checked`) and
    measure the cost (after a warm-up: :func:`_warm`)."""
    _warm()
    with work.counting() as done:
        started = time.process_time()
        with contextlib.suppress(ReadError):  # a document the reader refuses costs its reading
            P.checked(data, tolerated=tolerated("damaged"))
        cpu = time.process_time() - started
    return Cost(cpu, len(data), done)


def _keep(data: bytes, cost: Cost) -> None:
    digest = hashlib.sha1(data).hexdigest()[:12]
    if any(d == digest for _, d, _, _ in SLOWEST):
        return
    entry = (cost.cpu, digest, data, cost)
    if len(SLOWEST) < KEPT:
        heapq.heappush(SLOWEST, entry)
    elif cost.cpu > SLOWEST[0][0]:
        heapq.heapreplace(SLOWEST, entry)


def check_is_bounded(data: bytes) -> Cost:
    """The hunt's property: checking ``data`` does at most :data:`WORK_BOUNDS` of work; the cost per kB and the cost
    are Hypothesis's targets, and slow documents are counted in ``STATS["slow"]``."""
    P.STATS["hostile"] += 1
    cost = measure(data)
    target(cost.per_kb, label="CPU s per kB")
    target(cost.cpu, label="CPU s")
    _keep(data, cost)
    if cost.size < LARGE and cost.cpu > SLOW_SECONDS:
        P.STATS["slow"] += 1
    over = {kind: n for kind, n in cost.work.items() if n > WORK_BOUNDS.get(kind, 0)}
    assert not over, f"checking a {cost.size:,}-byte document did more work than {WORK_BOUNDS}: {over}"
    return cost


def save_slowest(directory: Path, count: int = 20) -> list[Path]:
    """Write the ``count`` slowest documents of :data:`SLOWEST` to ``directory`` (named by their content's digest),
    slowest first; returns their paths."""
    directory.mkdir(parents=True, exist_ok=True)
    out = []
    for _, digest, data, _ in sorted(SLOWEST, reverse=True)[:count]:
        path = directory / f"{digest}.xodr"
        path.write_bytes(data)
        out.append(path)
    return out
