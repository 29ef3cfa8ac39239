"""Each fix on a file damaged in one place: the fix gives back the file as it was, byte for byte (comments, attribute
order, number spellings and layout included), and says what it did; on the rules' own failing fixtures it removes
the rule's findings; a file it cannot fix safely is left alone, with the reason."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.conftest import REPO
from xodrcheck.check import check
from xodrcheck.fix.result import fix

T_JUNCTION = (REPO / "examples" / "t-junction.xodr").read_bytes()
FIXTURES = REPO / "tests" / "xodrcheck" / "rules" / "fixtures"


def damaged(data: bytes, old: bytes, new: bytes) -> bytes:
    assert data.count(old) >= 1, old
    return data.replace(old, new, 1)


def codes(data: bytes) -> list[str]:
    return sorted(f.code for f in check(data).findings)


def test_the_example_is_clean_and_comes_out_byte_identical():
    assert codes(T_JUNCTION) == []
    result = fix(T_JUNCTION)
    assert result.data == T_JUNCTION and not result.changed and not result.applied and result.diff() == ""


ROAD1_LANE1 = b'<lane id="1" type="driving" level="false">\n            <width sOffset="0" a="3.5"'
CONNECTION_0 = b'<connection id="0" incomingRoad="1" connectingRoad="101" contactPoint="start">'
ROAD1_LANE_RIGHT = b'<lane id="-1" type="driving" level="false">\n            <width sOffset="0" a="3.5"'

CENTRE = b'<lane id="0" type="none" level="false">\n            <roadMark'

#: (what is damaged, the bytes replaced, by what, the rule whose finding the damage makes, the fix that undoes it)
DAMAGES = [
    (
        "an empty lane <link/>",
        ROAD1_LANE1,
        ROAD1_LANE1.replace(b"\n", b"\n            <link/>\n", 1),
        "L024",
        "remove-empty-lane-link",
    ),
    (
        "an empty <link></link> over lines",
        ROAD1_LANE1,
        ROAD1_LANE1.replace(b"\n", b"\n            <link>\n            </link>\n", 1),
        "L024",
        "remove-empty-lane-link",
    ),
    (
        "a lane link into a junction",
        ROAD1_LANE_RIGHT,
        ROAD1_LANE_RIGHT.replace(b"\n", b'\n            <link><successor id="-1"/></link>\n', 1),
        "L024",
        "remove-lane-link-into-junction",
    ),
    (
        "a width on the centre lane",
        CENTRE,
        CENTRE.replace(b"\n", b'\n            <width sOffset="0" a="0.2" b="0" c="0" d="0"/>\n', 1),
        "L002",
        "remove-centre-lane-width",
    ),
    (
        "a contact point at the wrong end",
        b'<connection id="1" incomingRoad="2" connectingRoad="101" contactPoint="end">',
        b'<connection id="1" incomingRoad="2" connectingRoad="101" contactPoint="start">',
        "J002",
        "set-connection-contact-point",
    ),
    (
        "a missing contact point",
        b'<connection id="1" incomingRoad="2" connectingRoad="101" contactPoint="end">',
        b'<connection id="1" incomingRoad="2" connectingRoad="101">',
        "J002",
        "set-connection-contact-point",
    ),
    (
        "a laneLink to a lane the connecting road lacks",
        CONNECTION_0 + b'\n      <laneLink from="-1" to="-1"/>',
        CONNECTION_0 + b'\n      <laneLink from="-1" to="-2"/>',
        "R012",
        "correct-junction-lane-link",
    ),
    (
        "a laneLink from a lane the incoming road lacks",
        b'<connection id="2" incomingRoad="1" connectingRoad="102" contactPoint="start">\n      <laneLink from="-1"',
        b'<connection id="2" incomingRoad="1" connectingRoad="102" contactPoint="start">\n      <laneLink from="-3"',
        "R012",
        "correct-junction-lane-link",
    ),
]


@pytest.mark.parametrize(("what", "old", "new", "code", "name"), DAMAGES, ids=[d[0] for d in DAMAGES])
def test_a_damage_is_undone_byte_for_byte(what, old, new, code, name):
    broken = damaged(T_JUNCTION, old, new)
    assert code in codes(broken)
    result = fix(broken)
    assert result.data == T_JUNCTION, result.diff()
    assert [a.fixer.name for a in result.applied] == [name]
    assert result.fixed() == {code: 1} and result.report.findings == () and not result.rolled_back
    assert fix(result.data).data == result.data  # idempotent


def test_a_link_holding_a_comment_is_left_with_the_reason():
    broken = damaged(T_JUNCTION, ROAD1_LANE1, ROAD1_LANE1.replace(b"\n", b"\n            <link><!-- keep --></link>\n"))
    result = fix(broken)
    assert result.data == broken
    (reason,) = [why for f, why in result.remaining if f.code == "L024"]
    assert "comment" in reason


def test_fixes_leave_comments_user_data_and_spellings_alone():
    extra = b"<userData code='x' value='&lt;kept&gt;'/><!-- note -->"
    broken = damaged(T_JUNCTION, ROAD1_LANE1, ROAD1_LANE1.replace(b"\n", b"\n            <link/>" + extra + b"\n", 1))
    result = fix(broken)
    assert result.data == broken.replace(b"<link/>", b"", 1)


#: The example as OpenDRIVE 1.5 (whose schema has no junction type and a numeric map version).
OLD = (
    T_JUNCTION.replace(b'revMinor="8"', b'revMinor="5"').replace(b' type="default"', b"").replace(b' version="1"', b"")
)


def test_empty_elevation_profiles_of_a_1_5_file_are_removed():
    assert codes(OLD) == ["S001"] * 6  # the six empty <elevationProfile/>, which 1.8 allows
    result = fix(OLD)
    assert result.data == OLD.replace(b"    <elevationProfile/>\n", b"")
    assert result.report.findings == () and result.fixed() == {"S001": 6}


def test_a_geo_reference_beside_the_header_is_moved_into_it():
    geo = b"<geoReference><![CDATA[+proj=utm +zone=32]]></geoReference>"
    broken = damaged(T_JUNCTION, b"\n\n  <!-- Leg west", b"\n  " + geo + b"\n\n  <!-- Leg west")
    assert codes(broken) == ["S001"]
    result = fix(broken)
    header = b'north="10" south="-110" east="110" west="-110">\n    ' + geo + b"\n  </header>\n\n  <!-- Leg west"
    assert header in result.data and result.data.count(geo) == 1 and codes(result.data) == []


def test_a_header_older_than_the_features_used_is_raised(corpus_dir: Path):
    path = corpus_dir / "scenariogeneration-examples" / "direct_junction_creator0.xodr"
    result = fix(path)
    assert b'revMinor="7"' in result.data and b'revMinor="5"' in path.read_bytes()
    assert [f for f in result.report.findings if f.severity.name == "ERROR"] == []
    assert "raise-header-version" in {a.fixer.name for a in result.applied}


#: Failing fixtures of the rules (tests/xodrcheck/rules/fixtures) and whether their finding needs --unsafe.
FIXED_FIXTURES = [
    ("lane-link-not-omitted/fail.xodr", "L024", False),
    ("lane-link-not-omitted/fail_empty.xodr", "L024", False),
    ("lane-link-missing-lane/fail_dangling.xodr", "R015", False),
    ("lane-link-not-reciprocal/fail.xodr", "L011", False),
    ("link-not-reciprocal/fail.xodr", "K001", False),
    ("link-not-reciprocal/fail_1_9.xodr", "K001", False),
    ("junction-lane-link-missing-lane/fail_from.xodr", "R012", False),
    ("junction-lane-link-missing-lane/fail_to.xodr", "R012", False),
    ("lane-records-out-of-order/fail_access.xodr", "L019", False),
    ("lane-records-out-of-order/fail_material.xodr", "L019", False),
    ("lane-records-out-of-order/fail_rule.xodr", "L019", False),
    ("lane-records-out-of-order/fail_visibility.xodr", "L019", False),
    ("duplicate-element-id/fail.xodr", "R020", False),
    ("degenerate-geometry/fail.xodr", "G006", True),
    ("road-link-target-missing/fail.xodr", "R010", True),
    ("road-link-target-missing/fail_junction.xodr", "R010", True),
]


@pytest.mark.parametrize(("name", "code", "unsafe"), FIXED_FIXTURES)
def test_failing_fixtures_are_fixed(name, code, unsafe):
    path = FIXTURES / name
    assert code in codes(path.read_bytes())
    if unsafe:
        assert fix(path).data == path.read_bytes()  # nothing without --unsafe
    result = fix(path, unsafe=unsafe)
    assert code not in {f.code for f in result.report.findings}
    assert result.fixed()[code] >= 1 and all(a.fixer.safe is not unsafe or not unsafe for a in result.applied)
    assert fix(result.data, unsafe=unsafe).data == result.data


def test_a_returned_road_link_reads_as_written_by_hand():
    result = fix(FIXTURES / "link-not-reciprocal" / "fail.xodr")
    assert result.data == (FIXTURES / "link-not-reciprocal" / "pass.xodr").read_bytes()


def test_passing_fixtures_come_out_byte_identical():
    for path in sorted(FIXTURES.glob("*/pass*.xodr")):
        result = fix(path, unsafe=True)
        assert result.data == path.read_bytes(), (path, result.diff())


def test_a_small_gap_is_snapped_only_with_unsafe_and_says_how_far():
    two = b'<geometry s="0" x="-110" y="0" hdg="0" length="100"><line/></geometry>'
    split = (
        b'<geometry s="0" x="-110" y="0" hdg="0" length="50"><line/></geometry>\n'
        b'      <geometry s="50" x="-59.996" y="0" hdg="0" length="50"><line/></geometry>'
    )
    broken = damaged(T_JUNCTION, two, split)
    assert "G001" in codes(broken)
    assert fix(broken).data == broken
    result = fix(broken, unsafe=True)
    assert b'x="-60.0" y="0.0"' in result.data and "G001" not in codes(result.data)
    (applied,) = result.applied
    assert applied.fixer.name == "snap-plan-view-gap" and abs(applied.repair.moved - 0.004) < 1e-9


def test_a_gap_over_the_tolerance_is_left():
    broken = (FIXTURES / "plan-view-gap" / "fail.xodr").read_bytes()
    result = fix(broken, unsafe=True)
    assert result.data == broken
    (reason,) = [why for f, why in result.remaining if f.code == "G001"]
    assert "over the gap tolerance" in reason
