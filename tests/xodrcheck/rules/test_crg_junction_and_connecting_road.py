"""Rule crg-junction-and-connecting-road (U002): the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "crg-junction-and-connecting-road"


def test_connecting_road_with_its_own_crg():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.road == "10" and f.line == line_of(path, 'file="road10.crg"')
    junction_crg = line_of(path, 'file="junction.crg"')
    assert f"junction 100, whose own <CRG> (line {junction_crg})" in f.message
