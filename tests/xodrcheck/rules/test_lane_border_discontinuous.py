"""Rule lane-border-discontinuous: the finding each fail fixture gives."""

import math

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "lane-border-discontinuous"


def test_width_jumps_at_a_section_boundary():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.section_s, f.s) == ("1", -1, 50.0, 50.0)
    assert "jump by 1 m" in f.message
    assert f.x == pytest.approx(50.0) and f.y == pytest.approx(-2.5)


def test_full_width_lane_linked_in_place_of_the_continuing_one():
    path = fixture(RULE, "fail_appearing.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", -2)
    assert "jump by 3.5 m" in f.message


def test_lane_height_steps_at_a_section_boundary():
    """A sidewalk raised 0.15 m in one lane section and not in the next: the borders stay, the surface steps."""
    path = fixture(RULE, "fail_height.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.s) == ("1", -2, 50.0)
    assert "steps by 0.15 m in height" in f.message and "jump" not in f.message
    assert f.z == pytest.approx(0.0)  # the edge after the boundary


def test_level_flag_change_on_a_superelevated_road_steps():
    """Lanes rolled by 0.05 rad up to s=50 and level after: lane -1's outer edge rises by 3.5 sin(0.05)."""
    path = fixture(RULE, "fail_level.xodr")
    by_lane = {f.lane: f for f in findings(path, RULE)}
    assert sorted(by_lane) == [-2, -1]
    assert f"steps by {3.5 * math.sin(0.05):.4g} m" in by_lane[-1].message


def test_a_split_linked_to_every_lane_meets_as_a_band():
    assert findings(fixture(RULE, "pass_split.xodr"), RULE) == []


def test_a_split_linked_to_one_lane_only_names_multiple_connections():
    (f,) = findings(fixture(RULE, "fail_split_unlinked.xodr"), RULE)
    assert f.rule_uid == "asam.net:xodr:1.4.0:road.lane.link.multiple_connections"
    assert "lane -1 splits into lanes -1 to -2: link it to each of them" in f.message


def test_a_merge_linked_from_one_lane_only_names_multiple_connections():
    (f,) = findings(fixture(RULE, "fail_merge_unlinked.xodr"), RULE)
    assert f.rule_uid == "asam.net:xodr:1.4.0:road.lane.link.multiple_connections"
    assert "lanes -1 to -2 merge into lane -1" in f.message


def test_a_plain_jump_names_no_rule_of_the_standard():
    (f,) = findings(fixture(RULE, "fail.xodr"), RULE)
    assert f.rule_uid is None
