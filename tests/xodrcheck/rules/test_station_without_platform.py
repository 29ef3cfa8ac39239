"""Rule station-without-platform (W003): the findings each fail fixture gives."""

from tests.xodrcheck.rules.helpers import findings, fixture, line_of
from xodrcheck.rules.shared import feature_uids as U

RULE = "station-without-platform"


def test_empty_station_and_platform_without_segment_one_finding_per_uid():
    path = fixture(RULE, "fail.xodr")
    found = findings(path, RULE)
    by_line: dict[int, set] = {}
    for f in found:
        by_line.setdefault(f.line, set()).add(f.rule_uid)
    assert by_line == {
        line_of(path, '<platform id="2"'): {U.PLATFORMS_MIN_SEGMENTS, U.SEGMENTS_PER_PLATFORM},
        line_of(path, '<station id="2"'): {U.PLATFORMS_MIN_AMOUNT, U.ONE_PLATFORM_PER_STATION},
    }
