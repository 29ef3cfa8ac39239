"""Rule duplicate-element-id (R020): the findings each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "duplicate-element-id"


def test_object_and_signal_ids_repeated_on_another_road():
    path = fixture(RULE, "fail.xodr")
    obj, sig = sorted(findings(path, RULE), key=lambda f: f.line)
    assert obj.road == sig.road == "2"
    assert (
        obj.line == line_of(path, '<object id="7"', 2)
        and f"first at line {line_of(path, '<object id=')}" in obj.message
    )
    assert sig.line == line_of(path, 'id="5"', 2) and sig.message.startswith("signal id '5' is used again")
