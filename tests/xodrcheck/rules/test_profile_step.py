"""Rule profile-step: a road's elevation, superelevation and laneOffset must not jump where a record starts."""

import math

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.findings import Severity
from xodrcheck.geometry.profile import jumps
from xodrcheck.model import Cubic

RULE = "profile-step"


@pytest.mark.parametrize(
    "name, element, size",
    [("fail_elevation.xodr", "elevation", "0.05 m"), ("fail_lane_offset.xodr", "laneOffset", "0.14 m")],
)
def test_a_record_starting_off_the_previous_one(name, element, size):
    path = fixture(RULE, name)
    (f,) = findings(path, RULE)
    assert (f.road, f.severity, f.basis) == ("1", Severity.WARNING, "plausibility")  # Annex D in words, no UID
    assert [g.severity for g in findings(path, RULE, "generator")] == [Severity.ERROR]
    assert f"the {element} jumps by {size}" in f.message
    assert f.line == line_of(path, f"<{element} s=", 2)


def test_superelevation_jump_is_an_angle():
    (f,) = findings(fixture(RULE, "fail_superelevation.xodr"), RULE)
    assert f.s == 40.0 and f"{math.degrees(0.02):.3g} deg (0.02 rad)" in f.message


def test_lane_offset_may_jump_where_a_lane_section_starts(tmp_path):
    """Lanes are renumbered at a section start with the laneOffset (CARLA does): lane-border-discontinuous decides."""
    text = fixture(RULE, "fail_lane_offset.xodr").read_text(encoding="utf-8")
    text = text.replace(
        "</laneSection>\n",
        '</laneSection>\n      <laneSection s="60">'
        + text.split('<laneSection s="0">')[1].split("</laneSection>")[0]
        + "</laneSection>\n",
        1,
    )
    path = tmp_path / "sections.xodr"
    path.write_text(text, encoding="utf-8")
    assert findings(path, RULE) == []


def test_jumps_compares_the_record_in_force():
    """Equal starts: the later record holds (as in the profile evaluation); unsorted records are taken sorted."""
    records = (
        Cubic(50.0, 9.0, 0, 0, 0),
        Cubic(0.0, 0.0, 0.1, 0, 0),
        Cubic(50.0, 5.0, 0, 0, 0),
        Cubic(80.0, 5.0, 0, 0, 0),
    )
    assert jumps(records) == [(records[2], 5.0, 5.0), (records[3], 5.0, 5.0)]
    assert jumps((Cubic(0.0, 1.0, 0, 0, 0), Cubic(10.0, math.nan, 0, 0, 0))) == []
