"""Rule direct-junction-crossing-traffic: crossing lane links in direct junctions, and splits and merges that pass."""

from pathlib import Path

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "direct-junction-crossing-traffic"
UID = "asam.net:xodr:1.8.0:junctions.direct.split_or_merge"


def _variant(tmp_path: Path, base: str, *edits: tuple[str, str]) -> Path:
    text = fixture(RULE, base).read_text(encoding="utf-8")
    for old, new in edits:
        assert old in text, old
        text = text.replace(old, new, 1)  # the first occurrence: road 2 comes before road 3
    path = tmp_path / "variant.xodr"
    path.write_text(text, encoding="utf-8")
    return path


def test_inner_lane_continues_outside():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert f.rule_uid == UID
    assert f.line == line_of(path, '<laneLink from="-1" to="-1"/>')
    assert (f.road, f.s, f.x, f.y) == ("1", 50.0, 50.0, 0.0)
    assert "direct junction 111" in f.message
    assert "connection 0 (lane -2 of road 1 to lane -1 of road 2" in f.message
    assert "connection 1 (lane -1 of road 1 to lane -1 of road 3" in f.message
    assert "lane -2 of road 1 lies right of lane -1 of road 1" in f.message
    assert "more pair" not in f.message


def test_order_kept_and_overlapping_lanes_pass():
    assert findings(fixture(RULE, "pass.xodr"), RULE) == []
    assert findings(fixture(RULE, "pass_overlap.xodr"), RULE) == []


def test_lanes_swapped_on_one_road(tmp_path):
    """Lanes 1 and -1 (both driving directions) swap sides on road 2: decided from the lane ids alone."""
    path = _variant(
        tmp_path,
        "pass.xodr",
        ('<laneLink from="1" to="1"/>', '<laneLink from="1" to="-1"/>'),
        ('<laneLink from="-1" to="-1"/>\n    </connection>', '<laneLink from="-1" to="1"/>\n    </connection>'),
    )
    (f,) = findings(path, RULE)
    assert "lane 1 of road 1 lies left of lane -1 of road 1" in f.message
    assert "(lane -1 of road 2) lies right of the other's (lane 1 of road 2)" in f.message


def test_one_lane_split_around_another(tmp_path):
    """Lane -1 continues on road 2 and on road 3, whose lane overlaps lane -2's target on road 2 at the joint and
    parts to its right: lane -1 crosses lane -2's path (ordered by the roads' sides)."""
    path = _variant(
        tmp_path,
        "pass_overlap.xodr",
        ('<laneLink from="-2" to="-1" overlapZone="30"/>', '<laneLink from="-1" to="-1"/>'),
        ('<laneLink from="-2" to="-2" overlapZone="30"/>', '<laneLink from="-2" to="-2"/>'),
    )
    (f,) = findings(path, RULE)
    assert "lane -2 of road 1 lies right of lane -1 of road 1" in f.message
    assert "(lane -2 of road 2) lies left of the other's (lane -1 of road 3)" in f.message


def test_merge_written_from_the_linked_road(tmp_path):
    """An entry: roads 2 and 3 are the incoming roads, road 1 the linked road (contact at its end)."""
    merge = (
        ('incomingRoad="1" linkedRoad="2" contactPoint="start"', 'incomingRoad="2" linkedRoad="1" contactPoint="end"'),
        ('incomingRoad="1" linkedRoad="3" contactPoint="start"', 'incomingRoad="3" linkedRoad="1" contactPoint="end"'),
    )
    kept = _variant(tmp_path, "pass.xodr", *merge, ('<laneLink from="-2" to="-1"/>', '<laneLink from="-1" to="-2"/>'))
    assert findings(kept, RULE) == []
    crossed = _variant(
        tmp_path, "fail.xodr", *merge, ('<laneLink from="-2" to="-1"/>', '<laneLink from="-1" to="-2"/>')
    )
    (f,) = findings(crossed, RULE)
    assert f.road == "1" and f.s == 50.0
    assert "connection 0 (lane -1 of road 2 to lane -2 of road 1" in f.message  # as the file writes the link
    assert "connection 1 (lane -1 of road 3 to lane -1 of road 1" in f.message


def test_linked_road_drawn_the_other_way(tmp_path):
    """Road 2 runs west, ending at the joint: its lane -1 lies north, left of its lane 1 there."""
    reverse = (
        (
            '<predecessor elementType="junction" elementId="111"/>',
            '<successor elementType="junction" elementId="111"/>',
        ),
        ('x="50.0" y="0.0" hdg="0.0" length="100.0"', 'x="150.0" y="0.0" hdg="3.141592653589793" length="100.0"'),
        ('incomingRoad="1" linkedRoad="2" contactPoint="start"', 'incomingRoad="1" linkedRoad="2" contactPoint="end"'),
    )
    turned = ('<laneLink from="1" to="1"/>', '<laneLink from="1" to="-1"/>')
    kept = _variant(tmp_path, "pass.xodr", *reverse, turned, ('"-1" to="-1"/>\n    </c', '"-1" to="1"/>\n    </c'))
    assert findings(kept, RULE) == []
    crossed = _variant(tmp_path, "pass.xodr", *reverse)  # lanes 1 -> 1 and -1 -> -1: the sides swap
    (f,) = findings(crossed, RULE)
    assert "lane 1 of road 1 lies left of lane -1 of road 1" in f.message
    assert "(lane 1 of road 2) lies right of the other's (lane -1 of road 2)" in f.message
