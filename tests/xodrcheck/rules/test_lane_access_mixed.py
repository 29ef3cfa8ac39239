"""Rule lane-access-mixed: the finding each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "lane-access-mixed"


def test_allow_and_deny_at_one_offset():
    path = fixture(RULE, "fail.xodr")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane) == ("1", -1)
    assert f.line == line_of(path, 'rule="deny"')


def test_offsets_are_compared_as_values(tmp_path):
    # "0" and "0.0" are one position: the deny at 0.0 still mixes with the allows at 0
    text = fixture(RULE, "fail.xodr").read_text(encoding="utf-8")
    path = tmp_path / "spelt.xodr"
    path.write_text(text.replace('sOffset="0" rule="deny"', 'sOffset="0.0" rule="deny"'), encoding="utf-8")
    (f,) = findings(path, RULE)
    assert (f.road, f.lane, f.line) == ("1", -1, line_of(path, 'rule="deny"'))
    assert "sOffset 0 mix" in f.message
