"""Rule undefined-reference (R021): the findings each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "undefined-reference"


def test_dependency_signal_reference_and_object_reference_to_missing_ids():
    path = fixture(RULE, "fail.xodr")
    dep, link, ref = sorted(findings(path, RULE), key=lambda f: f.line)
    assert dep.road == "1" and dep.line == line_of(path, '<dependency id="60"')
    assert "names a signal that the file does not define" in dep.message
    assert link.line == line_of(path, '<reference elementId="77"') and "elementId='77'" in link.message
    assert ref.road == "2" and "<objectReference id='70'> names an object" in ref.message


def test_roads_and_lanes_a_junction_names():
    """A junction's priority, cross paths (crossing road and their lane links), main road, boundary segments and
    virtual connections name roads and lanes too (a priority naming road 55 was not reported before)."""
    path = fixture(RULE, "fail_junction.xodr")
    lane, crossing, priority, main = sorted(findings(path, RULE), key=lambda f: f.line)
    assert (lane.road, lane.lane, lane.line) == ("1", 7, line_of(path, '<endLaneLink s="95" from="7"'))
    assert "cross path 0 names lane 7 of road 1" in lane.message
    assert (
        crossing.line == line_of(path, '<crossPath id="1" crossingRoad="58"')
        and "crossingRoad='58'" in crossing.message
    )
    assert priority.line == line_of(path, '<priority high="1" low="55"/>') and "low='55'" in priority.message
    assert main.line == line_of(path, '<junction id="557"') and "<junction mainRoad='91'>" in main.message
    # reported once, under ids.only_ref_defined_ids: not again as a crossing road outside its junction or a virtual
    # junction without its main road
    assert findings(path, "cross-path-roads") == []
    assert findings(path, "virtual-junction-branches") == []
