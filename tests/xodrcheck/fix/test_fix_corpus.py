"""Acceptance of ``xodrcheck fix`` on the 128 third-party corpus files: every finding a repair claims is gone and no
finding is new (judged from outside the fix loop), safe fixes move no lane centre and unsafe ones no more than they
say, a second run changes nothing, and the safe fixes remove at least 60 % of the corpus' errors."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import pytest

from tests.conftest import corpus_files
from tests.xodrcheck.fix.acceptance import Judged, bound, judge, within
from xodrcheck.check import check
from xodrcheck.fix.result import FixResult, fix

pytestmark = pytest.mark.slow  # part of the full suite (CI); left out by -m "not slow"

#: Files whose unsafe fixes are judged too: tiny plan-view elements (CARLA), dangling road and lane links, small gaps
#: (junction_m2a).
UNSAFE = ("Town02.xodr", "Town07.xodr", "stationary_objects.xodr", "junction_ma_2.xodr", "junction_m2a.xodr")


def _run(path: Path, unsafe: bool) -> tuple[FixResult, Judged, bool]:
    before = check(path)
    result = fix(path, unsafe=unsafe)
    return result, judge(before, result), fix(result.data, unsafe=unsafe).data == result.data


@pytest.fixture(scope="module")
def safe(corpus_dir) -> dict[str, tuple[FixResult, Judged, bool]]:
    return {str(p.relative_to(corpus_dir)): _run(p, False) for p in corpus_files()}


def test_claimed_findings_are_gone_and_none_is_new(safe):
    bad = {name: (j.new[:2], j.still_there[:2]) for name, (_, j, _) in safe.items() if j.new or j.still_there}
    assert bad == {}
    assert sum(1 for r, _, _ in safe.values() if r.changed) >= 100


def test_safe_fixes_move_no_lane_centre_and_are_idempotent(safe):
    assert {name: j.moved for name, (_, j, _) in safe.items() if j.moved != 0.0} == {}
    assert [name for name, (_, _, twice) in safe.items() if not twice] == []
    assert all(a.fixer.safe for r, _, _ in safe.values() for a in r.applied)


def test_safe_fixes_remove_at_least_60_percent_of_the_errors(safe):
    before = sum((j.errors_before for _, j, _ in safe.values()), Counter())
    after = sum((j.errors_after for _, j, _ in safe.values()), Counter())
    assert not [code for code in after if after[code] > before[code]]
    assert sum(before.values()) - sum(after.values()) >= 0.6 * sum(before.values()), (before, after)


@pytest.mark.parametrize("name", UNSAFE)
def test_unsafe_fixes_move_lanes_no_more_than_they_say(corpus_dir, name):
    (path,) = [p for p in corpus_files() if p.name == name]
    result, judged, twice = _run(path, True)
    assert result.applied and any(not a.fixer.safe for a in result.applied)
    assert not judged.new and not judged.still_there and twice
    assert within(judged.moved, bound(result)), (judged.moved, bound(result))
    assert sum(judged.errors_after.values()) <= sum(judged.errors_before.values())
