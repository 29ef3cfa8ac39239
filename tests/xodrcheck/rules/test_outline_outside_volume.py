"""Rule outline-outside-volume: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check

RULE = "outline-outside-volume"


def test_road_corner_past_the_box():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, '<cornerRoad s="36"') and "lies 1 m outside" in f.message
    assert (f.x, f.y) == pytest.approx((36.0, 3.5)), "placed by the road's reference line"


def test_corner_taller_than_the_box():
    path = fixture(RULE, "fail_height.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, 'height="0.5"') and "lies 0.35 m outside" in f.message
    assert "z=0.000 to 0.500" in f.message


def test_the_box_turns_with_the_object():
    """The arrow of the pass fixture lies along u; turned by a quarter turn more, its tip leaves the 0.552 m width."""
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8")
    turned = text.replace(
        'hdg="3.141592653589793" length="7.373" width="0.552"', 'hdg="0" length="0.552" width="7.373"'
    )
    found = [f for f in check(turned.encode(), select=("B018",)).findings if f.code == "B018"]
    assert len(found) == 1 and "object 5" in found[0].message and "box of length 0.552 m" in found[0].message
