"""Rule surface-hides-road-crg: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check

RULE = "surface-hides-road-crg"


def test_object_hiding_a_genuine_road_crg():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, 'hideRoadSurfaceCRG="true"') and "mode genuine" in f.message


def test_an_attached_road_crg_may_be_hidden():
    text = fixture(RULE, "fail.xodr").read_text(encoding="utf-8").replace('mode="genuine"', 'mode="attached"')
    assert [f for f in check(text.encode(), select=("B055",)).findings if f.code == "B055"] == []


def test_a_road_crg_elsewhere_along_the_road_is_not_hidden():
    text = (
        fixture(RULE, "fail.xodr")
        .read_text(encoding="utf-8")
        .replace('sStart="0" sEnd="100"', 'sStart="60" sEnd="100"')
    )
    assert [f for f in check(text.encode(), select=("B055",)).findings if f.code == "B055"] == []
