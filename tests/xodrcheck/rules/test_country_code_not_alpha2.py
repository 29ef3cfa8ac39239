"""Rule country-code-not-alpha2: the finding each fail fixture gives."""

import pytest

from tests.xodrcheck.rules.helpers import findings, fixture, line_of

RULE = "country-code-not-alpha2"


@pytest.mark.parametrize(
    ("name", "code", "why"),
    [
        ("fail.xodr", "DEU", "an ALPHA-3 code"),
        ("fail_name.xodr", "Germany", "not a country code"),
        ("fail_lower_case.xodr", "de", 'not in capitals (write "DE")'),
        ("fail_opendrive.xodr", "OpenDRIVE", "not a country code"),
    ],
)
def test_country_code_that_is_not_alpha_2(name, code, why):
    path = fixture(RULE, name)
    (f,) = findings(path, RULE)
    assert f.road == "1" and f.line == line_of(path, "<type ")
    assert f'country="{code}", {why}' in f.message


def test_a_signal_of_the_opendrive_signal_reference_keeps_its_country():
    """14.1: signals without an official type (traffic lights) take the signal reference's type, country="OpenDRIVE"."""
    assert findings(fixture(RULE, "pass_signal.xodr"), RULE) == []
