"""What the acceptance of ``xodrcheck fix`` measures on a file, judged from outside the fix loop: the findings before
and after compared by rule and place (lines left out: edits move them), and how far lane centres moved."""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass

import numpy as np

from xodrcheck.analysis.sample import sample_lanes
from xodrcheck.check import Report, check
from xodrcheck.findings import Finding, Severity
from xodrcheck.fix.result import FixResult
from xodrcheck.reader import read


def place(f: Finding) -> tuple:
    return (
        f.code,
        f.severity,
        f.road,
        f.lane,
        None if f.section_s is None else round(f.section_s, 6),
        None if f.s is None else round(f.s, 3),
    )


@dataclass(frozen=True)
class Judged:
    """A fix judged: findings of the fixed file not in the original (by rule and place), claimed findings still
    there, errors before and after by code, and the largest move of a lane-centre point (m)."""

    new: tuple[Finding, ...]
    still_there: tuple[Finding, ...]
    errors_before: Counter
    errors_after: Counter
    moved: float


def centre_points(data: bytes, step: float = 2.0) -> dict[tuple, np.ndarray]:
    document = read(data).document
    assert document is not None
    return {
        (line.road, line.section_s, line.lane): np.column_stack([line.s, line.x, line.y])
        for line in sample_lanes(document, step)
    }


def largest_move(before: bytes, after: bytes) -> float:
    """The largest distance between a lane-centre point before and the point of the same lane and ``s`` after (the
    lanes must be the same ones); 0 when the bytes are equal."""
    if before == after:
        return 0.0
    old, new = centre_points(before), centre_points(after)
    assert old.keys() == new.keys(), sorted(set(old) ^ set(new))[:5]
    worst = 0.0
    for key, a in old.items():
        b = new[key]
        assert a.shape == b.shape and np.array_equal(a[:, 0], b[:, 0]), key
        finite = np.isfinite(a[:, 1:]).all(axis=1) & np.isfinite(b[:, 1:]).all(axis=1)
        if finite.any():
            worst = max(worst, float(np.max(np.hypot(*(a[finite, 1:] - b[finite, 1:]).T))))
    return worst


def judge(before: Report, result: FixResult) -> Judged:
    after = check(result.data)
    old, new = Counter(place(f) for f in before.findings), Counter(place(f) for f in after.findings)
    fresh = tuple(f for f in after.findings if new[place(f)] > old[place(f)])
    claimed = Counter(place(f) for a in result.applied for f in a.repair.findings)
    left = tuple(
        f for a in result.applied for f in a.repair.findings if new[place(f)] > old[place(f)] - claimed[place(f)]
    )
    errors = Severity.ERROR
    return Judged(
        fresh,
        left,
        Counter(f.code for f in before.findings if f.severity >= errors),
        Counter(f.code for f in after.findings if f.severity >= errors),
        largest_move(result.original, result.data),
    )


def bound(result: FixResult) -> float:
    """What the repairs applied say they moved, at most (safe ones: nothing)."""
    return max((a.repair.moved for a in result.applied), default=0.0)


def within(moved: float, allowed: float) -> bool:
    """A move within what the repairs stated, give or take rounding of the evaluation (1 nm)."""
    return math.isfinite(moved) and moved <= allowed + 1e-9
