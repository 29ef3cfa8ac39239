"""Rule plan-view-s-jump: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "plan-view-s-jump"


def test_s_jumps_by_two_metres():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.s) == ("1", 52.0)
    assert "should start at s=50" in f.message and "gap of 2 m" in f.message


def test_a_jump_of_exactly_the_tolerance_is_none(tmp_path):
    """ika's junction_m2a road 801: s=364.036 after s=202.082 + 161.953 = 364.035, 1 mm (``length_abs``) written
    with 1 mm resolution; its binary difference exceeds 1 mm by 3e-14 and was reported."""
    text = fixture(RULE, "pass.xodr").read_text(encoding="utf-8")
    first = '<geometry s="0" x="0" y="0" hdg="0" length="50"><line/></geometry>'
    second = '<geometry s="50" x="50" y="0" hdg="0" length="50"><line/></geometry>'
    assert first in text and second in text
    elements = (
        '<geometry s="0" x="0" y="0" hdg="0" length="202.082"><line/></geometry>'
        '<geometry s="202.082" x="202.082" y="0" hdg="0" length="161.953"><line/></geometry>'
        '<geometry s="S" x="364.035" y="0" hdg="0" length="10"><line/></geometry>'
    )
    path = tmp_path / "rounded.xodr"
    path.write_text(text.replace(first, elements.replace('s="S"', 's="364.036"')).replace(second, ""), "utf-8")
    assert findings(path, RULE) == []
    path.write_text(text.replace(first, elements.replace('s="S"', 's="364.0372"')).replace(second, ""), "utf-8")
    (f,) = findings(path, RULE)
    assert "gap of 0.0022 m" in f.message
