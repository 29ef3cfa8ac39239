"""Rule link-attribute-usage: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.check import check
from xodrcheck.config import Config
from xodrcheck.findings import Basis, Severity
from xodrcheck.rules.shared import road_uids as U

RULE = "link-attribute-usage"


def test_junction_linked_without_its_element_type():
    path = fixture(RULE, "fail_junction.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.rule_uid, f.severity) == ("1", U.LINKAGE_JUNCTION_ATTRIBUTES, Severity.ERROR)
    assert f.line == line_of(path, '<successor elementId="100"')
    assert 'junction 100 is linked with elementType="junction"' in f.message


def test_junction_linked_with_a_contact_point_is_a_plausibility_warning():
    """The UID asks for elementType and elementId and forbids nothing more: a contact point on a junction link means
    nothing, a warning by default, an error under the generator profile."""
    path = fixture(RULE, "fail_junction_contact_point.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.rule_uid, f.basis, f.severity) == ("1", None, Basis.PLAUSIBILITY, Severity.WARNING)
    assert f.line == line_of(path, '<successor elementType="junction"')
    assert "default junction with contactPoint" in f.message
    (g,) = [g for g in check(path, Config(profile="generator")).findings if g.code == "K004"]
    assert g.severity is Severity.ERROR


def test_road_linked_without_element_type():
    path = fixture(RULE, "fail_road.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.rule_uid) == ("10", U.LINKAGE_ROAD_ATTRIBUTES)
    assert f.line == line_of(path, '<predecessor elementId="1"')


def test_element_s_without_element_dir():
    path = fixture(RULE, "fail_virtual.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.rule_uid) == ("2", U.LINKAGE_VIRTUAL_ATTRIBUTES)
    assert "has elementS but no elementDir" in f.message


def test_virtual_junction_road_joining_its_main_road_at_a_contact_point():
    path = fixture(RULE, "fail_virtual_main_road.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.rule_uid) == ("2", U.LINKAGE_VIRTUAL_ATTRIBUTES)
    assert "main road of virtual junction 555" in f.message


def test_a_file_older_than_1_7_is_held_to_the_road_link_rule_only():
    """The junction and virtual-junction attribute rules apply from OpenDRIVE 1.7 on."""
    for name in ("fail_junction.xodr", "fail_junction_contact_point.xodr"):
        text = fixture(RULE, name).read_text(encoding="utf-8").replace('revMinor="7"', 'revMinor="6"')
        report = check(text.encode(), select=("K004",))
        assert [f for f in report.findings if f.code == "K004"] == []
