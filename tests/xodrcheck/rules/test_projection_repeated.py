"""Rule projection-repeated: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check

RULE = "projection-repeated"


def test_two_geo_references():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "+proj=tmerc") and "2 <geoReference> elements" in f.message


def test_two_projections_in_one_string():
    path = fixture(RULE, "fail_one_string.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, "<geoReference>") and "(+proj=utm, +proj=tmerc)" in f.message


def test_the_rule_applies_from_opendrive_1_9_on():
    text = fixture(RULE, "fail_one_string.xodr").read_text(encoding="utf-8").replace('revMinor="9"', 'revMinor="8"')
    assert [f for f in check(text.encode(), select=("H003",)).findings if f.code == "H003"] == []
