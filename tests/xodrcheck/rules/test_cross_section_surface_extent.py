"""Rule cross-section-surface-extent (U011): the findings each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture

RULE = "cross-section-surface-extent"


def test_late_start_and_record_beyond_the_end():
    found = findings(fixture(RULE, "fail.xodr"), RULE)
    assert len(found) == 2
    late, beyond = sorted(found, key=lambda f: f.line)
    assert late.s == 10 and "<width> of strip 1 starts at s=10" in late.message
    assert "<constant> of strip -1 has <coefficients> from s=120, beyond the road's end (length 100)" in beyond.message
