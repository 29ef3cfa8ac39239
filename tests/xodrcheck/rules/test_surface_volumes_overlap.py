"""Rule surface-volumes-overlap: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "surface-volumes-overlap"


def test_two_patches_half_a_metre_apart():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, 'id="p1"') and "road 1 object p2" in f.message and "by 0.24 m2" in f.message
    assert (f.x, f.y) == pytest.approx((50.25, -1.75)), "inside the shared area"


def test_instances_of_one_repeat():
    (f,) = findings(fixture(RULE, "fail_repeat.xodr"), RULE)
    assert "another instance of it (at s=20.5)" in f.message


def _repeated(length: str, distance: str) -> bytes:
    text = fixture(RULE, "fail_repeat.xodr").read_text(encoding="utf-8")
    repeat = '<repeat s="20" length="1" distance="0.5"'
    assert repeat in text
    return text.replace(repeat, f'<repeat s="20" length="{length}" distance="{distance}"').encode()


def test_piled_up_instances_are_thinned_and_still_overlap():
    """10 000 instances 1 mm apart (a typo for 1 m): a few dozen boxes, not 10^8 pairs, and the overlap is found."""
    from xodrcheck.check import check
    from xodrcheck.reader import read
    from xodrcheck.rules.object_surfaces import surface_boxes
    from xodrcheck.rules.shared.context import Context

    data = _repeated("10", "0.001")
    found = [f for f in check(data, select=("B",)).findings if f.code in ("B053", "X900", "X901")]
    assert [f.code for f in found] == ["B053"] and "another instance of it" in found[0].message
    ctx = Context(read(data).document, data=data)
    boxes = surface_boxes(ctx)
    assert 2 <= len(boxes) <= 100, len(boxes)
    assert boxes[0].instance.s == 20 and boxes[-1].instance.s == pytest.approx(30, abs=0.01)


def test_a_repeat_of_overflowing_count_does_not_crash():
    """length 1e308 over distance 1e-300 is an infinite count: capped, never an OverflowError."""
    from xodrcheck.check import check

    codes = {f.code for f in check(_repeated("1e308", "1e-300"), select=("B",)).findings}
    assert "X900" not in codes and "B053" in codes
