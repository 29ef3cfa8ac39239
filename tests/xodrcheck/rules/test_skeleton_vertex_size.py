"""Rule skeleton-vertex-size: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "skeleton-vertex-size"


def test_radius_beside_width_and_length():
    path = fixture(RULE, "fail.xodr")
    found = [(f.line, f.rule_uid.rsplit(":", 1)[-1]) for f in findings(path, RULE)]
    pole, trunk = line_of(path, 'width="0.2"'), line_of(path, 'width="0.24"')
    assert found == [
        (pole, "road.object.skeleton.vertex_road.no_radius_with_width_length"),
        (pole, "road.object.skeleton.use_radius_or_width_length"),
        (trunk, "road.object.skeleton.vertex_local.vertex_local_elements"),
        (trunk, "road.object.skeleton.use_radius_or_width_length"),
    ]


def test_vertex_without_size():
    path = fixture(RULE, "fail_missing.xodr")
    (f,) = findings(path, RULE)
    assert f.line == line_of(path, 'z="4.5" id="3"') and "neither radius nor width and length" in f.message
