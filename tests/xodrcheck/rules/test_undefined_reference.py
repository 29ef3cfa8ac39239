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
