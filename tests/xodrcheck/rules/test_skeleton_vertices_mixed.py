"""Rule skeleton-vertices-mixed: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "skeleton-vertices-mixed"


def test_road_and_local_vertices_in_one_polyline():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    assert [f.rule_uid.rsplit(":", 1)[-1] for f in found] == [
        "road.object.skeleton.vertex_road.polyline_elements",
        "road.object.skeleton.vertex_local.no_mixing_road_local",
    ]
    assert {f.line for f in found} == {line_of(path, '<vertexLocal u="0" v="-1.2"')}
    assert "polyline 2" in found[0].message
